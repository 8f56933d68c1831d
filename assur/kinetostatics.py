"""Reverse pass: inertia loads, joint reactions group by group, balancing loads.

Every link gets its d'Alembert loads (``-m a_G`` at the centre of mass and ``-J_G
alpha``), gravity and external loads. The groups are then solved in the reverse order
of attachment, each statically determinate and receiving the reactions of the groups
solved before it; the driving links come last and give the balancing torque (or force).
The principle of virtual power gives the same balancing loads independently.
"""

from __future__ import annotations

from dataclasses import dataclass

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
    zero = np.zeros(n)
    wrenches: list[Wrench] = [[zero, zero, zero] for _ in range(count)]
    slides = {name: s[0] for name, s in state.slide.items()}
    for b in np.flatnonzero(loads.mass):
        m = bodies[b]
        g = point(m, loads.center[b], 0)
        acc = point(m, loads.center[b], 2)
        fi = -loads.mass[b] * acc
        inertia_force[:, b] = fi
        inertia_torque[:, b] = -loads.inertia[b] * m.phi[2]
        f = fi + loads.mass[b] * loads.gravity
        wrenches[b] = [f[:, 0], f[:, 1],
                       g[:, 0] * f[:, 1] - g[:, 1] * f[:, 0] + inertia_torque[:, b]]
    for b, offset, value, entry in loads.forces:
        p = point(bodies[b], offset, 0)
        fx, fy = (table_values(value, plan, state.drive, slides, entry)
                  if not isinstance(value, np.ndarray) else (value[0], value[1]))
        w = wrenches[b]
        wrenches[b] = [w[0] + fx, w[1] + fy, w[2] + p[:, 0] * fy - p[:, 1] * fx]
    for b, value, entry in loads.torques:
        t = (table_values(value, plan, state.drive, slides, entry)[0]
             if not isinstance(value, int | float) else value)
        w = wrenches[b]
        wrenches[b] = [w[0], w[1], w[2] + t]
    return wrenches, inertia_force, inertia_torque


def solve(plan: Plan, bodies: list[Motion], state: KinematicState) -> ForceState:
    """Solve the kinetostatics of a sweep whose motion is ``bodies`` / ``state``."""
    loads = compile_loads(plan)
    applied, inertia_force, inertia_torque = applied_loads(plan, loads, bodies, state)
    wrenches = [list(w) for w in applied]
    reactions: dict[str, tuple[Array, Array]] = {}
    for solver in reversed(plan.solvers):
        if isinstance(solver, DyadPlan):
            _dyad.reactions(solver, bodies, wrenches, reactions)
        else:
            general.reactions(solver, bodies, wrenches, reactions)
    balancing = np.stack([balance(d, bodies, wrenches, reactions) for d in plan.drivers],
                         axis=-1)
    check = np.stack([_virtual_power(plan, bodies, applied, i)
                      for i in range(len(plan.drivers))], axis=-1)
    shaking = np.stack(wrenches[0], axis=-1)
    residual = _residual(plan, bodies, applied, reactions, balancing)
    return ForceState(inertia_force, inertia_torque, reactions, balancing, check,
                      shaking, residual)


def _virtual_power(plan: Plan, bodies: list[Motion], applied: list[Wrench],
                   which: int) -> Array:
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
    total = 0.0
    for b in range(1, len(plan.bodies)):
        f_x, f_y, tau = applied[b]
        w = coeff[b].phi[1]
        v = coeff[b].o[1]
        o = bodies[b].o[0]
        vx = v[:, 0] + w * o[:, 1]
        vy = v[:, 1] - w * o[:, 0]
        total = total + f_x * vx + f_y * vy + tau * w
    return -total


def _residual(plan: Plan, bodies: list[Motion], applied: list[Wrench],
              reactions: dict[str, tuple[Array, Array]], balancing: Array) -> Array:
    """Largest unbalanced force (N) and moment about the link's origin (N m)."""
    totals = [list(w) for w in applied]
    for name, (force, couple) in reactions.items():
        pair = plan.pairs[name]
        q = point(bodies[pair.second], pair.d_second, 0)
        tau = q[:, 0] * force[:, 1] - q[:, 1] * force[:, 0] + couple
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            t = totals[body]
            totals[body] = [t[0] + sign * force[:, 0], t[1] + sign * force[:, 1],
                            t[2] + sign * tau]
    for i, d in enumerate(plan.drivers):
        t = totals[d.body]
        if d.kind == "R":
            totals[d.body] = [t[0], t[1], t[2] + balancing[:, i]]
        else:
            f = balancing[:, i, None] * d.pair.axis
            o = bodies[d.body].o[0]
            totals[d.body] = [t[0] + f[:, 0], t[1] + f[:, 1],
                              t[2] + o[:, 0] * f[:, 1] - o[:, 1] * f[:, 0]]
    force = np.zeros(balancing.shape[0])
    moment = np.zeros(balancing.shape[0])
    for b in range(1, len(plan.bodies)):
        f_x, f_y, tau = totals[b]
        o = bodies[b].o[0]
        force = np.maximum(force, np.maximum(np.abs(f_x), np.abs(f_y)))
        moment = np.maximum(moment, np.abs(tau - (o[:, 0] * f_y - o[:, 1] * f_x)))
    return np.stack((force, moment), axis=-1)
