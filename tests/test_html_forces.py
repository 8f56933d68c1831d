"""The report's inertia loads and free-body diagrams against the forces table.

Both sections show the report's first position. The inertia table is read back
from the page; the free-body diagrams are inline SVG whose labels matplotlib keeps
as comments (``<!-- $\\vec F_{\\text{2},\\text{3}}$ = 20.6 N -->``), read back the
same way.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.html import render_report

from .test_html import browser  # noqa: F401 (the headless Chromium fixture)

EXAMPLES = Path(__file__).parent.parent / "examples"
ANGLES = [30.0, 75.0, 140.0]


LINK_ROW = r'<tr data-link="([^"]+)"><th scope="row">[^<]*</th>(.*?)</tr>'
"""A row of the inertia table: its link's key and its cells after the link's name."""


def section(page: str, name: str) -> str:
    """The HTML of the section ``id=name``."""
    start = page.index(f'id="{name}"')
    return page[start : page.index("</section>", start)]


def close(printed: str, want: float, digits: int) -> bool:
    """Whether a number printed to ``digits`` significant digits is ``want``."""
    if printed in ("–", "0"):
        return not math.isfinite(want) or abs(want) < 1e-9 * (1 + abs(want))
    got = float(printed)
    return abs(got - want) <= 0.51 * 10 ** (
        math.floor(math.log10(abs(want))) - digits + 1
    )


@pytest.fixture(scope="module", params=["six_bar_lecture", "slider_crank_friction"])
def report(request) -> tuple[str, assur.Table]:
    mech = assur.load(EXAMPLES / f"{request.param}.toml")
    return render_report(mech, ANGLES), assur.forces(mech, ANGLES)


def test_inertia_loads_agree_with_the_table(report) -> None:
    page, table = report
    part = section(page, "inertia")
    assert "(φ = 30.0°)" in part  # the report's first position, with its unit
    rows = re.findall(LINK_ROW, part)
    massive = [link.name for link in table.mechanism.links if link.mass]
    assert [name for name, _ in rows] == massive
    for name, cells in rows:
        values = re.findall(r"<td>([^<]*)</td>", cells)
        link = table.mechanism.link(name)
        fx, fy = float(table[f"{name}.Fi.x"][0]), float(table[f"{name}.Fi.y"][0])
        mi = float(table[f"{name}.Mi"][0])
        a = math.hypot(table[f"{name}.G.ax"][0], table[f"{name}.G.ay"][0])
        size = math.hypot(fx, fy)
        want = [
            link.mass,
            a,
            size,
            math.degrees(math.atan2(fy, fx)),
            link.inertia,
            float(table[f"{name}.alpha"][0]),
            mi,
            abs(mi) / size,
        ]
        assert len(values) == len(want)
        for printed, expected in zip(values, want, strict=True):
            assert close(printed, expected, 5), (name, printed, expected)
        # Fi = m aG, Mi = -JG eps: the table's d'Alembert loads
        np.testing.assert_allclose(size, link.mass * a, rtol=1e-12)
        np.testing.assert_allclose(
            mi, -(link.inertia or 0.0) * table[f"{name}.alpha"][0], atol=1e-12
        )


def test_one_free_body_per_group_with_the_table_s_reactions(report) -> None:
    page, table = report
    part = section(page, "free-bodies")
    plan = table.plan
    figures = re.findall(r'<figure id="free-body-(\d+)">(.*?)</figure>', part, re.S)
    assert [int(i) for i, _ in figures] == list(range(1, len(plan.groups) + 1))
    for index, figure in figures:
        svg = figure[figure.index("<svg") : figure.rindex("</svg>") + 6]
        ET.fromstring(svg)  # well formed
        group = plan.groups[int(index) - 1]
        # a reaction is named by the links it joins (F_{i,j}, link i on link j)
        found = re.findall(
            r"<!-- \$\\vec F_\{\\text\{(\w+)\},\\text\{(\w+)\}\}\$ = (\S+) N -->", svg
        )
        by_links = {}
        for name, pair in plan.pairs.items():
            ends = (plan.bodies[pair.first], plan.bodies[pair.second])
            by_links[ends] = by_links[ends[::-1]] = name.split("~")[0]
        labels = [(by_links[(i, j)], printed) for i, j, printed in found]
        # every pair on its links: the groups solved before it act on it too
        bodies = {plan.body(x) for x in group.links}
        joints = {
            name.split("~")[0]
            for name, pair in plan.pairs.items()
            if {pair.first, pair.second} & bodies and not pair.virtual
        }
        assert {j for j, _ in labels} == joints
        for joint, printed in labels:
            assert close(printed, float(table[f"{joint}.F"][0]), 3), (joint, printed)
        for link in group.links:
            if table.mechanism.link(link).mass:
                fi = math.hypot(table[f"{link}.Fi.x"][0], table[f"{link}.Fi.y"][0])
                tex = re.escape(f"$F_{{i,\\text{{{link}}}}}$")
                label = re.search(rf"<!-- {tex} = (\S+) N -->", svg)
                assert label, link
                assert close(label.group(1), fi, 3)


def test_the_diagrams_keep_the_page_self_contained(report) -> None:
    page, _ = report
    assert re.search(r"https?://", page) is None
    ids = re.findall(r'\bid="([^"]+)"', page)
    assert len(ids) == len(set(ids))  # several diagrams, no id twice
    known = set(ids)
    for target in re.findall(r'url\(#([^)]+)\)|href="#([^"]+)"', page):
        assert (target[0] or target[1]) in known


def test_a_kinematics_report_has_neither_section() -> None:
    page = render_report(assur.load(EXAMPLES / "lever_var9.toml"), [30.0, 60.0])
    assert 'id="inertia"' not in page
    assert 'id="free-bodies"' not in page
    assert "<figure id=" not in page


@pytest.mark.browser
def test_the_diagrams_show_in_a_browser(browser, tmp_path: Path) -> None:  # noqa: F811
    # headless Chromium lays the inline diagrams out, offline (skips without it)
    path = tmp_path / "report.html"
    path.write_text(
        render_report(assur.load(EXAMPLES / "six_bar_lecture.toml"), ANGLES),
        encoding="utf-8",
    )
    browser.get(path.as_uri())
    sizes = browser.execute_script(
        "return Array.from(document.querySelectorAll('#free-bodies svg'))"
        ".map(e => [e.getBoundingClientRect().width, e.getBoundingClientRect().height])"
    )
    assert len(sizes) == 2
    assert all(w > 200 and h > 150 for w, h in sizes)
    # the glyphs are drawn through <use href="#..."> of their own diagram
    used = browser.execute_script(
        "return document.querySelectorAll('#free-body-2 use').length"
    )
    assert used > 20


def test_the_first_position_is_written_with_its_unit() -> None:
    # a slider's position was shown without its unit, "(-0.04)"
    from types import SimpleNamespace

    import numpy as np

    from assur._position_titles import row_position
    from assur.html._sections import first_position

    def table(*kinds: str) -> SimpleNamespace:
        drivers = [
            SimpleNamespace(kind=k, pair=SimpleNamespace(name=n)) for k, n in kinds
        ]
        given = np.array([[30.0, -0.04][: len(kinds)]])
        return SimpleNamespace(plan=SimpleNamespace(drivers=drivers), given=given)

    assert first_position(table(("R", "A"))) == "φ = 30.0°"
    assert row_position(table(("P", "guide")), 0) == "s = 30 m"
    assert (
        row_position(table(("R", "A"), ("P", "E")), 0) == "A: φ = 30.0°, E: s = -0.04 m"
    )


def test_a_prismatic_pair_s_couple_is_shown_with_its_slide() -> None:
    # the slot's couple M was on no part of the page
    from assur.html._data import report_data

    table = assur.forces(
        assur.load(Path(__file__).parent.parent / "examples" / "whitworth.toml"),
        np.arange(0.0, 360.0, 30.0),
    )
    data = report_data(table.plan, assur.structure(table.mechanism), table)
    slides = data["current"]["slides"]
    assert slides["head"][-1] == "M (N·m)"
    assert [row["keys"][-1] for row in slides["rows"]] == ["slot.M", "guide.M"]
    np.testing.assert_allclose(data["columns"]["slot.M"], table["slot.M"], rtol=1e-5)


def test_a_small_link_s_inertia_loads_are_its_own_not_round_off() -> None:
    # a crank of 5.16e-13 kg m^2 (a watch's, say) beside links of 1e-3: its
    # moment of inertia and inertia torque were shown as 0 (an absolute cut-off
    # at 1e-9), its offset h as 5e-8 m beside them
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    small = text.replace("inertia = 5.16e-05", "inertia = 5.16e-13")
    mech = assur.loads(small)
    page = render_report(mech, [0.0, 90.0])
    rows = dict(re.findall(LINK_ROW, page))
    cells = re.findall(r"<td>([^<]*)</td>", rows["crank"])
    # J_G, epsilon (the driver's 10 rad/s^2), M_i = -J_G epsilon
    assert cells[4:7] == ["5.16e-13", "10", "-5.16e-12"]


def _cells(page: str, link: str) -> list[str]:
    rows = dict(re.findall(LINK_ROW, page))
    return re.findall(r"<td>([^<]*)</td>", rows[link])


def test_round_off_is_told_by_the_motion_s_own_scale() -> None:
    # a parallelogram turning steadily: every angular acceleration is round-off
    # (1e-13 rad/s^2), the largest of them too; the motion's own scale (the fastest
    # link's speed squared) tells them 0, and the coupler's torque and offset with
    # them
    mech = assur.catalog.four_bar(crank=0.04, coupler=0.10, rocker=0.04)
    with pytest.warns(assur.AssurWarning, match="change point"):
        page = render_report(mech, [30.0, 60.0])
    assert _cells(page, "coupler")[5:] == ["0", "0", "0"]
    assert _cells(page, "coupler")[:3] == ["0.2", "4", "0.8"]


def test_a_table_s_round_off_is_told_by_the_largest_value_of_its_unit() -> None:
    # at the dead centre the guide carries 2.8e-14 N and the crank 1.2e-14 N m,
    # round-off beside the 443 N and 84.6 N m at 45 deg: 0 in the page's tables
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    page = render_report(mech, [180.0, 45.0])
    part = section(page, "table")
    keys = re.findall(r'<th scope="col" data-key="([^"]+)">', part)
    row = part.split('data-row="0">')[1].split("</tr>")[0]
    first = re.findall(r"<t[hd][^>]*>([^<]*)</t[hd]>", row)
    shown = dict(zip(keys, first, strict=False))
    assert shown["guide.F"] == "0"
    assert shown["driver.torque"] == "0"
    # and a summary's mean torque of a turn that does no net work: 1.5e-16 N m
    page = render_report(assur.load(EXAMPLES / "class3.toml"))
    mean = re.search(
        r'data-key="driver.torque.mean"><th scope="row">[^<]*</th><td>([^<]*)', page
    )
    assert mean is not None
    assert mean[1] == "0"


def test_the_largest_value_of_a_column_is_its_largest_finite_one() -> None:
    from assur._digits import largest
    from assur.html._sections import number

    assert largest([1.0, math.inf, math.nan, -3.0]) == 3.0
    assert largest([]) == 0.0
    # an infinite value does not make every other of its unit 0
    assert number(1e-3, largest([1.0, math.inf])) == "0.001"
