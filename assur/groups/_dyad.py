"""What every dyad (class II group) shares: its coordinates, derivatives and reactions.

Each of a dyad's two links hangs on a known link by an external pair, which leaves it
one coordinate: its rotation (revolute pair, the body's origin is the pin) or its slide
along the guide (prismatic pair, the body turns with the guide). The middle pair gives
two equations in those two coordinates. Positions are closed form, one module per kind;
velocities, accelerations and jerks solve the same 2x2 Jacobian with Cramer's rule,
element by element over the batch; reactions eliminate the external pairs with one
equation per link (the virtual power along that link's own coordinate).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import comb
from typing import Any

import numpy as np

from assur.groups._motion import Motion, Vec, direction, point
from assur.groups._pairs import PairPlan, partials, residual, unit_wrenches

__all__ = ["DyadPlan", "Wrench", "derivative", "jacobian", "reactions", "set_pose"]

Wrench = list[Any]
"""``[F_x, F_y, tau]``: a force (N) and its moment about the fixed origin (N m)."""
Jacobian = tuple[Any, Any, Any, Any]


@dataclass(frozen=True, slots=True)
class DyadPlan:
    """Precomputed data of one dyad.

    ``bodies`` are the two links' indices in signature order, ``ext`` their external
    pairs, ``mid`` the middle pair, ``known`` the known links the external pairs join,
    ``d_known`` the external pairs' offsets on those links, ``d_mid`` the middle pair's
    offsets on the two links, ``branch`` the assembly branch (+1 or -1).
    """

    kind: str
    label: str
    bodies: tuple[int, int]
    ext: tuple[PairPlan, PairPlan]
    mid: PairPlan
    known: tuple[int, int]
    d_known: tuple[tuple[float, float], tuple[float, float]]
    d_mid: tuple[tuple[float, float], tuple[float, float]]
    branch: float = 1.0


def guide(plan: DyadPlan, bodies: list[Motion], b: int, k: int = 0) -> Vec:
    """k-th derivative of the slide direction of external prismatic pair ``b``."""
    axis = plan.ext[b].axis
    assert axis is not None
    return direction(bodies[plan.known[b]], axis, k)


def set_pose(plan: DyadPlan, bodies: list[Motion], q1: Any, q2: Any) -> None:
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
                [ax + q * ex, 0.0, 0.0, 0.0],
                [ay + q * ey, 0.0, 0.0, 0.0],
            )
        motion.q = [q]
        bodies[plan.bodies[b]] = motion


def _fill(plan: DyadPlan, bodies: list[Motion], k: int) -> None:
    """Set level k of both links, their own k-th coordinate derivative taken as 0."""
    for b in (0, 1):
        known = bodies[plan.known[b]]
        m = bodies[plan.bodies[b]]
        ax, ay = point(known, plan.d_known[b], k)
        if plan.ext[b].kind == "R":
            m.phi[k] = 0.0
        else:
            m.phi[k] = known.phi[k]
            for j in range(
                k
            ):  # Leibniz on sigma * e, the k-th term of sigma is unknown
                ex, ey = guide(plan, bodies, b, k - j)
                if ex.__class__ is float and ey.__class__ is float and not (ex or ey):
                    continue  # a guide that does not turn: no term
                coef = comb(k, j) * m.q[j]
                ax, ay = ax + coef * ex, ay + coef * ey
        m.ox[k], m.oy[k] = ax, ay


def jacobian(plan: DyadPlan, bodies: list[Motion]) -> Jacobian:
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
            cols.append(tuple(r[0] * ex + r[1] * ey for r in rows))
    return cols[0][0], cols[1][0], cols[0][1], cols[1][1]


def conditioning(plan: DyadPlan, jac: Jacobian, scale: float) -> Any:
    """Sine of the angle between the Jacobian's columns: 0 at a dead centre.

    The sine does not change when a column is scaled, so the units of the links'
    coordinates (rad or m) do not matter; a prismatic pair's normal equation is divided
    by the mechanism's size ``scale`` (m) to weigh like its rotation equation. For an
    RRR dyad the measure is the sine of the transmission angle.
    """
    j00, j01, j10, j11 = jac
    if plan.mid.kind == "P":
        j10, j11 = j10 / scale, j11 / scale
    det = j00 * j11 - j01 * j10
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(det) / np.sqrt((j00 * j00 + j10 * j10) * (j01 * j01 + j11 * j11))


def solve2(jac: Jacobian, r0: Any, r1: Any) -> tuple[Any, Any]:
    """Solve ``J x = -r`` by Cramer's rule, element by element."""
    j00, j01, j10, j11 = jac
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / (j00 * j11 - j01 * j10)
        return (j01 * r1 - j11 * r0) * inv, (j10 * r0 - j00 * r1) * inv


