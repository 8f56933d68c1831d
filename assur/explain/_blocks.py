r"""The blocks of a note: headings, paragraphs, equations, tables and lists.

Text holds inline mathematics between dollar signs (``$\omega_1 = 200$``); a
:class:`Display` holds equations, one per line, in the TeX subset of
:mod:`assur.explain._mathml`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Block", "Display", "Grid", "Heading", "Items", "Para", "segments"]


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
    """A table: a heading row and rows of cells (text with inline mathematics).

    Each row is named by its first cell. ``caption`` says what the table holds, in
    words a screen reader reads before it (the HTML's hidden ``<caption>``; the
    paragraph before the table says it to the eye, and Markdown has no caption).
    """

    head: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    caption: str


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
