"""Command lines that a fuzzer of the options found wanting, one test each.

Each ran to a traceback, a stray line on standard error, or a file written from a
failure; the contract is one line ``assur: error: ...`` and exit status 2, or the
output whole and nothing else.
"""

from __future__ import annotations

import math

import assur

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
