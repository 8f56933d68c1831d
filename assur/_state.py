"""The forward pass's frozen result: :class:`KinematicState`, one array per quantity.

The state is made from the motions the forward pass solved (:func:`state_of`), the
motions are rebuilt from it (:func:`motions`), and a state is extended by the levels it
lacks, up to the jerks (:func:`extend`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._follow import drivers
from assur._vec import Array, Leaf, gather, is_array, take_rows
from assur.groups._motion import Motion
from assur.groups._pairs import slide
from assur.plan import Plan

__all__ = ["KinematicState", "extend", "jerks", "motions", "own_slides", "state_of"]

LEVELS = 4
"""Position, velocity, acceleration and jerk."""
CHUNK = 16384
"""Driver positions solved at once: a long sweep runs in slices of this size, and
its jerks, solved later, in the same slices (so every number is as in the sweep).

Read where it is used (``_state.CHUNK``), so that a test can make slices small.
Half of it took 1.1 to 1.6 times as long for 10^4 to 10^5 positions (benchmarks/):
a sweep's slices are gathered into its whole arrays, and each slice repeats the
Python-level work of every step."""


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
    jerk : tuple of leaves
        Each driver's jerk (rad/s^3 or m/s^3), for the jerks solved later; empty:
        zero, a driver whose acceleration holds.
    """

    drive: Array
    speed: tuple[Leaf, ...]
    acceleration: tuple[Leaf, ...]
    motion: tuple[tuple[Leaf, ...], ...]
    slide: dict[str, tuple[Leaf, ...]]
    top: int
    jerk: tuple[Leaf, ...] = ()

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
            take_rows(self.jerk, rows),
        )


def _at(value: Leaf, row: int) -> float:
    """Return a leaf's value at one row."""
    return float(value[row]) if is_array(value) else float(value)


def state_of(
    plan: Plan,
    bodies: list[Motion],
    drive: Array,
    rates: tuple[tuple[Leaf, ...], ...],
    top: int,
) -> KinematicState:
    """Return the state of a batch whose motions the forward pass has solved.

    The motions' arrays become the state's own (nothing is copied).
    """
    motion = tuple(
        (*m.phi[: top + 1], *m.ox[: top + 1], *m.oy[: top + 1], m.c, m.s)
        for m in bodies
    )
    slides = _slides(plan, bodies, top)
    return KinematicState(drive, rates[0], rates[1], motion, slides, top, jerks(rates))


def jerks(rates: tuple[tuple[Leaf, ...], ...]) -> tuple[Leaf, ...]:
    """Return the drivers' jerks of ``rates``; empty where none is other than zero."""
    jerk = rates[2] if len(rates) > 2 else ()
    if all(isinstance(v, float) and v == 0.0 for v in jerk):
        return ()
    return jerk


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
        state.drive, state.speed, state.acceleration, motion, slide, 3, state.jerk
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
    if state.top < 2 or state.jerk:
        # the state holds the drivers' motions up to its top level only (and a
        # driver's jerk of zero above it): they move as their rates say
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


def _rates(state: KinematicState) -> tuple[tuple[Leaf, ...], ...]:
    """Return the drivers' speeds, accelerations and jerks of ``state``."""
    return state.speed, state.acceleration, state.jerk


def _slide_jerks(plan: Plan, bodies: list[Motion]) -> dict[str, Leaf]:
    """Return the jerk of every prismatic pair's slide (m/s^3), as :func:`_slides`."""
    return {k: v[0] for k, v in _slide_levels(plan, bodies, range(3, 4)).items()}
