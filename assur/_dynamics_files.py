"""The outputs of ``assur dynamics``: its table streamed, its files whole or none.

A long sweep is never held whole: :func:`stream` computes the table slice by slice
(``rows.part``) and hands each slice to every writer; :func:`write_files` writes the
start-up's samples and the table's ``--csv PATH`` and ``--parquet PATH`` files, all
of them landing or none.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np

from assur._cli_common import bar_shown, is_stdout, quiet
from assur._cli_tables import open_output
from assur._landing import together
from assur._output import finishing, output_path, path_text, write_bytes
from assur._progress import BAR_DELAY, progress
from assur._tableio import CsvWriter, ParquetWriter
from assur._text import counted

__all__ = ["SLICE", "stream", "write_files"]

SLICE = 65536
"""Rows computed and written at once (the table is never held whole)."""


def stream(rows: Any, writers: Sequence[Any], args: argparse.Namespace) -> None:
    """Write every slice of ``rows`` with each of ``writers``; a bar on a long sweep.

    ``rows`` gives ``len(rows)``, ``rows.names`` and ``rows.part(start, stop)``, a
    table of those rows: each slice is computed once, whatever the writers.
    """
    n = len(rows)
    show = bar_shown(args, bool(args.json), args.csv, args.parquet)
    with progress("dynamics", n, show, BAR_DELAY, " positions") as bar:
        for start in range(0, n, SLICE):
            part = rows.part(start, min(start + SLICE, n))
            columns = [np.asarray(part[c], dtype=float) for c in rows.names]
            for writer in writers:
                writer.write(columns)
            bar.advance(len(part))
            del part, columns  # one slice in memory at a time


def write_files(
    args: argparse.Namespace, files: list[tuple[Any, str, int, int]], rows: Any
) -> None:
    """Write the files asked for, whole or none of them; say so.

    ``files`` holds ``(path, text, rows, columns)`` (the start-up's samples); with
    ``rows`` (as :func:`stream` reads them) the table goes to ``--csv PATH`` and
    ``--parquet PATH``, both from one pass over the sweep.
    """
    written = []
    with together(), contextlib.ExitStack() as stack:
        for path, text, count, columns in files:
            write_bytes(path, text.encode("utf-8"))  # lands with the others
            written.append((path, count, columns))
        writers: list[Any] = []
        if rows is not None and args.csv and args.csv != "-":
            write, _ = open_output(stack, args.csv)
            table = CsvWriter(write, rows.names)
            writers.append(stack.enter_context(finishing(table)))
            written.append((args.csv, len(rows), len(rows.names)))
        if rows is not None and args.parquet:
            temporary = stack.enter_context(output_path(args.parquet))
            binary = ParquetWriter(temporary, rows.mech.name, rows.names, rows.units)
            writers.append(stack.enter_context(finishing(binary)))
            written.append((args.parquet, len(rows), len(rows.names)))
        if writers:
            stream(rows, writers, args)
    _wrote(args, written)


def _wrote(args: argparse.Namespace, written: list[tuple[Any, int, int]]) -> None:
    """Say which files were written (``(path, rows, columns)``), unless --quiet."""
    if quiet(args):
        return
    # standard output may carry the table, the JSON or the Parquet file (a pipe as
    # /dev/stdout): the lines go to stderr then
    binary = bool(args.parquet) and is_stdout(args.parquet)
    lines = sys.stderr if (args.json or args.csv == "-" or binary) else sys.stdout
    for path, rows, columns in written:
        size = f"{counted(rows, 'row')} x {counted(columns, 'column')}"
        print(f"wrote {size} to {path_text(path)}", file=lines)
