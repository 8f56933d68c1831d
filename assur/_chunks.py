"""Table columns computed slice by slice from the links' rebuilt motions.

Points off a link's origin, prismatic offsets, the virtual-power checks and the
equilibrium residuals: all of those asked for at once share each slice's rebuilt
motions (:func:`assur._kinematics.motions`) and applied loads.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._kinematics import motions
from assur._loads import compile_loads
from assur._vec import Array, full, norm, rows_of
from assur.columns import POINT_PARTS, Column, schema
from assur.groups._motion import point_into
from assur.kinetostatics import (
    applied_loads,
    offset,
    residual,
    virtual_power,
    with_friction,
)

if TYPE_CHECKING:
    from assur.kinetostatics import ForceState
    from assur.table import Table

__all__ = ["CHUNK"]

CHUNK = 8192
"""Rows computed at once when a column needs the links' motions rebuilt."""


def _chunked(
    table: Table, columns: list[Column], done: dict[str, Array] | None = None
) -> dict[str, Array]:
    """Compute points, offsets, checks and residuals in one pass over slices.

    ``done`` holds columns computed already (a joint's reaction magnitude, say).
    """
    plan, state, n = table.plan, table.state, len(table)
    if n <= CHUNK and any(c.level > state.top for c in columns):
        # one slice: the state extended to jerks serves every level in one pass
        state = table.motion(3)
    top = state.top
    out: dict[str, Array] = {}
    wanted = [c for c in columns if c.family == "point" and c.level <= top]
    # a link's origin is in the state already; other points are rebuilt by slices
    at_origin, rebuilt = _split(plan, {c.key[0] for c in wanted})
    out.update(_origins(plan, state, at_origin, range(top + 1)))
    rebuilt, same = _distinct(plan, rebuilt)
    points = _allocate(plan, rebuilt, range(top + 1), n)
    offsets = sorted({c.owner for c in columns if c.family == "offset"})
    off = {name: np.empty(n) for name in offsets}
    families = {c.family for c in columns}
    checks = np.empty((len(plan.drivers), n)) if "check" in families else None
    left = np.empty((2, n)) if "residual" in families else None
    loads = compile_loads(plan) if checks is not None or left is not None else None
    # one slice holding every row reads the states as they are
    whole = n <= CHUNK
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        part = state if whole else state.rows(rows)
        bodies = motions(plan, part)
        forces = table.force_state
        if forces is not None and not whole and (offsets or loads is not None):
            forces = forces.rows(rows)
        for p, arrays in points.items():
            _point(plan, bodies, p, arrays, rows)
        if offsets:
            assert forces is not None
            scale = _largest_reaction(forces, rows, done or {})
        for name in offsets:
            assert forces is not None
            fx, fy, couple = forces.reactions[name]
            off[name][rows] = offset(
                plan.pairs[name], bodies, fx, fy, couple, scale, plan.scale
            )
        if loads is None:
            continue
        known = forces.inertia if forces is not None else None
        applied = applied_loads(plan, loads, bodies, part, known)
        friction = forces.friction if forces is not None else {}
        if checks is not None:
            # friction does work: its power counts like any load's
            rubbed = with_friction(plan, bodies, applied, friction)
            speeds = part.speed
            for i in range(len(plan.drivers)):
                checks[i, rows] = virtual_power(plan, bodies, rubbed, i, speeds[i])
        if left is not None:
            # a prismatic pair's friction force is in its reaction already
            assert forces is not None
            rubbed = with_friction(plan, bodies, applied, friction, "R")
            residual(plan, bodies, rubbed, forces, left[:, rows])
    for arrays in points.values():
        out.update(arrays)
    out.update(_aliases(plan, points, same))
    jerks = sorted({c.key[0] for c in columns if c.family == "point" and c.level > top})
    if jerks:
        out.update(_jerks(table, jerks))
    out.update({f"{name}.offset": values for name, values in off.items()})
    if checks is not None:
        for c in schema(plan, True):
            if c.family == "check":
                out[c.name] = checks[c.key[0]]
    if left is not None:
        out["residual.force"], out["residual.moment"] = left[0], left[1]
    return out


def _split(plan: Any, points: Iterable[int]) -> tuple[list[int], list[int]]:
    """Split ``points`` into those at their link's origin and the others, in order."""
    at_origin: list[int] = []
    rebuilt: list[int] = []
    for p in sorted(points):
        (at_origin if plan.point_offset[p] == (0.0, 0.0) else rebuilt).append(p)
    return at_origin, rebuilt


