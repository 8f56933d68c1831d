"""Change points met on the straight paths of several drivers.

With several drivers each position of a sweep is reached along its own straight path
in driver space from the reference pose (:func:`assur._kinematics.continuation`). Every
closed-form dyad's discriminant is sampled along each path; where it touches zero (a
change point, see :mod:`assur._branches`) the dyad moves on onto its other branch, so
a position's branch is the reference pose's flipped once per change point on its path.

Scanned: the groups before the first one solved by Newton's method (the dyads after
one would need its continuation to every sample of every path).
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._branches import CANDIDATE, TOUCH, flipped, lowest
from assur._follow import drivers
from assur._vec import Array, Index
from assur.plan import Plan

__all__ = ["PathChanges", "path_changes"]

CRANK_STEP = math.radians(2.0)
"""Largest step between samples of a path along a crank's angle, rad (four of the
one-driver scan's grid: a minimum between samples is also told by the parabola
through the three nearest, see :func:`_touches`)."""
SLIDER_STEP = 0.008
"""Largest step between samples of a path along a slider, in mechanism sizes."""
SAMPLES = 1 << 14
"""Samples assembled at once: the paths are taken in slices of about this many."""
KEPT = 4
"""Batches of positions whose change points are kept with the plan (the sweep's own
and its slices' are asked for again by the forward pass)."""


@dataclass(frozen=True, slots=True)
class PathChanges:
    """The change points on each position's straight path, by solver index.

    ``count[g]`` (n,) is how many change points of group ``g`` lie on the path from
    the reference pose to each position, ``branch[g]`` (n,) its branch there (+1 or
    -1); groups that meet none on any path are absent.
    """

    count: dict[int, Index]
    branch: dict[int, Array]


def path_changes(plan: Plan, drive: Array) -> PathChanges:
    """Return the change points on the paths to driver positions ``drive`` (n, d), SI.

    The last few batches asked for are kept with the plan.
    """
    kept: dict[bytes, PathChanges] = plan.memo.setdefault("path-changes", {})
    key = np.ascontiguousarray(drive, dtype=float).tobytes() + str(drive.shape).encode()
    found = kept.get(key)
    if found is None:
        found = _changes(plan, drive)
        if len(kept) >= KEPT:
            kept.pop(next(iter(kept)))
        kept[key] = found
    return found


def _scanned(plan: Plan) -> list[int]:
    """Return the solvers scanned: those before the first Newton-solved one."""
    out = []
    for g, solver in enumerate(plan.solvers):
        if solver.newton:
            break
        out.append(g)
    return out


def _changes(plan: Plan, drive: Array) -> PathChanges:
    """Scan the paths to ``drive`` slice by slice (see :func:`path_changes`)."""
    groups = _scanned(plan)
    n = drive.shape[0]
    counts: dict[int, Index] = {g: np.zeros(n, dtype=np.int64) for g in groups}
    if n and groups:
        reference = np.array([d.reference for d in plan.drivers])
        unit = np.array(
            [
                CRANK_STEP if d.kind == "R" else SLIDER_STEP * plan.scale
                for d in plan.drivers
            ]
        )
        far = np.max(np.abs(drive - reference) / unit, axis=1)
        intervals = np.maximum(2, np.ceil(far)).astype(np.int64)
        for rows in _slices(intervals + 3):
            found = _counts(plan, groups, reference, drive[rows], intervals[rows])
            for g, c in found.items():
                counts[g][rows] = c
    count = {g: c for g, c in counts.items() if c.any()}
    branch = {}
    for g, c in count.items():
        branch[g] = flipped(plan.solvers[g].branch, c)
    return PathChanges(count, branch)


def _slices(sizes: Index) -> Iterator[slice]:
    """Yield slices of consecutive paths of about :data:`SAMPLES` samples in all."""
    total = np.cumsum(sizes)
    start = 0
    while start < sizes.shape[0]:
        before = total[start - 1] if start else 0
        stop = int(np.searchsorted(total, before + SAMPLES, side="right"))
        stop = max(stop, start + 1)
        yield slice(start, stop)
        start = stop


@dataclass(frozen=True, slots=True)
class _Paths:
    """Samples of straight paths: each sample's path, parameter and driver position.

    Path ``i`` runs from the reference pose (``s = 0``) to its position (``s = 1``)
    in ``m[i]`` steps, with one sample more at either end (``s = -1/m`` and
    ``1 + 1/m``) so that a change point at the position itself is found.
    """

    reference: Array
    delta: Array
    m: Index
    owner: Index
    j: Index
    s: Array
    first: Index

    def at(self, s: Array, paths: Index) -> Array:
        """Return driver positions at parameters ``s`` on ``paths`` (k, d)."""
        return self.reference + s[:, None] * self.delta[paths]


def _sampled(reference: Array, drive: Array, m: Index) -> _Paths:
    """Return samples of the paths from ``reference`` to ``drive``, ``m`` steps each."""
    per = m + 3
    owner = np.repeat(np.arange(drive.shape[0]), per)
    first = np.cumsum(per) - per
    j = np.arange(owner.size) - first[owner] - 1
    s = j / m[owner]
    return _Paths(reference, drive - reference, m, owner, j, s, first)


def _counts(
    plan: Plan, groups: list[int], reference: Array, drive: Array, m: Index
) -> dict[int, Index]:
    """Return each group's change points on the paths to ``drive`` (n,), by solver.

    One pass over the samples: each group is assembled on the branches its change
    points give it before the next group's discriminant is taken.
    """
    paths = _sampled(reference, drive, m)
    size = paths.owner.size
    still = (0.0,) * len(plan.drivers)
    bodies = drivers(plan, paths.at(paths.s, paths.owner), still, still)
    flipped: dict[int, Array] = {}
    out = {}
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for g in groups:
            solver = plan.solvers[g]
            values = solver.discriminant(bodies)
            if values is not None:
                values = np.broadcast_to(values, (size,))
                where, s = _touches(plan, groups, paths, values, flipped, g)
                if where.size:
                    out[g], flipped[g] = _flips(solver.branch, paths, where, s)
            if g != groups[-1]:
                solver.assemble(bodies, size, branch=flipped.get(g))
    return out


def _flips(own: float, paths: _Paths, where: Index, s: Array) -> tuple[Index, Array]:
    """Return the change points on each path and the branch at every sample.

    ``where`` are the paths and ``s`` the parameters of the change points found; one
    at the reference pose itself (s = 0) is not crossed.
    """
    crossed = (s > 1e-9) & (s <= 1.0 + 1e-9)
    count = np.bincount(where[crossed], minlength=paths.m.shape[0])
    # every sample from the change point to its path's end is past it
    size = paths.owner.size
    change = np.zeros(size + 1, dtype=np.int64)
    past = np.clip(np.ceil(s * paths.m[where] - 1e-9), -1, paths.m[where] + 1)
    np.add.at(change, paths.first[where] + past.astype(np.int64) + 1, 1)
    np.add.at(change, paths.first[where] + paths.m[where] + 3, -1)
    before = np.cumsum(change)[:size]
    return count, flipped(own, before)


def _touches(
    plan: Plan,
    groups: list[int],
    paths: _Paths,
    values: Array,
    flipped: dict[int, Array],
    g: int,
) -> tuple[Index, Array]:
    """Locate where group ``g``'s discriminant touches zero between samples.

    Returns the paths and parameters of the touches. A discriminant constant along a
    path (a dyad its drivers do not move) has no minimum there.
    """
    inside = (paths.j >= 0) & (paths.j <= paths.m[paths.owner])
    k = np.flatnonzero(inside)
    before, here, after = values[k - 1], values[k], values[k + 1]
    low = (here < before) & (here <= after)
    # the lowest value of the parabola through the three samples: zero for a
    # discriminant that touches zero quadratically, however far the samples
    bend = before - 2.0 * here + after
    vertex = here - (after - before) ** 2 / (8.0 * np.where(bend > 0.0, bend, np.inf))
    k = k[low & (np.minimum(np.abs(here), np.abs(vertex)) < CANDIDATE)]
    if k.size == 0:
        return k, np.zeros(0)
    where = paths.owner[k]
    middle, minimum = lowest(
        lambda s: _values(plan, groups, paths.at(s, where), flipped, k, g),
        paths.s[k - 1],
        paths.s[k + 1],
    )
    # a touch, not a dip below zero (where the dyad stops: no branch beyond)
    touch = np.abs(minimum) <= TOUCH
    return where[touch], middle[touch]


def _values(
    plan: Plan,
    groups: list[int],
    at: Array,
    flipped: dict[int, Array],
    k: Index,
    g: int,
) -> Any:
    """Return group ``g``'s discriminant at driver positions ``at`` near samples ``k``.

    The groups before it are assembled on their branches at those samples.
    """
    n = at.shape[0]
    still = (0.0,) * len(plan.drivers)
    bodies = drivers(plan, at, still, still)
    for h in groups:
        solver = plan.solvers[h]
        if h == g:
            return np.broadcast_to(solver.discriminant(bodies), (n,))
        branch = flipped.get(h)
        solver.assemble(bodies, n, branch=None if branch is None else branch[k])
    msg = f"group index {g} is not among the scanned ones"
    raise AssertionError(msg)
