"""A decimal comma (0,5 for a half) where a point is meant: the messages ask about it.

Each case is the slider-crank exercise, or its command line, with one number
written as most of Europe writes it.
"""

from __future__ import annotations

import pytest

from assur.cli import main

from .conftest import EXAMPLES

HINT = "; a decimal comma? decimals are written with a point (0.5, not 0,5)"


@pytest.mark.parametrize(
    ("old", "new"),
    [
        # "0,052": TOML reads the 0 after the comma, then stops at its leading zero
        ("at = [0.0, 0.0]", "at = [0,052, 0,052]"),
        ("at = [0.0, 0.0]", "at = [0.0, 0,05]"),
        # in an inline table "05" reads as the next key, refused at the brace
        ("at = [0.0, 0.0]", 'at = {from = "A", toward = "B", distance = 0,05}'),
    ],
)
def test_a_decimal_with_a_leading_zero_in_an_array_is_asked_about(
    tmp_path, capsys, old, new
):
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "comma.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    assert main(["structure", str(path)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert err[0].startswith(f"assur: error: {path}: not valid TOML: ")
    assert err[0].endswith(HINT)


def test_an_unclosed_array_of_whole_numbers_is_not_asked_about(tmp_path, capsys):
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    path = tmp_path / "open.toml"
    path.write_text(text.replace("at = [0.0, 0.0]", "at = [0, 0", 1), "utf-8")
    assert main(["structure", str(path)]) == 2
    err = capsys.readouterr().err
    assert "not valid TOML" in err
    assert "decimal comma" not in err


@pytest.mark.parametrize(
    ("angles", "asked"),
    [("0:90:22,5", True), ("0:90:10,0:40:10", False)],  # the second: two ranges
)
def test_a_decimal_comma_in_two_drivers_angles_is_asked_about(capsys, angles, asked):
    # two drivers take two ranges: "0:90:22,5" is one range (5 positions) and the
    # single value 5, told as unequal counts
    path = str(EXAMPLES / "five_bar_two_cranks.toml")
    assert main(["kinematics", path, "--angles", angles]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1
    assert "the ranges have " in err[0]
    assert err[0].endswith(HINT) is asked
