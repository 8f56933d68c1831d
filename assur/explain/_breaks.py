r"""Where a long display equation of the note is broken into rows, for HTML.

MathML Core breaks no line: an equation wider than the page's column was cut on
paper and hidden behind a scroll bar on screen. A long chain ``a = b = c`` is set as
a student writes it, one step a row, each row after the first starting with its
``=``; a ``\quad`` between two statements starts a row too. A step still too wide
(a sum of many moments) is broken before a ``+`` or a ``-`` between its terms.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from typing import Any

from assur.explain._mathml import SIGN_AFTER, SYMBOLS, TOKEN, mathml

__all__ = ["WIDEST", "broken", "clauses", "first_equals", "pieces", "rows", "terms"]

WIDEST = 66
"""Most characters a row holds (as :func:`shown_width` counts them). An A4 column is
655 px; printed at 0.9 em of 16 px type, a note's equations take 7.4 px a character
(the median of 539 of them), 9.8 px at most: 66 fit in the column."""
QUADS = ("\\quad", "\\qquad")
"""Spaces that separate two statements on one line."""
LEADING = re.compile(r"^(?:\\q?quad|\\[ ,;]|\s)+")
"""The spaces a row after the first does without: its start sets it apart."""
WORDS = frozenset(("\\text",))
"""Commands whose braces hold words: a sign after them is a number's, as in MathML."""
WORDS_END = "\\text}"
"""What :func:`_split` takes the token before to be just after such braces."""
SIGNED_AFTER = frozenset(
    (
        "^",
        "_",
        "-",
        WORDS_END,
        *SIGN_AFTER,
        *(f"\\{n}" for n, s in SYMBOLS.items() if s in SIGN_AFTER),
    )
)
"""Tokens after which a ``+`` or a ``-`` is a sign, not one between two terms: those
the note's MathML sets a sign after (``=``, ``,``, ``\\cdot``, ``\\approx``, ...),
and a script's ``^`` or ``_``, which a row may not end with."""
BLANKS = frozenset(("\\ ", "\\,", "\\;", "\\:", "\\quad", "\\qquad"))
"""TeX's spaces, passed over as white space is in telling what a sign follows:
``(0.1,\\ -0.2)`` is a vector, not a difference."""


def pieces(tex: str) -> list[str]:
    r"""Split ``tex`` before each ``=`` and ``\quad`` outside braces and brackets.

    A statement after a ``\quad`` keeps its first ``=``: a row never ends with the
    name an equation is of. Joined, the pieces are ``tex``.

    Examples
    --------
    >>> pieces(r"a = \frac{b}{c=d} = 2,\quad e = \left(f = g\right) = 3")
    ['a ', '= \\frac{b}{c=d} ', '= 2,', '\\quad e = \\left(f = g\\right) ', '= 3']
    """

    def where(token: str, before: str, braces: int, brackets: int, piece: str) -> bool:
        if braces or brackets or not (token == "=" or token in QUADS):
            return False
        # a statement's first "=" stays with the name it follows
        named = piece.lstrip().startswith(QUADS) and "=" not in piece
        return token in QUADS or not named

    return _split(tex, where)


def first_equals(tex: str) -> int:
    r"""Return where the first ``=`` outside braces and brackets is in ``tex``, or -1.

    Examples
    --------
    >>> first_equals(r"\text{at } B \quad a_{x=1} = (b = c) = d")
    27
    """

    def where(token: str, before: str, braces: int, brackets: int, piece: str) -> bool:
        return token == "=" and not braces and not brackets

    first, *rest = _split(tex, where)
    return len(first) if rest else -1


def terms(tex: str, inside: int = 0) -> list[str]:
    r"""Split ``tex`` before each ``+`` and ``-`` between two terms.

    Only outside braces and ``\left``/``\right``, and within at most ``inside``
    brackets: ``inside=1`` breaks a sum in brackets (``-[a + b + c]``). Joined, the
    pieces are ``tex``.

    Examples
    --------
    >>> terms(r"M = [a \cdot (-b) - c] + [-d] - e")
    ['M = [a \\cdot (-b) - c] ', '+ [-d] ', '- e']
    >>> terms(r"= -[a + b \cdot (c - d)]", inside=1)
    ['= -[a ', '+ b \\cdot (c - d)]']
    """

    def where(token: str, before: str, braces: int, brackets: int, piece: str) -> bool:
        binary = before != "" and before not in SIGNED_AFTER
        return token in ("+", "-") and binary and not braces and brackets <= inside

    return _split(tex, where)


def clauses(tex: str) -> list[str]:
    r"""Split ``tex`` after each comma (and its spaces) and before each ``\text``.

    Only outside braces and brackets. The last resort for a row of words and
    formulas ("turned 90 deg, as 2 turns, a = ..."). Joined, the pieces are ``tex``.

    Examples
    --------
    >>> clauses(r"x,\ y = (1, 2) \text{ at } B")
    ['x,\\ ', 'y = (1, 2) ', '\\text{ at } B']
    """

    def where(token: str, before: str, braces: int, brackets: int, piece: str) -> bool:
        after_comma = before == "," and not _blank(token)
        return (after_comma or token == "\\text") and not braces and not brackets

    return _split(tex, where)


