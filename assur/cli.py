"""Command line: ``assur structure|kinematics|forces|explain|dynamics|plot|...``.

A thin edge over the library: it parses arguments, reads the mechanism file, runs the
analysis and writes text, CSV or JSON. Any error of the input, of an option or of an
output becomes one line on standard error and exit status 2; Ctrl-C exits with 130.
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import json
import math
import os
import signal
import sys
import threading
import warnings
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn

import numpy as np

from assur import _output, _start
from assur._cli_common import (
    add_angle_option,
    check_distinct,
    check_not_input,
    file_name,
    given,
    input_file,
    is_stdout,
    load_mechanism,
    one_position,
    parse_angles,
    positions,
    terminal,
)
from assur._output import (
    StdoutError,
    finishing,
    output_path,
    path_text,
    stdout_writer,
    write_stdout,
)
from assur._sliced import Skipped, Slice, slices
from assur._text import describe, number_text, suggest
from assur._troubles import SKIPPED_WHY
from assur._vec import Array
from assur.errors import (
    AssurError,
    AssurWarning,
    DecompositionError,
    ModelError,
    OutputError,
    UsageError,
)

if TYPE_CHECKING:
    from assur.summary import Summary

__all__ = ["main", "parse_angles"]

COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {}
INTERRUPTED = 130
"""Exit status after Ctrl-C (128 + SIGINT), as shells report it."""
SUMMARY_ROWS = 400
"""Most rows of the readable table; --csv, --json and --parquet give them all."""
LONG_SWEEP = 100_000
"""Driver positions from which a sweep shows a progress bar (on a terminal)."""
QUIET = "no progress bars, no 'wrote ...' lines or notes (errors and warnings stay)"


class _Parser(argparse.ArgumentParser):
    """argparse's parser, except that a failed write of its help is not ignored.

    argparse drops the OSError of ``--help`` written to a full disk (exit 0, no
    help); here it reaches :func:`main`, which says so (exit 2).
    """

    def _print_message(self, message: str, file: Any = None) -> None:
        if message:
            (file or sys.stderr).write(message)

    def error(self, message: str) -> NoReturn:  # type: ignore[override]
        """Exit 2 with one line naming the command and the option at fault.

        argparse prints its usage block first (six lines for ``dynamics``): the
        line that says what is wrong is then the last of many.
        """
        # arguments no command takes are found by the top parser: name the command
        command = self.prog.partition(" ")[2] or self.command
        where, prog = (f"{command}: ", f"assur {command}") if command else ("", "assur")
        line = f"assur: error: {where}{message} (see '{prog} --help')"
        self.exit(2, " ".join(line.split()) + "\n")

    command = ""
    """The command being parsed, once known (see :func:`_main`)."""


def _parser() -> tuple[_Parser, list[str]]:
    """Return the parser and the names of its commands."""
    parser = _Parser(
        prog="assur",
        description="Kinetostatic analysis of planar linkages, built on Assur groups.",
    )
    parser.add_argument("-q", "--quiet", action="store_true", help=QUIET)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("structure", help="degrees of freedom and Assur groups")
    p.add_argument("file", type=input_file)
    p.add_argument(
        "--json", action="store_true", help="print JSON instead of the report"
    )
    p.add_argument("--driver", metavar="JOINT", help="analyse with this joint as input")
    for name, text in (
        ("kinematics", "positions, velocities, accelerations, jerks"),
        ("forces", "inertia loads, joint reactions, balancing torque"),
    ):
        p = sub.add_parser(name, help=text)
        p.add_argument("file", type=input_file)
        p.add_argument(
            "--angles",
            metavar="START:STOP:STEP",
            help="driver positions, deg (m for a prismatic driver); default: "
            "one turn from the reference pose in steps of 1 deg",
        )
        p.add_argument(
            "--csv",
            type=given,
            metavar="PATH",
            help="write the full table as CSV ('-': stdout)",
        )
        p.add_argument(
            "--json", action="store_true", help="print the full table as JSON"
        )
        p.add_argument(
            "--parquet",
            type=given,
            metavar="PATH",
            help="write the full table as Parquet (needs pyarrow)",
        )
        p.add_argument(
            "--skip-unassembled",
            action="store_true",
            help=f"leave out the positions {SKIPPED_WHY}",
        )
    p.add_argument(
        "--summary",
        action="store_true",
        help="print the summary instead of the table: largest and RMS reaction in "
        "every joint, balancing load, mean power, friction losses (JSON with --json)",
    )
    p = sub.add_parser("explain", help="the analysis at one position, step by step")
    p.add_argument("file", type=input_file)
    add_angle_option(p)
    p.add_argument(
        "-o",
        "--output",
        type=file_name,
        metavar="PATH",
        help="write the note to PATH: .md (Markdown), .html (MathML) or .tex "
        "(LaTeX); default: Markdown on standard output",
    )
    p.add_argument(
        "--answers",
        metavar="TOML",
        type=input_file,
        help="given answers to compare with (a table [answers] of quantity = value)",
    )
    from assur import dynamics_cli

    COMMANDS.update(dynamics_cli.register(sub))
    _add_picture_commands(sub)
    for p in sub.choices.values():
        # after the command too; SUPPRESS keeps an earlier --quiet
        p.add_argument(
            "-q", "--quiet", action="store_true", default=argparse.SUPPRESS, help=QUIET
        )
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
    standard error), 130 after Ctrl-C, 128 plus the signal's number after SIGTERM or
    SIGHUP (143, 129). A reader of standard output that has gone (``| head``) ends
    the command quietly with status 0.
    """
    try:
        _start.release()  # Ctrl-C is a KeyboardInterrupt again, caught below
        with _stoppable(), _closed_streams(), _lenient_streams():
            return _main(list(sys.argv[1:] if argv is None else argv))
    except (KeyboardInterrupt, _Stopped) as stop:
        try:
            sys.stdout.flush()
        except OSError:
            _quiet_stdout()
        if isinstance(stop, _Stopped):
            print("assur: terminated", file=sys.stderr)
            return 128 + stop.signum
        print("assur: interrupted", file=sys.stderr)
        return INTERRUPTED


