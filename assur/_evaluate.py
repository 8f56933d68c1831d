"""Table columns computed from a table's frozen states.

Most columns are the states' own arrays, or a few operations on them. Points off a
link's origin, prismatic offsets, the virtual-power checks and the equilibrium
residuals need the links' motions rebuilt: those are computed slice by slice
(``assur._chunks``), all asked for at once in one pass (:func:`materialize`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._chunks import CHUNK, _chunked
from assur._quiet import quiet
from assur._vec import Array, full, is_array, norm
from assur.columns import Column

if TYPE_CHECKING:
    from assur.kinetostatics import ForceState
    from assur.table import Table

__all__ = ["evaluate", "grouped", "materialize"]

TRANSLATION = 1e-12
"""A link whose angular speed times the mechanism's size is below this fraction of
its origin's speed translates: its instant centre is at infinity (NaN)."""
CHUNKED = ("point", "offset", "check", "residual")
"""Families computed slice by slice from rebuilt motions."""
SHORT = 2048
"""Rows up to which reading a column computes its family, and reading a column that
needs rebuilt motions every such column up to accelerations, in one pass."""

Evaluator = Callable[["Table", list[Column]], dict[str, Array]]


def evaluate(table: Table, column: Column) -> dict[str, Array]:
    """Compute ``column`` of ``table``, with the columns computed along with it.

    Returns arrays by column name; a family computed as a whole (a point's positions
    and derivatives, the virtual-power checks) gives all its columns at once.
    """
    if column.family in CHUNKED:
        return materialize(table, _company(table, column))
    return SIMPLE[column.family](table, [column])


def _company(table: Table, column: Column) -> list[Column]:
    """Return the table's columns best computed in the same pass as ``column``.

    Points and offsets share the rebuilt motions; checks and residuals the applied
    loads too; jerks need the state extended first.
    """
    top = table.state.top
    families = table._families

    def of(*names: str) -> list[Column]:
        return [c for name in names for c in families.get(name, ())]

    if column.level <= top and len(table) <= SHORT:
        # one pass of a short table costs about what each of its steps does alone
        return [c for c in of(*CHUNKED) if c.level <= top]
    if column.family in ("check", "residual"):
        return of("check", "residual")
    if column.level > top:
        return [c for c in of("point") if c.level > top]
    return [c for c in of("point", "offset") if c.level <= top]


def materialize(table: Table, columns: Iterable[Column]) -> dict[str, Array]:
    """Compute many columns, the ones needing rebuilt motions in one pass of slices.

    Returns every column asked for, and those computed along with them.
    """
    families: dict[str, list[Column]] = {}
    for column in columns:
        families.setdefault(column.family, []).append(column)
    return grouped(table, families)


def grouped(table: Table, families: Mapping[str, Sequence[Column]]) -> dict[str, Array]:
    """Compute the columns of ``families`` (columns by family), as :func:`materialize`.

    A table's own grouping (``Table._families``) serves every column at once with no
    pass over the columns.
    """
    out: dict[str, Array] = {}
    chunked: list[Column] = []
    for family in CHUNKED:
        chunked += families.get(family, ())
    # a family's columns at once: those of several links or joints share each step
    for family, members in families.items():
        if family not in CHUNKED:
            out.update(SIMPLE[family](table, list(members)))
    if chunked:
        out.update(_chunked(table, chunked, out))
    return out


# ------------------------------------------------------------------------------------
# Columns read from the states


def _given(table: Table, columns: list[Column]) -> dict[str, Array]:
    return {c.name: table.given[:, c.key[0]] for c in columns}


def _angle(table: Table, columns: list[Column]) -> dict[str, Array]:
    """Links' angles (deg): a driver's as given, the others' unwrapped.

    The links that are not drivers are computed together, one row each.
    """
    plan, n = table.plan, len(table)
    out: dict[str, Array] = {}
    free: list[Column] = []
    for column in columns:
        (b,) = column.key
        given = [i for i, d in enumerate(plan.drivers) if d.body == b and d.kind == "R"]
        if given:
            out[column.name] = table.given[:, given[0]]
        else:
            free.append(column)
    if not free:
        return out
    bodies = [c.key[0] for c in free]
    angle = np.array([full(table.state.rotation(b, 0), n) for b in bodies])
    angle += np.array([plan.angle0[b] for b in bodies])[:, None]
    driven = [any(d.body == b for d in plan.drivers) for b in bodies]
    if n and not any(driven):
        angle = _continuous(angle)
    elif n and not all(driven):
        rows = np.flatnonzero(np.logical_not(driven))
        angle[rows] = _continuous(angle[rows])
    angle *= 180.0 / math.pi
    out.update((c.name, row) for c, row in zip(free, angle, strict=True))
    return out


