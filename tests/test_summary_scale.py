"""A summary's couples read the same at any size of the mechanism.

A couple's round-off is that of the reactions beside it times the mechanism's size
(:meth:`assur._running.Running.add`, :data:`assur.summary.ROUND_OFF`): where two
couples tie, and whether a couple is zero, must then not change when the whole
mechanism is scaled (a similarity: every force times the scale, every moment times
its square).
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur._running import TIE

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
