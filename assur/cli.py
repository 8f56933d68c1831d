"""Command line: ``assur structure|kinematics|forces|plot|diagrams|animate|report``.

A thin edge over the library: it parses arguments, reads the mechanism file, runs the
analysis and writes text, CSV or JSON. Any error of the input, of an option or of an
output becomes one line on standard error and exit status 2; Ctrl-C exits with 130.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import sys
import warnings
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from assur._cli_common import (
    check_not_input,
    load_mechanism,
    parse_angles,
    positions,
)
from assur._output import path_text, write_stdout
from assur._text import describe, suggest
from assur.errors import (
    AssurError,
    AssurWarning,
    DecompositionError,
    OutputError,
    UsageError,
)

__all__ = ["main", "parse_angles"]

COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {}
INTERRUPTED = 130
"""Exit status after Ctrl-C (128 + SIGINT), as shells report it."""
SUMMARY_ROWS = 400
"""Most rows of the readable table; --csv and --json give them all."""


def _parser() -> tuple[argparse.ArgumentParser, list[str]]:
    """Return the parser and the names of its commands."""
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
    return parser, list(sub.choices)


def _add_picture_commands(sub: Any) -> None:
    """Register the commands of :mod:`assur.pictures_cli` when it is present."""
    try:
        from assur import pictures_cli
    except ImportError:  # pragma: no cover - pictures are optional in a slim build
        return
    COMMANDS.update(pictures_cli.register(sub))


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status.

    0 when done, 2 for bad input or an output that cannot be written (one line on
    standard error), 130 after Ctrl-C. A reader of standard output that has gone
    (``| head``) ends the command quietly with status 0.
    """
    try:
        with _lenient_streams():
            return _main(list(sys.argv[1:] if argv is None else argv))
    except KeyboardInterrupt:
        try:
            sys.stdout.flush()
        except OSError:
            _quiet_stdout()
        print("assur: interrupted", file=sys.stderr)
        return INTERRUPTED


def _main(argv: list[str]) -> int:
    """Parse ``argv`` and run its command (see :func:`main`)."""
    parser, commands = _parser()
    # a range may start below zero: keep "--angles -30:30:10" from reading as an option
    for i in range(len(argv) - 1):
        if argv[i] in ("--angles", "--angle") and argv[i + 1].startswith("-"):
            argv[i : i + 2] = [f"{argv[i]}={argv[i + 1]}", ""]
    argv = [a for a in argv if a != ""]
    if argv and not argv[0].startswith("-") and argv[0] not in commands:
        parser.print_usage(sys.stderr)
        hint = suggest(argv[0], commands)
        print(
            f"assur: error: unknown command {describe(argv[0])}{hint}", file=sys.stderr
        )
        return 2
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0)
    handler = COMMANDS.get(args.command) or globals()[f"_cmd_{args.command}"]
    try:
        status = _run(handler, args)
        sys.stdout.flush()
    except BrokenPipeError:
        # the reader (``| head``) has gone: stop quietly, as command-line tools do
        _quiet_stdout()
        return 0
    except OSError as err:  # standard output on a full disk, say
        _quiet_stdout()
        print(
            f"assur: error: standard output: cannot write ({err.strerror or err})",
            file=sys.stderr,
        )
        return 2
    return status


@contextlib.contextmanager
def _lenient_streams() -> Iterator[None]:
    """Write what a terminal's encoding cannot show as backslash escapes."""
    saved = []
    for stream in (sys.stdout, sys.stderr):
        errors = getattr(stream, "errors", None)
        if errors in (None, "backslashreplace") or not hasattr(stream, "reconfigure"):
            continue
        with contextlib.suppress(OSError, ValueError):
            stream.reconfigure(errors="backslashreplace")
            saved.append((stream, errors))
    try:
        yield
    finally:
        for stream, errors in saved:
            with contextlib.suppress(OSError, ValueError):
                stream.reconfigure(errors=errors)


