"""The width of text on a terminal, for the tables and lists printed there.

A name may be written in any script: a CJK character takes two columns of a
terminal, a combining accent or a zero-width character none, so aligning by
``len`` shifted every column after such a name.
"""

from __future__ import annotations

import unicodedata

__all__ = ["ljust", "rjust", "shown_width"]

_NONE = frozenset({"Mn", "Me", "Cf"})
"""Categories that take no column: combining marks and format characters (U+200B)."""


def shown_width(text: str) -> int:
    """Return the number of terminal columns ``text`` takes.

    East Asian wide and full-width characters take two columns, combining marks
    and format characters none, every other character one (as ``wcwidth`` counts
    them, without the table of a particular terminal).

    Examples
    --------
    >>> shown_width("rod"), shown_width("滑块"), shown_width("e\u0301")
    (3, 4, 1)
    """
    return sum(_columns(c) for c in text)


def _columns(char: str) -> int:
    """Return the terminal columns of one character."""
    if unicodedata.category(char) in _NONE:
        return 0
    return 2 if unicodedata.east_asian_width(char) in ("W", "F") else 1


def rjust(text: str, width: int) -> str:
    """Return ``text`` right-aligned in ``width`` terminal columns."""
    return " " * max(0, width - shown_width(text)) + text


def ljust(text: str, width: int) -> str:
    """Return ``text`` left-aligned in ``width`` terminal columns."""
    return text + " " * max(0, width - shown_width(text))
