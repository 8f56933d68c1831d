"""The tables of ``assur kinematics|forces``: a sweep analysed slice by slice.

The slices go to the outputs asked for (:mod:`assur._cli_tables`), or to the readable
table or the summary (:mod:`assur._cli_summary`); a long sweep on a terminal shows a
progress bar.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from collections.abc import Iterator
from typing import Any

from assur._cli_common import (
    bar_shown,
    is_stdout,
    load_mechanism,
    positions,
    quiet,
)
from assur._cli_summary import _summary, _summary_text, _summed, terminal_width
from assur._cli_tables import _check_outputs, _write_tables
from assur._output import path_text, write_stdout
from assur._progress import BAR_DELAY
from assur._skipped import Skipped
from assur._sliced import slices
from assur._text import counted

__all__ = ["_sweep"]


def _sweep(args: argparse.Namespace, forces: bool) -> int:
    """Analyse the sweep slice by slice; write its table or print its summary."""
    _check_outputs(args)
    mech = load_mechanism(args.file)
    given = positions(mech, args.angles)
    skipped = Skipped()
    from assur.summary import Summary

    summary = Summary() if getattr(args, "summary", False) else None
    tables = bool(args.csv or args.parquet or (args.json and summary is None))
    writing = tables or summary is not None
    with _bar(args, "forces" if forces else "kinematics", len(given)) as bar:
        told = None if bar is None or tables else bar.advance
        parts = slices(
            mech, given, forces, args.skip_unassembled, skipped, told, check=writing
        )
        if summary is not None:
            parts = _summed(parts, summary)
        if tables:
            rows, names = _write_tables(args, parts, bar)
        elif summary is not None:
            for _ in parts:
                pass
        else:
            text, names = _summary(parts, forces, terminal_width())
    hushed = quiet(args)
    if skipped.count and not hushed:
        print(skipped.note(args.file, given), file=sys.stderr)
    if summary is not None:
        write_stdout(_summary_text(mech.name, summary, args.json) + "\n")
    if not writing:
        write_stdout(text + "\n")
        if not hushed:
            full = "--csv PATH or --json for the full table"
            print(f"({len(names)} columns in all: {full})")
        return 0
    if not tables:
        return 0
    # standard output may carry a table: the lines then go to standard error
    lines = sys.stderr if args.json or is_stdout(args.csv or "") else sys.stdout
    for target in (args.csv, args.parquet):
        if target and not is_stdout(target) and not hushed:
            size = f"{counted(rows, 'row')} x {counted(len(names), 'column')}"
            print(f"wrote {size} to {path_text(target)}", file=lines)
    return 0


@contextlib.contextmanager
def _bar(args: argparse.Namespace, what: str, total: int) -> Iterator[Any]:
    """Yield a progress bar on a terminal (shown once the sweep runs long), or None."""
    # a summary is printed at the end: with --json too, nothing streams meanwhile
    json_table = bool(args.json) and not getattr(args, "summary", False)
    if not bar_shown(args, json_table, args.csv, args.parquet):
        yield None
        return
    from assur._progress import progress

    with progress(what, total, True, BAR_DELAY, " positions") as bar:
        yield bar
