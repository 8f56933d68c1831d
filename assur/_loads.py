"""Mass properties, gravity and external loads, compiled against a plan.

Loads are constant or tabulated against a position (the first driver's, periodic for a
crank, or a prismatic joint's slide) and interpolated linearly over the batch.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._tables import (
    Reading,
    in_turn,
    interpolate,
    periodic,
    reading,
    step_before,
    steps,
)
from assur._vec import Array
from assur._warn import warn
from assur.errors import AssurWarning, ModelError
from assur.model import LoadTable, Mechanism, resolve_point
from assur.plan import Plan

__all__ = [
    "LoadPlan",
    "compile_loads",
    "driver_steps",
    "massless_texts",
    "step_hits",
    "table_reading",
    "table_step",
    "table_values",
]

WHAT = {
    "center": "centre of mass",
    "inertia": "moment of inertia about the centre of mass, kg m^2",
}


@dataclass(frozen=True, slots=True)
class LoadPlan:
    """Per-body mass (kg), centre offset (m) and inertia (kg m^2); forces and torques.

    ``forces`` holds ``(body, offset, value, entry)`` with ``value`` a constant force
    ``(F_x, F_y)`` (N) or a :class:`LoadTable`; ``torques`` holds ``(body, value,
    entry)``.
    """

    mass: Array
    center: tuple[tuple[float, float], ...]
    inertia: Array
    gravity: tuple[float, float]
    forces: tuple[tuple[int, tuple[float, float], Any, str], ...]
    torques: tuple[tuple[int, Any, str], ...]
    stacked: tuple[tuple[int, Any, Any], ...] | None = None
    """For variants stacked over their rows (:mod:`assur._stack`): each body with a
    mass, its mass and inertia as leaves; None for one mechanism."""

    @property
    def empty(self) -> bool:
        """Whether no link has a mass and no load is applied."""
        return not (self.mass.any() or self.forces or self.torques)

    massive: tuple[tuple[int, Any, Any], ...] = field(
        init=False, repr=False, compare=False
    )
    """What :meth:`bodies` returns, made once: every batch of a sweep asks for it."""

    def __post_init__(self) -> None:
        massive = self.stacked
        if massive is None:
            massive = tuple(
                (b, float(self.mass[b]), float(self.inertia[b]))
                for b in np.flatnonzero(self.mass).tolist()
            )
        object.__setattr__(self, "massive", massive)

    def bodies(self) -> tuple[tuple[int, Any, Any], ...]:
        """Return each body with a mass: its index, mass (kg) and inertia (kg m^2)."""
        return self.massive


def compile_loads(plan: Plan) -> LoadPlan:
    """Collect the mass properties and loads of ``plan``'s mechanism (once per plan).

    Raises
    ------
    ModelError
        When a link has a mass but no centre of mass or no moment of inertia.
    """
    found = plan.memo.get("loads")
    if found is None:
        found = plan.memo["loads"] = _compile(plan)
    return found  # type: ignore[no-any-return]


def massless_texts(mech: Mechanism) -> list[str]:
    """Return the warnings of links given an inertia but no mass, which is left out.

    A link without a mass is massless (the file format): its inertia would be left
    out of the analysis without a word. None without a mass or a load anywhere:
    there is no force analysis to warn of.
    """
    if not (mech.loads or any(link.mass for link in mech.links)):
        return []
    return [
        f"links.{link.name}.inertia: {link.inertia:g} kg m^2 on a link with "
        f"{'no mass' if link.mass is None else 'a mass of 0'} is left out: the link "
        "is massless; give it a mass > 0 for its inertia to count"
        for link in mech.links
        if link.inertia and not link.mass
    ]


def _compile(plan: Plan) -> LoadPlan:
    """Body of :func:`compile_loads`."""
    mech = plan.mechanism
    count = len(plan.bodies)
    mass, inertia, center = np.zeros(count), np.zeros(count), np.zeros((count, 2))
    still = _never_turning(plan)
    for msg in massless_texts(mech):
        warn(msg, AssurWarning, stacklevel=2)
    for link in mech.links:
        if not link.mass:
            continue
        for key in ("center", "inertia"):
            # a slider on the frame's guide never turns: its inertia never enters
            if key == "inertia" and plan.body(link.name) in still:
                continue
            if getattr(link, key) is None:
                msg = (
                    f"links.{link.name}: a link with a mass needs its '{key}' "
                    f"({WHAT[key]}) for the force analysis"
                )
                raise ModelError(msg)
        b = plan.body(link.name)
        mass[b] = link.mass
        inertia[b] = link.inertia or 0.0
        assert link.center is not None
        center[b] = plan.offset(b, resolve_point(mech, link.center))
    centers = tuple((float(x), float(y)) for x, y in center)
    forces, torques = [], []
    for i, load in enumerate(mech.loads):
        b = plan.body(load.link)
        if load.force is not None:
            assert load.at is not None
            ox, oy = plan.offset(b, resolve_point(mech, load.at))
            value = (
                load.force
                if isinstance(load.force, LoadTable)
                else (float(load.force[0]), float(load.force[1]))
            )
            forces.append((b, (float(ox), float(oy)), value, f"loads[{i}].force"))
        if load.torque is not None:
            torque = (
                load.torque
                if isinstance(load.torque, LoadTable)
                else float(load.torque)
            )
            torques.append((b, torque, f"loads[{i}].torque"))
    gravity = (
        (0.0, 0.0)
        if mech.gravity is None
        else (float(mech.gravity[0]), float(mech.gravity[1]))
    )
    return LoadPlan(
        mass,
        centers,
        inertia,
        gravity,
        tuple(forces),
        tuple(torques),
    )


def table_values(
    table: LoadTable, plan: Plan, drive: Array, slides: dict[str, Array], entry: str
) -> list[Array]:
    """Interpolate ``table`` at every analysed position; one array (n,) per component.

    Raises
    ------
    ModelError
        When a table over a slide or a prismatic driver does not cover the sweep.
    """
    xs, at, turning = _reading(table, plan, drive, slides, entry)
    if turning:
        return periodic(xs, table.values, at)
    return [interpolate(at, xs, np.asarray(v, dtype=float)) for v in table.values]


def driver_steps(loads: LoadPlan, plan: Plan) -> list[tuple[str, Array, Array]]:
    """Return every load table over the driver that steps: entry, positions, steps.

    The table's positions (deg over a crank, m over a sliding driver) and the
    positions where it steps, as :func:`assur._tables.steps` finds them. A table
    over a joint's slide is left out: a sweep lands on its steps only by chance.
    """
    found = plan.memo.get("driver_steps")
    if found is not None:  # once per plan: a summary asks for them every slice
        return found  # type: ignore[no-any-return]
    out = []
    entries = [(f[2], f[3]) for f in loads.forces] + [
        (t[1], t[2]) for t in loads.torques
    ]
    turning = plan.drivers[0].kind == "R"
    for table, entry in entries:
        if isinstance(table, LoadTable) and table.over == "driver":
            xs = np.asarray(table.table, dtype=float)
            jumps = steps(xs, table.values, turning)
            if jumps.size:
                out.append((entry, xs, jumps))
    plan.memo["driver_steps"] = out
    return out


def step_hits(loads: LoadPlan, plan: Plan, drive: Array) -> tuple[Array, set[Any]]:
    """Return the positions on a step of a load table over the driver, and the steps.

    ``drive`` (n, drivers) holds the driver positions (rad, or m). Returned: the
    mask of the positions on a step, and the steps landed on, as ``(entry, step)``.
    """
    hit = np.zeros(drive.shape[0], dtype=bool)
    landed: set[Any] = set()
    turning = plan.drivers[0].kind == "R"
    for entry, xs, jumps in driver_steps(loads, plan):
        if turning:
            at = in_turn(xs, np.degrees(drive[:, 0]))
            on = at[:, None] == jumps[None, :]
        else:
            # exactly, as the table reads a slider's position: a hair before the
            # step is read before it
            on = drive[:, :1] == jumps[None, :]
        hit |= on.any(axis=1)
        landed |= {(entry, float(s)) for s in jumps[on.any(axis=0)].tolist()}
    return hit, landed


def table_step(
    table: LoadTable, plan: Plan, drive: Array, slides: dict[str, Array], entry: str
) -> list[float] | None:
    """Return ``table``'s values just before the one position analysed, at a step.

    None where the table does not step there (see :func:`table_values`).
    """
    xs, at, turning = _reading(table, plan, drive, slides, entry)
    return step_before(xs, table.values, float(at[0]), turning)


def table_reading(
    table: LoadTable, plan: Plan, drive: Array, slides: dict[str, Array], entry: str
) -> Reading:
    """Return between which entries ``table`` is read at the one position analysed."""
    xs, at, turning = _reading(table, plan, drive, slides, entry)
    return reading(xs, table.values, float(at[0]), turning)


def _reading(
    table: LoadTable, plan: Plan, drive: Array, slides: dict[str, Array], entry: str
) -> tuple[Array, Array, bool]:
    """Return a table's positions, where it is read, and whether over a crank's turn.

    Raises
    ------
    ModelError
        When a table over a slide or a prismatic driver does not cover the sweep.
    """
    xs = np.asarray(table.table, dtype=float)
    if table.over == "driver":
        first = plan.drivers[0]
        if first.kind == "R":
            return xs, np.degrees(drive[:, 0]), True
        at, what = drive[:, 0], "the driver's position"
    else:
        at, what = slides[table.over], f"the slide of joint {table.over!r}"
    low, high = float(np.min(at)), float(np.max(at))
    tol = 1e-9 * max(1.0, abs(xs[0]), abs(xs[-1]))
    if low < xs[0] - tol or high > xs[-1] + tol:
        msg = (
            f"{entry}.table: covers {xs[0]:g} to {xs[-1]:g} m but {what} runs from "
            f"{low:.6g} to {high:.6g} m; expected a table covering every analysed "
            "position"
        )
        raise ModelError(msg)
    return xs, at, False


def _never_turning(plan: Plan) -> set[int]:
    """Return the bodies that cannot turn: the frame and what slides on it, in turn.

    A prismatic pair keeps its two links' rotations equal.
    """
    still = {0}
    grown = True
    while grown:
        grown = False
        for pair in plan.pairs.values():
            if pair.kind == "P" and (pair.first in still) != (pair.second in still):
                still |= {pair.first, pair.second}
                grown = True
    return still
