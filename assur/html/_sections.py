"""The parts of the report written in HTML by Python, readable without JavaScript.

The summary line under the title, the group legend, the structure section and the
table of values; every name and number from the model is escaped here.
"""

from __future__ import annotations

import math
from html import escape
from typing import Any

import numpy as np

from assur._digits import ROUND_OFF, by_unit, settled
from assur._position_titles import row_position
from assur._structure import Structure
from assur._structure_display import GROUP_HEADINGS as NOTEBOOK_GROUP_HEADINGS
from assur._structure_display import group_cells
from assur._text import roman
from assur._troubles import skipped_why
from assur.analysis import Table
from assur.columns import pretty_unit
from assur.html._series import table_columns
from assur.plan import Plan

LONG_TABLE = 60
"""Tables with more rows than this show every 10th row."""
GROUP_HEADINGS = (
    '<span class="unseen">Colour in the drawing</span>',
    *NOTEBOOK_GROUP_HEADINGS,
)
"""Column headings of the table of groups (HTML); the first column holds the colour,
its heading read by a screen reader alone, the others a notebook's too."""
GROUPS_CAPTION = "Assur groups in the order they are solved, each named by its step"
"""What the table of groups holds, said to a screen reader (its card says Structure)."""
SUMMARY_TITLE = "Summary over the sweep"
"""The summary's heading, and its table's caption."""


def caption(text: str) -> str:
    """Return a table's caption, read by a screen reader and not shown.

    ``text`` is plain text; the card's heading above the table says it to the eye.
    """
    return f'<caption class="unseen">{escape(text)}</caption>'


def columns_row(headings: list[str]) -> str:
    """Return a table's head: a row of column headings (each HTML)."""
    cells = "".join(f'<th scope="col">{h}</th>' for h in headings)
    return f"<thead><tr>{cells}</tr></thead>"


def table_title(table: Table) -> str:
    """Return the heading of the table of values over the sweep, and its caption."""
    return (
        "Reactions and balancing load"
        if table.force_state is not None
        else "Kinematics"
    )


def wide_card(ident: str, title: str, body: str) -> str:
    """Return a full-width card of the page: its id, heading and body (both HTML)."""
    head = f'<section class="card wide" id="{ident}">'
    return f"{head}\n<h2>{title}</h2>\n{body}\n</section>"


def first_position(table: Table) -> str:
    """Return the table's first driver position as HTML text, with its unit."""
    return escape(row_position(table, 0))


def number(v: float, scale: float | None = None) -> str:
    """Format a value; below ``ROUND_OFF * scale`` it is round-off and shows as 0.

    Without a scale (a datum, or a result cleaned of its round-off already) only
    zero shows as 0: a small mechanism's values are its own, however small.
    """
    if not math.isfinite(v):
        return "–"
    if v == 0.0 or (scale is not None and abs(v) < ROUND_OFF * scale):
        return "0"
    return f"{settled(v):.5g}"  # a decimal tie rounds alike on every machine


def meta_html(struct: Structure, table: Table, data: dict[str, Any]) -> str:
    """Return the summary under the title: mobility, class, sweep and analysis."""
    driver = data["driver"]
    angle = np.asarray(table["angle"])
    parts = [
        f"W = {struct.dof}",
        f"class {roman(struct.mechanism_class)} mechanism",
        f"{len(table)} position{'s' if len(table) != 1 else ''}, "
        f"{driver['label']} {number(angle[0])} to "
        f"{number(angle[-1])} {driver['unit']}",
        "force analysis" if data["forces"] else "kinematics only (no masses or loads)",
    ]
    if table.skipped.size:
        total = len(table) + table.skipped.shape[0]
        parts.append(
            f"{table.skipped.shape[0]} of {total} positions left out "
            f"({skipped_why(table.plan, table.skipped)})"
        )
    return " · ".join(escape(p) for p in parts)


def legend_html(data: dict[str, Any]) -> str:
    """Return the legend of the drawing: one coloured entry per group."""
    items = []
    for g in data["groups"]:
        what = "driver" if g["class"] == 1 else f"order {g['order']} · {g['kind']}"
        text = f"{g['roman']} · {what} · {', '.join(g['links'])}"
        swatch = f'<span class="swatch" style="background:{g["colour"]}"></span>'
        items.append(f"<li>{swatch}{escape(text)}</li>")
    return '<ul class="legend">' + "".join(items) + "</ul>"


