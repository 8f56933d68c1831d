"""Import direction inside the package, read from the source with ``ast``.

STYLE.md: imports point one way along ``errors, _vec, _text -> model -> _structure,
report -> groups -> plan -> _loads, _kinematics -> kinetostatics -> columns -> table ->
analysis -> io, _output, plotting, html -> cli, pictures_cli`` (the loads are compiled
against a plan, so they come after it). A module may import
modules of a lower rank or of its own; the cycle check keeps modules of one rank (and
the modules of one package) apart. Imports inside functions count, since they run when
the function does; imports under ``if TYPE_CHECKING:`` only serve annotations and are
left out. Each submodule of a package is a node of its own; ``assur.groups.*``,
``assur.plotting.*`` and ``assur.html.*`` take their package's rank.
"""

from __future__ import annotations

import ast
from pathlib import Path

import networkx as nx
import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "assur"

RANKS = {
    "assur.errors": 0,
    "assur._vec": 0,
    "assur._quiet": 0,
    # a package's names loaded at their first use
    "assur._lazy": 0,
    "assur._lookalike": 0,
    "assur._text": 0,
    # an argument's list of names, checked
    "assur._listed": 0,
    "assur._width": 0,
    "assur._position_titles": 0,
    "assur._digits": 0,
    # the results' rich display in a notebook: HTML pieces, a table's rows shown
    "assur._display": 0,
    "assur._table_display": 8,
    "assur._decimal_comma": 0,
    "assur._fonts": 0,
    "assur._optional": 0,
    "assur._progress": 0,
    # the library's own warnings, given or held (a context variable)
    "assur._warn": 0,
    "assur._style": 0,
    # the command line's Ctrl-C guard, run first by the package: the standard library
    "assur._start": 0,
    "assur._tables": 0,
    # the model's checks, below it: numbers and names -> points -> loads, motor ->
    # the whole mechanism (the cycle check keeps them apart)
    "assur._checks": 0,
    "assur._points": 0,
    "assur._load_checks": 0,
    "assur._motor": 0,
    "assur._validation": 1,
    "assur.model": 1,
    # the structure's modules, in their own direction: _topology -> _diagnosis ->
    # _group_search, _group -> _structure (the cycle check keeps them apart)
    "assur._topology": 2,
    "assur._diagnosis": 2,
    "assur._leftover": 2,
    "assur._freedom": 2,
    "assur._group_search": 2,
    # one group found by the search, classified
    "assur._group": 2,
    "assur._structure": 2,
    "assur.report": 2,
    # a structure as a notebook shows it: the report's counts, the groups' table
    "assur._structure_display": 2,
    "assur.groups": 3,
    "assur._metres": 3,
    "assur.plan": 4,
    "assur._loads": 5,
    "assur._friction": 5,
    # when a pair is at rest, below the friction that reads it
    "assur._still": 5,
    # the sizes of a group's reactions with friction, by Newton's method
    "assur._newton": 5,
    "assur._follow": 5,
    # walks of the Newton groups along straight paths, through change points
    "assur._walk": 5,
    "assur._kinematics": 5,
    # the forward pass's frozen result: made from the motions, rebuilt, extended
    "assur._state": 5,
    # the driver positions and speeds a sweep is given, read and turned into SI units
    "assur._drive": 5,
    "assur._branches": 6,
    "assur._paths": 6,
    # the driver positions one driver reaches from the reference pose, scanned once
    "assur._reach": 6,
    "assur.kinetostatics": 6,
    # the reverse pass checked again: virtual power, every link's equilibrium
    "assur._crosscheck": 6,
    "assur.columns": 7,
    "assur._evaluate": 7,
    # the columns computed slice by slice from the links' rebuilt motions
    "assur._chunks": 7,
    # what a pass over slices computes, per plan and set of columns
    "assur._recipe": 7,
    # a sweep's troubles: errors, positions left out, warnings (change points too)
    "assur._runs": 6,
    "assur._troubles": 7,
    "assur._unexplained": 8,
    "assur.table": 8,
    # a table's columns kept read-only
    "assur._keep": 8,
    # what every table of results offers: its columns by name, and their export
    "assur._exports": 8,
    "assur.summary": 8,
    "assur._running": 1,
    "assur._efficiency": 0,
    "assur._timing": 1,
    "assur._steps": 7,
    "assur._summary_rows": 7,
    "assur._summary_notes": 9,
    "assur._undefined": 0,
    "assur._stack": 6,
    # many variants compiled at once against a template plan
    "assur._variants": 6,
    # their parts: the checks made on the variants' rows, their stacked plan and loads
    "assur._variant_checks": 6,
    "assur._variant_plans": 6,
    "assur.analysis": 9,
    # a sweep solved slice by slice: the passes over its slices, its states gathered
    "assur._passes": 9,
    # variants of one topology solved in one batch, from the analysis's own steps
    "assur._batch": 9,
    # where a sweep's lines break, after the positions the analysis left out
    "assur._gaps": 9,
    # studies: many variants, summarised; pandas, xarray and dask imported lazily
    "assur.study": 10,
    # a study's parts: its inputs checked -> its variants compiled and stacked, its
    # full tables, its partitions on a cluster (the cycle check keeps them apart)
    "assur._study_inputs": 10,
    "assur._study_stacks": 10,
    "assur._study_tables": 10,
    "assur._study_cluster": 10,
    "assur.io": 10,
    # a mechanism file, for io: its entries read (the file contract, KEYS) -> its
    # syntax decoded, its text written (the cycle check keeps them apart)
    "assur._file_entries": 10,
    "assur._file_syntax": 10,
    "assur._file_text": 10,
    "assur._output": 10,
    # where an output goes: the path named, the file it leads to
    "assur._targets": 10,
    "assur._landing": 10,
    "assur._stdout": 10,
    # long sweeps a slice at a time: the command line's tables, long studies
    "assur._sliced": 10,
    "assur._skipped": 10,
    "assur._tableio": 10,
    "assur._csvtext": 10,
    "assur.plotting": 10,
    # the dynamic model and the motion in time: sweeps of the analysis, reduced
    "assur.dynamics_reduced": 10,
    "assur._dynamic_checks": 10,
    "assur._grid_warnings": 1,
    "assur.dynamics_steady": 10,
    "assur.dynamics_model": 10,
    "assur.dynamics_flywheel": 10,
    "assur.dynamics_startup": 10,
    # the start-up's parts: what it is given, checked; how its run of turns ends;
    # when it settles
    "assur._startup_checks": 10,
    "assur._startup_curves": 10,
    "assur._startup_steps": 10,
    "assur._change_limits": 10,
    "assur._startup_turns": 10,
    "assur._startup_settle": 10,
    "assur.dynamics_shown": 10,
    # the figures of the dynamic model and of a start-up, as lines: below the model
    "assur._dynamics_text": 10,
    "assur.html": 10,
    # the explanatory note reads the analysis like the pictures do
    "assur.explain": 10,
    # ready-made mechanisms for users and examples: model objects, never core input
    "assur.catalog": 10,
    # the public API re-exports the core and io
    "assur": 11,
    "assur._cli_common": 12,
    "assur._cli_types": 12,
    "assur._stdin": 10,
    "assur._cli_parser": 11,
    # the command line's parts, apart from its parser and dispatch (the cycle check
    # keeps them apart): signals and standard streams; the sweep commands' tables,
    # written (_cli_tables) or printed (_cli_summary), slice by slice (_cli_sweep)
    "assur._cli_process": 12,
    "assur._cli_summary": 12,
    "assur._cli_tables": 12,
    "assur._cli_sweep": 12,
    # the command line's parser and its commands' options, below the dispatch
    "assur._cli_commands": 12,
    "assur.cli": 12,
    # the dynamics command's parts: its options checked, the figures it gives, its
    # tables and files written
    "assur._dynamics_options": 12,
    "assur._dynamics_figures": 12,
    "assur._dynamics_files": 12,
    "assur.dynamics_cli": 12,
    # the picture commands' parts (the cycle check keeps them apart): the files ->
    # the sweeps drawn -> assur plans
    "assur._picture_files": 12,
    "assur._picture_sweeps": 12,
    "assur._picture_plans": 12,
    "assur._picture_panels": 12,
    "assur._picture_animate": 12,
    "assur.pictures_cli": 12,
    "assur.__main__": 13,
}
"""Rank of every module along STYLE.md's direction (packages rank their submodules)."""

