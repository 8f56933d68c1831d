"""The self-contained HTML report (assur.html): its file, its data and its page.

The browser test opens the report in Debian's headless Chromium through chromedriver
(selenium) and moves the range slider; it is skipped when either is missing.
"""

from __future__ import annotations

import dataclasses
import html
import json
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import assur
from assur import catalog
from assur.analysis import default_positions
from assur.columns import pretty_unit
from assur.html import render_report, write_report
from assur.plan import compile_plan
from assur.summary import Summary

from .conftest import example_files
from .test_imports import names_imported

EXAMPLES = Path(__file__).parent.parent / "examples"
KINEMATIC = EXAMPLES / "lever_var9.toml"
FORCED = EXAMPLES / "slider_crank_exercise.toml"
TENBAR = EXAMPLES / "tenbar.toml"
DATA_BLOCK = re.compile(
    r'<script type="application/json" id="assur-data">(.*?)</script>', re.S
)
ROUNDING = 5.01e-6
"""The page keeps 6 significant digits: half a unit of the 6th, relative to the
value, plus a hair."""


def page_data(text: str) -> dict[str, Any]:
    """The JSON object embedded in a report."""
    blocks = DATA_BLOCK.findall(text)
    assert len(blocks) == 1
    return json.loads(blocks[0])


@pytest.fixture(scope="module")
def pages() -> dict[str, str]:
    """Reports of the three reference examples, by file stem."""
    return {p.stem: render_report(assur.load(p)) for p in (KINEMATIC, FORCED, TENBAR)}


def test_write_report_writes_one_self_contained_file(tmp_path: Path) -> None:
    out = tmp_path / "report.html"
    write_report(assur.load(FORCED), out)
    assert [p.name for p in tmp_path.iterdir()] == ["report.html"]
    text = out.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>")
    assert text.rstrip().endswith("</html>")
    # offline: no address of any kind, no file loaded from elsewhere
    assert re.search(r"https?://", text) is None
    assert re.search(r"<(link|img|iframe)\b|\bsrc\s*=|@import|url\((?!#)", text) is None
    assert text.count("<script") == 2
    assert '<input type="range" id="angle"' in text


@pytest.mark.parametrize("stem", ["lever_var9", "slider_crank_exercise", "tenbar"])
def test_embedded_positions_match_the_kinematics(
    pages: dict[str, str], stem: str
) -> None:
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    table = assur.kinematics(mech, default_positions(mech))
    plan = compile_plan(mech)
    data = page_data(pages[stem])
    assert data["rows"] == len(table) == len(data["angle"])
    np.testing.assert_allclose(data["angle"], table["angle"], rtol=ROUNDING)
    joints = [p.name for p in plan.pairs.values() if not p.virtual]
    assert [j["name"] for j in data["joints"]] == joints
    assert sorted(data["points"]) == sorted(plan.points)
    size = compile_plan(mech).scale
    for name, xy in data["points"].items():
        for axis in "xy":
            assert len(xy[axis]) == len(table)
            np.testing.assert_allclose(
                xy[axis], table[f"{name}.{axis}"], rtol=ROUNDING, atol=1e-12 * size
            )


def test_links_and_groups_in_the_data(pages: dict[str, str]) -> None:
    mech = assur.load(TENBAR)
    struct = assur.structure(mech)
    data = page_data(pages["tenbar"])
    assert len(data["groups"]) == len(struct.drivers) + len(struct.groups)
    assert [g["kind"] for g in data["groups"]] == ["driver", "RRR", "RRR", "RRP", "RRR"]
    colours = [g["colour"] for g in data["groups"]]
    assert len(set(colours)) == len(colours)
    links = {link["name"]: link for link in data["links"]}
    assert sorted(links) == sorted(link.name for link in mech.links)
    # the ternary links 2 (B, C, E, H) and 6 (H, K, L) are plates
    assert sorted(links["2"]["points"]) == ["B", "C", "E", "H"]
    assert sorted(links["6"]["points"]) == ["H", "K", "L"]
    assert links["7"]["points"] == ["L", "S", "guide"]
    group_of = {x: g["colour"] for g in data["groups"] for x in g["links"]}
    assert all(link["colour"] == group_of[name] for name, link in links.items())
    assert [g["joint"] for g in data["guides"]] == ["guide"]


