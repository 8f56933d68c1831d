"""What every picture of one table needs: the links' placement at a row and colours.

A :class:`_Context` is built once per picture from a table; it names each body's
colour, the legend's entries, the travel of every slide and the size of the symbols.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._position_titles import row_position
from assur._style import link_colours
from assur._text import counted, describe, roman
from assur._vec import real
from assur.columns import pretty_unit, schema
from assur.errors import UsageError
from assur.plotting._style import ARROW_LENGTH, GROUND_COLOR, PLAIN_COLOR

if TYPE_CHECKING:
    from assur.analysis import Table
    from assur.kinetostatics import ForceState
    from assur.plan import Plan

LONGEST_ARROW = 1e4
"""Most times the largest force may be drawn longer than the automatic scale draws
it: beyond, the mechanism is a dot in the picture, and at 1e-300 N per cm the
picture's numbers overflow."""

Legend = list[tuple[str, str, tuple[int, ...]]]
"""Legend entries: text, colour and the bodies drawn in that colour."""


@dataclass(frozen=True)
class _Pose:
    """Every link's placement at one row of a table."""

    phi: np.ndarray
    origin: np.ndarray

    def turn(self, body: int, v: Any) -> np.ndarray:
        """Vector ``v`` fixed in ``body``, in the fixed frame."""
        c, s = math.cos(self.phi[body]), math.sin(self.phi[body])
        return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])

    def at(self, body: int, offset: Any) -> np.ndarray:
        """Point of ``body`` at body-fixed ``offset`` from its origin, m."""
        return self.origin[body] + self.turn(body, offset)


@dataclass(frozen=True)
class _Context:
    """What every picture of one table needs: plan, colours, symbol sizes, travel."""

    table: Table
    plan: Plan
    color: dict[int, str]
    legend: Legend
    travel: dict[str, tuple[float, float]]
    size: float
    centroid: np.ndarray

    @property
    def forces(self) -> ForceState:
        """Loads and reactions of the table, for the pictures of a forces table."""
        return _need_forces(self.table, "force arrows")

    @property
    def r(self) -> float:
        """Radius of a revolute joint's circle, m."""
        return 0.012 * self.size

    def pose(self, row: int) -> _Pose:
        """Return the links' placement at ``row``."""
        phi, origin = self.table.state.pose(row)
        return _Pose(phi, origin + np.asarray(self.plan.shift))

    def hidden(self, body: int) -> bool:
        """Whether ``body`` is a virtual block standing for a slot."""
        return "~" in self.plan.bodies[body]


def _colors(plan: Plan, groups: bool) -> tuple[dict[int, str], Legend]:
    """Colour each body by its Assur group (or all alike); return the legend too.

    The colours are those of the report (:func:`assur._style.link_colours`).
    """
    by_name = link_colours(plan)
    color: dict[int, str] = {0: GROUND_COLOR}
    for b, name in enumerate(plan.bodies[1:], 1):
        color[b] = by_name[name] if groups else PLAIN_COLOR
    legend: Legend = [
        (f"I, driver (ground, {plan.bodies[d.body]})", color[d.body], (d.body,))
        for d in plan.drivers
    ]
    for g in plan.groups:
        bodies = tuple(plan.body(x) for x in g.links)
        # a group beyond the triads is labelled by its class, named once here
        label = g.label if g.kind != "general" else "group " + g.label.split(" ", 2)[2]
        text = f"{roman(g.group_class)}, order {g.order}, {label}"
        legend.append((text, color[bodies[0]], bodies))
    return color, legend


def _context(table: Table, groups: bool = True) -> _Context:
    """Return the context of the pictures of ``table`` (``groups``: colour by group)."""
    whole(table, "the pictures")
    plan = table.plan
    color, legend = _colors(plan, groups)
    travel = {
        name: (
            float(np.nanmin(table[f"{name}.s"])),
            float(np.nanmax(table[f"{name}.s"])),
        )
        for name, pair in plan.pairs.items()
        if pair.kind == "P" and f"{name}.s" in table
    }
    pts = np.array([p.d_second + plan.origins[p.second] for p in plan.pairs.values()])
    pts = pts + np.asarray(plan.shift)
    # symbols scale with the picture: the region swept by the points
    swept = np.concatenate(
        [np.column_stack([table[f"{p}.x"], table[f"{p}.y"]]) for p in plan.points]
    )
    swept = swept[np.isfinite(swept).all(axis=1)]
    size = max(plan.scale, float(np.ptp(swept, axis=0).max()) if len(swept) else 0.0)
    return _Context(table, plan, color, legend, travel, size, pts.mean(axis=0))


