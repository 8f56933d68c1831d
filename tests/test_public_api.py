"""The public API: ``assur.__all__`` sorted and complete; ``import assur`` light.

The import checks run in a fresh interpreter, since this one has long since imported
whatever other tests needed.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import json
import os
import re
import subprocess
import sys
import types
from pathlib import Path

import assur

ROOT = Path(__file__).resolve().parent.parent

# What the file contract and the project's brief promise, at the least.
PROMISED = {
    "load",
    "loads",
    "dumps",
    "save",
    "structure",
    "kinematics",
    "forces",
    "mobility",
    "Mechanism",
    "Link",
    "Joint",
    "Driver",
    "Load",
    "LoadTable",
    "Point",
    "Toward",
    "Structure",
    "Group",
    "Table",
    "AssurError",
    "ModelError",
    "DecompositionError",
    "AssemblyError",
    "SingularConfigurationError",
    "AssurWarning",
    "__version__",
}


def run_python(code: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    return subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )


def test_all_is_sorted_and_unique():
    assert list(assur.__all__) == sorted(assur.__all__)
    assert len(set(assur.__all__)) == len(assur.__all__)


def test_every_exported_name_exists():
    missing = [name for name in assur.__all__ if not hasattr(assur, name)]
    assert missing == []


def test_promised_names_are_exported():
    assert set(assur.__all__) >= PROMISED


def test_all_is_complete():
    # every public object that assur defines is exported; submodules need not be
    stray = [
        name
        for name, value in vars(assur).items()
        if not name.startswith("_")
        and name not in assur.__all__
        and not isinstance(value, types.ModuleType)
        and getattr(value, "__module__", "").startswith("assur")
    ]
    assert stray == []


def test_no_foreign_names_in_the_namespace():
    stray = [
        name
        for name, value in vars(assur).items()
        if not name.startswith("_")
        and name not in assur.__all__
        and not isinstance(value, types.ModuleType)
    ]
    assert stray == []


def test_functions_are_the_functions():
    # the submodule assur.kinematics must not shadow the function assur.kinematics
    for module in ("assur.cli", "assur._kinematics", "assur.kinetostatics"):
        importlib.import_module(module)

    for name in (
        "kinematics",
        "forces",
        "structure",
        "mobility",
        "load",
        "loads",
        "dumps",
        "save",
    ):
        assert inspect.isfunction(getattr(assur, name)), name


def test_parameters_are_named_as_format_md_writes_them():
    """``assur.structure(mechanism)``, ``assur.kinematics(mechanism, angles, omega=None,
    epsilon=None)``, ...: a call by those names works."""
    for name in assur.__all__:
        value = getattr(assur, name)
        if not inspect.isfunction(value):
            continue
        first = next(iter(inspect.signature(value).parameters))
        assert first not in ("mech", "m"), name
    mech = assur.catalog.four_bar()
    assert assur.mobility(mechanism=mech) == 1
    assert assur.structure(mechanism=mech).formula.startswith("I(ground, crank)")
    assert assur.graph(mechanism=mech).number_of_edges() == 4
    assert assur.loads(assur.dumps(mechanism=mech)) == mech
    for analyse in (assur.kinematics, assur.forces):
        params = list(inspect.signature(analyse).parameters)
        assert params[:4] == ["mechanism", "angles", "omega", "epsilon"]


def test_the_api_index_lists_every_name():
    # docs/api/index.rst's "Top-level names" documents each name where it lives
    text = (ROOT / "docs" / "api" / "index.rst").read_text(encoding="utf-8")
    listed = {
        name: module
        for module, name in re.findall(r"~(assur[\w.]*)\.(\w+)$", text, re.M)
    }
    for name in assur.__all__:
        value = getattr(assur, name)
        if name == "__version__":
            continue
        if isinstance(value, types.ModuleType):
            assert f"``assur.{name}``" in text, name
            continue
        assert name in listed, f"docs/api/index.rst does not list {name}"
        home = importlib.import_module(listed[name])
        assert getattr(home, name) is value, f"{name} is not {listed[name]}.{name}"


def test_the_api_index_lists_top_level_names_only():
    # it listed assur.analysis.Columns among the names "importable from the package
    # itself", and assur.Columns was an AttributeError
    text = (ROOT / "docs" / "api" / "index.rst").read_text(encoding="utf-8")
    top = text.split("Top-level names", 1)[1].split("\nModules\n", 1)[0]
    listed = re.findall(r"~assur[\w.]*\.(\w+)$", top, re.M)
    assert len(listed) > 30
    assert [name for name in listed if name not in assur.__all__] == []


def test_cross_references_name_where_a_top_level_name_is_documented():
    # :func:`assur.load` linked nowhere: the API pages document assur.io.load, and
    # assur.load is no target of its own (sphinx -n: "reference target not found")
    role = re.compile(r":(?:func|class|exc|meth|data|attr):`~?assur\.(\w+)[.\w]*`")
    files = sorted((ROOT / "docs").glob("*.rst")) + sorted(
        (ROOT / "assur").rglob("*.py")
    )
    found = [
        f"{path.relative_to(ROOT)}: assur.{name}"
        for path in files
        for name in role.findall(path.read_text(encoding="utf-8"))
        if name in assur.__all__
        and not isinstance(getattr(assur, name), types.ModuleType)
        and importlib.util.find_spec(f"assur.{name}") is None  # assur.explain.explain
    ]
    assert found == []


def test_modules_the_pages_call_into_have_an_api_page():
    # docs/study.rst has a study's rows read by assur.summary.undefined(row), and
    # assur.summary had no page in the API reference
    conf = (ROOT / "docs" / "conf.py").read_text(encoding="utf-8")
    pages = set(re.findall(r'"(assur[\w.]*)"', conf))
    text = "".join(p.read_text(encoding="utf-8") for p in (ROOT / "docs").glob("*.rst"))
    called = set()
    for dotted in re.findall(r"\b(assur\.[a-z]\w*)\.\w+\(", text):
        if importlib.util.find_spec(dotted) is not None:
            called.add(dotted)
    assert "assur.summary" in called
    assert called - pages == set()


def test_error_tree():
    assert issubclass(assur.ModelError, assur.AssurError)
    assert issubclass(assur.ModelError, ValueError)
    for name in ("DecompositionError", "AssemblyError", "SingularConfigurationError"):
        assert issubclass(getattr(assur, name), assur.AssurError)
    assert issubclass(assur.AssurWarning, UserWarning)


def test_array_like_parameters_are_annotated_so():
    # angles: Sequence[float] | Array refused what the docstrings call array_like
    # (np.arange(0, 360, 10), the (n, drivers) nested list of several drivers) in a
    # typed script: mypy said "incompatible type", though the call works
    documented = re.compile(
        r"^(\w+(?:, \w+)*) : (?:float or )?array_like(?:, optional)?$", re.M
    )
    checked = []
    for name in assur.__all__:
        value = getattr(assur, name)
        if not inspect.isfunction(value):
            continue
        signature = inspect.signature(value)
        doc = inspect.getdoc(value) or ""
        for names in documented.findall(doc):
            for parameter in names.split(", "):
                annotation = signature.parameters[parameter].annotation
                assert "ArrayLike" in str(annotation), (name, parameter, annotation)
                checked.append(f"{name}({parameter})")
    assert "forces(angles)" in checked
    assert "kinematics(omega)" in checked
    # a DataFrame is no Mapping to a typed script (pandas-stubs), yet sweep takes one
    parameters = inspect.signature(assur.sweep).parameters["parameters"]
    assert "pandas.DataFrame" in _documented_parameters(assur.sweep)["parameters"]
    assert "DataFrame" in str(parameters.annotation)
    assert "ArrayLike" in str(parameters.annotation)


def _documented_parameters(function: object) -> dict[str, str]:
    """Return each parameter of a numpydoc Parameters section: its type, its text."""
    doc = inspect.getdoc(function) or ""
    part = re.split(r"^Parameters\n-+\n", doc, flags=re.M)
    if len(part) == 1:
        return {}
    body = re.split(r"^\w[\w ]*\n-+\n", part[1], maxsplit=1, flags=re.M)[0]
    found: dict[str, str] = {}
    for names, kind, text in re.findall(
        r"^(\S[^:\n]*?)(?: : (.*))?\n((?: .*\n?)*)", body, re.M
    ):
        for name in names.split(", "):
            found[name.lstrip("*")] = " ".join(f"{kind}\n{text}".split())
    return found


def test_docstrings_describe_every_parameter():
    # catalog.slider_crank, the factory of the README's study, had no Parameters
    # section: its lengths' and angle's units were nowhere
    functions = [getattr(assur, n) for n in assur.__all__]
    functions += [getattr(assur.catalog, n) for n in assur.catalog.__all__]
    for function in functions:
        if not inspect.isfunction(function):
            continue
        documented = _documented_parameters(function)
        named = list(inspect.signature(function).parameters)
        assert list(documented) == named, function.__qualname__
    for name in assur.catalog.__all__:
        texts = _documented_parameters(getattr(assur.catalog, name)).values()
        units = [re.search(r", (m|deg|rad/s)[.:]", text) for text in texts]
        assert all(units), name


def test_a_table_is_drawn_at_the_positions_its_docstring_allows():
    # Table.plot(angle: float | None) refused the one value per driver its
    # docstring allows ("float or sequence of float") in a typed script
    assert "sequence of float" in _documented_parameters(assur.Table.plot)["angle"]
    annotation = inspect.signature(assur.Table.plot).parameters["angle"].annotation
    assert "ArrayLike" in str(annotation)


def test_the_package_says_it_is_typed():
    # without the PEP 561 marker a user's mypy takes every name of the installed
    # package for Any ("missing library stubs or py.typed marker"); hatchling's
    # wheel takes every file of the package, the marker with them
    assert (ROOT / "assur" / "py.typed").is_file()
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert '"Typing :: Typed"' in text


def test_version_is_a_string():
    assert isinstance(assur.__version__, str)
    assert assur.__version__


def test_import_is_light():
    code = (
        "import sys, json\n"
        "import assur\n"
        "heavy = ('matplotlib', 'scipy', 'networkx')\n"
        "heavy = sorted(m for m in heavy if m in sys.modules)\n"
        "data = {'heavy': heavy, 'file': assur.__file__}\n"
        "print(json.dumps(data))\n"
    )
    result = run_python(code)
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert Path(data["file"]).resolve().parent == ROOT / "assur"
    # what it costs in time is measured by benchmarks/bench_sweep.py, not here
    assert data["heavy"] == []


def test_reading_and_structure_stay_light():
    # reading a file and reporting its structure need no plotting
    code = (
        "import sys, assur\n"
        "mech = assur.load('examples/four_bar.toml')\n"
        "str(assur.structure(mech))\n"
        "print('matplotlib' in sys.modules)\n"
    )
    result = run_python(code)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "False"


PICTURES = (
    "decomposition",
    "diagrams",
    "dynamics",
    "force_diagrams",
    "lever",
    "mechanism",
    "plans",
    "polygons",
)
"""The modules of :mod:`assur.plotting` whose functions return a picture."""


def test_the_picture_functions_are_annotated_with_what_they_return() -> None:
    # they returned Any: a typed script's ax.set_xlabel(...) was checked against
    # nothing, and an ax= of any type passed
    seen = 0
    for name in PICTURES:
        module = importlib.import_module(f"assur.plotting.{name}")
        for attr in module.__all__:
            f = getattr(module, attr)
            doc = inspect.getdoc(f) or ""
            returns = re.search(
                r"Returns\n-------\nmatplotlib\.(axes|figure)\.(\w+)", doc
            )
            if returns is None:
                continue
            seen += 1
            signature = inspect.signature(f)
            assert signature.return_annotation == returns.group(2), attr
            ax = signature.parameters.get("ax")
            assert ax is None or ax.annotation == "Axes | None", attr
    assert seen >= 15


def test_a_tables_picture_and_frame_are_annotated_with_what_they_return() -> None:
    # Table.plot and to_pandas returned Any: a typed script's table.plot().set_title
    # and frame.loc were checked against nothing
    from assur._exports import Columns
    from assur.table import Table

    assert inspect.signature(Table.plot).return_annotation == "Axes"
    assert inspect.signature(Columns.to_pandas).return_annotation == "pd.DataFrame"
    for f, name in (
        (Table.plot, "matplotlib.axes.Axes"),
        (Columns.to_pandas, "pandas.DataFrame"),
    ):
        assert f"Returns\n-------\n{name}\n" in (inspect.getdoc(f) or "")
