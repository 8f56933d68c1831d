"""Everything the note reads at one driver position, from the core's own records.

The forces table of the one position gives the frozen motions; the reverse pass is
run again on them to get each group's :class:`~assur.groups._protocol.Equilibrium`
record. Points are returned in the file's coordinates (the core's shifted back).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._kinematics import motions
from assur._loads import LoadPlan, compile_loads
from assur._runs import positions_where
from assur._text import listing
from assur._vec import Array
from assur.errors import ModelError
from assur.groups._motion import Motion, point, rotated
from assur.groups._pairs import PairPlan
from assur.kinetostatics import Applied, Reverse, applied_loads, reverse
from assur.model import Mechanism
from assur.plan import Plan

if TYPE_CHECKING:
    from assur.table import Table

__all__ = ["ROUND_OFF", "Position", "at", "from_table", "value"]

ROUND_OFF = 1e-12
"""A rate below this fraction of the mechanism's at its level is round-off and is
written 0 (a yoke at mid-stroke: 3e-13); a small rate the user gave (an epsilon of
1e-7 beside an omega of 20: 2.5e-10) is kept."""


def value(leaf: Any) -> float:
    """Return the one value of a leaf (an array of one row, or a float)."""
    return float(np.asarray(leaf, dtype=float).reshape(-1)[0])


def at(x: Any, y: Any) -> Array:
    """Return a 2-vector of the one row of two leaves."""
    return np.array([value(x), value(y)])


@dataclass(frozen=True, slots=True)
class Position:
    """The solved mechanism at one driver position.

    Attributes
    ----------
    table : Table
        The forces table of that one position (where friction locks a group, with
        NaN for the forces the reverse pass has not reached: see ``locked``).
    bodies : list of Motion
        Every body's motion, rebuilt from the table's state.
    applied : Applied or None
        Every link's applied loads (inertia, gravity, external loads); None for a
        mechanism without masses and loads (kinematics only).
    result : Reverse or None
        The reverse pass's records, groups in the order solved (or None).
    loads : LoadPlan
        Masses, centres, inertias and loads, compiled.
    locked : str or None
        The label of the first group of the reverse pass that friction locks here
        (None: none does). Its record, and those of the groups solved after it,
        hold sizes that did not settle: the note stops at it.
    """

    table: Table
    bodies: list[Motion]
    applied: Applied | None
    result: Reverse | None
    loads: LoadPlan
    locked: str | None = None
    scales: dict[tuple[int, int], float] = field(
        default_factory=dict, compare=False, repr=False
    )
    memo: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)
    """Indexes a note reads at every link, built once (a chain of 400 dyads spent
    most of its note scanning every pair for each link)."""

    def pairs_of(self, body: int) -> list[PairPlan]:
        """Return the pairs ``body`` takes part in, in the plan's order."""
        index = self.memo.get("pairs")
        if index is None:
            index = {}
            for pair in self.plan.pairs.values():
                index.setdefault(pair.first, []).append(pair)
                if pair.second != pair.first:
                    index.setdefault(pair.second, []).append(pair)
            self.memo["pairs"] = index
        return index.get(body, [])  # type: ignore[no-any-return]

    def points_of(self, body: int) -> list[tuple[str, tuple[float, float]]]:
        """Return the named points of ``body``, each ``(name, offset)``.

        The pins it carries, then its reported points (see
        :func:`assur.explain._rates.body_points`).
        """
        index = self.memo.get("points")
        if index is None:
            # every body's points at once: the note asks for them link by link
            plan = self.plan
            every: dict[int, dict[str, tuple[float, float]]] = {}
            for pair in plan.pairs.values():
                if pair.kind == "R":
                    found = every.setdefault(pair.first, {})
                    found.setdefault(pair.name.split("~")[0], pair.d_first)
                    if pair.name.endswith("~pin"):
                        # a slot's pin belongs to its link too (the crank's B,
                        # which the slot's group starts from)
                        found = every.setdefault(pair.second, {})
                        found.setdefault(pair.name.split("~")[0], pair.d_second)
            for point, b, offset in zip(
                plan.points, plan.point_body, plan.point_offset, strict=True
            ):
                every.setdefault(b, {}).setdefault(point, offset)
            index = {b: list(f.items()) for b, f in every.items()}
            self.memo["points"] = index
        return list(index.get(body, []))

    def reactions(self) -> dict[str, Any]:
        """Return every pair's reaction the reverse pass solved, by pair name."""
        found = self.memo.get("reactions")
        if found is None:
            found = {}
            if self.result is not None:
                for rec in self.result.groups:
                    found.update(rec.reactions)
            self.memo["reactions"] = found
        return found  # type: ignore[no-any-return]

    @property
    def plan(self) -> Plan:
        """The compiled mechanism."""
        return self.table.plan

    @property
    def mechanism(self) -> Mechanism:
        """The mechanism."""
        return self.table.plan.mechanism

    def shift(self) -> Array:
        """Return the core's origin in file coordinates, m."""
        return np.asarray(self.plan.shift, dtype=float)

    def point(self, body: int, offset: tuple[float, float], k: int = 0) -> Array:
        """Return level ``k`` of a body point (position in file coordinates)."""
        p = at(*point(self.bodies[body], offset, k))
        return p + self.shift() if k == 0 else self._clean(p, k)

    def pair_point(self, pair: PairPlan, k: int = 0) -> Array:
        """Return level ``k`` of a pair's point, the one moving with its second link."""
        return self.point(pair.second, pair.d_second, k)

    def origin(self, body: int) -> Array:
        """Return a body's origin, file coordinates (m)."""
        m = self.bodies[body]
        return at(m.ox[0], m.oy[0]) + self.shift()

    def omega(self, body: int) -> float:
        """Return a body's angular velocity, rad/s (0 for round-off)."""
        return self._turn(body, 1)

    def epsilon(self, body: int) -> float:
        """Return a body's angular acceleration, rad/s^2 (0 for round-off)."""
        return self._turn(body, 2)

    def _turn(self, body: int, k: int) -> float:
        """Return level ``k`` of a body's rotation, zero if it is round-off."""
        w = value(self.bodies[body].phi[k])
        if any(d.body == body for d in self.plan.drivers):
            return w  # the user's own input, however small
        return 0.0 if abs(w) * self.size() < ROUND_OFF * self.rate_scale(k) else w

    def angle(self, body: int) -> float:
        """Return a link's angle (its axis direction, or its rotation), rad."""
        return value(self.bodies[body].phi[0]) + float(self.plan.angle0[body])

    def turned(self, body: int, d: tuple[float, float]) -> Array:
        """Return the body-fixed vector ``d`` turned with the body."""
        return at(*rotated(self.bodies[body], d))

    def coincident(self, body: int, p: Array, k: int) -> Array:
        """Return level ``k`` (1 or 2) of the point of ``body`` that is at ``p`` now.

        ``p`` is in file coordinates.
        """
        m = self.bodies[body]
        r = p - self.origin(body)
        w = self.omega(body)
        base = at(m.ox[k], m.oy[k])
        if k == 1:
            return self._clean(base + w * perp(r), k)
        return self._clean(base + self.epsilon(body) * perp(r) - w * w * r, k)

    def link(self, body: int) -> str:
        """Return a body's name as the file gives it."""
        return self.plan.bodies[body]

    def size(self) -> float:
        """Return the mechanism's size, m."""
        return float(self.plan.scale)

    def rate_scale(self, k: int) -> float:
        """Return a size of the mechanism's motion at level ``k`` (m/s, m/s^2).

        What a velocity or an acceleration is told from round-off by: a yoke at
        mid-stroke has 1e-11 m/s^2 where the crank's pin has 20.
        """
        # once per motion (a lever's copy has velocities per unit speed): a note
        # asks for it at every point it writes
        key = (id(self.bodies), k)
        found = self.scales.get(key)
        if found is None:
            size, found = self.size(), 0.0
            for m in self.bodies:
                turn = max(abs(value(m.phi[j])) ** (k / j) for j in range(1, k + 1))
                found = max(found, math.hypot(value(m.ox[k]), value(m.oy[k])))
                found = max(found, turn * size)
            self.scales[key] = found
        return found

    def force_scale(self) -> float:
        """Return a size of the loads at play, N: the largest applied force or reaction.

        What a force is told from round-off by: the guide's normal force of an
        in-line slider-crank at its dead centre is 1.4e-14 N beside 3000 N.
        """
        found = self.memo.get("force_scale")
        if found is None:
            found = 0.0
            if self.applied is not None:
                for w in self.applied.wrenches:
                    found = max(found, math.hypot(value(w[0]), value(w[1])))
            if self.result is not None:
                for rec in self.result.groups:
                    for r in rec.reactions.values():
                        found = max(found, math.hypot(value(r.fx), value(r.fy)))
            self.memo["force_scale"] = found
        return found  # type: ignore[no-any-return]

    def _clean(self, v: Array, k: int) -> Array:
        """Return ``v`` (level ``k``) with its round-off set to zero."""
        v[np.abs(v) < ROUND_OFF * self.rate_scale(k)] = 0.0
        return v