def linear_step(
    plan: DyadPlan, bodies: list[Motion], q1: Any, q2: Any
) -> tuple[Any, Any]:
    """Take one Newton step from ``(q1, q2)``: exact where the equations are linear."""
    set_pose(plan, bodies, q1, q2)
    x1, x2 = solve2(jacobian(plan, bodies), *residual(plan.mid, bodies, 0))
    return q1 + x1, q2 + x2


def derivative(plan: DyadPlan, bodies: list[Motion], k: int, jac: Jacobian) -> None:
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
            m.ox[k] = m.ox[k] + x[b] * ex
            m.oy[k] = m.oy[k] + x[b] * ey


def _eliminator(plan: DyadPlan, bodies: list[Motion], b: int) -> tuple[Any, Any, Any]:
    """Weights (w_x, w_y, w_tau) of the equation of link b free of its external pair.

    Revolute: moments about the pin. Prismatic: forces along the guide.
    """
    if plan.ext[b].kind == "R":
        m = bodies[plan.bodies[b]]
        return m.oy[0], -m.ox[0], 1.0
    ex, ey = guide(plan, bodies, b)
    return ex, ey, 0.0


def reactions(
    plan: DyadPlan,
    bodies: list[Motion],
    wrenches: list[Wrench],
    out: dict[str, tuple[Any, Any, Any]],
) -> None:
    """Solve the dyad's three reactions and pass the external ones to the known links.

    Parameters
    ----------
    wrenches : list of Wrench
        The known loads on every body (inertia, gravity, external, and reactions of
        groups solved already); the known links' entries are increased by the
        reactions of this dyad.
    out : dict
        Receives, per pair name, the force ``(F_x, F_y)`` (N) exerted by its first link
        on its second and the couple (N m) about the pair's point (zero for revolute
        pairs).
    """
    cols = unit_wrenches(plan.mid, bodies)
    rows, rhs, signs = [], [], []
    for b in (0, 1):
        wx, wy, wt = _eliminator(plan, bodies, b)
        sign = 1.0 if plan.bodies[b] == plan.mid.second else -1.0
        rows.append([sign * (wx * c[0] + wy * c[1] + wt * c[2]) for c in cols])
        load = wrenches[plan.bodies[b]]
        rhs.append(wx * load[0] + wy * load[1] + wt * load[2])
        signs.append(sign)
    lam0, lam1 = solve2(
        (rows[0][0], rows[0][1], rows[1][0], rows[1][1]), rhs[0], rhs[1]
    )
    mid = [lam0 * cols[0][i] + lam1 * cols[1][i] for i in range(3)]
    record(plan.mid, bodies, mid, out)
    for b in (0, 1):
        body = plan.bodies[b]
        total = [wrenches[body][i] + signs[b] * mid[i] for i in range(3)]
        known = wrenches[plan.known[b]]
        for i in range(3):
            known[i] = known[i] + total[i]
        pair = plan.ext[b]
        record(pair, bodies, total if pair.second != body else [-t for t in total], out)


def record(
    pair: PairPlan,
    bodies: list[Motion],
    wrench: Wrench,
    out: dict[str, tuple[Any, Any, Any]],
) -> None:
    """Store the wrench of ``pair`` on its second link as force and couple."""
    fx, fy, tau = wrench
    if pair.kind == "R":
        out[pair.name] = (fx, fy, 0.0)
        return
    qx, qy = point(bodies[pair.second], pair.d_second, 0)
    out[pair.name] = (fx, fy, tau - (qx * fy - qy * fx))
