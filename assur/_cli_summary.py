"""What ``assur kinematics|forces`` prints instead of the full table.

The readable table of the first rows (:func:`_summary`, :func:`format_table`) and,
with ``--summary``, the summary of the whole sweep (:func:`_summed`,
:func:`_summary_text`).
"""

from __future__ import annotations

import json
import math
import shutil
import sys
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._digits import cleaned
from assur._sliced import Slice
from assur._stdout import as_written
from assur._text import counted, number_text
from assur._vec import Array
from assur._width import ljust, rjust, shown_width

if TYPE_CHECKING:
    from assur.summary import Summary

__all__ = [
    "SUMMARY_ROWS",
    "_summary",
    "_summary_text",
    "_summed",
    "format_table",
    "summary_columns",
    "terminal_width",
]

SUMMARY_ROWS = 400
"""Most rows of the readable table; --csv, --json and --parquet give them all."""


ABOUT = "about the origin of the file's coordinates"
"""What the summary's shaking moment is taken about, said beside it."""


def _summed(parts: Iterator[Slice], summary: Summary) -> Iterator[Slice]:
    """Yield the slices, each added to ``summary`` on its way."""
    for part in parts:
        summary.add(part.table)
        yield part


def _summary_text(name: str, summary: Summary, as_json: bool) -> str:
    """Return the summary as aligned lines with units, or as JSON."""
    from assur._summary_notes import notes, turning
    from assur.summary import undefined

    values = summary.result()
    why = undefined(values)
    if as_json:
        data = {
            "name": name,
            "positions": summary.count,
            "closes_a_turn": summary.closes(),
            "means_over": summary.means_over()[0],
            "summary": {k: v if math.isfinite(v) else None for k, v in values.items()},
            "units": {k: summary.units[k] for k in values},
        }
        if why:
            data["undefined"] = why  # why a value is null
        if summary.clockwise:
            data["clockwise"] = list(summary.clockwise)  # driving torques below 0
        said = notes(summary)
        if "shaking.M.max" in summary.units:
            said.append(f"shaking.M is taken {ABOUT}")
        if said:
            data["notes"] = said
        return json.dumps(data, indent=2)
    # aligned as standard output shows the names (escaped where it cannot write them)
    keys = {key: as_written(key) for key in values}
    width = max(map(shown_width, keys.values()))
    # a whole turn's sweep ends on its first pose: the means count that pose once
    once = ", the closing pose counted once" if summary.closes() else ""
    lines = [f"Summary over {counted(summary.count, 'position')}{once} ({name})"]
    for key, value in values.items():
        unit = summary.units[key]
        head = ljust(keys[key], width)
        if key in why:
            lines.append(f"  {head}  {'undefined':>14}  ({why[key]})")
            continue
        shown = number_text(value, ">14.6g")
        # the shaking moment's value depends on the point it is taken about
        about = f" ({ABOUT})" if key == "shaking.M.max" else ""
        lines.append(f"  {head}  {shown}  {unit}{about}".rstrip())
    lines += [f"  ({line})" for line in notes(summary)]
    if summary.clockwise:
        first, *rest = turning(summary)
        lines += [f"  ({first}", *(f"   {line}" for line in rest)]
        lines[-1] += ")"
    return "\n".join(lines)


def _summary(
    parts: Iterator[Slice], forces: bool, width: int | None = None
) -> tuple[str, tuple[str, ...]]:
    """Return the readable table of the first rows and the table's column names.

    ``width``: a terminal's, in characters, which a wider table is cut to fit.
    """
    names: tuple[str, ...] = ()
    picked: list[str] = []
    units: list[str] = []
    kept: list[list[Array]] = []
    rows = 0
    for part in parts:
        table = part.table
        if not names:
            names = table.columns
            picked = summary_columns(table, forces)
            units = [table.column(c).unit for c in picked]
        room = SUMMARY_ROWS - sum(len(k[0]) for k in kept)
        if room > 0 and len(table):
            kept.append([part.column(c)[:room] for c in picked])
        rows += len(table)
    columns = [np.concatenate(k) for k in zip(*kept, strict=True)] if kept else []
    return format_table(picked, units, columns, rows, width=width), names


def summary_columns(table: Any, forces: bool) -> list[str]:
    """Pick the readable table's columns from the table's schema.

    Kinematics: every link's angle, angular velocity and angular acceleration.
    Forces: the magnitude of every reaction and every balancing load with its
    virtual-power check (and, with friction, the load without friction).
    """
    if forces:
        families = {"magnitude", "balancing", "check", "ideal"}
        picked = [c.name for c in table.schema if c.family in families]
    else:
        picked = [
            c.name
            for c in table.schema
            if (c.family == "angle")
            or (c.family == "link" and c.quantity in ("omega", "alpha"))
        ]
    return ["angle", *picked]


def terminal_width() -> int | None:
    """Return the width of the terminal standard output writes to; None if none."""
    try:
        if not sys.stdout.isatty():
            return None
    except (AttributeError, OSError, ValueError):
        return None

    return shutil.get_terminal_size().columns


def _blocks(widths: list[int], width: int | None) -> list[list[int]]:
    """Return the columns of each block of a table ``width`` characters wide.

    Every block starts with the first column; one column wider than the width
    alone has a block of its own (a terminal then wraps it).
    """
    if width is None or sum(widths) + 2 * (len(widths) - 1) <= width:
        return [list(range(len(widths)))]
    blocks = []
    block, used = [0], widths[0]
    for i in range(1, len(widths)):
        if len(block) > 1 and used + 2 + widths[i] > width:
            blocks.append(block)
            block, used = [0], widths[0]
        block.append(i)
        used += 2 + widths[i]
    blocks.append(block)
    return blocks


def format_table(
    names: list[str],
    units: list[str],
    columns: list[Array],
    rows: int,
    limit: int = SUMMARY_ROWS,
    width: int | None = None,
) -> str:
    """Return an aligned text table of ``columns`` with a units row.

    ``rows`` is the number of rows in all; beyond the ``limit`` shown, a last line
    says how many were left out. A table wider than ``width`` characters (a
    terminal's) is cut into blocks of columns that fit, one under the other, each
    led by the first column (the driver's position).
    """
    heads = [as_written(name) for name in names]  # as standard output shows them
    marks = [f"[{u}]" if u else "" for u in units]
    cells = (
        [
            [number_text(v) for v in values]
            for values in zip(*cleaned(units, columns), strict=True)
        ]
        if columns
        else []
    )
    widths = [
        max(shown_width(h), len(u), *(len(r[i]) for r in cells))
        for i, (h, u) in enumerate(zip(heads, marks, strict=True))
    ]
    lines: list[str] = []
    for block in _blocks(widths, width):
        if lines:
            lines.append("")
        lines.append("  ".join(rjust(heads[i], widths[i]) for i in block))
        lines.append("  ".join(marks[i].rjust(widths[i]) for i in block))
        lines += ["  ".join(r[i].rjust(widths[i]) for i in block) for r in cells]
    if rows > limit:
        more = counted(rows - limit, "more row")
        lines.append(f"... {more}: --csv PATH or --json for all")
    return "\n".join(lines)
