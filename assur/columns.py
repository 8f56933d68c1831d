"""The table columns of the file contract: one schema, and how each is computed.

A :class:`Column` names a column, what it belongs to (a link, a joint, a point, the
driver), the quantity and its unit; the schema of a plan lists every column in table
order and is built once. The command line, the pictures and the report read units and
labels from here; :mod:`assur._evaluate` computes each column from a table's frozen
states when it is asked for.

Column order: ``angle`` (and every driver's position); every moving link's angle, its
derivatives and its instant centre; every joint's, extra point's and centre of mass's
position and derivatives (prismatic joints also their slide); then the loads and
reactions of a force analysis.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from assur._listed import listed
from assur._text import describe, suggest
from assur.errors import UsageError
from assur.plan import Plan

if TYPE_CHECKING:
    pass

__all__ = [
    "Column",
    "Selection",
    "balancing_columns",
    "families",
    "pretty_unit",
    "schema",
    "selection",
]

POINT_PARTS = (("x", "y"), ("vx", "vy"), ("ax", "ay"), ("jx", "jy"))
"""Column suffixes of a point's position, velocity, acceleration and jerk."""
LINEAR_UNITS = ("m", "m/s", "m/s^2", "m/s^3")
ANGULAR_UNITS = ("deg", "rad/s", "rad/s^2", "rad/s^3")
LINK_PARTS = ("angle", "omega", "alpha", "jerk")
SLIDE_PARTS = ("s", "v", "a", "j")


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
    """Return a unit as pictures write it: ``"rad/s²"``, ``"N·m"``, ``"kg·m²"``."""
    out = unit.replace("^2", "²").replace("^3", "³")
    return out.replace("N m", "N·m").replace("kg m", "kg·m")


def schema(plan: Plan, forces: bool) -> tuple[Column, ...]:
    """Return every column of a kinematics (or forces) table of ``plan``, in order.

    Built once per plan and kept in ``plan.memo``.

    Raises
    ------
    ModelError
        For a mechanism without a driver: no table has columns for it.
    """
    if not plan.drivers:
        from assur._drive import _no_driver

        raise _no_driver(plan)
    key = "schema-forces" if forces else "schema-kinematics"
    found = plan.memo.get(key)
    if found is None:
        found = _kinematic_columns(plan)
        if forces:
            found += _force_columns(plan)
        found = plan.memo[key] = tuple(found)
    return found  # type: ignore[no-any-return]


def balancing_columns(plan: Plan) -> list[str]:
    """Return the names of the drivers' balancing loads in a forces table of ``plan``.

    ``driver.torque`` (N m), or ``driver.force`` (N) for a prismatic driver; with
    several drivers also each one's own, named after its joint (``A.torque``,
    ``P.force``), in table order.
    """
    return [c.name for c in schema(plan, True) if c.family == "balancing"]


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
    rubbing = any(p.friction > 0.0 for p in plan.pairs.values())
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
        if rubbing:
            part, unit = ("Mf", "N m") if pair.kind == "R" else ("Ff", "N")
            cols.append(
                Column(f"{name}.{part}", name, part, unit, "friction", (), 2, True)
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
            if rubbing:
                cols.append(
                    Column(
                        f"{owner}.{what}_ideal",
                        owner,
                        f"{what}_ideal",
                        unit,
                        "ideal",
                        (i,),
                        2,
                        True,
                    )
                )
    if rubbing:
        cols.append(
            Column("friction.power", "friction", "power", "W", "loss", (), 2, True)
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
    families: dict[str, tuple[Column, ...]]
    """The columns of each family, in table order."""


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
    index = {c.name: c for c in full}
    wanted = {"angle"}
    for name in listed(names, "columns", "column"):
        if name not in index:
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
    return Selection(
        columns, {c.name: c for c in columns}, forces, top, families(columns)
    )


def families(columns: tuple[Column, ...]) -> dict[str, tuple[Column, ...]]:
    """Return ``columns`` by family (see :attr:`Column.family`), in table order."""
    out: dict[str, list[Column]] = {}
    for c in columns:
        out.setdefault(c.family, []).append(c)
    return {family: tuple(members) for family, members in out.items()}
