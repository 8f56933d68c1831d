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

from assur._follow import BranchOf, advance, drivers, layout, nested, tangents
from assur._vec import Array, Leaf, Mask, gather, is_array, take_rows
from assur.groups._motion import Motion
from assur.groups._pairs import slide
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
LEVELS = 4
"""Position, velocity, acceleration and jerk."""
CHUNK = 8192
"""Positions whose jerks are solved at once (the sweep's own slices)."""


@dataclass(frozen=True, slots=True)
class Trouble:
    """Driver positions (``mask``) where a group met trouble.

    Group ``group`` failed (``what``: "assembly", "singular"), came near a dead
    centre ("near") or was reached the other way round the crank's circle ("other
    way": the short way its branch folds before the position).
    """

    group: str
    what: str
    mask: Mask


@dataclass(frozen=True, slots=True)
class KinematicState:
    """The motion of every link over a sweep: the forward pass's frozen result.

    Every quantity is a leaf: an array with one value per position, or a float where
    it does not change over the sweep (the frame, a crank's constant speed).

    Attributes
    ----------
    drive : ndarray (n, d)
        Driver positions, rad (m for a prismatic driver), as solved: a crank's angle
        within half a turn of the reference pose.
    speed, acceleration : tuple of leaves
        Each driver's speed (rad/s or m/s) and acceleration (rad/s^2 or m/s^2).
    motion : tuple
        Per body (index 0 is the frame), its rotation from the reference pose and the
        path of its origin (m, core coordinates: see ``Plan.shift``) with their
        derivatives, then the rotation's cosine and sine: ``phi[0..top], ox[0..top],
        oy[0..top], cos, sin``.
    slide : dict of str to tuple
        Slide (m) of every prismatic pair and its derivatives, levels 0 to ``top``.
    top : int
        The highest time derivative solved (2: accelerations; 3: jerks).
    """

    drive: Array
    speed: tuple[Leaf, ...]
    acceleration: tuple[Leaf, ...]
    motion: tuple[tuple[Leaf, ...], ...]
    slide: dict[str, tuple[Leaf, ...]]
    top: int

    def __len__(self) -> int:
        return int(self.drive.shape[0])

    def rotation(self, body: int, k: int) -> Leaf:
        """Return level ``k`` of a body's rotation (rad, rad/s, ...)."""
        return self.motion[body][k]

    def origin(self, body: int, k: int) -> tuple[Leaf, Leaf]:
        """Return level ``k`` of a body's origin (m, m/s, ..., core coordinates)."""
        levels = self.top + 1
        entries = self.motion[body]
        return entries[levels + k], entries[2 * levels + k]

    def pose(self, row: int) -> tuple[Array, Array]:
        """Return every body's rotation (B,) and origin (B, 2) at ``row`` (core)."""
        levels = self.top + 1
        phi = np.array([_at(m[0], row) for m in self.motion])
        origin = np.array(
            [[_at(m[levels], row), _at(m[2 * levels], row)] for m in self.motion]
        )
        return phi, origin

    def rows(self, rows: Any) -> KinematicState:
        """Return the state at ``rows`` (a slice gives views, a mask copies)."""
        motion = tuple(
            tuple(x[rows] if is_array(x) else x for x in entries)
            for entries in self.motion
        )
        slide = take_rows(self.slide, rows)
        return KinematicState(
            self.drive[rows],
            take_rows(self.speed, rows),
            take_rows(self.acceleration, rows),
            motion,
            slide,
            self.top,
        )


def _at(value: Leaf, row: int) -> float:
    """Return a leaf's value at one row."""
    return float(value[row]) if is_array(value) else float(value)


def solve(
    plan: Plan,
    drive: Array,
    speed: Any,
    acceleration: Any,
    top: int = 3,
    branch_of: BranchOf | None = None,
) -> tuple[list[Motion], list[Trouble]]:
    """Solve the motion of every link at driver positions ``drive`` (n, d), SI units.

    ``speed`` and ``acceleration`` hold each driver's rate: a float per driver (a
    sequence) or an array (n,) per driver; ``branch_of`` gives the groups' branches
    past change points. Returns the links' motions (levels 0 to ``top``) and the
    troubles met; positions that fail hold NaN.
    """
    n = drive.shape[0]
    guesses, around = _continued(plan, drive, branch_of) if plan.newton else ([], [])
    branch = {} if branch_of is None else branch_of(drive, len(plan.solvers))
    bodies = drivers(plan, drive, speed, acceleration)
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