RESEND = 0.5
"""Seconds after which SIGTERM or SIGHUP is sent again when Python ignored the
exception it raised."""


class _Stopped(BaseException):
    """SIGTERM or SIGHUP, raised where the command is: it unwinds like Ctrl-C."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


@contextlib.contextmanager
def _stoppable() -> Iterator[None]:
    """Let SIGTERM and SIGHUP end the command as Ctrl-C does, while it runs.

    By default they end the process at once, leaving an output's temporary file
    behind; raised as an exception, they remove it and keep the old file. (Only
    the main thread can take signals; SIGKILL cannot be taken at all.)
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    again: list[threading.Timer] = []

    def stop(signum: int, frame: Any) -> None:
        raise _Stopped(signum)

    previous = sys.unraisablehook

    def unraised(unraisable: Any) -> None:
        stopped = unraisable.exc_value
        if not isinstance(stopped, _Stopped):
            previous(unraisable)
            return
        # raised where Python ignores an exception (a __del__, a weakref callback
        # of matplotlib's), the stop left the command running: it comes again
        # shortly, unreported, until one lands where it unwinds the command
        timer = threading.Timer(RESEND, os.kill, (os.getpid(), stopped.signum))
        timer.daemon = True
        again.append(timer)
        timer.start()

    saved = {}
    for name in ("SIGTERM", "SIGHUP"):
        number = getattr(signal, name, None)
        if number is not None:
            saved[number] = signal.signal(number, stop)
    sys.unraisablehook = unraised
    try:
        yield
    finally:
        for timer in again:
            timer.cancel()
        for number, handler in saved.items():
            signal.signal(number, handler)
        sys.unraisablehook = previous


