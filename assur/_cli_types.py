"""The command line's argument types: names of files and folders, numbers, and FILE.

argparse's own ``float`` and ``int`` said only "invalid float value: ''"; these say
what was expected, as the rest of the command line does. Each is an argparse type:
its fault is an :class:`argparse.ArgumentTypeError`, which the parser turns into one
line.
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path
from typing import Any

from assur._text import describe

__all__ = [
    "ANGLES_HELP",
    "FILE_HELP",
    "add_file_argument",
    "file_name",
    "folder",
    "given",
    "input_file",
    "joints",
    "number",
    "whole_number",
]

EMPTY_NAME = "expected a {what} name, got an empty one"
"""What an option that takes a path says of an empty value (``--csv=``)."""


def given(text: str) -> str:
    """Return a file name as it is written (``-`` too); refuse an empty one.

    An argparse type: ``--csv=`` (or ``--csv ''``) printed the table and wrote
    nothing, and ``-o ''`` meant the current folder.

    Raises
    ------
    argparse.ArgumentTypeError
        For an empty name.
    """
    return _named(text, "file")


def _named(text: str, what: str) -> str:
    """Return ``text``; an empty one is refused as a ``what`` name (argparse)."""
    if text == "":
        raise argparse.ArgumentTypeError(EMPTY_NAME.format(what=what))
    return text


NUMBER = re.compile(
    r"\s*[+-]?((\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?|inf|infinity|nan)\s*",
    re.I | re.ASCII,
)
"""A number as the command line reads one: ``float``'s syntax without the digit
separators (``1_0``) and the digits of other scripts (``٤٥``) it also takes."""


def plain_number(text: str) -> float:
    """Return ``text`` as a float; ValueError for what :data:`NUMBER` refuses."""
    if not NUMBER.fullmatch(text):
        raise ValueError(text)
    return float(text)


WHOLE = re.compile(r"\s*[+-]?\d+\s*", re.ASCII)
"""A whole number as the command line reads one (``int`` takes ``1_0`` too)."""


def number(text: str) -> float:
    """Return the number ``text`` (an argparse type); say what was expected if not.

    argparse's own ``float`` said only "invalid float value: ''". The range of
    each option is checked by its command (:func:`check_range`).

    Raises
    ------
    argparse.ArgumentTypeError
        For text that is not a number.
    """
    try:
        return plain_number(text)
    except ValueError:
        msg = f"expected a number, got {describe(text)}"
        raise argparse.ArgumentTypeError(msg) from None


def whole_number(text: str) -> int:
    """Return the whole number ``text`` (an argparse type); say what was expected.

    Raises
    ------
    argparse.ArgumentTypeError
        For text that is not a whole number (``1.5``, ``1e3``).
    """
    try:
        if not WHOLE.fullmatch(text):
            raise ValueError(text)
        return int(text)
    except ValueError:
        msg = f"expected a whole number, got {describe(text)}"
        raise argparse.ArgumentTypeError(msg) from None


def joints(text: str) -> str | list[str]:
    """Return the joint of ``--driver``, or a list of several (an argparse type).

    Names are separated by commas, with spaces around them as a reader writes
    them; an empty piece (a trailing comma) is passed over.

    Raises
    ------
    argparse.ArgumentTypeError
        For text that names no joint ("", ","): it was taken for no driver.
    """
    names = [name.strip() for name in text.split(",") if name.strip()]
    if not names:
        msg = f"no joint named in {describe(text)}; expected a joint name"
        raise argparse.ArgumentTypeError(msg)
    return names if len(names) != 1 else names[0]


def input_file(text: str) -> Path:
    """Return the name of a file to read as a Path; refuse an empty one."""
    return Path(given(text))


ANGLES_HELP = (
    "driver positions, deg (m for a prismatic driver): START:STOP:STEP, STOP "
    "included when on the grid, or one value; several drivers: one range each, "
    "separated by commas; default: one turn from the reference pose in steps of 1 "
    "deg (a prismatic driver: 101 positions over a round stroke within +-20 %% of "
    "the mechanism's size)"
)
"""What ``--help`` says of ``--angles`` (argparse reads ``%%`` as ``%``)."""
FILE_HELP = "the mechanism file, .toml or .json ('-': read from stdin)"
"""What ``--help`` says of the FILE every command reads."""


def add_file_argument(parser: Any) -> None:
    """Add the positional ``file``, the mechanism file every command reads."""
    parser.add_argument("file", type=input_file, help=FILE_HELP)


def file_name(text: str) -> Path:
    """Return an output file's name as a Path (an argparse type).

    Raises
    ------
    argparse.ArgumentTypeError
        For an empty name, or one ending with a slash, a folder's (a Path would
        drop the slash).
    """
    from assur._targets import folder_name

    fault = folder_name(given(text))
    if fault is not None:
        msg = f"{text}: {fault}; expected a file"
        raise argparse.ArgumentTypeError(msg)
    return Path(text)


def folder(text: str) -> Path:
    """Return an output folder's name as a Path; refuse an empty one.

    An empty name was the current folder, whose old pictures of the same names
    were then replaced (and the stale ones of a set removed).
    """
    return Path(_named(text, "folder"))
