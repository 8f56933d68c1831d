"""The options of ``assur dynamics``, checked before anything is computed.

A flywheel, a number of turns, a coefficient of speed fluctuation out of range, or
output files that clash or cannot be written (Parquet without pyarrow), are refused
as a :class:`~assur.errors.UsageError`.
"""

from __future__ import annotations

import argparse

from assur._checks import LARGEST
from assur._cli_common import (
    check_distinct,
    check_not_input,
    check_table_suffix,
    is_stdout,
)
from assur._cli_tables import check_off_stdout, check_parquet
from assur._output import path_text
from assur._startup_checks import MOST_TURNS
from assur.dynamics_flywheel import SMALLEST_DELTA, delta_in_range
from assur.dynamics_model import flywheel_in_range
from assur.errors import UsageError


def _check_options(args: argparse.Namespace) -> None:
    """Refuse options that cannot be used, before anything is computed."""
    if args.flywheel is not None and not flywheel_in_range(args.flywheel):
        msg = (
            f"--flywheel {args.flywheel:g}: expected an inertia >= 0, kg m^2 (at "
            f"most {LARGEST:g})"
        )
        raise UsageError(msg)
    if args.turns is not None and not 1 <= args.turns <= MOST_TURNS:
        msg = (
            f"--turns {args.turns}: expected a whole number of turns from 1 to "
            f"{MOST_TURNS} (each turn's samples are kept)"
        )
        raise UsageError(msg)
    if args.turns is not None and not (args.startup or args.startup_csv is not None):
        # only the start-up counts turns: the option alone did nothing, silently
        msg = f"--turns {args.turns}: expected --startup (or --startup-csv) with it"
        raise UsageError(msg)
    if args.delta is not None and not delta_in_range(args.delta):
        msg = (
            f"--delta {args.delta:g}: expected a coefficient of speed fluctuation "
            f"from {SMALLEST_DELTA:g} to below 2, such as 0.02"
        )
        raise UsageError(msg)
    if args.csv and is_stdout(args.csv):
        # /dev/stdout and its kin are written as "-" is: no file replaced there
        shown = args.csv if args.csv == "-" else path_text(args.csv)
        if args.json:
            msg = (
                f"--csv {shown} and --json: both write to standard output; expected "
                "one of them"
            )
            raise UsageError(msg)
        args.csv = "-"
    if args.csv:
        check_not_input("--csv", args.csv, args.file)
        check_table_suffix("--csv", args.csv, "CSV")
    if args.parquet:
        check_off_stdout(args, "--parquet")
        check_parquet(args.parquet)
        check_not_input("--parquet", args.parquet, args.file)
        check_table_suffix("--parquet", args.parquet, "Parquet")
    if args.startup_csv is not None:
        if is_stdout(args.startup_csv):
            msg = (
                f"--startup-csv {args.startup_csv}: expected a file of its own "
                "(not standard output, nor the --csv file)"
            )
            raise UsageError(msg)
        check_not_input("--startup-csv", args.startup_csv, args.file)
        check_table_suffix("--startup-csv", args.startup_csv, "CSV")
    check_distinct(
        [
            ("--csv", args.csv),
            ("--parquet", args.parquet),
            ("--startup-csv", args.startup_csv),
        ]
    )
