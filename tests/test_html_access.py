"""The report for readers who do not see its colours: screen readers, grey paper.

Every picture of the page is named for a screen reader, the series of one
diagram differ by more than their hue, and the row of the position shown is
marked by more than a tint (the page's script is run under node on the
fake DOM of :mod:`tests.test_html`).
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest

import assur
from assur.html import render_report, write_report

from .test_html import (
    FAKE_DOM,
    _executable,
    _move_slider,
    _open,
    browser,  # noqa: F401 (the headless Chromium fixture)
)
from .test_html_print import _rule, _style

EXAMPLES = Path(__file__).parent.parent / "examples"

CHART_LINES = r"""
const charts = [];
function walk(n, out) {
  if (n.tag === "path" || n.tag === "line") out.push(n);
  n.children.forEach((c) => walk(c, out));
}
for (const figure of byId.charts.children) {
  const [caption, svg, legend] = figure.children;
  const lines = [];
  walk(svg, lines);
  const keys = legend.children.map((span) => {
    const found = [];
    walk(span, found);
    return found.map((n) => [n.attrs.stroke, n.attrs["stroke-dasharray"]]);
  });
  charts.push({title: caption.textContent,
    series: lines.filter((n) => n.tag === "path")
      .map((n) => [n.attrs.stroke, n.attrs["stroke-dasharray"]]),
    keys: keys});
}
console.log(JSON.stringify(charts));
"""
"""Each diagram's series and legend keys as [colour, dash pattern] pairs."""


def test_every_picture_of_the_page_is_named() -> None:
    # the free-body diagrams (matplotlib's SVG, its words drawn as outlines) had
    # neither a role nor a name: a screen reader met a picture it could not name
    page = render_report(
        assur.load(EXAMPLES / "six_bar_lecture.toml"), [30.0, 120.0, 210.0]
    )
    body = page.split('<script type="application/json"')[0]
    roots = re.findall(r"<svg\b[^>]*>", body)
    assert len(roots) == 3  # the drawing and two groups' free bodies
    for root in roots:
        assert 'role="img"' in root
        label = re.search(r'aria-label="([^"]+)"', root)
        assert label is not None
    named = re.findall(r'<svg[^>]*aria-label="Free-body diagram of ([^"]+)"', body)
    assert named == ["Group 1: RRR (3, 4)", "Group 2: RRR (5, 6)"]


def _six_bar_script(folder: Path, tail: str) -> Any:
    """Run the six-bar's report script under node on the fake DOM, then ``tail``.

    Returns what ``tail`` printed, read as JSON; skips without node.
    """
    node = _executable("node", "nodejs")
    if node is None:
        pytest.skip("node not found")
    path = folder / "six_bar.html"
    write_report(assur.load(EXAMPLES / "six_bar_lecture.toml"), path)
    script = FAKE_DOM.split("const heads = [];")[0] + tail
    out = subprocess.run(
        [node, "-e", script, str(path)], capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout)


def test_a_diagram_s_series_differ_by_more_than_their_hue(tmp_path: Path) -> None:
    # the joint reactions (7 series) and the angular velocities (5) were told by
    # hue alone, six of which print as one grey: each series now has a pattern
    # of its own among its first five, and its legend key shows it
    charts = {c["title"]: c for c in _six_bar_script(tmp_path, CHART_LINES)}
    reactions = charts["Joint reactions |F|"]["series"]
    assert len(reactions) == 7
    patterns = [dash for _, dash in reactions]
    assert len(set(patterns[:5])) == 5
    # the check by virtual power stays the dashed black line over its load
    check = charts["Balancing load and its check"]["series"]
    assert check == [["#2563eb", "none"], ["#111827", "5 4"]]
    for chart in charts.values():
        series = [tuple(s) for s in chart["series"]]
        assert len(set(series)) == len(series)
        # the key of each series is drawn as its line is
        assert [tuple(k[0]) for k in chart["keys"]] == series


