"""Change points of one driver's sweep (``assur._branches``) past Newton groups.

The checks are geometric: a dyad that forms a parallelogram with a link and the frame
stays one (its coupler keeps the frame's direction, its rocker turns as the link it
copies) only on the branch the change points give it.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import assur

from .conftest import DATA

TWO_TRIADS = DATA / "edge" / "two_triads_one_crank.toml"

PARALLELOGRAMS = [
    ("coupler0", "copy", "crank", "O1", "O2"),
    ("pc", "po", "left_rocker", "F", "K"),
    ("pc2", "po2", "left_rocker2", "F2", "K2"),
]
"""Each parallelogram dyad: its coupler, its rocker, the link the rocker copies and
the two frame pivots whose line the coupler stays parallel to."""


def _turn(a: np.ndarray) -> np.ndarray:
    """Return angles ``a`` (deg) brought into [-180, 180)."""
    return (a + 180.0) % 360.0 - 180.0


@pytest.fixture(
    scope="module",
    params=[np.linspace(0.0, 720.0, 1441), np.arange(-360.0, 360.0, 45.0) + 0.3],
    ids=["two-turns", "sparse"],
)
def swept(request: pytest.FixtureRequest) -> tuple[assur.Table, list[str]]:
    """Two full turns of the crank, densely and sparsely, and the warnings said."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(assur.load(TWO_TRIADS), request.param)
    return table, [str(w.message) for w in caught]


@pytest.mark.parametrize(
    ("coupler", "rocker", "copied", "first", "second"), PARALLELOGRAMS
)
def test_every_parallelogram_after_two_triads_holds(
    swept, coupler, rocker, copied, first, second
):
    """The scan took the second triad's poses from anchors walked before the dyad
    between the triads had its change points: the last dyad's change points (near
    120 and 228 deg) were missed, and po2 was up to 4.4 deg off the rocker's
    direction at 432 of the 1441 positions, from 120.5 deg to 588 deg, with a dead
    centre's warning alone."""
    table, _ = swept
    mech = assur.load(TWO_TRIADS)
    a, b = (np.array(mech.joint(j).at, dtype=float) for j in (first, second))
    frame = np.degrees(np.arctan2(*(b - a)[::-1]))
    # the coupler is parallel to the frame's line (either way along it)
    off = _turn(table[f"{coupler}.angle"] - frame)
    off = np.minimum(np.abs(off), 180.0 - np.abs(off))
    np.testing.assert_allclose(off, 0.0, atol=1e-6)
    # the rocker turns as the link it copies
    gap = _turn(table[f"{rocker}.angle"] - table[f"{copied}.angle"])
    np.testing.assert_allclose(_turn(gap - gap[0]), 0.0, atol=1e-6)
    # with continuous velocities (off by 5e-6 rad/s at most, next to a change point)
    np.testing.assert_allclose(
        table[f"{rocker}.omega"], table[f"{copied}.omega"], rtol=0, atol=1e-5
    )


def test_the_last_dyads_change_points_are_said(swept):
    """Both of them, as the first dyads' are (positions are reached from the
    reference pose within half a turn: both sweeps pass them there)."""
    _, said = swept
    changes = [s for s in said if s.startswith("group RRR (pc2, po2)")]
    for where in ("-131.875", "120.016"):
        assert any(f"position {where} deg (a change point)" in s for s in changes), said


@pytest.mark.parametrize("angles", [[180.0], [90.0, 135.0, 180.0], [250.0, 180.0]])
def test_a_sweep_ending_on_a_change_point_is_not_told_it_is_carried_through(angles):
    # at 180 deg alone: "the motion is carried through onto the branch whose
    # velocities are continuous", then the error of the dead centre there
    docs = Path(__file__).parent.parent / "docs" / "files" / "errors"
    mech = assur.load(docs / "parallelogram.toml")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(assur.SingularConfigurationError, match="180 deg"):
            assur.kinematics(mech, angles)
    carried = [str(w.message) for w in caught if "carried through" in str(w.message)]
    # 250 deg lies past the change point: carried through to it, rightly said
    assert len(carried) == (1 if 250.0 in angles else 0), carried


def test_the_branch_function_flips_a_parallelogram_past_its_change_points():
    """The sweep's and the reach's branches past change points (one function): a
    parallelogram's dyad keeps its branch between 0 and 180 deg, where the reference
    pose (45 deg) is, takes the other past either, and is back a turn later."""
    from assur._branches import branch_function
    from assur.plan import plan_of

    from .test_numbers import PARALLELOGRAM

    plan = plan_of(assur.loads(PARALLELOGRAM))
    own = plan.solvers[0].branch
    drive = np.radians([[90.0], [200.0], [-90.0], [400.0]])
    for upto in range(len(plan.solvers)):  # one scan gives every group's branches
        found = branch_function(plan)(drive, upto)
        np.testing.assert_array_equal(found[0], [own, -own, -own, own])
