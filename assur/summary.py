"""Summaries of a force table: the few numbers joints, bearings and motors are sized on.

For every joint the largest reaction, where it occurs and its RMS (a sliding pair's
largest couple too); for the driver the largest, smallest, mean and RMS balancing
load, its mean, largest and smallest power; the largest shaking force and moment; with
friction the power lost in each joint, in all, and the cycle's mechanical efficiency. A
:class:`Summary` is built slice by slice, so that a sweep too long for memory is
summarised as it is analysed; :func:`summarize` does it for one table.

Means and RMS values are time averages over the sweep, whose positions are taken as
equally spaced (the default sweep of one turn in 1 degree steps is): at a constant
driver speed, plain means over the positions; where one driver's speed varies
(``omega=`` given per position, the dynamic model's real speed), each position
weighted by the time the driver spends there, ``1 / |speed|`` (:mod:`assur._timing`).
A position on a load table's step counts half on each side (:mod:`assur._steps`). A
crank's sweep that ends a whole number of turns on from its first position
(``0:360:10``) ends on its first pose again, and that pose counts once.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._efficiency import efficiency
from assur._running import Running, lasts, peaks, per_variant, settled_mean, sums
from assur._summary_rows import rows_of
from assur._timing import Clock
from assur._undefined import undefined
from assur._vec import Array
from assur.errors import UsageError

__all__ = ["Summary", "efficiency", "summarize", "undefined"]

ROUND_OFF = 1e-12
"""A couple or shaking load below this share of the largest reaction (times the
mechanism's size, for a moment), or a mean power or balancing load below this
share of its own peak, is round-off: the summary gives 0."""


@dataclass
class Summary:
    """The summary of a force table, added to one slice of positions at a time.

    ``add(table)`` takes each slice (a forces table); ``result()`` returns the values
    by name and ``units`` gives each name's unit. The names and their definitions are
    those of :meth:`assur.Table.summary <assur.analysis.Table.summary>`. With
    ``variants`` > 1 a table holds that
    many variants of one mechanism one after the other, each over the same number of
    positions: ``results()`` then gives every value per variant.
    """

    variants: int = 1
    count: int = 0
    units: dict[str, str] = field(default_factory=dict)
    _joints: dict[str, Running] = field(default_factory=dict)
    _couples: dict[str, Running] = field(default_factory=dict)
    """A sliding pair's couple, |J.M|, by the pair's name."""
    _drivers: dict[str, Running] = field(default_factory=dict)
    _peaks: dict[str, Running] = field(default_factory=dict)
    """The drivers' power, all together (``driver``) and each one's (several)."""
    _shaking: dict[str, Running] = field(default_factory=dict)
    """|shaking force| (``F``) and |shaking moment| (``M``)."""
    _power: Any = 0.0
    _own: dict[str, Any] = field(default_factory=dict)
    """Each driver's own mean power, by its joint's name (several drivers)."""
    _ideal: Any = 0.0
    _losses: dict[str, Any] = field(default_factory=dict)
    _rubbing: bool = False
    _crank: bool = False
    """One revolute driver: a sweep may end where it began, a turn on."""
    clockwise: tuple[str, ...] = ()
    """The joints of the cranks turning clockwise (their mean speed below 0)."""
    drivers: int = 0
    """The mechanism's number of drivers."""
    _size: float = 1.0
    """The mechanism's size (m): a force times it is a moment of the same scale."""
    _ends: list[float] = field(default_factory=list)
    """The first and the last driver position added (deg)."""
    _tail: dict[str, Any] = field(default_factory=dict)
    """The sums' terms of the last position added, by the sum's name."""
    _weight: Any = 0.0
    """The positions counted and the time they stand for, stacked (2, variants)."""
    _clock: Clock = field(default_factory=Clock)
    plan: Any = None
    """The mechanism summarised (its first slice's plan)."""
    landed: set[Any] = field(default_factory=set)
    """The steps of load tables a position landed on, as ``(entry, step)``."""
    one_sided: bool = False
    """Positions on steps were counted on one side (a table of a few columns)."""
    spacing: float = math.inf
    """The least distance between two positions added (deg or m): their spacing, however
    many were left out (``--skip-unassembled``)."""

    def add(self, table: Any) -> None:
        """Add the positions of ``table``, a forces table (one slice of a sweep).

        Raises
        ------
        UsageError
            When ``table`` is a kinematics table (no forces to summarise).
        """
        if table.force_state is None:
            msg = (
                "summary: a table made with columns= of kinematics only has no forces; "
                "expected a force column among them, or no columns="
                if getattr(table, "partial", False)
                else "summary: a kinematics table has no forces; expected assur.forces"
            )
            raise UsageError(msg)
        if not self.units:
            self._start(table)
        n = len(table)
        shape = (self.variants, n // self.variants)
        self.count += shape[1]
        rows = rows_of(table, self.variants, self._clock.record(table, shape))
        self.landed |= rows.landed
        self.one_sided = self.one_sided or rows.one_sided
        where, w, last = rows.where, rows.weights, rows.last
        forces = {name: rows.column(f"{name}.F") for name in self._joints}
        # where a force or moment ties, its round-off is the reactions' (see
        # Running.add): the slice's largest, per variant
        big = np.fmax.reduce([peaks(f) for f in forces.values()], initial=0.0)
        for name, running in self._joints.items():
            running.add(forces[name], where, w, last, big)
        for name, running in self._couples.items():
            running.add(rows.size(f"{name}.M"), where, w, last, big * self._size)
        for name, running in self._drivers.items():
            running.add(rows.column(name), where, w, last)
        if "F" in self._shaking:
            shaking = rows.size("shaking.Fx", "shaking.Fy")
            self._shaking["F"].add(shaking, where, w, last, big)
        if "M" in self._shaking:
            moment = rows.size("shaking.M")
            self._shaking["M"].add(moment, where, w, last, big * self._size)
        ones = np.ones(where.shape)
        tail: dict[str, Any] = {
            "power": 0.0,
            "ideal": 0.0,
            "weight": lasts(ones, w, last),
        }
        self._weight = self._weight + sums(ones, w)
        total: Any = 0.0
        for i, driver in enumerate(table.plan.drivers):
            speed = rows.speed(i)
            power = rows.balancing(i) * speed
            total = total + power
            self._power = self._power + sums(power, w)
            tail["power"] = tail["power"] + lasts(power, w, last)
            name = driver.pair.name
            if name in self._own:
                self._own[name] = self._own[name] + sums(power, w)
                self._peaks[name].add(power, where, w, last)
                tail[name] = lasts(power, w, last)
            if self._rubbing:
                ideal = rows.ideal(i) * speed
                self._ideal = self._ideal + sums(ideal, w)
                tail["ideal"] = tail["ideal"] + lasts(ideal, w, last)
        self._peaks["driver"].add(total + np.zeros(where.shape), where, w, last)
        for name, power in rows.friction().items():
            self._losses[name] = self._losses.get(name, 0.0) - sums(power, w)
            tail[f"{name}.friction"] = -lasts(power, w, last)
        where = where[:, : shape[1]]  # the table's own positions
        if shape[1]:
            self._tail = tail
            # the positions' spacing: the least step between two, across slices too
            given = np.concatenate([self._ends[-1:], where[0]])
            steps = np.abs(np.diff(given))
            if np.any(steps > 0):
                self.spacing = min(self.spacing, float(np.min(steps[steps > 0])))
            self._ends[:] = [*self._ends[:1], float(where[0, -1])]
            if len(self._ends) == 1:  # the first slice: its first position too
                self._ends.insert(0, float(where[0, 0]))

    def timed(self) -> bool:
        """Whether the means are weighted by time (see :class:`assur._timing.Clock`)."""
        return self._clock.timed()

    def _start(self, table: Any) -> None:
        """Name the summary's values after the table's columns."""
        plan = table.plan
        unit = table.column("angle").unit if "angle" in table else "deg"
        units = self.units
        for column in table.schema:
            if column.family == "magnitude":
                self._joints[column.owner] = Running.start(self.variants)
                name = column.owner
                units[f"{name}.F.max"] = "N"
                units[f"{name}.F.at"] = unit
                units[f"{name}.F.rms"] = "N"
            elif column.family == "reaction" and column.quantity == "M":
                self._couples[column.owner] = Running.start(self.variants)
        for name in self._couples:
            units[f"{name}.M.max"] = "N m"
            units[f"{name}.M.at"] = unit
        for column in table.schema:
            if column.family == "balancing":
                self._drivers[column.name] = Running.start(self.variants)
                for part in ("max", "min", "mean", "rms"):
                    units[f"{column.name}.{part}"] = column.unit
        units["driver.power.mean"] = "W"
        units["driver.power.max"] = "W"
        units["driver.power.min"] = "W"
        self._peaks["driver"] = Running.start(self.variants)
        if len(plan.drivers) > 1:
            for driver in plan.drivers:
                units[f"{driver.pair.name}.power.mean"] = "W"
                units[f"{driver.pair.name}.power.max"] = "W"
                units[f"{driver.pair.name}.power.min"] = "W"
                self._own[driver.pair.name] = 0.0
                self._peaks[driver.pair.name] = Running.start(self.variants)
        # a table made with columns= summarises the shaking loads it holds
        parts = {"F": ("Fx", "Fy"), "M": ("M",)}
        for part, what in (("F", "N"), ("M", "N m")):
            if all(f"shaking.{c}" in table for c in parts[part]):
                self._shaking[part] = Running.start(self.variants)
                units[f"shaking.{part}.max"] = what
                units[f"shaking.{part}.at"] = unit
        self._rubbing = any(p.friction > 0.0 for p in plan.pairs.values())
        self._crank = len(plan.drivers) == 1 and plan.drivers[0].kind == "R"
        self.plan = plan
        self._clock.one = len(plan.drivers) == 1
        self._clock.rate = "omega" if plan.drivers[0].kind == "R" else "v"
        self.drivers = len(plan.drivers)
        # a study's variants each have their size: the largest bounds the noise
        self._size = float(np.max(plan.scale))
        if len(table):
            self.clockwise = tuple(
                d.pair.name
                for i, d in enumerate(plan.drivers)
                if d.kind == "R" and np.mean(table.state.speed[i]) < 0.0
            )
        if self._rubbing:
            for name, pair in plan.pairs.items():
                if pair.friction > 0.0 and not pair.virtual:
                    units[f"{name}.friction.loss"] = "W"
                    self._losses[name] = 0.0
            units["friction.loss"] = "W"
            units["driver.power_ideal.mean"] = "W"
            units["efficiency"] = ""

    def result(self) -> dict[str, float]:
        """Return the summary's values by name (as ``Table.summary()`` names them).

        Raises
        ------
        UsageError
            When no position was added (every one left out, or an empty sweep).
        """
        return {name: float(values[0]) for name, values in self.results().items()}

    def results(self) -> dict[str, Array]:
        """Return the summary's values by name, one per variant (shape (variants,)).

        Raises
        ------
        UsageError
            When no position was added (every one left out, or an empty sweep).
        """
        if not self.count:
            msg = "summary: the table has no positions to summarise"
            raise UsageError(msg)
        # a sweep that ends a whole turn on from where it began (0:360:10) ends on
        # its first pose again: counted twice, it tipped a cycle's mean power
        closing = self.closes()
        row = 1 if self.timed() else 0

        def less(total: Any, last: Any) -> Any:
            # the sum without its last position's term, when that is the first's;
            # over the positions or over time
            return np.asarray(total - last if closing else total)[row]

        n = less(self._weight, self._tail["weight"])

        out: dict[str, Array] = {}
        tops = [r.top for r in self._joints.values()]
        force = np.max(tops, axis=0) if tops else np.zeros(self.variants)
        # each joint's reaction, then its couple (columns= may hold the couple alone)
        for name in dict.fromkeys([*self._joints, *self._couples]):
            r = self._joints.get(name)
            if r is not None:
                out[f"{name}.F.max"] = r.top
                out[f"{name}.F.at"] = r.at
                out[f"{name}.F.rms"] = np.sqrt(less(r.squares, r.last_squares) / n)
            couple = self._couples.get(name)
            if couple is not None:
                top, at = self._settled(couple, force * self._size)
                out[f"{name}.M.max"], out[f"{name}.M.at"] = top, at
        for name, r in self._drivers.items():
            out[f"{name}.max"] = r.top
            out[f"{name}.min"] = r.bottom
            mean = less(r.total, r.last) / n
            out[f"{name}.mean"] = settled_mean(mean, r.bottom, r.top, ROUND_OFF)
            out[f"{name}.rms"] = np.sqrt(less(r.squares, r.last_squares) / n)
        power = less(self._power, self._tail.get("power"))
        for name, total in [("driver", power)] + [
            (k, less(own, self._tail.get(k))) for k, own in self._own.items()
        ]:
            peak = self._peaks[name]
            mean = per_variant(total / n, self.variants)
            out[f"{name}.power.mean"] = settled_mean(
                mean, peak.bottom, peak.top, ROUND_OFF
            )
            out[f"{name}.power.max"] = peak.top
            out[f"{name}.power.min"] = peak.bottom
        for part, r in self._shaking.items():
            size = force * (self._size if part == "M" else 1.0)
            out[f"shaking.{part}.max"], out[f"shaking.{part}.at"] = self._settled(
                r, size
            )
        if self._rubbing:
            losses = {
                name: less(loss, self._tail.get(f"{name}.friction"))
                for name, loss in self._losses.items()
            }
            for name, loss in losses.items():
                out[f"{name}.friction.loss"] = per_variant(loss / n, self.variants)
            lost = per_variant(sum(losses.values()) / n, self.variants)
            out["friction.loss"] = lost
            ideal = per_variant(
                less(self._ideal, self._tail.get("ideal")) / n, self.variants
            )
            power = out["driver.power.mean"]
            # no load takes work (inertia alone): the mean is round-off of powers
            # that cancel, -1.6e-13 W beside a driver's 2564 W, and is 0. Round-off
            # of the powers at play, the driver's peaks: beside a friction of 1e-12
            # the means are all small, and the noise made an efficiency of 1.2e-5
            peaks = [out["driver.power.max"], out["driver.power.min"], power, lost]
            noise = ROUND_OFF * np.max(np.abs(np.stack(peaks)), axis=0)
            ideal = np.where(np.abs(ideal) <= noise, 0.0, ideal)
            out["driver.power_ideal.mean"] = ideal
            # the power with friction is the power without and friction's, at
            # every position: where its mean is round-off, their sum tells it
            driving = np.where(np.abs(power) <= noise, ideal + lost, power)
            out["driver.power.mean"] = driving
            out["efficiency"] = np.array(
                [efficiency(*v) for v in zip(driving, ideal, lost, strict=True)]
            )
        return out

    def _settled(self, r: Running, size: Array) -> tuple[Array, Array]:
        """Return a largest size and where it is; 0 at the first position if noise.

        A couple that is zero but for round-off (an in-line slider's guide,
        7e-15 N m beside reactions of 1e3 N) had its largest at wherever the
        round-off peaked: 0 now, at the sweep's first position, as exact zeros are.
        """
        noise = r.top <= ROUND_OFF * size
        first = self._ends[0] if self._ends else math.nan
        return np.where(noise, 0.0, r.top), np.where(noise, first, r.at)

    def means_over(self) -> tuple[str, str]:
        """Return what the means and RMS values are over, and why where it matters."""
        return self._clock.over()

    def span(self) -> tuple[float, float] | None:
        """Return the first and the last driver position added (deg or m), if any."""
        return (self._ends[0], self._ends[-1]) if self._ends else None

    def covered(self) -> float | None:
        """Return the angle a crank's positions stand for, deg; None for no crank.

        Equally spaced: to the last and a step on, or to the last where the sweep
        closes a turn (0:360:10 covers 360 deg).
        """
        if not self._crank or len(self._ends) != 2:
            return None
        span = abs(self._ends[1] - self._ends[0])
        if self.closes() or not math.isfinite(self.spacing):
            return span
        return span + self.spacing

    def closes(self) -> bool:
        """Whether the positions end a whole number of turns on from where they began.

        One revolute driver, more than one position: the last is then the first
        pose again.
        """
        if not self._crank or self.count < 2 or len(self._ends) != 2:
            return False
        first, last = self._ends
        # in halves: positions near the largest float (-1.7e308:1.7e308:1e308) are
        # a sound range whose span overflows, and round() of an inf raises
        turns = (last / 2 - first / 2) / 180.0
        return last != first and abs(turns - round(turns)) <= 1e-12 * max(
            1.0, abs(turns)
        )


def summarize(table: Any) -> dict[str, float]:
    """Return the summary of one forces table, as ``Table.summary()`` gives it."""
    summary = Summary()
    summary.add(table)
    return summary.result()
