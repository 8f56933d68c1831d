"""Assembly of the report page from its template, its sections and its data.

The template ``page.html``, the style sheet ``report.css`` and the script
``report.js`` are data files of this package, read when a page is rendered and
inlined, so that the page stays one file that opens offline.
"""

from __future__ import annotations

from collections.abc import Callable
from html import escape
from importlib.resources import files
from string import Template
from typing import Any

from assur._structure import Structure
from assur._style import REACTION_COLOUR
from assur.analysis import Table
from assur.html._data import to_json
from assur.html._free_bodies import free_bodies_html
from assur.html._inertia import inertia_html
from assur.html._sections import (
    first_position,
    legend_html,
    meta_html,
    structure_html,
    summary_html,
    table_html,
    table_title,
    wide_card,
)
from assur.plan import Plan

DRAWING_WIDTH = 556
"""Width (px) of the drawing inside its margins."""


def assemble_page(
    plan: Plan,
    struct: Structure,
    table: Table,
    data: dict[str, Any],
    dynamics: str = "",
    told: Callable[[], None] = lambda: None,
) -> str:
    """Return the whole page: the template filled with sections, data and assets.

    ``dynamics`` is the HTML of the dynamics section, or empty. ``told()`` is
    called when the note is made, and when the free-body diagrams are.
    """
    note = note_html(plan, table)
    told()
    bodies = free_bodies_html(table)
    told()
    mech = plan.mechanism
    description = (
        f'<p class="description">{escape(mech.description)}</p>'
        if mech.description
        else ""
    )
    forced = data["forces"] is not None
    fields = {
        "title": escape(mech.name or "Mechanism"),
        "description": description,
        "meta": meta_html(struct, table, data),
        "drawing_height": drawing_height(data["bounds"]),
        "last_row": len(table) - 1,
        "legend": legend_html(data),
        "force_note": '<p class="note" id="force-note"></p>' if forced else "",
        "structure": structure_html(struct, data),
        "dynamics": dynamics,
        "table_title": table_title(table),
        "table": table_html(plan, table),
        "note": note,
        "inertia": inertia_html(table),
        "free_bodies": bodies,
        "summary": summary_html(table),
        "data": to_json(data),
        "reaction_colour": REACTION_COLOUR,
        "css": _asset("report.css"),
        "script": _asset("report.js"),
    }
    return Template(_asset("page.html")).substitute(fields)


def note_html(plan: Plan, table: Table) -> str:
    """Return the note of the first position: the analysis written out (MathML).

    The first row of the sweep is the driver position the note explains.
    """
    from assur.explain import explain
    from assur.explain._html import html_body

    if len(table) == 0:
        return ""
    given = table.given[0]
    note = explain(plan.mechanism, given if given.shape[0] > 1 else float(given[0]))
    return wide_card(
        "note",
        f"The analysis at the first position ({first_position(table)}), step by step",
        html_body(note, below=2),
    )


def drawing_height(bounds: list[float]) -> int:
    """Return the height (px) of the 640 px wide drawing that fits the box (m)."""
    ratio = (bounds[3] - bounds[2]) / (bounds[1] - bounds[0])
    return int(min(max(round(DRAWING_WIDTH * ratio) + 90, 260), 560))


def _asset(name: str) -> str:
    """Return the text of the package data file ``name``."""
    return files("assur.html").joinpath(name).read_text(encoding="utf-8")
