"""Reverse pass: inertia loads, joint reactions group by group, balancing loads.

Every link gets its d'Alembert loads (``-m a_G`` at the centre of mass and ``-J_G
alpha``), gravity and external loads. The groups are then solved in the reverse order
of attachment, each statically determinate and receiving the reactions of the groups
solved before it; the driving links come last and give the balancing torque (or force).
The principle of virtual power gives the same balancing loads independently.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._kinematics import KinematicState, velocity_coefficients
from assur._loads import LoadPlan, compile_loads, table_values
from assur._vec import Array
from assur.groups import _dyad, general
from assur.groups._dyad import DyadPlan, Wrench
from assur.groups._motion import Motion, point, rotated
from assur.groups._pairs import PairPlan
from assur.groups.driver import balance
from assur.plan import Plan

__all__ = ["ForceState", "applied_loads", "solve"]


@dataclass(frozen=True, slots=True)
class ForceState:
    """Loads and reactions over a sweep.

    Attributes
    ----------
    inertia_force : ndarray (n, B, 2)
        ``-m a_G`` of every link, N.
    inertia_torque : ndarray (n, B)
        ``-J_G alpha``, N m.
    reactions : dict of str to (ndarray (n, 2), ndarray (n,))
        Per pair: force exerted by its first link on its second (N) and, for prismatic
        pairs, the couple about the pair's point moving with the second link (N m).
    balancing, check : ndarray (n, d)
        Balancing torque (N m) or force (N) per driver, from equilibrium and from the
        principle of virtual power.
    shaking : ndarray (n, 3)
        Resultant force (N) and moment about the origin (N m) of all loads on the frame.
    residual : ndarray (n, 2)
        Largest force (N) and moment (N m) left unbalanced on any link.
    magnitude : dict of str to ndarray (n,)
        Magnitude of every pair's reaction force, N.
    offset : dict of str to ndarray (n,)
        For prismatic pairs: where the normal force acts, m along the axis from the
        pair's point (NaN without normal force).
    """

    inertia_force: Array
    inertia_torque: Array
    reactions: dict[str, tuple[Array, Array]]
    balancing: Array
    check: Array
    shaking: Array
    residual: Array
    magnitude: dict[str, Array] = field(default_factory=dict)
    offset: dict[str, Array] = field(default_factory=dict)


def applied_loads(
    plan: Plan,
    loads: LoadPlan,
    bodies: list[Motion],
    state: KinematicState,
    inertia_force: Array,
    inertia_torque: Array,
) -> list[Wrench]:
    """Return every link's applied wrench (inertia, gravity, external loads).

    Returns the wrenches ``[F_x, F_y, tau about the origin]`` per body; the inertia
    forces (n, B, 2) and torques (n, B) are written to the arrays given.
    """
    count = len(plan.bodies)
    wrenches: list[Wrench] = [[0.0, 0.0, 0.0] for _ in range(count)]
    slides = {name: s[0] for name, s in state.slide.items()}
    gx, gy = loads.gravity
    for b in np.flatnonzero(loads.mass):
        m = bodies[b]
        mass = loads.mass[b]
        p = loads.center_point[b]  # the centre's motion is in the state already
        px, py = state.point[0, :, p, 0], state.point[0, :, p, 1]
        ax, ay = state.point[2, :, p, 0], state.point[2, :, p, 1]
        fx, fy = -mass * ax, -mass * ay
        torque = -loads.inertia[b] * m.phi[2]
        inertia_force[:, b, 0], inertia_force[:, b, 1] = fx, fy
        inertia_torque[:, b] = torque
        fx, fy = fx + mass * gx, fy + mass * gy
        wrenches[b] = [fx, fy, px * fy - py * fx + torque]
    for b, offset, value, entry in loads.forces:
        px, py = point(bodies[b], offset, 0)
        if isinstance(value, tuple):
            fx, fy = value
        else:
            fx, fy = table_values(value, plan, state.drive, slides, entry)
        w = wrenches[b]
        wrenches[b] = [w[0] + fx, w[1] + fy, w[2] + px * fy - py * fx]
    for b, value, entry in loads.torques:
        t = (
            value
            if isinstance(value, float)
            else table_values(value, plan, state.drive, slides, entry)[0]
        )
        w = wrenches[b]
        wrenches[b] = [w[0], w[1], w[2] + t]
    return wrenches


def allocate(plan: Plan, n: int) -> ForceState:
    """Return a writable force state for ``n`` driver positions, filled by chunks."""
    count, drivers = len(plan.bodies), len(plan.drivers)
    # a revolute pair has no couple: its entries share one array of zeros, never written
    none = np.zeros(n)
    reactions = {
        name: (np.empty((2, n)).T, np.empty(n) if p.kind == "P" else none)
        for name, p in plan.pairs.items()
    }
    return ForceState(
        np.zeros((2, count, n)).transpose(2, 1, 0),
        np.zeros((count, n)).T,
        reactions,
        np.empty((drivers, n)).T,
        np.empty((drivers, n)).T,
        np.empty((3, n)).T,
        np.empty((2, n)).T,
        {name: np.empty(n) for name in plan.pairs},
        {name: np.empty(n) for name, p in plan.pairs.items() if p.kind == "P"},
    )


def freeze(state: ForceState) -> ForceState:
    """Make every array of ``state`` read-only."""
    arrays = [
        state.inertia_force,
        state.inertia_torque,
        state.balancing,
        state.check,
        state.shaking,
        state.residual,
    ]
    for force, couple in state.reactions.values():
        arrays += [force, couple]
    arrays += [*state.magnitude.values(), *state.offset.values()]
    for arr in arrays:
        arr.flags.writeable = False
    return state


def solve(
    plan: Plan,
    bodies: list[Motion],
    state: KinematicState,
    out: ForceState | None = None,
    start: int = 0,
) -> ForceState:
    """Solve the kinetostatics of the chunk whose motion is ``bodies`` / ``state``.

    The results go to rows ``start`` to ``start + n`` of ``out`` (allocated when not
    given), which is returned.
    """
    n = state.drive.shape[0]
    if out is None:
        out = allocate(plan, n)
    rows = slice(start, start + n)
    loads = compile_loads(plan)
    applied = applied_loads(
        plan, loads, bodies, state, out.inertia_force[rows], out.inertia_torque[rows]
    )
    wrenches = [list(w) for w in applied]
    raw: dict[str, tuple[Any, Any, Any]] = {}
    for solver in reversed(plan.solvers):
        if isinstance(solver, DyadPlan):
            _dyad.reactions(solver, bodies, wrenches, raw)
        else:
            general.reactions(solver, bodies, wrenches, raw, n)
    balancing = out.balancing[rows]
    for i, d in enumerate(plan.drivers):
        balancing[:, i] = balance(d, bodies, wrenches, raw)
        out.check[rows, i] = _virtual_power(plan, bodies, applied, i, n)
    reactions = {}
    for name, (fx, fy, couple) in raw.items():
        force, moment = out.reactions[name]
        force[rows, 0], force[rows, 1] = fx, fy
        if plan.pairs[name].kind == "P":
            moment[rows] = couple
        reactions[name] = (force[rows], moment[rows])
    for i in range(3):
        out.shaking[rows, i] = wrenches[0][i]
    out.residual[rows] = _residual(plan, bodies, applied, reactions, balancing, state)
    for name, (force, couple) in reactions.items():
        out.magnitude[name][rows] = np.sqrt(force[:, 0] ** 2 + force[:, 1] ** 2)
        pair = plan.pairs[name]
        if pair.kind == "P":
            out.offset[name][rows] = _offset(pair, bodies, force, couple)
    return out


def _virtual_power(
    plan: Plan, bodies: list[Motion], applied: list[Wrench], which: int, n: int
) -> Any:
    r"""Balancing load of driver ``which`` from the principle of virtual power.

    Notes
    -----
    For a unit speed of the driver (the others held), the power of the balancing load
    plus that of every applied load (inertia loads included) is zero:
    :math:`T = -\sum_b (F_b \cdot v_{b,O} + \tau_{b,O}\,\omega_b)`, where
    :math:`v_{b,O} = v_b - \omega_b o_b^\perp` is the velocity of the body point at the
    origin about which :math:`\tau_{b,O}` is taken.
    """
    speed = plan.drivers[which].omega
    if len(plan.drivers) == 1 and speed:
        coeff, scale = bodies, 1.0 / speed  # velocities are linear in the one speed
    else:
        coeff, scale = velocity_coefficients(plan, bodies, which, n), 1.0
    total: Any = 0.0
    for b in range(1, len(plan.bodies)):
        fx, fy, tau = applied[b]
        if not (np.ndim(fx) or np.ndim(tau) or fx or fy or tau):
            continue  # a massless, unloaded link does no work
        m, v = bodies[b], coeff[b]
        w = v.phi[1]
        total = (
            total
            + fx * (v.ox[1] + w * m.oy[0])
            + fy * (v.oy[1] - w * m.ox[0])
            + tau * w
        )
    return -scale * total


def _offset(pair: PairPlan, bodies: list[Motion], force: Array, couple: Array) -> Array:
    """Where a prismatic pair's normal force acts: distance along the axis (m).

    The couple about the pair's point moves the resultant normal force ``N`` by
    ``M / N`` along the slide line; NaN where there is no normal force.
    """
    nx, ny = rotated(bodies[pair.first], pair.normal)
    normal = force[:, 0] * nx + force[:, 1] * ny
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(np.abs(normal) > 1e-12, couple / normal, np.nan)


def _residual(
    plan: Plan,
    bodies: list[Motion],
    applied: list[Wrench],
    reactions: dict[str, tuple[Array, Array]],
    balancing: Array,
    state: KinematicState,
) -> Array:
    """Largest unbalanced force (N) and moment about the link's origin (N m).

    Every link's loads are summed again from the applied loads, the reactions of all
    its pairs and the balancing loads: an independent check of the reverse pass.
    """
    n = balancing.shape[0]
    # rows: the bodies; one array per component, summed in place
    total = np.empty((3, len(plan.bodies), n))
    for b, wrench in enumerate(applied):
        for i in range(3):
            total[i, b] = wrench[i]
    for name, (force, couple) in reactions.items():
        pair = plan.pairs[name]
        p = plan.point_index.get(name)
        if p is None:
            qx, qy = point(bodies[pair.second], pair.d_second, 0)
        else:
            qx, qy = state.point[0, :, p, 0], state.point[0, :, p, 1]
        fx, fy = force[:, 0], force[:, 1]
        tau = qx * fy - qy * fx
        if pair.kind == "P":
            tau += couple
        for i, value in enumerate((fx, fy, tau)):
            total[i, pair.second] += value
            total[i, pair.first] -= value
    for i, d in enumerate(plan.drivers):
        if d.kind == "R":
            total[2, d.body] += balancing[:, i]
        else:
            ex, ey = d.pair.axis  # type: ignore[misc]
            fx, fy = balancing[:, i] * ex, balancing[:, i] * ey
            m = bodies[d.body]
            total[0, d.body] += fx
            total[1, d.body] += fy
            total[2, d.body] += m.ox[0] * fy - m.oy[0] * fx
    moving = total[:, 1:]
    ox, oy = state.origin[:, 1:, 0].T, state.origin[:, 1:, 1].T
    moment = np.abs(moving[2] - (ox * moving[1] - oy * moving[0])).max(axis=0)
    force = np.maximum(np.abs(moving[0]).max(axis=0), np.abs(moving[1]).max(axis=0))
    return np.stack((force, moment), axis=-1)