def perp(v: Array) -> Array:
    """Return ``v`` turned by +90 degrees."""
    return np.array([-v[1], v[0]])


def cross(a: Array, b: Array) -> float:
    """Return the z component of ``a x b``."""
    return float(a[0] * b[1] - a[1] * b[0])


def unit(v: Array) -> Array:
    """Return ``v`` divided by its length (``v`` itself when it has none)."""
    length = math.hypot(v[0], v[1])
    return v / length if length > 0 else v


def from_table(table: Table, row: int = 0) -> Position:
    """Return the solved mechanism at ``row`` of a kinematics or forces table.

    Raises
    ------
    ModelError
        When the links' motion there is not finite (an overflow the sweep warned
        of): a note or a plan written from it would be made of inf and NaN.
    """
    table_row = table if len(table) == 1 else _one_row(table, row)
    _check_finite(table_row)
    plan = table_row.plan
    bodies = motions(plan, table_row.state)
    loads = compile_loads(plan)
    if table_row.force_state is None or loads.empty:
        return Position(table_row, bodies, None, None, loads)
    applied = applied_loads(plan, loads, bodies, table_row.state)
    return Position(table_row, bodies, applied, reverse(plan, bodies, applied), loads)


def _check_finite(table: Table) -> None:
    """Refuse a one-row table whose links' motion is not finite, naming the links."""
    state, plan = table.state, table.plan
    bad = [
        plan.bodies[b]
        for b in range(1, len(plan.bodies))
        if not all(np.isfinite(x).all() for x in state.motion[b])
    ]
    if bad:
        where = positions_where(plan, table.given, np.ones(1, dtype=bool))
        msg = (
            f"the motion of {listing(bad)} "
            f"is not finite at {where}: the inputs are out of the range the "
            "arithmetic can follow; expected a position (or inputs) where it is"
        )
        raise ModelError(msg)


def _one_row(table: Table, row: int) -> Table:
    """Return a table of the one row ``row`` (its states cut to that row)."""
    rows = slice(row, row + 1)
    force = None if table.force_state is None else table.force_state.rows(rows)
    return type(table)(
        table.plan,
        table.schema,
        table.given[rows],
        table.state.rows(rows),
        force,
    )


__all__ += ["cross", "perp", "unit"]
