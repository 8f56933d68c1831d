"""A sliding pair's couple far from the origin: the same as near it.

A slot's or a guide's couple is a moment about a point of the pair, whose arm is a
difference of coordinates: a mechanism shifted almost as far as :data:`assur.plan.FAR`
of its sizes from the origin (its coordinates then keep nine digits of its shape)
gives the same reactions, couples and summary as at the origin, but for the moments
about the origin (the shaking moment), which the shift changes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import assur
from assur.plan import FAR
from assur.summary import ROUND_OFF

from .mechanisms import moved

EXAMPLES = Path(__file__).parent.parent / "examples"
SLOTS = ["whitworth", "scotch_yoke", "slot_mechanism"]


def _far(mech: assur.Mechanism, size: float) -> assur.Mechanism:
    """Return ``mech`` shifted 0.9 FAR of its size ``size`` (m) from the origin."""
    return moved(mech, 0.0, (0.9 * FAR * size, -0.6 * FAR * size))


@pytest.mark.parametrize("name", SLOTS)
def test_far_from_the_origin_the_reactions_and_couples_are_the_same(name: str) -> None:
    mech = assur.load(EXAMPLES / f"{name}.toml")
    at = np.arange(0.0, 360.0, 5.0)
    near = assur.forces(mech, at)
    size = near.plan.scale
    far = assur.forces(_far(mech, size), at)
    largest = max(float(np.max(near[c])) for c in near.columns if c.endswith(".F"))
    for column in near.columns:
        if near.column(column).family != "reaction":
            continue
        moment = near.column(column).unit == "N m"
        # each against its own peak; one of round-off (a component, a couple that
        # is zero) against the reactions' round-off, times the size for a couple
        floor = ROUND_OFF * largest * (size if moment else 1.0)
        peak = float(np.max(np.abs(near[column])))
        np.testing.assert_allclose(
            far[column],
            near[column],
            rtol=0.0,
            atol=1e-6 * peak + floor,
            err_msg=column,
        )


@pytest.mark.parametrize("name", SLOTS)
def test_far_from_the_origin_the_summary_is_the_same(name: str) -> None:
    mech = assur.load(EXAMPLES / f"{name}.toml")
    at = np.arange(0.0, 360.0, 1.0)
    near = assur.forces(mech, at)
    want, got = near.summary(), assur.forces(_far(mech, near.plan.scale), at).summary()
    assert list(got) == list(want)
    for key, value in want.items():
        if key.startswith("shaking.M."):
            continue  # about the origin, which moved
        if key.endswith(".at"):
            assert got[key] == value, key
        else:
            assert got[key] == pytest.approx(value, rel=1e-6, abs=1e-9), key
