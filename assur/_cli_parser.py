"""The command line's argument parser: one line for each usage error, no shortening.

argparse's own prints its usage block before the line that says what is wrong, takes
the start of an option's name for the option, and lets a failed write of its help
pass: :class:`_Parser` does none of these.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any, NoReturn

from assur._text import spoken, suggest

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
        if not option.startswith("--"):
            return ""
        return suggest(name, known, listing=False)

    command = ""
    """The command being parsed, once known (see :func:`_main`)."""