def test_the_row_shown_is_marked_by_more_than_its_tint() -> None:
    # a light blue (1.2:1 against white) was all that marked it: gone on grey
    # paper, and nothing at all for a screen reader
    page = render_report(assur.load(EXAMPLES / "four_bar.toml"), [0.0, 90.0])
    css = _style(page)
    assert "font-weight: 600" in _rule(css, "table.values tr.shown td")
    assert "font-weight: 600" in _rule(css, "#values tr.shown th")
    assert "box-shadow" in _rule(css, "#values tr.shown th:first-child")


def _four_bar_page(driver: Any, folder: Path) -> None:
    """Open the four-bar's report, of its default sweep, in ``driver``."""
    path = folder / "four_bar.html"
    write_report(assur.load(EXAMPLES / "four_bar.toml"), path)
    _open(driver, path)


@pytest.mark.browser
def test_the_row_shown_is_current_for_a_screen_reader(
    browser: Any,  # noqa: F811
    tmp_path: Path,
) -> None:
    _four_bar_page(browser, tmp_path)
    for row in ("0", "90"):
        _move_slider(browser, int(row))
        marked = browser.find_elements(
            "css selector", '#values tr[aria-current="true"]'
        )
        assert [m.get_attribute("data-row") for m in marked] == [row]


def test_the_colour_column_of_the_groups_has_a_heading() -> None:
    # its heading was an empty cell: a screen reader named the column by nothing
    page = render_report(assur.load(EXAMPLES / "four_bar.toml"), [0.0, 90.0])
    table = page.split('<table class="groups"')[1].split("</thead>")[0]
    first = re.findall(r'<th scope="col">(.*?)</th>', table)[0]
    assert re.sub(r"<[^>]+>", "", first) == "Colour in the drawing"
    assert "position: absolute" in _rule(_style(page), ".unseen")


@pytest.mark.browser
def test_the_position_is_said_by_the_slider_and_not_announced_at_each_frame(
    browser: Any,  # noqa: F811
    tmp_path: Path,
) -> None:
    # the readout, an <output> and so a live region, was announced at each of
    # Play's 25 frames a second; the slider said only its row number
    _four_bar_page(browser, tmp_path)
    readout = browser.find_element("id", "readout")
    assert readout.get_attribute("aria-live") == "off"
    slider = browser.find_element("id", "angle")
    first = slider.get_attribute("aria-valuetext")
    assert first == readout.text
    _move_slider(browser, 90)
    assert slider.get_attribute("aria-valuetext") == readout.text != first


TICK_TEXTS = r"""
const texts = [];
function walk(n) {
  if (n.tag === "text") texts.push(n.textContent);
  n.children.forEach(walk);
}
walk(byId.charts);
console.log(JSON.stringify(texts));
"""
"""Every text drawn in the diagrams: tick labels, units, captions of the axes."""


def test_a_diagram_s_negative_numbers_carry_a_minus_sign(tmp_path: Path) -> None:
    # they were written with a hyphen ("-0.5"), a dash shorter than the plus
    texts = _six_bar_script(tmp_path, TICK_TEXTS)
    numbers = [t for t in texts if re.fullmatch(r"\S?[\d.]+", t)]
    assert any(t.startswith("\u2212") for t in numbers)
    assert not any(t.startswith("-") for t in numbers)


def test_the_block_and_pin_of_a_slot_read_as_words_in_the_page() -> None:
    # the groups' pairs and the free bodies' captions: "B~pin" and "B~block" are
    # the names of the JSON output, "B (pin)" and "B (block)" the reader's
    page = render_report(assur.load(EXAMPLES / "slot_mechanism.toml"), [30.0])
    body = page.split('<script type="application/json"')[0]
    assert "<td>O4, B (pin)</td>" in body
    assert "<figcaption>Group 1: RPR (rocker, B (block))</figcaption>" in body
