"""Table columns computed slice by slice from the links' rebuilt motions.

Points off a link's origin, prismatic offsets, the virtual-power checks and the
equilibrium residuals: all of those asked for at once share each slice's rebuilt
motions (:func:`assur._kinematics.motions`) and applied loads.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur._kinematics import motions
from assur._loads import compile_loads
from assur._recipe import aliases, distinct, origins, parts, recipe, split
from assur._vec import Array, full, norm, rows_of
from assur.columns import Column
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

CHUNK = 16384
"""Rows computed at once when a column needs the links' motions rebuilt (as many as
a sweep's slice, :data:`assur._state.CHUNK`)."""


def _chunked(
    table: Table, columns: list[Column], done: dict[str, Array] | None = None
) -> dict[str, Array]:
    """Compute points, offsets, checks and residuals in one pass over slices.

    ``done`` holds columns computed already (a joint's reaction magnitude, say).
    """
    plan, state, n = table.plan, table.state, len(table)
    how = recipe(plan, columns, state.top, n <= CHUNK)
    if how.deeper:
        # one slice: the state extended to jerks serves every level in one pass
        state = table.motion(3)
    out = _origins(plan, state, how.origins)
    points = _allocate(how.rebuilt, n)
    off = {name: np.empty(n) for name in how.offsets}
    checks = np.empty((len(plan.drivers), n)) if how.checks else None
    left = np.empty((2, n)) if how.residual else None
    loads = compile_loads(plan) if checks is not None or left is not None else None
    # one slice holding every row reads the states as they are
    whole = n <= CHUNK
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        part = state if whole else state.rows(rows)
        bodies = motions(plan, part)
        forces = table.force_state
        if forces is not None and not whole and (off or loads is not None):
            forces = forces.rows(rows)
        for p, targets in points:
            _point(plan, bodies, p, targets, rows)
        if off:
            assert forces is not None
            scale = _largest_reaction(forces, rows, done or {})
        for name, values in off.items():
            assert forces is not None
            fx, fy, couple = forces.reactions[name]
            values[rows] = offset(
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
    for _, targets in points:
        for _, x, values_x, y, values_y in targets:
            out[x], out[y] = values_x, values_y
    out.update((name, out[same]) for name, same in how.aliases)
    if how.jerks:
        out.update(_jerks(table, list(how.jerks)))
    out.update((f"{name}.offset", values) for name, values in off.items())
    if checks is not None:
        out.update((name, checks[i]) for name, i in how.checks)
    if left is not None:
        out["residual.force"], out["residual.moment"] = left[0], left[1]
    return out


def _origins(
    plan: Any, state: Any, origins: tuple[tuple[int, int, str, str], ...]
) -> dict[str, Array]:
    """Return the columns of points at their link's origin, from ``state``.

    ``origins`` lists each column pair (see :class:`assur._recipe.Recipe`); ``state``
    holds every level of them.
    """
    n, (sx, sy), levels, motion = len(state), plan.shift, state.top + 1, state.motion
    out = {}
    for body, k, name_x, name_y in origins:
        entries = motion[body]
        x, y = full(entries[levels + k], n), full(entries[2 * levels + k], n)
        if k == 0:
            if sx:
                x = x + sx
            if sy:
                y = y + sy
        out[name_x], out[name_y] = x, y
    return out


Targets = list[tuple[int, str, Array, str, Array]]
"""A point's levels with the names and arrays of their two columns."""


def _allocate(
    rebuilt: tuple[tuple[int, tuple[tuple[int, str, str], ...]], ...], n: int
) -> list[tuple[int, Targets]]:
    """Return empty columns for the levels of each point of ``rebuilt``."""
    block = iter(rows_of(2 * sum(len(parts) for _, parts in rebuilt), n))
    return [
        (p, [(k, x, next(block), y, next(block)) for k, x, y in parts])
        for p, parts in rebuilt
    ]


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


def _point(plan: Any, bodies: list[Any], p: int, targets: Targets, rows: slice) -> None:
    """Write point ``p``'s columns over ``rows``: ``targets`` holds them by level."""
    m = bodies[plan.point_body[p]]
    offset_ = plan.point_offset[p]
    shift = plan.shift
    spare = np.empty(rows.stop - rows.start)
    for k, _, x, _, y in targets:
        x, y = x[rows], y[rows]
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
    at_origin, rebuilt = split(plan, points)
    out = _origins(plan, state, origins(plan, at_origin, (3,)))
    rebuilt, same = distinct(plan, rebuilt)
    chunked = _allocate(tuple((p, parts(plan, p, (3,))) for p in rebuilt), n)
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        bodies = motions(plan, state if n <= CHUNK else state.rows(rows))
        for p, targets in chunked:
            _point(plan, bodies, p, targets, rows)
    for _, targets in chunked:
        for _, x, values_x, y, values_y in targets:
            out[x], out[y] = values_x, values_y
    out.update((name, out[q]) for name, q in aliases(plan, same, (3,)))
    return out
