"""The pages' tables for a screen reader: a caption, and headings that say their way.

Every table the package writes (the report's, the explanatory note's, the live
tables the report's script builds) names what it holds in a ``<caption>``, marks
its column headings ``scope="col"`` and names each of its rows by a ``<th
scope="row">``: every one of them has rows named by a cell (a group by its step, a
joint, link or figure by its name, a position by the driver's value, a step of
the friction's iteration by its number).
"""

from __future__ import annotations

import json
import re
import subprocess
import warnings
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pytest

import assur
from assur.explain import explain
from assur.html import render_report, write_report
from assur.html._series import current

from .test_html import (
    FAKE_DOM,
    _executable,
    _open,
    browser,  # noqa: F401 (the headless Chromium fixture)
)

EXAMPLES = Path(__file__).parent.parent / "examples"
LOCKING = Path(__file__).parent.parent / "docs" / "files" / "errors" / "locking.toml"


class _Tables(HTMLParser):
    """Collect each table's caption, column headings and body rows' cells."""

    def __init__(self) -> None:
        super().__init__()
        self.tables: list[dict[str, Any]] = []
        self.part = ""
        self.in_caption = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        found = dict(attrs)
        if tag == "table":
            kind = found.get("class") or "note"
            self.tables.append({"kind": kind, "caption": "", "heads": [], "rows": []})
        elif tag in ("thead", "tbody"):
            self.part = tag
        elif tag == "caption":
            self.in_caption = True
        elif tag == "tr" and self.part == "tbody":
            self.tables[-1]["rows"].append([])
        elif tag in ("th", "td"):
            if self.part == "thead":
                self.tables[-1]["heads"].append(found.get("scope"))
            else:
                self.tables[-1]["rows"][-1].append((tag, found.get("scope")))

    def handle_endtag(self, tag: str) -> None:
        if tag == "caption":
            self.in_caption = False
        elif tag in ("thead", "tbody"):
            self.part = ""

    def handle_data(self, data: str) -> None:
        if self.in_caption:
            self.tables[-1]["caption"] += data


def _tables(page: str) -> list[dict[str, Any]]:
    """Return the tables of ``page``'s HTML (its script and its data left out)."""
    parser = _Tables()
    parser.feed(page.split('<script type="application/json"')[0])
    return parser.tables


def _check(table: dict[str, Any], named: int = 1) -> None:
    """Assert ``table`` has a caption, column and row headings, as the module says.

    Each row is named by one cell (a group's step, after its colour), or by its
    first ``named`` cells (the drivers' positions).
    """
    assert table["caption"].strip()
    assert all(scope == "col" for scope in table["heads"])
    assert table["rows"]
    for row in table["rows"]:
        heads = [cell for cell in row if cell[0] == "th"]
        assert heads == [("th", "row")] * named
        assert named == 1 or row[:named] == heads
        # a cell under each heading: the row's names are among its cells, not more
        assert not table["heads"] or len(row) == len(table["heads"])


