"""What every picture of :mod:`assur.plotting` shares: colours, opacities, names."""

from __future__ import annotations

from typing import Any

from assur._style import REACTION_COLOUR

BALANCING_COLOR = "#6a3d9a"
"""Colour of the balancing loads (the links' colours are in :mod:`assur._style`)."""
GROUND_COLOR = "#333333"
PLAIN_COLOR = "#4d4d4d"
REACTION_LEGEND = (
    "reaction F\N{LATIN SUBSCRIPT SMALL LETTER I}\N{LATIN SUBSCRIPT SMALL LETTER J}:"
    " link i on link j (J.Fx, J.Fy)"
)
"""The legend's entry for the reactions, the same in every picture that draws them
(plain text: a legend's entries are drawn as written, see :func:`literal`)."""
INTERNAL_LEGEND = "dashed: inside the group, on both links"
"""The legend's entry for a group's internal reactions, drawn in pairs that cancel."""
INERTIA_COLOR = "#111111"
LOAD_COLOR = "#00838f"
PATH_COLORS = (
    "#1f77b4",
    "#d62728",
    "#2ca02c",
    "#9467bd",
    "#ff7f0e",
    "#17becf",
    "#8c564b",
    "#e377c2",
    "#bcbd22",
    "#7f7f7f",
)
"""Colours of the paths of points (cycled)."""
PATH_MARKERS = ("", "s", "^", "D")
"""Marks along the paths of points (cycled with the colours): the first four colours
are close to one grey, and red and green, blue and purple look alike to a
deuteranope, so neighbouring paths differ in their marks too. Marks, not dashes: a
rocking point goes back over its own path, and the dashes of the way back fill
the gaps of the way out."""
PATH_MARK_SPACING = 0.09
"""Distance between two marks along a path, relative to the axes' diagonal."""
FAINT = 0.22
"""Opacity of the links drawn only for orientation."""
ARROW_LENGTH = 0.28
"""Length of the largest force arrow at the default scale, relative to the mechanism."""


def literal(text: str) -> str:
    """Return ``text`` (a name from the file) to be drawn as it is written.

    matplotlib reads the text between two ``$`` as mathtext: a name such as
    ``$^$`` would be parsed (and fail to draw), ``$x$`` set in italics.
    """
    return text.replace("$", r"\$")


MATH_TEXT = {"$": r"\$", "{": r"\{", "}": r"\}", "\\": "\N{SET MINUS}"}
r"""How a name's characters are written inside mathtext's ``\text{...}``: the
others are drawn as they are (``^``, ``_``, ``%``, ...); a backslash would start a
command, so it is drawn as the set-minus sign, which looks like it."""


def math_name(text: str) -> str:
    r"""Return a name from the file for a mathtext label, drawn as written.

    Examples
    --------
    >>> math_name("a^b")
    '\\text{a^b}'
    """
    return "\\text{" + "".join(MATH_TEXT.get(c, c) for c in text) + "}"


def titled(mechanism: Any) -> str:
    """Return a mechanism's name for a title, drawn as written ("Mechanism" if none)."""
    return literal(mechanism.name or "Mechanism")


def load_colour(tex: str) -> str:
    """Return the colour of a known load (the note's TeX), as the other pictures'.

    A reaction of a link solved before (``F_{i,j}``, a guide's normal force ``N``
    and its friction force ``F_f``) is drawn as every reaction is; inertia loads
    and the other loads in their colours of the mechanism drawings.
    """
    tex = tex.removeprefix("-")
    if tex.startswith("\\vec F_{i,"):
        return INERTIA_COLOR
    if tex.startswith(("\\vec F_{", "\\vec N_")):
        return REACTION_COLOUR
    return LOAD_COLOR
