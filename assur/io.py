"""Mechanism files (TOML or JSON) and result tables (CSV, JSON).

Reading checks every key against the file contract and names the file and the entry
of any fault; writing gives back a file that reads to the same mechanism. The text's
syntax is read by :mod:`assur._file_syntax`, its entries by :mod:`assur._file_entries`;
:mod:`assur._file_text` writes it.
"""

from __future__ import annotations

import io
import json
from os import PathLike
from typing import TYPE_CHECKING, Any

from assur import _output
from assur._file_entries import parse
from assur._file_syntax import _decoded, file_data
from assur._file_text import toml_text
from assur._output import (
    StdoutError,
    finishing,
    output_path,
    path_text,
    stdout_writer,
    write_text,
)
from assur._text import python_value
from assur._vec import is_flag
from assur.errors import AssurError, ModelError, UsageError
from assur.model import Mechanism, mechanism_of

if TYPE_CHECKING:
    from pathlib import Path

__all__ = ["dumps", "load", "loads", "parse", "save", "write_csv", "write_parquet"]

MAX_FILE_BYTES = 16 * 2**20
"""Largest mechanism file read, bytes (16 MiB; a mechanism takes a few kB)."""


def load(path: str | Path) -> Mechanism:
    """Read a mechanism file (``.toml`` or ``.json``).

    Parameters
    ----------
    path : str or path-like
        The file; at most 16 MiB (``MAX_FILE_BYTES``) of UTF-8 text (a byte-order
        mark is welcome). A ``.json`` suffix (any case) reads JSON, any other TOML.

    Returns
    -------
    Mechanism
        The mechanism the file describes, validated.

    Raises
    ------
    ModelError
        With a one-line message naming the file, the entry and what is wrong.
    UsageError
        When ``path`` is not a path.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from assur import catalog
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "four_bar.toml"
    >>> save(catalog.four_bar(), path)
    >>> load(path) == catalog.four_bar()
    True
    """
    from pathlib import Path

    path = Path(_path(path, "the mechanism file's"))
    where = path_text(path)
    data = _read(path, where)
    try:
        return loads(_decoded(data), json_format=path.suffix.lower() == ".json")
    except AssurError as err:
        msg = f"{where}: {err}"
        raise type(err)(msg) from err


def _read(path: Path, where: str) -> bytes:
    """Return the bytes of the file ``path``, at most :data:`MAX_FILE_BYTES`."""
    return read_capped(
        path,
        where,
        MAX_FILE_BYTES,
        "a TOML or JSON file",
        "a mechanism file (a few kilobytes of TOML or JSON)",
    )


def read_capped(path: Any, where: str, most: int, kind: str, expected: str) -> bytes:
    """Return the bytes of the file ``path``: at most ``most`` of them, whole MiB.

    ``where`` names the file in messages; ``kind`` is what a folder was expected
    to be, ``expected`` what a file too large was expected to be.

    Raises
    ------
    ModelError
        When the file cannot be read or holds more than ``most`` bytes.
    """
    try:
        with open(path, "rb") as stream:
            # one byte beyond the cap tells a file too large from one just large
            data = stream.read(most + 1)
    except IsADirectoryError as err:
        msg = f"{where}: cannot read the file (it is a folder); expected {kind}"
        raise ModelError(msg) from err
    except OSError as err:
        msg = f"{where}: cannot read the file ({err.strerror or err})"
        raise ModelError(msg) from err
    except ValueError as err:  # a name with a NUL character
        msg = f"{where}: cannot read the file ({err})"
        raise ModelError(msg) from err
    if len(data) > most:
        msg = f"{where}: larger than {most // 2**20} MiB; expected {expected}"
        raise ModelError(msg)
    return data


def loads(text: str, json_format: bool = False) -> Mechanism:
    """Read a mechanism from TOML (or JSON) text.

    Parameters
    ----------
    text : str or bytes
        The text of a mechanism file (bytes are read as UTF-8, a byte-order mark
        welcome).
    json_format : bool, default False
        Read ``text`` as JSON instead of TOML.

    Returns
    -------
    Mechanism
        The mechanism the text describes, validated.

    Raises
    ------
    ModelError
        With a one-line message naming the entry and what is wrong.
    UsageError
        When ``text`` is not text, or is a file's path (a ``Path``, or one line
        ending in ``.toml`` or ``.json``): read a file with :func:`load`.
    """
    _check_flag(json_format)
    if isinstance(text, bytes | bytearray):
        text = _decoded(bytes(text))
    if not isinstance(text, str):
        hint = " (read a file with assur.load)" if isinstance(text, PathLike) else ""
        msg = f"text: expected a mechanism file's text, got {type(text).__name__}{hint}"
        raise UsageError(msg)
    if "\n" not in text.strip() and text.strip().lower().endswith((".toml", ".json")):
        # assur.loads("examples/x.toml") said "not valid TOML: Expected '='"
        msg = (
            f"text: {text.strip()!r} is a file's name; expected a mechanism file's "
            "text (read a file with assur.load)"
        )
        raise UsageError(msg)
    return parse(file_data(text, json_format))


