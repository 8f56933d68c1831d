"""A load's symbol on a picture: the note's TeX, set as matplotlib's mathtext.

The names in a symbol are drawn as written; a symbol mathtext cannot set is written
plain.
"""

from __future__ import annotations

import functools
from typing import Any

from assur.explain._tex import TEX_SPECIAL
from assur.explain._tex import name as tex_name
from assur.plotting._style import literal, math_name

SYMBOLS = 4096
"""Symbols whose form for a picture is kept (a chain of 40 dyads has some 3300
instant centres, each with a symbol)."""


@functools.lru_cache(maxsize=SYMBOLS)
def _symbol(tex: str) -> str:
    """Return a load's TeX symbol (as the note writes it) for a picture, as mathtext.

    The names in it are drawn as written (:func:`~assur.plotting._style.math_name`);
    a symbol mathtext still cannot set is written plain. Each symbol is tried once:
    the trial is a whole mathtext parse, the pictures ask for the same symbols many
    times (the lever for each load's arrow, colour and line of its list), and
    matplotlib keeps only its last 50 parses.
    """
    math_text = f"${_names(tex)}$"
    try:
        _parser().parse(math_text, 72)
    except ValueError:
        return literal(tex.replace("\\vec ", "").replace("\\", ""))
    return math_text


def reaction_symbol(by: str, on: str) -> str:
    r"""Return the name of the force of link ``by`` on link ``on`` in every picture.

    The note's :math:`\vec F_{i,j}` (the textbook's :math:`R_{ij}` with the links'
    names): the same text in the overview, a free body, a force polygon and the
    report, whichever joint carries the force (the table's ``J.Fx`` is
    :math:`\vec F_{first,second}` of joint J).

    Examples
    --------
    >>> reaction_symbol("crank", "rod")
    '$\\vec F_{\\text{crank},\\text{rod}}$'
    """
    return _symbol(f"\\vec F_{{{tex_name(by)},{tex_name(on)}}}")


def couple_symbol(by: str, on: str) -> str:
    r"""Return the name of the couple of link ``by`` on link ``on`` in every picture.

    A sliding pair's reaction couple (the table's ``J.M``) beside its force
    :func:`reaction_symbol`: the same subscripts under an :math:`M`, so that a
    couple drawn apart from its force is not read as a force in N m.

    Examples
    --------
    >>> couple_symbol("ground", "ram")
    '$M_{\\text{ground},\\text{ram}}$'
    """
    return _symbol(f"M_{{{tex_name(by)},{tex_name(on)}}}")


def centre_symbol(link: str, other: str | None = None) -> str:
    r"""Return the name of an instant centre: ``link``'s, or of ``other`` and ``link``.

    Written as the forces are (:func:`reaction_symbol`): the links' names in the
    subscript, :math:`I_{crank}` for a link's absolute centre (about the frame),
    :math:`I_{crank,coupler}` for the relative one of two links.

    Examples
    --------
    >>> centre_symbol("coupler", "crank")
    '$I_{\\text{crank},\\text{coupler}}$'
    """
    names = [tex_name(n) for n in (other, link) if n is not None]
    return _symbol(f"I_{{{','.join(names)}}}")


NAME = "\\mathrm{"
"""How the note's TeX begins a name (see :func:`assur.explain._tex.name`)."""
UNESCAPED = sorted(
    ((code, char) for char, code in {**TEX_SPECIAL, " ": "\\ "}.items()),
    key=lambda pair: -len(pair[0]),
)
"""The note's TeX escapes of a name's characters, longest first."""


def _names(tex: str) -> str:
    r"""Return ``tex`` with every name (``\mathrm{...}``) as mathtext draws it."""
    out = []
    start = tex.find(NAME)
    while start >= 0:
        out.append(tex[:start])
        i, chars = start + len(NAME), []
        while tex[i] != "}":
            for code, char in UNESCAPED:
                if tex.startswith(code, i):
                    chars.append(char)
                    i += len(code)
                    break
            else:
                chars.append(tex[i])
                i += 1
        out.append(math_name("".join(chars)))
        tex = tex[i + 1 :]
        start = tex.find(NAME)
    out.append(tex)
    return "".join(out)


@functools.cache
def _parser() -> Any:
    """Return a mathtext parser (made once)."""
    from matplotlib.mathtext import MathTextParser

    return MathTextParser("path")
