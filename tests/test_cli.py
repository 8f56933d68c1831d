"""The command line: ``main([...])`` with files in ``tmp_path``, output from ``capsys``.

Bad input gives exactly one line on standard error, ``assur: error: FILE: ...``, exit
status 2 and no traceback; good input gives the report, a readable table, CSV or JSON.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.cli import main, parse_angles

from .conftest import EXAMPLES
from .test_model import BAD, BASE, Bad

ROOT = Path(__file__).resolve().parent.parent


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def fails(capsys, argv: list[str], path: Path | str) -> str:
    """Run ``argv``; check the single error line and return its text after the file."""
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert status == 2, err
    assert out == ""
    assert "Traceback" not in err
    lines = err.splitlines()
    assert len(lines) == 1, err
    prefix = f"assur: error: {path}: "
    assert lines[0].startswith(prefix), lines[0]
    return lines[0][len(prefix) :]


def succeeds(capsys, argv: list[str]) -> tuple[str, str]:
    status = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert status == 0, err
    return out, err


def commands(case: Bad) -> list[list[str]]:
    """The commands that meet the fault of ``case``."""
    if case.stage == "load":
        return [
            ["structure"],
            ["kinematics", "--angles", "0"],
            ["forces", "--angles", "0"],
        ]
    if case.stage == "structure":
        return [["structure"], ["kinematics"]]
    return [["forces", "--angles", "0:10:10"]]


# --- bad input ---------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_file(name, tmp_path, capsys):
    case = BAD[name]
    path = write(tmp_path, f"{name}{case.suffix}", case.text)
    for command in commands(case):
        text = fails(capsys, [command[0], path, *command[1:]], path)
        assert re.search(case.match, text), (command, text)


def test_missing_file(tmp_path, capsys):
    path = tmp_path / "nowhere.toml"
    text = fails(capsys, ["structure", path], path)
    assert text.startswith("cannot read the file")


def test_file_not_in_utf8(tmp_path, capsys):
    path = tmp_path / "latin1.toml"
    path.write_bytes(
        BASE.replace("Slider-crank", "Manivelle \xe0 coulisse").encode("latin-1")
    )
    fails(capsys, ["structure", path], path)


@pytest.mark.parametrize(
    ("spec", "fault"),
    [
        ("abc", "cannot read 'abc'"),
        ("0:10", "cannot read '0:10'"),
        ("", "cannot read ''"),
        ("0:10:5:1", "cannot read '0:10:5:1'"),
        # float() takes them, a reader would not: digit separators, other digits
        ("1_0", "cannot read '1_0'"),
        ("\u0664\u0665", "cannot read '\u0664\u0665'"),
        # read, and no position: "cannot read 'inf'" was said
        ("nan", "'nan' holds a number that is not finite"),
        ("0:inf:1", "'0:inf:1' holds a number that is not finite"),
        ("-inf", "'-inf' holds a number that is not finite"),
    ],
)
def test_bad_angles(spec, fault, capsys):
    path = EXAMPLES / "four_bar.toml"
    text = fails(capsys, ["kinematics", path, f"--angles={spec}"], path)
    assert text == (
        f"--angles: {fault}; expected START:STOP:STEP with a step that leads from "
        "START to STOP, or a single value"
    )


@pytest.mark.parametrize(
    ("spec", "why"),
    [
        (
            "0:10:-1",
            "leads away from STOP; expected a step that leads from START to "
            "STOP (1 here)",
        ),
        (
            "10:0:2.5",
            "leads away from STOP; expected a step that leads from START "
            "to STOP (-2.5 here)",
        ),
        ("0:10:0", "is 0; expected a step that leads from START to STOP"),
    ],
)
def test_a_step_going_nowhere_is_told_so(spec, why, capsys):
    # read, but "cannot read '0:90:-10'" was all it said
    path = EXAMPLES / "four_bar.toml"
    text = fails(capsys, ["kinematics", path, f"--angles={spec}"], path)
    assert text == f"--angles: in {spec!r} the step {why}"


def test_angles_for_two_drivers(capsys):
    path = EXAMPLES / "five_bar_two_cranks.toml"
    text = fails(capsys, ["kinematics", path, "--angles", "0:20:10"], path)
    assert text == (
        "--angles: 1 range given for 2 drivers; expected one "
        "START:STOP:STEP per driver, separated by commas"
    )
    text = fails(capsys, ["forces", path, "--angles", "0:20:10,100:130:10"], path)
    assert text == "--angles: the ranges have 3 and 4 positions; expected equal counts"


def test_a_wrong_structure_is_named_before_the_count_of_angles(tmp_path, capsys):
    # two drivers on one degree of freedom: the ranges given (one) match neither
    # the drivers nor the freedom; the error is the structure's
    path = tmp_path / "two_drivers.toml"
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    path.write_text(
        text + '\n[[drivers]]\njoint = "O4"\nomega = 1.0\n', encoding="utf-8"
    )
    picture = ["--angle", "0", "-o", tmp_path / "p.png"]
    for command in ("kinematics", "forces", "plot", "dynamics"):
        options = picture if command == "plot" else ["--angles", "0"]
        text = fails(capsys, [command, path, *options], path)
        assert text.startswith("drivers: the mechanism has W = "), (command, text)
        assert "but 2 drivers" in text


def test_dynamics_counts_the_drivers_of_the_file(capsys):
    path = EXAMPLES / "five_bar_two_cranks.toml"
    text = fails(capsys, ["dynamics", path, "--angles", "0:90:90,10:100:90"], path)
    assert text.startswith("dynamics: the mechanism has 2 drivers; expected one")


def test_driver_option_on_two_degrees_of_freedom(capsys):
    path = EXAMPLES / "five_bar_two_cranks.toml"
    text = fails(capsys, ["structure", path, "--driver", "A"], path)
    assert text.startswith("--driver: the mechanism has W = ")
    assert text.endswith(
        "(--driver sets one input; without it the file's drivers are used)"
    )
    # one joint for each degree of freedom, separated by commas, in any order
    out, _ = succeeds(capsys, ["structure", path, "--driver", "E,A"])
    s = assur.structure(assur.load(path), driver=["E", "A"])
    assert out == str(s) + "\n"
    assert [g.internal for g in s.drivers] == [("E",), ("A",)]
    assert s.formula.count("I(ground") == 2
    text = fails(capsys, ["structure", path, "--driver", "A,A"], path)
    assert text == (
        "--driver: joint 'A' is driven twice; expected each driver on a joint of its "
        "own"
    )
    four = EXAMPLES / "four_bar.toml"
    text = fails(capsys, ["structure", four, "--driver", "O2,O4"], four)
    assert text.endswith(
        "(--driver sets 2 inputs; without it the file's drivers are used)"
    )


def test_driver_option_unknown_joint(capsys):
    path = EXAMPLES / "class3.toml"
    assert (
        fails(capsys, ["structure", path, "--driver", "Q"], path)
        == "--driver: unknown joint 'Q' (joints with the frame: F, G, O2)"
    )


def test_driver_option_off_the_frame(capsys):
    path = EXAMPLES / "class3.toml"
    text = fails(capsys, ["structure", path, "--driver", "C"], path)
    assert text.startswith("--driver: ")


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["structure"],
            "structure: the following arguments are required: file (see 'assur "
            "structure --help')",
        ),
        # "assur" alone said "required: COMMAND" and named none
        (
            ["-q"],
            "expected a command: animate, diagrams, dynamics, explain, forces, "
            "kinematics, plans, plot, report or structure (see 'assur --help')",
        ),
        (
            ["-q", "kinematics", "x.toml", "--nope"],
            "kinematics: unrecognized arguments: --nope (see 'assur kinematics "
            "--help')",
        ),
        (
            ["dynamics", "x.toml", "--delta", "0.02", "--flywheel", "1"],
            "dynamics: argument --flywheel: not allowed with argument --delta (see "
            "'assur dynamics --help')",
        ),
        (["forcs", "x.toml"], "unknown command 'forcs'; did you mean 'forces'?"),
        # the start of one command's name
        (["kin", "x.toml"], "unknown command 'kin'; did you mean 'kinematics'?"),
        # an option shortened is no option: "--angle" was "--angles" in kinematics
        # and refused by plot, whose --angle it is
        (
            ["kinematics", "x.toml", "--angle", "10"],
            "kinematics: unrecognized arguments: --angle 10; did you mean "
            "'--angles'? (see 'assur kinematics --help')",
        ),
        (
            ["plot", "x.toml", "-o", "p.png", "--angles", "10"],
            "plot: unrecognized arguments: --angles 10; did you mean '--angle'? (see "
            "'assur plot --help')",
        ),
        (
            ["plot", "x.toml", "-o", "p.png", "--fo"],
            "plot: unrecognized arguments: --fo; did you mean '--forces'? (see "
            "'assur plot --help')",
        ),
        # a picture's -o given to a table's command: it named nothing to use
        (
            ["kinematics", "x.toml", "-o", "t.csv"],
            "kinematics: unrecognized arguments: -o t.csv; a table is written to a "
            "file with --csv PATH or --parquet PATH (see 'assur kinematics --help')",
        ),
        (
            ["dynamics", "x.toml", "--output", "t.csv"],
            "dynamics: unrecognized arguments: --output t.csv; a table is written to a "
            "file with --csv PATH or --parquet PATH (see 'assur dynamics --help')",
        ),
        (
            ["forces", "x.toml", "--csvv=t.csv"],
            "forces: unrecognized arguments: --csvv=t.csv; did you mean '--csv'? (see "
            "'assur forces --help')",
        ),
        # after "--" an option is a file: "did you mean '--json'?" of --json itself
        (
            ["forces", "--", "x.toml", "--json"],
            "forces: unrecognized arguments: --json; options go before '--', after "
            "which every argument is a file (see 'assur forces --help')",
        ),
        (
            ["forces", "x.toml", "--json", "--", "--csv"],
            "forces: unrecognized arguments: -- --csv; options go before '--', after "
            "which every argument is a file (see 'assur forces --help')",
        ),
        # assur's own option after the command: "did you mean '--json'?"
        (
            ["forces", "x.toml", "--version"],
            "forces: unrecognized arguments: --version; --version is an option of "
            "assur itself, given before the command (see 'assur forces --help')",
        ),
        # after assur's own options too: argparse's "invalid choice" had no hint
        (
            ["-q", "forcse", "x.toml"],
            "unknown command 'forcse'; did you mean 'forces'?",
        ),
        # argparse's "invalid int value: '1.5'" did not say what was expected
        (
            ["plot", "x.toml", "-o", "p.png", "--group", "1.5"],
            "plot: argument --group: expected a whole number, got "
            "'1.5' (see 'assur plot --help')",
        ),
        (
            ["plot", "x.toml", "-o", "p.png", "--dpi", ""],
            "plot: argument --dpi: expected a number, got '' (see 'assur plot --help')",
        ),
        (
            ["animate", "x.toml", "-o", "a.gif", "--frames", "1e3"],
            "animate: argument --frames: expected a whole number, got "
            "'1e3' (see 'assur animate --help')",
        ),
        (
            ["animate", "x.toml", "-o", "a.gif", "--fps", "fast"],
            "animate: argument --fps: expected a number, got 'fast' (see 'assur "
            "animate --help')",
        ),
        (
            ["animate", "x.toml", "-o", "a.gif", "--frames", "1_0"],
            "animate: argument --frames: expected a whole number, got "
            "'1_0' (see 'assur animate --help')",
        ),
        (
            ["plot", "x.toml", "-o", "p.png", "--dpi", "1_50"],
            "plot: argument --dpi: expected a number, got '1_50' (see 'assur plot "
            "--help')",
        ),
        (
            ["dynamics", "x.toml", "--turns", "2.5"],
            "dynamics: argument --turns: expected a whole number, got "
            "'2.5' (see 'assur dynamics --help')",
        ),
    ],
)
def test_usage_error_exits_2(capsys, argv, line):
    # one line naming the command and the option: argparse's usage block (six
    # lines for dynamics) came first
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err == f"assur: error: {line}\n"


COMMANDS = ["structure", "kinematics", "forces", "explain", "dynamics"]
COMMANDS += ["plot", "diagrams", "animate", "plans", "report"]


@pytest.mark.parametrize("command", COMMANDS)
def test_help_says_what_the_file_is(capsys, command):
    # "positional arguments: file" alone left the reader to guess its format
    assert main([command, "--help"]) == 0
    out = capsys.readouterr().out
    assert re.search(
        r"^\s+file\s+the mechanism file, \.toml or \.json \('-'", out, re.M
    )


def _options(command: str) -> dict[str, argparse.Action]:
    """Return the options of ``command`` by each of their names."""
    from assur.cli import _parser

    parser, _ = _parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    found = {}
    for action in sub.choices[command]._actions:
        for name in action.option_strings:
            found[name] = action
    return found


def test_the_docs_spell_every_option_as_the_help_does():
    # the docs had --dpi D, --fps F where --help says --dpi DPI, --fps FPS
    text = (ROOT / "docs" / "cli.rst").read_text(encoding="utf-8")
    usage = re.findall(r"^   assur (\w+) +FILE (.*)$", text, re.M)
    assert len(usage) == len(COMMANDS)
    for command, line in usage:
        options = _options(command)
        for name, metavar in re.findall(r"(--?[\w-]+) ([A-Z][\w:.|-]*)", line):
            shown = options[name].metavar or options[name].dest.upper()
            assert metavar.split("|")[0] == shown, (command, name, metavar, shown)


def test_the_docs_list_every_option_of_every_command():
    # an option added to the parser but not to the docs' synopsis went unseen
    text = (ROOT / "docs" / "cli.rst").read_text(encoding="utf-8")
    for command, line in re.findall(r"^   assur (\w+) +FILE (.*)$", text, re.M):
        listed = set(re.findall(r"(?<![\w-])(--[\w-]+|-o)\b", line))
        options = _options(command)
        parsed = {n for n in options if n.startswith("--")} - {"--help", "--quiet"}
        parsed = {"-o" if n == "--output" else n for n in parsed}
        assert listed == parsed, command


def test_the_options_shared_by_commands_are_told_alike():
    sweeps = ["kinematics", "forces", "diagrams", "animate", "report"]
    angles = {_options(c)["--angles"].help for c in sweeps}
    assert len(angles) == 1
    # right for a prismatic driver too, whose default is no turn
    assert "a prismatic driver: 101 positions over a round stroke within +-20 %%" in (
        angles.pop()
    )
    assert _options("plot")["--forces"].help == _options("animate")["--forces"].help
    assert "values" in _options("plot")["--no-labels"].help
    # not N, the unit of force
    assert _options("plot")["--scale"].metavar == "NPERCM"
    assert "newtons per cm" in _options("plot")["--scale"].help
    # the default scale, and the ranges of several drivers, went unsaid
    assert "default: a round one" in _options("plot")["--scale"].help
    assert "several drivers: one range each" in _options("forces")["--angles"].help


@pytest.mark.parametrize("command", COMMANDS)
def test_help_says_what_the_command_does(capsys, command):
    # "assur dynamics --help" listed the options alone: what the command does was
    # said only by "assur --help"
    from assur.cli import _parser

    parser, _ = _parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    told = next(a.help for a in sub._choices_actions if a.dest == command)
    assert main([command, "--help"]) == 0
    out = capsys.readouterr().out
    assert f"\n\n{told}\n\n" in out


# --- structure ---------------------------------------------------------------------


def test_structure_report(capsys):
    out, err = succeeds(capsys, ["structure", EXAMPLES / "tenbar.toml"])
    assert err == ""
    assert out.startswith("Structure of Ten-bar advance-and-grip mechanism")
    assert "W = 3n - 2p5 - p4 = 3*9 - 2*13 - 0 = 1" in out
    assert "Class II, order 2, dyad RRP: links 6 and 7" in out
    assert "Structure formula: I(ground, 1) -> II(2, 3) -> " in out
    assert out.rstrip().endswith("the force analysis in the reverse order.")


def test_structure_json(capsys):
    out, _ = succeeds(capsys, ["structure", EXAMPLES / "lever_var9.toml", "--json"])
    data = json.loads(out)
    assert data["dof"] == 1
    assert [(g["kind"], g["links"]) for g in data["groups"]] == [
        ("RRP", ["2", "3"]),
        ("PRP", ["4", "5"]),
    ]
    assert data["formula"] == "I(ground, 1) -> II(2, 3) -> II(4, 5)"


def test_structure_with_another_driver(capsys):
    path = EXAMPLES / "class3.toml"
    out, _ = succeeds(capsys, ["structure", path])
    assert "Class of the mechanism: III" in out
    out, _ = succeeds(capsys, ["structure", path, "--driver", "F", "--json"])
    data = json.loads(out)
    assert data["mechanism_class"] == 2
    assert data["drivers"][0]["links"] == ["ground", "left_rocker"]


def test_python_dash_m(tmp_path):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    result = subprocess.run(
        [sys.executable, "-m", "assur", "structure", "examples/tenbar.toml"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    assert "Structure formula: I(ground, 1)" in result.stdout
    result = subprocess.run(
        [sys.executable, "-m", "assur", "structure", str(tmp_path / "none.toml")],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 2
    assert result.stderr.startswith("assur: error: ")
    assert len(result.stderr.splitlines()) == 1


# --- kinematics and forces: text, CSV, JSON ----------------------------------------


def read_csv(text: str) -> tuple[list[str], np.ndarray]:
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], np.array(rows[1:], dtype=float).reshape(len(rows) - 1, len(rows[0]))


def test_kinematics_default_is_a_readable_full_turn(capsys):
    out, _ = succeeds(capsys, ["kinematics", EXAMPLES / "four_bar.toml"])
    lines = out.splitlines()
    assert lines[0].split() == [
        "angle",
        "crank.angle",
        "crank.omega",
        "crank.alpha",
        "coupler.angle",
        "coupler.omega",
        "coupler.alpha",
        "rocker.angle",
        "rocker.omega",
        "rocker.alpha",
    ]
    assert lines[1].split()[:4] == ["[deg]", "[deg]", "[rad/s]", "[rad/s^2]"]
    assert len(lines) == 2 + 360 + 1
    angles = np.array([float(line.split()[0]) for line in lines[2:-1]])
    np.testing.assert_allclose(angles, 60.0 + np.arange(360.0), rtol=0, atol=1e-9)
    assert re.fullmatch(
        r"\(\d+ columns in all: --csv PATH or --json for the full "
        r"table\)",
        lines[-1],
    )


def test_forces_default(capsys):
    out, _ = succeeds(capsys, ["forces", EXAMPLES / "slider_crank_exercise.toml"])
    lines = out.splitlines()
    assert "driver.torque" in lines[0].split()
    assert "driver.torque_check" in lines[0].split()
    assert "[N m]" in lines[1]
    assert len(lines) == 2 + 360 + 1


def test_single_angle(capsys):
    path = EXAMPLES / "slider_crank_exercise.toml"
    out, _ = succeeds(capsys, ["forces", path, "--angles", "45"])
    lines = out.splitlines()
    assert len(lines) == 4
    row = dict(zip(lines[0].split(), map(float, lines[2].split()), strict=True))
    expected = assur.forces(assur.load(path), [45.0])
    assert row["angle"] == 45.0
    np.testing.assert_allclose(
        row["driver.torque"], expected["driver.torque"][0], rtol=1e-5, atol=0
    )


@pytest.mark.parametrize(
    ("spec", "angles"),
    [
        ("0:90:30", [0.0, 30.0, 60.0, 90.0]),
        ("0:100:30", [0.0, 30.0, 60.0, 90.0]),
        ("0:1:0.1", np.linspace(0.0, 1.0, 11)),
        ("90:0:-45", [90.0, 45.0, 0.0]),
        ("-30", [-30.0]),
        ("10:10:5", [10.0]),
    ],
)
def test_angle_ranges(spec, angles, capsys):
    out, _ = succeeds(
        capsys,
        ["kinematics", EXAMPLES / "four_bar.toml", f"--angles={spec}", "--csv", "-"],
    )
    header, values = read_csv(out)
    np.testing.assert_allclose(
        values[:, header.index("angle")], angles, rtol=0, atol=1e-12
    )
    np.testing.assert_allclose(parse_angles(spec), angles, rtol=0, atol=1e-12)


def test_negative_start_as_a_separate_argument(capsys):
    succeeds(
        capsys, ["kinematics", EXAMPLES / "four_bar.toml", "--angles", "-30:30:10"]
    )


def test_csv_to_stdout_matches_the_library(capsys):
    path = EXAMPLES / "offset_slider_crank.toml"
    out, err = succeeds(capsys, ["forces", path, "--angles", "0:360:45", "--csv", "-"])
    assert err == ""
    header, values = read_csv(out)
    table = assur.forces(assur.load(path), np.arange(0.0, 361.0, 45.0))
    assert header == list(table.columns)
    assert values.shape == (9, len(table.columns))
    for i, column in enumerate(header):
        np.testing.assert_allclose(
            values[:, i], table[column], rtol=1e-11, atol=1e-9, err_msg=column
        )
    assert out == table.to_csv()


def test_the_mechanism_read_from_standard_input(capsys, monkeypatch):
    import io

    def piped(data: bytes) -> None:
        monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(data)))

    text = (EXAMPLES / "four_bar.toml").read_bytes()
    piped(text)
    out, _ = succeeds(capsys, ["structure", "-"])
    assert out == str(assur.structure(assur.load(EXAMPLES / "four_bar.toml"))) + "\n"
    # JSON too, told by its opening brace
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    piped(assur.dumps(mech, json_format=True).encode())
    out, _ = succeeds(capsys, ["forces", "-", "--angles", "45", "--csv", "-"])
    assert out == assur.forces(mech, [45.0]).to_csv()
    # a fault names <stdin>, as it names a file
    piped(b"format = 1\n[links.a]\n")
    assert main(["kinematics", "-"]) == 2
    assert capsys.readouterr().err == (
        "assur: error: <stdin>: links.a: a link with no joints; expected it in some "
        "joint's links\n"
    )
    monkeypatch.setattr(sys, "stdin", None)  # started closed (<&-)
    assert main(["structure", "-"]) == 2
    assert capsys.readouterr().err == (
        "assur: error: <stdin>: standard input is closed; expected a mechanism file "
        "piped in\n"
    )
    # a terminal: reading waited, without a word, for a file typed in
    piped(text)
    monkeypatch.setattr(sys.stdin, "isatty", lambda: True)
    assert main(["structure", "-"]) == 2
    assert capsys.readouterr().err == (
        "assur: error: <stdin>: standard input is a terminal; expected a mechanism "
        "file piped in (assur structure - < four_bar.toml)\n"
    )


def test_csv_to_a_path(tmp_path, capsys):
    target = tmp_path / "table.csv"
    out, _ = succeeds(
        capsys,
        ["kinematics", EXAMPLES / "tenbar.toml", "--angles", "0:10:1", "--csv", target],
    )
    header, values = read_csv(target.read_text(encoding="utf-8"))
    assert values.shape == (11, len(header))
    assert out == f"wrote 11 rows x {len(header)} columns to {target}\n"
    assert {"9.angle", "M.x", "guide.s", "guide.j"} <= set(header)
    out, _ = succeeds(
        capsys,
        ["kinematics", EXAMPLES / "tenbar.toml", "--angles", "10", "--csv", target],
    )
    assert out == f"wrote 1 row x {len(header)} columns to {target}\n"  # not "1 rows"


def test_json(capsys):
    path = EXAMPLES / "whitworth.toml"
    out, _ = succeeds(capsys, ["forces", path, "--angles", "0:180:90", "--json"])
    data = json.loads(out)
    table = assur.forces(assur.load(path), [0.0, 90.0, 180.0])
    assert data["name"] == "Whitworth quick-return mechanism"
    assert data["columns"] == list(table.columns)
    assert [row["angle"] for row in data["rows"]] == [0.0, 90.0, 180.0]
    np.testing.assert_allclose(
        [row["driver.torque"] for row in data["rows"]],
        table["driver.torque"],
        rtol=1e-12,
        atol=0,
    )


def test_two_drivers_with_comma_ranges(capsys):
    path = EXAMPLES / "five_bar_two_cranks.toml"
    out, _ = succeeds(
        capsys, ["forces", path, "--angles", "0:20:10,100:120:10", "--csv", "-"]
    )
    header, values = read_csv(out)
    column = dict(zip(header, values.T, strict=True))
    np.testing.assert_allclose(column["A.drive"], [0.0, 10.0, 20.0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        column["E.drive"], [100.0, 110.0, 120.0], rtol=0, atol=1e-12
    )
    np.testing.assert_allclose(column["angle"], column["A.drive"], rtol=0, atol=0)
    np.testing.assert_allclose(
        column["driver.torque"], column["A.torque"], rtol=0, atol=0
    )
    assert "E.torque" in column
    out, _ = succeeds(capsys, ["kinematics", path, "--angles", "5,15"])
    assert len(out.splitlines()) == 4


# --- positions that cannot be assembled --------------------------------------------


def test_unassembled_positions_fail(double_rocker, capsys):
    text = fails(
        capsys, ["kinematics", double_rocker, "--angles", "0:360:30"], double_rocker
    )
    assert text == (
        "group RRR (coupler, rocker): cannot be assembled at driver position "
        "0 deg (9 of 13 positions fail, 2 more out of reach from the reference pose); "
        "it assembles for 30 deg to 60 deg"
        " (--skip-unassembled leaves such positions out)"
    )
    text = fails(capsys, ["forces", double_rocker, "--angles", "120"], double_rocker)
    assert text.startswith(
        "group RRR (coupler, rocker): cannot be assembled at driver "
        "position 120 deg (1 of 1 position fails)"
    )


def test_skip_unassembled(double_rocker, capsys):
    out, err = succeeds(
        capsys,
        [
            "kinematics",
            double_rocker,
            "--angles",
            "0:360:30",
            "--skip-unassembled",
            "--csv",
            "-",
        ],
    )
    _, values = read_csv(out)
    # 300 and 330 deg: the other circuit
    np.testing.assert_allclose(values[:, 0], [30.0, 60.0], rtol=0, atol=1e-12)
    lines = err.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(
        f"assur: note: {double_rocker}: left out 11 positions "
        "where a group cannot be assembled, stands at a dead centre or a change "
        "point, or is locked by friction, or that the mechanism cannot reach from "
        "its reference pose: "
    )
    # read from standard input, the note names it as errors do ("-: left out ...")
    import io

    data = io.BytesIO(double_rocker.read_bytes())
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(sys, "stdin", io.TextIOWrapper(data))
        argv = ["kinematics", "-", "--angles", "0:360:30", "--skip-unassembled"]
        _, err = succeeds(capsys, [*argv, "--csv", "-"])
    assert err.startswith("assur: note: <stdin>: left out 11 positions ")
    out, err = succeeds(
        capsys,
        [
            "forces",
            double_rocker,
            "--angles",
            "0:360:30",
            "--skip-unassembled",
            "--json",
        ],
    )
    np.testing.assert_allclose(
        [row["angle"] for row in json.loads(out)["rows"]],
        [30.0, 60.0],
        rtol=1e-12,
        atol=0,
    )
    assert "left out 11 positions" in err


def test_skip_unassembled_names_runs_of_positions_in_degrees(double_rocker, capsys):
    # 0, 90, 120, ..., 360 deg left out, 30 and 60 kept: two runs as the sweep
    # lists them (the closing pose's run is not joined to the first)
    _, err = succeeds(
        capsys,
        ["kinematics", double_rocker, "--angles", "0:360:30", "--skip-unassembled"],
    )
    assert err.splitlines()[0].endswith("reference pose: 0 deg; 90 deg to 360 deg")


def test_minus_zero_is_shown_as_zero(capsys):
    # a value that is zero shows as 0 whatever its sign bit (atan2 and products of
    # zeros give -0.0): in readable tables and the dynamic model's figures
    from assur._cli_summary import format_table

    text = format_table(["a", "b"], ["N", "m"], [np.array([-0.0]), np.array([-1.5])], 1)
    assert text.splitlines()[2].split() == ["0", "-1.5"]
    # one row more than shown: "1 more rows" it said
    text = format_table(["a"], ["N"], [np.array([1.0])], 2, limit=1)
    assert text.splitlines()[-1] == "... 1 more row: --csv PATH or --json for all"
    out, _ = succeeds(capsys, ["dynamics", EXAMPLES / "four_bar.toml", "--angles", "0"])
    assert "  motor torque " in out
    assert "-0 " not in out


def test_round_off_is_shown_as_zero_in_the_readable_table(capsys):
    # at its dead centres the slider-crank's rod turned at -1.49379e-14 rad/s
    # beside 74 rad/s: the sign and digits of this machine's arithmetic, other
    # ones on another CPU or BLAS; 0 on every one, as in the HTML report
    path = EXAMPLES / "slider_crank_exercise.toml"
    angles = [0.0, 90.0, 180.0, 270.0, 360.0]
    omega = np.asarray(assur.kinematics(assur.load(path), angles)["rod.omega"])
    assert abs(omega[1]) < 1e-12 * np.max(np.abs(omega))  # round-off there
    out, _ = succeeds(capsys, ["kinematics", path, "--angles", "0:360:90"])
    lines = out.splitlines()
    rows = [dict(zip(lines[0].split(), r.split(), strict=True)) for r in lines[2:7]]
    assert [r["rod.omega"] for r in rows] == ["-74", "0", "74", "0", "-74"]
    # the dynamic model's table: the acceleration at the largest speed
    out, _ = succeeds(capsys, ["dynamics", path])
    lines = out.splitlines()
    (heads,) = [r.split() for r in lines if r.startswith("angle ")]
    (row,) = [r.split() for r in lines if r.startswith("  180  ")]
    # 3e-12 rad/s^2 beside 1e4 rad/s^2
    assert dict(zip(heads, row, strict=True))["driver.epsilon"] == "0"


def test_round_off_is_told_by_the_largest_value_of_its_unit():
    from assur._cli_summary import format_table

    columns = [
        np.array([1000.0, 1e-8]),
        np.array([1e-8, -2e-6]),
        np.array([-1e-7, 3e-7]),
    ]
    text = format_table(["F", "x", "y"], ["N", "m", "m"], columns, 2)
    # 1e-8 N beside 1000 N is round-off; a small mechanism's 1e-8 m is its own
    assert [r.split() for r in text.splitlines()[2:]] == [
        ["1000", "1e-08", "-1e-07"],
        ["0", "-2e-06", "3e-07"],
    ]


@pytest.mark.parametrize("width", [30, 44, 80, 1000])
def test_a_wide_table_is_cut_to_the_terminal_s_width(width):
    # six_bar_lecture's 19 columns ran 156 characters wide, each row wrapped
    from assur._cli_summary import format_table

    names = ["angle"] + [f"link{i}.omega" for i in range(12)]
    columns = [np.arange(3.0) * 10] + [np.full(3, -1234.5678 * i) for i in range(12)]
    text = format_table(names, ["deg"] + ["rad/s"] * 12, columns, 3, width=width)
    blocks = [b.splitlines() for b in text.split("\n\n")]
    whole = format_table(names, ["deg"] + ["rad/s"] * 12, columns, 3)
    if max(map(len, whole.splitlines())) <= width:
        assert blocks == [whole.splitlines()]
        return
    assert len(blocks) > 1
    seen = []
    for block in blocks:
        assert len(block) == 2 + 3  # heads, units, rows
        assert all(len(line) <= width for line in block)
        heads = block[0].split()
        assert heads[0] == "angle"  # each block led by the driver's position
        assert [line.split()[0] for line in block[2:]] == ["0", "10", "20"]
        seen += heads[1:]
    assert seen == names[1:]  # every column once, in order


def test_the_readable_table_fits_the_terminal(capsys, monkeypatch):
    import os
    import shutil

    path = EXAMPLES / "six_bar_lecture.toml"
    piped, _ = succeeds(capsys, ["kinematics", path, "--angles", "0:30:10"])
    assert max(map(len, piped.splitlines())) > 80  # in a pipe: one row a line
    monkeypatch.setattr(sys.stdout, "isatty", lambda: True)
    size = os.terminal_size((80, 24))
    monkeypatch.setattr(shutil, "get_terminal_size", lambda *a, **k: size)
    shown, _ = succeeds(capsys, ["kinematics", path, "--angles", "0:30:10"])
    assert max(map(len, shown.splitlines())) <= 80
    heads = [line.split()[0] for line in shown.splitlines() if line.startswith("angle")]
    assert heads == ["angle"] * 3  # three blocks of columns
    assert sorted(shown.split()) != sorted(piped.split())  # the angles repeat
    assert set(shown.split()) == set(piped.split())


def test_a_range_near_the_largest_float(recwarn):
    # STEP times the count overflowed (an inf, a RuntimeWarning), the range was sound
    found = parse_angles("-1.7e308:1.7e308:1e308")
    np.testing.assert_allclose(
        found, [-1.7e308, -0.7e308, 0.3e308, 1.3e308], rtol=1e-15
    )
    assert not recwarn.list
    # and ordinary ranges keep every bit: START + STEP * k
    for start, step, count in ((0.0, 0.1, 3601), (-33.3, 0.37, 2793)):
        found = parse_angles(f"{start}:{start + step * (count - 1)}:{step}")
        np.testing.assert_array_equal(found, start + step * np.arange(count))


def test_version(capsys):
    # main() turns argparse's exit into its status
    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"assur {assur.__version__}\n"


def test_one_position_out_of_the_range_says_where_the_range_is(double_rocker, capsys):
    # "it assembles for none of them" was all a student got for --angle 200 (and
    # "none of them" is not said of one position)
    text = fails(capsys, ["forces", double_rocker, "--angles", "200"], double_rocker)
    found = re.search(
        r"\(1 of 1 position fails\); the mechanism reaches only positions from about "
        r"(\S+) deg to (\S+) deg \(or whole turns from them\)",
        text,
    )
    assert found is not None, text
    low, high = (float(v) for v in found.groups())
    # the range the sweep of test_unassembled_positions_fail found, 30 to 60 deg in
    # steps of 30, within the scan's step
    assert low < 30.0 < 60.0 < high < 200.0
    assert text.endswith("(--skip-unassembled leaves such positions out)")


@pytest.mark.parametrize(
    "outputs",
    [["--csv", "t.csv"], ["--json"], ["--csv", "t.csv", "--parquet", "t.parquet"], []],
)
def test_a_sweep_with_every_position_left_out_is_an_error(
    outputs, tmp_path, capsys, monkeypatch
):
    # "wrote 0 rows x 83 columns" and exit status 0, where the pictures of the same
    # sweep stop with this error; in slices of 2, no output opens before it
    from assur import _sliced

    monkeypatch.setattr(_sliced, "CHUNK", 2)
    if "--parquet" in outputs:
        pytest.importorskip("pyarrow")
    path = tmp_path / "rocker.toml"
    assur.save(assur.catalog.four_bar(crank=0.09), path)
    argv = ["kinematics", path, "--angles", "-15:15:10", "--skip-unassembled"]
    argv += [str(tmp_path / a) if a.startswith("t.") else a for a in outputs]
    text = fails(capsys, argv, path)
    assert text.startswith("every position of the sweep is left out (where a group ")
    # and why, at the first: the group, the position and where it assembles
    assert "friction); at the first, group RRR (coupler, rocker): cannot be " in text
    # the first position's own count ("1 of 1 position fails") is not the sweep's
    assert " deg; the mechanism reaches only" in text
    assert "1 of 1" not in text
    assert text.endswith("; expected positions where the mechanism moves")
    assert sorted(os.listdir(tmp_path)) == ["rocker.toml"]
    # the summary says the same, not that it has nothing to summarise
    text = fails(capsys, ["forces", *argv[1:5], "--summary"], path)
    assert text.startswith("every position of the sweep is left out")
    # one position is the one
    text = fails(
        capsys, ["kinematics", path, "--angles", "0", "--skip-unassembled"], path
    )
    assert text.startswith("the one position of the sweep is left out (")
    assert "friction); there, group RRR (coupler, rocker): cannot be " in text


@pytest.mark.parametrize(
    "argv",
    [
        ["kinematics", "--csv", "{missing}/t.csv"],
        ["forces", "--parquet", "{missing}/t.parquet"],
        ["dynamics", "--csv", "{missing}/d.csv"],
        ["dynamics", "--startup-csv", "{missing}/s.csv"],
    ],
)
def test_a_table_in_a_missing_folder_is_refused_before_the_analysis(
    argv, tmp_path, capsys
):
    # found when the first slice was written, after the analysis (an analysis that
    # fails, here a crank asked for a pose it cannot reach, spoke first)
    path = tmp_path / "rocker.toml"
    assur.save(assur.catalog.four_bar(crank=0.09), path)
    missing = tmp_path / "no" / "such"
    command, option, target = argv
    target = Path(target.format(missing=missing))
    status = main([command, str(path), "--angles", "0", option, str(target)])
    err = capsys.readouterr().err
    assert status == 2
    assert err == (
        f"assur: error: {target}: cannot write the file (No such file or directory)\n"
    )


def test_a_sweep_left_out_whole_says_one_expected(capsys):
    # "...; expected less friction, or positions where it can be driven; expected
    # positions where the mechanism moves": two clauses of what was expected
    path = Path(__file__).parent / "data" / "friction" / "rpp_steep.toml"
    text = fails(
        capsys, ["forces", path, "--angles", "200", "--skip-unassembled"], path
    )
    assert text.startswith("the one position of the sweep is left out (")
    assert text.count("expected") == 1, text
    assert text.endswith(
        "; expected less friction, or positions where it can be driven"
    )


def test_one_position_by_default_is_the_reference_pose(capsys):
    # a prismatic driver's default positions start a stroke below the pose, and
    # --angle's default ("the reference pose") took the first of them: -0.05 m
    data = Path(__file__).parent / "data"
    ram = str(data / "explain" / "slider_driven.toml")
    assert main(["explain", ram]) == 0
    heading = capsys.readouterr().out.splitlines()[0]
    assert heading.endswith("at driver position 0 m: the analysis explained")
    # the same pose as asked for by its value
    assert main(["explain", ram, "--angle", "0"]) == 0
    assert capsys.readouterr().out.splitlines()[0] == heading
    # a crank's is its angle in the file; beside a ram, each driver its own
    from assur._cli_common import one_position

    assert float(one_position(assur.catalog.four_bar(), None)) == pytest.approx(60.0)
    # (its crank drawn at 0 deg, then its ram)
    both = assur.load(data / "edge" / "drag_link_beside_a_ram.toml")
    assert [d.kind for d in assur.plan.plan_of(both).drivers] == ["R", "P"]
    np.testing.assert_array_equal(one_position(both, None), [0.0, 0.0])
    assert assur.analysis.default_positions(both)[0][1] < 0.0