def dumps(mechanism: Mechanism, json_format: bool = False) -> str:
    """Return the text of a mechanism file for ``mechanism``, TOML or JSON.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism to write.
    json_format : bool, default False
        Write JSON of the same keys and values instead of TOML.

    Returns
    -------
    str
        The file's text; :func:`loads` (with the same ``json_format``) reads it back
        as an equal mechanism.

    Raises
    ------
    UsageError
        When ``mechanism`` is not a :class:`~assur.model.Mechanism`.
    """
    _check_flag(json_format)
    if json_format:
        import tomllib

        # the TOML text's data, which holds exactly the mechanism's numbers
        text = dumps(mechanism)
        return json.dumps(tomllib.loads(text), indent=2, ensure_ascii=False)
    return toml_text(mechanism_of(mechanism))


def save(mechanism: Mechanism, path: str | Path) -> None:
    """Write ``mechanism`` as a mechanism file, whole or not at all.

    JSON for a ``.json`` suffix (any case), TOML for any other, as :func:`load` reads
    them. The file is written whole or not at all: to a temporary file beside it, then
    moved over it in one step.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism to write.
    path : str or path-like
        The file to write; a ``.json`` suffix writes JSON, any other TOML.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept.
    UsageError
        When ``path`` is not a path or ``mechanism`` not a Mechanism.
    """
    from pathlib import Path

    path = _path(path, "the file's")
    json_format = Path(path).suffix.lower() == ".json"
    write_text(path, dumps(mechanism, json_format=json_format))


def _path(path: Any, whose: str) -> Any:
    """Return ``path``, checked to be a file's path (str or path-like)."""
    if not isinstance(path, str | PathLike):
        msg = f"path: expected {whose} path, got {type(path).__name__}"
        raise UsageError(msg)
    return path


def write_csv(table: Any, path: Any = None) -> str | None:
    """Write a result table as CSV (12 significant digits); return it without path.

    Parameters
    ----------
    table : Table
    path : str, path-like, file object or "-", optional
        Where to write: a file (written whole or not at all: to a temporary file
        moved over it), an open text or binary stream (UTF-8), or ``"-"``
        for standard output.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept. For
        ``"-"``, also when standard output's encoding cannot write a column's name.

    Examples
    --------
    >>> from assur import catalog, kinematics
    >>> text = write_csv(kinematics(catalog.four_bar(), [0.0, 90.0]))
    >>> text.splitlines()[0].split(",")[:3]
    ['angle', 'crank.angle', 'crank.omega']
    """
    from assur._tableio import CsvWriter, table_columns

    columns = table_columns(table)
    if path is None:
        parts: list[bytes] = []
        CsvWriter(parts.append, table.columns).write(columns)
        return b"".join(parts).decode("utf-8")
    if isinstance(path, str) and path == "-":
        write, encode = stdout_writer()
        try:
            CsvWriter(write, table.columns, encode).write(columns)
        except StdoutError as err:
            raise err.error from None
    elif hasattr(path, "write"):
        # a binary stream (open(..., "wb"), io.BytesIO) takes the UTF-8 bytes
        binary = isinstance(path, io.RawIOBase | io.BufferedIOBase) or "b" in str(
            getattr(path, "mode", "")
        )
        write = path.write if binary else (lambda data: path.write(data.decode()))
        CsvWriter(write, table.columns).write(columns)
    else:
        path = _path(path, "a CSV file's")
        with output_path(path) as temporary, temporary.open("wb") as stream:
            # looked up when called: tests put a failing writer in its place
            CsvWriter(
                lambda data: _output.write_all(stream, data), table.columns
            ).write(columns)
    return None


def write_parquet(table: Any, path: Any) -> None:
    """Write a result table to a Parquet file (needs pyarrow).

    Every column is float64, named as in the table, with its unit in the field's
    metadata (key ``unit``); the schema's metadata holds the mechanism's name (key
    ``assur.name``). The rows go in groups of 65536 (``PARQUET_ROWS``). The file is
    written whole or not at all.

    Raises
    ------
    ImportError
        When pyarrow is not installed.
    OutputError
        When the file cannot be written; an old file of that name is kept.
    """
    from assur._tableio import (
        PARQUET_ROWS,
        ParquetWriter,
        import_pyarrow,
        table_columns,
    )

    import_pyarrow()
    columns = table_columns(table)
    units = [table.column(name).unit for name in table.columns]
    with output_path(_path(path, "a Parquet file's")) as temporary:
        writer = ParquetWriter(temporary, table.mechanism.name, table.columns, units)
        with finishing(writer):
            for start in range(0, len(table), PARQUET_ROWS):
                writer.write([c[start : start + PARQUET_ROWS] for c in columns])


def _check_flag(json_format: object) -> None:
    """Refuse a ``json_format`` that is not True or False.

    ``loads(text, "toml")`` read TOML as JSON: any non-empty string is true.
    """
    if not is_flag(json_format):
        msg = f"json_format: expected True or False, got {python_value(json_format)}"
        raise UsageError(msg)