def test_force_report(pages: dict[str, str]) -> None:
    mech = assur.load(FORCED)
    table = assur.forces(mech, default_positions(mech))
    text = pages["slider_crank_exercise"]
    data = page_data(text)
    assert data["analysis"] == "forces"
    assert data["forces"]["joints"] == ["A", "B", "C", "guide"]
    for key in ("driver.torque", "driver.torque_check", "A.Fx", "guide.Fy", "C.F"):
        # a frictionless guide's Fx is round-off (1e-14 N) around zero
        np.testing.assert_allclose(
            data["columns"][key], table[key], rtol=ROUNDING, atol=1e-9
        )
    titles = [c["title"] for c in data["charts"]]
    assert titles == [
        "Balancing load and its check",
        "Joint reactions |F|",
        "Angular velocities of the links",
    ]
    assert "Reactions and balancing load" in text
    assert "balancing torque (N·m)" in text
    # 360 positions: every 10th row in the HTML table, the first one included
    rows = re.findall(r'<tr data-row="(\d+)">', text)
    assert rows == [str(i) for i in range(0, 360, 10)]


def test_force_report_shows_the_summary(pages: dict[str, str]) -> None:
    mech = assur.load(FORCED)
    parts = Summary()
    parts.add(assur.forces(mech, default_positions(mech)))
    summary = parts.result()
    text = pages["slider_crank_exercise"]
    assert '<section class="card wide" id="summary">' in text
    shown = re.findall(
        r'<tr data-key="([^"]+)"><th scope="row">[^<]+</th><td>([^<]+)</td>'
        r"<td>([^<]*)</td>",
        text,
    )
    assert [key for key, _, _ in shown] == list(summary)
    for key, value, unit in shown:
        # five significant digits in the page's tables
        assert float(value) == pytest.approx(summary[key], rel=5.01e-5, abs=1e-9)
        # spelt as the rest of the page spells it: N·m, not the CLI's N m
        assert unit == pretty_unit(parts.units[key])
    assert 'id="summary"' not in pages["lever_var9"]
    # turning counter-clockwise, no word on signs; clockwise, the CLI's note
    assert "turns clockwise" not in text
    mech = dataclasses.replace(mech, drivers=(assur.Driver("A", -200.0),))
    clockwise = render_report(mech, angles=[45.0, 90.0])
    assert (
        "The crank turns clockwise and torques are counter-clockwise positive: a "
        "torque that drives it is negative; a positive power is work the drivers "
        "supply.</p>" in clockwise
    )


def test_kinematics_only_report(pages: dict[str, str]) -> None:
    text = pages["lever_var9"]
    data = page_data(text)
    assert data["analysis"] == "kinematics"
    assert data["forces"] is None
    assert [c["id"] for c in data["charts"]] == ["chart-omega"]
    assert "kinematics only (no masses or loads)" in text
    assert 'id="force-note"' not in text
    assert "<h2>Kinematics</h2>" in text
    assert [s["name"] for s in data["charts"][0]["series"]] == ["1", "2", "4"]


def test_structure_report_in_the_page(pages: dict[str, str]) -> None:
    mech = assur.load(KINEMATIC)
    struct = assur.structure(mech)
    text = pages["lever_var9"]
    for line in str(struct).splitlines():
        if line.strip():
            assert html.escape(line.strip()) in text
    assert html.escape(struct.formula.replace(" -> ", " → ")) in text
    groups_table = re.search(r'<table class="groups">(.*?)</table>', text, re.S)
    assert groups_table is not None
    assert groups_table.group(1).count("<tr>") == 1 + 3  # header, driver, two dyads


def test_short_sweep_shows_every_row() -> None:
    text = render_report(catalog.four_bar(), angles=[0.0, 30.0, 60.0])
    data = page_data(text)
    assert data["rows"] == 3
    assert re.findall(r'<tr data-row="(\d+)">', text) == ["0", "1", "2"]
    assert 'max="2"' in text


def test_two_drivers() -> None:
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    angles = np.column_stack([np.arange(60.0, 150.0, 30.0), np.full(3, 120.0)])
    data = page_data(render_report(mech, angles))
    assert data["rows"] == 3
    keys = [s["key"] for s in data["charts"][0]["series"]]
    assert keys == ["A.torque", "A.torque_check", "E.torque", "E.torque_check"]


