"""The optional dependencies: missing or broken, one message that says what to do."""

from __future__ import annotations

import re
import shlex
import sys

import pytest

import assur
from assur._optional import optional
from assur.cli import main

from .conftest import EXAMPLES


@pytest.fixture
def broken(tmp_path, monkeypatch):
    """A package ``brokenpkg`` whose import raises RuntimeError over two lines."""
    folder = tmp_path / "brokenpkg"
    folder.mkdir()
    (folder / "__init__.py").write_text(
        "raise RuntimeError('built for another numpy\\nsecond line')\n",
        encoding="utf-8",
    )
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(sys.modules, "brokenpkg", raising=False)
    return "brokenpkg"


def test_a_missing_package_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError) as info:
        optional("pandas", "a study", "study")
    assert str(info.value) == (
        "a study needs pandas, which is not installed; expected 'pip install pandas' "
        "(or 'pip install \"assur[study]\"')"
    )


def test_the_extra_s_install_command_is_quoted_for_any_shell(monkeypatch):
    # zsh refused the bare assur[study] of the message: "no matches found"
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError) as info:
        optional("pandas", "a study", "study")
    command = re.search(r"\(or '(.*)'\)$", str(info.value)).group(1)
    assert shlex.split(command) == ["pip", "install", "assur[study]"]
    assert not re.search(r"(^| )[^\"' ]*\[", command)  # no bracket outside quotes


def test_a_broken_package_says_what_it_raised(broken):
    with pytest.raises(ImportError) as info:
        optional(f"{broken}.sub", "writing Parquet", "parquet")
    assert str(info.value) == (
        "writing Parquet needs brokenpkg, which is installed but fails to import "
        "(RuntimeError: built for another numpy); expected a working install, "
        "'pip install --force-reinstall brokenpkg'"
    )
    assert isinstance(info.value.__cause__, RuntimeError)


@pytest.mark.parametrize(
    ("raised", "what"),
    [
        (
            "ImportError('libarrow.so.2600: cannot open shared object file')",
            "ImportError: libarrow.so.2600: cannot open shared object file",
        ),
        (
            "import no_tz",
            "ModuleNotFoundError: No module named 'no_tz'",
        ),
    ],
)
def test_an_import_error_inside_the_package_is_a_broken_install(
    tmp_path, monkeypatch, raised, what
):
    # a library that cannot be loaded, or a dependency of the package missing, was
    # told as the package "not installed"
    folder = tmp_path / "halfpkg"
    folder.mkdir()
    statement = raised if raised.startswith("import") else f"raise {raised}"
    (folder / "__init__.py").write_text(statement + "\n", encoding="utf-8")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.delitem(sys.modules, "halfpkg", raising=False)
    with pytest.raises(ImportError) as info:
        optional("halfpkg", "writing Parquet", "parquet")
    assert str(info.value) == (
        f"writing Parquet needs halfpkg, which is installed but fails to import "
        f"({what}); expected a working install, 'pip install --force-reinstall "
        "halfpkg'"
    )


def test_to_pandas_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)
    table = assur.kinematics(assur.catalog.four_bar(), [0.0])
    with pytest.raises(ImportError, match=r"Table.to_pandas\(\) needs pandas, which"):
        table.to_pandas()


def test_broken_pyarrow_is_one_line_on_the_command_line(
    broken, tmp_path, monkeypatch, capsys
):
    import importlib
    import types

    from assur import _optional

    def imported(name, *args):
        # pyarrow, as a build for another numpy would fail
        return importlib.import_module(name.replace("pyarrow", broken), *args)

    shim = types.SimpleNamespace(import_module=imported)
    monkeypatch.setattr(_optional, "importlib", shim)
    target = tmp_path / "t.parquet"
    path = EXAMPLES / "slider_crank_exercise.toml"
    status = main(["forces", str(path), "--parquet", str(target)])
    out, err = capsys.readouterr()
    assert status == 2
    assert out == ""
    assert err == (
        f"assur: error: {path}: --parquet {target}: writing Parquet needs pyarrow, "
        "which is installed but fails to import (RuntimeError: built for another "
        "numpy); expected a working install, 'pip install --force-reinstall "
        "pyarrow'\n"
    )
    assert not target.exists()
