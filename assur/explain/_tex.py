"""Numbers, vectors and names as the note writes them, in a small subset of TeX.

Every number of the note goes through :func:`num`, so a reader (or a test) knows how
far to trust its last digit: at least two decimals and at least four significant
digits, trailing zeros left out. Names from the mechanism file are set upright.
"""

from __future__ import annotations

import math
from contextvars import ContextVar
from typing import Any

import numpy as np

from assur._digits import settled

__all__ = [
    "LENGTH",
    "ROTATION",
    "ZERO",
    "cramer",
    "deg",
    "half_turn",
    "kept",
    "name",
    "num",
    "par",
    "plain",
    "point_name",
    "segment",
    "squared",
    "text",
    "times",
    "unit",
    "vec",
]

ZERO = 1e-9
"""Values smaller than this, relative to the scale they are compared with, are
round-off and print as 0."""
SIGNIFICANT = 4
"""Fewest significant digits a number keeps."""
DECIMALS = 2
"""Fewest decimals a number keeps."""
SCIENTIFIC = (1e-4, 1e8)
"""Magnitudes outside this range are written with a power of ten."""
SMALL = 1e-2
"""Magnitudes below this are written with a power of ten beside one so written."""
LENGTH = ("m", "m/s", "m/s^2")
"""Units of a position, a velocity and an acceleration (by level 0, 1, 2)."""
ROTATION = ("rad", "rad/s", "rad/s^2")
"""Units of an angle, an angular velocity and an angular acceleration."""


def unit(symbol: str) -> str:
    r"""Return the unit ``symbol`` to follow a result, as ``\ \mathrm{m/s}``."""
    return f"\\ \\mathrm{{{symbol}}}"


FLOOR: ContextVar[float] = ContextVar("assur_note_floor", default=1.0)
"""The scale a value is told from round-off by where its line gives none: at most 1
(in SI), less for a small mechanism (its forces, moments and powers are small, not
round-off); set by the note for its mechanism
(:func:`assur.explain._explain._floor`)."""


def num(x: float, scale: float | None = None, least: int = 0) -> str:
    """Return ``x`` rounded as the note rounds (TeX).

    At least :data:`DECIMALS` decimals, :data:`SIGNIFICANT` significant digits and
    ``least`` decimals; trailing zeros dropped; below ``ZERO * scale`` the value
    is 0 (``scale`` :data:`FLOOR` by default).

    Examples
    --------
    >>> num(1282.5660), num(0.0523259), num(8000.0), num(-1e-15)
    ('1282.57', '0.05233', '8000', '0')
    """
    x = float(x)
    if not math.isfinite(x):
        return r"\text{undefined}"
    if scale is None:
        scale = FLOOR.get()
    if abs(x) < ZERO * max(abs(scale), 1e-300) or x == 0.0:
        return "0"
    size = abs(x)
    if not SCIENTIFIC[0] <= size < SCIENTIFIC[1]:
        return _powered(x)
    decimals = max(DECIMALS, SIGNIFICANT - 1 - math.floor(math.log10(size)), least)
    # a decimal tie (0.147 * 22.5 = 3.3075) rounds alike on every machine
    text = _trim(f"{settled(x):.{decimals}f}")
    return "0" if text in ("-0", "0") else text


def _powered(x: float) -> str:
    """Return ``x`` (not 0) with a power of ten, :data:`SIGNIFICANT` digits (TeX)."""
    mantissa, exponent = f"{settled(x):.{SIGNIFICANT - 1}e}".split("e")
    return f"{_trim(mantissa)} \\cdot 10^{{{int(exponent)}}}"


def _trim(text: str) -> str:
    """Drop trailing zeros (and a trailing point) of a decimal number."""
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text


def kept(x: float) -> str:
    r"""Return :func:`num` of ``x``, however small: a datum, or a value cleaned already.

    A mass, a moment of inertia, a rate the note cleaned of its round-off (relative
    to the mechanism's motion): 5e-13 kg m^2 is a small link's own, not round-off.

    Examples
    --------
    >>> kept(5.16e-13), num(5.16e-13)
    ('5.16 \\cdot 10^{-13}', '0')
    """
    return num(x, abs(x))


def par(x: float, scale: float | None = None, least: int = 0) -> str:
    """Return :func:`num` of ``x``, in parentheses when negative (for products)."""
    text = num(x, scale, least)
    return f"({text})" if text.startswith("-") else text


def squared(x: float, scale: float | None = None) -> str:
    r"""Return ``x`` squared as TeX: in parentheses when negative or a power of ten.

    Examples
    --------
    >>> squared(0.12), squared(-0.2), squared(6.536e-5)
    ('0.12^2', '(-0.2)^2', '(6.536 \\cdot 10^{-5})^2')
    """
    text = num(x, scale)
    return f"({text})^2" if text.startswith("-") or "\\cdot" in text else f"{text}^2"


def times(*factors: str) -> str:
    r"""Join factors with ``\cdot``."""
    return r" \cdot ".join(factors)


