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

from assur._branches import CANDIDATE, TOUCH, flipped, lowest
from assur._follow import advance, drivers, layout, tangents
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


def path_changes(plan: Plan, drive: Array, upto: int | None = None) -> PathChanges:
    """Return the change points on the paths to driver positions ``drive`` (n, d), SI.

    ``upto``: the groups before this solver index are all the caller reads (the
    continuation of a Newton group needs those before it only). The last few batches
    asked for are kept with the plan.
    """
    groups = _scanned(plan, len(plan.solvers) if upto is None else upto)
    if not groups:
        return PathChanges({}, {})
    kept: dict[bytes, PathChanges] = plan.memo.setdefault("path-changes", {})
    key = np.ascontiguousarray(drive, dtype=float).tobytes()
    key += f"{drive.shape} {len(groups)}".encode()
    found = kept.get(key)
    if found is None:
        found = _changes(plan, groups, drive)
        if len(kept) >= KEPT:
            kept.pop(next(iter(kept)))
        kept[key] = found
    return found


def _scanned(plan: Plan, upto: int) -> list[int]:
    """Return the solvers scanned: up to the last closed-form one before ``upto``."""
    closed = [g for g, s in enumerate(plan.solvers[:upto]) if not s.newton]
    return list(range(closed[-1] + 1)) if closed else []


def _changes(plan: Plan, groups: list[int], drive: Array) -> PathChanges:
    """Scan ``groups`` on the paths to ``drive``, slice by slice."""
    n = drive.shape[0]
    counts: dict[int, Index] = {
        g: np.zeros(n, dtype=np.int64) for g in groups if not plan.solvers[g].newton
    }
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


@dataclass(frozen=True, slots=True)
class _Scan:
    """What a scan of sampled paths has found so far, by solver index.

    ``flipped[g]``: a dyad's branch at every sample; ``met[g]``: the paths and
    parameters of its change points; ``walked[g]``: a Newton group's link poses at
    every sample (see :func:`assur._follow.nested`).
    """

    paths: _Paths
    flipped: dict[int, Array] = field(default_factory=dict)
    met: dict[int, tuple[Index, Array]] = field(default_factory=dict)
    walked: dict[int, list[Any]] = field(default_factory=dict)


def _counts(
    plan: Plan, groups: list[int], reference: Array, drive: Array, m: Index
) -> dict[int, Index]:
    """Return each dyad's change points on the paths to ``drive`` (n,), by solver.

    One pass over the samples: each group is assembled on the branches its change
    points give it before the next group's discriminant is taken; a Newton group
    takes the poses its walk along each path reaches (:func:`_walked`).
    """
    scan = _Scan(_sampled(reference, drive, m))
    paths = scan.paths
    size = paths.owner.size
    still = (0.0,) * len(plan.drivers)
    bodies = drivers(plan, paths.at(paths.s, paths.owner), still, still)
    out = {}
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
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
    return out


def _flips(own: float, paths: _Paths, where: Index, s: Array) -> tuple[Index, Array]:
    """Return the change points on each path and the branch at every sample.

    ``where`` are the paths and ``s`` the parameters of the change points found. One
    ahead of the reference pose (0 < s <= 1) is crossed on the way to the position;
    one at the reference pose itself or behind it (s <= 0) is not, though the sample
    behind the reference pose is past it.
    """
    ahead = s > 1e-9
    count = np.bincount(where[ahead & (s <= 1.0 + 1e-9)], minlength=paths.m.shape[0])
    size = paths.owner.size
    change = np.zeros(size + 1, dtype=np.int64)
    m, first = paths.m[where], paths.first[where]
    # ahead: every sample from the change point to its path's end is past it
    past = np.clip(np.ceil(s * m - 1e-9), 0, m + 1).astype(np.int64)
    np.add.at(change, np.where(ahead, first + past + 1, first), 1)
    np.add.at(change, np.where(ahead, first + m + 3, first + 1), -1)
    before = np.cumsum(change)[:size]
    return count, flipped(own, before)


