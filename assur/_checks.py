"""Checks of a mechanism's numbers, names and vectors, and their messages.

The smallest parts of the model's validation (:mod:`assur.model`): each check names
the entry at fault, the value received and what was expected, and raises
:class:`~assur.errors.ModelError`.
"""

from __future__ import annotations

import math
import unicodedata
from collections.abc import Collection, Iterable
from typing import Any, NoReturn

import numpy as np

from assur._text import describe, key_text, listing, spoken, suggest
from assur.errors import ModelError

GROUND = "ground"
"""Name of the frame (public as :data:`assur.model.GROUND`)."""

JOINT_KINDS = ("revolute", "prismatic", "slot")
POINT_FORMS = "[x, y], a joint's name or {from, toward, distance}"
"""The forms of a point (FORMAT.md, "File"), said where one is missing."""
RESERVED = ("~", ".", ",")
RESERVED_NAMES = ("angle", "driver", "shaking", "residual")
"""Names the tables use for their own columns."""
LARGEST = 1e15
"""Largest magnitude of a number in a mechanism (m, kg, N, rad/s, ...): products of
a few such numbers (an acceleration, a jerk, a moment) stay far from overflow."""
MOST_FRICTION = 1e6
"""Largest friction coefficient: beyond it the friction of a pair whose normal force
it all but cancels is lost in the rounding of the reactions (no real pair comes
near: a coefficient above 1 is rare)."""
COINCIDENT = 1e-12
"""Distance under which two points coincide, m (relative to the coordinates' size
beyond 1 m, where round-off grows with them)."""


_SIMPLE = frozenset({float, int, str})


def _plain(value: Any) -> Any:
    """Return lists and arrays as tuples, numpy numbers as Python's (hashable)."""
    # the common case, a tuple of plain numbers or names, is kept as it is
    if value.__class__ is tuple and all(v.__class__ in _SIMPLE for v in value):
        return value
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value.item()  # a number made with np.array(x)
    if isinstance(value, np.ndarray | list | tuple):
        return tuple(_plain(v) for v in value)
    if isinstance(value, np.generic):
        return value.item()
    return value


def _tuples(obj: Any, *names: str) -> None:
    """Store the fields ``names`` of a frozen dataclass as plain tuples."""
    for name in names:
        value = getattr(obj, name)
        if isinstance(value, np.ndarray | list | tuple | np.generic):
            object.__setattr__(obj, name, _plain(value))


def _fail(entry: str, message: str) -> NoReturn:
    msg = f"{entry}: {message}"
    raise ModelError(msg)


def _check_unique(entry: str, name: str, taken: Collection[str], fault: str) -> None:
    """Fail with ``fault`` when ``name`` is ``taken`` already (by a link, say)."""
    if name in taken:
        _fail(entry, f"{fault}; expected a name for each")


def _number(value: object) -> bool:
    """Whether ``value`` is a number (not a boolean)."""
    return isinstance(value, int | float) and not isinstance(value, bool)


def _finite(value: object) -> bool:
    """Whether ``value`` is a number of magnitude at most :data:`LARGEST`."""
    if value.__class__ is float:  # the common case, checked first
        return abs(value) <= LARGEST  # type: ignore[arg-type]
    return _number(value) and abs(value) <= LARGEST  # type: ignore[arg-type]


def _number_fault(value: object) -> str:
    """Return what is wrong with a number that is not :func:`_finite`."""
    if not _number(value):
        return f"expected a number, got {describe(value)}"
    # an integer is finite, however large (math.isfinite of 10**400 overflows)
    if isinstance(value, float) and not math.isfinite(value):
        return f"expected a finite number, got {describe(value)}"
    return f"expected a number of magnitude at most {LARGEST:g}, got {describe(value)}"


def _check_number(entry: str, value: object, minimum: float | None = None) -> None:
    if not _finite(value):
        _fail(entry, _number_fault(value))
    if minimum is not None and value < minimum:  # type: ignore[operator]
        _fail(entry, f"expected a number >= {minimum:g}, got {describe(value)}")


