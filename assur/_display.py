"""HTML pieces of the results' rich display in a notebook (``_repr_html_``).

Plain text in, escaped HTML out: every name and number given here is escaped, so
that a mechanism named ``<script>`` shows as its name. The standard library only:
``import assur`` loads none of this until a notebook asks for a display.
"""

from __future__ import annotations

from collections.abc import Sequence
from html import escape

__all__ = ["STYLE", "figures_html", "note_html"]

STYLE = "border-collapse:collapse;font-variant-numeric:tabular-nums"
"""The tables' own style: notebooks (Jupyter, VS Code) give the rest."""


def figures_html(caption: str, rows: Sequence[tuple[str, str]]) -> str:
    """Return a table of figures, one ``(label, value)`` row each, under ``caption``.

    A row with an empty label goes on from the one above it (as the command line's
    aligned lines do).
    """
    cells = "".join(
        f'<tr><th scope="row" style="text-align:left">{escape(label)}</th>'
        f'<td style="text-align:left">{escape(value)}</td></tr>'
        for label, value in rows
    )
    return (
        f'<table class="assur-figures" style="{STYLE}">'
        f"<caption>{escape(caption)}</caption><tbody>{cells}</tbody></table>"
    )


def note_html(text: str) -> str:
    """Return a line of plain ``text`` under a table, small."""
    return f"<p><small>{escape(text)}</small></p>"
