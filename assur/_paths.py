"""Change points met on the straight paths of several drivers.

With several drivers each position of a sweep is reached along its own straight path
in driver space from the reference pose (:func:`assur._kinematics.continuation`). Every
closed-form dyad's discriminant is sampled along each path; where it touches zero (a
change point, see :mod:`assur._branches`) the dyad moves on onto its other branch, so
a position's branch is the reference pose's flipped once per change point on its path.

Scanned: every closed-form dyad. A group solved by Newton's method has no branch to
choose; it is walked along each path from sample to sample, so that the dyads after
it are scanned on the poses its continuation reaches.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._branches import CANDIDATE, TOUCH, closed, lowest
from assur._follow import drivers, layout, tangents
from assur._quiet import quiet
from assur._vec import Array, Index
from assur._walk import PAST, Met, flipped, stops, walk
from assur.plan import Plan

__all__ = ["PathBranches", "PathChanges", "path_changes"]

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
    -1); groups that meet none on any path are absent. ``met`` holds every change
    point found near the paths (a little behind the reference pose and beyond the
    positions too): its path and parameter.
    """

    count: dict[int, Index]
    branch: dict[int, Array]
    met: Met = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class PathBranches:
    """The groups' branches at positions reached on straight paths (a BranchOf).

    Also tells the change points on the paths (see :class:`assur._walk.OnPaths`):
    the continuation then walks through them rather than asking at every step.
    """

    plan: Plan

    def __call__(self, at: Array, upto: int) -> dict[int, Array]:
        """Return each dyad's branch at driver positions ``at`` (n, d), SI units."""
        return path_changes(self.plan, at, upto).branch

    def met(self, drive: Array, upto: int) -> Met:
        """Return the change points on the paths to ``drive`` (n, d), SI units."""
        return path_changes(self.plan, drive, upto).met


def path_changes(plan: Plan, drive: Array, upto: int | None = None) -> PathChanges:
    """Return the change points on the paths to driver positions ``drive`` (n, d), SI.

    ``upto``: the groups before this solver index are all the caller reads (the
    continuation of a Newton group needs those before it only). The last few batches
    asked for are kept with the plan.
    """
    groups = closed(plan, len(plan.solvers) if upto is None else upto)
    if not groups:
        return PathChanges({}, {})
    kept: dict[bytes, PathChanges] = plan.memo.setdefault("path-changes", {})
    key = np.ascontiguousarray(drive, dtype=float).tobytes()
    key += f"{drive.shape} {len(groups)}".encode()
    found = kept.get(key)
    if found is None:
        found = _changes(plan, groups, drive)
        if len(kept) >= KEPT:
            # another thread may drop the same oldest batch at once: no KeyError
            oldest = next(iter(list(kept)), None)
            if oldest is not None:
                kept.pop(oldest, None)
        kept[key] = found
    return found


def _changes(plan: Plan, groups: list[int], drive: Array) -> PathChanges:
    """Scan ``groups`` on the paths to ``drive``, slice by slice."""
    n = drive.shape[0]
    counts: dict[int, Index] = {
        g: np.zeros(n, dtype=np.int64) for g in groups if not plan.solvers[g].newton
    }
    met: dict[int, list[tuple[Index, Array]]] = {}
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
            for g, c in found[0].items():
                counts[g][rows] = c
            for g, (where, at) in found[1].items():
                met.setdefault(g, []).append((where + rows.start, at))
    count = {g: c for g, c in counts.items() if c.any()}
    branch = {}
    for g, c in count.items():
        branch[g] = flipped(plan.solvers[g].branch, c)
    joined: Met = {}
    for g, parts in met.items():
        joined[g] = (
            np.concatenate([where for where, _ in parts]),
            np.concatenate([at for _, at in parts]),
        )
    return PathChanges(count, branch, joined)


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


