"""The note and the report as a teacher hands them out: on a phone and on paper.

A phone lays both pages out at its own width, nothing wider than the screen but
inside a scrolling box; on paper a heading or a chart's caption is not left at
the foot of a page, away from what it heads; a diagram's unit does not overprint
its numbers.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

import assur
from assur.explain import explain
from assur.explain._html import html_page
from assur.html import render_report, write_report

from .test_html import _open, browser  # noqa: F401 (the headless Chromium fixture)
from .test_html_print import LONG, _print_rules, _rule, _style

EXAMPLES = Path(__file__).parent.parent / "examples"
HEADINGS = ("h1", "h2", "h3", "h4", "h5", "h6")


def _note_page(stem: str = "six_bar_lecture") -> str:
    return html_page(explain(assur.load(EXAMPLES / f"{stem}.toml"), 45.0))


def test_the_note_page_is_laid_out_at_a_phone_s_width() -> None:
    # without it a phone drew the note 980 pixels wide and shrank it to fit
    head = _note_page().split("</head>")[0]
    assert '<meta name="viewport" content="width=device-width, initial-scale=1">' in (
        head
    )


def test_a_heading_stays_with_what_follows_on_paper() -> None:
    report = render_report(assur.load(EXAMPLES / "four_bar.toml"), [0.0, 90.0])
    for page in (_note_page(), report):
        rules = _print_rules(page)
        for heading in HEADINGS:
            assert "break-after: avoid" in _rule(rules, heading)
        assert "break-inside: avoid" in _rule(rules, "tr")
    # a chart's caption was printed at a page's foot, its chart on the next
    rules = _print_rules(report)
    assert "break-after: avoid" in _rule(rules, "figcaption")
    assert "break-inside: avoid" in _rule(rules, "figure")


def test_tables_scroll_only_on_a_screen() -> None:
    # on paper a scrolling box would clip the table's right-hand columns; the box
    # is around the table, which stays a table (display: block made it none to
    # some screen readers)
    page = _note_page()
    assert "overflow-x: auto" in _rule(_style(page).split("@media print")[0], ".grid")
    assert "overflow: visible" in _rule(_print_rules(page), ".grid")
    assert '<div class="grid"><table>' in page
    assert "display: block" not in _style(page).replace('display="block"', "")


def _phone(driver: Any) -> None:
    driver.execute_cdp_cmd(
        "Emulation.setDeviceMetricsOverride",
        {"width": 400, "height": 900, "deviceScaleFactor": 1, "mobile": True},
    )


@pytest.mark.browser
def test_neither_page_is_wider_than_a_phone(browser: Any, tmp_path: Path) -> None:  # noqa: F811
    # the note was 980 pixels wide, the report 519 (its readout, the table of
    # groups and the note's tables): the reader scrolled the whole page sideways
    note = tmp_path / "note.html"
    explain(assur.load(EXAMPLES / "six_bar_lecture.toml"), 45.0).write(note)
    report = tmp_path / "report.html"
    write_report(assur.load(EXAMPLES / "six_bar_lecture.toml"), report)
    _phone(browser)
    try:
        widths = {}
        for path in (note, report):
            if path is note:
                browser.get(path.as_uri())
            else:
                _open(browser, path)
            widths[path.name] = browser.execute_script(
                "return document.documentElement.scrollWidth"
            )
    finally:
        browser.execute_cdp_cmd("Emulation.clearDeviceMetricsOverride", {})
    assert widths == {"note.html": 400, "report.html": 400}


@pytest.mark.browser
def test_a_diagram_s_unit_clears_its_numbers(browser: Any, tmp_path: Path) -> None:  # noqa: F811
    # "kg·m²" of the reduced inertia was written over its tick label "0.0015"
    path = tmp_path / "four_bar.html"
    write_report(assur.load(EXAMPLES / "four_bar.toml"), path)
    _open(browser, path)
    clashes = browser.execute_script(
        """
        const out = [];
        for (const axis of document.querySelectorAll('figure svg g.axis')) {
          const texts = Array.from(axis.querySelectorAll('text'));
          const unit = texts.find(t => t.hasAttribute('transform'));
          const u = unit.getBoundingClientRect();
          for (const t of texts) {
            if (t === unit) continue;
            const r = t.getBoundingClientRect();
            if (r.left < u.right && u.left < r.right && r.top < u.bottom
                && u.top < r.bottom) out.push([unit.textContent, t.textContent]);
          }
        }
        return out;
        """
    )
    assert clashes == []


@pytest.mark.browser
def test_the_table_of_groups_keeps_its_words_whole(
    browser: Any,  # noqa: F811
    tmp_path: Path,
) -> None:
    # in the Whitworth's narrow Structure card "input link" read "inpu t link"
    # and "block, lever" put its comma on a line of its own
    path = tmp_path / "whitworth.html"
    write_report(assur.load(EXAMPLES / "whitworth.toml"), path)
    browser.set_window_size(1280, 900)
    _open(browser, path)
    split = browser.execute_script(
        """
        const out = [], walk = document.createTreeWalker(
          document.querySelector('table.groups'), NodeFilter.SHOW_TEXT);
        for (let node = walk.nextNode(); node; node = walk.nextNode()) {
          const text = node.textContent;
          for (const m of text.matchAll(/\\S+/g)) {
            const range = document.createRange();
            range.setStart(node, m.index);
            range.setEnd(node, m.index + m[0].length);
            const tops = new Set(Array.from(range.getClientRects(),
                                            r => Math.round(r.top)));
            if (tops.size > 1) out.push(m[0]);
          }
        }
        return out;
        """
    )
    assert split == []
    # a name of 67 letters scrolls inside the card rather than widening the page
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace('"coupler"', f'"{LONG}"').replace(
        "links.coupler", f"links.{LONG}"
    )
    path.write_text(render_report(assur.loads(text), [0.0, 90.0]), encoding="utf-8")
    _open(browser, path)
    widths = browser.execute_script(
        "const e = document.documentElement; return [e.scrollWidth, e.clientWidth]"
    )
    assert widths[0] == widths[1]


def test_brackets_keep_their_size_and_bars_hug_what_they_enclose() -> None:
    from assur.explain._mathml import mathml

    # a ")" under a square was a stretchy operator alone in its <msup>: Chromium
    # drew it larger and below its line; "|w|" was two infix bars, spaced apart
    got = mathml(r"(-54.21)^2 = |\omega| \cdot l")
    assert '<msup><mo stretchy="false">)</mo><mn>2</mn></msup>' in got
    assert '<mo form="prefix" stretchy="false">|</mo><mi>ω</mi>' in got
    assert '<mi>ω</mi><mo form="postfix" stretchy="false">|</mo>' in got
    assert got.count('<mo form="prefix">−</mo>') == 1  # still a sign after "("
    # |a|^2: the bar under a square is a fence too; \left( still stretches
    squared = mathml(r"|\vec w|^2 = -\left(a + b\right)")
    assert '<mo form="prefix" stretchy="false">|</mo><mover' in squared
    assert '<msup><mo form="postfix" stretchy="false">|</mo>' in squared
    assert "<mo>(</mo>" in squared
    assert "<mo>)</mo>" in squared


@pytest.mark.browser
@pytest.mark.parametrize("stem", ["class3", "six_bar_lecture", "five_bar_two_cranks"])
def test_a_long_equation_fits_a_printed_column(
    browser: Any,  # noqa: F811
    tmp_path: Path,
    stem: str,
) -> None:
    # MathML breaks no line: 6 to 19 equations of a note were wider than an A4
    # column (655 px) and lost their ends on paper, the longest 1237 px
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    angle = [40.0, 100.0] if len(mech.drivers) > 1 else 45.0
    note = tmp_path / "note.html"
    explain(mech, angle).write(note)
    size = browser.get_window_size()
    browser.set_window_size(760, 900)
    browser.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": "print"})
    try:
        browser.get(note.as_uri())
        # the page's column, 655 px as on A4 paper, its type as printed
        browser.execute_script("document.body.style.maxWidth = '655px'")
        wide = browser.execute_script(
            "return [...document.querySelectorAll('math[display=\"block\"]')]"
            ".filter((m) => m.scrollWidth > document.body.clientWidth)"
            ".map((m) => m.getAttribute('alttext'))"
        )
        rows = browser.execute_script(
            "return document.querySelectorAll('mtable').length"
        )
    finally:
        browser.execute_cdp_cmd("Emulation.setEmulatedMedia", {"media": ""})
        browser.set_window_size(size["width"], size["height"])
    assert wide == []
    assert rows > 0
