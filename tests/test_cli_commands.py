"""The command line's parser and its handlers: a new value on every build.

The handlers were once gathered in a module-level dict that every build of the
parser filled as a side effect; a build now returns its own mapping, and the
dispatch runs the handler of the parser it parsed with.
"""

from __future__ import annotations

import argparse

import pytest

from assur import _cli_commands, cli, dynamics_cli

from .conftest import EXAMPLES

FOUR_BAR = EXAMPLES / "four_bar.toml"


def _names(parser: argparse.ArgumentParser) -> list[str]:
    """Return the parser's command names, in its order."""
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return list(sub.choices)


def _stub(args: argparse.Namespace) -> int:
    """Stand in for a command's handler."""
    return 7


def test_two_builds_share_no_handlers() -> None:
    first_parser, first = cli._parser()
    second_parser, second = cli._parser()
    assert first_parser is not second_parser
    assert first is not second
    first["dynamics"] = _stub
    assert second["dynamics"] is dynamics_cli._cmd_dynamics
    assert cli._parser()[1]["dynamics"] is dynamics_cli._cmd_dynamics


def test_every_command_has_its_handler_in_the_parsers_order() -> None:
    parser, handlers = cli._parser()
    assert list(handlers) == _names(parser)
    assert handlers["structure"] is cli._cmd_structure
    assert all(callable(h) for h in handlers.values())


def test_no_registry_is_kept_at_module_level() -> None:
    # a mutable module global would be state that one build leaves to the next
    kept = {
        name: type(value).__name__
        for name, value in vars(_cli_commands).items()
        if not name.startswith("__") and isinstance(value, dict | list | set)
    }
    assert kept == {}


def test_dispatch_runs_the_handler_of_its_own_parser(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    built = cli._parser

    def stubbed() -> tuple[argparse.ArgumentParser, dict]:
        parser, handlers = built()
        return parser, handlers | {"structure": _stub}

    monkeypatch.setattr(cli, "_parser", stubbed)
    assert cli.main(["structure", str(FOUR_BAR)]) == 7
    monkeypatch.undo()
    assert cli.main(["-q", "structure", str(FOUR_BAR)]) == 0