def structure_html(struct: Structure, data: dict[str, Any]) -> str:
    """Return the structure section: formula, table of groups and teaching report."""
    rows = []
    # the cells a notebook's display shows too (one spelling of the groups)
    for cells, info in zip(group_cells(struct), data["groups"], strict=True):
        swatch = f'<span class="swatch" style="background:{info["colour"]}"></span>'
        # the step names the group's row, its colour before it
        rows.append(
            f'<tr><td>{swatch}</td><th scope="row">{escape(cells[0])}</th>'
            + "".join(f"<td>{escape(c)}</td>" for c in cells[1:])
            + "</tr>"
        )
    head = columns_row(list(GROUP_HEADINGS))
    formula = escape(struct.formula.replace(" -> ", " → "))
    return (
        f'<p class="formula">{formula}</p>\n'
        f'<div class="scroll"><table class="groups">{caption(GROUPS_CAPTION)}'
        f"{head}\n<tbody>"
        + "\n".join(rows)
        + "</tbody></table></div>\n"
        + _report_html(str(struct))
    )


def _report_html(text: str) -> str:
    """Return the teaching report as HTML, one block per line.

    A line that wraps goes on indented under its start.
    """
    lines = []
    for line in text.splitlines():
        indent = len(line) - len(line.lstrip(" "))
        body = escape(line.strip()) or "&nbsp;"
        lines.append(
            f'<div style="padding-left:{indent + 4}ch;text-indent:-4ch">{body}</div>'
        )
    return '<div class="report">' + "\n".join(lines) + "</div>"


def summary_html(table: Table) -> str:
    """Return the summary section of a forces table (empty for kinematics).

    The few numbers joints and motors are sized on
    (:meth:`assur.Table.summary <assur.analysis.Table.summary>`), one row each with
    its unit.
    """
    if table.force_state is None or len(table) == 0:
        return ""
    from assur._summary_notes import notes, turning
    from assur.summary import Summary

    summary = Summary()
    summary.add(table)
    found, units = summary.result(), summary.units
    # a mean torque of 1e-16 N m beside peaks of 0.2 (a turn of a mechanism that
    # does no net work) is round-off
    sizes = by_unit([units[key] for key in found], list(found.values()))
    rows = "\n".join(
        f'<tr data-key="{escape(key)}"><th scope="row">{escape(key)}</th>'
        f"<td>{number(value, size)}</td>"
        f"<td>{escape(pretty_unit(units[key]))}</td></tr>"
        for (key, value), size in zip(found.items(), sizes, strict=True)
    )
    # as the command line's summary says it: which sign drives a clockwise crank
    said = [" ".join(turning(summary)), *notes(summary)]
    told = "".join(
        f'<p class="note">{escape(s[:1].upper() + s[1:])}.</p>\n' for s in said if s
    )
    return wide_card(
        "summary",
        SUMMARY_TITLE,
        '<p class="note">Largest and RMS reaction in every joint and where the '
        "largest occurs, a sliding pair's largest couple, the balancing load's "
        "extremes, mean and RMS, the drivers' mean, largest and smallest power, the "
        "largest shaking force and moment (about the origin of the file's "
        "coordinates) and where; means over the positions shown, or over time as "
        "said below.</p>\n"
        f"{told}"
        '<div class="table-wrap"><table class="values summary">'
        f"{caption(SUMMARY_TITLE)}<tbody>\n"
        f"{rows}\n</tbody></table></div>",
    )


def table_html(plan: Plan, table: Table) -> str:
    """Return the table of values over the sweep, every 10th row of a long one.

    Each row carries ``data-row``, its index in the sweep, for the script to
    highlight the position shown; each heading ``data-key``, its column.
    """
    columns = table_columns(plan, table)
    step = 10 if len(table) > LONG_TABLE else 1
    values = [np.asarray(table[key]) for key, _ in columns]
    sizes = by_unit([table.column(key).unit for key, _ in columns], values)
    head = "".join(
        f'<th scope="col" data-key="{escape(key)}">{escape(title)}</th>'
        for key, title in columns
    )
    # the drivers' positions name the row: with several drivers, one alone repeats
    named = len(plan.drivers)
    rows = []
    for i in range(0, len(table), step):
        texts = [
            number(float(v[i]), size) for v, size in zip(values, sizes, strict=True)
        ]
        rows.append(
            f'<tr data-row="{i}">'
            + "".join(f'<th scope="row">{t}</th>' for t in texts[:named])
            + "".join(f"<td>{t}</td>" for t in texts[named:])
            + "</tr>"
        )
    note = (
        f"Every {step}th of {len(table)} positions."
        if step > 1
        else f"All {len(table)} positions."
    )
    return (
        f'<p class="note">{note} The highlighted row is the position shown in the '
        'drawing.</p>\n<div class="table-wrap"><table class="values" id="values">'
        f"{caption(table_title(table))}<thead><tr>{head}</tr></thead>\n<tbody>"
        + "\n".join(rows)
        + "</tbody></table></div>"
    )
