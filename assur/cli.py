"""Command line: ``assur structure|kinematics|forces|explain|dynamics|plot|...``.

A thin edge over the library: it parses arguments, reads the mechanism file, runs the
analysis and writes text, CSV or JSON. Any error of the input, of an option or of an
output becomes one line on standard error and exit status 2; Ctrl-C exits with 130.

This module holds :func:`main` and the dispatch to the commands; the parser and its
commands' options are :mod:`assur._cli_commands`'s, the signals and streams
:mod:`assur._cli_process`'s, sweeps :mod:`assur._cli_sweep`'s.
"""

from __future__ import annotations

import argparse
import errno
import json
import sys
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path

from assur import _cli_commands, _start
from assur._cli_commands import Handler
from assur._cli_common import (
    check_not_input,
    is_stdout,
    load_mechanism,
    one_position,
    parse_angles,
    quiet,
    skip_hint,
)
from assur._cli_parser import _Parser
from assur._cli_process import (
    _closed_streams,
    _lenient_streams,
    _plain_matplotlib,
    _quiet_stdout,
    _stoppable,
    _Stopped,
)
from assur._cli_sweep import _sweep
from assur._fonts import GLYPH_MISSING, glyphs_logged, missing_glyphs
from assur._output import path_text, write_stdout
from assur._stdin import input_text
from assur._text import describe, suggest
from assur.errors import (
    AssurError,
    AssurWarning,
    ModelError,
    OutputError,
    UsageError,
)

__all__ = ["main", "parse_angles"]


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status.

    0 when done, 2 for bad input or an output that cannot be written (one line on
    standard error), 130 after Ctrl-C, 128 plus the signal's number after SIGTERM or
    SIGHUP (143, 129). A reader of standard output that has gone (``| head``) ends
    the command quietly with status 0.
    """
    _plain_matplotlib()
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
        return _start.INTERRUPTED


def _main(argv: list[str]) -> int:
    """Parse ``argv`` and run its command (see :func:`main`)."""
    parser, commands = _parser()
    argv = _joined_ranges(argv)
    # the command comes first, or after the options of assur itself (-q forcse)
    first = next((a for a in argv if a not in ("-q", "--quiet")), None)
    if first is not None and not first.startswith("-") and first not in commands:
        starting = [c for c in commands if c.startswith(first)]
        hint = (
            f"; did you mean {describe(starting[0])}?"
            if len(starting) == 1
            else suggest(first, commands)
        )
        print(f"assur: error: unknown command {describe(first)}{hint}", file=sys.stderr)
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
            handler = commands[args.command]
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


def _parser() -> tuple[_Parser, dict[str, Handler]]:
    """Return the parser and every command's handler, by name, in the parser's order.

    A new mapping on every call; the ``_cmd_*`` functions of this module are read
    when it is built, so a test that replaces one is obeyed by the next run.
    """
    own = {
        "structure": _cmd_structure,
        "kinematics": _cmd_kinematics,
        "forces": _cmd_forces,
        "explain": _cmd_explain,
    }
    return _cli_commands._parser(own)


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


class _OtherFileError(ModelError):
    """A fault of a file other than the mechanism's, which its message names."""


def _run(handler: Callable[[argparse.Namespace], int], args: argparse.Namespace) -> int:
    """Run one command, turning assur's errors and warnings into one-line messages."""
    source = input_text(args.file)
    failure = None
    with warnings.catch_warnings(record=True) as caught, glyphs_logged() as logged:
        warnings.simplefilter("always", AssurWarning)
        # matplotlib's advice on a crowded picture: none a user here can take
        warnings.filterwarnings("ignore", "constrained_layout not applied", UserWarning)
        try:
            status = handler(args)
        except (OutputError, _OtherFileError) as err:  # not about the mechanism file
            failure = str(err)
        except AssurError as err:
            text = str(err) + skip_hint(args, err)
            failure = text if text.startswith(source) else f"{source}: {text}"
        except BrokenPipeError:
            raise  # the reader of standard output has gone: main stops quietly
        except OSError as err:
            reason = err.strerror or str(err)
            if err.filename:
                failure = f"{path_text(err.filename)}: {reason}"
                if err.errno == errno.ENAMETOOLONG:
                    # from a check of an output's name (is it a folder?), before
                    # any write: what would make it usable is said too
                    failure += "; expected a shorter name"
            else:
                failure = f"standard output: cannot write ({reason})"
        except MemoryError:
            failure = (
                f"{source}: out of memory; expected fewer positions (--angles) or a "
                "smaller output"
            )
    # shown only once the recording has stopped, so showing cannot record again;
    # the warnings met on the way come before the error that stopped the command
    told = set()
    glyphs = missing_glyphs([str(w.message) for w in caught] + logged)
    if glyphs is not None:  # one line, not one per character and drawing
        print(f"assur: warning: {source}: {glyphs}", file=sys.stderr)
    for w in caught:
        if GLYPH_MISSING.fullmatch(str(w.message)):
            continue
        if issubclass(w.category, AssurWarning):
            line = _one_line(w.message)
            if line in told:  # from another sweep (the dynamic model's, say)
                continue
            told.add(line)
            print(f"assur: warning: {source}: {line}", file=sys.stderr)
        else:
            warnings.showwarning(w.message, w.category, w.filename, w.lineno)
    if failure is not None:
        _error(failure)
        status = 2
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
    from assur._structure import DriverChoiceError, structure

    mech = load_mechanism(args.file)
    try:
        s = structure(mech, args.driver)  # "A, E" read by _cli_types.joints
    except DriverChoiceError as err:
        # the option, not the file: named as the command line spells it
        raise UsageError(err.spelled("--driver", "--driver")) from err
    _say(json.dumps(s.to_dict(), indent=2) if args.json else str(s))
    return 0


NOTE_SUFFIXES = (".md", ".markdown", ".html", ".htm", ".tex")
"""File types of ``assur explain -o``."""


def _cmd_explain(args: argparse.Namespace) -> int:
    from assur.explain import explain, read_answers

    if args.answers is not None and str(args.answers) == "-":
        msg = "--answers -: standard input is not read for answers; expected a file"
        raise UsageError(msg)
    if args.output is not None and is_stdout(args.output):
        args.output = None  # standard output (- or /dev/stdout): the note's Markdown
    if args.output is not None:
        suffix = Path(args.output).suffix.lower()
        if Path(args.output).is_dir():
            msg = (
                f"-o {path_text(args.output)}: is a folder; expected a file name "
                "ending in .md, .html or .tex"
            )
            raise UsageError(msg)
        if suffix not in NOTE_SUFFIXES:
            what = f"unknown type of note {describe(suffix)}" if suffix else "no suffix"
            msg = (
                f"-o {path_text(args.output)}: {what}; expected a name ending in .md, "
                ".html or .tex"
            )
            raise UsageError(msg)
        check_not_input("-o", args.output, args.file)
        if args.answers:
            # the note would replace the answers it was checked against
            check_not_input("-o", args.output, args.answers, "the answers file")
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
    if not quiet(args):
        print(f"wrote {path_text(args.output)}")
    return 0


def _cmd_kinematics(args: argparse.Namespace) -> int:
    return _sweep(args, forces=False)


def _cmd_forces(args: argparse.Namespace) -> int:
    return _sweep(args, forces=True)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