def _continuous(angle: Array) -> Array:
    """Remove the jumps of a turn from angles (rad), along the last axis, in place.

    The first of each row is put in (-pi, pi]; returns ``angle``.
    """
    first = angle[..., :1]
    shift = first - (math.pi - np.remainder(math.pi - first, 2.0 * math.pi))
    # the turns between neighbours, then their running sum, in one array: a long
    # sweep's angles pass through memory a few times instead of nine (np.diff,
    # np.any and np.cumsum's own operations, without numpy's Python-level dispatch)
    turns = np.subtract(angle[..., 1:], angle[..., :-1])
    turns *= 0.5 / math.pi
    with quiet():
        np.rint(turns, out=turns)
    if turns.any():
        np.nan_to_num(turns, copy=False)
        np.add.accumulate(turns, axis=-1, out=turns)
        turns *= 2.0 * math.pi
        angle[..., 1:] -= turns
    angle -= shift
    return angle


def _link(table: Table, columns: list[Column]) -> dict[str, Array]:
    n = len(table)
    state = table.motion(max(c.level for c in columns))
    return {c.name: full(state.rotation(*c.key), n) for c in columns}


def _ic(table: Table, columns: list[Column]) -> dict[str, Array]:
    r"""Instant centres of links: :math:`p = o + \hat z \times v_o / \omega`.

    A link whose motion is constant gives constants; the others are computed
    together, one row each, slice by slice.
    """
    state, plan, n = table.state, table.plan, len(table)
    out: dict[str, Array] = {}
    moving: list[tuple[str, list[Any]]] = []
    # the variants of a study stack their plans: a size and a shift per row
    per_row = is_array(plan.scale) or any(is_array(v) for v in plan.shift)
    for b in dict.fromkeys(c.key[0] for c in columns):
        name = plan.bodies[b]
        leaves = [state.rotation(b, 1), *state.origin(b, 0), *state.origin(b, 1)]
        if leaves[0].__class__ is float and not leaves[0]:
            # a link that never turns translates (or rests) at every position
            out[f"{name}.ic.x"] = out[f"{name}.ic.y"] = full(None, n)
        elif per_row or any(is_array(v) for v in leaves):
            moving.append((name, leaves))
        else:
            cx, cy = _fixed_centre(plan, leaves)
            out[f"{name}.ic.x"], out[f"{name}.ic.y"] = full(cx, n), full(cy, n)
    if not moving:
        return out
    block = np.empty((2, len(moving), n))
    x, y = block
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        size = rows.stop - start
        part = [
            _stacked([v[rows] if is_array(v) else full(v, size) for v in quantity])
            for quantity in zip(*(leaves for _, leaves in moving), strict=True)
        ]
        _centre(plan, part, x[:, rows], y[:, rows])
    for i, (name, _) in enumerate(moving):
        out[f"{name}.ic.x"], out[f"{name}.ic.y"] = x[i], y[i]
    return out


def _stacked(arrays: list[Array]) -> Array:
    """Return ``arrays`` as the rows of one 2-D array.

    A single array is seen as one row, not copied.
    """
    return arrays[0][None] if len(arrays) == 1 else np.array(arrays)


def _fixed_centre(plan: Any, leaves: list[Any]) -> tuple[float, float]:
    """Return the instant centre of a link whose motion is constant (m).

    The arithmetic of :func:`_centre`, on numbers; NaN for a translating link.
    """
    omega, ox, oy, vx, vy = (math.nan if v is None else float(v) for v in leaves)
    if not abs(omega) * plan.scale > TRANSLATION * math.hypot(vx, vy):
        return math.nan, math.nan
    return (plan.shift[0] + ox) - vy / omega, (plan.shift[1] + oy) + vx / omega


