"""Forward pass: positions, velocities, accelerations and jerks, group by group.

The driving links move as prescribed; each Assur group then follows from the links it
hangs on, for the whole batch of driver positions at once, a Newton-solved group from
poses reached by continuation from the reference pose. The frozen result is a
:class:`KinematicState` (kept in ``assur._state``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._follow import BranchOf, advance, drivers, layout, nested, tangents
from assur._state import KinematicState, extend, motions, state_of
from assur._vec import Array, Mask
from assur._walk import OnPaths, stops, walk
from assur.groups._motion import Motion
from assur.groups.driver import motion
from assur.plan import Plan

__all__ = [
    "KinematicState",
    "Trouble",
    "continuation",
    "extend",
    "motions",
    "solve",
    "state_of",
    "velocity_coefficients",
]

CONTINUATION_STEP = math.radians(5.0)
"""Largest step of the driver along the continuation path of a Newton-solved group."""
MAX_STEPS = 4000
"""Most continuation steps from the reference pose to one position."""


@dataclass(frozen=True, slots=True)
class Trouble:
    """Driver positions (``mask``) where a group met trouble.

    Group ``group`` failed (``what``: "assembly", "singular"), came near a dead
    centre ("near") or was reached the other way round the crank's circle ("other
    way": the short way its branch folds before the position). The passes add
    "unreached" (:mod:`assur._reach`): the group stops the mechanism before the
    position, which it assembles on another circuit or past a dead centre.
    """

    group: str
    what: str
    mask: Mask


def solve(
    plan: Plan,
    drive: Array,
    speed: Any,
    acceleration: Any,
    top: int = 3,
    branch_of: BranchOf | None = None,
    jerk: Any = (),
) -> tuple[list[Motion], list[Trouble]]:
    """Solve the motion of every link at driver positions ``drive`` (n, d), SI units.

    ``speed``, ``acceleration`` (and ``jerk``, zero if not given) hold each driver's
    rate: a float per driver (a sequence) or an array (n,) per driver;
    ``branch_of`` gives the groups' branches past change points. Returns the links'
    motions (levels 0 to ``top``) and the troubles met; positions that fail hold NaN.
    """
    n = drive.shape[0]
    guesses, around = _continued(plan, drive, branch_of) if plan.newton else ([], [])
    branch = {} if branch_of is None else branch_of(drive, len(plan.solvers))
    bodies = drivers(plan, drive, speed, acceleration, jerk)
    troubles: list[Trouble] = []
    g = 0
    for index, solver in enumerate(plan.solvers):
        guess = turned = None
        if solver.newton:
            guess, turned, g = guesses[g], around[g], g + 1
        failed = solver.assemble(bodies, n, guess, branch.get(index)).failed
        if turned is not None and (turned & ~failed).any():
            troubles.append(Trouble(solver.label, "other way", turned & ~failed))
        lin = solver.linearize(bodies)
        # a failed pose has no conditioning (NaN): it is below no threshold
        low = lin.conditioning < solver.near
        if failed.any() or low.any():
            singular = ~failed & lin.singular
            near = ~failed & ~singular & low
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


def continuation(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    kept: dict[float, Array] | None = None,
) -> list[Any]:
    """Follow the Newton groups from the reference pose to ``drive``.

    Each position is reached along the straight path of the driver from the reference
    pose; a crank position that path cannot reach (the group does not assemble
    somewhere on the way) is tried again the other way round the circle. ``kept``
    holds the anchors walked on the branches ``branch_of`` gives (see
    :func:`_anchor_poses`); None: the plan's own.
    """
    return _continued(plan, drive, branch_of, kept)[0]


def _continued(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    kept: dict[float, Array] | None = None,
) -> tuple[list[Any], list[Mask]]:
    """Return :func:`continuation`'s poses and where each group went the other way.

    The masks (n,), one per Newton group, mark the positions reached the other way
    round the circle.
    """
    guesses = _walk(plan, drive, branch_of, kept)
    n = drive.shape[0]
    around = [np.zeros(n, dtype=bool) for _ in guesses]
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R" or not guesses:
        return guesses, around
    failed = np.zeros(n, dtype=bool)
    for group in guesses:
        failed |= ~np.isfinite(group[0][0])
    if not failed.any():
        return guesses, around
    gap = drive[failed] - plan.drivers[0].reference
    turn = 2.0 * math.pi * np.where(gap >= 0, 1.0, -1.0)
    retry = _walk(plan, drive[failed] - turn, branch_of, kept)
    for group, again, turned in zip(guesses, retry, around, strict=True):
        turned[failed] = ~np.isfinite(group[0][0][failed]) & np.isfinite(again[0][0])
        for i, (pose, other) in enumerate(zip(group, again, strict=True)):
            merged = []
            for value, alternative in zip(pose, other, strict=True):
                value = value.copy()
                value[failed] = np.where(
                    np.isfinite(value[failed]), value[failed], alternative
                )
                merged.append(value)
            group[i] = tuple(merged)
    return guesses, around


def _walk(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    kept: dict[float, Array] | None = None,
) -> list[Any]:
    """Return the Newton groups' poses along straight paths to ``drive``.

    Every position takes steps of at most :data:`CONTINUATION_STEP` (a crank) or a
    twentieth of the mechanism's size (a slider) from the reference pose; a position
    stops at its first failed step (its pose is then NaN), so the work grows with the
    distance the mechanism can actually travel. With one driver the positions share
    their paths (:func:`_anchored`).

    Raises
    ------
    ConvergenceError
        When a position is more than :data:`MAX_STEPS` steps away.
    """
    n = drive.shape[0]
    reference, step, counts = _distances(plan, drive)
    if len(plan.drivers) == 1 and n and np.isfinite(drive).all():
        # anchored even when few positions share an anchor: a position's pose then
        # never depends on the others in the batch
        marks, which = np.unique(
            np.trunc((drive[:, 0] - reference[0]) / step[0]), return_inverse=True
        )
        walked = _anchor_poses(plan, marks, branch_of, kept)
        start = reference[0] + marks[which.ravel()] * step[0]
        return _anchored(plan, drive, branch_of, walked, which.ravel(), start)
    return _straight(plan, drive, branch_of, reference, counts)


def _separate(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    kept: dict[float, Array] | None = None,
) -> list[Any]:
    """Walk every position on its own straight path from the reference pose.

    What :func:`_walk` does with several drivers; with one, the paths it shares
    reach the same poses (the tests and benchmarks/bench_continuation.py compare,
    putting it in :func:`_walk`'s place: ``kept`` is that one's, no anchors here).
    """
    reference, _, counts = _distances(plan, drive)
    return _straight(plan, drive, branch_of, reference, counts)


def _distances(plan: Plan, drive: Array) -> tuple[Array, Array, Array]:
    """Return the drivers' reference positions, their steps and each position's count.

    Raises
    ------
    ConvergenceError
        When a position is more than :data:`MAX_STEPS` steps away.
    """
    n = drive.shape[0]
    reference = np.array([d.reference for d in plan.drivers])
    step = np.array([_stride(plan, d) for d in plan.drivers])
    counts = np.ones(n)
    if n:
        counts = np.maximum(1.0, np.ceil(np.max(np.abs(drive - reference) / step, 1)))
    if n and counts.max() > MAX_STEPS:
        _too_far(plan, drive, counts)
    return reference, step, counts


def _stride(plan: Plan, driver: Any) -> float:
    """Return a driver's longest continuation step: rad for a crank, m for a slider."""
    return CONTINUATION_STEP if driver.kind == "R" else 0.05 * plan.scale