def test_positions_that_do_not_assemble() -> None:
    # a crank longer than the coupler plus the rocker: the loop opens near 180 deg
    mech = catalog.four_bar(crank=0.08, coupler=0.05, rocker=0.05, frame=0.1)
    text = render_report(mech, angles=[60.0, 180.0])
    assert page_data(text)["rows"] == 1
    assert "1 of 2 positions left out" in text
    # no position left: the first one's error, naming its group and the position
    with pytest.raises(
        assur.AssemblyError, match=r"group RRR \(coupler, rocker\): .* 170 deg"
    ):
        render_report(mech, angles=[170.0, 180.0])


def test_a_sweep_locked_by_friction_is_said_to_be(tmp_path: Path) -> None:
    # "cannot be assembled" was said of positions that assemble but lock
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    path = tmp_path / "locked.toml"
    path.write_text(text.replace("friction = 0.8", "friction = 1.5"), encoding="utf-8")
    with pytest.raises(assur.SelfLockingError, match="240 deg"):
        render_report(assur.load(path), angles=[240.0, 245.0, 250.0])


def test_names_cannot_break_out_of_the_page() -> None:
    name = 'Bad </script><b onclick="x()"> & name'
    mech = dataclasses.replace(catalog.four_bar(), name=name, description="<i>d</i>")
    text = render_report(mech, angles=[0.0, 90.0])
    assert "<b onclick" not in text
    assert "<i>d</i>" not in text
    assert text.count("</script>") == 2
    data = page_data(text)
    assert data["name"] == name
    assert data["description"] == "<i>d</i>"


@pytest.mark.parametrize("path", example_files(), ids=lambda p: p.stem)
def test_every_unit_is_the_schema_s(path: Path) -> None:
    from assur.columns import schema
    from assur.plan import plan_of

    mech = assur.load(path)
    text = render_report(mech, default_positions(mech)[::30])
    data = page_data(text)
    units = {c.name: pretty_unit(c.unit) for c in schema(plan_of(mech), True)}
    assert data["driver"]["unit"] == units["angle"]
    for chart in (c for c in data["charts"] if c["series"]):
        shown = chart["unit"].split(" or ")
        assert shown == list(dict.fromkeys(units[s["key"]] for s in chart["series"]))
    if data["forces"] is not None:
        assert data["forces"]["unit"] == units[f"{data['forces']['joints'][0]}.F"]
        assert {units[f"{j}.F"] for j in data["forces"]["joints"]} == {"N"}
        for item in data["forces"]["balancing"]:
            assert item["unit"] == units[item["key"]]
    for part in data["current"].values():
        for row in part["rows"]:
            headings = part["head"][1:]
            assert [h.rsplit(" (", 1)[1] for h in headings] == [
                f"{units[key]})" for key in row["keys"]
            ]
    head = r'<th scope="col" data-key="([^"]+)">[^<]*\(([^()]+)\)</th>'
    headings = re.findall(head, text)
    assert len(headings) == text.count('<th scope="col" data-key=')
    assert headings
    for key, unit in headings:
        assert unit == units[html.unescape(key)]


def test_units_in_the_force_report(pages: dict[str, str]) -> None:
    data = page_data(pages["slider_crank_exercise"])
    assert data["current"]["links"]["head"] == [
        "link",
        "angle (deg)",
        "ω (rad/s)",
        "α (rad/s²)",
    ]
    assert data["current"]["joints"]["head"] == [
        "joint",
        "Fx (N)",
        "Fy (N)",
        "|F| (N)",
    ]
    # the inertia loads follow the slider: each massive link's Fi and Mi columns
    assert data["current"]["inertia"]["head"] == [
        "inertia of",
        "Fi,x (N)",
        "Fi,y (N)",
        "Mi (N·m)",
    ]
    rows = data["current"]["inertia"]["rows"]
    assert [r["name"] for r in rows] == ["crank", "rod", "slider"]
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    table = assur.forces(mech, default_positions(mech))
    for row in rows:
        for key in row["keys"]:
            np.testing.assert_allclose(data["columns"][key], table[key], rtol=1e-5)
    assert [c["unit"] for c in data["charts"]] == ["N·m", "N", "rad/s"]
    assert data["forces"]["balancing"][0]["unit"] == "N·m"
    kinematic = page_data(pages["lever_var9"])
    assert kinematic["current"]["slides"]["head"] == [
        "slide",
        "s (m)",
        "v (m/s)",
        "a (m/s²)",
    ]
    assert kinematic["current"]["joints"]["head"] == ["joint", "x (m)", "y (m)"]