def _origins(
    plan: Any, state: Any, points: list[int], levels: Iterable[int]
) -> dict[str, Array]:
    """Return the columns of points at their link's origin, from ``state``.

    ``state`` holds every level of ``levels``.
    """
    n, shift = len(state), plan.shift
    names = _point_names(plan)
    out = {}
    for k in levels:
        sx, sy = shift if k == 0 else (0.0, 0.0)
        for p in points:
            x, y = state.origin(plan.point_body[p], k)
            x, y = full(x, n), full(y, n)
            if sx:
                x = x + sx
            if sy:
                y = y + sy
            name_x, name_y = names[p][k]
            out[name_x], out[name_y] = x, y
    return out


def _point_names(plan: Any) -> tuple[tuple[tuple[str, str], ...], ...]:
    """Return the column names of every point's components, by point and level."""
    found = plan.memo.get("point-names")
    if found is None:
        found = plan.memo["point-names"] = tuple(
            tuple((f"{name}.{x}", f"{name}.{y}") for x, y in POINT_PARTS)
            for name in plan.points
        )
    return found  # type: ignore[no-any-return]


def _allocate(
    plan: Any, points: list[int], levels: Iterable[int], n: int
) -> dict[int, dict[str, Array]]:
    """Return empty columns for the ``levels`` of each of ``points``, by name."""
    parts = [part for k in levels for part in POINT_PARTS[k]]
    block = iter(rows_of(len(points) * len(parts), n))
    return {
        p: {f"{plan.points[p]}.{part}": next(block) for part in parts} for p in points
    }


def _largest_reaction(forces: ForceState, rows: slice, done: dict[str, Array]) -> Array:
    """Return the largest reaction force at each position of ``rows`` (N).

    ``forces`` holds those rows only; a magnitude column in ``done`` (all rows) is
    used as it is.
    """
    size = rows.stop - rows.start
    largest = np.zeros(size)
    for name, (fx, fy, _) in forces.reactions.items():
        known = done.get(f"{name}.F")
        value = norm(full(fx, size), full(fy, size)) if known is None else known[rows]
        np.maximum(largest, value, out=largest)
    return largest


def _point(
    plan: Any, bodies: list[Any], p: int, arrays: dict[str, Array], rows: slice
) -> None:
    """Write point ``p``'s columns over ``rows``: ``arrays`` holds them by name."""
    name = plan.points[p]
    m = bodies[plan.point_body[p]]
    offset_ = plan.point_offset[p]
    shift = plan.shift
    spare = np.empty(rows.stop - rows.start)
    for k, parts in enumerate(POINT_PARTS):
        target = arrays.get(f"{name}.{parts[0]}")
        if target is None:
            continue
        x, y = target[rows], arrays[f"{name}.{parts[1]}"][rows]
        moved = k == 0 and (shift[0] or shift[1])
        # the applied loads' centres of mass come from the motions' memo: kept
        point_into(m, offset_, k, x, y, spare, keep=not moved)
        if moved:
            x += shift[0]
            y += shift[1]


def _jerks(table: Table, points: list[int]) -> dict[str, Array]:
    """Compute the jerks of reported points from the state extended to jerks."""
    plan, n = table.plan, len(table)
    state = table.motion(3)
    out: dict[str, Array] = {}
    at_origin, rebuilt = _split(plan, points)
    out.update(_origins(plan, state, at_origin, (3,)))
    rebuilt, same = _distinct(plan, rebuilt)
    chunked = _allocate(plan, rebuilt, (3,), n)
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        bodies = motions(plan, state if n <= CHUNK else state.rows(rows))
        for p, arrays in chunked.items():
            _point(plan, bodies, p, arrays, rows)
    for arrays in chunked.values():
        out.update(arrays)
    out.update(_aliases(plan, chunked, same))
    return out


def _distinct(plan: Any, points: list[int]) -> tuple[list[int], dict[int, int]]:
    """Split ``points`` into those at distinct places and the others.

    Returns the first point at each place (a link and an offset on it) and, for
    each other point, the first at its place: a centre of mass at a joint, say, is
    computed once.
    """
    first: dict[tuple[int, tuple[float, float]], int] = {}
    same = {}
    for p in points:
        place = (plan.point_body[p], plan.point_offset[p])
        if place in first:
            same[p] = first[place]
        else:
            first[place] = p
    return list(first.values()), same


def _aliases(
    plan: Any, arrays: dict[int, dict[str, Array]], same: dict[int, int]
) -> dict[str, Array]:
    """Return the columns of each point of ``same``: those of the first at its place."""
    out = {}
    for p, q in same.items():
        cut = len(plan.points[q])
        for name, values in arrays[q].items():
            out[plan.points[p] + name[cut:]] = values
    return out
