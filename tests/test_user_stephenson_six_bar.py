"""A Stephenson six-bar written from the file format with {from, toward, distance}
points: a crank-rocker whose coupler drives a second RRR dyad, a coupler point load,
a torque on the last rocker and gravity.

Held to the oracle's global solve (with and without friction), virtual power, finite
differences and the note's arithmetic; by hand (Kennedy's theorem), the coupler's
instant centre lies on the lines of the crank O2A and of the rocker O4B.
"""

from __future__ import annotations

import numpy as np

import assur

from . import usercheck

MECH = usercheck.load("stephenson_six_bar")
TURN = usercheck.POSITIONS["stephenson_six_bar"]


def _off_line(table: assur.Table, start: str, end: str) -> np.ndarray:
    """Distance (m) of the coupler's instant centre from the line start-end."""
    p = np.stack([table[f"{start}.x"], table[f"{start}.y"]], axis=-1)
    q = np.stack([table[f"{end}.x"], table[f"{end}.y"]], axis=-1)
    ic = np.stack([table["coupler.ic.x"], table["coupler.ic.y"]], axis=-1)
    d, r = q - p, ic - p
    return np.abs(d[:, 0] * r[:, 1] - d[:, 1] * r[:, 0]) / np.hypot(d[:, 0], d[:, 1])


def test_coupler_instant_centre_is_where_crank_and_rocker_lines_cross():
    table = assur.kinematics(MECH, TURN)
    # a far instant centre (crank and rocker nearly parallel) scales the rounding
    far = np.maximum(1.0, np.hypot(table["coupler.ic.x"], table["coupler.ic.y"]))
    assert np.all(_off_line(table, "O2", "A") <= 1e-9 * far)
    assert np.all(_off_line(table, "O4", "B") <= 1e-9 * far)
