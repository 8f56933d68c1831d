"""Progress bars of the picture commands on a terminal, and --quiet."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from assur import cli

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
FOUR_BAR = EXAMPLES / "four_bar.toml"


def run(capsys, *args) -> tuple[int, str, str]:
    status = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.pictures
def test_diagrams_show_a_bar_on_a_terminal(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles", "0:360:30", "-o", tmp_path / "d"
    )
    assert status == 0
    assert "diagrams:" in err
    assert "6.00/6.00" in err  # four-bar has masses: six pictures
    assert out.count("wrote ") == 6


@pytest.mark.pictures
def test_diagrams_without_a_terminal_or_quiet(tmp_path, capsys, monkeypatch):
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles", "0:360:30", "-o", tmp_path / "d"
    )
    assert (status, err) == (0, "")
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles=0:360:30", "-o", tmp_path / "e", "-q"
    )
    assert (status, out, err) == (0, "", "")
    assert len(list((tmp_path / "e").iterdir())) == 6


@pytest.mark.pictures
def test_quiet_pictures_say_nothing(tmp_path, capsys):
    for args in (
        ["plot", FOUR_BAR, "-o", tmp_path / "p.png"],
        ["animate", FOUR_BAR, "--frames", "2", "-o", tmp_path / "a.gif"],
    ):
        status, out, err = run(capsys, "--quiet", *args)
        assert (status, out, err) == (0, "", "")
        assert Path(args[-1]).exists()
