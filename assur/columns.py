"""The table columns of the file contract: one schema, and how each is computed.

A :class:`Column` names a column, what it belongs to (a link, a joint, a point, the
driver), the quantity and its unit; the schema of a plan lists every column in table
order and is built once. The command line, the pictures and the report read units and
labels from here. Each column is computed from the frozen kinematic and force states
(:func:`evaluate`), only when it is asked for.

Column order: ``angle`` (and every driver's position); every moving link's angle, its
derivatives and its instant centre; every joint's, extra point's and centre of mass's
position and derivatives (prismatic joints also their slide); then the loads and
reactions of a force analysis.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._text import describe, suggest
from assur._vec import Array, full, is_array, take_rows
from assur.errors import UsageError
from assur.plan import Plan

if TYPE_CHECKING:
    from assur.kinetostatics import ForceState
    from assur.table import Table

__all__ = ["Column", "Selection", "evaluate", "pretty_unit", "schema", "selection"]

POINT_PARTS = (("x", "y"), ("vx", "vy"), ("ax", "ay"), ("jx", "jy"))
"""Column suffixes of a point's position, velocity, acceleration and jerk."""
LINEAR_UNITS = ("m", "m/s", "m/s^2", "m/s^3")
ANGULAR_UNITS = ("deg", "rad/s", "rad/s^2", "rad/s^3")
LINK_PARTS = ("angle", "omega", "alpha", "jerk")
SLIDE_PARTS = ("s", "v", "a", "j")
CHUNK = 8192
"""Rows computed at once when a column is derived from the states."""
TRANSLATION = 1e-12
"""A link whose angular speed times the mechanism's size is below this fraction of
its origin's speed translates: its instant centre is at infinity (NaN)."""


@dataclass(frozen=True, slots=True)
class Column:
    """One column of a table.

    Attributes
    ----------
    name : str
        The column's name, e.g. ``"rod.omega"`` or ``"B.Fx"``.
    owner : str
        What it belongs to: a link, a joint, a reported point (``"rod.G"`` for a
        centre of mass), ``"driver"``, ``"shaking"``, ``"residual"`` or ``"angle"``.
    quantity : str
        The quantity, e.g. ``"omega"``, ``"vx"``, ``"Fx"``, ``"torque"``.
    unit : str
        SI unit in plain text (``"rad/s^2"``, ``"N m"``); angles in degrees.
    family : str
        How it is computed (see :func:`evaluate`).
    key : tuple
        What the family needs to compute it (body index, level, component, ...).
    level : int
        Highest time derivative of the motion it needs (0 to 3).
    forces : bool
        Whether it needs the force analysis.
    """

    name: str
    owner: str
    quantity: str
    unit: str
    family: str
    key: tuple[Any, ...]
    level: int
    forces: bool = False

    @property
    def label(self) -> str:
        """The name with its unit, e.g. ``"rod.omega [rad/s]"``."""
        return f"{self.name} [{self.unit}]" if self.unit else self.name


def pretty_unit(unit: str) -> str:
    """Return a unit as pictures write it: ``"rad/s²"``, ``"N·m"``."""
    return unit.replace("^2", "²").replace("^3", "³").replace("N m", "N·m")


def schema(plan: Plan, forces: bool) -> tuple[Column, ...]:
    """Return every column of a kinematics (or forces) table of ``plan``, in order.

    Built once per plan and kept in ``plan.memo``.
    """
    key = "schema-forces" if forces else "schema-kinematics"
    found = plan.memo.get(key)
    if found is None:
        found = _kinematic_columns(plan)
        if forces:
            found += _force_columns(plan)
        found = plan.memo[key] = tuple(found)
    return found  # type: ignore[no-any-return]


def _position_unit(plan: Plan, i: int) -> str:
    return "deg" if plan.drivers[i].kind == "R" else "m"


def _kinematic_columns(plan: Plan) -> list[Column]:
    drivers = plan.drivers
    cols = [
        Column("angle", "angle", "angle", _position_unit(plan, 0), "given", (0,), 0)
    ]
    if len(drivers) > 1:
        for i, d in enumerate(drivers):
            cols.append(
                Column(
                    f"{d.pair.name}.drive",
                    d.pair.name,
                    "drive",
                    _position_unit(plan, i),
                    "given",
                    (i,),
                    0,
                )
            )
    for b, name in enumerate(plan.bodies):
        if b == 0 or "~" in name:
            continue
        cols.append(Column(f"{name}.angle", name, "angle", "deg", "angle", (b,), 0))
        for k in (1, 2, 3):
            part = LINK_PARTS[k]
            cols.append(
                Column(
                    f"{name}.{part}", name, part, ANGULAR_UNITS[k], "link", (b, k), k
                )
            )
        for c, part in enumerate(("x", "y")):
            cols.append(
                Column(f"{name}.ic.{part}", name, f"ic.{part}", "m", "ic", (b, c), 1)
            )
    for p, name in enumerate(plan.points):
        for k in range(4):
            for c, part in enumerate(POINT_PARTS[k]):
                cols.append(
                    Column(
                        f"{name}.{part}",
                        name,
                        part,
                        LINEAR_UNITS[k],
                        "point",
                        (p, k, c),
                        k,
                    )
                )
        pair = plan.pairs.get(name)
        if pair is not None and pair.kind == "P":
            for k, part in enumerate(SLIDE_PARTS):
                cols.append(
                    Column(
                        f"{name}.{part}", name, part, LINEAR_UNITS[k], "slide", (k,), k
                    )
                )
    return cols


