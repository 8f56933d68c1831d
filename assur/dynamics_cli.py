"""Command line: ``assur dynamics FILE [--flywheel J | --delta D] [--forces] ...``.

:mod:`assur.cli` calls :func:`register` to add the command. It prints the figures of
the steady state (the coefficient of speed fluctuation, the flywheel, the motor
torque) and the table of the reduced quantities and the crank's motion; with
``--forces`` the force table at that motion, with ``--startup`` the start-up under
the file's motor. Tables go out whole or not at all (:mod:`assur._output`); faults
raise :class:`~assur.errors.UsageError` or :class:`~assur.errors.ModelError`.
Its parts: the options checked (``assur._dynamics_options``), the figures given
(``assur._dynamics_figures``).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._cli_common import (
    check_structure,
    load_mechanism,
    parse_angles,
    quiet,
    terminal,
)
from assur._cli_summary import format_table, terminal_width
from assur._cli_types import (
    add_file_argument,
    given,
    number,
    whole_number,
)
from assur._dynamic_checks import check_dynamic
from assur._dynamics_figures import (
    _figures,
    _head,
    _header,
    _startup_data,
    startup_csv,
)
from assur._dynamics_files import SLICE, stream, write_files
from assur._dynamics_options import _check_options
from assur._dynamics_text import startup_lines
from assur._output import (
    StdoutError,
    stdout_writer,
    write_stdout,
)
from assur._startup_checks import MOST_TURNS
from assur._stdin import input_text
from assur._tableio import CsvWriter, JsonWriter
from assur._vec import Array
from assur._warn import held, warn
from assur.dynamics_flywheel import SMALLEST_DELTA
from assur.dynamics_model import COLUMNS, solved
from assur.dynamics_model import result as dynamics_rows
from assur.dynamics_startup import MAX_TURNS
from assur.errors import AssurWarning, ModelError

__all__ = ["register"]

ROWS_SHOWN = 400
"""Most rows of the readable tables; --csv and --json give them all."""


def register(sub: Any) -> dict[str, Callable[[argparse.Namespace], int]]:
    """Add the ``dynamics`` command to the ``sub`` parsers; return its handler."""
    p = sub.add_parser(
        "dynamics",
        help="dynamic model reduced to the crank: steady state, flywheel, start-up",
    )
    add_file_argument(p)
    p.add_argument(
        "--angles",
        metavar="START:STOP:STEP",
        help="crank angles of the table, deg; default: one turn from the reference "
        "pose in steps of 1 deg",
    )
    size = p.add_mutually_exclusive_group()
    size.add_argument(
        "--flywheel",
        type=number,
        metavar="J",
        help="flywheel on the crank, kg m^2 (default 0)",
    )
    size.add_argument(
        "--delta",
        type=number,
        metavar="D",
        help="find the flywheel for this coefficient of speed fluctuation "
        f"(max w - min w) / omega, from {SMALLEST_DELTA:g} to below 2",
    )
    p.add_argument(
        "--forces",
        action="store_true",
        help="add the force table at the steady motion (kinetostatics)",
    )
    p.add_argument(
        "--startup",
        action="store_true",
        help="integrate the start-up from rest under the file's [motor]",
    )
    p.add_argument(
        "--turns",
        type=whole_number,
        metavar="N",
        help=f"most turns the start-up may take to settle (default {MAX_TURNS}, at "
        f"most {MOST_TURNS}; with --startup or --startup-csv)",
    )
    p.add_argument(
        "--startup-csv",
        type=given,
        metavar="PATH",
        help="write the start-up's time, crank angle and speed as CSV (implies "
        "--startup)",
    )
    p.add_argument(
        "--csv", type=given, metavar="PATH", help="write the table as CSV ('-': stdout)"
    )
    p.add_argument(
        "--parquet",
        type=given,
        metavar="PATH",
        help="write the table as Parquet (needs pyarrow)",
    )
    p.add_argument("--json", action="store_true", help="print everything as JSON")
    return {"dynamics": _cmd_dynamics}


def _cmd_dynamics(args: argparse.Namespace) -> int:
    import assur
    from assur.analysis import default_positions

    _check_options(args)
    mech = load_mechanism(args.file)
    check_structure(mech)
    check_dynamic(mech)  # one crank and masses, before its --angles are read
    angles = (
        default_positions(mech) if args.angles is None else parse_angles(args.angles)
    )
    sizing = None
    inertia = 0.0 if args.flywheel is None else args.flywheel
    if args.delta is not None:
        sizing = assur.flywheel_sizing(mech, args.delta)
        inertia = sizing.exact
    start = args.startup or args.startup_csv is not None
    turns = MAX_TURNS if args.turns is None else args.turns
    run = None
    if start:
        shown = terminal() and not quiet(args)
        run = assur.startup(mech, inertia, turns=turns, progress=shown)
    try:
        state = solved(mech, inertia)
    except ModelError as err:
        if run is None or args.csv or args.parquet or args.forces:
            raise
        # a motor may carry the crank round where no steady state at the file's
        # omega (under a constant torque) exists: the start-up is still shown
        warn(f"{err}; shown: the start-up alone", AssurWarning, stacklevel=2)
        state = None
    startup_file = []
    if run is not None and args.startup_csv is not None:
        startup_file.append((args.startup_csv, startup_csv(run), len(run.time), 3))
    if state is None:
        _notes(args, mech)
        write_files(args, startup_file, None)
        if args.json:
            document = {"name": mech.name, "startup": _startup_data(run)}
            write_stdout(json.dumps(document) + "\n")
        else:
            write_stdout(_header(mech, startup_lines(run)) + "\n")
        return 0
    rows = _Rows(mech, state, angles, args.forces)
    rows.check()
    if args.json or args.csv == "-":
        # standard output that cannot take the table (a name its encoding cannot
        # write, UTF-16) stops the command before any file lands
        encode = stdout_writer()[1]
        if args.csv == "-":
            encode(",".join(rows.names))
    _notes(args, mech)
    # the files first, as a set: standard output read by a pipe may go away
    write_files(args, startup_file, rows)
    if args.json or args.csv == "-":
        write, encode = stdout_writer()
        try:
            head = _head(rows.first, sizing, run)
            out: CsvWriter | JsonWriter = (
                JsonWriter(
                    write, mech.name, rows.names, encode, head=head, units=rows.units
                )
                if args.json
                else CsvWriter(write, rows.names, encode)
            )
            stream(rows, [out], args)
            out.close()
            if args.json:
                write(encode("\n"))
        except StdoutError as err:
            raise err.error from None
    elif not (args.csv or args.parquet):
        shown = rows.part(0, ROWS_SHOWN)
        figures = _figures(rows.first, sizing, run)
        text = _readable(shown, args.forces, len(angles))
        write_stdout(figures + "\n\n" + text + "\n")
    return 0


def _notes(args: argparse.Namespace, mech: Any) -> None:
    """Tell what the dynamic model leaves out of the file, once the work is done."""
    if quiet(args):
        return
    where = f"assur: note: {input_text(args.file)}: the dynamic model leaves the"
    if any(j.friction > 0.0 for j in mech.joints):
        shown = (
            "; the force table's driver.torque overcomes it too (its "
            "driver.torque_ideal is the model's)"
            if args.forces
            else ""
        )
        print(f"{where} joints' friction out{shown}", file=sys.stderr)
    epsilon = float(mech.drivers[0].epsilon)
    if epsilon != 0.0:
        # the model finds the crank's acceleration from its equation of motion
        print(
            f"{where} driver's epsilon = {epsilon:g} rad/s^2 out: the crank's "
            "acceleration is its equation of motion's (driver.epsilon)",
            file=sys.stderr,
        )


class _Rows:
    """The dynamics table (and the forces at its motion) over a sweep, by slices.

    A long sweep is never held whole: each slice's rows are computed from the one
    steady state, as :func:`assur.dynamics <assur.dynamics_model.dynamics>`
    computes them all at once.
    """

    def __init__(self, mech: Any, state: Any, angles: Array, forces: bool) -> None:
        self.mech, self.state, self.angles, self.forces = mech, state, angles, forces
        self.checked = False
        model, steady = state
        # the figures of the steady state: the same whatever the rows
        self.first = dynamics_rows(mech, model, steady, angles[:1])
        first = self.part(0, 1)
        self.names = first.columns
        self.units = [first.column(name).unit for name in self.names]

    def part(self, start: int, stop: int) -> Any:
        """Return the rows ``start`` to ``stop`` (a Dynamics, or joined with forces)."""
        import assur

        model, steady = self.state
        result = dynamics_rows(self.mech, model, steady, self.angles[start:stop])
        if not self.forces:
            return result
        # said once by the check of the whole sweep
        with held() if self.checked else contextlib.nullcontext():
            motion = assur.forces(
                self.mech,
                result["angle"],
                omega=result["driver.omega"],
                epsilon=result["driver.epsilon"],
                jerk=result["driver.jerk"],
            )
        return _Joined(result, motion)

    def __len__(self) -> int:
        return int(self.angles.shape[0])

    def check(self) -> None:
        """Solve the forces over the whole sweep first, the balancing torque alone.

        A position that friction locks is then an error before any row is written,
        counted over the whole sweep, and a warning is given once, not per slice.
        """
        if not self.forces:
            return
        import assur

        model, steady = self.state
        parts = [
            dynamics_rows(self.mech, model, steady, self.angles[i : i + SLICE])
            for i in range(0, len(self), SLICE)
        ]
        assur.forces(
            self.mech,
            np.concatenate([p["angle"] for p in parts]),
            omega=np.concatenate([p["driver.omega"] for p in parts]),
            epsilon=np.concatenate([p["driver.epsilon"] for p in parts]),
            columns=["driver.torque"],
        )
        self.checked = True


class _Joined:
    """The dynamics table and the force table at its motion, side by side."""

    def __init__(self, result: Any, motion: Any) -> None:
        self.mechanism = result.mechanism
        self.parts = (result, motion)
        seen = set(result.columns)
        self.columns = (*result.columns, *(c for c in motion.columns if c not in seen))

    def __getitem__(self, name: str) -> Array:
        result, motion = self.parts
        return result[name] if name in result else motion[name]

    def __len__(self) -> int:
        return len(self.parts[0])

    def column(self, name: str) -> Any:
        result, motion = self.parts
        return result.column(name) if name in result else motion.column(name)

    def to_csv(self, path: Any = None) -> str | None:
        from assur.io import write_csv

        return write_csv(self, path)


def _readable(table: Any, forces: bool, total: int) -> str:
    """Return the first rows of the main columns as an aligned text table.

    ``table`` holds those rows, of ``total`` in the sweep.
    """
    own = len(COLUMNS)  # the dynamics' columns, then the forces'
    names = list(table.columns[:own])
    if forces:
        names += [
            c
            for c in table.columns[own:]
            if c.endswith((".F", "driver.torque", "driver.torque_check"))
        ]
    units = [table.column(c).unit for c in names]
    columns = [np.asarray(table[c])[:ROWS_SHOWN] for c in names]
    return format_table(names, units, columns, total, ROWS_SHOWN, terminal_width())
