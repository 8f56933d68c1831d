"""The output the documentation shows is the output the command line prints today.

Every ``$ assur ...`` line of a console or bash block of ``docs/*.rst`` and README.md
that has lines after it is run from the repository's root, as a reader types it, and
each line shown must be printed (on standard output or standard error), in the order
shown. A line ``...`` stands for lines left out; a line with ``...`` inside it is a
printed line cut to fit the page: it must start with what comes before the ``...``
and end with what comes after. docs/errors.rst has its own test
(tests/test_docs_errors.py), which runs its blocks from ``docs/files/errors``.

A few commands read a file the page only describes (``bad.toml`` with a misspelt
key): the test writes it, from the example it is taken from, with the page's fault.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from assur.cli import main

ROOT = Path(__file__).resolve().parent.parent
PAGES = [p for p in sorted((ROOT / "docs").glob("*.rst")) if p.name != "errors.rst"]
README = (ROOT / "README.md").read_text("utf-8")
PICTURES = {"plot", "plans", "diagrams", "animate", "report"}
EXERCISE = ROOT / "examples" / "slider_crank_exercise.toml"
RODS = 'links = ["crank", "rod"]'

# the files of docs/file_format.rst's commands: (file, example, text, replacement)
DESCRIBED = {
    "structure bad.toml": ("bad.toml", "mass = 10.0", "mas = 10.0"),
    "kinematics bad.toml": ("bad.toml", RODS, RODS.replace("rod", "rdo")),
    "dynamics engine.toml --startup": (
        "engine.toml",
        "",
        "\n[motor]\ntorque = 5.0\nno_load_speed = -3.0\n",
    ),
}


def _block_lines(text: str, markdown: bool) -> list[list[tuple[int, str]]]:
    """The lines (number, text) of each console or bash block of a page."""
    lines = text.splitlines()
    blocks: list[list[tuple[int, str]]] = []
    fence = r"^```(console|bash)$"
    opening = fence if markdown else r"^\.\. code-block:: (console|bash)$"
    for number, line in enumerate(lines):
        if not re.match(opening, line):
            continue
        block = []
        for later in range(number + 1, len(lines)):
            body = lines[later]
            if (markdown and body.startswith("```")) or (
                not markdown and body and not body.startswith("   ")
            ):
                break
            block.append((later + 1, body))
        blocks.append(block)
    return blocks


def commands() -> list[tuple[str, str, list[str]]]:
    """Each shown command with output: (page:line, command, the lines shown)."""
    found: list[tuple[str, str, list[str]]] = []
    for page in [*PAGES, ROOT / "README.md"]:
        for block in _block_lines(page.read_text("utf-8"), page.suffix == ".md"):
            current: list[tuple[str, str, list[str]]] = []
            for number, line in block:
                text = line.strip()
                if text.startswith("$ "):
                    where = f"{page.name}:{number}"
                    current.append((where, text[2:].split(" #")[0].strip(), []))
                elif current and current[-1][1].endswith("\\"):  # continued
                    where, command, _ = current.pop()
                    current.append((where, f"{command[:-1].strip()} {text}", []))
                elif text and current:
                    current[-1][2].append(text)
            found += [case for case in current if case[1].startswith("assur ")]
    return [case for case in found if case[2]]


CASES = commands()


def _matches(shown: str, printed: str) -> bool:
    if shown == printed:
        return True
    if "..." not in shown:
        return False
    head, *_, tail = (part.strip() for part in shown.split("..."))
    return printed.startswith(head) and printed.endswith(tail)


def _argument(word: str) -> str:
    """A path into the repository made absolute; any other word as it is."""
    if word.split("/")[0] in ("examples", "docs"):
        return str(ROOT / word)
    return word


def test_the_pages_show_the_output_of_commands():
    # a change to the pages' markup must not leave this test without cases
    pages = {where.split(":")[0] for where, _, _ in CASES}
    wanted = {"cli.rst", "concepts.rst", "getting_started.rst", "file_format.rst"}
    assert wanted <= pages
    assert len(CASES) >= 15


@pytest.mark.parametrize(
    ("where", "command", "shown"), CASES, ids=[f"{w} {c}" for w, c, _ in CASES]
)
def test_each_command_prints_what_the_page_shows(
    where, command, shown, tmp_path, monkeypatch, capsys
):
    argv = shlex.split(command)[1:]
    if argv[0] in PICTURES:
        pytest.importorskip("matplotlib")
    rest = " ".join(argv)
    if rest in DESCRIBED:
        name, old, new = DESCRIBED[rest]
        text = EXERCISE.read_text("utf-8")
        assert not old or text.count(old) == 1
        text = text.replace(old, new) if old else text + new
        (tmp_path / name).write_text(text, encoding="utf-8")
    monkeypatch.chdir(tmp_path)  # what the command writes lands here
    status = main([_argument(word) for word in argv])
    out, err = capsys.readouterr()
    printed = [line.strip() for line in (out + err).splitlines()]
    error = any(line.startswith("assur: error:") for line in shown)
    assert status == (2 if error else 0), err
    # every line shown is printed, in the order shown
    left = iter(printed)
    missing = [
        line
        for line in shown
        if line != "..." and not any(_matches(line, got) for got in left)
    ]
    assert not missing, f"{where}: not printed: {missing}"


def test_the_readme_s_error_is_the_one_printed(tmp_path, monkeypatch, capsys):
    readme = (ROOT / "README.md").read_text("utf-8")
    quoted = re.search(r"`(assur: error: m\.toml: [^`]*)`", readme)
    assert quoted
    text = EXERCISE.read_text("utf-8")
    (tmp_path / "m.toml").write_text(text.replace(RODS, RODS.replace("rod", "rodd")))
    monkeypatch.chdir(tmp_path)
    assert main(["forces", "m.toml"]) == 2
    assert capsys.readouterr().err.strip() == quoted.group(1)


def _plain(markdown: str) -> str:
    """A line of the note's Markdown as the page writes it in plain text."""
    text = re.sub(r"\\mathrm\{([^}]*)\}", r"\1", markdown.replace("$", ""))
    text = text.replace("\\cdot", "·").replace("\\ ", " ").replace("^2", "²")
    return " ".join(re.sub(r"_\{([^}]*)\}", r"_\1", text).split())