def _sequence_fault(value: object, expected: str, count: int | None = None) -> str:
    """Return what is wrong with a sequence of numbers (``expected``: what it is not).

    Numbers of the right count of which one is too large or not finite are named
    as such, not said to be of the wrong count.
    """
    if (
        isinstance(value, tuple | list)
        and (len(value) == count if count is not None else len(value) >= 2)
        and all(map(_number, value))
    ):
        bad = next((v for v in value if not _finite(v)), None)
        if bad is not None:
            return f"{_number_fault(bad)} in {describe(value)}"
    return f"expected {expected}, got {describe(value)}"


def _check_vec(entry: str, value: object) -> None:
    if not _vec_ok(value):
        _fail(entry, _sequence_fault(value, "two finite numbers [x, y]", 2))


def _vec_ok(value: object) -> bool:
    """Whether :func:`_check_vec` accepts ``value``."""
    return (
        isinstance(value, tuple | list) and len(value) == 2 and all(map(_finite, value))
    )


BIDI_CONTROLS = frozenset("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")
"""Unicode's explicit embeddings, overrides and isolates: one in a name turns the
rest of the line around it (a table's header, a message) on a terminal or in an
editor, as an escape sequence would recolour it. The marks U+200E and U+200F,
which right-to-left scripts need and which reorder nothing beyond them, stay."""


def _control(name: str) -> str | None:
    """Return the first control character of ``name`` (or a line separator)."""
    for c in name:
        if unicodedata.category(c) in ("Cc", "Zl", "Zp") or c in BIDI_CONTROLS:
            return c
    return None


def _check_title(name: str) -> None:
    """Check the mechanism's name: one line, no control character."""
    control = _control(name)
    if control is not None:
        # the name heads summaries and titles on a terminal: a line break or an
        # escape sequence in it would split or recolour them
        _fail(
            "name",
            f"the name {describe(name)} holds the control character "
            f"{control!a}; expected one line of printable characters",
        )


_GOOD_NAMES: set[str] = set()
"""Names found valid already: the variants of a study repeat their names, and the
check reads every character's Unicode category."""


def _check_name(entry: str, name: object) -> None:
    if name.__class__ is str and name in _GOOD_NAMES:
        return
    _check_new_name(entry, name)
    if len(_GOOD_NAMES) >= 4096:
        _GOOD_NAMES.clear()
    _GOOD_NAMES.add(name)  # type: ignore[arg-type]


def _check_new_name(entry: str, name: object) -> None:
    """Check a name not met before: text, no reserved or control character."""
    if not isinstance(name, str) or not name or any(c in name for c in RESERVED):
        _fail(
            entry,
            f"expected a non-empty name without '~', '.' or ',', got {describe(name)}",
        )
    control = _control(name)
    if control is not None:
        _fail(
            entry,
            f"the name {describe(name)} holds the control character "
            f"{control!a}; expected printable characters only",
        )
    if name in RESERVED_NAMES:
        _fail(
            entry,
            f"the name {describe(name)} is taken by the result tables; expected "
            f"another name (not {spoken(RESERVED_NAMES, 'or')})",
        )


def _unknown(kind: str, name: object, known: Iterable[str]) -> str:
    """Return the message of an unknown reference ``name``, with a hint."""
    hint = suggest(name, known) if isinstance(name, str) else ""
    return f"unknown {kind} {describe(name)}{hint}"


def _on_the_frame(why: str, links: list[str]) -> str:
    """Return the message of a point or load on the frame (``why``: what it does)."""
    choices = listing(links, last="or")
    return f"{GROUND!r} is the frame: {why}; expected a moving link ({choices})"


def _entry(kind: str, name: object, suffix: str) -> str:
    """Return an entry such as ``joints.B.at``."""
    return f"{kind}.{key_text(name)}{suffix}"


def _no_entry(kind: str, name: object, suffix: str) -> str:
    """Return no entry (see :func:`_check_resolvable`)."""
    return ""


def _coincide(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two reference-pose points are one (see :data:`COINCIDENT`)."""
    # plain floats: two points cost less so than as numpy reductions
    ax, ay, bx, by = float(a[0]), float(a[1]), float(b[0]), float(b[1])
    size = max(1.0, abs(ax), abs(ay), abs(bx), abs(by))
    return math.hypot(bx - ax, by - ay) <= COINCIDENT * size