def _anchor_poses(
    plan: Plan,
    marks: Array,
    branch_of: BranchOf | None,
    kept: dict[float, Array] | None = None,
) -> Array:
    """Return the Newton groups at ``marks`` whole steps from the reference (packed).

    The reference pose is solved first; the anchors on either side are then walked
    to one after the other, each one step on from the last, both sides together, and
    kept with the plan (a few numbers): the slices of a long sweep, and every later
    sweep of the mechanism, start from them. Each anchor keeps its poses, their rates
    of change per unit of the driver and their Jacobians' signs (rows, marks); a side
    whose step fails is NaN from there on, and its walk stops. ``kept`` holds the
    anchors walked on the branches ``branch_of`` gives, by mark; None: the plan's own
    for the reference pose's branches or for every change point.
    """
    driver = plan.drivers[0]
    step = _stride(plan, driver)
    if kept is None:
        key = "anchors" if branch_of is None else "anchors-past-change-points"
        kept = plan.memo.setdefault(key, {})
    size = 3 * sum(layout(plan))
    if 0.0 not in kept:
        at = np.array([[driver.reference]])
        pose, _, rate, signs = tangents(plan, at, None, np.ones((1, 1)), branch_of)
        kept[0.0] = np.concatenate([pose[:, 0], rate[:, 0], signs[:, 0]])
    wanted = marks.tolist()
    # each side: its direction, the last anchor walked to and the farthest wanted
    sides = []
    for sign in (1.0, -1.0):
        far = max((m * sign for m in wanted), default=0.0)
        # a snapshot of the marks: another thread sharing the plan may add some
        last = max((m * sign for m in list(kept)), default=0.0)
        if far > last:
            sides.append([sign, last, far])
    while sides:
        rows = np.array([kept[sign * last] for sign, last, _ in sides]).T
        sign, last = np.array([side[:2] for side in sides]).T
        start = (driver.reference + sign * last * step)[:, None]
        at = (driver.reference + sign * (last + 1.0) * step)[:, None]
        stride = sign * step
        begun = (rows[:size], rows[size : 2 * size] * stride, rows[2 * size :])
        top = np.ones(len(sides))
        pose, rate, signs, failed = advance(plan, start, at, begun, branch_of, top)
        flat = np.concatenate([pose, rate / stride, signs])
        for i, side in enumerate(sides):
            side[1] += 1.0
            kept[side[0] * side[1]] = flat[:, i]
            if failed[:, i].all():
                # nothing comes back from a failed step: every farther anchor fails
                while side[1] < side[2]:
                    side[1] += 1.0
                    kept[side[0] * side[1]] = flat[:, i]
        sides = [side for side in sides if side[1] < side[2]]
    return np.array([kept[m] for m in wanted]).T


