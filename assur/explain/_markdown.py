"""The note as Markdown: headings, paragraphs, TeX between dollar signs, tables."""

from __future__ import annotations

from typing import TYPE_CHECKING

from assur.explain._blocks import Display, Grid, Heading, Items, Para

if TYPE_CHECKING:
    from assur.explain._note import Note

__all__ = ["markdown"]


def markdown(note: Note) -> str:
    """Return ``note`` as Markdown; display equations as ``$$ ... $$`` lines."""
    out = [f"# {note.title}", ""]
    for block in note.blocks:
        if isinstance(block, Heading):
            out += [f"{'#' * block.level} {block.text}", ""]
        elif isinstance(block, Para):
            out += [block.text, ""]
        elif isinstance(block, Display):
            out += [f"$$ {line} $$" for line in block.lines] + [""]
        elif isinstance(block, Grid):
            out.append("| " + " | ".join(_cell(c) for c in block.head) + " |")
            out.append("|" + "---|" * len(block.head))
            out += [
                "| " + " | ".join(_cell(c) for c in row) + " |" for row in block.rows
            ]
            out.append("")
        elif isinstance(block, Items):
            out += [f"- {item}" for item in block.items] + [""]
    return "\n".join(out).rstrip("\n") + "\n"


def _cell(text: str) -> str:
    """Return a table cell: a bar would end it."""
    return text.replace("|", r"\vert ")