def _main(argv: list[str]) -> int:
    """Parse ``argv`` and run its command (see :func:`main`)."""
    parser, commands = _parser()
    argv = _joined_ranges(argv)
    if argv and not argv[0].startswith("-") and argv[0] not in commands:
        hint = suggest(argv[0], commands)
        print(
            f"assur: error: unknown command {describe(argv[0])}{hint}", file=sys.stderr
        )
        return 2
    parser.command = next((a for a in argv if a in commands), "")
    handler = None
    try:
        try:
            args = parser.parse_args(argv)
        except SystemExit as exc:
            # --help was printed (or a usage error): it must reach its reader
            status = int(exc.code or 0)
        else:
            handler = COMMANDS.get(args.command) or globals()[f"_cmd_{args.command}"]
        if handler is not None:
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


def _joined_ranges(argv: list[str]) -> list[str]:
    """Join ``--angles`` to a value that starts with a minus sign.

    A range may start below zero: "--angles -30:30:10" must not read as two options.
    Other arguments stay as they are, empty ones too (``--csv ''`` is refused by
    name, not taken for an option without its value).
    """
    joined: list[str] = []
    rest = iter(argv)
    for argument in rest:
        if argument in ("--angles", "--angle"):
            value = next(rest, None)
            if value is not None and value.startswith("-"):
                joined.append(f"{argument}={value}")
                continue
            joined.extend([argument] if value is None else [argument, value])
            continue
        joined.append(argument)
    return joined


class _Closed:
    """Standard output started closed (``>&-``): every write is an OSError.

    Python leaves ``sys.stdout`` None then; a command writing only files, with
    ``--quiet``, still runs, one that writes to standard output says it cannot.
    """

    encoding = "utf-8"
    errors = "strict"

    @property
    def buffer(self) -> _Closed:
        return self

    def write(self, data: Any) -> int:
        raise OSError(errno.EBADF, "standard output is closed")

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        raise OSError(errno.EBADF, "standard output is closed")


@contextlib.contextmanager
def _closed_streams() -> Iterator[None]:
    """Stand in for standard output or error when they started closed."""
    saved = sys.stdout, sys.stderr
    with contextlib.ExitStack() as stack:
        if sys.stdout is None:
            sys.stdout = _Closed()  # type: ignore[assignment]
        if sys.stderr is None:  # nowhere to say anything: the exit status speaks
            sys.stderr = stack.enter_context(open(os.devnull, "w"))
        try:
            yield
        finally:
            sys.stdout, sys.stderr = saved


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


class _OtherFileError(ModelError):
    """A fault of a file other than the mechanism's, which its message names."""


def _run(handler: Callable[[argparse.Namespace], int], args: argparse.Namespace) -> int:
    """Run one command, turning assur's errors and warnings into one-line messages."""
    source = path_text(args.file)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", AssurWarning)
        try:
            status = handler(args)
        except (OutputError, _OtherFileError) as err:  # not about the mechanism file
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
        text = str(err)
        if args.driver is not None and text.startswith("driver:"):
            # the option, not the file: named as the command line spells it
            text = "--" + text.replace("(driver= sets", "(--driver sets", 1)
            raise UsageError(text) from err
        raise
    _say(json.dumps(s.to_dict(), indent=2) if args.json else str(s))
    return 0


NOTE_SUFFIXES = (".md", ".markdown", ".html", ".htm", ".tex")
"""File types of ``assur explain -o``."""


def _cmd_explain(args: argparse.Namespace) -> int:
    from assur.explain import explain, read_answers

    if args.output is not None:
        suffix = Path(args.output).suffix.lower()
        if suffix not in NOTE_SUFFIXES:
            msg = (
                f"-o {path_text(args.output)}: unknown type of note "
                f"{describe(suffix or '(none)')}; expected .md, .html or .tex"
            )
            raise UsageError(msg)
        check_not_input("-o", args.output, args.file)
    mech = load_mechanism(args.file)
    angle = one_position(mech, args.angle)
    answers, source = None, ""
    if args.answers:
        try:
            answers, source = read_answers(args.answers)  # its errors name the file
        except ModelError as err:
            raise _OtherFileError(str(err)) from None
    try:
        note = explain(mech, angle, answers, source)
    except ModelError as err:
        if answers and str(err).startswith("answers."):
            # a quantity the mechanism does not have: a fault of the answers' file
            msg = f"{path_text(args.answers)}: {err}"
            raise _OtherFileError(msg) from None
        raise
    if args.output is None:
        _say(str(note).rstrip("\n"))
        return 0
    note.write(args.output)
    if not _quiet(args):
        print(f"wrote {path_text(args.output)}")
    return 0


