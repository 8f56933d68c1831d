"""The messages of docs/errors.rst are the ones the command line prints.

Every console block of the page is run from ``docs/files/errors``: its ``$ assur``
line is the command, the lines after it are what the command prints on standard
error, exactly, and the exit status is 2 when one of them is an error, else 0.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from assur.cli import main

DOCS = Path(__file__).parent.parent / "docs"
PAGE = DOCS / "errors.rst"
FOLDER = "docs/files/errors"  # where the page tells the reader to run its commands


def commands() -> list[tuple[list[str], list[str]]]:
    """Each ``$ assur ...`` line of the page's console blocks and the lines after it."""
    found: list[tuple[list[str], list[str]]] = []
    for block in re.split(r"\.\. code-block:: console\n", PAGE.read_text("utf-8"))[1:]:
        lines = []
        for line in block.splitlines()[1:]:
            if line and not line.startswith("   "):
                break
            lines.append(line.strip())
        for line in lines:
            if line.startswith("$ assur "):
                found.append((shlex.split(line[len("$ assur ") :]), []))
            elif line and found:
                found[-1][1].append(line)
    return found


CASES = commands()


def test_the_page_shows_every_error_kind():
    assert len(CASES) >= 9
    text = PAGE.read_text("utf-8")
    import assur.errors

    for name in assur.errors.__all__:
        assert f"~assur.errors.{name}`" in text, name


def test_the_page_says_where_its_commands_run():
    # its commands name the files bare: a reader at the root got "cannot read the file"
    assert f"``cd {FOLDER}``" in PAGE.read_text("utf-8")
    assert all((DOCS.parent / FOLDER / argv[1]).is_file() for argv, _ in CASES[:3])


def test_the_conventions_table_lists_every_error_kind():
    text = (DOCS / "conventions.rst").read_text("utf-8")
    import assur.errors

    for name in assur.errors.__all__:
        if name != "AssurError":  # the base class, named above the table
            assert f"* - :class:`~assur.errors.{name}`" in text, name


@pytest.mark.parametrize(("argv", "lines"), CASES, ids=[" ".join(a) for a, _ in CASES])
def test_each_message_is_printed_as_shown(argv, lines, monkeypatch, capsys):
    monkeypatch.chdir(DOCS.parent / FOLDER)
    status = main(argv)
    err = capsys.readouterr().err.strip().splitlines()
    assert err == lines
    assert status == (2 if any(x.startswith("assur: error:") for x in lines) else 0)
