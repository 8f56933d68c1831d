"""The command line's parser: its commands and each command's options.

:func:`_parser` builds it for :func:`assur.cli.main`, with the commands of
:mod:`assur.dynamics_cli` and (when present) :mod:`assur.pictures_cli`, and returns
every command's handler with it, a new mapping on every call: no registry is kept
here. The commands of :mod:`assur.cli` itself are its ``_cmd_*`` functions, which
that module passes in.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Mapping
from typing import Any

from assur._cli_common import add_angle_option
from assur._cli_parser import _Parser
from assur._cli_types import (
    ANGLES_HELP,
    add_file_argument,
    file_name,
    given,
    input_file,
    joints,
)
from assur._troubles import SKIPPED_WHY, UNREACHED_WHY

__all__ = ["QUIET", "Handler", "_parser"]

Handler = Callable[[argparse.Namespace], int]
"""A command's function: its parsed arguments in, the exit status out."""
QUIET = "no progress bars, no 'wrote ...' lines or notes (errors and warnings stay)"


def _parser(own: Mapping[str, Handler]) -> tuple[_Parser, dict[str, Handler]]:
    """Return the parser and every command's handler, by name, in the parser's order.

    ``own`` holds the handlers of the commands of :mod:`assur.cli` itself (above
    this module); the others are those of :mod:`assur.dynamics_cli` and
    :mod:`assur.pictures_cli`. Every call builds a new parser and a new mapping, so
    what one caller changes in its mapping no other call sees.
    """
    parser = _Parser(
        prog="assur",
        description="Kinetostatic analysis of planar linkages, built on Assur groups.",
    )
    parser.add_argument("-q", "--quiet", action="store_true", help=QUIET)
    from assur import __version__

    parser.add_argument("--version", action="version", version=f"assur {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("structure", help="degrees of freedom and Assur groups")
    add_file_argument(p)
    p.add_argument(
        "--json", action="store_true", help="print JSON instead of the report"
    )
    p.add_argument(
        "--driver",
        type=joints,
        metavar="JOINT",
        help="analyse with this joint as input (several degrees of freedom: one "
        "joint each, separated by commas)",
    )
    for name, text in (
        ("kinematics", "positions, velocities, accelerations, jerks"),
        ("forces", "inertia loads, joint reactions, balancing torque"),
    ):
        p = sub.add_parser(name, help=text)
        add_file_argument(p)
        p.add_argument(
            "--angles",
            metavar="START:STOP:STEP",
            help=ANGLES_HELP,
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
            help=f"leave out the positions {SKIPPED_WHY}, {UNREACHED_WHY}",
        )
    p.add_argument(
        "--summary",
        action="store_true",
        help="print the summary instead of the table: largest and RMS reaction in "
        "every joint, balancing load, mean power, friction losses (JSON with --json)",
    )
    p = sub.add_parser("explain", help="the analysis at one position, step by step")
    add_file_argument(p)
    add_angle_option(p)
    p.add_argument(
        "-o",
        "--output",
        type=file_name,
        metavar="PATH",
        help="write the note to PATH: .md (Markdown), .html (MathML) or .tex "
        "(LaTeX); default and '-': Markdown on standard output",
    )
    p.add_argument(
        "--answers",
        metavar="TOML",
        type=input_file,
        help="given answers to compare with (a table [answers] of quantity = value)",
    )
    from assur import dynamics_cli

    handlers = {**own, **dynamics_cli.register(sub), **_picture_commands(sub)}
    for told in sub._choices_actions:  # else COMMAND --help lists options alone
        sub.choices[told.dest].description = told.help
    for p in sub.choices.values():
        # after the command too; SUPPRESS keeps an earlier --quiet
        p.add_argument(
            "-q", "--quiet", action="store_true", default=argparse.SUPPRESS, help=QUIET
        )
    # in the parser's order, which its listings and hints follow
    return parser, {name: handlers[name] for name in sub.choices}


def _picture_commands(sub: Any) -> dict[str, Handler]:
    """Add the commands of :mod:`assur.pictures_cli`, when present; return handlers."""
    try:
        from assur import pictures_cli
    except ImportError:  # pragma: no cover - pictures are optional in a slim build
        return {}
    return pictures_cli.register(sub)
