"""A decimal comma where a point is meant: the hint of a message that meets one.

In Russian, German, French and most of Europe "0,5" is a half. In a TOML file it is
a syntax error ("Expected newline or end of document after a statement"), and in
``--angles 0:90:22,5`` it read as a second range: the messages now ask whether a
decimal comma was meant.
"""

from __future__ import annotations

import re

__all__ = ["HINT", "comma_at", "has_decimal_comma", "range_hint"]

HINT = "; a decimal comma? decimals are written with a point (0.5, not 0,5)"
"""The words added to a message where a decimal comma may be the fault."""

_DIGITS_COMMA_DIGITS = re.compile(r"\d,\d")
_PLACE = re.compile(r"at line (\d+), column (\d+)")
_COMMA_BEFORE = re.compile(r"\d,\d+$")
"""A decimal comma whose digits end where the parser stopped: "[0,052" stops at
the 5, since TOML reads the 0 after the comma as a whole number, then refuses its
leading zero."""


def has_decimal_comma(text: str) -> bool:
    """Whether ``text`` holds a digit, a comma and a digit, with no space between.

    Examples
    --------
    >>> has_decimal_comma("0:90:22,5"), has_decimal_comma("0:90:10,0:90:10")
    (True, True)
    >>> has_decimal_comma("10, 20")
    False
    """
    return _DIGITS_COMMA_DIGITS.search(text) is not None


def range_hint(parts: list[str]) -> str:
    """Return :data:`HINT` for ``--angles`` split at its commas into ``parts``, or "".

    Only where a part is no range of its own: "0:90:22,5" is a step of 22.5 deg
    to a Russian reader, "0:90:10,0:90:10" two ranges.

    Examples
    --------
    >>> range_hint(["0:90:22", "5"]) == HINT, range_hint(["0:90:10", "0:90:10"])
    (True, '')
    """
    joined = ",".join(parts)
    return (
        HINT if has_decimal_comma(joined) and not all(":" in p for p in parts) else ""
    )


def comma_at(text: str, message: str) -> bool:
    r"""Whether a parser's ``message`` points at a comma between two digits of ``text``.

    Or just past the digits after such a comma, where a decimal with a leading zero
    ("0,052") stopped the parser. ``message`` names the place as tomllib does:
    "(at line 15, column 9)", both counted from 1.

    Examples
    --------
    >>> comma_at("a = 1\nmass = 0,5\n", "Expected newline (at line 2, column 9)")
    True
    >>> comma_at("at = [0,052, 0,052]", "Unclosed array (at line 1, column 10)")
    True
    >>> comma_at("at = [0, 52", "Unclosed array (at line 1, column 12)")
    False
    """
    place = _PLACE.search(message)
    if place is None:
        return False
    # lines as tomllib counts them, at "\n" alone: splitlines() also splits at
    # U+2028 and U+2029, which a comment or a string may hold
    lines = text.split("\n")
    row, column = int(place.group(1)) - 1, int(place.group(2)) - 1
    # a place before the line's start (JSON's column 1, one back) names no comma:
    # line[:-1] would read the rest of the line as before it
    if not 0 <= row < len(lines) or column < 0:
        return False
    line = lines[row]
    at_comma = 0 < column < len(line) - 1 and has_decimal_comma(
        line[column - 1 : column + 2]
    )
    return at_comma or _COMMA_BEFORE.search(line[:column]) is not None
