"""A structural analysis as a notebook shows it (``Structure._repr_html_``).

The degrees of freedom counted, the structure formula, the table of the groups the
HTML report shows (:func:`group_cells`, shared with it) and, folded under them, the
whole teaching report (``str(structure)``).
"""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

from assur._display import STYLE
from assur._text import public_name, roman
from assur.model import GROUND
from assur.report import freedom_lines

if TYPE_CHECKING:
    from assur._structure import Structure

__all__ = ["GROUP_HEADINGS", "group_cells", "structure_html"]

GROUP_HEADINGS = (
    "Step",
    "Class",
    "Order",
    "Kind",
    "Links",
    "Internal pairs",
    "External pairs",
)
"""Column headings of the table of groups (plain text)."""


def group_cells(struct: Structure) -> list[list[str]]:
    """Return a row of plain-text cells per driver and group, in order of attachment.

    Under :data:`GROUP_HEADINGS`: the step, the class (a Roman numeral), the order
    ("—" for a driver: an input link is of no order), the kind ("input link" for a
    driver), the moving links and the pairs, named as the reader knows them ("B
    (block)").
    """
    rows = []
    for step, g in enumerate((*struct.drivers, *struct.groups), 1):
        rows.append(
            [
                str(step),
                roman(g.group_class),
                "—" if g.group_class == 1 else str(g.order),
                "input link" if g.group_class == 1 else g.kind,
                ", ".join(public_name(x) for x in g.links if x != GROUND),
                ", ".join(public_name(x) for x in g.internal),
                ", ".join(public_name(x) for x in g.external),
            ]
        )
    return rows


def structure_html(struct: Structure) -> str:
    """Return the structure as HTML: W, the formula, the groups, the report folded."""
    name = struct.name or "the mechanism"
    freedom = "<br>".join(escape(line.strip()) for line in freedom_lines(struct))
    formula = struct.formula.replace(" -> ", " → ")
    heads = "".join(f'<th scope="col">{h}</th>' for h in GROUP_HEADINGS)
    rows = "".join(
        f'<tr><th scope="row">{escape(cells[0])}</th>'
        + "".join(f"<td>{escape(c)}</td>" for c in cells[1:])
        + "</tr>"
        for cells in group_cells(struct)
    )
    return (
        f'<div class="assur-structure"><p><strong>Structure of {escape(name)}'
        f"</strong></p><p>{freedom}</p>"
        f'<p>Structure formula: <code class="formula">{escape(formula)}</code> '
        f"(class {roman(struct.mechanism_class)})</p>"
        f'<table class="assur-groups" style="{STYLE}">'
        "<caption>Assur groups in the order they are solved</caption>"
        f"<thead><tr>{heads}</tr></thead><tbody>{rows}</tbody></table>"
        "<details><summary>The teaching report</summary>"
        f"<pre>{escape(str(struct))}</pre></details></div>"
    )