def _centre(plan: Any, leaves: list[Array], x: Array, y: Array) -> None:
    """Write the instant centres of links moving as ``leaves`` into ``x`` and ``y``.

    ``leaves`` are the links' angular speeds and their origins' positions and
    velocities, one row per link; NaN where a link translates.
    """
    omega, ox, oy, vx, vy = leaves
    translating = ~(np.abs(omega) * plan.scale > TRANSLATION * norm(vx, vy))
    with quiet():
        np.divide(vy, omega, out=x)
        np.subtract(plan.shift[0] + ox, x, out=x)
        np.divide(vx, omega, out=y)
        np.add(plan.shift[1] + oy, y, out=y)
    if translating.any():
        x[translating] = np.nan
        y[translating] = np.nan


def _slide(table: Table, columns: list[Column]) -> dict[str, Array]:
    n = len(table)
    slide = table.motion(max(c.level for c in columns)).slide
    return {c.name: full(slide[c.owner][c.key[0]], n) for c in columns}


def _forces(table: Table) -> ForceState:
    # the force state as kept: a table of the drivers' columns keeps those it needs
    forces = table._kept_forces
    assert forces is not None
    if not table._frozen:
        table._freeze()  # its arrays are handed out as columns: read-only
    return forces


def _inertia(table: Table, columns: list[Column]) -> dict[str, Array]:
    inertia, n = _forces(table).inertia, len(table)
    out = {}
    for c in columns:
        b, k = c.key
        values = inertia[b]
        out[c.name] = full(0.0 if values is None else values[k], n)
    return out


def _reaction(table: Table, columns: list[Column]) -> dict[str, Array]:
    reactions, n = _forces(table).reactions, len(table)
    return {c.name: full(reactions[c.owner][c.key[0]], n) for c in columns}


def _magnitude(table: Table, columns: list[Column]) -> dict[str, Array]:
    """Joints' reaction magnitudes (N); those that vary computed together."""
    reactions, n = _forces(table).reactions, len(table)
    out: dict[str, Array] = {}
    varying = []
    for c in columns:
        fx, fy, _ = reactions[c.owner]
        if is_array(fx) or is_array(fy):
            varying.append(c)
        else:
            out[c.name] = full(np.hypot(full(fx, 1), full(fy, 1))[0], n)
    if varying:
        fx = _stacked([full(reactions[c.owner][0], n) for c in varying])
        fy = _stacked([full(reactions[c.owner][1], n) for c in varying])
        out.update(zip((c.name for c in varying), norm(fx, fy), strict=True))
    return out


def _balancing(table: Table, columns: list[Column]) -> dict[str, Array]:
    balancing, n = _forces(table).balancing, len(table)
    return {c.name: full(balancing[c.key[0]], n) for c in columns}


def _friction(table: Table, columns: list[Column]) -> dict[str, Array]:
    friction, n = _forces(table).friction, len(table)
    # a joint at rest has no friction: 0, where the law's sign gave -0 ("-0.0")
    return {c.name: full(friction.get(c.owner, 0.0), n) + 0.0 for c in columns}


def _ideal(table: Table, columns: list[Column]) -> dict[str, Array]:
    ideal, n = _forces(table).ideal, len(table)
    return {c.name: full(ideal[c.key[0]], n) for c in columns}


def _loss(table: Table, columns: list[Column]) -> dict[str, Array]:
    """Compute the power of all friction loads (W)."""
    total = np.zeros(len(table))
    for power in friction_powers(table).values():
        total = total + power
    return {c.name: total for c in columns}


def friction_powers(table: Table) -> dict[str, Array]:
    """Return the power of each joint's friction load per position (W, <= 0).

    A revolute joint's friction couple times its links' relative angular speed; a
    prismatic joint's friction force times its slide's speed.
    """
    forces = table.force_state
    if forces is None:
        return {}
    plan, state, n = table.plan, table.state, len(table)
    out = {}
    for name, value in forces.friction.items():
        pair = plan.pairs[name]
        if pair.kind == "R":
            speed = full(state.rotation(pair.second, 1), n) - full(
                state.rotation(pair.first, 1), n
            )
        else:
            speed = full(state.slide[name][1], n)
        out[name] = full(value, n) * speed
    return out


def _shaking(table: Table, columns: list[Column]) -> dict[str, Array]:
    shaking, n = _forces(table).shaking, len(table)
    return {c.name: full(shaking[c.key[0]], n) for c in columns}


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
    "friction": _friction,
    "ideal": _ideal,
    "loss": _loss,
}
"""How each family of columns read from the states is computed."""