def _anchored(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    walked: Array,
    which: Any,
    start: Array,
) -> list[Any]:
    """Reach ``drive`` (one driver) from the anchors ``walked`` (:func:`_anchor_poses`).

    The anchors lie whole continuation steps from the reference pose on the driver's
    path, ``which[i]`` the last before position ``i``: each position is reached from
    it by :func:`assur._follow.advance` (one step where nothing is in the way), at the
    cost of one step a position instead of one for every step of its distance (a
    dense sweep of a crank has many positions per anchor). A group's pose is NaN
    where it failed, at the anchor or on the way. ``start`` holds each position's
    anchor (rad or m).
    """
    size = 3 * sum(layout(plan))
    values = walked[:, which]
    span = drive[:, 0] - start
    begun = (values[:size], values[size : 2 * size] * span, values[2 * size :])
    top = np.ones(drive.shape[0])
    pose = advance(plan, start[:, None], drive, begun, branch_of, top)[0]
    return nested(plan, pose)


def _straight(
    plan: Plan,
    drive: Array,
    branch_of: BranchOf | None,
    reference: Array,
    counts: Array,
) -> list[Any]:
    """Walk every position to ``drive`` on its own path, in steps of 1/``counts``."""
    n = drive.shape[0]
    if not n:
        return nested(plan, np.zeros((3 * sum(layout(plan)), 0)))
    base = np.repeat(reference[None, :], n, axis=0)
    path = drive - base
    if isinstance(branch_of, OnPaths):
        # the change points on the paths, found once: the walks stop at them
        # rather than asking for the branches at every trial step
        last = max(g for g, solver in enumerate(plan.solvers) if solver.newton)
        met = branch_of.met(drive, last)
        # each path's stops: the change points on the way, then the position
        everywhere = np.arange(n)
        ends = stops(n, met, np.ones(n), everywhere, everywhere)[:3]
        pose = walk(plan, (reference, path), ends, met, 1.0 / counts)[0]
        return nested(plan, pose)
    pose, _, rate, sign = tangents(plan, base, None, path, branch_of)
    pose = advance(plan, base, drive, (pose, rate, sign), branch_of, 1.0 / counts)[0]
    return nested(plan, pose)


def _too_far(plan: Plan, drive: Array, counts: Array) -> None:
    """Raise the error of a position too far from the reference pose to walk to."""
    from assur._position_titles import position_text
    from assur.errors import ConvergenceError

    row = int(np.argmax(counts > MAX_STEPS))
    values = [
        math.degrees(x) if d.kind == "R" else float(x)
        for d, x in zip(plan.drivers, drive[row], strict=True)
    ]
    where = position_text([d.kind for d in plan.drivers], values)
    msg = (
        f"driver position {where} is {int(counts[row])} continuation steps from the "
        f"reference pose; expected at most {MAX_STEPS} (positions within "
        f"{MAX_STEPS // 20} mechanism sizes of it)"
    )
    raise ConvergenceError(msg)


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