def vec(v: Any, scale: float | None = None) -> str:
    r"""Return a vector's components in parentheses.

    A small component is written as its neighbour is, with a power of ten, where
    that one has one: one form within a vector. A component is told from
    round-off by ``scale``; by default by the larger of its neighbour and the
    note's :data:`FLOOR`, as :func:`num` tells a number: a difference of two
    points that coincide, (9.7e-17, -1.8e-16) m, is (0, 0), not round-off's
    digits as its own scale.

    Examples
    --------
    >>> vec((0.0001456, 6.575e-5)), vec((0.2665, 3e-5))
    ('(1.456 \\cdot 10^{-4},\\ 6.575 \\cdot 10^{-5})', '(0.2665,\\ 3 \\cdot 10^{-5})')
    >>> vec((9.714e-17, -1.804e-16)), vec((9.714e-17, -1.804e-16), 1e-16)
    ('(0,\\ 0)', '(9.714 \\cdot 10^{-17},\\ -1.804 \\cdot 10^{-16})')
    """
    own = max(abs(float(v[0])), abs(float(v[1])))
    ref = max(own, FLOOR.get()) if scale is None else scale
    texts = [num(v[0], ref), num(v[1], ref)]
    if any("\\cdot" in s for s in texts):
        texts = [
            _powered(float(x)) if s != "0" and abs(float(x)) < SMALL else s
            for s, x in zip(texts, v, strict=False)
        ]
    return f"({texts[0]},\\ {texts[1]})"


def deg(radians: float) -> str:
    r"""Return an angle in degrees, within (-180, 180], with ``^\circ``."""
    return f"{num(_within(math.degrees(float(radians))))}^\\circ"


def _within(d: float) -> float:
    """Return an angle ``d`` (deg) moved by whole turns into (-180, 180]."""
    d = (d + 180.0) % 360.0 - 180.0
    # -180 (atan2 of -0.0 to the left) and its round-off are the half turn 180
    if d <= -180.0 + 1e-12:
        d += 360.0
    return d


def half_turn(radians: float) -> float:
    """Return an angle (rad) moved by whole turns to the one :func:`deg` writes.

    Within (-pi, pi]; an angle already there is returned as it is. A sum worked
    out from an angle the line before wrote takes this value, so that both read
    alike: atan2(-0.0, -1) = -pi is written 180 deg, and summed as 180 deg too.

    Examples
    --------
    >>> half_turn(math.atan2(-0.0, -1.0)) == math.pi, half_turn(-1.0)
    (True, -1.0)
    """
    r = float(radians)
    d = math.degrees(r)
    turns = round((d - _within(d)) / 360.0)
    return r - turns * 2.0 * math.pi if turns else r


TEX_SPECIAL = {
    "\\": r"\backslash ",
    "_": r"\_",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "%": r"\%",
    "&": r"\&",
    "#": r"\#",
    "^": r"\hat{}",
    "~": r"\sim ",
}


def name(text: str) -> str:
    r"""Return a name from the file set upright in TeX (``\mathrm{rod}``).

    A slot's block is called ``J~block`` inside; it reads "J (block)" here, as in
    the paragraphs.
    """
    public = text.replace("~block", " (block)").replace("~pin", "")
    # a space after an escape (``\sim``) ends its command: it is not a space drawn
    body = "".join(r"\ " if c == " " else TEX_SPECIAL.get(c, c) for c in public)
    return f"\\mathrm{{{body}}}"


def point_name(point: str) -> str:
    r"""Return a reported point's name: a joint, an extra point or ``L.G``.

    The centre of mass of link L is :math:`G_L`.
    """
    if point.endswith(".G") and point.count(".") == 1:
        return f"G_{{{name(point[:-2])}}}"
    return name(point)


def segment(a: str, b: str) -> str:
    """Return the name of the line through two points, as a paragraph writes it.

    One letter each: run together, as a textbook writes BC. Longer names are
    joined by a dash ("D–slot (pin)"): run together they read as one name.
    """
    return f"{a}{b}" if len(a) == 1 and len(b) == 1 else f"{a}–{b}"


def plain(text: str) -> str:
    """Return text for a paragraph: a dollar sign of a name escaped.

    A slot's block and pin (``J~block``, ``J~pin`` inside) read "J (block)" and
    "J (pin)".
    """
    public = text.replace("~block", " (block)").replace("~pin", " (pin)")
    return public.replace("$", r"\$")


def text(words: str) -> str:
    r"""Return words for ``\text{...}``: TeX's special characters escaped.

    Examples
    --------
    >>> text("left_rocker")
    'left\\_rocker'
    """
    words = words.replace("~block", " block").replace("~pin", "")
    kept = "".join(c for c in words if c not in "\\^~")
    return "".join("\\" + c if c in "_{}$%&#" else c for c in kept)


def cramer(
    names: list[str], a: Any, rhs: Any, units: tuple[str, str] = ("", "")
) -> tuple[list[str], list[float]]:
    """Return a 2 x 2 system ``a x = rhs`` solved by Cramer's rule, with numbers.

    The lines are the two component equations, the determinant and each unknown's
    quotient, ending with ``units[i]`` (a :func:`unit`, or ""); the values are the
    unknowns ``names``.
    """
    det = float(a[0, 0] * a[1, 1] - a[0, 1] * a[1, 0])
    tops = [
        float(rhs[0] * a[1, 1] - a[0, 1] * rhs[1]),
        float(a[0, 0] * rhs[1] - rhs[0] * a[1, 0]),
    ]
    ref = float(np.abs(a).max())
    lines = [
        f"{axis}:\\ {num(a[i, 0], ref)}\\,{names[0]} + {par(a[i, 1], ref)}\\,{names[1]}"
        f" = {num(rhs[i])}"
        for i, axis in enumerate("xy")
    ]
    lines.append(
        f"\\Delta = {par(a[0, 0], ref)} \\cdot {par(a[1, 1], ref)} - "
        f"{par(a[0, 1], ref)}"
        f" \\cdot {par(a[1, 0], ref)} = {num(det, ref * ref)}"
    )
    values = [t / det for t in tops]
    for i in (0, 1):
        lines.append(
            f"{names[i]} = \\frac{{{num(tops[i])}}}{{{num(det, ref * ref)}}} = "
            f"{num(values[i])}{units[i]}"
        )
    return lines, values
