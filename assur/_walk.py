"""Walks of the Newton-solved groups along straight paths, through change points.

With several drivers each position is reached on its own straight path from the
reference pose, ``reference + s delta`` for s from 0 to 1. The closed-form dyads'
branches flip at their change points on it; a walk stops at each one, so that no
step spans one and every step keeps one branch per dyad (see
:func:`assur._follow.advance`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Protocol, runtime_checkable

import numpy as np

from assur._follow import advance, tangents
from assur._vec import Array, Index
from assur.plan import Plan

__all__ = ["PAST", "Met", "OnPaths", "crossed", "flipped", "stops", "walk"]

Met = dict[int, tuple[Index, Array]]
"""The change points of closed-form groups on straight paths, by solver index: the
paths they lie on and their parameters along them (0 at the reference pose, 1 at
the path's end)."""
PAST = 1e-9
"""A change point this close to the reference pose (in a path's parameter) is at it:
it is behind the reference pose, not crossed on the way to the path's end."""


@runtime_checkable
class OnPaths(Protocol):
    """The groups' branches at positions reached on straight paths (a BranchOf).

    ``met(drive, upto)`` gives the change points of the groups before solver index
    ``upto`` on the paths to driver positions ``drive`` (n, d), SI units.
    """

    def __call__(self, at: Array, upto: int) -> dict[int, Array]: ...

    def met(self, drive: Array, upto: int) -> Met: ...


def flipped(own: float, count: Any) -> Array:
    """Return the branch ``own`` (+1 or -1) flipped ``count`` times (an array)."""
    return np.where(count % 2 == 1, -own, own).astype(float)


def crossed(plan: Plan, met: Met, n: int, go: Index, x: Array) -> dict[int, Array]:
    """Return the branches of the groups of ``met`` at parameters ``x`` on paths ``go``.

    ``n`` paths in all. A change point is crossed when it lies between the reference
    pose (s = 0) and ``x``: one ahead of the reference pose from its parameter on,
    one at or behind it going back from its parameter on.
    """
    at = np.full(n, np.nan)
    at[go] = x
    out = {}
    for h, (where, s) in met.items():
        y = at[where]
        past = np.where(s > PAST, s <= y, s >= y)
        count = np.bincount(where[past], minlength=n)[go]
        out[h] = flipped(plan.solvers[h].branch, count)
    return out


def stops(
    n: int, met: Met, s: Array, owner: Index, sample: Index
) -> tuple[Array, Index, Index, Index]:
    """Return the stops of a walk along ``n`` paths, by path and parameter.

    The stops are the points at parameters ``s`` on paths ``owner`` (``sample``
    their indices, kept with them) and the change points of ``met`` between the
    reference pose and each path's last point. Returns their parameters, each
    path's first stop and count (what :func:`walk` takes), and the samples (-1 for
    a change point).
    """
    last = np.zeros(n)
    np.maximum.at(last, owner, s)
    params, paths, samples = [s], [owner], [sample]
    for where, t in met.values():
        keep = (t > PAST) & (t < last[where])
        params.append(t[keep])
        paths.append(where[keep])
        samples.append(np.full(int(keep.sum()), -1))
    at = np.concatenate(params)
    on = np.concatenate(paths)
    order = np.lexsort((at, on))
    count = np.bincount(on, minlength=n)
    first = np.cumsum(count) - count
    return at[order], first, count, np.concatenate(samples)[order]


def walk(
    plan: Plan,
    path: tuple[Array, Array],
    stops: tuple[Array, Index, Index],
    met: Met,
    top: Array,
    begun: tuple[Array, Array, Array] | None = None,
    seen: Callable[[Index, Array], None] | None = None,
) -> tuple[Array, Array, Array]:
    """Follow the Newton groups along straight paths through each path's stops.

    ``path`` is the reference pose's driver positions (d,) and each path's ``delta``
    (n, d); ``stops`` their parameters path by path, increasing and above 0, with
    each path's first stop and count (:func:`stops`). The dyads' branches flip at
    the change points ``met``, which the stops must include (no step spans one);
    ``top`` (n,) is the largest step, in units of the parameter. ``begun`` holds the
    packed poses, rates per unit of the parameter and Jacobians' signs at the
    reference pose (solved when None); ``seen(k, pose)`` is given the poses at stops
    ``k`` as they are reached. Returns the same three at each path's last stop; a
    path's poses are NaN from where a group fails.
    """
    reference, delta = path
    s, first, count = stops
    n = delta.shape[0]
    if begun is None:
        at = np.repeat(reference[None, :], n, axis=0)
        pose, _, rate, sign = tangents(plan, at, None, delta, {})
    else:
        pose, rate, sign = (a.copy() for a in begun)
    for r in range(int(count.max(initial=0))):
        go = np.flatnonzero(count > r)
        k = first[go] + r
        a = s[k - 1] if r else np.zeros(go.size)
        b = s[k]
        span = b - a
        branch = crossed(plan, met, n, go, 0.5 * (a + b))
        moved = span > 0.0
        step = np.ones(go.size)
        step[moved] = np.minimum(1.0, top[go][moved] / span[moved])
        found = advance(
            plan,
            reference + a[:, None] * delta[go],
            reference + b[:, None] * delta[go],
            (pose[:, go], rate[:, go] * span, sign[:, go]),
            branch,
            step,
        )
        pose[:, go], sign[:, go] = found[0], found[2]
        rate[:, go[moved]] = found[1][:, moved] / span[moved]
        if seen is not None:
            seen(k, found[0])
    return pose, rate, sign