def test_only_render_report_compiles_a_plan() -> None:

    import assur.html

    recompilers = {"compile_plan", "plan_of", "decompose", "structure"}
    folder = Path(assur.html.__file__).parent
    for path in sorted(folder.glob("*.py")):
        imported = names_imported(path)
        expected = {"plan_of", "structure"} if path.name == "__init__.py" else set()
        assert imported & recompilers == expected, path.name


def test_import_loads_no_matplotlib() -> None:
    code = "import sys, assur.html; print('matplotlib' in sys.modules)"
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert result.stdout.strip() == "False"


# ------------------------------------------------------- the script under node

FAKE_DOM = r"""
// Just enough of a DOM to run the report's script under node and read what it wrote.
const fs = require("fs");
const page = fs.readFileSync(process.argv[1], "utf8");
const data = page.match(/id="assur-data">([\s\S]*?)<\/script>/)[1];
const script = page.match(/<script>\n([\s\S]*?)<\/script>/)[1];
function make(tag) {
  return {tag, attrs: {}, children: [], style: {}, dataset: {}, textContent: "",
    value: "0", classList: {add() {}, remove() {}},
    setAttribute(k, v) { this.attrs[k] = v; },
    getAttribute(k) { return this.attrs[k]; },
    appendChild(c) { this.children.push(c); return c; }, addEventListener() {},
    insertRow() { return this.appendChild(make("tr")); },
    insertCell() { return this.appendChild(make("td")); },
    createTHead() { return this.appendChild(make("thead")); },
    createTBody() { return this.appendChild(make("tbody")); }};
}
const svg = make("svg");
svg.namespaceURI = "svg";
svg.viewBox = {baseVal: {width: 640, height: 400}};
const byId = {mechanism: svg};
global.window = {addEventListener() {}};
global.setInterval = () => 0;
global.clearInterval = () => {};
global.document = {documentElement: {dataset: {}},
  getElementById(id) {
    if (id === "assur-data") return {textContent: data};
    return byId[id] || (byId[id] = make(id));
  },
  createElementNS(ns, tag) { return make(tag); },
  createElement(tag) { return make(tag); },
  createTextNode(text) { const n = make("#text"); n.textContent = text; return n; },
  querySelectorAll() { return []; }};
eval(script);
const heads = [];
(function walk(n) {
  if (n.tag === "th") heads.push(n.textContent);
  // the column headings: a row's name is a heading too, in the table's body
  if (n.tag !== "tbody") n.children.forEach(walk);
})(byId.current);
console.log(JSON.stringify({ready: document.documentElement.dataset.ready,
  errors: window.assurErrors, readout: byId.readout.textContent, heads: heads,
  note: byId["force-note"].textContent}));
"""
"""A stand-in for a browser's DOM: runs the page's script, prints what it wrote."""


def test_script_writes_the_schema_units(tmp_path: Path) -> None:
    # the browser tests below need Chromium; node runs the script on a fake DOM
    node = _executable("node", "nodejs")
    if node is None:
        pytest.skip("node not found")
    path = tmp_path / "slider_crank.html"
    write_report(assur.load(FORCED), path)
    out = subprocess.run(
        [node, "-e", FAKE_DOM, str(path)], capture_output=True, text=True, check=True
    )
    shown = json.loads(out.stdout)
    assert shown["ready"] == "true"
    assert shown["errors"] == []
    assert shown["readout"] == "driver angle 45° · balancing torque 84.63 N·m"
    assert shown["heads"] == [
        "link",
        "angle (deg)",
        "ω (rad/s)",
        "α (rad/s²)",
        "slide",
        "s (m)",
        "v (m/s)",
        "a (m/s²)",
        "M (N·m)",
        "joint",
        "Fx (N)",
        "Fy (N)",
        "|F| (N)",
        "inertia of",
        "Fi,x (N)",
        "Fi,y (N)",
        "Mi (N·m)",
    ]
    assert "the bar in the lower left corner is 10000 N)" in shown["note"]