def continuation(plan: Plan, drive: Array, branch_of: BranchOf | None) -> list[Any]:
    """Follow the Newton groups from the reference pose to ``drive``.

    Each position is reached along the straight path of the driver from the reference
    pose; a crank position that path cannot reach (the group does not assemble
    somewhere on the way) is tried again the other way round the circle.
    """
    return _continued(plan, drive, branch_of)[0]


def _continued(
    plan: Plan, drive: Array, branch_of: BranchOf | None
) -> tuple[list[Any], list[Mask]]:
    """Return :func:`continuation`'s poses and where each group went the other way.

    The masks (n,), one per Newton group, mark the positions reached the other way
    round the circle.
    """
    guesses = _walk(plan, drive, branch_of)
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
    retry = _walk(
        plan, drive[failed] - 2.0 * math.pi * np.where(gap >= 0, 1.0, -1.0), branch_of
    )
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


def _walk(plan: Plan, drive: Array, branch_of: BranchOf | None) -> list[Any]:
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
        walked = _anchor_poses(plan, marks, branch_of)
        start = reference[0] + marks[which.ravel()] * step[0]
        return _anchored(plan, drive, branch_of, walked, which.ravel(), start)
    return _straight(plan, drive, branch_of, reference, counts)


def _separate(plan: Plan, drive: Array, branch_of: BranchOf | None) -> list[Any]:
    """Walk every position on its own straight path from the reference pose.

    What :func:`_walk` does with several drivers; with one, the paths it shares
    reach the same poses (the tests and benchmarks/bench_continuation.py compare).
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


def _anchor_poses(plan: Plan, marks: Array, branch_of: BranchOf | None) -> Array:
    """Return the Newton groups at ``marks`` whole steps from the reference (packed).

    The reference pose is solved first; the anchors on either side are then walked
    to one after the other, each one step on from the last, both sides together, and
    kept with the plan (a few numbers): the slices of a long sweep, and every later
    sweep of the mechanism, start from them. Each anchor keeps its poses, their rates
    of change per unit of the driver and their Jacobians' signs (rows, marks); a side
    whose step fails is NaN from there on, and its walk stops.
    """
    driver = plan.drivers[0]
    step = _stride(plan, driver)
    key = "anchors" if branch_of is None else "anchors-past-change-points"
    kept: dict[float, Array] = plan.memo.setdefault(key, {})
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
        last = max((m * sign for m in kept), default=0.0)
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
    pose, _, rate, sign = tangents(plan, base, None, path, branch_of)
    pose = advance(plan, base, drive, (pose, rate, sign), branch_of, 1.0 / counts)[0]
    return nested(plan, pose)


def _too_far(plan: Plan, drive: Array, counts: Array) -> None:
    """Raise the error of a position too far from the reference pose to walk to."""
    from assur._text import position_text
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


def state_of(
    plan: Plan,
    bodies: list[Motion],
    drive: Array,
    rates: tuple[tuple[Leaf, ...], tuple[Leaf, ...]],
    top: int,
) -> KinematicState:
    """Return the state of a batch whose motions the forward pass has solved.

    The motions' arrays become the state's own (nothing is copied).
    """
    motion = tuple(
        (*m.phi[: top + 1], *m.ox[: top + 1], *m.oy[: top + 1], m.c, m.s)
        for m in bodies
    )
    return KinematicState(
        drive, rates[0], rates[1], motion, _slides(plan, bodies, top), top
    )


def _slides(plan: Plan, bodies: list[Motion], top: int) -> dict[str, tuple[Leaf, ...]]:
    """Slides of the prismatic pairs: a group's own coordinate where it is one."""
    return _slide_levels(plan, bodies, range(top + 1))


def _slide_levels(
    plan: Plan, bodies: list[Motion], levels: range
) -> dict[str, tuple[Leaf, ...]]:
    """Return the derivatives ``levels`` of every prismatic pair's slide (m, m/s...)."""
    own = own_slides(plan)
    out = {}
    for name, pair in plan.pairs.items():
        if pair.kind != "P":
            continue
        if name in own:
            body, sign = own[name]
            q = bodies[body].q
            out[name] = tuple(q[k] if sign > 0 else -q[k] for k in levels)
        else:
            out[name] = tuple(slide(pair, bodies, k) for k in levels)
    return out