def _crossed(plan: Plan, scan: _Scan, g: int, go: Index, x: Array) -> dict[int, Array]:
    """Return the dyads' branches before group ``g`` at ``x`` on paths ``go``.

    The rule of :func:`_flips`: a change point is crossed when it lies between the
    reference pose (s = 0) and ``x``, on either side.
    """
    n = scan.paths.m.shape[0]
    at = np.full(n, np.nan)
    at[go] = x
    out = {}
    for h, (where, s) in scan.met.items():
        if h < g:
            y = at[where]
            crossed = np.where(s > 1e-9, s <= y, s >= y)
            count = np.bincount(where[crossed], minlength=n)[go]
            out[h] = flipped(plan.solvers[h].branch, count)
    return out


def _stops(scan: _Scan, g: int) -> tuple[Array, Index, Index, Index]:
    """Return the stops of the walk of Newton group ``g`` along every path, in order.

    A path's stops are its samples from the reference pose on and the change points
    ahead of it of the dyads before ``g``. Returns their parameters ``s``, their
    samples (-1 for a change point), and each path's first stop and count of stops.
    """
    paths = scan.paths
    ahead = np.flatnonzero(paths.j >= 0)
    s, owner, sample = [paths.s[ahead]], [paths.owner[ahead]], [ahead]
    for h, (where, t) in scan.met.items():
        keep = (h < g) & (t > 1e-9) & (t < 1.0 + 1.0 / paths.m[where])
        s.append(t[keep])
        owner.append(where[keep])
        sample.append(np.full(int(keep.sum()), -1))
    order = np.lexsort((np.concatenate(s), np.concatenate(owner)))
    count = np.bincount(np.concatenate(owner), minlength=paths.m.shape[0])
    first = np.cumsum(count) - count
    return np.concatenate(s)[order], np.concatenate(sample)[order], first, count


def _walked(plan: Plan, g: int, scan: _Scan) -> list[Any]:
    """Return Newton group ``g``'s link poses at every sample, walked along each path.

    Each path is followed from the reference pose through its stops (:func:`_stops`):
    the dyads' branches flip at their change points, and no step spans one. The
    sample behind the reference pose is reached by a step back. A path's poses are
    NaN from where the group fails.
    """
    paths = scan.paths
    n = paths.m.shape[0]
    s, sample, first, count = _stops(scan, g)
    newton = [h for h, solver in enumerate(plan.solvers) if solver.newton]
    before = 3 * sum(layout(plan)[: newton.index(g)])
    rows = slice(before, before + 3 * len(plan.solvers[g].bodies))
    out = np.full((rows.stop - rows.start, paths.owner.size), np.nan)
    everywhere = np.arange(n)
    at = paths.at(np.zeros(n), everywhere)
    pose, _, rate, sign = tangents(plan, at, None, paths.delta, {})
    out[:, paths.first + 1] = pose[rows]
    back = -1.0 / paths.m
    begun = (pose, rate * back, sign)
    branch = _crossed(plan, scan, g, everywhere, 0.5 * back)
    found = advance(plan, at, paths.at(back, everywhere), begun, branch, np.ones(n))
    out[:, paths.first] = found[0][rows]
    for r in range(int(count.max()) - 1):
        go = np.flatnonzero(count > r + 1)
        k = first[go] + r
        a, b = s[k], s[k + 1]
        span = b - a
        branch = _crossed(plan, scan, g, go, 0.5 * (a + b))
        begun = (pose[:, go], rate[:, go] * span, sign[:, go])
        found = advance(
            plan, paths.at(a, go), paths.at(b, go), begun, branch, np.ones(go.size)
        )
        pose[:, go], sign[:, go] = found[0], found[2]
        moved = span > 0.0
        rate[:, go[moved]] = found[1][:, moved] / span[moved]
        here = sample[k + 1]
        out[:, here[here >= 0]] = found[0][rows][:, here >= 0]
    values = iter(out)
    return [tuple(next(values) for _ in range(3)) for _ in plan.solvers[g].bodies]


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