SCRIPT = Path(assur.html.__file__).parent / "report.js"
SPREAD = re.compile(r"[(,]\s*\.\.\.|\.apply\(")
"""An array spread into a call's arguments (``Math.min(...values)``), or applied."""


def test_script_spreads_no_array_into_a_call() -> None:
    # each argument takes a place on the stack: Math.max(...values) over a sweep
    # of 36 001 positions overflows it (RangeError), so the script loops instead
    code = re.sub(r"//.*", "", SCRIPT.read_text(encoding="utf-8"))
    spread = [
        line.strip() for line in code.splitlines() if SPREAD.search(line) is not None
    ]
    assert spread == []


def test_script_finds_the_extent_of_a_long_sweep() -> None:
    node = _executable("node", "nodejs")
    if node is None:
        pytest.skip("node not found")
    found = re.search(
        r"^  function extent\(.*?^  }$", SCRIPT.read_text(encoding="utf-8"), re.M | re.S
    )
    assert found is not None
    # 200 000 values (twice the most positions a page holds), every 7th left out
    run = found.group() + (
        "\nconst a = Array.from({length: 200000}, (_, i) => i % 7 ? i - 1e5 : null);"
        "\nconsole.log(JSON.stringify(extent([a, [null, 3e5]])));"
    )
    out = subprocess.run(
        [node, "-e", run], capture_output=True, text=True, check=True, timeout=60
    )
    assert json.loads(out.stdout) == [-99999, 300000]


# ------------------------------------------------------------------ the browser

CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--window-size=1280,900",
)


def _executable(*names: str) -> str | None:
    for name in names:
        found = shutil.which(name) or (
            f"/usr/bin/{name}" if Path(f"/usr/bin/{name}").exists() else None
        )
        if found:
            return found
    return None


@pytest.fixture(scope="module")
def browser() -> Any:
    """A headless Chromium driven through chromedriver, or a skip saying what is
    missing."""
    webdriver = pytest.importorskip(
        "selenium.webdriver", reason="selenium is not installed (pip install selenium)"
    )
    from selenium.webdriver.chrome.service import Service

    binary = _executable("chromium", "chromium-browser")
    driver_path = _executable("chromedriver")
    if binary is None or driver_path is None:
        pytest.skip(
            "headless Chromium not found (apt-get install chromium chromium-driver)"
        )
    options = webdriver.ChromeOptions()
    # a fixed browser and driver: selenium then never looks for others online
    options.binary_location = binary
    profile = tempfile.TemporaryDirectory()
    for flag in (*CHROMIUM_FLAGS, f"--user-data-dir={profile.name}"):
        options.add_argument(flag)
    driver = webdriver.Chrome(service=Service(driver_path), options=options)
    try:
        yield driver
    finally:
        driver.quit()
        profile.cleanup()


def _open(browser: Any, path: Path) -> None:
    from selenium.webdriver.support.ui import WebDriverWait

    browser.get(path.as_uri())
    WebDriverWait(browser, 10).until(
        lambda b: b.execute_script("return document.documentElement.dataset.ready")
    )
    assert browser.execute_script("return window.assurErrors") == []


def _move_slider(browser: Any, row: int) -> None:
    browser.execute_script(
        "const s = document.getElementById('angle'); s.value = arguments[0];"
        "s.dispatchEvent(new Event('input', {bubbles: true}));",
        str(row),
    )


def _joint(browser: Any, name: str) -> tuple[float, float]:
    node = browser.find_element("css selector", f'circle[data-joint="{name}"]')
    return float(node.get_attribute("cx")), float(node.get_attribute("cy"))


