"""Forward pass: positions, velocities, accelerations and jerks, group by group.

The driving links move as prescribed; each Assur group then follows from the links it
hangs on, in the order of attachment, for the whole batch of driver positions at once.
The result is a :class:`KinematicState` of read-only arrays, driver position first.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assur._vec import Array, perp
from assur.groups import DYADS, _dyad, general
from assur.groups._dyad import DyadPlan
from assur.groups._motion import Motion
from assur.groups._pairs import slide
from assur.groups.driver import motion
from assur.plan import Plan

__all__ = ["SINGULAR", "KinematicState", "Trouble", "collect", "solve", "velocity_coefficients"]

SINGULAR = 1e-9
"""Below this sine of the angle between a group's Jacobian columns a pose is a dead
centre: velocities are undefined there."""
NEAR_SINGULAR = 0.035
"""Below this (about 2 degrees of transmission angle) a pose is reported as near-singular."""
NEAR_SINGULAR_GENERAL = 1e-3
"""The same for the reciprocal condition number of a larger group's Jacobian."""
CONTINUATION_STEP = math.radians(10.0)
"""Largest step of the driver along the continuation path of a Newton-solved group."""


@dataclass(frozen=True, slots=True)
class Trouble:
    """Driver positions at which group ``group`` failed (``what``: "assembly",
    "singular") or came near a dead centre ("near")."""

    group: str
    what: str
    mask: Array


@dataclass(frozen=True, slots=True)
class KinematicState:
    """The motion of every link and reported point over a sweep.

    Attributes
    ----------
    drive : ndarray (n, d)
        Driver positions, rad (m for a prismatic driver).
    link : ndarray (4, n, B)
        Each link's rotation from the reference pose (rad) and its derivatives
        (rad/s, rad/s^2, rad/s^3); index 0 is the frame.
    origin : ndarray (4, n, B, 2)
        Each link's origin (m) and its derivatives.
    point : ndarray (4, n, P, 2)
        Position (m), velocity, acceleration and jerk of every reported point.
    slide : dict of str to ndarray (4, n)
        Slide (m) of every prismatic pair and its derivatives.
    """

    drive: Array
    link: Array
    origin: Array
    point: Array
    slide: dict[str, Array]


def solve(plan: Plan, drive: Array, top: int = 3) -> tuple[list[Motion], list[Trouble]]:
    """Solve the motion of every link at driver positions ``drive`` (n, d), SI units.

    Returns the links' motions (levels 0..``top``) and the troubles met. Positions that
    fail hold NaN.
    """
    n = drive.shape[0]
    guesses = _continuation(plan, drive) if plan.newton else None
    bodies = _drivers(plan, drive)
    troubles: list[Trouble] = []
    g = 0
    for solver in plan.solvers:
        if isinstance(solver, DyadPlan):
            q1, q2 = DYADS[solver.kind].assemble(solver, bodies)
            _dyad.set_pose(solver, bodies, q1, q2)
            jac = _dyad.jacobian(solver, bodies)
            cond = _dyad.conditioning(solver, jac, plan.scale)
            failed = ~(np.isfinite(q1) & np.isfinite(q2))
        else:
            general.positions(solver, bodies, None if guesses is None else guesses[g])
            g += 1
            failed = ~np.isfinite(bodies[solver.bodies[0]].phi[0])
            jac = general.jacobian(solver, bodies)
            jac[failed] = np.eye(jac.shape[-1])
            cond = general.conditioning(solver, jac)
        singular = ~failed & ~(cond >= SINGULAR)
        limit = NEAR_SINGULAR if isinstance(solver, DyadPlan) else NEAR_SINGULAR_GENERAL
        near = ~failed & ~singular & (cond < limit)
        for what, mask in (("assembly", failed), ("singular", singular), ("near", near)):
            if mask.any():
                troubles.append(Trouble(solver.label, what, mask))
        if not isinstance(solver, DyadPlan):
            jac[singular] = np.eye(jac.shape[-1])
        for k in range(1, top + 1):
            if isinstance(solver, DyadPlan):
                _dyad.derivative(solver, bodies, k, jac)
            else:
                general.derivative(solver, bodies, k, jac)
    del n
    return bodies, troubles


def _drivers(plan: Plan, drive: Array, rates: Array | None = None) -> list[Motion]:
    n = drive.shape[0]
    bodies: list[Motion] = [Motion.fixed(n, np.zeros(2))] * len(plan.bodies)
    for i, d in enumerate(plan.drivers):
        bodies[d.body] = motion(d, drive[:, i], None if rates is None else rates[i])
    return bodies


