"""Interval arithmetic on the note's printed equations, for the tests.

A printed number stands for every value that rounds to it: an interval of half a
unit of its last kept digit either side (``num`` keeps at least two decimals and
four significant digits, then drops trailing zeros, so the unit is that of the
digits it would have kept). An equation ``lhs = e_1 = e_2 = ... = r`` is consistent
when each pair of neighbouring pieces made of numbers only (``e_k`` and ``e_{k+1}``)
has intervals that meet: the exact value lies in both.

The grammar is the note's: ``+ -``, ``\\cdot``, ``\\frac{}{}``, ``\\sqrt{}``,
``\\vec k \\times`` (a vector turned by 90 degrees), powers
``^2``, ``^{k}``, parentheses, brackets, ``\\left( \\right)``, vectors ``(x,\\ y)``,
and a trailing unit. A piece holding anything else (a symbol) is not numbers only.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass

__all__ = ["Interval", "evaluate", "number_interval", "pieces_checked"]


@dataclass(frozen=True)
class Interval:
    """The closed interval [lo, hi]."""

    lo: float
    hi: float

    def __add__(self, o: Interval) -> Interval:
        return Interval(self.lo + o.lo, self.hi + o.hi)

    def __sub__(self, o: Interval) -> Interval:
        return Interval(self.lo - o.hi, self.hi - o.lo)

    def __neg__(self) -> Interval:
        return Interval(-self.hi, -self.lo)

    def __mul__(self, o: Interval) -> Interval:
        p = [a * b for a in (self.lo, self.hi) for b in (o.lo, o.hi)]
        return Interval(min(p), max(p))

    def divided(self, o: Interval) -> Interval | None:
        """Return self / o; None when o holds zero (no bound)."""
        if o.lo <= 0.0 <= o.hi:
            return None
        return self * Interval(1.0 / o.hi, 1.0 / o.lo)

    def square(self) -> Interval:
        ends = sorted((self.lo * self.lo, self.hi * self.hi))
        return Interval(0.0 if self.lo <= 0.0 <= self.hi else ends[0], ends[1])

    def root(self) -> Interval:
        return Interval(math.sqrt(max(self.lo, 0.0)), math.sqrt(max(self.hi, 0.0)))

    def meets(self, o: Interval, slack: float) -> bool:
        """Whether the two intervals, widened by ``slack``, share a point."""
        return self.lo - slack <= o.hi and o.lo - slack <= self.hi


Value = tuple[Interval, ...]
"""A scalar (one interval) or a vector (two)."""

MATH = re.compile(r"\$\$(.*?)\$\$|\$(.*?)\$")
TOKEN = re.compile(
    r"\s*(\d+(?:\.\d+)?(?: ?\\cdot 10\^\{-?\d+\})?|\\left\(|\\right\)|\\cdot|"
    r"\\frac|\\sqrt|\\vec k \\times|,\\ |\^\{-?\d+\}|\^\d|[-+()\[\]{}])"
)
UNIT = re.compile(r"(?:\\[ ,]\s*\\mathrm\{(?:[^{}]|\{[^{}]*\})*\}|\\,\\%|\^\\circ)\s*$")
ZERO_HALF = 1e-4
"""What a printed 0 may hide: ``num`` prints values below 1e-9 of their scale as
0, and no scale in the examples passes 1e5."""


def number_interval(text: str) -> Interval:
    """Return the interval of the values ``num`` prints as ``text``.

    ``num`` keeps max(2, 3 - floor(log10 |x|)) decimals, then drops trailing zeros:
    the printed value gives that count (or a smaller one, a wider interval, where
    rounding crossed a power of ten). A mantissa of ``m \\cdot 10^{k}`` keeps
    three decimals.
    """
    found = re.fullmatch(r"(\d+(?:\.\d+)?)(?: ?\\cdot 10\^\{(-?\d+)\})?", text)
    assert found, text
    mantissa, exponent = found.groups()
    x = float(mantissa)
    if exponent is not None:
        power = 10.0 ** int(exponent)
        return Interval((x - 5e-4) * power, (x + 5e-4) * power)
    if x == 0.0:
        return Interval(-ZERO_HALF, ZERO_HALF)
    kept = max(2, 3 - math.floor(math.log10(x)))
    half = 0.5 * 10.0**-kept
    return Interval(x - half, x + half)


class _NotNumbersError(Exception):
    """The piece is not numbers only (or not in the grammar)."""


class _Parser:
    """A recursive-descent evaluator over the tokens of one piece."""

    def __init__(self, tokens: list[str]) -> None:
        self.tokens = tokens
        self.i = 0

    def peek(self) -> str | None:
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def take(self, want: str | None = None) -> str:
        token = self.peek()
        if token is None or (want is not None and token != want):
            raise _NotNumbersError
        self.i += 1
        return token

    def expr(self) -> Value:
        sign = self.take() if self.peek() in ("+", "-") else "+"
        value = self.term()
        if sign == "-":
            value = tuple(-v for v in value)
        while self.peek() in ("+", "-"):
            op = self.take()
            other = self.term()
            if len(other) != len(value):
                raise _NotNumbersError
            pairs = zip(value, other, strict=True)
            value = tuple(a + b if op == "+" else a - b for a, b in pairs)
        return value

    def term(self) -> Value:
        value = self.factor()
        while self.peek() == "\\cdot":
            self.take()
            other = self.factor()
            if len(value) == 1:
                value = tuple(value[0] * b for b in other)
            elif len(other) == 1:
                value = tuple(a * other[0] for a in value)
            else:
                raise _NotNumbersError
        return value

    def factor(self) -> Value:
        value = self.atom()
        token = self.peek()
        if token is not None and token.startswith("^"):
            self.take()
            power = int(token.strip("^{}"))
            if len(value) != 1 or power != 2:
                raise _NotNumbersError
            value = (value[0].square(),)
        return value

    def group(self, close: str) -> Value:
        value = self.expr()
        self.take(close)
        return value

    def atom(self) -> Value:
        token = self.take()
        if token[0].isdigit():
            return (number_interval(token),)
        if token == "-":
            return tuple(-v for v in self.factor())
        if token == "(":
            first = self.expr()
            if self.peek() == ",\\ ":
                self.take()
                second = self.expr()
                self.take(")")
                if len(first) != 1 or len(second) != 1:
                    raise _NotNumbersError
                return (first[0], second[0])
            self.take(")")
            return first
        if token == "[":
            return self.group("]")
        if token == "\\left(":
            return self.group("\\right)")
        if token == "{":
            return self.group("}")
        if token == "\\vec k \\times":
            # k x (x, y) = (-y, x): a vector turned a quarter turn counter-clockwise
            x, y = self.factor()
            return (-y, x)
        if token == "\\sqrt":
            self.take("{")
            inside = self.group("}")
            if len(inside) != 1:
                raise _NotNumbersError
            return (inside[0].root(),)
        if token == "\\frac":
            self.take("{")
            top = self.group("}")
            self.take("{")
            bottom = self.group("}")
            if len(bottom) != 1:
                raise _NotNumbersError
            out = [t.divided(bottom[0]) for t in top]
            if any(o is None for o in out):
                raise _NotNumbersError
            return tuple(o for o in out if o is not None)
        raise _NotNumbersError


def evaluate(piece: str) -> Value | None:
    """Return the value of a piece made of numbers only; None for any other."""
    text = UNIT.sub("", piece.strip()).strip()
    tokens, at = [], 0
    while at < len(text):
        found = TOKEN.match(text, at)
        if found is None:
            return None
        tokens.append(found.group(1))
        at = found.end()
    if not tokens:
        return None
    parser = _Parser(tokens)
    try:
        value = parser.expr()
    except _NotNumbersError:
        return None
    return value if parser.peek() is None else None


def pieces_checked(markdown: str) -> tuple[int, list[str]]:
    """Check every equation of a note; return how many steps held, and the others.

    A step is two neighbouring pieces of an equation, both numbers only.
    """
    count, wrong = 0, []
    for display, inline in MATH.findall(markdown):
        for part in re.split(r",\\quad |\\quad ", (display or inline).strip()):
            values = [evaluate(p) for p in part.split(" = ")]
            for a, b in itertools.pairwise(values):
                if a is None or b is None:
                    continue
                if len(a) != len(b):
                    wrong.append(part)
                    continue
                size = max(abs(x) for v in (*a, *b) for x in (v.lo, v.hi))
                # float round-off of the interval ends themselves
                if all(x.meets(y, 1e-12 * size) for x, y in zip(a, b, strict=True)):
                    count += 1
                else:
                    wrong.append(part)
    return count, wrong
