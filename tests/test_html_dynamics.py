"""The dynamics section of the HTML report: figures, diagrams and their data."""

from __future__ import annotations

import html
import re

import numpy as np
import pytest

import assur
from assur.analysis import default_positions
from assur.dynamics_shown import SHOWN_DELTA
from assur.html import render_report

from .conftest import EXAMPLES
from .test_html import ROUNDING, page_data

SECTION = re.compile(r'<section class="card wide" id="dynamics">(.*?)</section>', re.S)


def section(text: str) -> str | None:
    found = SECTION.findall(text)
    assert len(found) <= 1
    return found[0] if found else None


def test_a_mechanism_that_runs_without_a_flywheel():
    mech = assur.load(EXAMPLES / "four_bar.toml")
    angles = default_positions(mech)[::10]
    text = render_report(mech, angles)
    t = assur.dynamics(mech, angles)
    part = html.unescape(section(text))
    assert "without a flywheel" in part
    assert f"<td>{t.delta:.5g}</td>" in part
    assert f"{t.speed_max:.5g} rad/s at {t.angle_max:.5g}°" in part
    data = page_data(text)
    assert data["dynamics"]["summary"] == t.summary()
    titles = [c["title"] for c in data["dynamics"]["charts"]]
    assert titles == [
        "Reduced inertia J(φ)",
        "Reduced torque of the loads and the motor torque",
        "Crank speed in the steady state",
    ]
    assert [c["unit"] for c in data["dynamics"]["charts"]] == ["kg·m²", "N·m", "rad/s"]
    for key in ("reduced.inertia", "reduced.torque", "driver.motor", "driver.omega"):
        np.testing.assert_allclose(
            data["columns"][key], t[key], rtol=ROUNDING, atol=1e-12
        )
    # the other diagrams are as they were
    assert [c["id"] for c in data["charts"]] == [
        "chart-balancing",
        "chart-reactions",
        "chart-omega",
    ]


def test_a_light_mechanism_gets_the_flywheel_it_needs():
    mech = assur.load(EXAMPLES / "whitworth.toml")
    text = render_report(mech, default_positions(mech)[::30])
    part = html.unescape(section(text))
    assert f"holds δ to {SHOWN_DELTA:g}" in part
    # the reason for the flywheel: not "would stop at its nominal speed", which
    # reads as if the crank stopped while turning at that speed
    assert "without one, the crank would come to rest within a turn" in part
    inertia = assur.flywheel(mech, SHOWN_DELTA)
    assert f"{inertia:.5g} kg·m²" in part
    assert page_data(text)["dynamics"]["summary"]["delta"] == pytest.approx(SHOWN_DELTA)


@pytest.mark.parametrize("name", ["tenbar", "five_bar_two_cranks", "lever_var9"])
def test_no_section_without_masses_or_one_crank(name):
    text = render_report(
        assur.load(EXAMPLES / f"{name}.toml"), [[0.0, 0.0]][:0] or None
    )
    assert section(text) is None
    assert page_data(text)["dynamics"] is None


def test_a_crank_that_cannot_turn_round_is_noted():
    rocker = assur.catalog.four_bar(crank=0.09, coupler=0.06, rocker=0.08)
    text = render_report(rocker)  # the positions that do not assemble are left out
    part = html.unescape(section(text))
    assert (
        "No steady state to show: dynamics: the crank cannot make a full turn" in part
    )
    assert page_data(text)["dynamics"] is None


def test_a_clockwise_crank_s_figures_read_as_the_command_line_s(tmp_path):
    text = (EXAMPLES / "whitworth.toml").read_text(encoding="utf-8")
    assert text.count("omega = 5.0") == 1
    path = tmp_path / "clockwise.toml"
    path.write_text(text.replace("omega = 5.0", "omega = -5.0"), encoding="utf-8")
    mech = assur.load(path)
    angles = default_positions(mech)[::30]
    part = html.unescape(section(render_report(mech, angles)))
    t = assur.dynamics(mech, angles, assur.flywheel(mech, SHOWN_DELTA))
    # the largest and smallest speeds are sizes: the nominal one is one too, turning
    # clockwise, and the mean of the two
    assert t.omega < 0 < t.speed_min
    assert "nominal speed 5 rad/s, clockwise (the mean of the largest" in part
    assert "nominal speed -5" not in part
    # torques are counter-clockwise positive: the motor's sign is told, as the
    # command line tells it
    row = re.search(r'<th scope="row">motor torque</th><td>(.*?)</td>', part)
    assert row is not None
    assert row[1].startswith(f"{t.motor:.5g} N·m (constant, counter-clockwise positive")
    assert "it brakes: the loads drive the crank" in row[1]
    # the file's motor turns the crank the other way: the page says it in the
    # start-up's warning's words, with the page's unit
    assert row[1].endswith(
        "). The file's [motor] drives the start-up alone, but the motor turns the "
        "crank counter-clockwise (torque 40 N·m), against the driver's omega = -5 "
        "rad/s: the start-up runs the other way than every analysis at omega."
    )
    assert "N m" not in row[1]
    # the note above the figures said the motor does "the work the loads take",
    # where the figures say it brakes: the loads give the work it takes
    note = re.search(r'<p class="note">(.*?)</p>', part, re.S)
    assert note is not None
    assert "the work the loads take" not in note[1]
    assert "balances the loads'" in note[1]


def test_a_speed_that_varies_without_work_is_explained():
    # no loads: the report's "energy swing 0 J" stood beside a delta of 0.254
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    angles = default_positions(mech)[::30]
    part = html.unescape(section(render_report(mech, angles)))
    t = assur.dynamics(mech, angles)
    assert t.energy_swing == 0.0 < t.delta
    row = re.search(r'<th scope="row">energy swing</th><td>(.*?)</td>', part)
    assert row is not None
    assert row[1] == (
        "0 J. No load does work: the speed varies with the links' reduced inertia "
        "alone."
    )


def test_the_speed_and_the_swing_are_written_as_the_report_s_figures(tmp_path):
    # five digits, as every figure of the report: the nominal speed and the energy
    # swing were written to the command line's six, beside "5.125 rad/s"
    text = (EXAMPLES / "whitworth.toml").read_text(encoding="utf-8")
    path = tmp_path / "whitworth.toml"
    path.write_text(text.replace("omega = 5.0", "omega = -5.123456"), encoding="utf-8")
    mech = assur.load(path)
    page = render_report(mech, default_positions(mech)[::30])
    part = html.unescape(section(page))
    summary = page_data(page)["dynamics"]["summary"]
    assert f"nominal speed {-summary['omega']:.5g} rad/s, clockwise (" in part
    assert f"<td>{summary['energy_swing']:.5g} J</td>" in part
