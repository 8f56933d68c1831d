"""Table columns computed from a table's frozen states.

Most columns are the states' own arrays, or a few operations on them. Points off a
link's origin, prismatic offsets, the virtual-power checks and the equilibrium
residuals need the links' motions rebuilt (:func:`assur._kinematics.motions`); they
are computed slice by slice, and all of those asked for at once share each slice's
rebuilt motions and applied loads (:func:`materialize`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._kinematics import motions
from assur._loads import compile_loads
from assur._vec import Array, full, take_rows
from assur.columns import POINT_PARTS, Column, schema
from assur.groups._motion import point
from assur.kinetostatics import applied_loads, offset, residual, virtual_power

if TYPE_CHECKING:
    from assur.kinetostatics import ForceState
    from assur.table import Table

__all__ = ["evaluate", "materialize"]

CHUNK = 8192
"""Rows computed at once when a column needs the links' motions rebuilt."""
TRANSLATION = 1e-12
"""A link whose angular speed times the mechanism's size is below this fraction of
its origin's speed translates: its instant centre is at infinity (NaN)."""
CHUNKED = ("point", "offset", "check", "residual")
"""Families computed slice by slice from rebuilt motions."""

Evaluator = Callable[["Table", Column], dict[str, Array]]


def evaluate(table: Table, column: Column) -> dict[str, Array]:
    """Compute ``column`` of ``table``, with the columns computed along with it.

    Returns arrays by column name; a family computed as a whole (a point's positions
    and derivatives, the virtual-power checks) gives all its columns at once.
    """
    if column.family in CHUNKED:
        return materialize(table, [column])
    return SIMPLE[column.family](table, column)


def materialize(table: Table, columns: Iterable[Column]) -> dict[str, Array]:
    """Compute many columns, the ones needing rebuilt motions in one pass of slices.

    Returns every column asked for, and those computed along with them.
    """
    out: dict[str, Array] = {}
    chunked: list[Column] = []
    for column in columns:
        if column.family in CHUNKED:
            chunked.append(column)
        elif column.name not in out:
            out.update(SIMPLE[column.family](table, column))
    if chunked:
        out.update(_chunked(table, chunked))
    return out


# ------------------------------------------------------------------------------------
# Columns read from the states


def _given(table: Table, column: Column) -> dict[str, Array]:
    return {column.name: table.given[:, column.key[0]]}


def _angle(table: Table, column: Column) -> dict[str, Array]:
    (b,) = column.key
    plan = table.plan
    for i, d in enumerate(plan.drivers):
        if d.body == b and d.kind == "R":
            return {column.name: table.given[:, i]}
    angle = plan.angle0[b] + full(table.state.rotation(b, 0), len(table))
    if not any(d.body == b for d in plan.drivers) and angle.size:
        angle = _continuous(angle)
    return {column.name: angle * (180.0 / math.pi)}


def _continuous(angle: Array) -> Array:
    """Remove the jumps of a turn from angles (rad); the first is put in (-pi, pi]."""
    first = angle[0]
    shift = first - (math.pi - (math.pi - first) % (2.0 * math.pi))
    with np.errstate(invalid="ignore"):
        turns = np.round(np.diff(angle) * (0.5 / math.pi))
    if np.any(turns):
        turns = np.nan_to_num(turns)
        angle = angle - 2.0 * math.pi * np.concatenate(([0.0], np.cumsum(turns)))
    return angle - shift if shift else angle


def _link(table: Table, column: Column) -> dict[str, Array]:
    b, k = column.key
    return {column.name: full(table.motion(k).rotation(b, k), len(table))}


def _ic(table: Table, column: Column) -> dict[str, Array]:
    r"""Instant centre of a link: :math:`p = o + \hat z \times v_o / \omega`."""
    (b, _) = column.key
    state, plan, n = table.state, table.plan, len(table)
    name = plan.bodies[b]
    omega = full(state.rotation(b, 1), n)
    ox, oy = (full(v, n) for v in state.origin(b, 0))
    vx, vy = (full(v, n) for v in state.origin(b, 1))
    speed = np.hypot(vx, vy)
    translating = ~(np.abs(omega) * plan.scale > TRANSLATION * speed)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = np.where(translating, np.nan, plan.shift[0] + ox - vy / omega)
        y = np.where(translating, np.nan, plan.shift[1] + oy + vx / omega)
    return {f"{name}.ic.x": x, f"{name}.ic.y": y}


def _slide(table: Table, column: Column) -> dict[str, Array]:
    (k,) = column.key
    return {column.name: full(table.motion(k).slide[column.owner][k], len(table))}


def _forces(table: Table) -> ForceState:
    assert table.force_state is not None
    return table.force_state


def _inertia(table: Table, column: Column) -> dict[str, Array]:
    b, c = column.key
    values = _forces(table).inertia[b]
    return {column.name: full(0.0 if values is None else values[c], len(table))}


def _reaction(table: Table, column: Column) -> dict[str, Array]:
    (c,) = column.key
    return {column.name: full(_forces(table).reactions[column.owner][c], len(table))}


