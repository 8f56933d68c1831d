"""The results' rich display in a notebook: ``_repr_html_`` of tables, structures,
the dynamic model and the start-up, read back with ``html.parser``."""

from __future__ import annotations

import dataclasses
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import numpy as np

import assur
from assur import Motor
from assur._cli_summary import format_table
from assur._dynamics_text import figure_lines, startup_lines
from assur._structure_display import GROUP_HEADINGS, group_cells
from assur._table_display import (
    HEAD_COLUMNS,
    HEAD_ROWS,
    TAIL_COLUMNS,
    TAIL_ROWS,
    table_html,
)
from assur.columns import pretty_unit

from .test_dynamics import crank

DATA = Path(__file__).parent / "data"
EXAMPLES = Path(__file__).parent.parent / "examples"
HOSTILE = "<script>alert('x')</script> & <b>co</b>"
"""A mechanism's name that would run, or bolden, if it were not escaped."""


class Page(HTMLParser):
    """What a notebook shows of an HTML fragment: tables' cells, captions, tags."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.tags: list[str] = []
        self.captions: list[str] = []
        self.tables: list[list[list[tuple[str, str]]]] = []
        self.blocks: dict[str, list[str]] = {}
        self._open: list[str] = []
        self._text: list[str] = []
        self.feed(text)
        self.close()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self.tables[-1].append([])
        if tag in ("th", "td", "caption", "pre", "code", "p", "small"):
            self._open.append(tag)
            self._text = []

    def handle_endtag(self, tag: str) -> None:
        if not self._open or self._open[-1] != tag:
            return
        self._open.pop()
        text = "".join(self._text)
        if tag in ("th", "td"):
            self.tables[-1][-1].append((tag, text))
        elif tag == "caption":
            self.captions.append(text)
        else:
            self.blocks.setdefault(tag, []).append(text)

    def handle_data(self, data: str) -> None:
        self._text.append(data)


def hostile_mechanism() -> assur.Mechanism:
    """The slider-crank exercise with a hostile name, and a link named in HTML."""
    text = (DATA / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    text = text.replace('name = "Slider-crank exercise"', f'name = "{HOSTILE}"')
    text = text.replace("links.rod", 'links."<b>rod</b>"')
    return assur.loads(text.replace('"rod"', '"<b>rod</b>"'))


def shown_columns(table: assur.Table) -> list[str]:
    """The columns a display shows: the first and the last ones."""
    names = list(table.columns)
    if len(names) <= HEAD_COLUMNS + TAIL_COLUMNS:
        return names
    return names[:HEAD_COLUMNS] + names[-TAIL_COLUMNS:]


def shown_rows(count: int) -> list[int]:
    """The rows a display shows: the first and the last ones."""
    if count <= HEAD_ROWS + TAIL_ROWS:
        return list(range(count))
    return [*range(HEAD_ROWS), *range(count - TAIL_ROWS, count)]


def without_gap(cells: list[str], wide: bool) -> list[str]:
    """Return a row's cells without its row heading and its column of "…"."""
    cells = cells[1:]
    return cells[:HEAD_COLUMNS] + cells[HEAD_COLUMNS + 1 :] if wide else cells


def test_a_table_shows_its_name_shape_and_headings_with_units():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    t = assur.forces(mech, [0.0, 120.0, 240.0])
    page = Page(t._repr_html_())
    rows, columns = len(t), len(t.columns)
    shape = f"{rows} rows × {columns} columns"
    assert page.captions == [f"forces of {mech.name!r}: {shape}"]
    (table,) = page.tables
    names, units, *body = ([text for _, text in row] for row in table)
    shown = shown_columns(t)
    assert columns > len(shown)  # wide enough to be cut
    assert names[HEAD_COLUMNS + 1] == "…"
    assert without_gap(names, True) == shown
    assert without_gap(units, True) == [pretty_unit(t.column(n).unit) for n in shown]
    # every row is shown, under its number
    assert [row[0] for row in body] == [str(k) for k in range(rows)]
    # how to see the columns left out, counted
    (note,) = page.blocks["small"]
    assert note.startswith(f"{columns - len(shown)} columns not shown")
    assert "table.to_pandas()" in note
    assert "table.arrays()" in note


