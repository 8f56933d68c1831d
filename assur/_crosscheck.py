"""Independent checks of the reverse pass.

The balancing loads found again from the principle of virtual power, and every link's
loads summed again from the applied loads, the reactions and the balancing loads.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur._kinematics import velocity_coefficients
from assur._vec import Array, add, cross, full, is_array
from assur.groups._motion import point

if TYPE_CHECKING:
    from assur.groups._motion import Motion
    from assur.kinetostatics import Applied, ForceState
    from assur.plan import Plan

__all__ = ["SLOW", "residual", "virtual_power"]

SLOW = 1e-100
"""Below this driver speed (rad/s or m/s) velocities are too small to be divided by
the speed: the velocity coefficients are solved at unit speed instead."""


def virtual_power(
    plan: Plan, bodies: list[Motion], applied: Applied, which: int, speed: Any
) -> Any:
    r"""Balancing load of driver ``which`` from the principle of virtual power.

    ``speed`` is the driver's speed in ``bodies`` (rad/s or m/s; a float or one value
    per position).

    Notes
    -----
    For a unit speed of the driver (the others held), the power of the balancing load
    plus that of every applied load (inertia loads included) is zero:
    :math:`T = -\sum_b (F_b \cdot v_{b,O} + \tau_{b,O}\,\omega_b)`, where
    :math:`v_{b,O} = v_b - \omega_b o_b^\perp` is the velocity of the body point at the
    origin about which :math:`\tau_{b,O}` is taken.
    """
    scale: Any
    if len(plan.drivers) == 1 and (np.abs(speed) > SLOW).all():
        coeff, scale = bodies, 1.0 / speed  # velocities are linear in the one speed
    else:
        coeff, scale = velocity_coefficients(plan, bodies, which), 1.0
    total: Any = 0.0
    for b in range(1, len(plan.bodies)):
        fx, fy, tau = applied.wrenches[b]
        if not (is_array(fx) or is_array(fy) or is_array(tau) or fx or fy or tau):
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


def residual(
    plan: Plan, bodies: list[Motion], applied: Applied, forces: ForceState, out: Array
) -> None:
    """Write the largest unbalanced force (N) and moment about the link's origin (N m).

    Every link's loads are summed again from the applied loads, the reactions of all
    its pairs and the balancing loads: an independent check of the reverse pass.
    ``out`` is an array (2, n): the forces are written into its first row, the
    moments into its second.
    """
    n, count = out.shape[1], len(plan.bodies)
    # the sums of the moving links only (the frame takes what they pass to it): a
    # link's force and moment are one array (3, n), added to in one operation
    total = np.empty((count, 3, n))
    total[1:] = [[full(v, n) for v in applied.wrenches[b]] for b in range(1, count)]
    for name, (fx, fy, couple) in forces.reactions.items():
        pair = plan.pairs[name]
        qx, qy = point(bodies[pair.second], pair.d_second, 0)
        tau = cross(qx, qy, fx, fy)
        if pair.kind == "P":
            tau = add(tau, couple)
        load = np.array((full(fx, n), full(fy, n), full(tau, n)))
        total[pair.second] += load
        if pair.first:
            total[pair.first] -= load
    for d, value in zip(plan.drivers, forces.balancing, strict=True):
        if d.kind == "R":
            total[d.body, 2] += value
        else:
            assert d.pair.axis is not None
            ex, ey = d.pair.axis
            fx, fy = value * ex, value * ey
            m = bodies[d.body]
            total[d.body, 0] += fx
            total[d.body, 1] += fy
            total[d.body, 2] += m.ox[0] * fy - m.oy[0] * fx
    # every moving link at once, a row each: the largest is exact in any order
    loads = total[1:]
    fx, fy, tau = loads[:, 0], loads[:, 1], loads[:, 2]
    ox = np.array([full(m.ox[0], n) for m in bodies[1:]])
    oy = np.array([full(m.oy[0], n) for m in bodies[1:]])
    # the moments about the links' origins: tau - o x F, in place
    tau -= np.multiply(ox, fy, out=ox)
    tau += np.multiply(oy, fx, out=oy)
    np.abs(loads, out=loads)
    # the ufuncs' own reductions: np.max would reach them through Python
    np.maximum.reduce(loads[:, :2], axis=(0, 1), out=out[0])
    np.maximum.reduce(tau, axis=0, out=out[1])