def _force_columns(plan: Plan) -> list[Column]:
    cols = []
    for b, name in enumerate(plan.bodies):
        if b and "~" not in name:
            for c, part in enumerate(("Fi.x", "Fi.y")):
                cols.append(
                    Column(
                        f"{name}.{part}", name, part, "N", "inertia", (b, c), 2, True
                    )
                )
            cols.append(
                Column(f"{name}.Mi", name, "Mi", "N m", "inertia", (b, 2), 2, True)
            )
    for name, pair in plan.pairs.items():
        if pair.virtual:
            continue
        for c, part in enumerate(("Fx", "Fy")):
            cols.append(
                Column(f"{name}.{part}", name, part, "N", "reaction", (c,), 2, True)
            )
        cols.append(Column(f"{name}.F", name, "F", "N", "magnitude", (), 2, True))
        if pair.kind == "P":
            cols.append(
                Column(f"{name}.M", name, "M", "N m", "reaction", (2,), 2, True)
            )
            cols.append(
                Column(f"{name}.offset", name, "offset", "m", "offset", (), 2, True)
            )
    for i, d in enumerate(plan.drivers):
        what, unit = ("torque", "N m") if d.kind == "R" else ("force", "N")
        owners = ["driver"] if i == 0 else []
        if len(plan.drivers) > 1:
            owners.append(d.pair.name)
        for owner in owners:
            cols.append(
                Column(f"{owner}.{what}", owner, what, unit, "balancing", (i,), 2, True)
            )
            cols.append(
                Column(
                    f"{owner}.{what}_check",
                    owner,
                    f"{what}_check",
                    unit,
                    "check",
                    (i,),
                    2,
                    True,
                )
            )
    for c, (part, unit) in enumerate((("Fx", "N"), ("Fy", "N"), ("M", "N m"))):
        cols.append(
            Column(f"shaking.{part}", "shaking", part, unit, "shaking", (c,), 2, True)
        )
    for c, (part, unit) in enumerate((("force", "N"), ("moment", "N m"))):
        cols.append(
            Column(
                f"residual.{part}", "residual", part, unit, "residual", (c,), 2, True
            )
        )
    return cols


@dataclass(frozen=True, slots=True)
class Selection:
    """The columns a sweep computes, by name, and what the sweep must solve for them.

    ``forces``: whether a force analysis is needed; ``top``: the highest time
    derivative of the motion.
    """

    columns: tuple[Column, ...]
    index: dict[str, Column]
    forces: bool
    top: int


def selection(plan: Plan, forces: bool, names: Any = None) -> Selection:
    """Return every column of a sweep, or ``angle`` and the columns ``names``.

    Raises
    ------
    UsageError
        For a name that is not a column of such a table.
    """
    full = schema(plan, forces)
    if names is None:
        key = f"selection-{forces}"
        found = plan.memo.get(key)
        if found is None:
            found = plan.memo[key] = _selection(full)
        return found  # type: ignore[no-any-return]
    if isinstance(names, str):
        names = [names]
    index = {c.name: c for c in full}
    wanted = {"angle"}
    for name in names:
        if not isinstance(name, str) or name not in index:
            extra = ""
            if not forces and name in {c.name for c in schema(plan, True)}:
                extra = " (a force column: use assur.forces)"
            msg = (
                f"columns: no column {describe(name)}{extra}"
                f"{suggest(str(name), index, listing=False)}"
            )
            raise UsageError(msg)
        wanted.add(name)
    return _selection(tuple(c for c in full if c.name in wanted))


def _selection(columns: tuple[Column, ...]) -> Selection:
    forces = any(c.forces for c in columns)
    top = max(2 if forces else 0, *(c.level for c in columns))
    return Selection(columns, {c.name: c for c in columns}, forces, top)


Evaluator = Callable[["Table", Column], dict[str, Array]]


