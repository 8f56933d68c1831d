"""The command line's argument parser: one line for each usage error, no shortening.

argparse's own prints its usage block before the line that says what is wrong, takes
the start of an option's name for the option, keeps the last of an option's values
given twice, and lets a failed write of its help pass: :class:`_Parser` does none of
these.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any, NoReturn

from assur._text import describe, spoken, suggest

__all__ = ["_Parser"]


class _Parser(argparse.ArgumentParser):
    """argparse's parser, except that a failed write of its help is not ignored.

    argparse drops the OSError of ``--help`` written to a full disk (exit 0, no
    help); here it reaches :func:`assur.cli.main`, which says so (exit 2).
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        # no option shortened: "--angle" taken for "--angles" by one command was
        # refused by another, and every new option could break a shortening
        kwargs.setdefault("allow_abbrev", False)
        super().__init__(*args, **kwargs)
        self._given: dict[argparse.Action, tuple[str, Any]] = {}

    def parse_known_args(self, args: Any = None, namespace: Any = None) -> Any:
        """Parse as argparse does, no option given yet (see :meth:`_get_values`)."""
        self._given = {}
        return super().parse_known_args(args, namespace)

    def _get_values(self, action: argparse.Action, arg_strings: list[str]) -> Any:
        """Return an option's value; refuse a second, different value of it.

        argparse keeps the last value: ``--angles 0:360:10 --angles 5`` analysed one
        position, ``--csv a.csv --csv b.csv`` wrote b.csv alone. A flag given twice
        (``--json``) and the same value again ask for the same result and pass; an
        option meant to repeat (an ``append`` action) is not a store and passes too.
        """
        if arg_strings == ["--"] and action.option_strings and action.nargs is None:
            # argparse drops a "--" it is given as the value (--flywheel=--) and
            # stores an empty list: a traceback later, or --csv=-- printed the table
            msg = "expected a value, got '--' (the end of the options)"
            raise argparse.ArgumentError(action, msg)
        values = super()._get_values(action, arg_strings)
        if type(action) is not argparse._StoreAction or not action.option_strings:
            return values
        if len(arg_strings) != 1:  # a store of several values (nargs): none here
            return values
        written = arg_strings[0]
        if action in self._given:
            first, earlier = self._given[action]
            # the same text is the same value, even where it reads as NaN (which
            # equals nothing): 'nan' and 'nan' are not two values
            if written != first and earlier != values:
                msg = (
                    f"given twice, {describe(first)} and {describe(written)}; "
                    "expected one value"
                )
                raise argparse.ArgumentError(action, msg)
        self._given[action] = (written, values)
        return values

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
        if message.startswith("unrecognized arguments: "):
            message += self._closest(message.split()[2], command)
        if message.endswith("required: COMMAND"):  # "assur" alone: which there are
            message = f"expected a command: {spoken(self._commands(), 'or')}"
        line = f"assur: error: {where}{message} (see '{prog} --help')"
        self.exit(2, " ".join(line.split()) + "\n")

    def _commands(self) -> list[str]:
        """Return the names of the commands, in alphabetical order."""
        found = [
            name
            for action in self._actions
            if isinstance(action, argparse._SubParsersAction)
            for name in action.choices
        ]
        return sorted(found)

    def _closest(self, option: str, command: str) -> str:
        """Return a hint for an unknown ``option``: the command's nearest one.

        ``-o`` (the pictures' output) given to a table's command names the options
        a table is written with.
        """
        parser: argparse.ArgumentParser = self
        for action in self._actions:
            if isinstance(action, argparse._SubParsersAction) and command:
                parser = action.choices.get(command, self)
        known = [o for o in parser._option_string_actions if o.startswith("--")]
        name = option.partition("=")[0]
        if name in ("-o", "--output") and "--csv" in known:
            tables = [f"{o} PATH" for o in ("--csv", "--parquet") if o in known]
            return f"; a table is written to a file with {' or '.join(tables)}"
        if option == "--" or name in known:
            # after "--" every argument is read as a file: "did you mean '--json'?"
            # was said of --json itself
            return "; options go before '--', after which every argument is a file"
        if parser is not self and name in self._option_string_actions:
            # "did you mean '--json'?" was said of --version after the command
            return f"; {name} is an option of assur itself, given before the command"
        if not option.startswith("--"):
            return ""
        return suggest(name, known, listing=False)

    command = ""
    """The command being parsed, once known (see :func:`_main`)."""