def _quiet_stdout() -> None:
    """Point standard output at nothing, so the exit does not flush it again."""
    try:
        descriptor = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):
        return  # not a file: nothing flushes at exit
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, descriptor)
    finally:
        os.close(devnull)


def _run(handler: Callable[[argparse.Namespace], int], args: argparse.Namespace) -> int:
    """Run one command, turning assur's errors and warnings into one-line messages."""
    source = path_text(args.file)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", AssurWarning)
        try:
            status = handler(args)
        except OutputError as err:  # names the output, not the mechanism file
            _error(str(err))
            status = 2
        except AssurError as err:
            text = str(err)
            _error(text if text.startswith(source) else f"{source}: {text}")
            status = 2
        except BrokenPipeError:
            raise  # the reader of standard output has gone: main stops quietly
        except OSError as err:
            reason = err.strerror or str(err)
            if err.filename:
                _error(f"{path_text(err.filename)}: {reason}")
            else:
                _error(f"standard output: cannot write ({reason})")
            status = 2
        except MemoryError:
            _error(
                f"{source}: out of memory; expected fewer positions (--angles) or a "
                "smaller output"
            )
            status = 2
    # shown only once the recording has stopped, so showing cannot record again
    for w in caught:
        if issubclass(w.category, AssurWarning):
            print(f"assur: warning: {source}: {_one_line(w.message)}", file=sys.stderr)
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    return status


def _one_line(text: object) -> str:
    """Return a message on one line."""
    return " ".join(str(text).split())


def _say(text: str) -> None:
    """Print ``text`` on standard output; a write that fails there raises."""
    write_stdout(text + "\n")


def _error(text: str) -> None:
    """Print the one error line of a command."""
    print(f"assur: error: {_one_line(text)}", file=sys.stderr)


def _cmd_structure(args: argparse.Namespace) -> int:
    from assur._structure import structure

    mech = load_mechanism(args.file)
    try:
        s = structure(mech, driver=args.driver)
    except DecompositionError as err:
        if args.driver is not None and str(err).startswith("--driver:"):
            raise UsageError(str(err)) from err  # the option, not the file
        raise
    _say(json.dumps(s.to_dict(), indent=2) if args.json else str(s))
    return 0


def _cmd_kinematics(args: argparse.Namespace) -> int:
    from assur.analysis import kinematics

    if args.csv:
        check_not_input("--csv", args.csv, args.file)
    mech = load_mechanism(args.file)
    table = kinematics(mech, positions(mech, args.angles), args.skip_unassembled)
    return _emit(args, table, _summary_columns(table, force=False))


def _cmd_forces(args: argparse.Namespace) -> int:
    from assur.analysis import forces

    if args.csv:
        check_not_input("--csv", args.csv, args.file)
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
            f"assur: note: {path_text(args.file)}: left out {len(table.skipped)} "
            f"position(s) that cannot be assembled: {skipped}",
            file=sys.stderr,
        )
    if args.csv:
        table.to_csv(args.csv if args.csv == "-" else Path(args.csv))
        if args.csv != "-":
            print(
                f"wrote {len(table)} rows x {len(table.columns)} columns to "
                f"{path_text(args.csv)}"
            )
        return 0
    if args.json:
        _say(json.dumps(table.to_dict()))
        return 0
    _say(format_table(table, summary))
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


def format_table(table: Any, columns: list[str], limit: int = SUMMARY_ROWS) -> str:
    """Return an aligned text table of ``columns`` with a units row.

    Beyond ``limit`` rows, a last line says how many were left out.
    """
    heads = list(columns)
    units = [f"[{_unit(c, table)}]" if _unit(c, table) else "" for c in columns]
    rows = [
        [f"{v:.6g}" for v in values]
        for values in zip(*(table[c][:limit] for c in columns), strict=True)
    ]
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
    if len(table) > limit:
        lines.append(
            f"... {len(table) - limit} more rows: --csv PATH or --json for all"
        )
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
