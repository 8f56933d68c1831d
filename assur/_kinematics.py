"""Forward pass: positions, velocities, accelerations and jerks, group by group.

The driving links move as prescribed; each Assur group then follows from the links it
hangs on, in the order of attachment, for the whole batch of driver positions at once.
The result is a :class:`KinematicState` of read-only arrays, driver position first.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array
from assur.groups import DYADS, _dyad, general
from assur.groups._dyad import DyadPlan
from assur.groups._motion import Motion
from assur.groups._motion import point as point_of
from assur.groups._pairs import slide
from assur.groups.driver import motion
from assur.plan import Plan

__all__ = [
    "SINGULAR",
    "KinematicState",
    "Trouble",
    "collect",
    "solve",
    "velocity_coefficients",
]

SINGULAR = 1e-9
"""Below this sine of the angle between a group's Jacobian columns a pose is a dead
centre: velocities are undefined there."""
NEAR_SINGULAR = 0.035
"""Below this (about 2 degrees of transmission angle) a pose is near-singular."""
NEAR_SINGULAR_GENERAL = 1e-3
"""The same for the reciprocal condition number of a larger group's Jacobian."""
CONTINUATION_STEP = math.radians(5.0)
"""Largest step of the driver along the continuation path of a Newton-solved group."""


@dataclass(frozen=True, slots=True)
class Trouble:
    """Driver positions (``mask``) where a group met trouble.

    Group ``group`` failed (``what``:
    "assembly", "singular") or came near a dead centre ("near").
    """

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
    origin : ndarray (n, B, 2)
        Each link's origin, m (the point its body-fixed offsets start from).
    point : ndarray (4, n, U, 2)
        Position (m), velocity, acceleration and jerk of every distinct reported
        point; ``Plan.point_index`` gives a point's slot by name.
    slide : dict of str to ndarray (4, n)
        Slide (m) of every prismatic pair and its derivatives.
    """

    drive: Array
    link: Array
    origin: Array
    point: Array
    slide: dict[str, Array]


def _batch(q: Any, n: int) -> Array:
    """Return ``q`` as n values (a group hanging on the frame alone is constant)."""
    return q if np.ndim(q) else np.full(n, float(q))


def solve(plan: Plan, drive: Array, top: int = 3) -> tuple[list[Motion], list[Trouble]]:
    """Solve the motion of every link at driver positions ``drive`` (n, d), SI units.

    Returns the links' motions (levels 0 to ``top``) and the troubles met.
    Positions that
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
            q1, q2 = _batch(q1, n), _batch(q2, n)
            _dyad.set_pose(solver, bodies, q1, q2)
            jac: Any = _dyad.jacobian(solver, bodies)
            cond = _dyad.conditioning(solver, jac, plan.scale)
            failed = ~(np.isfinite(q1) & np.isfinite(q2))
            limit = NEAR_SINGULAR
        else:
            general.positions(
                solver, bodies, n, None if guesses is None else guesses[g]
            )
            g += 1
            failed = ~np.isfinite(bodies[solver.bodies[0]].phi[0])
            jac = general.jacobian(solver, bodies, n)
            jac[failed] = np.eye(jac.shape[-1])
            cond = general.conditioning(solver, jac)
            limit = NEAR_SINGULAR_GENERAL
        singular = ~failed & ~(cond >= SINGULAR)
        near = ~failed & ~singular & (cond < limit)
        for what, mask in (
            ("assembly", failed),
            ("singular", singular),
            ("near", near),
        ):
            if mask.any():
                troubles.append(Trouble(solver.label, what, mask))
        for k in range(1, top + 1):
            if isinstance(solver, DyadPlan):
                _dyad.derivative(solver, bodies, k, jac)
            else:
                jac[singular] = np.eye(jac.shape[-1])
                general.derivative(solver, bodies, k, jac, n)
        if top == 3:
            for b in solver.bodies:
                bodies[b].finish()
    return bodies, troubles


