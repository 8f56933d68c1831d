"""An option given twice on the command line: refused when it asks for two things.

argparse kept the last value: ``--angles 0:360:10 --angles 5`` analysed one position,
``--csv a.csv --csv b.csv`` wrote b.csv alone. Every command's options are found in
the parser itself, so that a new command or option is covered without a new line.
"""

from __future__ import annotations

import argparse
import math

import pytest

from assur import cli
from assur._cli_parser import _Parser

from .conftest import EXAMPLES

FOUR_BAR = EXAMPLES / "four_bar.toml"


def _commands() -> dict[str, argparse.ArgumentParser]:
    """Return every command's parser, by name."""
    parser, _ = cli._parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(sub.choices)


def _options(kind: type[argparse.Action]) -> list[tuple[str, str]]:
    """Return (command, option) for every option of the kind ``kind`` exactly."""
    return [
        (command, action.option_strings[-1])
        for command, parser in _commands().items()
        for action in parser._actions
        if type(action) is kind and action.option_strings
    ]


def _required(command: str, option: str) -> list[str]:
    """Return the options ``command`` requires (``-o`` of a picture), but ``option``."""
    return [
        text
        for action in _commands()[command]._actions
        if action.required and action.option_strings
        if option not in action.option_strings
        for text in (action.option_strings[-1], "1")
    ]


VALUED = _options(argparse._StoreAction)
FLAGS = _options(argparse._StoreTrueAction)


def test_every_command_has_a_valued_option_checked():
    assert {command for command, _ in VALUED} == set(_commands())


@pytest.mark.parametrize(("command", "option"), VALUED)
def test_a_valued_option_given_twice_is_one_error(
    capsys, tmp_path, monkeypatch, command, option
):
    monkeypatch.chdir(tmp_path)  # were the option taken, its output lands here
    # "1" and "2" are values every option's type takes: the second one is refused
    # for being a second, not for its form
    status = cli.main([command, str(FOUR_BAR), option, "1", f"{option}=2"])
    out, err = capsys.readouterr()
    assert (status, out) == (2, "")
    assert "Traceback" not in err
    assert list(tmp_path.iterdir()) == []
    assert err.count("\n") == 1, err
    action = next(
        a for a in _commands()[command]._actions if option in a.option_strings
    )
    name = "/".join(action.option_strings)
    assert err == (
        f"assur: error: {command}: argument {name}: given twice, '1' and '2'; "
        f"expected one value (see 'assur {command} --help')\n"
    )


def test_the_short_and_long_spellings_are_one_option(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv = ["explain", str(FOUR_BAR), "-o", "a.md", "--output", "b.md"]
    assert cli.main(argv) == 2
    err = capsys.readouterr().err
    assert "argument -o/--output: given twice, 'a.md' and 'b.md'; " in err
    assert list(tmp_path.iterdir()) == []


def test_a_range_below_zero_given_twice_is_one_error(capsys):
    argv = ["kinematics", str(FOUR_BAR), "--angles", "-30:30:10", "--angles", "-5"]
    assert cli.main(argv) == 2
    assert "argument --angles: given twice, '-30:30:10' and '-5'; " in (
        capsys.readouterr().err
    )


@pytest.mark.parametrize(("command", "option"), VALUED)
def test_the_same_value_again_is_taken(command, option):
    parser, _ = cli._parser()
    given = [command, str(FOUR_BAR), *_required(command, option), option, "1"]
    assert parser.parse_args([*given, option, "1"]) == parser.parse_args(given)


@pytest.mark.parametrize(("command", "option"), FLAGS)
def test_a_flag_given_twice_is_given(command, option):
    parser, _ = cli._parser()
    required = _required(command, option)
    args = parser.parse_args([command, str(FOUR_BAR), *required, option, option])
    assert vars(args)[option.lstrip("-").replace("-", "_")] is True


def test_quiet_before_and_after_the_command_is_quiet():
    parser, _ = cli._parser()
    args = parser.parse_args(["-q", "structure", str(FOUR_BAR), "-q", "--quiet"])
    assert args.quiet is True


def test_an_option_meant_to_repeat_keeps_every_value():
    parser = _Parser(prog="assur")
    parser.add_argument("--column", action="append")
    args = parser.parse_args(["--column", "a", "--column", "b"])
    assert args.column == ["a", "b"]


def test_a_second_parse_starts_with_no_option_given():
    parser = _Parser(prog="assur")
    parser.add_argument("--angles")
    assert parser.parse_args(["--angles", "1"]).angles == "1"
    assert parser.parse_args(["--angles", "2"]).angles == "2"


def test_the_same_text_again_is_taken_even_where_it_is_nan():
    # NaN equals nothing, not even itself: the value is refused for its range by
    # the command, not as a second value
    parser = _Parser(prog="assur")
    parser.add_argument("--delta", type=float)
    args = parser.parse_args(["--delta", "nan", "--delta", "nan"])
    assert math.isnan(args.delta)


def test_the_same_value_written_twice_otherwise_is_taken():
    # "--driver A,B" and "--driver 'A, B'" name the same joints: the values are
    # compared, not the text that gave them
    parser, _ = cli._parser()
    given = ["structure", str(FOUR_BAR), "--driver", "A,B"]
    again = parser.parse_args([*given, "--driver", "A, B"])
    assert again == parser.parse_args(given)
