"""Words shared by every message and report: numerals, suggestions, echoed values.

The one place where roman numerals, "did you mean" hints, driver positions and values
echoed back to the user are written out, so that the model, the file reader, the
tables, the reports and the pictures word them alike.
"""

from __future__ import annotations

import datetime
import difflib
import math
import numbers
from collections.abc import Callable, Iterable, Mapping, Sequence

from assur._digits import settled
from assur._lookalike import lookalike, spelled_apart

__all__ = [
    "ROMAN",
    "WORDS",
    "crank_angle_text",
    "describe",
    "fitting",
    "key_text",
    "listing",
    "number_text",
    "roman",
    "shortened",
    "spelt",
    "spoken",
    "suggest",
]

ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V", 6: "VI", 7: "VII", 8: "VIII"}
"""Roman numerals of the classes of Assur groups."""
ECHO_LIMIT = 60
"""Most characters of a value echoed back in a message."""
ITEMS_SHOWN = 4
"""Most items of a list or keys of a table echoed back in a message."""
NAMES_SHOWN = 12
"""Most names listed by :func:`suggest`."""
NAME_LIMIT = 30
"""Most characters of one name listed by :func:`suggest`."""
LISTING_LIMIT = 160
"""Most characters of the names listed by :func:`suggest`, separators included."""


def number_text(value: float, spec: str = ".6g") -> str:
    """Return ``value`` formatted by ``spec``; minus zero shows as 0.

    The value is :func:`settled` first: a decimal tie rounds alike on every
    machine.

    Examples
    --------
    >>> number_text(-0.0), number_text(-1.5), number_text(2.0, ">6.3g")
    ('0', '-1.5', '     2')
    >>> number_text(364.05750000000006), number_text(364.05749999999995)
    ('364.058', '364.058')
    """
    return format(settled(value), spec)


def crank_angle_text(
    deg: float, unit: str = " deg", shown: Callable[[float], str] = number_text
) -> str:
    """Return a crank angle (deg), one past a turn with its place on the dial.

    The dynamic model counts angles within the turn from the reference pose: 364.72
    deg is 4.72 deg on the crank's dial, which is said beside it.

    Examples
    --------
    >>> crank_angle_text(364.72), crank_angle_text(-30.0), crank_angle_text(45.0)
    ('364.72 deg (that is, 4.72 deg)', '-30 deg (that is, 330 deg)', '45 deg')
    >>> crank_angle_text(365.316664), crank_angle_text(360.0 + 4e-9)
    ('365.317 deg (that is, 5.317 deg)', '360 deg (that is, 0 deg)')

    ``unit`` follows each number, written by ``shown`` (the HTML report's "°"). The
    dial's angle has the decimals of the angle written before it.
    """
    written = shown(deg)
    text = f"{written}{unit}"
    # to a millionth of a degree: 360 deg and its round-off are a turn, not 4e-09 deg
    near = round(deg, 6)
    if 0.0 <= near < 360.0 or not math.isfinite(deg):
        return text
    return f"{text} (that is, {_dial(near % 360.0, written, shown)}{unit})"


def _dial(angle: float, written: str, shown: Callable[[float], str]) -> str:
    """Return ``angle`` (deg, in [0, 360)) with as many decimals as ``written``."""
    if 360.0 - angle < 1.5e-6:  # a millionth below a turn: the turn itself
        angle = 0.0
    try:
        float(written)
    except ValueError:  # a form of its own (a typographic minus): as it writes it
        return shown(angle)
    if "e" in written.lower():
        return shown(angle)
    places = len(written.partition(".")[2])
    dial = f"{angle:.{places}f}"
    if float(dial) >= 360.0:  # 359.9996 to three places is a whole turn
        return "0"
    return dial.rstrip("0").rstrip(".") if "." in dial else dial


def spoken(items: Sequence[str], last: str = "and") -> str:
    """Return items as a sentence lists them: the last after ``last``.

    Examples
    --------
    >>> spoken(["a"]), spoken(["a", "b"]), spoken(["a", "b", "c"], "or")
    ('a', 'a and b', 'a, b or c')
    """
    if len(items) < 2:
        return "".join(items)
    return f"{', '.join(items[:-1])} {last} {items[-1]}"


WORDS = {
    1: "one",
    2: "two",
    3: "three",
    4: "four",
    5: "five",
    6: "six",
    7: "seven",
    8: "eight",
}
"""Small counts written as words."""


