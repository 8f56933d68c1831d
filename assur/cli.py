"""Command line: ``assur structure|kinematics|forces|plot|diagrams|animate|report``.

A thin edge over the library: it parses arguments, reads the mechanism file, runs the
analysis and writes text, CSV or JSON. Any error of the input becomes one line on
standard error and exit status 2.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from assur.errors import AssurError, AssurWarning, ModelError

__all__ = ["main", "parse_angles"]

COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {}
MAX_POSITIONS = 10_000_000
"""Most driver positions one command analyses (the library takes any number)."""


def parse_angles(spec: str, drivers: int = 1) -> np.ndarray:
    """Parse ``START:STOP:STEP`` (STOP included when on the grid) or a single value.

    Several drivers take one range each, separated by commas, with equal counts.

    Examples
    --------
    >>> parse_angles("0:90:45").tolist()
    [0.0, 45.0, 90.0]
    >>> parse_angles("0:10:5,30:40:5", drivers=2).tolist()
    [[0.0, 30.0], [5.0, 35.0], [10.0, 40.0]]
    """
    parts = spec.split(",")
    if len(parts) != drivers:
        msg = (
            f"--angles: {len(parts)} range(s) given for {drivers} driver(s); expected "
            "one START:STOP:STEP per driver, separated by commas"
        )
        raise ModelError(msg)
    ranges = [_one_range(part) for part in parts]
    if len({len(r) for r in ranges}) != 1:
        counts = ", ".join(str(len(r)) for r in ranges)
        msg = f"--angles: the ranges have {counts} positions; expected equal counts"
        raise ModelError(msg)
    return ranges[0] if drivers == 1 else np.stack(ranges, axis=-1)


def _one_range(text: str) -> np.ndarray:
    fields = text.split(":")
    try:
        values = [float(f) for f in fields]
    except ValueError:
        values = []
    if len(values) == 1 and math.isfinite(values[0]):
        return np.array(values)
    if (
        len(values) != 3
        or not all(map(math.isfinite, values))
        or values[2] == 0
        or (values[1] - values[0]) / values[2] < 0
    ):
        msg = (
            f"--angles: cannot read {text!r}; expected START:STOP:STEP with a step "
            "that leads from START to STOP, or a single value"
        )
        raise ModelError(msg)
    start, stop, step = values
    count = math.floor((stop - start) / step + 1e-9) + 1
    if count > MAX_POSITIONS:
        msg = (
            f"--angles: {text!r} gives {count} positions; expected at most "
            f"{MAX_POSITIONS} (a larger step)"
        )
        raise ModelError(msg)
    return start + step * np.arange(count)


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assur",
        description="Kinetostatic analysis of planar linkages, built on Assur groups.",
    )
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("structure", help="degrees of freedom and Assur groups")
    p.add_argument("file", type=Path)
    p.add_argument(
        "--json", action="store_true", help="print JSON instead of the report"
    )
    p.add_argument("--driver", metavar="JOINT", help="analyse with this joint as input")
    for name, text in (
        ("kinematics", "positions, velocities, accelerations, jerks"),
        ("forces", "inertia loads, joint reactions, balancing torque"),
    ):
        p = sub.add_parser(name, help=text)
        p.add_argument("file", type=Path)
        p.add_argument(
            "--angles",
            metavar="START:STOP:STEP",
            help="driver positions, deg (m for a prismatic driver); default: "
            "one turn from the reference pose in steps of 1 deg",
        )
        p.add_argument(
            "--csv", metavar="PATH", help="write the full table as CSV ('-': stdout)"
        )
        p.add_argument(
            "--json", action="store_true", help="print the full table as JSON"
        )
        p.add_argument(
            "--skip-unassembled",
            action="store_true",
            help="leave out positions that cannot be assembled",
        )
    _add_picture_commands(sub)
    return parser


def _add_picture_commands(sub: Any) -> None:
    """Register the commands of :mod:`assur.pictures_cli` when it is present."""
    try:
        from assur import pictures_cli
    except ImportError:  # pragma: no cover - pictures are optional in a slim build
        return
    COMMANDS.update(pictures_cli.register(sub))


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status (0 fine, 2 bad input)."""
    parser = _parser()
    argv = list(sys.argv[1:] if argv is None else argv)
    # a range may start below zero: keep "--angles -30:30:10" from reading as an option
    for i in range(len(argv) - 1):
        if argv[i] in ("--angles", "--angle") and argv[i + 1].startswith("-"):
            argv[i : i + 2] = [f"{argv[i]}={argv[i + 1]}", ""]
    argv = [a for a in argv if a != ""]
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    handler = COMMANDS.get(args.command) or globals()[f"_cmd_{args.command}"]
    try:
        return _run(handler, args)
    except BrokenPipeError:
        # the reader (``| head``) has gone: stop quietly, as command-line tools do
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - keeps exit from flushing
        return 0


