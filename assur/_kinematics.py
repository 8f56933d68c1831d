"""Forward pass: positions, velocities, accelerations and jerks, group by group.

The driving links move as prescribed; each Assur group then follows from the links it
hangs on, in the order of attachment, for the whole batch of driver positions at once.
The result is a :class:`KinematicState` of read-only arrays, driver position first: the
motion of every link (its rotation and the path of its origin, with their derivatives),
from which every point of every link follows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array
from assur.groups._motion import Motion
from assur.groups._pairs import slide
from assur.groups.driver import motion
from assur.plan import Plan

__all__ = [
    "KinematicState",
    "Trouble",
    "allocate",
    "collect",
    "freeze",
    "motions",
    "solve",
    "velocity_coefficients",
]

CONTINUATION_STEP = math.radians(5.0)
"""Largest step of the driver along the continuation path of a Newton-solved group."""
LEVELS = 4
"""Position, velocity, acceleration and jerk."""


@dataclass(frozen=True, slots=True)
class Trouble:
    """Driver positions (``mask``) where a group met trouble.

    Group ``group`` failed (``what``: "assembly", "singular") or came near a dead
    centre ("near").
    """

    group: str
    what: str
    mask: Array


@dataclass(frozen=True, slots=True)
class KinematicState:
    """The motion of every link over a sweep: the forward pass's frozen result.

    Attributes
    ----------
    drive : ndarray (n, d)
        Driver positions, rad (m for a prismatic driver), as solved: a crank's angle
        within half a turn of the reference pose.
    speed, acceleration : ndarray (n, d)
        Each driver's speed (rad/s or m/s) and acceleration (rad/s^2 or m/s^2).
    link : ndarray (4, n, B)
        Each link's rotation from the reference pose (rad) and its derivatives
        (rad/s, rad/s^2, rad/s^3); index 0 is the frame.
    origin : ndarray (4, n, B, 2)
        Each link's origin (m, core coordinates: see ``Plan.shift``) and its
        velocity, acceleration and jerk.
    slide : dict of str to ndarray (4, n)
        Slide (m) of every prismatic pair and its derivatives.
    top : int
        The highest derivative solved (3: jerks; 2: accelerations).
    scalars : tuple
        Per body, the twelve quantities ``phi[k], ox[k], oy[k]`` (k = 0..3) that do
        not change over the sweep, as floats (None where they do): what
        :func:`motions` needs to rebuild the forward pass's motions exactly.
    """

    drive: Array
    speed: Array
    acceleration: Array
    link: Array
    origin: Array
    slide: dict[str, Array]
    top: int = 3
    scalars: tuple[tuple[Any, ...], ...] = ()

    def __len__(self) -> int:
        return int(self.drive.shape[0])

    def rows(self, rows: slice) -> KinematicState:
        """Return the state at a slice of rows, as views."""
        return KinematicState(
            self.drive[rows],
            self.speed[rows],
            self.acceleration[rows],
            self.link[:, rows],
            self.origin[:, rows],
            {k: v[:, rows] for k, v in self.slide.items()},
            self.top,
            self.scalars,
        )

    def take(self, rows: Any) -> KinematicState:
        """Return the state at ``rows`` (a mask or indices), a copy."""
        return KinematicState(
            self.drive[rows],
            self.speed[rows],
            self.acceleration[rows],
            self.link[:, rows],
            self.origin[:, rows],
            {k: v[:, rows] for k, v in self.slide.items()},
            self.top,
            self.scalars,
        )


def solve(
    plan: Plan, drive: Array, speed: Any, acceleration: Any, top: int = 3
) -> tuple[list[Motion], list[Trouble]]:
    """Solve the motion of every link at driver positions ``drive`` (n, d), SI units.

    ``speed`` and ``acceleration`` hold each driver's rate: a float per driver (a
    sequence) or an array (n,) per driver. Returns the links' motions (levels 0 to
    ``top``) and the troubles met; positions that fail hold NaN.
    """
    n = drive.shape[0]
    guesses = _continuation(plan, drive) if plan.newton else None
    bodies = drivers(plan, drive, speed, acceleration)
    troubles: list[Trouble] = []
    g = 0
    for solver in plan.solvers:
        guess = None
        if solver.newton:
            assert guesses is not None
            guess, g = guesses[g], g + 1
        failed = solver.assemble(bodies, n, guess).failed
        lin = solver.linearize(bodies)
        singular = ~failed & lin.singular
        near = ~failed & ~singular & (lin.conditioning < solver.near)
        for what, mask in (
            ("assembly", failed),
            ("singular", singular),
            ("near", near),
        ):
            if mask.any():
                troubles.append(Trouble(solver.label, what, mask))
        for k in range(1, top + 1):
            solver.derivative(bodies, k, lin)
        for b in solver.bodies:
            bodies[b].finish()
    return bodies, troubles


def drivers(plan: Plan, drive: Array, speed: Any, acceleration: Any) -> list[Motion]:
    """Return every body at rest but the driving links, which move as prescribed."""
    bodies: list[Motion] = [Motion.fixed()] * len(plan.bodies)
    for i, d in enumerate(plan.drivers):
        m = motion(d, drive[:, i], speed[i], acceleration[i])
        m.finish()
        bodies[d.body] = m
    return bodies


def _continuation(plan: Plan, drive: Array) -> list[Any]:
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


def _walk(plan: Plan, drive: Array) -> list[Any]:
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
    still = [0.0] * len(plan.drivers)
    guesses: list[Any] = [None] * sum(s.newton for s in plan.solvers)
    for s in range(1, count + 1):
        bodies = drivers(
            plan, reference + (drive - reference) * (s / count), still, still
        )
        g = 0
        for solver in plan.solvers:
            if solver.newton:
                guesses[g] = solver.assemble(bodies, n, guesses[g]).guess
                g += 1
            else:
                solver.assemble(bodies, n)
    return guesses


def velocity_coefficients(plan: Plan, bodies: list[Motion], which: int) -> list[Motion]:
    """Return the links' velocities for a unit speed of driver ``which``, others still.

    Only the velocity level (index 1) of the returned motions is meaningful; it is the
    partial derivative of every link's velocity with respect to that driver's speed,
    the weight of each load in the principle of virtual power.
    """
    out: list[Motion] = list(bodies)
    for i, d in enumerate(plan.drivers):
        rate = motion(d, np.zeros(1), 1.0 if i == which else 0.0, 0.0)
        out[d.body] = _copy(bodies[d.body], rate.phi[1], rate.ox[1], rate.oy[1])
    for solver in plan.solvers:
        for b in solver.bodies:
            out[b] = _copy(bodies[b], 0.0, 0.0, 0.0)
        solver.derivative(out, 1, solver.linearize(out))
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


def allocate(plan: Plan, n: int, top: int = 3) -> KinematicState:
    """Return a writable state for ``n`` driver positions, to be filled by chunks.

    Each array is stored with the driver position last (contiguous rows per link, so
    that chunks are written in place) and exposed driver position first.
    """
    count, d = len(plan.bodies), len(plan.drivers)
    return KinematicState(
        np.empty((d, n)).T,
        np.empty((d, n)).T,
        np.empty((d, n)).T,
        np.empty((LEVELS, count, n)).transpose(0, 2, 1),
        np.empty((LEVELS, 2, count, n)).transpose(0, 3, 2, 1),
        {
            name: np.empty((LEVELS, n))
            for name, p in plan.pairs.items()
            if p.kind == "P"
        },
        top,
    )


def freeze(state: KinematicState) -> KinematicState:
    """Make every array of ``state`` read-only."""
    for arr in (
        state.drive,
        state.speed,
        state.acceleration,
        state.link,
        state.origin,
        *state.slide.values(),
    ):
        arr.flags.writeable = False
    return state


def collect(
    plan: Plan,
    bodies: list[Motion],
    drive: Array,
    rates: tuple[Any, Any],
    out: KinematicState,
    start: int = 0,
) -> KinematicState:
    """Write the links' motions into rows ``start`` onwards of ``out``.

    ``rates`` holds the drivers' speeds and accelerations as given to :func:`solve`.
    Returns ``out`` with the scalars of the motions recorded.
    """
    n = drive.shape[0]
    rows = slice(start, start + n)
    link, origin = out.link[:, rows], out.origin[:, rows]
    top = out.top
    for b, m in enumerate(bodies):
        for k in range(top + 1):
            link[k, :, b] = m.phi[k]
            origin[k, :, b, 0] = m.ox[k]
            origin[k, :, b, 1] = m.oy[k]
    out.drive[rows] = drive
    for i in range(len(plan.drivers)):
        out.speed[rows, i] = rates[0][i]
        out.acceleration[rows, i] = rates[1][i]
    _slides(plan, bodies, {name: arr[:, rows] for name, arr in out.slide.items()}, top)
    if out.scalars:
        return out
    scalars = tuple(
        tuple(
            v if v.__class__ is float else None
            for v in (*m.phi[: top + 1], *m.ox[: top + 1], *m.oy[: top + 1])
        )
        for m in bodies
    )
    return KinematicState(
        out.drive,
        out.speed,
        out.acceleration,
        out.link,
        out.origin,
        out.slide,
        top,
        scalars,
    )


def _slides(plan: Plan, bodies: list[Motion], out: dict[str, Array], top: int) -> None:
    """Slides of the prismatic pairs: a group's own coordinate where it is one."""
    own: dict[str, tuple[int, float]] = {}
    for solver in plan.solvers:
        own.update(solver.own_slides())
    for name, arr in out.items():
        if name in own:
            body, sign = own[name]
            for k in range(top + 1):
                arr[k] = sign * bodies[body].q[k]
        else:
            for k in range(top + 1):
                arr[k] = slide(plan.pairs[name], bodies, k)


def motions(plan: Plan, state: KinematicState, rows: Any = slice(None)) -> list[Motion]:
    """Rebuild the forward pass's motions from a frozen state, at ``rows``.

    The quantities that were constant floats in the forward pass are floats again, so
    every kernel run on the rebuilt motions takes the same steps and gives the same
    numbers as on the originals.
    """
    levels = state.top + 1
    pad = [0.0] * (LEVELS - levels)
    out = []
    for b, scalars in enumerate(state.scalars):
        arrays = (state.link[:, rows, b], *state.origin[:, rows, b].transpose(2, 0, 1))
        parts = [
            [
                arr[k] if scalars[j * levels + k] is None else scalars[j * levels + k]
                for k in range(levels)
            ]
            + pad
            for j, arr in enumerate(arrays)
        ]
        out.append(Motion(*parts))
    for solver in plan.solvers:
        for name, (body, sign) in solver.own_slides().items():
            out[body].q = [sign * v for v in state.slide[name][:levels, rows]]
    for m in out:
        m.finish()
    return out
