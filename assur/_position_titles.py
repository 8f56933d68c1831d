"""Driver positions as messages and titles write them: "30 deg", "φ = 30.0°".

A message names a position in the user's units ("(30 deg, 0.125 m)" for several
drivers, in parentheses so that a run of them reads as positions); a picture's or
the report's title writes "φ = 30.0°" or "s = 0.125 m".
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

__all__ = ["position_text", "position_title", "row_position"]


def position_text(
    kinds: Sequence[str], values: Sequence[float], digits: int = 6
) -> str:
    """Return driver positions for a message: "30 deg", "0.1 m" or several's.

    ``kinds`` holds each driver's pair kind ("R" or "P"), ``values`` its position in
    the user's units (deg, or m), written to ``digits`` significant digits. Several
    drivers' are one position in parentheses: "(30 deg, 0.125 m)", so that a run
    "(178 deg, 238 deg) to (179 deg, 239 deg)" reads as two positions, not four.

    Examples
    --------
    >>> position_text(["R", "P"], [30.0, 0.125])
    '(30 deg, 0.125 m)'
    >>> position_text(["R"], [30.0])
    '30 deg'
    """
    text = ", ".join(
        f"{x:.{digits}g} deg" if kind == "R" else f"{x:.{digits}g} m"
        for kind, x in zip(kinds, values, strict=False)
    )
    return f"({text})" if len(values) > 1 else text


def position_title(
    units: Sequence[str], values: Sequence[float], names: Sequence[str] = ()
) -> str:
    """Return driver positions for a title: "φ = 30.0°" or "s = 0.1 m".

    ``units`` holds the unit of each position as the table's columns give it
    (``"deg"`` for an angle, else a length), ``values`` the positions in those units;
    with ``names`` (several drivers) each position follows its joint's name.

    Examples
    --------
    >>> position_title(["deg"], [30.0])
    'φ = 30.0°'
    >>> position_title(["deg", "m"], [30.0, 0.125], ["A", "E"])
    'A: φ = 30.0°, E: s = 0.125 m'
    """
    parts = [
        f"φ = {x:.1f}°" if unit == "deg" else f"s = {x:.4g} {unit}"
        for unit, x in zip(units, values, strict=True)
    ]
    if names:
        parts = [f"{n}: {p}" for n, p in zip(names, parts, strict=True)]
    return ", ".join(parts)


def row_position(table: Any, row: int) -> str:
    """Return the driver positions of ``table`` at ``row`` for a title.

    :func:`position_title` of the drivers' positions (deg for a crank, m for a
    slider), each named by its joint when there are several drivers.
    """
    drivers = table.plan.drivers
    units = ["deg" if d.kind == "R" else "m" for d in drivers]
    names = [d.pair.name for d in drivers] if len(drivers) > 1 else []
    return position_title(units, table.given[row].tolist(), names)
