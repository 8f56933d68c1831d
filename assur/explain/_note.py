"""The note: its blocks, written as Markdown, HTML with MathML or LaTeX.

The same blocks (:mod:`assur.explain._blocks`) are written as Markdown (``str()``),
as a self-contained HTML page with MathML or as a LaTeX report.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any

from assur.errors import UsageError
from assur.explain._blocks import Block, Display, Grid, Heading, Items, Para, segments
from assur.explain._html import html_page
from assur.explain._latex import latex_document
from assur.explain._markdown import markdown

__all__ = [
    "Block",
    "Display",
    "Grid",
    "Heading",
    "Items",
    "Note",
    "Para",
    "segments",
]


@dataclass(frozen=True)
class Note:
    """The analysis at one driver position, written out step by step.

    ``str(note)`` is Markdown (mathematics in TeX between dollar signs);
    :meth:`to_html` a self-contained page whose equations are MathML and
    :meth:`to_latex` a LaTeX report.

    Attributes
    ----------
    title : str
        The note's title.
    blocks : tuple of Block
        Headings, paragraphs, equations, tables and lists in reading order.
    values : dict of str to float
        The analysis at the note's position, by table column name (the forces
        table's columns, NaN for the forces the reverse pass has not reached where
        friction locks a group; the kinematics table's for a mechanism with no
        loads).
    """

    title: str
    blocks: tuple[Block, ...]
    values: dict[str, float]

    def __str__(self) -> str:
        return self.to_markdown()

    def __repr__(self) -> str:
        # the blocks are the whole note (some 20 000 characters): counted, not shown
        return (
            f"Note({self.title!r}, {len(self.blocks)} blocks, "
            f"{len(self.values)} values)"
        )

    def to_markdown(self) -> str:
        """Return the note as Markdown with TeX mathematics."""
        return markdown(self)

    def to_html(self) -> str:
        """Return the note as one self-contained HTML page (MathML equations)."""
        return html_page(self)

    def to_latex(self) -> str:
        """Return the note as a LaTeX document that compiles with pdflatex.

        Names in Cyrillic, Greek or CJK letters are beyond its T1 fonts: an
        :class:`~assur.errors.AssurWarning` and the document's first line say so.
        """
        return latex_document(self)

    def write(self, path: str | os.PathLike[str]) -> None:
        """Write the note to ``path``: Markdown, HTML or LaTeX by its suffix.

        The file is written whole or not at all.

        Parameters
        ----------
        path : str or path-like
            The file to write (.md, .markdown, .html, .htm or .tex).

        Raises
        ------
        OutputError
            When the file cannot be written.
        UsageError
            When the suffix is not .md, .html, .htm or .tex.
        """
        from assur._output import write_text

        write_text(path, self.render(_named(path)))

    def render(self, path: str) -> str:
        """Return the text of the note in the format that ``path``'s suffix names.

        Parameters
        ----------
        path : str
            A file name; only its suffix is read.
        """
        suffix = os.path.splitext(_named(path))[1].lower()
        makers: dict[str, Any] = {
            ".md": self.to_markdown,
            ".markdown": self.to_markdown,
            ".html": self.to_html,
            ".htm": self.to_html,
            ".tex": self.to_latex,
        }
        if suffix not in makers:
            # render("docx") said "unknown type of note '(none)'"
            what = f"unknown type of note {suffix!r}" if suffix else "no suffix"
            msg = f"{path}: {what}; expected a name ending in .md, .html or .tex"
            raise UsageError(msg)
        return str(makers[suffix]())


def _named(path: Any) -> str:
    """Return ``path`` as a file name; a UsageError for what is none (None, 3)."""
    if not isinstance(path, str | os.PathLike):
        msg = (
            "path: expected a file name (.md, .html, .htm or .tex), got "
            f"{type(path).__name__}"
        )
        raise UsageError(msg)
    return os.fspath(path)  # type: ignore[return-value]
