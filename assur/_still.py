"""When a pair is at rest: the speeds below which its friction has no sense.

Kinetic friction only: a pair whose links do not move relative to each other has
none. A relative speed below :data:`STILL` times the mechanism's fastest motion at
that position is rounding, not motion, and its sign would pick the friction's sense
at random. The reverse pass (:mod:`assur._friction`) and the note read one threshold.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from assur._vec import Leaf, mul, norm, sub
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan, slide

__all__ = ["STILL", "Still", "rate", "still"]

STILL = 1e-11
"""A pair's relative speed, as a fraction of the fastest motion of the mechanism at
that position (rad/s, or m/s per mechanism size), below which the pair is at rest."""


@dataclass(frozen=True, slots=True)
class Still:
    """The speeds below which a pair is at rest, per position.

    ``turn`` is the relative angular speed (rad/s) below which a revolute pair is
    at rest; a prismatic pair's slide speed is compared with ``turn * size`` (m/s).
    """

    turn: Leaf
    size: float


def still(bodies: list[Motion], size: float) -> Still:
    """Return the rest thresholds of a batch whose motions are ``bodies``.

    The fastest motion is the largest angular speed of a link or speed of a link's
    origin per mechanism ``size`` (m); its ``STILL`` fraction is the threshold.
    """
    parts = [np.abs(b.phi[1]) for b in bodies]
    # a mechanism with every joint at one point has no size to divide by
    parts += [norm(b.ox[1], b.oy[1]) / max(size, 1e-12) for b in bodies]
    return Still(STILL * functools.reduce(np.maximum, parts, 0.0), size)


def rate(pair: PairPlan, bodies: list[Motion], rest: Still) -> Leaf:
    """Return the relative speed a pair's friction opposes, zero where at rest.

    The second link's angular speed relative to the first's (rad/s), or the slide's
    speed (m/s); a speed below the ``rest`` threshold is returned as exactly zero.
    """
    if pair.kind == "R":
        speed = sub(bodies[pair.second].phi[1], bodies[pair.first].phi[1])
        limit = rest.turn
    else:
        speed = slide(pair, bodies, 1)
        limit = mul(rest.turn, rest.size)
    return np.where(np.abs(speed) > limit, speed, 0.0)