def test_the_numbers_are_the_tables_as_the_command_line_prints_them():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    angles = np.arange(0.0, 360.0, 7.5)
    page = Page(assur.forces(mech, angles)._repr_html_())
    # a table of its own: the display's reading must not change the numbers
    fresh = assur.forces(mech, angles)
    names = shown_columns(fresh)
    at = shown_rows(len(fresh))
    units = [fresh.column(n).unit for n in names]
    # the command line's readable table of the same columns, every row: the rows
    # shown are among its lines
    printed = format_table(names, units, [fresh[n] for n in names], len(fresh))
    lines = [line.split() for line in printed.splitlines()[2:]]
    expected = [lines[k] for k in at]
    body = [[text for _, text in row] for row in page.tables[0][2:]]
    # the first and last rows, a row of "…" between them
    assert [row[0] for row in body] == [
        *map(str, at[:HEAD_ROWS]),
        "…",
        *map(str, at[HEAD_ROWS:]),
    ]
    assert set(body[HEAD_ROWS]) == {"…"}
    del body[HEAD_ROWS]
    assert [without_gap(row, True) for row in body] == expected
    # round-off among the values of its unit shows as 0, as the command line has it
    raw = np.asarray(fresh["residual.force"])[at]
    k = names.index("residual.force")
    assert np.any(raw != 0.0)
    assert {row[k] for row in expected} == {"0"}


def test_a_long_table_computes_the_columns_shown_only():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    t = assur.forces(mech, np.linspace(0.0, 360.0, 100_000))
    text = t._repr_html_()
    names = shown_columns(t)
    # a point's, a check's, a residual's columns are computed alone, not with the
    # neighbours reading one by name would compute along with them
    assert set(t._cache) == set(names)
    body = Page(text).tables[0][2:]
    assert len(body) == HEAD_ROWS + 1 + TAIL_ROWS
    assert body[-1][0] == ("th", str(len(t) - 1))
    # the display reads what it shows from the table, and keeps it
    for name in names:
        assert t._cache[name] is t[name]


def test_a_narrow_table_shows_every_column():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    t = assur.kinematics(mech, [0.0, 90.0], columns=["angle", "C.vx"])
    page = Page(t._repr_html_())
    names, units, *_ = ([text for _, text in row] for row in page.tables[0])
    assert names == ["", "angle", "C.vx"]
    assert units == ["", "deg", "m/s"]
    assert "small" not in page.blocks  # no column left out


def test_one_column_left_out_is_counted():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    names = list(assur.kinematics(mech, [0.0]).columns)
    wanted = names[: HEAD_COLUMNS + TAIL_COLUMNS + 1]  # one more than are shown
    page = Page(assur.kinematics(mech, [0.0, 90.0], columns=wanted)._repr_html_())
    (note,) = page.blocks["small"]
    assert note.startswith("1 column not shown")


class _Column:
    """A column's unit, as a table's ``column(name)`` gives it."""

    def __init__(self, unit: str) -> None:
        self.unit = unit


class _Stub:
    """A table of given columns: the little the display reads of one."""

    def __init__(self, columns: dict[str, tuple[str, np.ndarray]]) -> None:
        self._columns = columns
        self.columns = list(columns)
        self.mechanism = assur.load(DATA / "slider_crank_exercise.toml")

    def __len__(self) -> int:
        return len(next(iter(self._columns.values()))[1])

    def __getitem__(self, name: str) -> np.ndarray:
        return self._columns[name][1]

    def column(self, name: str) -> _Column:
        return _Column(self._columns[name][0])