def _continuation(plan: Plan, drive: Array) -> list:
    """Newton groups' poses along straight paths from the reference pose to ``drive``."""
    reference = np.array([d.reference for d in plan.drivers])
    step = np.array([CONTINUATION_STEP if d.kind == "R" else 0.05 * plan.scale
                     for d in plan.drivers])
    span = np.max(np.abs(drive - reference) / step) if drive.size else 0.0
    count = max(1, math.ceil(span))
    guesses: list = [None] * sum(not isinstance(s, DyadPlan) for s in plan.solvers)
    for s in range(1, count + 1):
        bodies = _drivers(plan, reference + (drive - reference) * (s / count))
        g = 0
        for solver in plan.solvers:
            if isinstance(solver, DyadPlan):
                _dyad.set_pose(solver, bodies, *DYADS[solver.kind].assemble(solver, bodies))
            else:
                guesses[g] = general.positions(solver, bodies, guesses[g])
                g += 1
    return guesses


def velocity_coefficients(plan: Plan, bodies: list[Motion], which: int) -> list[Motion]:
    """Return the links' velocities for a unit speed of driver ``which``, others still.

    Only the velocity level (index 1) of the returned motions is meaningful; it is the
    partial derivative of every link's velocity with respect to that driver's speed,
    the weight of each load in the principle of virtual power.
    """
    rates = np.zeros(len(plan.drivers))
    rates[which] = 1.0
    n = bodies[0].o[0].shape[0]
    drive = np.zeros((n, len(plan.drivers)))
    out = _drivers(plan, drive, rates)
    for i, d in enumerate(plan.drivers):
        m = out[d.body]
        out[d.body] = _copy(bodies[d.body], m.phi[1], m.o[1])
    for solver in plan.solvers:
        for b in solver.bodies:
            out[b] = _copy(bodies[b], None, None)
        if isinstance(solver, DyadPlan):
            _dyad.derivative(solver, out, 1, _dyad.jacobian(solver, out))
        else:
            jac = general.jacobian(solver, out)
            bad = ~np.isfinite(jac).all(axis=(1, 2))
            jac[bad] = np.eye(jac.shape[-1])
            general.derivative(solver, out, 1, jac)
    return out


def _copy(m: Motion, omega: Array | None, v: Array | None) -> Motion:
    """A motion sharing ``m``'s pose with its velocity level replaced."""
    c = Motion.__new__(Motion)
    c.phi = [m.phi[0], omega, None, None]
    c.o = [m.o[0], v, None, None]
    c.c, c.s = m.c, m.s
    c.q = list(m.q[:1])
    return c


def collect(plan: Plan, bodies: list[Motion]) -> KinematicState:
    """Gather the links' motions into arrays and compute every reported point."""
    n = bodies[0].o[0].shape[0]
    link = np.empty((4, n, len(bodies)))
    origin = np.empty((4, n, len(bodies), 2))
    for b, m in enumerate(bodies):
        for k in range(4):
            link[k, :, b] = m.phi[k]
            origin[k, :, b] = m.o[k]
    idx = plan.point_body
    d = plan.point_offset
    c = np.cos(link[0][:, idx])
    s = np.sin(link[0][:, idx])
    u = np.stack((c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]), axis=-1)
    pu = perp(u)
    w, a, z = (link[k][:, idx, None] for k in (1, 2, 3))
    point = np.empty((4, n, len(idx), 2))
    point[0] = origin[0][:, idx] + u
    point[1] = origin[1][:, idx] + w * pu
    point[2] = origin[2][:, idx] + a * pu - w * w * u
    point[3] = origin[3][:, idx] + (z - w * w * w) * pu - 3.0 * w * a * u
    slides = {name: np.stack([slide(p, bodies, k) for k in range(4)])
              for name, p in plan.pairs.items() if p.kind == "P"}
    drive = np.stack([bodies[d.body].phi[0] + d.angle0 if d.kind == "R"
                      else d.reference + _along(bodies[d.body].o[0] - d.origin, d)
                      for d in plan.drivers], axis=-1)
    for arr in (link, origin, point, drive, *slides.values()):
        arr.flags.writeable = False
    return KinematicState(drive, link, origin, point, slides)


def _along(gap: Array, d) -> Array:
    return gap @ d.pair.axis