def _split(tex: str, where: Callable[[str, str, int, int, str], bool]) -> list[str]:
    """Split ``tex`` before each token ``where`` says is a place to break.

    ``where`` is given the token, the one before it (spaces, TeX's too, passed
    over), the numbers of braces and of brackets open there, and the piece so far.
    """
    out: list[str] = []
    start = braces = brackets = at = 0
    before = ""
    words: list[bool] = []  # for each brace open, whether it holds words (\text)
    for token in TOKEN.findall(tex):
        if token in ("{", "\\left"):
            braces += 1
            words.append(token == "{" and before in WORDS)
        elif token in ("}", "\\right"):
            braces -= 1
            if words and words.pop():
                # after words a minus is a sign, as the MathML sets it
                before = WORDS_END
                at += len(token)
                continue
        elif token in ("(", "[", ")", "]") and before in ("\\left", "\\right"):
            pass  # the fence of \left or \right, counted with it as a brace
        elif token in ("(", "[") and not braces:
            brackets += 1  # a bracket in braces (words, a script) is theirs alone
        elif token in (")", "]") and not braces:
            brackets -= 1
        elif at > start and where(token, before, braces, brackets, tex[start:at]):
            out.append(tex[start:at])
            start = at
        if not _blank(token):
            before = token
        at += len(token)
    out.append(tex[start:])
    return out


def _blank(token: str) -> bool:
    r"""Return whether ``token`` is a space: TeX's (``\ ``, ``\quad``) or white."""
    return token.isspace() or token in BLANKS


def rows(tex: str, width: Callable[[str], float]) -> list[str]:
    r"""Return the rows ``tex`` is set in: its pieces, as many to a row as fit.

    ``width`` gives the characters a piece of TeX shows; a row holds at most
    :data:`WIDEST` of them. Steps (:func:`pieces`) are packed first, the left side
    never alone on the first row; a row still wider is packed again from finer
    pieces (:data:`FINER`). An equation that ends a row so split goes on with the
    next step where that fits. The spaces a row after the first starts with
    (``\quad``, ``\ ``) are dropped: its start sets it apart.
    """
    steps = _packed(pieces(tex), width)
    if len(steps) > 1 and len(pieces(steps[0])) == 1 and steps[1].startswith("="):
        # "a_G" alone, then "= a_F + ...": the two go on one row, split finer
        steps[:2] = [steps[0] + steps[1]]
    out: list[str] = []
    split = False  # whether the last row is the end of a step split finer
    for step in steps:
        parts = _finer(step, width, FINER)
        # a whole step goes on from an equation that ends a split one, if it fits:
        # "... as link lever turns," / "a^k = 2|w| v_r = 2 * 5.95 * 0.144 = ..."
        whole = split and len(parts) == 1 and _equation(out[-1])
        if whole and width(out[-1] + step) <= WIDEST:
            out[-1] += step
            continue
        out += parts
        split = len(parts) > 1
    return [out[0].lstrip(), *(LEADING.sub("", row) for row in out[1:])]


def _equation(row: str) -> bool:
    """Whether ``row`` holds an ``=`` of its own: a step may follow it on its row."""
    return any(piece.lstrip().startswith("=") for piece in pieces(row))


FINER: tuple[Callable[[str], list[str]], ...] = (
    terms,
    lambda tex: terms(tex, inside=1),
    clauses,
)
"""How a row still too wide is split, in turn: its terms, the terms of a sum in
brackets, its clauses."""


def _finer(row: str, width: Callable[[str], float], ways: tuple[Any, ...]) -> list[str]:
    """Return ``row``, or its rows split the first of ``ways`` that makes it fit."""
    if width(row) <= WIDEST or not ways:
        return [row]
    parts = _packed(ways[0](row), width)
    return [part for p in parts for part in _finer(p, width, ways[1:])]


def broken(tex: str) -> list[str]:
    """Return the rows of a display equation, its width that of its MathML text."""
    return rows(tex, lambda piece: shown_width(mathml(piece)))


def _packed(parts: list[str], width: Callable[[str], float]) -> list[str]:
    r"""Return ``parts`` joined into rows of at most :data:`WIDEST` characters shown.

    A part wider than that is a row alone. Rows keep their spaces: a row's end may
    be TeX's control space ("0.2\ "), and its start is cut where it is set.
    """
    out: list[str] = []
    shown = 0.0
    for piece in parts:
        size = width(piece)
        if out and shown + size <= WIDEST:
            out[-1] += piece
            shown += size
        else:
            out.append(piece)
            shown = size
    return out


def shown_width(mathml: str) -> float:
    """Return the width a MathML element shows, in characters of its text's size.

    A script counts :data:`SCRIPT` of its characters, a fraction its wider part,
    an accent nothing: a long subscript (``G_{left_rocker}``) is narrower than its
    letters.
    """
    return _width(ET.fromstring(mathml))


SCRIPT = 0.7
"""Size of a sub- or superscript relative to its base's characters."""
EM = 2.0
"""Characters of text in one em (a character is about half an em wide)."""


def _width(node: ET.Element) -> float:
    """Return the width of a MathML node in characters (see :func:`shown_width`)."""
    parts = [_width(child) for child in node]
    if node.tag in ("msub", "msup"):
        return parts[0] + SCRIPT * parts[1]
    if node.tag == "msubsup":
        return parts[0] + SCRIPT * max(parts[1], parts[2])
    if node.tag in ("mfrac", "mover", "munder"):
        return max(parts)
    if node.tag == "mspace":
        return EM * float(node.get("width", "0em").removesuffix("em"))
    return len(node.text or "") + sum(parts)