@pytest.mark.browser
def test_slider_moves_the_drawing(browser: Any, tmp_path: Path) -> None:
    path = tmp_path / "slider_crank.html"
    write_report(assur.load(FORCED), path)
    _open(browser, path)
    svg = browser.find_element("id", "mechanism")
    joints = svg.find_elements("css selector", "circle[data-joint]")
    assert sorted(j.get_attribute("data-joint") for j in joints) == ["A", "B", "C"]
    assert len(svg.find_elements("css selector", "g[data-block]")) == 1
    assert len(svg.find_elements("css selector", "line[data-force]")) == 4
    assert len(browser.find_elements("css selector", "#charts figure > svg")) == 3
    a0, b0 = _joint(browser, "A"), _joint(browser, "B")
    readout = browser.find_element("id", "readout").text
    assert readout.startswith("driver angle 45°")

    _move_slider(browser, 90)
    a1, b1 = _joint(browser, "A"), _joint(browser, "B")
    assert a1 == pytest.approx(a0, abs=1e-6)  # the frame pivot stays
    assert abs(b1[0] - b0[0]) + abs(b1[1] - b0[1]) > 20.0  # px: the crank turned
    # the crank keeps its length on the screen
    assert np.hypot(b1[0] - a1[0], b1[1] - a1[1]) == pytest.approx(
        np.hypot(b0[0] - a0[0], b0[1] - a0[1]), rel=1e-4
    )
    force = browser.find_element("css selector", 'line[data-force="B"]')
    assert float(force.get_attribute("x1")) == pytest.approx(b1[0], abs=1e-6)
    assert browser.find_element("id", "readout").text.startswith("driver angle 135°")
    shown = browser.find_element("css selector", "#values tr.shown")
    assert shown.get_attribute("data-row") == "90"
    assert browser.execute_script("return window.assurErrors") == []


@pytest.mark.browser
def test_kinematics_only_page_in_the_browser(browser: Any, tmp_path: Path) -> None:
    path = tmp_path / "lever.html"
    write_report(assur.load(KINEMATIC), path)
    _open(browser, path)
    assert browser.find_elements("css selector", "line[data-force]") == []
    blocks = browser.find_elements("css selector", "g[data-block]")
    assert sorted(b.get_attribute("data-block") for b in blocks) == [
        "block",
        "guide_C",
        "guide_D",
    ]
    before = _joint(browser, "C")
    _move_slider(browser, 120)
    after = _joint(browser, "C")
    assert after[1] == pytest.approx(before[1], abs=1e-6)  # C slides on y = 0
    assert abs(after[0] - before[0]) > 5.0
    assert browser.execute_script("return window.assurErrors") == []


def test_the_diagrams_break_where_positions_were_left_out() -> None:
    from assur._gaps import gaps

    triad = assur.load(Path(__file__).parent / "data" / "edge" / "triadP.toml")
    table = assur.kinematics(triad, np.arange(30.0, 390.0, 1.0), skip_unassembled=True)
    (row,) = gaps(table)
    assert table.given[row - 1, 0] == 114.0
    assert table.given[row, 0] == 238.0
    # an uneven sweep with nothing left out has no gap
    uneven = np.r_[np.arange(0.0, 90.0), np.arange(90.0, 361.0, 10.0)]
    assert gaps(assur.kinematics(assur.catalog.slider_crank(), uneven)) == []


def test_the_readout_gives_every_driver_s_position(tmp_path: Path) -> None:
    # only the first driver's angle was shown: the second crank's never was
    node = _executable("node", "nodejs")
    if node is None:
        pytest.skip("node not found")
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    path = tmp_path / "five_bar.html"
    write_report(mech, path)
    out = subprocess.run(
        [node, "-e", FAKE_DOM, str(path)], capture_output=True, text=True, check=True
    )
    shown = json.loads(out.stdout)
    assert shown["errors"] == []
    first, second = default_positions(mech)[0]
    assert shown["readout"].startswith(f"driver angle {first:g}° · E {second:g}° · ")


def test_the_page_s_parts_after_the_sweep_are_told():
    # the free-body diagrams took seconds after the sweep's bar had ended, with no
    # bar at all: the command line now shows one of the page's parts
    from assur.html import PAGE_PARTS, render_report

    told = []
    page = render_report(
        assur.load(EXAMPLES / "slider_crank_exercise.toml"),
        angles=[0.0, 90.0],
        parts=lambda done, total: told.append((done, total)),
    )
    assert told == [(k, PAGE_PARTS) for k in range(1, PAGE_PARTS + 1)]
    assert 'id="free-bodies"' in page


def test_the_note_s_headings_sit_below_its_card_s():
    # "1. Structure" was an h2 under the card's h2 "The analysis at the first ..."
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    page = render_report(mech, angles=np.arange(0.0, 360.0, 30.0))
    start = page.index('id="note"')
    note = page[start : page.index("</section>", start)]
    levels = [int(x) for x in re.findall(r"<h(\d)>", note)]
    assert levels[0] == 2
    assert all(level >= 3 for level in levels[1:])
    assert re.search(r"<h3>1\. Structure</h3>", note)
