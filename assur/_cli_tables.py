"""The tables of ``assur kinematics|forces``: their outputs checked, then written.

``--csv``, ``--parquet`` and ``--json`` are refused before anything is analysed when
they cannot be written (:func:`_check_outputs`); the sweep's slices are then written
to all of them, one slice in memory at a time (:func:`_write_tables`).
"""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Callable, Iterator
from typing import Any

from assur import _output
from assur._cli_common import (
    check_distinct,
    check_not_input,
    check_table_suffix,
    is_stdout,
)
from assur._landing import together
from assur._output import (
    StdoutError,
    finishing,
    output_path,
    path_text,
    stdout_writer,
    write_stdout,
)
from assur._sliced import Slice
from assur.errors import UsageError

__all__ = [
    "_check_outputs",
    "_write_tables",
    "check_off_stdout",
    "check_parquet",
    "open_output",
]


def _check_outputs(args: argparse.Namespace) -> None:
    """Refuse outputs that cannot be written, before anything is analysed."""
    for option, kind in (("--csv", "CSV"), ("--parquet", "Parquet")):
        target = getattr(args, option[2:])
        if target:
            check_not_input(option, target, args.file)
            check_table_suffix(option, target, kind)
    check_distinct([("--csv", args.csv), ("--parquet", args.parquet)])
    # /dev/stdout and its kin are standard output as much as "-" is
    csv = "-" if args.csv and is_stdout(args.csv) else args.csv
    shown = "-" if args.csv == "-" else path_text(args.csv)
    if csv == "-" and getattr(args, "summary", False):
        msg = (
            f"--csv {shown} and --summary: both write to standard output; expected "
            "--csv PATH with --summary"
        )
        raise UsageError(msg)
    if csv == "-" and args.json:
        msg = (
            f"--csv {shown} and --json: both write to standard output; expected one "
            "of them (or --csv PATH)"
        )
        raise UsageError(msg)
    for option in ("--csv", "--parquet"):
        check_off_stdout(args, option)
    check_parquet(args.parquet)


def check_off_stdout(args: argparse.Namespace, option: str) -> None:
    """Refuse ``option``'s file when it is standard output and a table goes there.

    /dev/stdout and its kin beside ``--json`` or ``--csv -``: two tables mixed in
    one stream.
    """
    on_stdout = "--json" if args.json else "--csv -" if args.csv == "-" else None
    target = getattr(args, option[2:])
    if on_stdout and target and target != "-" and is_stdout(target):
        msg = (
            f"{option} {path_text(target)}: is standard output, where {on_stdout} "
            "writes; expected a file of its own"
        )
        raise UsageError(msg)


def check_parquet(target: Any) -> None:
    """Refuse ``--parquet TARGET`` when it is standard output or pyarrow is missing."""
    if target == "-":
        msg = "--parquet -: a Parquet file is not text; expected a file name"
        raise UsageError(msg)
    if target:
        from assur._tableio import import_pyarrow

        try:
            import_pyarrow()
        except ImportError as err:
            msg = f"--parquet {path_text(target)}: {err}"
            raise UsageError(msg) from err


def _write_tables(
    args: argparse.Namespace, parts: Iterator[Slice], bar: Any
) -> tuple[int, tuple[str, ...]]:
    """Write every slice to the outputs asked for; return the rows and the columns."""
    rows = 0
    names: tuple[str, ...] = ()
    try:
        # the files land together at the end, --csv's and --parquet's
        with together(), contextlib.ExitStack() as stack:
            writers: list[Any] = []
            for part in parts:
                table = part.table
                if not writers:
                    names = table.columns
                    writers = _writers(args, stack, table, bar)
                arrays = part.arrays()
                for writer in writers:
                    writer.write(arrays)
                rows += len(table)
                if bar is not None:
                    bar.advance(len(table.skipped))
                del part, table, arrays  # one slice in memory at a time
    except StdoutError as err:
        raise err.error from None  # after the files' cleanup: main reports it
    for writer in writers:
        if isinstance(writer, _Spared) and writer.gone is not None:
            # the files are whole: main stops quietly, as for standard output alone
            raise writer.gone
    if _json_table(args):
        write_stdout("\n")  # the line that ends the JSON
    return rows, names


def _json_table(args: argparse.Namespace) -> bool:
    """Whether the table goes to standard output as JSON (``--json``, no summary)."""
    return bool(args.json) and not getattr(args, "summary", False)


class _Spared:
    """The writer of standard output beside file outputs.

    A reader that goes away (``| head``) stops the table on standard output, not
    the files asked for: they are written to the end; ``gone`` keeps the error.
    """

    def __init__(self, writer: Any) -> None:
        self.writer = writer
        self.gone: BrokenPipeError | None = None

    def write(self, columns: Any) -> None:
        self._guarded(self.writer.write, columns)

    def close(self) -> None:
        self._guarded(self.writer.close)

    def _guarded(self, action: Callable[..., None], *args: Any) -> None:
        if self.gone is not None:
            return
        try:
            action(*args)
        except StdoutError as err:
            if not isinstance(err.error, BrokenPipeError):
                raise
            self.gone = err.error


def _writers(
    args: argparse.Namespace, stack: contextlib.ExitStack, table: Any, bar: Any
) -> list[Any]:
    """Open the outputs asked for; return their writers (closed by ``stack``).

    The first writer tells the progress bar of the rows written.
    """
    from assur._tableio import CsvWriter, JsonWriter, ParquetWriter

    names, name = table.columns, table.mechanism.name
    advance = [None if bar is None else bar.advance]
    writers: list[Any] = []

    def told() -> Any:
        found, advance[0] = advance[0], None
        return found

    if args.csv:
        write, encode = open_output(stack, args.csv)
        writers.append(CsvWriter(write, names, encode, told()))
    if args.parquet:
        path = stack.enter_context(output_path(args.parquet))
        units = [table.column(c).unit for c in names]
        writers.append(ParquetWriter(path, name, names, units, told()))
    json_table = _json_table(args)
    if json_table:
        write, encode = open_output(stack, "-")
        units = [table.column(c).unit for c in names]
        writers.append(JsonWriter(write, name, names, encode, told(), units=units))
    if len(writers) > 1 and (json_table or args.csv == "-"):
        # standard output is one of the outputs, the files the others
        at = -1 if json_table else 0
        writers[at] = _Spared(writers[at])
    for writer in writers:
        stack.enter_context(finishing(writer))
    return writers


def open_output(stack: contextlib.ExitStack, target: str) -> tuple[Any, Any]:
    """Return the ``write(bytes)`` and ``encode(text)`` of an output (``-``: stdout)."""
    if target == "-":
        return stdout_writer()
    path = stack.enter_context(output_path(target))
    stream = stack.enter_context(path.open("wb"))
    return (lambda data: _output.write_all(stream, data)), None