def _drivers(plan: Plan, drive: Array, rates: Array | None = None) -> list[Motion]:
    bodies: list[Motion] = [Motion.fixed()] * len(plan.bodies)
    for i, d in enumerate(plan.drivers):
        bodies[d.body] = motion(
            d, drive[:, i], None if rates is None else float(rates[i])
        )
        if rates is None:
            bodies[d.body].finish()
    return bodies


def _continuation(plan: Plan, drive: Array) -> list:
    """Follow the Newton groups from the reference pose to ``drive``.

    Each position is reached along the straight path of the driver from the reference
    pose; a crank position that path cannot reach (the group does not assemble
    somewhere on the way) is tried again the other way round the circle.
    """
    guesses = _walk(plan, drive)
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R" or not guesses:
        return guesses
    failed = np.zeros(drive.shape[0], dtype=bool)
    for group in guesses:
        failed |= ~np.isfinite(group[0][0])
    if not failed.any():
        return guesses
    gap = drive[failed] - plan.drivers[0].reference
    retry = _walk(plan, drive[failed] - 2.0 * math.pi * np.where(gap >= 0, 1.0, -1.0))
    for group, again in zip(guesses, retry, strict=True):
        for i, (pose, other) in enumerate(zip(group, again, strict=True)):
            merged = []
            for value, alternative in zip(pose, other, strict=True):
                value = value.copy()
                value[failed] = np.where(
                    np.isfinite(value[failed]), value[failed], alternative
                )
                merged.append(value)
            group[i] = tuple(merged)
    return guesses


def _walk(plan: Plan, drive: Array) -> list:
    """Return the Newton groups' poses along straight paths to ``drive``."""
    n = drive.shape[0]
    reference = np.array([d.reference for d in plan.drivers])
    step = np.array(
        [
            CONTINUATION_STEP if d.kind == "R" else 0.05 * plan.scale
            for d in plan.drivers
        ]
    )
    span = float(np.max(np.abs(drive - reference) / step)) if drive.size else 0.0
    count = max(1, math.ceil(span))
    guesses: list = [None] * sum(not isinstance(s, DyadPlan) for s in plan.solvers)
    for s in range(1, count + 1):
        bodies = _drivers(plan, reference + (drive - reference) * (s / count))
        g = 0
        for solver in plan.solvers:
            if isinstance(solver, DyadPlan):
                q1, q2 = DYADS[solver.kind].assemble(solver, bodies)
                _dyad.set_pose(solver, bodies, _batch(q1, n), _batch(q2, n))
            else:
                guesses[g] = general.positions(solver, bodies, n, guesses[g])
                g += 1
    return guesses


def velocity_coefficients(
    plan: Plan, bodies: list[Motion], which: int, n: int
) -> list[Motion]:
    """Return the links' velocities for a unit speed of driver ``which``, others still.

    Only the velocity level (index 1) of the returned motions is meaningful; it is the
    partial derivative of every link's velocity with respect to that driver's speed,
    the weight of each load in the principle of virtual power.
    """
    out: list[Motion] = list(bodies)
    for i, d in enumerate(plan.drivers):
        rate = motion(d, np.zeros(1), 1.0 if i == which else 0.0)
        out[d.body] = _copy(bodies[d.body], rate.phi[1], rate.ox[1], rate.oy[1])
    for solver in plan.solvers:
        for b in solver.bodies:
            out[b] = _copy(bodies[b], 0.0, 0.0, 0.0)
        if isinstance(solver, DyadPlan):
            _dyad.derivative(solver, out, 1, _dyad.jacobian(solver, out))
        else:
            jac = general.jacobian(solver, out, n)
            bad = ~np.isfinite(jac).all(axis=(1, 2)) | (
                general.conditioning(solver, jac) < SINGULAR
            )
            jac[bad] = np.eye(jac.shape[-1])
            general.derivative(solver, out, 1, jac, n)
    return out