def own_slides(plan: Plan) -> dict[str, tuple[int, float]]:
    """Return the prismatic pairs whose slide is a group's own coordinate (per plan)."""
    found = plan.memo.get("own-slides")
    if found is None:
        found = {}
        for solver in plan.solvers:
            found.update(solver.own_slides())
        plan.memo["own-slides"] = found
    return found  # type: ignore[no-any-return]


def motions(plan: Plan, state: KinematicState, finished: bool = True) -> list[Motion]:
    """Rebuild the forward pass's motions from a frozen state.

    The quantities that were floats in the forward pass are floats again, so every
    kernel run on the rebuilt motions takes the same steps and gives the same numbers
    as on the originals. Levels above ``state.top`` are zero. ``finished=False``
    leaves the groups' links open to solving a further level (see :func:`extend`).
    """
    levels = state.top + 1
    pad = [0.0] * (LEVELS - levels)
    out = []
    for entries in state.motion:
        out.append(
            Motion.restore(
                [*entries[:levels], *pad],
                [*entries[levels : 2 * levels], *pad],
                [*entries[2 * levels : 3 * levels], *pad],
                entries[3 * levels],
                entries[3 * levels + 1],
            )
        )
    for name, (body, sign) in own_slides(plan).items():
        values = state.slide[name]
        out[body].q = [v if sign > 0 else -v for v in values]
    moving = {b for solver in plan.solvers for b in solver.bodies}
    for b, m in enumerate(out):
        if finished or b not in moving:
            m.finish()
    return out


def extend(plan: Plan, state: KinematicState) -> KinematicState:
    """Return ``state`` with the jerks solved too (level 3), group by group.

    A state of positions alone (that of a table of few columns) has its velocities
    and accelerations solved as well.

    A long sweep is solved in slices of ``CHUNK`` positions, as the sweep was;
    only the jerks are new, the lower levels are the state's own arrays.
    """
    if state.top >= 3:
        return state
    if state.top != 2:
        bodies = _solved(plan, state, range(state.top + 1, LEVELS))
        return state_of(plan, bodies, state.drive, _rates(state), 3)
    n = len(state)
    if n <= CHUNK:
        bodies = _jerks(plan, state)
        new = [(m.phi[3], m.ox[3], m.oy[3]) for m in bodies], _slide_jerks(plan, bodies)
    else:
        new = gather(n, _jerk_slices(plan, state))
    motion = tuple(
        (*e[0:3], j[0], *e[3:6], j[1], *e[6:9], j[2], e[9], e[10])
        for e, j in zip(state.motion, new[0], strict=True)
    )
    slide = {name: (*values, new[1][name]) for name, values in state.slide.items()}
    return KinematicState(
        state.drive, state.speed, state.acceleration, motion, slide, 3
    )


def _jerk_slices(plan: Plan, state: KinematicState) -> Any:
    """Yield each slice's rows and its links' and slides' jerks."""
    n = len(state)
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        bodies = _jerks(plan, state.rows(rows))
        yield (
            rows,
            (
                [(m.phi[3], m.ox[3], m.oy[3]) for m in bodies],
                _slide_jerks(plan, bodies),
            ),
        )


def _jerks(plan: Plan, state: KinematicState) -> list[Motion]:
    """Return the motions of ``state`` with their jerks solved."""
    return _solved(plan, state, range(3, LEVELS))


def _solved(plan: Plan, state: KinematicState, levels: range) -> list[Motion]:
    """Return the motions of ``state`` with the derivatives ``levels`` solved too.

    ``levels`` are those above ``state.top``; the driving links move as the state's
    rates say at every level.
    """
    bodies = motions(plan, state, finished=False)
    if state.top < 2:
        # the state holds the drivers' motions up to its top level only
        moving = drivers(plan, state.drive, *_rates(state))
        for d in plan.drivers:
            bodies[d.body] = moving[d.body]
    for solver in plan.solvers:
        lin = solver.linearize(bodies)
        for k in levels:
            solver.derivative(bodies, k, lin)
        for b in solver.bodies:
            bodies[b].finish()
    return bodies


def _rates(state: KinematicState) -> tuple[tuple[Leaf, ...], tuple[Leaf, ...]]:
    """Return the drivers' speeds and accelerations of ``state``."""
    return state.speed, state.acceleration


def _slide_jerks(plan: Plan, bodies: list[Motion]) -> dict[str, Leaf]:
    """Return the jerk of every prismatic pair's slide (m/s^3), as :func:`_slides`."""
    return {k: v[0] for k, v in _slide_levels(plan, bodies, range(3, 4)).items()}
