"""The note as one self-contained HTML page: MathML equations, inline style.

No script and no address of any kind: the page opens offline and its equations are
rendered by the browser itself (MathML Core).
"""

from __future__ import annotations

from html import escape
from typing import TYPE_CHECKING

from assur.explain._blocks import Display, Grid, Heading, Items, Para, segments
from assur.explain._breaks import broken
from assur.explain._mathml import mathml

if TYPE_CHECKING:
    from assur.explain._blocks import Block
    from assur.explain._note import Note

__all__ = ["html_body", "html_page"]

INDENT = '<mspace width="2em"/>'
"""Set before each row of a broken equation after the first (its ``=`` leads)."""
STYLE = """
body { font: 16px/1.5 system-ui, sans-serif; max-width: 60rem; margin: 2rem auto;
  padding: 0 1rem; color: #1f2937; }
h1 { font-size: 1.6rem; } h2 { margin-top: 2rem; border-bottom: 1px solid #d1d5db; }
math { font-family: "STIX Two Math", "Latin Modern Math", "Cambria Math", math; }
math[display="block"] { margin: 0.4rem 0; padding-block: 0.25em; overflow-x: auto;
  overflow-y: hidden; text-align: left; }
.note-eq { margin: 0.6rem 0 0.6rem 1rem; }
.note-eq mtd { text-align: left; padding-inline: 0; }
table { border-collapse: collapse; margin: 0.6rem 0; }
td, th { border: 1px solid #d1d5db; padding: 0.2rem 0.5rem; text-align: left; }
/* a row's name is its heading for a screen reader, set as the cells beside it */
th[scope="row"] { font-weight: normal; }
/* read by a screen reader, not shown: a table's caption, the text before it says it */
.unseen { position: absolute; width: 1px; height: 1px; overflow: hidden;
  clip: rect(0 0 0 0); clip-path: inset(50%); white-space: nowrap; }
/* a caption set apart (Chromium) opened a pixel between the table's head and body:
   in flow, its pixel taken back */
caption.unseen { position: static; margin-bottom: -1px; }
/* a table wider than the screen scrolls in its box, a table still */
.grid { max-width: 100%; overflow-x: auto; }
/* on paper a heading stays with what follows it, a table row and an equation whole */
@media print { math[display="block"] { overflow: visible; font-size: 0.9em; }
  .grid { overflow: visible; }
  h1, h2, h3, h4, h5, h6 { break-after: avoid; }
  tr, math[display="block"] { break-inside: avoid; } }
"""


def math(tex: str, display: bool = False) -> str:
    """Return ``tex`` as MathML with its TeX as the element's alternative text.

    A screen reader that does not read MathML reads the TeX, and so does one who
    copies an equation.
    """
    return mathml(tex, display).replace(">", f" {_alt(tex)}>", 1)


def _alt(tex: str) -> str:
    """Return the ``alttext`` attribute of an equation: its TeX on one line."""
    return f'alttext="{escape(" ".join(tex.split()), quote=True)}"'


def display(tex: str) -> str:
    """Return a display equation as block MathML, a long one in rows.

    A chain too wide for a printed column is set one step a row
    (:mod:`assur.explain._breaks`), the rows after the first indented; the whole
    equation's TeX stays its alternative text.
    """
    parts = broken(tex)
    if len(parts) == 1:
        return math(tex, display=True)
    cells = "".join(
        f"<mtr><mtd>{INDENT if k else ''}"
        f"{mathml(row).removeprefix('<math>').removesuffix('</math>')}</mtd></mtr>"
        for k, row in enumerate(parts)
    )
    return f'<math display="block" {_alt(tex)}><mtable>{cells}</mtable></math>'


def inline(text: str) -> str:
    """Return text with its inline mathematics as MathML, the rest escaped."""
    return "".join(
        math(part) if is_math else escape(part) for is_math, part in segments(text)
    )


def _table(grid: Grid) -> str:
    """Return a table: its caption for a screen reader, rows named by a first cell."""
    head = "".join(f'<th scope="col">{inline(c)}</th>' for c in grid.head)
    rows = "".join(
        f'<tr><th scope="row">{inline(row[0])}</th>'
        + "".join(f"<td>{inline(c)}</td>" for c in row[1:])
        + "</tr>"
        for row in grid.rows
    )
    return (
        f'<table><caption class="unseen">{inline(grid.caption)}</caption>'
        f"<thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>"
    )


def _block(block: Block, deeper: int = 0) -> str:
    """Return one block as HTML, its heading ``deeper`` levels down."""
    if isinstance(block, Heading):
        level = min(block.level + deeper, 6)
        return f"<h{level}>{inline(block.text)}</h{level}>"
    if isinstance(block, Para):
        return f"<p>{inline(block.text)}</p>"
    if isinstance(block, Display):
        lines = "\n".join(display(line) for line in block.lines)
        return f'<div class="note-eq">\n{lines}\n</div>'
    if isinstance(block, Grid):
        return f'<div class="grid">{_table(block)}</div>'
    assert isinstance(block, Items)
    return "<ul>" + "".join(f"<li>{inline(x)}</li>" for x in block.items) + "</ul>"


def html_body(note: Note, below: int = 1) -> str:
    """Return the note's blocks as HTML (no page around them).

    ``below`` is the level of the heading the note sits under: its own headings
    go one level further down (the report's card is an h2: the note's "1.
    Structure" an h3 under it).
    """
    return "\n".join(_block(b, below - 1) for b in note.blocks)


def html_page(note: Note) -> str:
    """Return the note as a whole page."""
    from html import escape

    title = inline(note.title)
    # the title is Markdown, a name's dollar sign escaped: the tab shows it bare
    bare = escape(note.title.replace("\\$", "$"))
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        # a phone lays the page out at its own width, not at a desktop's 980 pixels
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        f"<title>{bare}</title>\n<style>{STYLE}</style>\n</head>\n"
        f'<body>\n<article class="note">\n<h1>{title}</h1>\n{html_body(note)}\n'
        "</article>\n</body>\n</html>\n"
    )