def _cmd_kinematics(args: argparse.Namespace) -> int:
    return _sweep(args, forces=False)


def _cmd_forces(args: argparse.Namespace) -> int:
    return _sweep(args, forces=True)


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
            text, names = _summary(parts, forces)
    quiet = _quiet(args)
    if skipped.count and not quiet:
        print(skipped.note(args.file), file=sys.stderr)
    if summary is not None:
        _say(_summary_text(mech.name, summary, args.json))
    if not writing:
        _say(text)
        if not quiet:
            full = "--csv PATH or --json for the full table"
            print(f"({len(names)} columns in all: {full})")
        return 0
    if not tables:
        return 0
    # standard output may carry a table: the lines then go to standard error
    lines = sys.stderr if args.json or is_stdout(args.csv or "") else sys.stdout
    for target in (args.csv, args.parquet):
        if target and not is_stdout(target) and not quiet:
            size = f"{rows} rows x {len(names)} columns"
            print(f"wrote {size} to {path_text(target)}", file=lines)
    return 0


def _check_outputs(args: argparse.Namespace) -> None:
    """Refuse outputs that cannot be written, before anything is analysed."""
    for option in ("--csv", "--parquet"):
        target = getattr(args, option[2:])
        if target:
            check_not_input(option, target, args.file)
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
    on_stdout = "--json" if args.json else "--csv -" if args.csv == "-" else None
    for option in ("--csv", "--parquet"):
        target = getattr(args, option[2:])
        if on_stdout and target and target != "-" and is_stdout(target):
            # /dev/stdout and its kin: two tables mixed in one stream
            msg = (
                f"{option} {path_text(target)}: is standard output, where "
                f"{on_stdout} writes; expected a file of its own"
            )
            raise UsageError(msg)
    if args.parquet == "-":
        msg = "--parquet -: a Parquet file is not text; expected a file name"
        raise UsageError(msg)
    if args.parquet:
        from assur._tableio import import_pyarrow

        try:
            import_pyarrow()
        except ImportError as err:
            msg = f"--parquet {path_text(args.parquet)}: {err}"
            raise UsageError(msg) from err


def _quiet(args: argparse.Namespace) -> bool:
    return bool(getattr(args, "quiet", False))


@contextlib.contextmanager
def _bar(args: argparse.Namespace, what: str, total: int) -> Iterator[Any]:
    """Yield a progress bar for a long sweep on a terminal, else None."""
    if _quiet(args) or total < LONG_SWEEP or not terminal():
        yield None
        return
    from assur._progress import progress

    with progress(what, total, show=True) as bar:
        yield bar


def _write_tables(
    args: argparse.Namespace, parts: Iterator[Slice], bar: Any
) -> tuple[int, tuple[str, ...]]:
    """Write every slice to the outputs asked for; return the rows and the columns."""
    rows = 0
    names: tuple[str, ...] = ()
    try:
        with contextlib.ExitStack() as stack:
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
        _say("")
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
        write, encode = _open(stack, args.csv)
        writers.append(CsvWriter(write, names, encode, told()))
    if args.parquet:
        path = stack.enter_context(output_path(args.parquet))
        units = [table.column(c).unit for c in names]
        writers.append(ParquetWriter(path, name, names, units, told()))
    json_table = _json_table(args)
    if json_table:
        write, encode = _open(stack, "-")
        writers.append(JsonWriter(write, name, names, encode, told()))
    if len(writers) > 1 and (json_table or args.csv == "-"):
        # standard output is one of the outputs, the files the others
        at = -1 if json_table else 0
        writers[at] = _Spared(writers[at])
    for writer in writers:
        stack.enter_context(finishing(writer))
    return writers