def _row(table: Table, angle: Any) -> int:
    """Index of the row nearest to driver position ``angle`` (deg, or m)."""
    if len(table) == 0:
        msg = "table: no rows to draw; expected at least one driver position"
        raise UsageError(msg)
    if angle is None:
        return 0
    plan = table.plan
    try:
        want = np.atleast_1d(np.asarray(angle, dtype=float))
    except (TypeError, ValueError, OverflowError) as err:
        # OverflowError: an integer too large for a float (10**400)
        msg = f"angle: expected a driver position (deg, or m), got {describe(angle)}"
        raise UsageError(msg) from err
    drive = table.given
    if want.size == drive.shape[1]:
        want = want.ravel()  # one row of positions, (1, drivers), say
    if want.ndim != 1 or want.shape[0] not in (1, drive.shape[1]):
        msg = (
            f"angle: {counted(want.size, 'value')} for "
            f"{counted(drive.shape[1], 'driver')}; expected one position per driver"
        )
        raise UsageError(msg)
    if not np.all(np.isfinite(want)):
        # the nearest row to NaN was row 0, drawn without a word
        msg = f"angle: expected a finite driver position, got {describe(angle)}"
        raise UsageError(msg)
    gap = np.zeros(drive.shape[0])
    for i in range(want.shape[0]):
        if plan.drivers[i].kind == "R":
            diff = drive[:, i] - want[i]
            gap += ((diff + 180.0) % 360.0 - 180.0) ** 2
        else:
            gap += (drive[:, i] - want[i]) ** 2
    return int(np.argmin(gap))


def checked_scale(scale: Any) -> float | None:
    """Return a force scale (N per cm), checked: None (automatic) or a number > 0.

    Raises
    ------
    UsageError
        For zero, a negative number (the arrows would point backwards), NaN or a
        value that is not a number.
    """
    if scale is None:
        return None
    value = real(scale)
    if value is None:
        msg = f"scale: expected a force scale in N per cm, got {describe(scale)}"
        raise UsageError(msg)
    if not (math.isfinite(value) and value > 0.0):
        msg = f"scale: {describe(scale)}; expected a force scale in N per cm, above 0"
        raise UsageError(msg)
    return value


def fitted_scale(scale: Any, arrows: Iterable[Any], size: float) -> float | None:
    """Return a force scale checked (see :func:`checked_scale`) against ``arrows``.

    ``arrows`` are the forces drawn (their ``force``, N, or None for a couple) on a
    drawing of ``size`` m.

    Raises
    ------
    UsageError
        Also for a scale that draws the largest force more than
        :data:`LONGEST_ARROW` times longer than the automatic scale does.
    """
    value = checked_scale(scale)
    if value is None:
        return None
    big = max(
        (float(np.hypot(*a.force)) for a in arrows if a.force is not None),
        default=0.0,
    )
    least = big / (ARROW_LENGTH * size * 100.0) / LONGEST_ARROW
    if value < least:
        length = big / value / 100.0
        drawn = f"{length:.3g} m long" if math.isfinite(length) else "too long to tell"
        reason = (
            f"draws the largest force ({big:.3g} N) {drawn}, on a drawing {size:.3g} "
            f"m across; expected a force scale of at least {least:.3g} N per cm"
        )
        msg = f"scale: {describe(scale)} {reason}"
        raise ScaleError(msg, reason)
    return value


class ScaleError(UsageError):
    """A force scale that draws the forces far too long; ``reason`` says how."""

    def __init__(self, message: str, reason: str) -> None:
        super().__init__(message)
        self.reason = reason


def _unit(table: Table, name: str) -> str:
    """Return the unit of column ``name`` as pictures write it ("rad/s²", "N·m").

    The unit is the schema's, also for a column the table was not asked to compute.
    """
    if name in table:
        return pretty_unit(table.column(name).unit)
    every = schema(table.plan, table.force_state is not None)
    return pretty_unit({c.name: c for c in every}[name].unit)


def _position_title(table: Table, row: int) -> str:
    """Driver position(s) at ``row`` for a title: "φ = 30.0°" or "s = 0.1 m"."""
    return row_position(table, row)


def _need_forces(table: Table, what: str) -> ForceState:
    """Return the loads and reactions of ``table``; raise if it holds kinematics only.

    ``what`` names the caller in the message.
    """
    whole(table, what)
    if table.force_state is None:
        msg = (
            f"{what}: needs a forces table (assur.forces); this table holds "
            "kinematics only"
        )
        raise UsageError(msg)
    return table.force_state


def whole(table: Any, what: str) -> None:
    """Check that ``table`` is a table of an analysis, as pictures need.

    A table made with ``columns=`` is one: a column it lacks says so when read.

    Raises
    ------
    UsageError
        For anything else (a Mechanism, say).
    """
    if not (hasattr(table, "schema") and hasattr(table, "plan")):
        msg = (
            f"{what}: expected a table of assur.kinematics or assur.forces, got "
            f"{type(table).__name__}"
        )
        raise UsageError(msg)
    if not len(table):
        # numpy's "zero-size array to reduction operation" came out of the drawing
        left = " (every position was left out)" if len(table.skipped) else ""
        msg = f"{what}: the table has no rows{left}; expected at least one to draw"
        raise UsageError(msg)


def _revolute(table: Table) -> bool:
    """Whether the (first) driver of ``table`` turns rather than slides."""
    return table.plan.drivers[0].kind == "R"