def spelt(count: int) -> str:
    """Return ``count`` in words up to eight, in digits above.

    Examples
    --------
    >>> spelt(3), spelt(12)
    ('three', '12')
    """
    return WORDS.get(count, str(count))


def counted(count: int, noun: str, plural: str | None = None) -> str:
    """Return ``count`` and ``noun``, in the plural unless the count is one.

    Examples
    --------
    >>> counted(1, "driver"), counted(2, "driver"), counted(0, "degree", "degrees")
    ('1 driver', '2 drivers', '0 degrees')
    """
    return f"{count} {noun_for(count, noun, plural)}"


def noun_for(count: int, noun: str, plural: str | None = None) -> str:
    """Return ``noun`` as it follows the number ``count``: plural unless one."""
    return noun if count == 1 else plural or noun + "s"


def public_name(name: str) -> str:
    """Return a link's or pair's name as a reader sees it.

    A slot ``J`` is replaced by the block ``J~block`` and the pin ``J~pin`` inside
    (the names of the JSON output); they read "J (block)" and "J (pin)".

    Examples
    --------
    >>> public_name("B~block"), public_name("B~pin"), public_name("rod")
    ('B (block)', 'B (pin)', 'rod')
    """
    return name.replace("~block", " (block)").replace("~pin", " (pin)")


def roman(number: int) -> str:
    """Return the roman numeral of a group's class (digits beyond VIII)."""
    return ROMAN.get(number, str(number))


def suggest(
    name: str, known: Iterable[str], listing: bool = True, label: str = "known"
) -> str:
    """Return a hint for an unknown ``name``: the closest of ``known``, or all of them.

    ``label`` heads the list of them all.

    Examples
    --------
    >>> suggest("rodd", ["crank", "rod"])
    "; did you mean 'rod'?"
    >>> suggest("B.fx", ["B.Fx", "B.x"])  # the same name in another case first
    "; did you mean 'B.Fx'?"
    >>> suggest("c2.X", ["C2.x", "c2.x"])  # the nearest such
    "; did you mean 'c2.x'?"
    >>> suggest("zz", ["a", "b"])
    ' (known: a, b)'
    """
    names = sorted(str(k) for k in known)
    twin = lookalike(str(name), names)
    if twin is not None:  # Latin O for a Cyrillic one, say: told apart
        return f"; did you mean {describe(twin)}? ({spelled_apart(str(name), twin)})"
    # the same name but for its case first ("B.fx": 'B.Fx', not the nearer 'B.x'),
    # the nearest of several such
    cased = [k for k in names if k.lower() == str(name).lower()]
    close = difflib.get_close_matches(str(name), cased, n=1, cutoff=0.0)
    close = close or difflib.get_close_matches(str(name), names, n=1)
    if close:
        return f"; did you mean {describe(close[0])}?"
    if not listing:
        return ""
    # a few names, each cut short: the message stays one readable line
    shown = [shortened(k, NAME_LIMIT) for k in names[:NAMES_SHOWN]]
    shown = shown[: fitting(shown, LISTING_LIMIT)]
    if len(shown) < len(names):
        shown.append("...")
    return f" ({label}: {', '.join(shown) or 'none'})"


def python_value(value: object) -> str:
    """Return a library argument as a message echoes it: its type and a short repr.

    Examples
    --------
    >>> python_value(b"B.Fx")
    "bytes b'B.Fx'"
    """
    return f"{type(value).__name__} {shortened(repr(value), 40)}"


def shortened(text: str, limit: int) -> str:
    """Return ``text`` cut to ``limit`` characters, ``...`` marking a cut."""
    return text if len(text) <= limit else text[: limit - 3] + "..."


def fitting(items: Sequence[str], width: int) -> int:
    """Return how many of the first ``items`` fit in ``width`` characters.

    Counted as joined by a two-character separator (``", "``, ``"; "``).

    Examples
    --------
    >>> fitting(["abc", "de", "fgh"], 9)
    2
    """
    used = -2
    for count, item in enumerate(items):
        used += len(item) + 2
        if used > width:
            return count
    return len(items)