def test_round_off_is_told_against_the_rows_left_out_too():
    # small values in the rows shown, a million times a million larger between
    # them: among the whole column they are round-off, as the command line says
    count = HEAD_ROWS + TAIL_ROWS + 5
    small = np.full(count, 1e-3)
    small[HEAD_ROWS : count - TAIL_ROWS] = 1e7
    stub = _Stub({"a.F": ("N", small), "a.x": ("m", np.linspace(0.1, 0.2, count))})
    page = Page(table_html(stub, "forces"))
    printed = format_table(stub.columns, ["N", "m"], [small, stub["a.x"]], count)
    lines = [line.split() for line in printed.splitlines()[2:]]
    body = [[text for _, text in row] for row in page.tables[0][2:]]
    del body[HEAD_ROWS]  # the row of "…"
    assert [row[1:] for row in body] == [lines[k] for k in shown_rows(count)]
    assert {row[1] for row in body} == {"0"}


def test_a_table_of_few_columns_is_shown_without_solving_it_again():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    t = assur.forces(mech, np.linspace(0.0, 360.0, 3000), columns=["driver.torque"])
    page = Page(t._repr_html_())
    assert page.captions[0].startswith("forces of ")
    assert repr(t).startswith("<assur.Table: forces of ")
    # the links' motions and reactions it did not keep are not solved to say so
    assert t._whole == []
    assert t.force_state is not None  # as the caption says


def test_names_are_escaped():
    mech = hostile_mechanism()
    t = assur.forces(mech, [0.0, 90.0])
    for text in (t._repr_html_(), assur.structure(mech)._repr_html_()):
        page = Page(text)
        # shown as text: no script and no bold text of the names
        assert "script" not in page.tags
        assert "b" not in page.tags
        assert any(HOSTILE in caption for caption in page.captions) or any(
            HOSTILE in block for block in page.blocks["p"]
        )
    names = [text for _, text in Page(t._repr_html_()).tables[0][0]]
    assert "<b>rod</b>.angle" in names


def test_the_structure_shows_its_formula_and_groups():
    mech = assur.load(DATA / "slider_crank_exercise.toml")
    struct = assur.structure(mech)
    page = Page(struct._repr_html_())
    assert struct.formula.replace(" -> ", " → ") in page.blocks["code"]
    assert any(f"= {struct.dof}" in p for p in page.blocks["p"])
    (groups,) = page.tables
    assert [text for _, text in groups[0]] == list(GROUP_HEADINGS)
    cells = group_cells(struct)
    assert len(cells) == len(struct.drivers) + len(struct.groups)
    assert [[text for _, text in row] for row in groups[1:]] == cells
    # the input link is of no order (it read 0); a group's order is its count of
    # external pairs
    order = GROUP_HEADINGS.index("Order")
    assert [row[order] for row in cells] == ["—"] + [
        str(g.order) for g in struct.groups
    ]
    assert [g.order for g in struct.groups] == [2]
    # the teaching report whole, as str() gives it
    assert page.blocks["pre"] == [str(struct)]


def test_the_dynamic_model_shows_its_figures_and_rows():
    result = assur.dynamics(crank(omega=-10.0, gravity=(0.0, -9.81)), flywheel=0.5)
    page = Page(result._repr_html_())
    figures, rows = page.tables
    shown = [(a, b) for (_, a), (_, b) in figures]
    assert shown == figure_lines(result, unit=pretty_unit)
    # the figures write their units as the table below them does: "kg·m²" beside
    # the column's "kg·m²", where they wrote "kg m^2"
    units = dict(zip(list(result.columns), [t for _, t in rows[1]][1:], strict=True))
    assert units["reduced.inertia"] == "kg·m²"
    assert dict(shown)["flywheel"] == f"0.5 {units['reduced.inertia']}"
    motor = dict(shown)["motor torque"]
    assert motor.startswith(f"0 {units['driver.motor']} (constant")
    assert not any("^" in v or " N m" in v for _, v in shown)
    assert page.captions[1].startswith("dynamic model of ")
    assert page.captions[1].endswith(
        f"{len(result)} rows × {len(result.columns)} columns"
    )
    assert [text for _, text in rows[0]][1:] == list(result.columns)


