"""The names an argument lists: one str, or an iterable of str, checked."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from assur._text import python_value
from assur.errors import UsageError

__all__ = ["listed"]


def listed(names: Any, entry: str, what: str) -> list[str]:
    """Return the names ``names`` gives: one str stands for itself.

    ``entry`` is the argument's name and ``what`` the kind of name, for the message.

    Raises
    ------
    UsageError
        For a value that is no list of str (a number, bytes, a list holding one):
        the loop over it raised TypeError, or read bytes as numbers.

    Examples
    --------
    >>> listed("B", "joints", "joint"), listed(("A", "B"), "joints", "joint")
    (['B'], ['A', 'B'])
    """
    if isinstance(names, str):
        return [names]
    if not isinstance(names, Iterable) or isinstance(names, bytes | bytearray):
        msg = f"{entry}: expected a list of {what} names, got {python_value(names)}"
        raise UsageError(msg)
    out = list(names)
    for name in out:
        if not isinstance(name, str):
            msg = f"{entry}: expected {what} names (str), got {python_value(name)}"
            raise UsageError(msg)
    return out
