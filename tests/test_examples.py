"""The gallery scripts and the documentation's Python snippets run as written.

Every ``examples/plot_*.py`` runs top to bottom under matplotlib's Agg backend and
must draw at least one figure. The ``>>>`` examples of the documentation pages run
as doctests from the repository's root, where their relative paths point. Each
```` ```python ```` block of README.md runs on its own, as a reader pastes it.
"""

from __future__ import annotations

import doctest
import re
import runpy
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SCRIPTS = sorted((ROOT / "examples").glob("plot_*.py"))
README = (ROOT / "README.md").read_text(encoding="utf-8")
README_BLOCKS = re.findall(r"^```python\n(.*?)^```", README, re.M | re.S)
PAGES = sorted(
    page
    for page in (ROOT / "docs").glob("*.rst")
    if ">>>" in page.read_text(encoding="utf-8")
)


@pytest.fixture
def agg(monkeypatch):
    """Draw off screen, make ``plt.show()`` a no-op and close every figure after."""
    matplotlib = pytest.importorskip("matplotlib")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.close("all")
    monkeypatch.setattr(plt, "show", lambda *args, **kwargs: None)
    yield plt
    plt.close("all")


def test_there_are_gallery_scripts():
    assert len(SCRIPTS) >= 6


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda path: path.stem)
def test_gallery_script_draws(script, agg, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)  # the scripts find their files through __file__
    runpy.run_path(str(script), run_name="__main__")
    assert agg.get_fignums(), f"{script.name} drew no figure"
    for number in agg.get_fignums():
        assert agg.figure(number).axes, f"{script.name}: figure {number} is empty"
    assert list(tmp_path.iterdir()) == [], f"{script.name} wrote files"


def test_the_docs_extra_installs_what_the_gallery_runs():
    # the build runs every script; a study (assur.sweep) needs the study extra's pandas
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    extras = pyproject["project"]["optional-dependencies"]
    studies = [s for s in SCRIPTS if "assur.sweep(" in s.read_text(encoding="utf-8")]
    assert studies
    assert "assur[study]" in extras["docs"] or set(extras["study"]) <= set(
        extras["docs"]
    )


def test_gallery_scripts_have_a_title():
    for script in SCRIPTS:
        text = script.read_text(encoding="utf-8")
        assert text.startswith('"""\n'), script.name
        title, underline = text.splitlines()[1:3]
        assert set(underline) == {"="}, script.name
        assert len(underline) == len(title), script.name


@pytest.mark.parametrize("page", PAGES, ids=lambda path: path.stem)
def test_documentation_snippets(page, monkeypatch):
    monkeypatch.chdir(ROOT)
    flags = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE
    result = doctest.testfile(
        str(page), module_relative=False, optionflags=flags, verbose=False, report=False
    )
    assert result.failed == 0, f"{page.name}: {result.failed} doctest(s) failed"


def test_readme_has_python_blocks():
    assert len(README_BLOCKS) >= 2


@pytest.mark.parametrize("number", range(len(README_BLOCKS)))
def test_readme_python_block(number, tmp_path, monkeypatch, capsys):
    code = README_BLOCKS[number]
    if "assur.sweep(" in code:
        pytest.importorskip("pandas")  # the study extra
    # in a scratch directory, where the block's examples/ paths still point
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, f"README.md python block {number + 1}", "exec"), {})