def test_the_startup_shows_its_figures():
    mech = crank(motor=Motor(2.0, 10.0))
    run = assur.startup(dataclasses.replace(mech, name=HOSTILE))
    page = Page(run._repr_html_())
    assert "script" not in page.tags
    assert page.captions == [f"{HOSTILE}: start-up of the crank"]
    (figures,) = page.tables
    assert [(a, b) for (_, a), (_, b) in figures] == startup_lines(run)


def test_import_assur_loads_no_display_module():
    modules = (
        "assur._display",
        "assur._table_display",
        "assur._structure_display",
        "assur._dynamics_text",
    )
    code = f"import sys, assur; print([m for m in {modules!r} if m in sys.modules])"
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "[]"


def test_a_table_s_cells_are_named_by_their_column_and_row_for_a_screen_reader():
    t = assur.forces(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 10.0))
    head, body = t._repr_html_().split("<tbody>")
    # two rows of headings (names, units), each after a corner cell: every other
    # heading, the column of "..." too, heads its column
    assert head.count("<tr>") == 2 == head.count("<th>")
    assert head.count('<th scope="col">') == head.count("</th>") - 2 > 20
    # each row is named by its number (or "..." where rows are left out)
    assert body.count('<th scope="row">') == body.count("<tr>") == 11


def test_a_short_table_tells_round_off_among_every_column_of_its_unit():
    # a balanced scotch yoke shakes its frame with no moment: the columns of N m
    # shown (its shaking moment, its residual) are round-off alone, beside the
    # driver's torque left out of the display
    t = assur.forces(assur.load(EXAMPLES / "scotch_yoke.toml"), np.arange(0, 360, 7.5))
    page = Page(t._repr_html_())
    names = [text for _, text in page.tables[0][0]]
    body = [[text for _, text in row] for row in page.tables[0][2:]]
    k = names.index("residual.moment")
    at = shown_rows(len(t))
    raw = np.asarray(t["residual.moment"])[at]
    assert np.any(raw != 0.0)
    assert "driver.torque" not in names
    assert {row[k] for row in body} == {"0", "…"}


def test_a_table_with_positions_left_out_says_so():
    # a crank-rocker whose crank cannot turn round: the positions it does not
    # reach are left out, and its rows are numbered among those kept
    rocker = assur.catalog.four_bar(crank=0.09, coupler=0.06, rocker=0.08)
    angles = np.arange(0.0, 360.0, 10.0)
    t = assur.kinematics(rocker, angles, skip_unassembled=True)
    assert 0 < t.skipped.shape[0] < len(angles)
    page = Page(t._repr_html_())
    (said,) = [b for b in page.blocks.get("small", []) if "left out" in b]
    assert said.startswith(
        f"{t.skipped.shape[0]} of {len(angles)} positions left out ("
    )
    assert said.endswith("): table.skipped gives them")
    # a table of every position says nothing of it
    whole = assur.kinematics(rocker, t.given[:, 0])
    shown = Page(whole._repr_html_()).blocks.get("small", [])
    assert not [b for b in shown if "left out" in b]


def test_getting_started_says_what_each_result_shows():
    # it said "the dynamic model and a start-up show their figures", where the
    # dynamic model shows its table of rows too
    page = (EXAMPLES.parent / "docs" / "getting_started.rst").read_text("utf-8")
    said = " ".join(page.split())
    model = Page(assur.dynamics(crank(), flywheel=0.5)._repr_html_())
    run = Page(assur.startup(crank(motor=Motor(2.0, 10.0)))._repr_html_())
    assert (len(model.tables), len(run.tables)) == (2, 1)
    assert "the dynamic model shows its figures and its table" in said
    assert "a start-up its figures" in said
