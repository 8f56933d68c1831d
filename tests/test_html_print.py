"""The report page on paper, without JavaScript and with awkward names.

Checked on the page's text: its print style sheet, its scrolling equations, the
scope of the free-body pictures' styles, long names, the order of its tables and
the spelling of its units.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import pytest

import assur
from assur.html import render_report

EXAMPLES = Path(__file__).parent.parent / "examples"
LONG = "the_coupler_of_this_crank_rocker_four_bar_with_a_very_long_name_xyz"
"""A link name of 67 letters and no space."""


@pytest.fixture(scope="module")
def four_bar() -> str:
    """The four-bar's report over a few positions."""
    return render_report(assur.load(EXAMPLES / "four_bar.toml"), [0.0, 90.0, 180.0])


def _style(page: str) -> str:
    """The page's own style sheet (the first style element), comments left out."""
    css = page.split("<style>")[1].split("</style>")[0]
    return re.sub(r"/\*.*?\*/", "", css, flags=re.S)


def _print_rules(page: str) -> str:
    """The rules inside the style sheet's ``@media print`` block."""
    css = _style(page)
    start = css.index("@media print {") + len("@media print {")
    depth, end = 1, start
    while depth:
        depth += {"{": 1, "}": -1}.get(css[end], 0)
        end += 1
    return css[start : end - 1]


def _rule(css: str, selector: str) -> str:
    """The declarations of every rule whose selector list holds ``selector``."""
    bodies = [
        body
        for selectors, body in re.findall(r"([^{}]+)\{([^{}]*)\}", css)
        if selector in [s.strip() for s in selectors.split(",")]
    ]
    assert bodies, selector
    return " ".join(bodies)


def test_tables_print_whole(four_bar: str) -> None:
    rules = _print_rules(four_bar)
    body = _rule(rules, ".table-wrap")
    assert "max-height: none" in body
    assert "overflow: visible" in body


def test_colour_swatches_print(four_bar: str) -> None:
    body = _rule(_print_rules(four_bar), ".swatch")
    assert "print-color-adjust: exact" in body
    assert "-webkit-print-color-adjust: exact" in body


def test_controls_do_not_print(four_bar: str) -> None:
    body = _rule(_print_rules(four_bar), ".controls")
    assert "display: none" in body
    assert 'class="controls"' in four_bar


def test_display_equations_print_unclipped(four_bar: str) -> None:
    body = _rule(_print_rules(four_bar), '#note math[display="block"]')
    assert "overflow: visible" in body


def test_display_equations_scroll_on_screen(four_bar: str) -> None:
    screen = _style(four_bar).split("@media print")[0]
    body = _rule(screen, '#note math[display="block"]')
    assert "max-width: 100%" in body
    assert "overflow-x: auto" in body
    assert '<math display="block"' in four_bar.split('id="note"')[1]


def test_free_body_pictures_do_not_style_the_page(four_bar: str) -> None:
    bodies = four_bar.split('id="free-bodies"')[1].split("</section>")[0]
    assert bodies.count("<svg") >= 1
    assert "<style" not in bodies
    # matplotlib's defaults kept, on each picture's root only
    roots = re.findall(r"<svg[^>]*>", bodies)
    assert all('stroke-linejoin="round"' in r for r in roots)


def test_long_names_wrap_and_draw_without_warnings() -> None:
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace('"coupler"', f'"{LONG}"').replace(
        "links.coupler", f"links.{LONG}"
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        page = render_report(assur.loads(text), [0.0, 90.0])
    assert f'<p class="formula">I(ground, crank) → II({LONG}, rocker)' in page
    screen = _style(page).split("@media print")[0]
    for selector in (".formula", ".legend li", "#note p"):
        assert "overflow-wrap: anywhere" in _rule(screen, selector)
    # the table of groups keeps its words whole and scrolls in its card instead,
    # in a box around it: a table set display: block is no table to some readers
    assert "overflow-x: auto" in _rule(screen, ".scroll")
    assert '<div class="scroll"><table class="groups">' in page
    assert not re.search(r"table[^{},]*\{[^}]*display: block", _style(page))


def test_without_javascript_the_page_says_what_is_missing(four_bar: str) -> None:
    found = re.findall(r"<noscript>(.*?)</noscript>", four_bar, re.S)
    assert len(found) == 1
    words = " ".join(found[0].split())
    assert "drawing, the slider and “At this position” need JavaScript" in words
    assert "the tables below do not" in words


def test_inertia_loads_follow_the_order_of_the_other_tables() -> None:
    page = render_report(
        assur.load(EXAMPLES / "five_bar_two_cranks.toml"), [[60.0, 120.0]]
    )
    order = ["left_crank", "right_crank", "left_rod", "right_rod"]
    inertia = page.split('id="inertia"')[1].split("</section>")[0]
    assert re.findall(r'data-link="([^"]+)"', inertia) == order
    data = page.split('id="assur-data">')[1].split("</script>")[0]
    # the live table "inertia of": its rows are those with an Fi.x key
    names = re.findall(r'"name": ?"([^"]+)", ?"keys": ?\["[^"]+\.Fi\.x"', data)
    assert names == order


def test_one_spelling_of_each_unit(four_bar: str) -> None:
    assert "N·m" in four_bar
    assert "kg·m²" in four_bar
    text = re.sub(r"<math.*?</math>", "", four_bar, flags=re.S)
    assert not re.search(r"\bN m\b", text)
    assert not re.search(r"\bkg m", text)


def test_the_note_page_prints_its_equations_unclipped() -> None:
    from assur.explain import explain

    page = explain(assur.load(EXAMPLES / "four_bar.toml"), 100.0).to_html()
    assert "overflow: visible" in _rule(_print_rules(page), 'math[display="block"]')
