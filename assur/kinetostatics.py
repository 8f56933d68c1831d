"""Reverse pass: inertia loads, joint reactions group by group, balancing loads.

Every link gets its d'Alembert loads (``-m a_G`` at the centre of mass and ``-J_G
alpha``), gravity and external loads. The groups are then solved in the reverse order
of attachment, each statically determinate and receiving the reactions of the groups
solved before it; the driving links come last and give the balancing torque (or force).
The principle of virtual power gives the same balancing loads independently.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array
from assur.groups import _dyad, general
from assur.groups._dyad import DyadPlan, Wrench
from assur.groups._motion import Motion, point
from assur.groups.driver import balance
from assur.kinematics import KinematicState, velocity_coefficients
from assur.loads import LoadPlan, compile_loads, table_values
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
    """

    inertia_force: Array
    inertia_torque: Array
    reactions: dict[str, tuple[Array, Array]]
    balancing: Array
    check: Array
    shaking: Array
    residual: Array


def _full(value: Any, n: int) -> Array:
    """``value`` as an array of n entries."""
    return np.broadcast_to(np.asarray(value, dtype=float), (n,))


def applied_loads(plan: Plan, loads: LoadPlan, bodies: list[Motion],
                  state: KinematicState) -> tuple[list[Wrench], Array, Array]:
    """Return every link's applied wrench (inertia, gravity, external loads).

    Returns the wrenches ``[F_x, F_y, tau about the origin]`` per body and the inertia
    forces (n, B, 2) and torques (n, B).
    """
    n = state.drive.shape[0]
    count = len(plan.bodies)
    inertia_force = np.zeros((n, count, 2))
    inertia_torque = np.zeros((n, count))
    wrenches: list[Wrench] = [[0.0, 0.0, 0.0] for _ in range(count)]
    slides = {name: s[0] for name, s in state.slide.items()}
    gx, gy = loads.gravity
    for b in np.flatnonzero(loads.mass):
        m = bodies[b]
        mass = loads.mass[b]
        center = loads.center[b]
        px, py = point(m, center, 0)
        ax, ay = point(m, center, 2)
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
        t = value if isinstance(value, float) else table_values(
            value, plan, state.drive, slides, entry)[0]
        w = wrenches[b]
        wrenches[b] = [w[0], w[1], w[2] + t]
    return wrenches, inertia_force, inertia_torque


def solve(plan: Plan, bodies: list[Motion], state: KinematicState) -> ForceState:
    """Solve the kinetostatics of a sweep whose motion is ``bodies`` / ``state``."""
    n = state.drive.shape[0]
    loads = compile_loads(plan)
    applied, inertia_force, inertia_torque = applied_loads(plan, loads, bodies, state)
    wrenches = [list(w) for w in applied]
    raw: dict[str, tuple[Any, Any, Any]] = {}
    for solver in reversed(plan.solvers):
        if isinstance(solver, DyadPlan):
            _dyad.reactions(solver, bodies, wrenches, raw)
        else:
            general.reactions(solver, bodies, wrenches, raw, n)
    balancing = np.empty((n, len(plan.drivers)))
    for i, d in enumerate(plan.drivers):
        balancing[:, i] = balance(d, bodies, wrenches, raw)
    check = np.empty_like(balancing)
    for i in range(len(plan.drivers)):
        check[:, i] = _virtual_power(plan, bodies, applied, i)
    reactions = {}
    for name, (fx, fy, couple) in raw.items():
        force = np.empty((n, 2))
        force[:, 0], force[:, 1] = fx, fy
        reactions[name] = (force, _full(couple, n))
    shaking = np.empty((n, 3))
    for i in range(3):
        shaking[:, i] = wrenches[0][i]
    residual = _residual(plan, bodies, applied, reactions, balancing)
    return ForceState(inertia_force, inertia_torque, reactions, balancing, check,
                      shaking, residual)


def _virtual_power(plan: Plan, bodies: list[Motion], applied: list[Wrench],
                   which: int) -> Any:
    """Balancing load of driver ``which`` from the principle of virtual power.

    Notes
    -----
    For a unit speed of the driver (the others held), the power of the balancing load
    plus that of every applied load (inertia loads included) is zero:
    :math:`T = -\\sum_b (F_b \\cdot v_{b,O} + \\tau_{b,O}\\,\\omega_b)`, where
    :math:`v_{b,O} = v_b - \\omega_b o_b^\\perp` is the velocity of the body point at the
    origin about which :math:`\\tau_{b,O}` is taken.
    """
    coeff = velocity_coefficients(plan, bodies, which)
    total: Any = 0.0
    for b in range(1, len(plan.bodies)):
        fx, fy, tau = applied[b]
        if not (np.ndim(fx) or np.ndim(tau) or fx or fy or tau):
            continue  # a massless, unloaded link does no work
        m, v = bodies[b], coeff[b]
        w = v.phi[1]
        total = total + fx * (v.ox[1] + w * m.oy[0]) + fy * (v.oy[1] - w * m.ox[0]) + tau * w
    return -total


def _residual(plan: Plan, bodies: list[Motion], applied: list[Wrench],
              reactions: dict[str, tuple[Array, Array]], balancing: Array) -> Array:
    """Largest unbalanced force (N) and moment about the link's origin (N m)."""
    totals = [list(w) for w in applied]
    for name, (force, couple) in reactions.items():
        pair = plan.pairs[name]
        qx, qy = point(bodies[pair.second], pair.d_second, 0)
        fx, fy = force[:, 0], force[:, 1]
        tau = qx * fy - qy * fx + couple
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            t = totals[body]
            totals[body] = [t[0] + sign * fx, t[1] + sign * fy, t[2] + sign * tau]
    for i, d in enumerate(plan.drivers):
        t = totals[d.body]
        if d.kind == "R":
            totals[d.body] = [t[0], t[1], t[2] + balancing[:, i]]
        else:
            ex, ey = d.pair.axis  # type: ignore[misc]
            fx, fy = balancing[:, i] * ex, balancing[:, i] * ey
            m = bodies[d.body]
            totals[d.body] = [t[0] + fx, t[1] + fy, t[2] + m.ox[0] * fy - m.oy[0] * fx]
    n = balancing.shape[0]
    force = np.zeros(n)
    moment = np.zeros(n)
    for b in range(1, len(plan.bodies)):
        fx, fy, tau = totals[b]
        m = bodies[b]
        force = np.maximum(force, np.maximum(np.abs(fx), np.abs(fy)))
        moment = np.maximum(moment, np.abs(tau - (m.ox[0] * fy - m.oy[0] * fx)))
    return np.stack((force, moment), axis=-1)
