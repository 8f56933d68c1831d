"""The syntax of a mechanism file: its bytes decoded, its TOML or JSON parsed.

Every fault of the text (not UTF-8, not valid TOML or JSON, a key given twice, nested
too deeply, an integer too long) becomes a one-line :class:`~assur.errors.ModelError`;
:mod:`assur._file_entries` then reads the entries of the data.
"""

from __future__ import annotations

import json
import re
import sys
from typing import Any

from assur._decimal_comma import HINT, comma_at
from assur._file_entries import _fail
from assur._text import key_text
from assur.errors import ModelError


def file_data(text: str, json_format: bool) -> Any:
    """Return the data of a mechanism file's ``text`` (TOML or JSON), depth checked."""
    import tomllib

    kind = "JSON" if json_format else "TOML"
    try:
        data = (
            json.loads(text, object_pairs_hook=_unique_keys)
            if json_format
            else tomllib.loads(text)
        )
    except (tomllib.TOMLDecodeError, json.JSONDecodeError) as err:
        msg = f"not valid {kind}: {_one_line(str(err))}"
        place = str(err)
        if isinstance(err, json.JSONDecodeError):
            # JSON stops at the digit after the comma ("0,5": a property name
            # expected at the 5); the place is given as tomllib gives it
            place = f"(at line {err.lineno}, column {err.colno - 1})"
        if comma_at(text, place):
            msg += HINT  # "mass = 0,5": a half, to a Russian or a German reader
        raise ModelError(msg) from err
    except RecursionError as err:
        msg = (
            f"not valid {kind}: nested too deeply (more than the parser can follow); "
            f"expected the few levels of a mechanism file"
        )
        raise ModelError(msg) from err
    except ValueError as err:  # an integer too long to convert
        msg = (
            _long_integer(text, json_format)
            or f"not valid {kind}: {_one_line(str(err))}"
        )
        raise ModelError(msg) from err
    _check_depth(data)
    return data


def _decoded(data: bytes, expected: str = "a TOML or JSON file saved as UTF-8") -> str:
    """Return a file's bytes as text (UTF-8, a byte-order mark welcome).

    ``expected`` says what the file should be, in the message of a fault.
    """
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        if data[:4] in (b"\xff\xfe\x00\x00", b"\x00\x00\xfe\xff"):
            found = "UTF-32 text (it starts with UTF-32's byte-order mark)"
        elif data[:2] in (b"\xff\xfe", b"\xfe\xff"):
            # an editor's "Unicode" is UTF-16: its mark says so at once
            found = "UTF-16 text (it starts with UTF-16's byte-order mark)"
        else:
            found = f"not UTF-8 text ({_where(data, err.start)} cannot be decoded)"
        msg = f"{found}; expected {expected}"
        raise ModelError(msg) from err


def _where(data: bytes, at: int) -> str:
    """Return the byte at offset ``at`` and where an editor shows it (line, column).

    A file saved in a code page (an editor's "ANSI": Windows-1251 for Russian) has
    its first non-ASCII letter there; a byte's offset alone left it to be counted.
    """
    start = data.rfind(b"\n", 0, at) + 1
    line = data.count(b"\n", 0, at) + 1
    column = len(data[start:at].decode("utf-8", "replace")) + 1
    return f"byte 0x{data[at]:02X} at line {line}, column {column}"


def _one_line(text: str) -> str:
    """Return a parser's message on one line."""
    return " ".join(text.split())


MAX_NESTING = 16
"""Deepest nesting of tables and arrays read; a mechanism file needs five levels."""


def _check_depth(data: Any) -> None:
    """Refuse data nested deeper than :data:`MAX_NESTING` (no recursion here)."""
    stack: list[tuple[Any, str, int]] = [(data, "", 0)]
    while stack:
        value, entry, depth = stack.pop()
        if depth > MAX_NESTING:
            _fail(
                entry,
                f"nested too deeply (more than {MAX_NESTING} levels); expected the "
                "few levels of a mechanism file",
            )
        if isinstance(value, dict):
            stack += [
                (v, f"{entry}.{key_text(k)}" if entry else key_text(k), depth + 1)
                for k, v in value.items()
            ]
        elif isinstance(value, list):
            stack += [(v, f"{entry}[{i}]", depth + 1) for i, v in enumerate(value)]


_HEADER = re.compile(r"^\s*(\[\[?)\s*([^\[\]#]+?)\s*\]\]?\s*(#.*)?$")
_TOML_KEY = re.compile(r"([A-Za-z0-9_.\- \"']+?)\s*=\s*[^={}]*$")
_JSON_KEY = re.compile(r'"([^"\\]{1,40})"\s*:\s*[^"{}:]*$')


def _long_integer(text: str, json_format: bool) -> str | None:
    """Return the message of an integer too long for Python, naming its entry."""
    limit = sys.get_int_max_str_digits()
    if limit == 0:
        return None
    for match in re.finditer(rf"[0-9][0-9_]{{{limit},}}", text):
        digits = sum(c.isdigit() for c in match.group())
        if digits <= limit:
            continue
        start = match.start()
        line = text.count("\n", 0, start) + 1
        before = text[text.rfind("\n", 0, start) + 1 : start]
        key = (_JSON_KEY if json_format else _TOML_KEY).search(before)
        entry = "" if key is None else key.group(1).strip().strip("\"'")
        if entry and not json_format:
            entry = _toml_table(text, start) + entry
        where = f"{key_text(entry)} (line {line})" if entry else f"line {line}"
        return (
            f"{where}: an integer of {digits} digits; expected a number of at most "
            f"{limit} digits"
        )
    return None


def _toml_table(text: str, end: int) -> str:
    """Return the dotted name, with a dot, of the TOML table open at ``end``."""
    table = ""
    counts: dict[str, int] = {}
    for line in text[:end].splitlines():
        match = _HEADER.match(line)
        if match is None:
            continue
        name = ".".join(part.strip().strip("\"'") for part in match.group(2).split("."))
        if match.group(1) == "[[":
            counts[name] = counts.get(name, -1) + 1
            table = f"{name}[{counts[name]}]."
        else:
            table = f"{name}."
    return table


class _Object(dict):  # type: ignore[type-arg]
    """A JSON object that remembers the keys it was given twice."""

    twice: tuple[str, ...] = ()


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """JSON object hook: a key given twice is an error, as it is in TOML."""
    out = _Object(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        twice = []
        for key, _ in pairs:
            if key in seen:
                twice.append(key)
            seen.add(key)
        out.twice = tuple(twice)
    return out