def describe(value: object, limit: int = ECHO_LIMIT) -> str:
    """Return ``value`` as a message echoes it: short, in the file's own words.

    Long strings and lists are cut, tables show their keys, dates and times their
    ISO form; never a Python repr of a foreign object.

    Examples
    --------
    >>> describe(list(range(10000)))
    '[0, 1, 2, 3, ... (10000 items)]'
    >>> describe(datetime.date(2020, 1, 1))
    'the date 2020-01-01'
    >>> import numpy as np
    >>> describe(np.float64(-1.5)), describe(np.int64(3)), describe(np.float32("nan"))
    ('-1.5', '3', 'nan')
    >>> describe(np.bool_(True)) == describe(True)
    True
    >>> describe(np.float32(0.1)), describe(np.float16(-2.5))  # in their own precision
    ('0.1', '-2.5')
    """
    return shortened(_describe(value, limit), limit)


def _describe(value: object, limit: int) -> str:
    """Body of :func:`describe`, before the final cut."""
    if hasattr(value, "dtype") and getattr(value, "shape", None) == ():
        kind, size = value.dtype.kind, value.dtype.itemsize  # type: ignore[attr-defined]
        if kind == "f" and size != 8:
            # float32's 0.1 as the user gave it, the shortest text of its own
            # precision: as a Python float (.item()) it read 0.10000000149011612
            return str(value)
        # a numpy scalar reads as the Python one it holds (no import of numpy)
        value = value.item()  # type: ignore[attr-defined]
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        shown = value if len(value) <= limit else value[: limit - 5] + "..."
        return repr(shown)
    if isinstance(value, numbers.Integral) and not isinstance(value, int):
        value = int(value)  # a numpy integer reads as the number it holds
    elif isinstance(value, numbers.Real) and not isinstance(value, int):
        value = float(value)  # np.float64(2.5) reads 2.5, not its repr
    if isinstance(value, int):
        digits = len(str(abs(value))) if abs(value) < 10**50 else None
        if digits is None:
            return f"an integer of {_digits(value)} digits"
        return str(value)
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else str(value)
    if isinstance(value, datetime.datetime):
        return f"the date and time {value.isoformat()}"
    if isinstance(value, datetime.date):
        return f"the date {value.isoformat()}"
    if isinstance(value, datetime.time):
        return f"the time {value.isoformat()}"
    if isinstance(value, Mapping):
        keys = [key_text(k, limit // 2) for k in list(value)[: ITEMS_SHOWN + 1]]
        more = ", ..." if len(value) > ITEMS_SHOWN else ""
        return "a table {" + ", ".join(keys[:ITEMS_SHOWN]) + more + "}"
    if isinstance(value, Sequence):
        items = [_describe(v, limit // 2) for v in list(value[: ITEMS_SHOWN + 1])]
        if len(value) > ITEMS_SHOWN:
            return "[" + ", ".join(items[:ITEMS_SHOWN]) + f", ... ({len(value)} items)]"
        return "[" + ", ".join(items) + "]"
    return f"a value of type {type(value).__name__}"


def key_text(name: object, limit: int = 40) -> str:
    """Return a user's name as it reads in an entry: as it is, or quoted and cut.

    A name that is not a short printable string (a newline in it, a number, a
    thousand characters) is echoed by :func:`describe`, so that a message stays one
    short line. The keys of a table in a message are shown so too.
    """
    if isinstance(name, str) and name.isprintable() and 0 < len(name) <= limit:
        return name
    if not isinstance(name, str | int | float):
        # a Python-built entry's name=None read "joints.a value of type NoneType"
        return f"({describe(name, limit)})"
    return describe(name, limit)


def _digits(value: int) -> int:
    """Count the decimal digits of a huge integer without turning it into text."""
    return max(1, math.floor(value.bit_length() * math.log10(2)) + 1)


def listing(names: Sequence[str], limit: int = 6, last: str = "and") -> str:
    """Return names as a sentence lists them; beyond ``limit``, a count of the rest.

    All shown, the last follows ``last`` ("and", or "or" for a choice); some left
    out, the shown ones are followed by the count.

    Examples
    --------
    >>> listing(["a", "b", "c"]), listing(["a", "b", "c"], last="or")
    ('a, b and c', 'a, b or c')
    >>> listing(["a", "b", "c"], limit=2)
    'a, b, ... (3 in all)'
    """
    if len(names) <= limit:
        return spoken(names, last)
    return f"{', '.join(names[:limit])}, ... ({len(names)} in all)"