def evaluate(table: Table, column: Column) -> dict[str, Array]:
    """Compute ``column`` of ``table``, with the columns computed along with it.

    Returns arrays by column name; a family computed as a whole (a point's positions
    and derivatives, the virtual-power checks) gives all its columns at once.
    """
    return FAMILIES[column.family](table, column)


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


def _point(table: Table, column: Column) -> dict[str, Array]:
    """Compute a point's position and derivatives (up to the state's), or its jerk."""
    from assur._kinematics import motions
    from assur.groups._motion import point

    p = column.key[0]
    plan, n = table.plan, len(table)
    jerk = column.level > table.state.top
    state = table.motion(column.level) if jerk else table.state
    levels = [3] if jerk else list(range(state.top + 1))
    body, offset = plan.point_body[p], plan.point_offset[p]
    arrays = np.empty((4, 2, n))
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        m = None if offset == (0.0, 0.0) else motions(plan, state.rows(rows))[body]
        for k in levels:
            if m is None:
                x, y = state.origin(body, k)
                arrays[k, 0, rows] = x[rows] if is_array(x) else x
                arrays[k, 1, rows] = y[rows] if is_array(y) else y
            else:
                arrays[k, 0, rows], arrays[k, 1, rows] = point(m, offset, k)
    if 0 in levels:
        arrays[0, 0] += plan.shift[0]
        arrays[0, 1] += plan.shift[1]
    name = plan.points[p]
    return {
        f"{name}.{part}": arrays[k, c]
        for k in levels
        for c, part in enumerate(POINT_PARTS[k])
    }


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


def _offset(table: Table, column: Column) -> dict[str, Array]:
    from assur._kinematics import motions
    from assur.kinetostatics import offset

    plan, state, n = table.plan, table.state, len(table)
    pair = plan.pairs[column.owner]
    fx, fy, couple = (full(v, n) for v in _forces(table).reactions[column.owner])
    out = np.empty(n)
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        bodies = motions(plan, state.rows(rows))
        out[rows] = offset(pair, bodies, fx[rows], fy[rows], couple[rows])
    return {column.name: out}


def _balancing(table: Table, column: Column) -> dict[str, Array]:
    (i,) = column.key
    return {column.name: full(_forces(table).balancing[i], len(table))}


def _shaking(table: Table, column: Column) -> dict[str, Array]:
    (c,) = column.key
    return {column.name: full(_forces(table).shaking[c], len(table))}


def _by_chunks(
    table: Table, width: int, compute: Callable[[Any, Any, slice], Any]
) -> Array:
    """Fill an array (n, width) by chunks: ``compute(bodies, applied, rows)``."""
    from assur._kinematics import motions
    from assur._loads import compile_loads
    from assur.kinetostatics import applied_loads

    plan, state = table.plan, table.state
    loads = compile_loads(plan)
    n = len(state)
    out = np.empty((n, width))
    for start in range(0, n, CHUNK):
        rows = slice(start, min(start + CHUNK, n))
        part = state.rows(rows)
        bodies = motions(plan, part)
        with np.errstate(invalid="ignore", divide="ignore"):
            out[rows] = compute(bodies, applied_loads(plan, loads, bodies, part), rows)
    return out


def _check(table: Table, column: Column) -> dict[str, Array]:
    from assur.kinetostatics import virtual_power

    plan, state = table.plan, table.state
    count = len(plan.drivers)

    def compute(bodies: Any, applied: Any, rows: slice) -> Array:
        speeds = take_rows(state.speed, rows)
        size = rows.stop - rows.start
        return np.stack(
            [
                full(virtual_power(plan, bodies, applied, i, speeds[i]), size)
                for i in range(count)
            ],
            axis=-1,
        )

    values = _by_chunks(table, count, compute)
    return {
        c.name: values[:, c.key[0]] for c in schema(plan, True) if c.family == "check"
    }


def _residual(table: Table, column: Column) -> dict[str, Array]:
    from assur.kinetostatics import residual

    fs = _forces(table)

    def compute(bodies: Any, applied: Any, rows: slice) -> Array:
        size = rows.stop - rows.start
        return residual(table.plan, bodies, applied, fs.rows(rows), size)

    values = _by_chunks(table, 2, compute)
    return {"residual.force": values[:, 0], "residual.moment": values[:, 1]}


FAMILIES: dict[str, Evaluator] = {
    "given": _given,
    "angle": _angle,
    "link": _link,
    "ic": _ic,
    "point": _point,
    "slide": _slide,
    "inertia": _inertia,
    "reaction": _reaction,
    "magnitude": _magnitude,
    "offset": _offset,
    "balancing": _balancing,
    "check": _check,
    "shaking": _shaking,
    "residual": _residual,
}
"""How each family of columns is computed from a table's states."""