@dataclass(frozen=True, slots=True)
class _Scan:
    """What a scan of sampled paths finds, by solver index, filled in group by group.

    ``flipped[g]``: a dyad's branch at every sample; ``met[g]``: the paths and
    parameters of its change points; ``walked[g]``: a Newton group's link poses at
    every sample (see :func:`assur._follow.nested`).
    """

    paths: _Paths
    flipped: dict[int, Array] = field(default_factory=dict)
    met: Met = field(default_factory=dict)
    walked: dict[int, list[Any]] = field(default_factory=dict)


def _counts(
    plan: Plan, groups: list[int], reference: Array, drive: Array, m: Index
) -> tuple[dict[int, Index], Met]:
    """Return each dyad's change points on the paths to ``drive``, by solver.

    Returns how many lie on each path (n,) and where they all lie (see
    :class:`PathChanges`). One pass over the samples: each group is assembled on the
    branches its change points give it before the next group's discriminant is taken;
    a Newton group takes the poses its walk along each path reaches (:func:`_walked`).
    """
    scan = _Scan(_sampled(reference, drive, m))
    paths = scan.paths
    size = paths.owner.size
    still = (0.0,) * len(plan.drivers)
    bodies = drivers(plan, paths.at(paths.s, paths.owner), still, still)
    out = {}
    with quiet():
        for g in groups:
            solver = plan.solvers[g]
            if solver.newton:
                scan.walked[g] = _walked(plan, g, scan)
                solver.assemble(bodies, size, scan.walked[g])
                continue
            values = solver.discriminant(bodies)
            if values is not None:
                values = np.broadcast_to(values, (size,))
                where, s = _touches(plan, groups, scan, values, g)
                if where.size:
                    out[g], scan.flipped[g] = _flips(solver.branch, paths, where, s)
                    scan.met[g] = (where, s)
            if g != groups[-1]:
                solver.assemble(bodies, size, branch=scan.flipped.get(g))
    return out, scan.met


def _flips(own: float, paths: _Paths, where: Index, s: Array) -> tuple[Index, Array]:
    """Return the change points on each path and the branch at every sample.

    ``where`` are the paths and ``s`` the parameters of the change points found. One
    ahead of the reference pose (0 < s <= 1) is crossed on the way to the position;
    one at the reference pose itself or behind it (s <= 0) is not, though the sample
    behind the reference pose is past it (the rule of :func:`assur._walk.crossed`).
    """
    ahead = s > PAST
    count = np.bincount(where[ahead & (s <= 1.0 + PAST)], minlength=paths.m.shape[0])
    size = paths.owner.size
    change = np.zeros(size + 1, dtype=np.int64)
    m, first = paths.m[where], paths.first[where]
    # ahead: every sample from the change point to its path's end is past it
    past = np.clip(np.ceil(s * m - PAST), 0, m + 1).astype(np.int64)
    np.add.at(change, np.where(ahead, first + past + 1, first), 1)
    np.add.at(change, np.where(ahead, first + m + 3, first + 1), -1)
    before = np.cumsum(change)[:size]
    return count, flipped(own, before)


