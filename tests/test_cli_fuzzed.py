"""Command lines that a fuzzer of the options found wanting, one test each.

Each ran to a traceback, a stray line on standard error, or a file written from a
failure; the contract is one line ``assur: error: ...`` and exit status 2, or the
output whole and nothing else.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import assur
from assur._picture_animate import _frames

from .conftest import EXAMPLES
from .conftest import run_cli as run

FOUR_BAR = EXAMPLES / "four_bar.toml"
NEAR_THE_LARGEST = "-1.7e308:1.7e308:1e308"
"""A sound range (parse_angles reads it) whose span overflows a float."""


def test_a_summary_over_positions_near_the_largest_float(capsys):
    # round() of the turns' inf raised OverflowError: a traceback from --summary
    status, out, err = run(
        capsys, "forces", FOUR_BAR, "--summary", f"--angles={NEAR_THE_LARGEST}"
    )
    assert (status, err) == (0, "")
    assert out.startswith("Summary over 4 positions")
    table = assur.forces(assur.load(FOUR_BAR), [-1.7e308, -0.7e308, 0.3e308, 1.3e308])
    assert all(map(math.isfinite, table.summary().values()))


def test_diagrams_of_positions_near_the_largest_float_are_refused_first(
    capsys, tmp_path
):
    # matplotlib's axis overflowed: numpy's warnings with their source lines, then
    # the folder named as the fault, "cannot write the file (ValueError: ...)"
    out = tmp_path / "d"
    argv = ["diagrams", FOUR_BAR, "-o", out, f"--angles={NEAR_THE_LARGEST}"]
    status, _, err = run(capsys, *argv)
    assert status == 2
    assert err == (
        f"assur: error: {FOUR_BAR}: --angles: a position of magnitude 1.7e+308; "
        "expected positions within +-1e+300, which the diagrams' axes can span\n"
    )
    assert not out.exists()


def test_the_frames_of_positions_near_the_largest_float(recwarn):
    # the span of the sweep overflowed: numpy's RuntimeWarning on standard error
    sweep = np.array([-1.7e308, -0.7e308, 0.3e308, 1.3e308])
    np.testing.assert_array_equal(_frames(sweep, 2, True), sweep[[0, 3]])
    assert not recwarn.list


def test_a_delta_just_below_2_is_echoed_as_given(capsys):
    # "delta: 2; ... expected a smaller delta": 2 itself is out of --delta's range
    argv = ["dynamics", FOUR_BAR, "--delta", "1.9999999", "--angles", "0"]
    status, out, err = run(capsys, *argv)
    assert (status, out) == (2, "")
    assert err.startswith(f"assur: error: {FOUR_BAR}: delta: 1.9999999; ")
    assert err.count("\n") == 1


@pytest.mark.parametrize(
    ("command", "option", "suffix"),
    [("forces", "--csv", ".csv"), ("plot", "-o", ".png"), ("diagrams", "-o", "")],
)
def test_an_output_name_too_long_says_what_is_expected(
    capsys, tmp_path, command, option, suffix
):
    # "NAME: File name too long", with no word of what would do
    name = tmp_path / ("a" * 300 + suffix)
    status, out, err = run(capsys, command, FOUR_BAR, option, name, "-q")
    assert (status, out) == (2, "")
    assert err.startswith(f"assur: error: {name}: ")  # the system's words next
    assert err.endswith("; expected a shorter name\n")
    assert err.count("\n") == 1


@pytest.mark.parametrize(
    "argv",
    [
        ["dynamics", "--flywheel=--"],
        ["dynamics", "--delta=--"],
        ["plot", "-o", "p.png", "--dpi=--"],
        ["explain", "--angle=--"],
        ["kinematics", "--angles", "--"],
        # no traceback here: the table was printed and no file written
        ["kinematics", "--csv=--"],
    ],
)
def test_a_value_of_two_dashes_is_one_usage_error(capsys, argv):
    # argparse dropped the "--" and stored an empty list: a traceback (TypeError)
    command, *options = argv
    status, out, err = run(capsys, command, FOUR_BAR, *options)
    assert (status, out) == (2, "")
    option = options[-1].partition("=")[0] if "=" in options[-1] else options[-2]
    assert err.startswith(f"assur: error: {command}: argument {option}")
    assert ": expected a value, got '--' (the end of the options) (see " in err
    assert err.count("\n") == 1
