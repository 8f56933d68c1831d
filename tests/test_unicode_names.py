"""Names in other scripts than Latin, in the outputs meant for a terminal.

Students name links in their own language: Cyrillic, Greek, CJK, accented Latin
written with combining marks. These tests write the slider-crank exercise so and
check what each output does with such names.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from assur._width import shown_width
from assur.cli import main

from .conftest import EXAMPLES

RENAMED = {
    '"crank"': '"кривошип"',
    "links.crank]": 'links."кривошип"]',
    '"rod"': '"шатун_φ"',
    "links.rod]": 'links."шатун_φ"]',
    '"slider"': '"ползун 滑块"',
    "links.slider]": 'links."ползун 滑块"]',
    "joints.guide]": 'joints."направляющая_e\u0301"]',
}
"""The exercise's names, written in Cyrillic, Greek, CJK and with a combining mark."""


@pytest.fixture
def renamed(tmp_path: Path) -> Path:
    """The slider-crank exercise with non-Latin names, in a folder named so too."""
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    for old, new in RENAMED.items():
        text = text.replace(old, new)
    folder = tmp_path / "Мои файлы τεστ 机构"
    folder.mkdir()
    path = folder / "кривошипно-ползунный.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("command", ["kinematics", "forces"])
def test_a_readable_table_of_wide_names_stays_aligned(renamed, capsys, command):
    # a CJK character is two columns wide and a combining mark none: aligned by
    # len(), every column after such a name was shifted on the terminal
    assert main([command, str(renamed), "--angles", "0:90:45"]) == 0
    lines = capsys.readouterr().out.splitlines()[:5]
    assert "ползун 滑块" in lines[0] or "e\u0301" in lines[0]
    assert len({shown_width(line) for line in lines}) == 1


def test_a_summary_of_wide_names_stays_aligned(renamed, capsys):
    assert main(["forces", str(renamed), "--angles", "0:90:45", "--summary"]) == 0
    rows = [r for r in capsys.readouterr().out.splitlines() if r.startswith("  ")]
    rows = [r for r in rows if not r.startswith("  (")]
    # each value's last digit in one column, whatever the name before it
    ends = {shown_width(r.split("  N")[0]) for r in rows if r.endswith("  N")}
    assert any("e\u0301" in r for r in rows)
    assert len(ends) == 1