def _walked(plan: Plan, g: int, scan: _Scan) -> list[Any]:
    """Return Newton group ``g``'s link poses at every sample, walked along each path.

    Each path is followed from the reference pose through its samples and the
    change points on it of the dyads before ``g`` (:func:`assur._walk.walk`); the
    sample behind the reference pose is reached by a walk back, through those
    between. A path's poses are NaN from where the group fails.
    """
    paths = scan.paths
    n = paths.m.shape[0]
    met = {h: found for h, found in scan.met.items() if h < g}
    newton = [h for h, solver in enumerate(plan.solvers) if solver.newton]
    before = 3 * sum(layout(plan)[: newton.index(g)])
    rows = slice(before, before + 3 * len(plan.solvers[g].bodies))
    out = np.full((rows.stop - rows.start, paths.owner.size), np.nan)
    reference = paths.reference
    at = np.repeat(reference[None, :], n, axis=0)
    pose, _, rate, sign = tangents(plan, at, None, paths.delta, {})
    begun = (pose, rate, sign)
    out[:, paths.first + 1] = pose[rows]
    # back: along -delta to the sample behind, through the change points between;
    # one at the reference pose itself is crossed going back, as _flips has it
    back = {
        h: (where, np.where(t > PAST, -t, np.maximum(-t, 2.0 * PAST)))
        for h, (where, t) in met.items()
    }
    everywhere = np.arange(n)
    ends = stops(n, back, 1.0 / paths.m, everywhere, paths.first)
    walk(
        plan,
        (reference, -paths.delta),
        ends[:3],
        back,
        np.full(n, np.inf),
        _reversed(begun),
        _recorder(out, rows, ends[3]),
    )
    ahead = np.flatnonzero(paths.j >= 1)
    ends = stops(n, met, paths.s[ahead], paths.owner[ahead], ahead)
    walk(
        plan,
        (reference, paths.delta),
        ends[:3],
        met,
        np.full(n, np.inf),
        begun,
        _recorder(out, rows, ends[3]),
    )
    values = iter(out)
    return [tuple(next(values) for _ in range(3)) for _ in plan.solvers[g].bodies]


def _recorder(out: Array, rows: slice, samples: Index) -> Any:
    """Return what keeps a walk's poses at its stops that are samples, in ``out``.

    ``rows`` are the group's rows of the packed poses; ``samples`` each stop's
    sample (-1 for a change point).
    """

    def record(k: Index, pose: Array) -> None:
        sample = samples[k]
        out[:, sample[sample >= 0]] = pose[rows][:, sample >= 0]

    return record


def _reversed(begun: tuple[Array, Array, Array]) -> tuple[Array, Array, Array]:
    """Return poses, rates and signs for a walk the other way: the rates negated."""
    return begun[0], -begun[1], begun[2]


def _touches(
    plan: Plan,
    groups: list[int],
    scan: _Scan,
    values: Array,
    g: int,
) -> tuple[Index, Array]:
    """Locate where group ``g``'s discriminant touches zero between samples.

    Returns the paths and parameters of the touches. A discriminant constant along a
    path (a dyad its drivers do not move) has no minimum there.
    """
    paths = scan.paths
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
    # a Newton group starts from its pose at the sample, then from its last pose
    near = {
        h: [tuple(v[k] for v in link) for link in scan.walked[h]] for h in scan.walked
    }
    middle, minimum = lowest(
        lambda s: _values(plan, groups, scan, paths.at(s, where), k, g, near),
        paths.s[k - 1],
        paths.s[k + 1],
    )
    # a touch, not a dip below zero (where the dyad stops: no branch beyond)
    touch = np.abs(minimum) <= TOUCH
    return where[touch], middle[touch]


def _values(
    plan: Plan,
    groups: list[int],
    scan: _Scan,
    at: Array,
    k: Index,
    g: int,
    near: dict[int, list[Any]],
) -> Any:
    """Return group ``g``'s discriminant at driver positions ``at`` near samples ``k``.

    The groups before it are assembled on their branches at those samples; a Newton
    group by Newton's method from its pose in ``near``, which then keeps the poses
    found (where they close).
    """
    n = at.shape[0]
    still = (0.0,) * len(plan.drivers)
    bodies = drivers(plan, at, still, still)
    for h in groups:
        solver = plan.solvers[h]
        if h == g:
            return np.broadcast_to(solver.discriminant(bodies), (n,))
        if solver.newton:
            found = solver.assemble(bodies, n, near[h]).guess
            near[h] = [
                tuple(
                    np.where(np.isfinite(v), v, w) for v, w in zip(*pair, strict=True)
                )
                for pair in zip(found, near[h], strict=True)
            ]
            continue
        branch = scan.flipped.get(h)
        solver.assemble(bodies, n, branch=None if branch is None else branch[k])
    msg = f"group index {g} is not among the scanned ones"
    raise AssertionError(msg)