def _magnitude(table: Table, column: Column) -> dict[str, Array]:
    fx, fy, _ = _forces(table).reactions[column.owner]
    n = len(table)
    return {column.name: np.hypot(full(fx, n), full(fy, n))}


def _balancing(table: Table, column: Column) -> dict[str, Array]:
    (i,) = column.key
    return {column.name: full(_forces(table).balancing[i], len(table))}


def _shaking(table: Table, column: Column) -> dict[str, Array]:
    (c,) = column.key
    return {column.name: full(_forces(table).shaking[c], len(table))}


SIMPLE: dict[str, Evaluator] = {
    "given": _given,
    "angle": _angle,
    "link": _link,
    "ic": _ic,
    "slide": _slide,
    "inertia": _inertia,
    "reaction": _reaction,
    "magnitude": _magnitude,
    "balancing": _balancing,
    "shaking": _shaking,
}
"""How each family of columns read from the states is computed."""


# ------------------------------------------------------------------------------------
# Columns computed from rebuilt motions, slice by slice


def _chunked(table: Table, columns: list[Column]) -> dict[str, Array]:
    """Compute points, offsets, checks and residuals in one pass over slices."""
    plan, state, n = table.plan, table.state, len(table)
    points = sorted({c.key[0] for c in columns if c.family == "point"})
    jerks = sorted(
        {c.key[0] for c in columns if c.family == "point" and c.level > state.top}
    )
    offsets = sorted({c.owner for c in columns if c.family == "offset"})
    families = {c.family for c in columns}
    positions = np.empty((len(points), state.top + 1, 2, n))
    off = np.empty((len(offsets), n))
    checks = np.empty((len(plan.drivers), n)) if "check" in families else None
    left = np.empty((2, n)) if "residual" in families else None
    loads = compile_loads(plan) if checks is not None or left is not None else None
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        part = state.rows(rows)
        bodies = motions(plan, part)
        for i, p in enumerate(points):
            _point(plan, bodies, part, p, range(state.top + 1), positions[i], rows)
        if offsets:
            scale = _largest_reaction(table, rows)
        for i, name in enumerate(offsets):
            fx, fy, couple = take_rows(_forces(table).reactions[name], rows)
            off[i, rows] = offset(plan.pairs[name], bodies, fx, fy, couple, scale)
        if loads is None:
            continue
        applied = applied_loads(plan, loads, bodies, part)
        if checks is not None:
            speeds = take_rows(state.speed, rows)
            for i in range(len(plan.drivers)):
                value = virtual_power(plan, bodies, applied, i, speeds[i])
                checks[i, rows] = value
        if left is not None:
            forces = _forces(table).rows(rows)
            left[:, rows] = residual(plan, bodies, applied, forces, rows.stop - start).T
    out: dict[str, Array] = {}
    for i, p in enumerate(points):
        name = plan.points[p]
        for k in range(state.top + 1):
            for axis, part_name in enumerate(POINT_PARTS[k]):
                values = positions[i, k, axis]
                if k == 0:
                    values = values + plan.shift[axis]
                out[f"{name}.{part_name}"] = values
    if jerks:
        out.update(_jerks(table, jerks))
    out.update({f"{name}.offset": off[i] for i, name in enumerate(offsets)})
    if checks is not None:
        for c in schema(plan, True):
            if c.family == "check":
                out[c.name] = checks[c.key[0]]
    if left is not None:
        out["residual.force"], out["residual.moment"] = left[0], left[1]
    return out


def _largest_reaction(table: Table, rows: slice) -> Array:
    """Return the largest reaction force at each of ``rows`` (N)."""
    size = rows.stop - rows.start
    largest = np.zeros(size)
    for fx, fy, _ in take_rows(_forces(table).reactions, rows).values():
        largest = np.maximum(largest, np.hypot(full(fx, size), full(fy, size)))
    return largest


def _point(
    plan: Any,
    bodies: list[Any],
    state: Any,
    p: int,
    levels: Iterable[int],
    out: Array,
    rows: slice,
) -> None:
    """Write point ``p``'s levels over ``rows`` into ``out`` (levels, 2, n)."""
    body, offset_ = plan.point_body[p], plan.point_offset[p]
    m = bodies[body]
    for k in levels:
        if offset_ == (0.0, 0.0):
            x, y = state.origin(body, k)
        else:
            x, y = point(m, offset_, k)
        out[k, 0, rows] = x
        out[k, 1, rows] = y


def _jerks(table: Table, points: list[int]) -> dict[str, Array]:
    """Compute the jerks of reported points from the state extended to jerks."""
    plan, n = table.plan, len(table)
    state = table.motion(3)
    values = np.empty((len(points), 4, 2, n))
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        part = state.rows(rows)
        bodies = motions(plan, part)
        for i, p in enumerate(points):
            _point(plan, bodies, part, p, (3,), values[i], rows)
    out = {}
    for i, p in enumerate(points):
        name = plan.points[p]
        for c, part_name in enumerate(POINT_PARTS[3]):
            out[f"{name}.{part_name}"] = values[i, 3, c]
    return out