def _pages() -> dict[str, str]:
    """Return a page of each kind the package writes, by a name of its own."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        locked = explain(assur.load(LOCKING), 250.0)
    friction = assur.load(EXAMPLES / "slider_crank_friction.toml")
    answers = {"crank.omega": 200.0, "rod.omega": -50.0}
    return {
        # the note's tables: the lever's, friction's, a locked group's, the answers'
        "note, friction": explain(friction, 45.0).to_html(),
        "note, locked": locked.to_html(),
        "note, answers": explain(friction, 45.0, answers, "the book").to_html(),
        # the report's: structure, dynamics, inertia, summary, values, its note
        "report, friction": render_report(friction, [45.0, 90.0]),
        "report, kinematics": render_report(
            assur.load(EXAMPLES / "lever_var9.toml"), [0.0, 30.0]
        ),
    }


def test_every_table_of_every_page_has_a_caption_and_scoped_headings() -> None:
    # a screen reader met tables named by nothing, their headings' way unknown:
    # a value was read without its joint or its position
    kinds = set()
    for name, page in _pages().items():
        tables = _tables(page)
        assert tables, name
        for table in tables:
            _check(table)
            kinds.add(table["kind"])
    assert kinds == {
        "groups",
        "figures",
        "note",
        "values inertia",
        "values summary",
        "values",
    }


def test_a_row_of_two_drivers_is_named_by_both_positions() -> None:
    # the first crank's position alone named a row: where it stays, the rows of
    # the second's sweep had one name
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    angles = [[0.0, 0.0], [0.0, 10.0], [0.0, 20.0]]
    (values,) = [
        t for t in _tables(render_report(mech, angles)) if t["kind"] == "values"
    ]
    _check(values, named=2)
    page = render_report(mech, angles)
    rows = re.findall(r'<tr data-row="\d+">(.*?)</tr>', page)
    names = [tuple(re.findall(r'<th scope="row">(.*?)</th>', row)) for row in rows]
    assert len(set(names)) == len(names) == 3


LIVE_TABLES = r"""
const tables = [];
for (const table of byId.current.children) {
  const caption = table.children.find((c) => c.tag === "caption");
  const part = (tag) => table.children.filter((c) => c.tag === tag)
    .flatMap((p) => p.children);
  tables.push({caption: caption ? caption.textContent : "",
    heads: part("thead").flatMap((tr) => tr.children).map((c) => c.attrs.scope),
    rows: part("tbody").map((tr) => tr.children.map((c) => [c.tag, c.attrs.scope]))});
}
console.log(JSON.stringify(tables));
"""
"""The live tables the script wrote, as :func:`_check` reads them."""


def test_the_live_tables_of_the_position_shown_are_alike(tmp_path: Path) -> None:
    node = _executable("node", "nodejs")
    if node is None:
        pytest.skip("node not found")
    path = tmp_path / "slider_crank.html"
    write_report(assur.load(EXAMPLES / "slider_crank_exercise.toml"), path, [45.0])
    script = FAKE_DOM.split("const heads = [];")[0] + LIVE_TABLES
    out = subprocess.run(
        [node, "-e", script, str(path)], capture_output=True, text=True, check=True
    )
    tables = json.loads(out.stdout)
    assert len(tables) == 4  # links, slides, joints, inertia loads
    for table in tables:
        _check({**table, "rows": [[tuple(c) for c in r] for r in table["rows"]]})
    captions = [t["caption"] for t in tables]
    assert len(set(captions)) == len(captions)


ROW_AND_NAME = """
const wrap = document.querySelector(arguments[0]).parentElement;
wrap.scrollTop = 200;
const row = wrap.querySelector("tbody tr");
return [row.children[0], row.children[1]].map((c) => c.getBoundingClientRect().top);
"""
"""Scroll a table's box by 200 px; return its first row's name's and value's tops."""


@pytest.mark.browser
def test_a_row_s_name_scrolls_with_its_values(
    browser: Any,  # noqa: F811
    tmp_path: Path,
) -> None:
    # the column headings stay at the top of a scrolled table, and so did every
    # row's name in the summary (sticky too): the names piled up at the top, each
    # beside the values of another row
    path = tmp_path / "slider_crank.html"
    write_report(assur.load(EXAMPLES / "slider_crank_friction.toml"), path)
    _open(browser, path)
    for table in ("table.summary", "#values"):
        name, value = browser.execute_script(ROW_AND_NAME, table)
        assert name == pytest.approx(value)


def test_a_live_joints_table_s_caption_says_what_its_columns_hold() -> None:
    # the joints' table holds reactions in a force analysis, places in a kinematic
    # one: its caption, read before its cells, says which
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    seen = set()
    for table in (assur.kinematics(mech, [45.0]), assur.forces(mech, [45.0])):
        joints = current(table.plan, table)["joints"]
        forced = joints["head"][1].startswith("Fx")
        seen.add(forced)
        assert joints["caption"].startswith("Reaction" if forced else "Place")
    assert seen == {False, True}


def test_a_caption_that_names_a_joint_escapes_it() -> None:
    # the inertia table's caption names each driver's joint (several drivers): a
    # name in HTML is shown as written, not read as markup
    text = (EXAMPLES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    name = "<i>A</i>"
    text = text.replace('"A"', f'"{name}"').replace("[joints.A]", f'[joints."{name}"]')
    page = render_report(assur.loads(text), [[0.0, 30.0]])
    (inertia,) = (t for t in _tables(page) if t["kind"] == "values inertia")
    assert f"({name}: " in inertia["caption"]
