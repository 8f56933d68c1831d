"""Every ``assur`` command the README and the pages show is one the program takes.

tests/test_docs_output.py runs the commands shown with their output; a command shown
alone (the README's "Using it" list, ``assur animate ... -o four_bar.gif``) was run
by no test, so an option renamed or a bundled file moved would leave it wrong
unnoticed. Each such line is parsed here by the command line's own parser, and the
files it reads must be where the reader finds them: in the source tree, from its top
folder, or in ``docs/files/errors`` for the errors page (tests/test_docs_errors.py).
A file a page only describes (``bad.toml``) is left to tests/test_docs_output.py.
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from assur.cli import _parser

ROOT = Path(__file__).resolve().parent.parent
DESCRIBED = {"bad.toml", "engine.toml"}  # files the pages describe, not ship


def _shown() -> list[tuple[str, Path, list[str]]]:
    """Each command line shown: (page:line, the folder it runs from, its words)."""
    found: list[tuple[str, Path, list[str]]] = []
    pages = [*sorted((ROOT / "docs").glob("*.rst")), ROOT / "README.md"]
    for page in pages:
        lines = page.read_text("utf-8").splitlines()
        folder = ROOT / "docs/files/errors" if page.name == "errors.rst" else ROOT
        markdown = page.suffix == ".md"
        opening = (
            r"^```(console|bash)$"
            if markdown
            else r"^\.\. code-block:: (console|bash)$"
        )
        inside = False
        for number, line in enumerate(lines, start=1):
            if re.match(opening, line):
                inside = True
                continue
            ended = line.startswith("```") if markdown else line[:1] not in ("", " ")
            inside = inside and not ended
            text = line.strip().removeprefix("$ ")
            if not inside or not text.startswith("assur "):
                continue
            later = number
            while text.endswith("\\"):  # continued on the next line
                text = f"{text[:-1].strip()} {lines[later].strip()}"
                later += 1
            words = shlex.split(text.split(" #")[0])
            found.append((f"{page.name}:{number}", folder, words[1:]))
    return found


CASES = _shown()


def test_the_readme_and_the_pages_show_commands():
    pages = {where.split(":")[0] for where, _, _ in CASES}
    assert {"README.md", "getting_started.rst", "cli.rst", "errors.rst"} <= pages
    assert len(CASES) >= 50


@pytest.mark.parametrize(
    ("where", "folder", "argv"), CASES, ids=[f"{w} {' '.join(a)}" for w, _, a in CASES]
)
def test_each_command_shown_is_taken(where, folder, argv, capsys):
    parser, _ = _parser()
    try:
        options = parser.parse_args(argv)
    except SystemExit:
        pytest.fail(f"{where}: assur {' '.join(argv)}: {capsys.readouterr().err}")
    for read in (options.file, getattr(options, "answers", None)):
        if read is None or str(read) == "-" or read.name in DESCRIBED:
            continue
        assert (folder / read).is_file(), f"{where}: no file {read} in {folder}"
