"""``import assur`` loads its public names at their first use (assur._lazy).

Each check runs in a fresh interpreter, where nothing of the package is loaded yet.
"""

from __future__ import annotations

import json
import sys
import warnings

import pytest

import assur

from .test_explain_locked import ANGLE, LOCKING
from .test_public_api import run_python


def _fresh(code: str) -> object:
    """Run ``code`` after ``import assur`` in a fresh Python; return what it prints."""
    result = run_python("import json, sys\nimport assur\n" + code)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_the_import_loads_no_analysis_until_a_name_is_used():
    loaded = _fresh(
        "before = sorted(m for m in sys.modules if m.startswith('assur'))\n"
        "forces = assur.forces\n"
        "after = 'assur.analysis' in sys.modules\n"
        "print(json.dumps([before, after, forces.__module__]))\n"
    )
    before, after, module = loaded
    assert "assur.analysis" not in before
    assert "assur.model" not in before
    assert after
    assert module == "assur.analysis"


def test_explain_stays_the_function_after_its_package_modules_load():
    # the package assur.explain has the function's name: importing its modules
    # first must not put the package in the function's place
    kinds = _fresh(
        "import assur.explain._note\n"
        "from assur.explain import Note, read_answers\n"
        "note = assur.explain(assur.catalog.slider_crank(), 30.0)\n"
        "print(json.dumps([callable(assur.explain), type(note) is Note, "
        "assur.Note is Note, read_answers.__name__]))\n"
    )
    assert kinds == [True, True, True, "read_answers"]


def test_every_public_name_is_listed_and_resolves_in_a_fresh_interpreter():
    names = _fresh(
        "listed = dir(assur)\n"
        "missing = [n for n in assur.__all__ if n not in listed]\n"
        "where = {n: getattr(assur, n).__module__ for n in assur.__all__\n"
        "         if hasattr(getattr(assur, n), '__module__')}\n"
        "print(json.dumps([missing, where]))\n"
    )
    missing, where = names
    assert missing == []
    assert where["Mechanism"] == "assur.model"
    assert where["structure"] == "assur._structure"
    assert where["Table"] == "assur.table"
    assert where["explain"] == "assur.explain"


def test_a_submodule_is_an_attribute_as_when_everything_was_loaded():
    kinds = _fresh(
        "print(json.dumps([assur.plan.__name__, assur.catalog.__name__, "
        "assur.groups.__name__]))\n"
    )
    assert kinds == ["assur.plan", "assur.catalog", "assur.groups"]


@pytest.mark.parametrize("name", ["nothing", "__wrapped__", "not a name"])
def test_a_name_the_package_lacks_is_an_attribute_error(name):
    package = sys.modules["assur.explain"]  # the package, not the function
    for module in (assur, package):
        with pytest.raises(AttributeError, match=f"no attribute {name!r}$"):
            getattr(module, name)
        assert not hasattr(module, name)


def test_the_note_still_warns_at_the_callers_line():
    # the function calls the note's module: the warning names this file, not it
    mech = assur.load(LOCKING)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assur.explain(mech, ANGLE)
    assert [w.filename for w in caught] == [__file__]


def test_reading_a_file_and_its_structure_load_no_sweep():
    loaded = _fresh(
        "mech = assur.load('examples/four_bar.toml')\n"
        "str(assur.structure(mech))\n"
        "sweeps = ('assur.analysis', 'assur._kinematics', 'assur.kinetostatics',\n"
        "          'assur.dynamics_model')\n"
        "print(json.dumps([m for m in sweeps if m in sys.modules]))\n"
    )
    assert loaded == []


def test_each_public_name_is_loaded_at_import_or_listed_once_to_load():
    # a name both in the namespace at import and in the table would never load
    # lazily; one in neither would be missing
    at_import, listed, public = _fresh(
        "print(json.dumps([sorted(vars(assur)), sorted(assur._WHERE),\n"
        "                  sorted(assur.__all__)]))\n"
    )
    assert not set(at_import) & set(listed)
    assert set(listed) <= set(public)
    assert set(public) <= set(at_import) | set(listed)
