"""Long sweeps analysed a slice of positions at a time.

``assur kinematics|forces`` call the library on slices of :data:`CHUNK` driver
positions and hand each slice's columns to the writers (:mod:`assur._tableio`); a
study summarises each variant of a long sweep slice by slice too. Memory stays
bounded whatever the number of positions, and what comes out is what the whole
table gives: the links' angles run on continuously from one slice to the
next, a warning near a dead centre names its positions over the whole sweep, once,
and a position that cannot be assembled is reported as the whole sweep reports it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any, NoReturn

import numpy as np

from assur import _state
from assur._drive import positions, to_si
from assur._skipped import Skipped
from assur._troubles import _change_points
from assur._vec import Array, full
from assur._warn import held, warn
from assur.columns import balancing_columns
from assur.errors import (
    AssemblyError,
    AssurError,
    AssurWarning,
    SelfLockingError,
    SingularConfigurationError,
)
from assur.plan import plan_of

__all__ = ["CHUNK", "Slice", "slices"]

FAILURES = (AssemblyError, SingularConfigurationError, SelfLockingError)
"""The errors of a sweep that fails at some of its positions."""
CHUNK = 65536
"""Most driver positions analysed and written at once (a multiple of the library's
slice, :data:`assur._state.CHUNK`, so that every number is computed as in one call
over the whole sweep)."""
SLICE_VALUES = 1 << 24
"""Most numbers of one slice's table (128 MB): a mechanism of very many columns
takes fewer positions at a time (see :func:`_chunk`)."""
RUNS_SHOWN = 6
"""Runs of positions that a warning lists (as :mod:`assur.analysis` does)."""
NEAR = ": near a dead centre "
POSITIONS = " at driver positions "
ONE_POSITION = " at driver position "


@dataclass(frozen=True)
class Slice:
    """One slice of a sweep: its table, and its link angles carried on."""

    table: Any
    angles: dict[str, Array]

    def column(self, name: str) -> Array:
        """Return one column over the slice (computed when first asked for)."""
        found = self.angles.get(name)
        return self.table[name] if found is None else found

    def arrays(self) -> list[Array]:
        """Return every column over the slice, in order."""
        return [self.column(name) for name in self.table.columns]


def slices(
    mech: Any,
    given: Array,
    forces: bool,
    skip: bool,
    skipped: Skipped,
    advance: Callable[[int], None] | None = None,
    check: bool = False,
) -> Iterator[Slice]:
    """Analyse ``given`` (driver positions, deg or m) slice by slice; yield each slice.

    Warnings near a dead centre are gathered and given once the sweep is done; when a
    slice fails, the warnings a whole sweep gives before its error are given first.
    Positions left out are added to ``skipped``. ``advance(count)`` is told of the
    positions solved (a progress bar). With ``check``, the positions of the whole
    sweep are solved first (slice by slice, a small part of the work), so that a
    position that cannot be assembled stops the command before anything is written.

    Raises
    ------
    AssemblyError, SingularConfigurationError, SelfLockingError
        As the analysis of the whole sweep at once raises them.
    """
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics

    analyse = force_table if forces else kinematics
    chunk = _chunk(mech, forces)
    n = len(given)
    angles: _Angles | None = None
    near = _Warnings(mech, skip)
    for start in range(0, max(n, 1), chunk):
        part = given[start : start + chunk]
        with held() as caught:
            try:
                table = analyse(
                    mech, part, skip_unassembled=skip, progress=_told(advance)
                )
            except FAILURES as err:
                failed: Exception | None = err
            else:
                failed = None
        near.add(caught, part)
        if failed is not None:
            # the warnings a whole sweep gives before its error, then the error
            near.give_before_error(given[start + chunk :], chunk)
            if n > chunk:
                locked = isinstance(failed, SelfLockingError)
                _raise_as_whole(mech, given, skip, failed, forces=locked)
            raise failed
        if check and not skip and start == 0:
            # after the first slice, so that its other faults (no masses) come first
            try:
                _check(mech, given[chunk:], given, chunk, forces)
            except FAILURES:
                near.give_before_error(given[chunk:], chunk)
                raise
        skipped.add(table.skipped, table.plan, part)
        last = start + chunk >= n
        if n and skipped.count == n and last:
            # a table of no rows was written without a word (exit status 0),
            # where the pictures of the same sweep stop; why, at the first
            near.give()
            raise skipped.none_kept(_first_failure(analyse, mech, given[:1]))
        if not len(table) and not last:
            continue  # no rows: the outputs open with the first slice that has some
        angles = angles or _Angles(table)
        yield Slice(table, angles.carry(table))
        del table  # one slice in memory at a time
    near.give()


def _first_failure(analyse: Any, mech: Any, first: Array) -> str:
    """Return the error of the position ``first`` (one row), as the sweep gives it."""
    with held():  # said by the sweep already
        try:
            analyse(mech, first)
        except FAILURES as err:
            return str(err)
    return ""


def _chunk(mech: Any, forces: bool) -> int:
    """Return the driver positions of one slice: its table within ``SLICE_VALUES``.

    A whole number of the library's slices while that fits (the numbers then are
    those of one call over the whole sweep, byte for byte); else a power of two,
    at least 64 (a chain of 300 dyads, 17 736 columns: 512 positions; numbers
    computed in another grouping may differ in their last bit).
    """
    from assur.columns import schema

    try:
        columns = len(schema(plan_of(mech), forces))
    except AssurError:
        return CHUNK  # the analysis of the first slice says what is wrong
    rows = SLICE_VALUES // max(1, columns)
    sweep_slice = _state.CHUNK
    if rows >= sweep_slice:
        return min(CHUNK, rows // sweep_slice * sweep_slice)
    return max(64, 1 << max(0, rows.bit_length() - 1))


def _told(advance: Callable[[int], None] | None) -> Any:
    """Return a library progress callback that tells ``advance`` of each step."""
    if advance is None:
        return False
    seen = [0]

    def callback(done: int, total: int) -> None:
        advance(done - seen[0])
        seen[0] = done

    return callback


def _check(
    mech: Any, rest: Array, given: Array, chunk: int, forces: bool = False
) -> None:
    """Solve the positions of ``rest`` of ``given`` by slices; raise as the whole sweep.

    Only the positions, a small part of the work of the analysis; with ``forces``
    and friction in a joint, the balancing loads too (friction may lock).
    """
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics

    rubbing = forces and any(j.friction > 0.0 for j in mech.joints)
    loads = balancing_columns(plan_of(mech)) if rubbing else []
    for start in range(0, len(rest), chunk):
        part = rest[start : start + chunk]
        with held():  # given once, by the analysis itself
            try:
                if rubbing:
                    force_table(mech, part, columns=loads)
                else:
                    kinematics(mech, part, columns=["angle"])
            except (AssemblyError, SingularConfigurationError) as err:
                _raise_as_whole(mech, given, False, err)
            except SelfLockingError as err:
                _raise_as_whole(mech, given, False, err, forces=True)


def _raise_as_whole(
    mech: Any, given: Array, skip: bool, err: Exception, forces: bool = False
) -> NoReturn:
    """Raise the error of the whole sweep: its counts and ranges cover every position.

    Only the positions are solved again (no velocities, no forces), with ``forces``
    (friction that locks) the balancing loads too, slice by slice: memory stays that
    of one slice and a byte a position.
    """
    from assur.analysis import report_troubles

    report_troubles(mech, given.reshape(len(given), -1), forces, skip)
    raise err  # pragma: no cover - the whole sweep fails where a slice did


class _Angles:
    """Link angles continuous over the whole sweep, as one table makes them.

    :mod:`assur.columns` makes every link's angle continuous along a table, starting
    within (-180, 180] deg: it removes a turn wherever two consecutive positions differ
    by more than half a turn. A slice alone would start again within (-180, 180]; here
    the turns counted so far carry on, with the same arithmetic as for one table, so
    the numbers are the same to the last bit.
    """

    def __init__(self, table: Any) -> None:
        plan = table.plan
        driven = {d.body for d in plan.drivers}
        self.bodies = {
            c.name: c.key[0]
            for c in table.schema
            if c.family == "angle" and c.key[0] not in driven
        }
        self.last: dict[str, Any] = {}
        self.turns: dict[str, Any] = {}
        self.shift: dict[str, Any] = {}

    def carry(self, table: Any) -> dict[str, Array]:
        """Return the link angles of one slice (deg), continuous with the last."""
        if not len(table):
            return {}
        return {
            name: self._angle(table, name, body)
            for name, body in self.bodies.items()
            if name in table
        }

    def _angle(self, table: Any, name: str, body: int) -> Array:
        """Return one link's angle (deg) over a slice, continuous with the last."""
        raw = table.plan.angle0[body] + full(table.state.rotation(body, 0), len(table))
        if name not in self.last:  # the first rows of the sweep: assur.columns' rule
            first = raw[0]
            self.shift[name] = first - (math.pi - (math.pi - first) % (2.0 * math.pi))
            steps = np.diff(raw)
        else:
            steps = np.diff(raw, prepend=self.last[name])
        with np.errstate(invalid="ignore"):
            turns = np.nan_to_num(np.round(steps * (0.5 / math.pi)))
        # the running count of turns, added up in the order one table adds it up
        if name in self.last:
            counted = np.cumsum(np.concatenate(([self.turns[name]], turns)))[1:]
        else:
            counted = np.concatenate(([0.0], np.cumsum(turns)))
        self.last[name] = raw[-1]
        self.turns[name] = counted[-1]
        angle = raw - 2.0 * math.pi * counted
        shift = self.shift[name]
        angle = angle - shift if shift else angle
        return angle * (180.0 / math.pi)


