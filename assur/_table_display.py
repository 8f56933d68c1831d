"""A table of results as a notebook shows it: a compact HTML table (``_repr_html_``).

Its first and last rows, its first and last columns with their units, the numbers
as the command line's readable table prints them (:func:`assur._text.number_text`,
round-off shown as 0). Only the columns shown are read: a long table's other
columns are not computed for a look at it, so round-off is told against the
largest of its unit among the columns shown. Where those of a unit are round-off
alone (a balanced scotch yoke's ``shaking.M`` and ``residual.moment``), their
digits show, which the command line's table beside the driver's torque writes as 0.
A table of up to :data:`WHOLE` rows reads every column of the units it shows, to
tell round-off among them all.
"""

from __future__ import annotations

from html import escape
from typing import Any

import numpy as np

from assur._digits import by_unit, cleaned, largest
from assur._display import STYLE, note_html
from assur._text import counted, number_text
from assur._troubles import skipped_why
from assur._vec import Array
from assur.columns import pretty_unit

__all__ = ["HEAD_COLUMNS", "HEAD_ROWS", "TAIL_COLUMNS", "TAIL_ROWS", "table_html"]

HEAD_ROWS = 5
"""Rows shown at the top of a longer table."""
TAIL_ROWS = 5
"""Rows shown at its bottom, after a row of "…"."""
HEAD_COLUMNS = 8
"""Columns shown on the left of a wider table."""
TAIL_COLUMNS = 4
"""Columns shown on its right, after a column of "…"."""
MORE = "…"
"""What stands for the rows or columns left out."""
WHOLE = 2048
"""Rows up to which round-off is told among every column of a unit shown: reading
them costs about what the display does, where a long table's would be a sweep."""


def cut(count: int, head: int, tail: int) -> tuple[list[int], list[int]]:
    """Return the indices shown of ``count``: the ``head`` first and ``tail`` last.

    All in the first list when they are no more than ``head + tail``; the second is
    then empty (nothing is left out between them).

    Examples
    --------
    >>> cut(3, 2, 1), cut(5, 2, 1)
    (([0, 1, 2], []), ([0, 1], [4]))
    """
    if count <= head + tail:
        return list(range(count)), []
    return list(range(head)), list(range(count - tail, count))


def read(table: Any, names: list[str]) -> list[Array]:
    """Return the columns ``names`` of ``table``, computing those only.

    A sweep's table computes a column that needs the links' motions rebuilt along
    with its neighbours (every point's); here the missing ones are computed together
    and alone (``Table._compute``), and kept as reading them by name keeps them.
    """
    compute = getattr(table, "_compute", None)
    cache = getattr(table, "_cache", None)
    if compute is not None and cache is not None:
        missing = [table.column(name) for name in names if name not in cache]
        if missing:
            compute(missing)
    return [np.asarray(table[name]) for name in names]


def table_html(table: Any, kind: str) -> str:
    """Return ``table`` as a compact HTML table: a caption, headings, some rows.

    Parameters
    ----------
    table : Table
        A table of results (:class:`~assur.analysis.Table`, or the dynamic model's).
    kind : str
        What it holds, in the caption: ``"forces"``, ``"kinematics"``, ...
    """
    names = list(table.columns)
    rows = len(table)
    left, right = cut(len(names), HEAD_COLUMNS, TAIL_COLUMNS)
    top, bottom = cut(rows, HEAD_ROWS, TAIL_ROWS)
    picked = [names[i] for i in (*left, *right)]
    units = [table.column(name).unit for name in picked]
    at = np.array([*top, *bottom], dtype=np.intp)
    # round-off against the largest value of its unit in the whole columns, as the
    # command line's readable table tells it among all its rows
    columns = read(table, picked)
    scales = by_unit(units, columns)
    if rows <= WHOLE:
        # the residuals are round-off beside the driver's torque left out
        kept = [n for n in names if n not in picked and table.column(n).unit in units]
        most = dict(zip(units, scales, strict=True))
        for name, column in zip(kept, read(table, kept), strict=True):
            unit = table.column(name).unit
            most[unit] = max(most[unit], largest(column))
        scales = [most[unit] for unit in units]
    values = cleaned(units, [column[at] for column in columns], scales)
    texts = [[number_text(v) for v in column.tolist()] for column in values]
    gap = len(left) if right else None  # where the column of "…" goes

    def line(cells: list[str], head: str, tag: str) -> str:
        # a screen reader names each value by its column and its row's number
        col, row = '<th scope="col">', '<th scope="row">'
        opening, first = (col, "<th>") if tag == "th" else ("<td>", row)
        cells = [f"{opening}{escape(c)}</{tag}>" for c in cells]
        if gap is not None:
            cells.insert(gap, f"{opening}{MORE}</{tag}>")
        return f"<tr>{first}{escape(head)}</th>{''.join(cells)}</tr>"

    heads = [line(picked, "", "th")]
    heads.append(line([pretty_unit(u) for u in units], "", "th"))
    body = [line([t[k] for t in texts], str(row), "td") for k, row in enumerate(at)]
    if bottom:
        body.insert(len(top), line([MORE] * len(picked), MORE, "td"))
    name = table.mechanism.name or "mechanism"
    shape = f"{counted(rows, 'row')} × {counted(len(names), 'column')}"
    out = (
        f'<table class="assur-table" style="{STYLE}">'
        f"<caption>{escape(f'{kind} of {name!r}: {shape}')}</caption>"
        f"<thead>{''.join(heads)}</thead><tbody>{''.join(body)}</tbody></table>"
    )
    hidden = len(names) - len(picked)
    if hidden:
        out += note_html(
            f"{counted(hidden, 'column')} not shown: table[name] gives one, "
            "table.to_pandas() or table.arrays() all of them (table.columns "
            "names them)"
        )
    skipped = getattr(table, "skipped", None)
    if skipped is not None and skipped.size:
        # the rows are numbered among those kept: say which positions are not there
        out += note_html(
            f"{skipped.shape[0]} of {counted(rows + skipped.shape[0], 'position')} "
            f"left out ({skipped_why(table.plan, skipped)}): table.skipped gives them"
        )
    return out