def _open(stack: contextlib.ExitStack, target: str) -> tuple[Any, Any]:
    """Return the ``write(bytes)`` and ``encode(text)`` of an output (``-``: stdout)."""
    if target == "-":
        return stdout_writer()
    path = stack.enter_context(output_path(target))
    stream = stack.enter_context(path.open("wb"))
    return (lambda data: _output.write_all(stream, data)), None


def _summed(parts: Iterator[Slice], summary: Summary) -> Iterator[Slice]:
    """Yield the slices, each added to ``summary`` on its way."""
    for part in parts:
        summary.add(part.table)
        yield part


def _summary_text(name: str, summary: Summary, as_json: bool) -> str:
    """Return the summary as aligned lines with units, or as JSON."""
    from assur.summary import undefined

    values = summary.result()
    why = undefined(values)
    if as_json:
        data = {
            "name": name,
            "positions": summary.count,
            "summary": {k: v if math.isfinite(v) else None for k, v in values.items()},
            "units": {k: summary.units[k] for k in values},
        }
        if why:
            data["undefined"] = why  # why a value is null
        return json.dumps(data, indent=2)
    width = max(len(k) for k in values)
    lines = [f"Summary over {summary.count} positions ({name})"]
    for key, value in values.items():
        unit = summary.units[key]
        if key in why:
            lines.append(f"  {key.ljust(width)}  {'undefined':>14}  ({why[key]})")
            continue
        shown = number_text(value, ">14.6g")
        lines.append(f"  {key.ljust(width)}  {shown}  {unit}".rstrip())
    return "\n".join(lines)


def _summary(parts: Iterator[Slice], forces: bool) -> tuple[str, tuple[str, ...]]:
    """Return the readable table of the first rows and the table's column names."""
    names: tuple[str, ...] = ()
    picked: list[str] = []
    units: list[str] = []
    kept: list[list[Array]] = []
    rows = 0
    for part in parts:
        table = part.table
        if not names:
            names = table.columns
            picked = summary_columns(table, forces)
            units = [table.column(c).unit for c in picked]
        room = SUMMARY_ROWS - sum(len(k[0]) for k in kept)
        if room > 0 and len(table):
            kept.append([part.column(c)[:room] for c in picked])
        rows += len(table)
    columns = [np.concatenate(k) for k in zip(*kept, strict=True)] if kept else []
    return format_table(picked, units, columns, rows), names


def summary_columns(table: Any, forces: bool) -> list[str]:
    """Pick the readable table's columns from the table's schema.

    Kinematics: every link's angle, angular velocity and angular acceleration.
    Forces: the magnitude of every reaction and every balancing load with its
    virtual-power check (and, with friction, the load without friction).
    """
    if forces:
        families = {"magnitude", "balancing", "check", "ideal"}
        picked = [c.name for c in table.schema if c.family in families]
    else:
        picked = [
            c.name
            for c in table.schema
            if (c.family == "angle")
            or (c.family == "link" and c.quantity in ("omega", "alpha"))
        ]
    return ["angle", *picked]


def format_table(
    names: list[str],
    units: list[str],
    columns: list[Array],
    rows: int,
    limit: int = SUMMARY_ROWS,
) -> str:
    """Return an aligned text table of ``columns`` with a units row.

    ``rows`` is the number of rows in all; beyond the ``limit`` shown, a last line
    says how many were left out.
    """
    heads = list(names)
    marks = [f"[{u}]" if u else "" for u in units]
    cells = (
        [[number_text(v) for v in values] for values in zip(*columns, strict=True)]
        if columns
        else []
    )
    widths = [
        max(len(h), len(u), *(len(r[i]) for r in cells))
        for i, (h, u) in enumerate(zip(heads, marks, strict=True))
    ]
    lines = [
        "  ".join(h.rjust(w) for h, w in zip(heads, widths, strict=True)),
        "  ".join(u.rjust(w) for u, w in zip(marks, widths, strict=True)),
    ]
    lines += [
        "  ".join(v.rjust(w) for v, w in zip(r, widths, strict=True)) for r in cells
    ]
    if rows > limit:
        lines.append(f"... {rows - limit} more rows: --csv PATH or --json for all")
    return "\n".join(lines)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
