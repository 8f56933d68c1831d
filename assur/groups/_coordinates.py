"""A dyad's two coordinates: its links' poses, its Jacobian and their derivatives.

Sets both links' poses from their coordinates (rad or m) and solves the velocities,
accelerations and jerks with the middle pair's 2x2 Jacobian by Cramer's rule, element
by element over the batch.
"""

from __future__ import annotations

from math import comb
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._quiet import quiet
from assur._vec import add, dot, mul, sub
from assur.groups._motion import Motion, Vec, direction, point
from assur.groups._pairs import partials, residual

if TYPE_CHECKING:
    from assur.groups._dyad import DyadSolver

__all__ = [
    "Jacobian",
    "conditioning",
    "derivative",
    "guide",
    "jacobian",
    "linear_step",
    "set_pose",
    "signed_conditioning",
    "solve2",
]

Jacobian = tuple[Any, Any, Any, Any]
"""A dyad's 2x2 Jacobian ``(j00, j01, j10, j11)``: row = equation, column = link."""


def guide(plan: DyadSolver, bodies: list[Motion], b: int, k: int = 0) -> Vec:
    """k-th derivative of the slide direction of external prismatic pair ``b``."""
    axis = plan.ext[b].axis
    assert axis is not None
    return direction(bodies[plan.known[b]], axis, k)


def set_pose(plan: DyadSolver, bodies: list[Motion], q1: Any, q2: Any) -> None:
    """Create the position level of both links from their coordinates (rad or m)."""
    for b, q in ((0, q1), (1, q2)):
        known = bodies[plan.known[b]]
        ax, ay = point(known, plan.d_known[b], 0)
        if plan.ext[b].kind == "R":
            motion = Motion(
                [q, 0.0, 0.0, 0.0], [ax, 0.0, 0.0, 0.0], [ay, 0.0, 0.0, 0.0]
            )
        else:
            ex, ey = guide(plan, bodies, b)
            motion = Motion(
                [known.phi[0], 0.0, 0.0, 0.0],
                [add(ax, mul(q, ex)), 0.0, 0.0, 0.0],
                [add(ay, mul(q, ey)), 0.0, 0.0, 0.0],
            )
        motion.q = [q]
        bodies[plan.bodies[b]] = motion


def _fill(plan: DyadSolver, bodies: list[Motion], k: int) -> None:
    """Set level k of both links, their own k-th coordinate derivative taken as 0."""
    for b in (0, 1):
        known = bodies[plan.known[b]]
        m = bodies[plan.bodies[b]]
        ax, ay = point(known, plan.d_known[b], k)
        if plan.ext[b].kind == "R":
            m.phi[k] = 0.0
        else:
            m.phi[k] = known.phi[k]
            # Leibniz on sigma * e: the k-th term of sigma is the unknown
            for j in range(k):
                ex, ey = guide(plan, bodies, b, k - j)
                if ex.__class__ is float and ey.__class__ is float and not (ex or ey):
                    continue  # a guide that does not turn: no term
                coef = mul(float(comb(k, j)), m.q[j])
                ax, ay = add(ax, mul(coef, ex)), add(ay, mul(coef, ey))
        m.ox[k], m.oy[k] = ax, ay


def jacobian(plan: DyadSolver, bodies: list[Motion]) -> Jacobian:
    """Return the 2x2 Jacobian of the middle pair in the links' coordinates.

    Returns ``(j00, j01, j10, j11)``: row = equation, column = link.
    """
    cols = []
    for b in (0, 1):
        rows = partials(plan.mid, bodies, plan.bodies[b])
        if plan.ext[b].kind == "R":
            cols.append((rows[0][2], rows[1][2]))
        else:
            ex, ey = guide(plan, bodies, b)
            cols.append(tuple(dot((r[0], r[1]), (ex, ey)) for r in rows))
    return cols[0][0], cols[1][0], cols[0][1], cols[1][1]


def conditioning(plan: DyadSolver, jac: Jacobian) -> Any:
    """Sine of the angle between the Jacobian's columns: 0 at a dead centre.

    The absolute value of :func:`signed_conditioning`.
    """
    return np.abs(signed_conditioning(plan, jac))


def signed_conditioning(plan: DyadSolver, jac: Jacobian) -> Any:
    """Signed sine of the angle between the Jacobian's columns (its determinant's sign).

    The sign changes only where the pose passes a dead centre (or a change point,
    where the branch changes): :mod:`assur._reach` finds the dead centres a sweep
    would pass between two grid points. The sine does not change when a column is
    scaled, so the units of the links' coordinates (rad or m) do not matter; a
    prismatic pair's normal equation (m) is divided by the group's own size ``size``
    (m) to weigh like its rotation equation (rad). For an RRR dyad the measure is the
    sine of the transmission angle. It is dimensionless and does not change when the
    whole mechanism is scaled, nor when the group is one of a larger machine.
    """
    j00, j01, j10, j11 = jac
    # a pose that does not close (parallel slide lines, say) has infinite entries:
    # its conditioning is NaN, below every threshold, and no warning is due
    with quiet():
        if plan.mid.kind == "P":
            # the group's lever arms, not the machine's: a slider 0.3 m across in a
            # chain 12 m long is no nearer its dead centre than on its own
            j10, j11 = j10 / plan.size, j11 / plan.size
        det = j00 * j11 - j01 * j10
        return det / np.sqrt((j00 * j00 + j10 * j10) * (j01 * j01 + j11 * j11))


def solve2(jac: Jacobian, r0: Any, r1: Any) -> tuple[Any, Any]:
    """Solve ``J x = -r`` by Cramer's rule, element by element."""
    j00, j01, j10, j11 = jac
    with quiet():
        # numpy's division: a zero determinant gives inf or NaN, not an exception
        inv = np.divide(1.0, sub(mul(j00, j11), mul(j01, j10)))
        return mul(sub(mul(j01, r1), mul(j11, r0)), inv), mul(
            sub(mul(j10, r0), mul(j00, r1)), inv
        )


def linear_step(
    plan: DyadSolver, bodies: list[Motion], q1: Any, q2: Any
) -> tuple[Any, Any]:
    """Take one Newton step from ``(q1, q2)``: exact where the equations are linear."""
    set_pose(plan, bodies, q1, q2)
    x1, x2 = solve2(jacobian(plan, bodies), *residual(plan.mid, bodies, 0))
    return q1 + x1, q2 + x2


def derivative(plan: DyadSolver, bodies: list[Motion], k: int, jac: Jacobian) -> None:
    """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of both links.

    Notes
    -----
    The k-th derivative of the middle pair's equations is linear in the links' k-th
    coordinate derivatives with the Jacobian as matrix; the rest (centripetal, Coriolis
    and their derivatives) is the residual evaluated with those set to zero.
    """
    _fill(plan, bodies, k)
    x = solve2(jac, *residual(plan.mid, bodies, k))
    for b in (0, 1):
        m = bodies[plan.bodies[b]]
        del m.q[k:]
        m.q.append(x[b])
        if plan.ext[b].kind == "R":
            m.phi[k] = x[b]
        else:
            ex, ey = guide(plan, bodies, b)
            m.ox[k] = add(m.ox[k], mul(x[b], ex))
            m.oy[k] = add(m.oy[k], mul(x[b], ey))