@dataclass
class _Runs:
    """The runs of positions of one warning, gathered slice by slice."""

    runs: list[list[str]]
    cut: bool
    last_slice: int


class _Warnings:
    """Warnings of the slices, given once for the whole sweep.

    A warning near a dead centre lists runs of consecutive positions: runs that
    meet where two slices meet become one, and the list is cut after
    :data:`RUNS_SHOWN` runs, as the whole sweep's warning is. Other warnings are
    given once each.
    """

    def __init__(self, mech: Any, skip: bool) -> None:
        self.mech = mech
        self.skip = skip
        self.near: dict[str, _Runs] = {}
        # the other warnings, in the order first met
        self.order: dict[tuple[type[Warning], str], None] = {}
        self.count = 0
        self.previous_last: Array | None = None

    def add(self, caught: list[Any], part: Array) -> None:
        """Take the warnings of one slice of positions ``part``."""
        for w in caught:
            text = str(w.message)
            if NEAR in text:
                # one position is "at driver position P": its runs merged alike
                text = text.replace(ONE_POSITION, POSITIONS)
            head, mark, ranges = text.rpartition(POSITIONS)
            if not (issubclass(w.category, AssurWarning) and mark and NEAR in head):
                self.order.setdefault((w.category, text))
                continue
            runs = [r.split(" to ") for r in ranges.split("; ")]
            cut = runs[-1] == ["..."]
            runs = runs[:-1] if cut else runs
            found = self.near.get(head + mark)
            if found is None:
                self.near[head + mark] = _Runs(runs, cut, self.count)
                continue
            if (
                found.last_slice == self.count - 1
                and not found.cut
                and self.previous_last is not None
                and self._near(head + mark, self.previous_last)
                and self._near(head + mark, part[:1])
            ):
                runs[0] = [found.runs[-1][0], runs[0][-1]]
                found.runs.pop()
            found.runs += runs
            found.cut |= cut
            found.last_slice = self.count
        self.previous_last = part[-1:]
        self.count += 1

    def _near(self, key: str, position: Array) -> bool:
        """Whether the warning ``key`` holds at one position (solved on its own)."""
        from assur.analysis import kinematics

        with held() as caught:
            kinematics(
                self.mech, position, skip_unassembled=self.skip, columns=["angle"]
            )
        told = (str(w.message).replace(ONE_POSITION, POSITIONS) for w in caught)
        return any(text.startswith(key) for text in told)

    def give_before_error(self, rest: Array, chunk: int) -> None:
        """Issue the warnings a whole sweep gives before its error.

        The change points over every position (those of ``rest``, the positions not
        yet solved, found ``chunk`` at a time) and the other warnings met so far, in
        the order first met; not the positions near a dead centre, which a sweep
        that fails does not list.
        """
        plan = plan_of(self.mech)
        with held() as caught:
            for start in range(0, len(rest), chunk):
                part = positions(plan, rest[start : start + chunk])
                _change_points(plan, part, to_si(plan, part))
        for w in caught:
            self.order.setdefault((w.category, str(w.message)))
        for category, other in self.order:
            warn(other, category, stacklevel=3)

    def give(self) -> None:
        """Issue the warnings of the whole sweep, in a whole sweep's order.

        One call warns of the change points first, then of values as they are
        solved, and of positions near a dead centre last; each kind in the order
        first met.
        """
        for category, other in self.order:
            warn(other, category, stacklevel=3)
        for key, found in self.near.items():
            runs = [r[0] if r[0] == r[-1] else f"{r[0]} to {r[-1]}" for r in found.runs]
            more = found.cut or len(runs) > RUNS_SHOWN
            text = "; ".join(runs[:RUNS_SHOWN]) + ("; ..." if more else "")
            one = len(found.runs) == 1 and found.runs[0][0] == found.runs[0][-1]
            if one and not found.cut:
                key = key.replace(POSITIONS, ONE_POSITION)
            warn(key + text, AssurWarning, stacklevel=3)
