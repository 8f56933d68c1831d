"""Values at a change point taken as their limits along the motion.

At a change point (a parallelogram four-bar at 0 and 180 degrees) a dyad's velocity
equations are singular, so a sweep refuses the position. The motion carries on
through it on the branch whose velocities are continuous (:mod:`assur._branches`),
and a quantity smooth along that motion, such as the reduced inertia or the loads'
torque, has there the value it tends to from either side.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from assur._branches import change_points
from assur._vec import Array
from assur._warn import held
from assur.plan import Plan

__all__ = ["across_change_points"]

NEAR = 1e-3
"""A crank angle this close to a change point (rad) takes the interpolated values:
the velocity equations are singular within about 1e-6 rad of it, and nearer than
about 1e-3 rad their rounding spoils the slope of the reduced inertia (1.4 times the
inertia at 1e-5 rad, 1.2e-4 at 5e-5 rad). Half the spacing ``STEP``: the cubic is
used between its two middle nodes."""
STEP = 2e-3
"""Spacing (rad) of the four positions, two either side of a change point, its values
are interpolated from (a cubic). Nearer it the sweep's rounding grows fast (the
discriminant touches zero there): as one over the distance squared in the positions'
rates, cubed in their second derivatives. At this distance the reduced inertia's
slope is off by about 1e-8 of the inertia; the cubic's own error is far smaller."""
NODES = np.array([-2.0, -1.0, 1.0, 2.0])
"""The four positions, in steps from the change point."""


def across_change_points(
    plan: Plan, angles: Array, evaluate: Callable[[Array], Sequence[Array]]
) -> list[Array]:
    """Return ``evaluate(angles)``, its values at change points interpolated.

    ``angles`` are crank angles (deg) of a one-crank plan; ``evaluate`` returns
    arrays of values at the angles it is given, one value per angle. The values at
    an angle within ``NEAR`` of a change point are interpolated by the cubic through
    those at ``STEP`` and twice that either side of it, on the branches the motion
    takes there.
    """
    at = _change_point_at(plan, angles)
    on = np.isfinite(at)
    if not on.any():
        return [np.asarray(v) for v in evaluate(angles)]
    step = math.degrees(STEP)
    # the positions around each change point met, node by node: their warnings
    # (near a dead centre) are of positions nobody asked for
    around = (at[on][None, :] + step * NODES[:, None]).ravel()
    with held():
        found = [np.asarray(v).reshape(NODES.shape[0], -1) for v in evaluate(around)]
    kept = [np.full(angles.shape, np.nan) for _ in found]
    rest = ~on
    if rest.any():
        for values, part in zip(kept, evaluate(angles[rest]), strict=True):
            values[rest] = part
    u = (angles[on] - at[on]) / step
    weights = []
    for i, node in enumerate(NODES):
        others = np.delete(NODES, i)
        weights.append(np.prod([(u - o) / (node - o) for o in others], axis=0))
    for values, near in zip(kept, found, strict=True):
        values[on] = np.sum(np.array(weights) * near, axis=0)
    return kept


def _change_point_at(plan: Plan, angles: Array) -> Array:
    """Return the change point (deg) each crank angle (deg) is within ``NEAR`` of.

    NaN for an angle near none.

    The change point is counted as the angle is: turns apart from the scanned one.
    """
    out = np.full(angles.shape, np.nan)
    found = change_points(plan) if len(plan.drivers) == 1 else None
    if found is None:
        return out
    x = np.radians(angles)
    for points in found.points:
        for c in points:
            gap = np.remainder(x - c + math.pi, 2.0 * math.pi) - math.pi
            near = np.abs(gap) < NEAR
            out[near] = np.degrees(x[near] - gap[near])
    return out
