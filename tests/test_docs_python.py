"""The documentation's ``.. code-block:: python`` snippets run as a reader runs them.

The ``>>>`` examples are doctests (tests/test_examples.py); the other Python blocks
of ``docs/*.rst`` were never run, so a block could use a name no block of its page
defines. Here the blocks of a page run in order in one namespace, as a reader pastes
them one after the other into a session, from a scratch directory where the pages'
``examples/`` and ``docs/`` paths point. A file a block reads that the page makes
with an ``assur`` command shown before it (``tenbar.csv``) is made by that command.
A block that needs a machine the reader names (a cluster's scheduler at
``tcp://...``) cannot run here: every name it uses must then be defined by the
page's earlier blocks, by the block itself or by Python. The numbers the
conventions page reads off a table in prose, and the reactions the walk-throughs of
the explanatory note quote, are the table's.
"""

from __future__ import annotations

import ast
import builtins
import doctest
import re
import shlex
from pathlib import Path

import pytest

from assur.cli import main

ROOT = Path(__file__).resolve().parent.parent
OPENING = ".. code-block:: python"


def _blocks(text: str) -> list[tuple[int, str]]:
    """The code of each Python block of an rst page, in the page's order.

    Each item is (line, code): a ``.. code-block:: python`` block dedented, or one
    ``>>>`` example, whose names the blocks after it use (``mech``).
    """
    lines = text.splitlines()
    blocks: list[tuple[int, str]] = [
        (example.lineno, example.source)
        for example in doctest.DocTestParser().get_examples(text)
    ]
    for number, line in enumerate(lines):
        if line.strip() != OPENING:
            continue
        indent = len(line) - len(line.lstrip()) + 3
        body: list[str] = []
        for later in lines[number + 1 :]:
            if later.strip() and len(later) - len(later.lstrip()) < indent:
                break
            body.append(later[indent:])
        blocks.append((number, "\n".join(body).strip("\n") + "\n"))
    return sorted(blocks)


PAGES = {
    page.name: _blocks(page.read_text("utf-8"))
    for page in sorted((ROOT / "docs").glob("*.rst"))
    if OPENING in page.read_text("utf-8")
}


def _free_names(code: str) -> set[str]:
    """The names ``code`` reads that it neither assigns nor imports."""
    tree = ast.parse(code)
    bound: set[str] = set()
    read: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            (read if isinstance(node.ctx, ast.Load) else bound).add(node.id)
        elif isinstance(node, ast.alias):
            bound.add((node.asname or node.name).split(".")[0])
        elif isinstance(node, ast.FunctionDef | ast.ClassDef):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
    return read - bound - set(dir(builtins))


def _make_files(page: str, code: str) -> None:
    """Write the files ``code`` reads by running the page's command that writes them."""
    text = (ROOT / "docs" / page).read_text("utf-8")
    for name in re.findall(r"[\"']([\w.-]+\.(?:csv|json|parquet))[\"']", code):
        if Path(name).exists():
            continue
        shown = re.search(
            rf"^\s*\$ (assur .*(?:--csv|--json|--parquet) {name})", text, re.M
        )
        assert shown, f"{page}: no command on the page writes {name}"
        argv = shlex.split(shown.group(1))[1:]
        argv = [
            str(ROOT / w) if w.split("/")[0] in ("examples", "docs") else w
            for w in argv
        ]
        assert main(argv) == 0


def test_the_pages_have_python_blocks():
    # a change to the pages' markup must not leave this test without cases
    assert {"getting_started.rst", "study.rst", "dynamics.rst"} <= set(PAGES)


@pytest.mark.parametrize("page", sorted(PAGES))
def test_python_blocks_run_in_order(page, tmp_path, monkeypatch, capsys):
    matplotlib = pytest.importorskip("matplotlib")
    if any("pandas" in code or "assur.sweep(" in code for _, code in PAGES[page]):
        pytest.importorskip("pandas")  # the study extra
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    monkeypatch.setattr(plt, "show", lambda *args, **kwargs: None)
    for folder in ("examples", "docs"):
        (tmp_path / folder).symlink_to(ROOT / folder)
    monkeypatch.chdir(tmp_path)
    scope: dict = {"__name__": "__main__"}
    try:
        for line, code in PAGES[page]:
            where = f"{page}:{line + 1}"
            if "tcp://" in code:  # a cluster the reader names
                unknown = _free_names(code) - set(scope)
                assert not unknown, f"{where}: the block uses {sorted(unknown)}"
                continue
            _make_files(page, code)
            exec(compile(code, where, "exec"), scope)
    finally:
        plt.close("all")


def test_the_conventions_worked_reading_quotes_the_table():
    # "``A.Fx, A.Fy`` = (−7563.5, −5946.2) N": the signs a reader learns from
    import assur

    page = (ROOT / "docs" / "conventions.rst").read_text("utf-8")
    section = page.split("A worked reading")[1].split(".. _errors:")[0]
    at = float(re.search(r"At (\d+)°", section).group(1))
    table = assur.forces(assur.load(ROOT / "examples/slider_crank_exercise.toml"), [at])
    quoted = re.findall(
        r"``([\w., ]+)`` = \(?([−\d., ]+?)\)? (?:N|is|because)", section
    )
    assert len(quoted) >= 5
    for names, values in quoted:
        for name, text in zip(names.split(", "), values.split(", "), strict=True):
            places = len(text.partition(".")[2])
            got = round(float(table[name][0]), places)
            assert got == float(text.replace("−", "-")), f"{name}: {got}, not {text}"


def _quoted_forces(text: str) -> list[tuple[str, str, str, str]]:
    """Each ``\\vec F_{i,j} = (x, y)`` a page writes: (i, j, x, y), i's force on j."""
    name = r"\\mathrm\{(\w+)\}"
    number = r"(-?[\d.]+)"
    return re.findall(rf"\\vec F_\{{{name},{name}\}} = \({number}, {number}\)", text)


@pytest.mark.parametrize("page", ["explain.rst", "explain_six_bar.rst"])
def test_the_reactions_a_page_quotes_are_the_table_s(page):
    # the walk-throughs quote the note's reactions: link i's force on link j
    import assur

    text = " ".join((ROOT / "docs" / page).read_text("utf-8").split())
    file, angle = re.search(r"\$ assur explain (\S+) --angle (\S+)", text).groups()
    mech = assur.load(ROOT / file)
    table = assur.forces(mech, [float(angle)])
    quoted = _quoted_forces(text)
    assert len(quoted) >= 2
    for first, second, *shown in quoted:
        (joint,) = [j for j in mech.joints if set(j.links) == {first, second}]
        sign = 1.0 if joint.links[0] == first else -1.0  # J.F is links[0] on links[1]
        for axis, value in zip("xy", shown, strict=True):
            got = sign * float(table[f"{joint.name}.F{axis}"][0])
            places = len(value.partition(".")[2])
            assert abs(got - float(value)) <= 0.5 * 10.0**-places + 1e-9, (
                f"{page}: F_{first},{second} {axis} is {got}, not {value}"
            )