def _run(handler: Callable[[argparse.Namespace], int], args: argparse.Namespace) -> int:
    """Run one command, turning assur's errors and warnings into one-line messages."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", AssurWarning)
        try:
            status = handler(args)
        except AssurError as err:
            text = str(err)
            path = str(args.file)
            if not text.startswith(path):
                text = f"{path}: {text}"
            print(f"assur: error: {text}", file=sys.stderr)
            status = 2
        except BrokenPipeError:
            raise  # the reader has gone: main stops quietly
        except OSError as err:  # an output path that cannot be written
            where = err.filename or args.file
            print(
                f"assur: error: {where}: cannot write ({err.strerror or err})",
                file=sys.stderr,
            )
            status = 2
    # shown only once the recording has stopped, so showing cannot record again
    for w in caught:
        if issubclass(w.category, AssurWarning):
            print(f"assur: warning: {args.file}: {w.message}", file=sys.stderr)
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    return status


def load_mechanism(path: Path) -> Any:
    """Read the mechanism file named on the command line."""
    from assur.io import load

    return load(path)


def positions(mech: Any, spec: str | None) -> np.ndarray:
    """Driver positions from ``--angles`` or the default full turn."""
    from assur.analysis import default_positions

    if spec is None:
        return default_positions(mech)
    return parse_angles(spec, max(1, len(mech.drivers)))


def _cmd_structure(args: argparse.Namespace) -> int:
    from assur._structure import structure

    s = structure(load_mechanism(args.file), driver=args.driver)
    print(json.dumps(s.to_dict(), indent=2) if args.json else str(s))
    return 0


def _cmd_kinematics(args: argparse.Namespace) -> int:
    from assur.analysis import kinematics

    mech = load_mechanism(args.file)
    table = kinematics(mech, positions(mech, args.angles), args.skip_unassembled)
    return _emit(args, table, _summary_columns(table, force=False))


def _cmd_forces(args: argparse.Namespace) -> int:
    from assur.analysis import forces

    mech = load_mechanism(args.file)
    table = forces(mech, positions(mech, args.angles), args.skip_unassembled)
    return _emit(args, table, _summary_columns(table, force=True))


def _summary_columns(table: Any, force: bool) -> list[str]:
    """Pick the readable table's columns.

    Reaction magnitudes and balancing loads, or the links' angles, speeds and
    accelerations.
    """
    if not force:
        return [
            "angle",
            *(c for c in table.columns if c.endswith((".angle", ".omega", ".alpha"))),
        ]
    drivers = {
        f"{d.joint}.{what}"
        for d in table.mechanism.drivers
        for what in ("torque", "force", "torque_check", "force_check")
    }
    picked = [
        c
        for c in table.columns
        if c.endswith(".F") or c.startswith("driver.") or c in drivers
    ]
    return ["angle", *picked]


def _emit(args: argparse.Namespace, table: Any, summary: list[str]) -> int:
    if len(table.skipped):
        skipped = ", ".join(f"{x:g}" for x in np.ravel(table.skipped)[:20])
        skipped += ", ..." if np.size(table.skipped) > 20 else ""
        print(
            f"assur: note: {args.file}: left out {len(table.skipped)} position(s) that "
            f"cannot be assembled: {skipped}",
            file=sys.stderr,
        )
    if args.csv:
        table.to_csv(args.csv if args.csv == "-" else Path(args.csv))
        if args.csv != "-":
            print(
                f"wrote {len(table)} rows x {len(table.columns)} columns to {args.csv}"
            )
        return 0
    if args.json:
        print(json.dumps(table.to_dict()))
        return 0
    print(format_table(table, summary))
    print(
        f"({len(table.columns)} columns in all: --csv PATH or --json for the full "
        "table)"
    )
    return 0


UNITS = {
    ".angle": "deg",
    ".omega": "rad/s",
    ".alpha": "rad/s2",
    ".F": "N",
    "torque": "N m",
    "torque_check": "N m",
    "force": "N",
    "force_check": "N",
}


def _unit(column: str, table: Any) -> str:
    if column == "angle":
        return "deg" if table.mechanism and _revolute_driver(table) else "m"
    for suffix, unit in UNITS.items():
        if column.endswith(suffix):
            return unit
    return ""


def _revolute_driver(table: Any) -> bool:
    return bool(table.plan.drivers[0].kind == "R")


def format_table(table: Any, columns: list[str], limit: int = 400) -> str:
    """Return an aligned text table of ``columns`` with a units row."""
    heads = list(columns)
    units = [f"[{_unit(c, table)}]" if _unit(c, table) else "" for c in columns]
    rows = [
        [f"{v:.6g}" for v in values]
        for values in zip(*(table[c] for c in columns), strict=True)
    ]
    if len(rows) > limit:
        rows = rows[:limit]
    widths = [
        max(len(h), len(u), *(len(r[i]) for r in rows)) if rows else max(len(h), len(u))
        for i, (h, u) in enumerate(zip(heads, units, strict=False))
    ]
    lines = [
        "  ".join(h.rjust(w) for h, w in zip(heads, widths, strict=False)),
        "  ".join(u.rjust(w) for u, w in zip(units, widths, strict=False)),
    ]
    lines += [
        "  ".join(v.rjust(w) for v, w in zip(r, widths, strict=True)) for r in rows
    ]
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
