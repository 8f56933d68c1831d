"""Change points on the straight paths of several drivers (``assur._paths``).

Each position of a sweep with several drivers is reached along its own straight path
from the reference pose; a dyad's branch flips once for each change point on it. The
checks are geometric: a dyad that forms a parallelogram with a link and the frame
stays one (its links turn as that link does) only on the branch the change points
give it.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import assur
from assur._paths import _flips, _sampled

from .conftest import DATA

TWO_CRANKS_CLASS3 = DATA / "edge" / "two_cranks_class3_parallelogram.toml"
TWO_TRIADS = DATA / "edge" / "two_triads_two_cranks.toml"
ONE_TRIAD = DATA / "edge" / "class3_parallelogram.toml"


def _sweep(angles: np.ndarray) -> tuple[assur.Table, list[str]]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(assur.load(TWO_CRANKS_CLASS3), angles)
    return table, [str(w.message) for w in caught]


def _parallel(table: assur.Table) -> None:
    """Assert that po turns as the left rocker does (the parallelogram holds)."""
    gap = (table["po.angle"] - table["left_rocker.angle"] + 180.0) % 360.0 - 180.0
    np.testing.assert_allclose(gap - gap[0], 0.0, atol=1e-6)
    np.testing.assert_allclose(
        table["po.omega"], table["left_rocker.omega"], rtol=1e-7, atol=1e-7
    )


def test_a_dyad_after_a_triad_on_two_cranks_stays_a_parallelogram():
    """Its change points were not looked for after the triad: between 80 and 265
    deg po was up to 52 deg off the rocker's direction, with a warning of a dead
    centre alone."""
    crank = np.arange(30.0, 390.0, 5.0)
    table, said = _sweep(np.stack([np.full_like(crank, 90.0), crank], axis=1))
    _parallel(table)
    changes = [s for s in said if "change point" in s]
    assert len(changes) == 1, said
    assert changes[0].startswith(
        "group RRR (pc, po): its two assembly branches meet on the straight path "
        "from the reference pose to driver positions (90 deg, 80 deg) to (90 deg, "
        "265 deg) (a change point)"
    ), changes


@pytest.mark.parametrize(
    "angles",
    [
        np.stack(np.meshgrid([-90.0, 120.0, 500.0], np.arange(-300.0, 400.0, 41.0)))
        .reshape(2, -1)
        .T,
        np.array([[195.0, -30.0], [-170.0, 400.0], [425.0, 95.0], [-250.0, 60.0]]),
    ],
    ids=["grid", "apart"],
)
def test_the_parallelogram_holds_wherever_both_cranks_go(angles):
    """Paths that turn both cranks, some through both change points."""
    table, _ = _sweep(angles)
    _parallel(table)


def test_two_triads_on_two_cranks_move_as_each_does_alone():
    """Two Newton groups with a dyad of change points between them: each copy moves
    as the one-crank file does on its own crank (the change points of both dyads
    crossed on the paths)."""
    first = np.array([-170.0, 30.0, 95.0, 265.0, 420.0])
    second = np.array([-100.0, 85.0, 270.0])
    angles = np.stack(np.meshgrid(first, second)).reshape(2, -1).T
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        both = assur.kinematics(assur.load(TWO_TRIADS), angles)
        one = assur.load(ONE_TRIAD)
        alone = [assur.kinematics(one, angles[:, i]) for i in (0, 1)]
    for suffix, table in zip(("", "_2"), alone, strict=True):
        gap = (both[f"po{suffix}.angle"] - table["po.angle"] + 180.0) % 360.0 - 180.0
        np.testing.assert_allclose(gap, 0.0, atol=1e-8)
        np.testing.assert_allclose(
            both[f"po{suffix}.omega"], table["po.omega"], rtol=1e-8, atol=1e-8
        )


def test_a_change_point_behind_the_reference_pose_flips_the_sample_behind_it():
    """A change point between the sample behind the reference pose and the reference
    pose itself lies on the way to that sample only; those ahead of the reference
    pose were flipped instead. One ahead flips every sample from it on."""
    drive = np.array([[1.0], [2.0]])
    paths = _sampled(np.zeros(1), drive, np.array([4, 8]))
    where = np.array([0, 1])
    s = np.array([-0.1, 0.3])
    count, branch = _flips(1.0, paths, where, s)
    np.testing.assert_array_equal(count, [0, 1])
    # path 0: samples j = -1..5; path 1: j = -1..9 (change point at j = 2.4)
    path0 = [-1, 1, 1, 1, 1, 1, 1]
    path1 = [1, 1, 1, 1, -1, -1, -1, -1, -1, -1, -1]
    np.testing.assert_array_equal(branch, path0 + path1)