def test_the_explain_page_quotes_the_note_s_verdict_on_the_given_answers(capsys):
    # the page quoted "...= 1282.566 N; the acceleration agrees, the difference",
    # where the note prints "... = 1282.566 N. The acceleration agrees; the difference"
    page = (ROOT / "docs" / "explain.rst").read_text("utf-8")
    quoted = re.search(r"says: \*([Tt]he given .*?)\*", page, re.S)
    assert quoted
    answers = ROOT / "docs" / "files" / "slider_crank_exercise_answers.toml"
    argv = ["explain", str(EXERCISE), "--angle", "45", "--answers", str(answers)]
    assert main(argv) == 0
    note = capsys.readouterr().out
    said = [_plain(line) for line in note.splitlines() if line.startswith("The given ")]
    assert said == [" ".join(quoted.group(1).split())]


def test_the_readme_s_quick_start_states_the_printed_torque(capsys):
    # "balancing torque 84.625 N m at 45 degrees": the first command's row at 45
    readme = (ROOT / "README.md").read_text("utf-8")
    stated = re.search(r"balancing torque ([-\d.]+) N m at ([\d.]+) degrees", readme)
    command = re.search(r"assur (forces examples/\S+ --angles \S+)\n", readme)
    assert stated
    assert command
    argv = [_argument(word) for word in command.group(1).split()]
    assert main(argv) == 0
    rows = [line.split() for line in capsys.readouterr().out.splitlines()]
    column = rows[0].index("driver.torque")
    row = next(r for r in rows[2:] if float(r[0]) == float(stated.group(2)))
    assert row[column] == stated.group(1)


def test_the_readme_s_code_comments_state_the_values_computed():
    # a line ``expression   # 0.075, -0.0225 N m`` states the expression's values
    import numpy as np

    stated = re.compile(r"^(\S.*?)\s+# (-?[\d.]+(?:, -?[\d.]+)*) \S.*$")
    checked = 0
    for block in re.findall(r"^```python\n(.*?)^```", README, re.M | re.S):
        lines = block.splitlines()
        for number, line in enumerate(lines):
            found = stated.match(line)
            if not found:
                continue
            scope: dict = {}
            exec("\n".join(lines[:number]), scope)  # the README's own code
            values = np.atleast_1d(eval(found.group(1), scope))
            shown = found.group(2).split(", ")
            assert len(values) == len(shown), line
            for value, text in zip(values, shown, strict=True):
                places = len(text.partition(".")[2])
                assert round(float(value), places) == float(text), line
            checked += 1
    assert checked
