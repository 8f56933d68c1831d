"""Loads tabulated against a position, and the checks of a mechanism's loads.

:class:`LoadTable` is public as :class:`assur.model.LoadTable`; the checks run when a
:class:`~assur.model.Mechanism` is made.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from assur._checks import (
    GROUND,
    POINT_FORMS,
    _check_vec,
    _fail,
    _finite,
    _number_fault,
    _on_the_frame,
    _sequence_fault,
    _tuples,
    _unknown,
)
from assur._points import _check_point
from assur._tables import disagreement
from assur._text import counted, describe, suggest

if TYPE_CHECKING:
    from assur.model import Load, Mechanism


@dataclass(frozen=True, slots=True)
class LoadTable:
    """A load tabulated against a position, interpolated linearly.

    Over a crank the table is periodic (positions modulo 360 deg): a table that
    stops short of a turn runs linearly from its last value back to its first, a
    turn on. A load over part of a turn only (a cutting stroke) is written with
    zeros at its ends, or it acts over the rest of the turn too. Over a slide or a
    prismatic driver the table must cover every analysed position.

    Parameters
    ----------
    over : str
        ``"driver"`` (the first driver's position, deg or m) or the name of a
        prismatic joint (its slide, m).
    table : tuple of float
        Increasing positions; one given twice is a step, where the value jumps
        from the first of its two values to the second.
    values : tuple of tuple of float
        One sequence per component: ``(x, y)`` for a force (N), ``(torque,)`` for a
        torque (N m).
    """

    over: str
    table: tuple[float, ...]
    values: tuple[tuple[float, ...], ...]

    def __post_init__(self) -> None:
        _tuples(self, "table", "values")


def _validate_table(entry: str, table: LoadTable, ncomp: int, mech: Mechanism) -> None:
    prismatic = [j.name for j in mech.joints if j.kind != "revolute"]
    if table.over != "driver" and table.over not in prismatic:
        hint = (
            suggest(table.over, ["driver", *prismatic])
            if isinstance(table.over, str)
            else ""
        )
        _fail(
            f"{entry}.over",
            f"expected 'driver' or a prismatic joint, got {describe(table.over)}{hint}",
        )
    if (
        not isinstance(table.table, tuple)
        or len(table.table) < 2
        or not all(map(_finite, table.table))
    ):
        _fail(
            f"{entry}.table",
            _sequence_fault(table.table, "at least two finite positions"),
        )
    xs = np.asarray(table.table, dtype=float)
    gaps = np.diff(xs)
    if np.any(gaps < 0) or np.any((gaps[:-1] == 0) & (gaps[1:] == 0)):
        _fail(
            f"{entry}.table",
            "expected increasing positions, each at most twice (twice: a step, the "
            "value jumps there)",
        )
    values = table.values
    if not isinstance(values, tuple) or len(values) != ncomp:
        count = len(values) if isinstance(values, tuple) else describe(values)
        _fail(entry, f"expected {counted(ncomp, 'value sequence')}, got {count}")
    for seq in values:
        if (
            not isinstance(seq, tuple)
            or len(seq) != len(xs)
            or not all(map(_finite, seq))
        ):
            _fail(
                entry,
                _sequence_fault(
                    seq, f"{len(xs)} finite values, one per table position", len(xs)
                ),
            )
    kinds = {j.name: j.kind for j in mech.joints}
    turning = bool(mech.drivers) and kinds.get(mech.drivers[0].joint) == "revolute"
    if table.over != "driver" or not turning:
        return
    for seq in values:
        # a crank's angle is read modulo 360: entries a turn apart are one position
        found = disagreement(xs, np.asarray(seq, dtype=float))
        if found is not None:
            at, other, which = found
            how = "before" if other < at else "after"
            _fail(
                entry,
                f"the value {which}at {at:g} deg is not the one at {other:g} deg, a "
                f"whole number of turns {how}; expected values that repeat from turn "
                "to turn (the crank's angle is read modulo 360)",
            )


def _validate_load(
    mech: Mechanism,
    entry: str,
    load: Load,
    link_names: list[str],
    point_names: set[str],
) -> None:
    if load.link == GROUND:
        why = "a load on it acts on no moving link and changes no reaction"
        _fail(f"{entry}.link", _on_the_frame(why, link_names))
    if not isinstance(load.link, str) or load.link not in link_names:
        _fail(f"{entry}.link", _unknown("link", load.link, link_names))
    if load.force is None and load.torque is None:
        _fail(entry, "expected a 'force' or a 'torque'")
    if load.force is not None:
        if load.at is None:
            _fail(
                entry,
                f"a force needs its point of application 'at'; expected {POINT_FORMS}",
            )
        if isinstance(load.force, LoadTable):
            _validate_table(f"{entry}.force", load.force, 2, mech)
        else:
            _check_vec(f"{entry}.force", load.force)
    if load.at is not None:
        _check_point(f"{entry}.at", load.at, point_names)
    if isinstance(load.torque, LoadTable):
        _validate_table(f"{entry}.torque", load.torque, 1, mech)
    elif load.torque is not None and not _finite(load.torque):
        _fail(f"{entry}.torque", _number_fault(load.torque))
