"""A summary's couples and shaking moment read the same at any size of the mechanism.

The round-off of a couple or of the shaking moment is that of the reactions beside
it times the mechanism's size (:meth:`assur._running.Running.add`,
:data:`assur.summary.ROUND_OFF`); the shaking force's is the reactions' alone: where
two of them tie, and whether one is zero, must then not change when the whole
mechanism is scaled (a similarity: every force times the scale, every moment times
its square).
"""

from __future__ import annotations

import dataclasses
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur._running import TIE
from assur.summary import ROUND_OFF

from .mechanisms import moved

EXAMPLES = Path(__file__).parent.parent / "examples"


def _forces(mech: assur.Mechanism, scale: float, at: np.ndarray) -> assur.Table:
    """Return the forces of ``mech`` scaled by ``scale``, a large one without its
    warning that lengths are in metres."""
    with warnings.catch_warnings():
        warnings.filterwarnings(
            "ignore", "joints: the mechanism is", assur.AssurWarning
        )
        return assur.forces(moved(mech, 0.0, (0.0, 0.0), scale), at)


def _largest_reaction(table: assur.Table) -> float:
    """Return the table's largest joint reaction, N."""
    return max(float(np.max(table[c])) for c in table.columns if c.endswith(".F"))


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_a_near_tie_of_couples_is_decided_alike_at_any_size(scale: float) -> None:
    # the slot's couple peaks twice a turn; turned by 0.3 rad its two largest on a
    # 1 deg grid differ by 1e-4 of them, 1.5e-10 of the reactions times the size:
    # no tie. At a thousandth of the size that is below TIE times the reactions
    # alone, so a floor without the size called it a tie and gave the first
    mech = moved(assur.load(EXAMPLES / "whitworth.toml"), 0.3)
    at = np.arange(0.0, 360.0, 1.0)
    table = assur.forces(mech, at)
    other = _forces(mech, scale, at)
    top, second = np.sort(np.abs(other["slot.M"]))[-1:-3:-1]
    reactions = _largest_reaction(other)
    assert TIE * reactions * other.plan.scale < top - second
    if scale < 1.0:  # where the size decides: no tie beside the reactions alone
        assert top - second < TIE * reactions
    want, got = table.summary(), other.summary()
    assert got["slot.M.at"] == want["slot.M.at"]
    assert got["slot.M.max"] == pytest.approx(want["slot.M.max"] * scale**2, rel=1e-9)


def test_a_couple_of_round_off_is_zero_at_any_size() -> None:
    # the slider's guide carries no couple; its round-off grows with the
    # reactions times the size, so beside the reactions alone (a floor without
    # the size) a mechanism a million times larger had a couple
    mech = assur.load(EXAMPLES / "offset_slider_crank.toml")
    at = np.arange(0.0, 360.0, 1.0)
    table = _forces(mech, 1e6, at)
    size = _largest_reaction(table) * table.plan.scale
    assert 0.0 < np.max(np.abs(table["guide.M"])) < 1e-12 * size
    assert np.max(np.abs(table["guide.M"])) > 1e-12 * _largest_reaction(table)
    found = table.summary()
    assert (found["guide.M.max"], found["guide.M.at"]) == (0.0, at[0])


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_a_near_tie_of_shaking_moments_is_decided_alike_at_any_size(
    scale: float,
) -> None:
    # two positions 1e-7 deg apart, where the shaking moment grows: the second's
    # is larger by 7.6e-11 of the reactions times the size, no tie at any scale.
    # At a thousandth of the size that is below TIE times the reactions alone, so
    # a floor without the size called it a tie and gave the first position
    mech = assur.load(EXAMPLES / "offset_slider_crank.toml")
    at = np.array([90.0, 90.0 + 1e-7])
    table = assur.forces(mech, at)
    other = _forces(mech, scale, at)
    first, second = np.abs(other["shaking.M"])
    reactions = _largest_reaction(other)
    assert TIE * reactions * other.plan.scale < second - first
    if scale < 1.0:  # where the size decides: no tie beside the reactions alone
        assert second - first < TIE * reactions
    want, got = table.summary(), other.summary()
    assert want["shaking.M.at"] == at[1]
    assert got["shaking.M.at"] == want["shaking.M.at"]
    assert got["shaking.M.max"] == pytest.approx(
        want["shaking.M.max"] * scale**2, rel=1e-9
    )


def _spring_in_the_slot(force: float) -> assur.Mechanism:
    """Return the scotch yoke with a spring of ``force`` (N) along its slot.

    The spring pushes the block and the yoke apart along the slot's line through the
    crank pin: a pair of loads the frame never feels, and no moment.
    """
    mech = assur.load(EXAMPLES / "scotch_yoke.toml")
    spring = (
        assur.Load("yoke", "slot", (0.0, force)),
        assur.Load("block", "slot", (0.0, -force)),
    )
    return dataclasses.replace(mech, loads=spring)


def test_shaking_loads_are_told_from_round_off_each_by_its_own_unit() -> None:
    # The yoke's shaking moment about the crank's pivot is zero: every inertia
    # force (the crank's and the block's centripetal, the yoke's along the guide
    # through the pivot) passes through it, no link's turning speeds up, and the
    # spring's loads cancel on one line. Its round-off is the reactions' times the
    # size, so beside the reactions alone (a floor without the size) a mechanism
    # a million times larger had one. The shaking force, the yoke's inertia, is
    # real though 6e-8 of the spring's reactions: beside them times the size (the
    # moment's floor) it was taken for round-off
    at = np.arange(0.0, 360.0, 1.0)
    table = _forces(_spring_in_the_slot(1e9), 1e6, at)
    reactions = _largest_reaction(table)
    size = reactions * table.plan.scale
    moment = np.abs(table["shaking.M"])
    force = np.hypot(table["shaking.Fx"], table["shaking.Fy"])
    assert ROUND_OFF * reactions < np.max(moment) < ROUND_OFF * size
    assert ROUND_OFF * reactions < np.max(force) < ROUND_OFF * size
    found = table.summary()
    assert (found["shaking.M.max"], found["shaking.M.at"]) == (0.0, at[0])
    assert found["shaking.F.max"] == pytest.approx(np.max(force), rel=1e-12)
    # the pivot as far off the origin as the mechanism is large: the moment about
    # the origin is real, the shaking force's arm
    shifted = moved(_spring_in_the_slot(1e9), 0.0, (0.0, 1e5), 1e6)
    with warnings.catch_warnings():
        warnings.filterwarnings(
            "ignore", "joints: the mechanism is", assur.AssurWarning
        )
        far = assur.forces(shifted, at)
    moment = np.abs(far["shaking.M"])
    assert np.max(moment) > ROUND_OFF * _largest_reaction(far) * far.plan.scale
    found = far.summary()
    assert found["shaking.M.max"] == pytest.approx(np.max(moment), rel=1e-12)
    assert found["shaking.M.at"] == at[np.argmax(moment)]
