"""The note: a sequence of headings, paragraphs, equations, tables and lists.

Text holds inline mathematics between dollar signs (``$\\omega_1 = 200$``); a
:class:`Display` holds equations, one per line, in the TeX subset of
:mod:`assur.explain._mathml`. The same blocks are written as Markdown (``str()``),
as a self-contained HTML page with MathML or as a LaTeX report.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from typing import Any

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


@dataclass(frozen=True, slots=True)
class Heading:
    """A heading of ``level`` 1 (the title) to 4."""

    level: int
    text: str


@dataclass(frozen=True, slots=True)
class Para:
    """A paragraph; mathematics inline between dollar signs."""

    text: str


@dataclass(frozen=True, slots=True)
class Display:
    """Equations set apart, one per line (TeX)."""

    lines: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Grid:
    """A table: a heading row and rows of cells (text with inline mathematics)."""

    head: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True, slots=True)
class Items:
    """A list of short items (text with inline mathematics)."""

    items: tuple[str, ...]


Block = Heading | Para | Display | Grid | Items

DOLLAR = re.compile(r"(?<!\\)\$")


def segments(text: str) -> list[tuple[bool, str]]:
    """Split text into ``(is_math, part)``, mathematics between dollar signs.

    Examples
    --------
    >>> segments("so $x = 1$ m")
    [(False, 'so '), (True, 'x = 1'), (False, ' m')]
    """
    parts = DOLLAR.split(text)
    return [
        (i % 2 == 1, part.replace(r"\$", "$") if i % 2 == 0 else part)
        for i, part in enumerate(parts)
        if part
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
        Results the note prints, by table column name (for readers and checks).
    """

    title: str
    blocks: tuple[Block, ...]
    values: dict[str, float]

    def __str__(self) -> str:
        return self.to_markdown()

    def to_markdown(self) -> str:
        """Return the note as Markdown with TeX mathematics."""
        from assur.explain._markdown import markdown

        return markdown(self)

    def to_html(self) -> str:
        """Return the note as one self-contained HTML page (MathML equations)."""
        from assur.explain._html import html_page

        return html_page(self)

    def to_latex(self) -> str:
        """Return the note as a LaTeX document that compiles with pdflatex."""
        from assur.explain._latex import latex_document

        return latex_document(self)

    def write(self, path: str | os.PathLike[str]) -> None:
        """Write the note to ``path``: Markdown, HTML or LaTeX by its suffix.

        The file is written whole or not at all.

        Raises
        ------
        OutputError
            When the file cannot be written.
        ValueError
            When the suffix is not .md, .html, .htm or .tex.
        """
        from assur._output import write_text

        write_text(path, self.render(os.fspath(path)))

    def render(self, path: str) -> str:
        """Return the text of the note in the format that ``path``'s suffix names."""
        suffix = os.path.splitext(path)[1].lower()
        makers: dict[str, Any] = {
            ".md": self.to_markdown,
            ".markdown": self.to_markdown,
            ".html": self.to_html,
            ".htm": self.to_html,
            ".tex": self.to_latex,
        }
        if suffix not in makers:
            msg = (
                f"{path}: unknown type of note {suffix or '(none)'!r}; expected .md, "
                ".html or .tex"
            )
            raise ValueError(msg)
        return str(makers[suffix]())