# (importer, imported, enclosing function, "" at module level): imports that point the
# wrong way, each with its reason. Keep this list short; drop an entry once it is fixed.
AGAINST_THE_DIRECTION = {
    # STYLE.md: a result may offer .plot() only as a one-line forward to plotting
    ("assur.table", "assur.plotting", "Table.plot"),
    # the same kind of one-line forward, to io.write_csv; STYLE.md names only .plot()
    ("assur._exports", "assur.io", "Columns.to_csv"),
    ("assur._exports", "assur.io", "Columns.to_parquet"),
}

# (importer, imported): imports left out of the cycle check, each with its reason.
KNOWN_CYCLES: set[tuple[str, str]] = set()


def names_imported(path: Path) -> set[str]:
    """Every name a module imports with ``from ... import name``, anywhere in it."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return {
        alias.name
        for node in ast.walk(tree)
        if isinstance(node, ast.ImportFrom)
        for alias in node.names
    }


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


MODULES = {_module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def _resolve(name: str) -> str:
    """Return the module that ``name`` (a module, or a name defined in one) lives in."""
    while name not in MODULES:
        name = name.rpartition(".")[0]
    return name


def _is_type_checking(test: ast.expr) -> bool:
    if isinstance(test, ast.Name):
        return test.id == "TYPE_CHECKING"
    return isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"


class _Imports(ast.NodeVisitor):
    """The assur modules one module imports at run time, with the enclosing scope."""

    def __init__(self, module: str, package: bool) -> None:
        self.module = module
        self.package = module if package else module.rpartition(".")[0]
        self.scope: list[str] = []
        self.found: set[tuple[str, str]] = set()

    def _add(self, name: str) -> None:
        if name == "assur" or name.startswith("assur."):
            target = _resolve(name)
            if target != self.module:
                self.found.add((target, ".".join(self.scope)))

    def _scoped(
        self, node: ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef
    ) -> None:
        self.scope.append(node.name)
        self.generic_visit(node)
        self.scope.pop()

    def visit_FunctionDef(self, node: ast.FunctionDef) -> None:
        self._scoped(node)

    def visit_AsyncFunctionDef(self, node: ast.AsyncFunctionDef) -> None:
        self._scoped(node)

    def visit_ClassDef(self, node: ast.ClassDef) -> None:
        self._scoped(node)

    def visit_If(self, node: ast.If) -> None:
        if _is_type_checking(node.test):
            for child in node.orelse:
                self.visit(child)
        else:
            self.generic_visit(node)

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            self._add(alias.name)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        base = node.module or ""
        if node.level:
            package = self.package
            for _ in range(node.level - 1):
                package = package.rpartition(".")[0]
            base = f"{package}.{base}" if base else package
        for alias in node.names:
            # "from assur import plotting" imports a module; "from assur.io import
            # load" a name of one
            self._add(f"{base}.{alias.name}")


def _imports() -> set[tuple[str, str, str]]:
    """Every run-time import between assur modules: (importer, imported, scope)."""
    edges = set()
    for module, path in MODULES.items():
        visitor = _Imports(module, path.name == "__init__.py")
        visitor.visit(ast.parse(path.read_text(encoding="utf-8"), str(path)))
        edges |= {(module, target, scope) for target, scope in visitor.found}
    return edges


IMPORTS = _imports()


def _rank(module: str) -> int:
    """Rank of ``module``, or of its package below the top (KeyError if unranked)."""
    if module in RANKS:
        return RANKS[module]
    package = module.rpartition(".")[0]
    if package in ("", "assur"):
        raise KeyError(module)
    return _rank(package)


def test_the_parser_sees_lazy_and_skips_annotation_imports():
    # Table.plot imports plotting inside a method; report imports _structure only
    # under TYPE_CHECKING; pictures_cli imports plotting as "from assur import ..."
    assert ("assur.table", "assur.plotting", "Table.plot") in IMPORTS
    assert not {e for e in IMPORTS if e[:2] == ("assur.report", "assur._structure")}
    assert {e for e in IMPORTS if e[:2] == ("assur.pictures_cli", "assur.plotting")}
    assert ("assur.plan", "assur.groups.driver", "") in IMPORTS


def test_every_module_has_a_rank():
    unranked = []
    for module in MODULES:
        try:
            _rank(module)
        except KeyError:
            unranked.append(module)
    assert not unranked, f"give these modules a rank in RANKS: {unranked}"


def test_no_import_cycle():
    graph = nx.DiGraph()
    graph.add_nodes_from(MODULES)
    graph.add_edges_from((a, b) for a, b, _ in IMPORTS if (a, b) not in KNOWN_CYCLES)
    cycles = sorted(sorted(c) for c in nx.simple_cycles(graph))
    assert nx.is_directed_acyclic_graph(graph), f"import cycles: {cycles}"


def test_imports_follow_the_direction():
    wrong = sorted(
        (a, b, scope)
        for a, b, scope in IMPORTS
        if _rank(b) > _rank(a) and (a, b, scope) not in AGAINST_THE_DIRECTION
    )
    assert not wrong, (
        f"imports against STYLE.md's direction (importer, imported, function): {wrong}"
    )


@pytest.mark.parametrize(
    "entry", sorted(AGAINST_THE_DIRECTION), ids=lambda e: f"{e[0]}->{e[1]}"
)
def test_allowed_imports_against_the_direction_still_exist(entry):
    importer, imported, _ = entry
    assert entry in IMPORTS, f"{entry} is gone: remove it from AGAINST_THE_DIRECTION"
    assert _rank(imported) > _rank(importer), f"{entry} follows the direction now"


@pytest.mark.parametrize("entry", sorted(KNOWN_CYCLES), ids=lambda e: f"{e[0]}->{e[1]}")
def test_known_cycles_are_still_cycles(entry):
    importer, imported = entry
    edges = {(a, b) for a, b, _ in IMPORTS}
    assert entry in edges, f"{entry} is gone: remove it from KNOWN_CYCLES"
    graph = nx.DiGraph(list(edges))
    assert nx.has_path(graph, imported, importer), (
        f"{entry} closes no cycle any more: remove it from KNOWN_CYCLES"
    )


def test_a_table_command_loads_no_picture_module(tmp_path: Path) -> None:
    import subprocess
    import sys

    # the picture commands' parser loaded assur.plotting whole (50 ms) for every
    # command, ``assur kinematics`` among them
    example = Path(__file__).parent.parent / "examples" / "four_bar.toml"
    code = (
        "import sys\n"
        "from assur.cli import main\n"
        f"main(['kinematics', {str(example)!r}, '--angles', '0', '-q', '--csv', "
        f"{str(tmp_path / 'k.csv')!r}])\n"
        "print(sorted(m for m in ('assur.plotting', 'matplotlib', 'scipy', "
        "'pandas') if m in sys.modules))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        check=True,
        timeout=120,
    )
    assert result.stdout.strip() == "[]"
    assert (tmp_path / "k.csv").exists()