def _copy(m: Motion, omega: Any, vx: Any, vy: Any) -> Motion:
    """Return a motion sharing ``m``'s pose with its velocity level replaced."""
    c = Motion.__new__(Motion)
    c.phi = [m.phi[0], omega, 0.0, 0.0]
    c.ox = [m.ox[0], vx, 0.0, 0.0]
    c.oy = [m.oy[0], vy, 0.0, 0.0]
    c.c, c.s, c.rot = m.c, m.s, m.rot
    c.memo = None  # other velocities: nothing of ``m``'s may be reused
    c.q = list(m.q[:1])
    return c


def allocate(plan: Plan, n: int) -> KinematicState:
    """Return a writable state for ``n`` driver positions, to be filled by chunks.

    Each array is stored with the driver position last (contiguous rows per link and
    point, so that chunks are written in place) and exposed driver position first.
    """
    count, points = len(plan.bodies), len(plan.point_sets)
    link = np.empty((4, count, n)).transpose(0, 2, 1)
    origin = np.empty((2, count, n)).transpose(2, 1, 0)
    point = np.empty((4, 2, points, n)).transpose(0, 3, 2, 1)
    drive = np.empty((len(plan.drivers), n)).T
    slides = {name: np.empty((4, n)) for name, p in plan.pairs.items() if p.kind == "P"}
    return KinematicState(drive, link, origin, point, slides)


def freeze(state: KinematicState) -> KinematicState:
    """Make every array of ``state`` read-only."""
    for arr in (
        state.drive,
        state.link,
        state.origin,
        state.point,
        *state.slide.values(),
    ):
        arr.flags.writeable = False
    return state


def collect(
    plan: Plan,
    bodies: list[Motion],
    n: int,
    out: KinematicState | None = None,
    start: int = 0,
) -> KinematicState:
    """Gather the links' motions and every reported point into ``out[start:start+n]``.

    Returns the state of this chunk (views of ``out`` when given).
    """
    if out is None:
        out = allocate(plan, n)
    rows = slice(start, start + n)
    link, origin, point = out.link[:, rows], out.origin[rows], out.point[:, rows]
    for b, m in enumerate(bodies):
        for k in range(4):
            link[k, :, b] = m.phi[k]
        origin[:, b, 0] = m.ox[0]
        origin[:, b, 1] = m.oy[0]
    # point by point on rows of the chunk: temporaries stay small enough for the cache
    # and below the allocator's mmap threshold, and rotations solved already are reused;
    # coincident points are computed once, a body's origin and a still body's
    # derivatives need no rotation terms
    for slot, (b, d) in enumerate(plan.point_sets):
        m = bodies[b]
        still = all(m.phi[j].__class__ is float and not m.phi[j] for j in (1, 2, 3))
        for k in range(4):
            if d == (0.0, 0.0) or (k and still):
                xy = (m.ox[k], m.oy[k])
            else:
                xy = point_of(m, d, k)
            point[k, :, slot, 0], point[k, :, slot, 1] = xy
    slides = {name: arr[:, rows] for name, arr in out.slide.items()}
    _slides(plan, bodies, slides)
    drive = out.drive[rows]
    for i, d in enumerate(plan.drivers):
        m = bodies[d.body]
        if d.kind == "R":
            drive[:, i] = m.phi[0] + d.angle0
        else:
            ex, ey = d.pair.axis  # type: ignore[misc]
            drive[:, i] = (
                d.reference
                + (m.ox[0] - d.origin[0]) * ex
                + (m.oy[0] - d.origin[1]) * ey
            )
    return KinematicState(drive, link, origin, point, slides)


def _slides(plan: Plan, bodies: list[Motion], out: dict[str, Array]) -> None:
    """Slides of the prismatic pairs: a dyad's own coordinate where it is one."""
    known: dict[str, tuple[int, float]] = {}
    for solver in plan.solvers:
        if isinstance(solver, DyadPlan):
            for b, pair in zip(solver.bodies, solver.ext, strict=False):
                if pair.kind == "P":
                    known[pair.name] = (b, 1.0 if pair.second == b else -1.0)
    for name, arr in out.items():
        if name in known:
            body, sign = known[name]
            for k in range(4):
                arr[k] = sign * bodies[body].q[k]
        else:
            for k in range(4):
                arr[k] = slide(plan.pairs[name], bodies, k)
