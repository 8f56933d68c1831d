r"""Where a long display equation of the note is broken into rows, for HTML.

MathML Core breaks no line: an equation wider than the page's column was cut on
paper and hidden behind a scroll bar on screen. A long chain ``a = b = c`` is set as
a student writes it, one step a row, each row after the first starting with its
``=``; a ``\quad`` between two statements starts a row too. A step still too wide
(a sum of many moments) is broken before a ``+`` or a ``-`` between its terms.
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable

from assur.explain._mathml import TOKEN, mathml

__all__ = ["WIDEST", "broken", "pieces", "rows", "terms"]

WIDEST = 72
"""Most characters a row holds. An A4 column is 655 px; printed at 0.9 em of 16 px
type a note's equations take 6.7 px a character shown (the median of 458 of them),
8.9 px at most: 72 fit in the column."""
QUADS = ("\\quad", "\\qquad")
"""Spaces that separate two statements on one line."""
OPENING = frozenset(("{", "\\left", "(", "["))
CLOSING = frozenset(("}", "\\right", ")", "]"))
SIGNED_AFTER = frozenset(("=", "(", "[", "{", ",", "+", "-", "\\cdot", "\\times"))
"""Tokens after which a ``+`` or a ``-`` is a sign, not one between two terms."""


def pieces(tex: str) -> list[str]:
    r"""Split ``tex`` before each ``=`` and ``\quad`` outside braces and fences.

    A statement after a ``\quad`` keeps its first ``=``: a row never ends with the
    name an equation is of. Joined, the pieces are ``tex``.

    Examples
    --------
    >>> pieces(r"a = \frac{b}{c=d} = 2,\quad e = \left(f = g\right) = 3")
    ['a ', '= \\frac{b}{c=d} ', '= 2,', '\\quad e = \\left(f = g\\right) ', '= 3']
    """
    out: list[str] = []
    start = depth = 0
    at = 0
    for token in TOKEN.findall(tex):
        if token in ("{", "\\left"):
            depth += 1
        elif token in ("}", "\\right"):
            depth -= 1
        elif depth == 0 and at > start and (token == "=" or token in QUADS):
            named = (
                tex[start:at].lstrip().startswith(QUADS) and "=" not in tex[start:at]
            )
            if token in QUADS or not named:
                out.append(tex[start:at])
                start = at
        at += len(token)
    out.append(tex[start:])
    return out


def terms(tex: str) -> list[str]:
    r"""Split ``tex`` before each ``+`` and ``-`` between two terms, outside brackets.

    Joined, the pieces are ``tex``.

    Examples
    --------
    >>> terms(r"M = [a \cdot (-b) - c] + [-d] - e")
    ['M = [a \\cdot (-b) - c] ', '+ [-d] ', '- e']
    """
    out: list[str] = []
    start = depth = at = 0
    before = ""
    for token in TOKEN.findall(tex):
        if token in OPENING:
            depth += 1
        elif token in CLOSING:
            depth -= 1
        elif (
            depth == 0 and token in ("+", "-") and before and before not in SIGNED_AFTER
        ):
            out.append(tex[start:at])
            start = at
        if not token.isspace():
            before = token
        at += len(token)
    out.append(tex[start:])
    return out


def rows(tex: str, width: Callable[[str], int]) -> list[str]:
    r"""Return the rows ``tex`` is set in: its pieces, as many to a row as fit.

    ``width`` gives the characters a piece of TeX shows; a row holds at most
    :data:`WIDEST` of them. Steps (:func:`pieces`) are packed first; a row still
    wider is packed again from its terms (:func:`terms`).
    """
    out: list[str] = []
    for row in _packed(pieces(tex), width):
        out += _packed(terms(row), width) if width(row) > WIDEST else [row]
    return out


def broken(tex: str) -> list[str]:
    """Return the rows of a display equation, its width that of its MathML text."""
    return rows(tex, lambda piece: shown_width(mathml(piece)))


def _packed(parts: list[str], width: Callable[[str], int]) -> list[str]:
    r"""Return ``parts`` joined into rows of at most :data:`WIDEST` characters shown.

    A part wider than that is a row alone. A ``\quad`` that starts a row is
    dropped: the row's start sets the statements apart.
    """
    out: list[str] = []
    shown = 0
    for piece in parts:
        size = width(piece)
        if out and shown + size <= WIDEST:
            out[-1] += piece
            shown += size
            continue
        if out:
            piece = _unquaded(piece)
        out.append(piece)
        shown = width(piece)
    # a row's end keeps its spaces: "0.2\ " ends in TeX's control space
    return [row.lstrip() for row in out]


def _unquaded(piece: str) -> str:
    r"""Return ``piece`` without the ``\quad`` it starts with."""
    for quad in sorted(QUADS, key=len, reverse=True):
        if piece.startswith(quad):
            return piece[len(quad) :]
    return piece


def shown_width(mathml: str) -> int:
    """Return the characters a MathML element shows: its text, entities read."""
    return len(html.unescape(re.sub(r"<[^>]+>", "", mathml)))
