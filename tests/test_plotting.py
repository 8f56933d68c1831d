"""Pictures of mechanisms and diagrams (assur.plotting), drawn on the Agg backend.

No image baselines: the tests check the artists drawn (counts, data, legend texts),
that the numbers in the pictures are the table's, that a free-body diagram is in
equilibrium, and that the files written are valid.
"""

from __future__ import annotations

import itertools
import subprocess
import sys
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur import plotting
from assur.analysis import default_positions
from assur.errors import UsageError
from assur.plan import compile_plan

from .conftest import load_example as _load
from .test_imports import names_imported

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Circle, FancyArrowPatch

EXAMPLES = Path(__file__).parent.parent / "examples"
SWEEP = np.arange(0.0, 360.0, 10.0)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def _reaction(table: assur.Table, joint: str, sign: float = 1.0) -> str:
    """The pictures' name of joint ``joint``'s reaction: on its second link (sign 1)."""
    from assur.plotting._mathtext import reaction_symbol

    plan = table.plan
    pair = plan.pairs[joint]
    by, on = plan.bodies[pair.first], plan.bodies[pair.second]
    return reaction_symbol(by, on) if sign > 0 else reaction_symbol(on, by)


def _couple(table: assur.Table, joint: str) -> str:
    """The pictures' name of a sliding joint's reaction couple on its second link."""
    from assur.plotting._mathtext import couple_symbol

    pair = table.plan.pairs[joint]
    return couple_symbol(table.plan.bodies[pair.first], table.plan.bodies[pair.second])


@pytest.fixture(scope="module")
def slider_crank() -> assur.Table:
    mech = _load("slider_crank_exercise")
    return assur.forces(mech, default_positions(mech)[::10])


@pytest.fixture(scope="module")
def tenbar() -> assur.Table:
    return assur.kinematics(_load("tenbar"), SWEEP)


@pytest.fixture(scope="module")
def slot() -> assur.Table:
    mech = _load("slot_mechanism")
    return assur.forces(mech, default_positions(mech)[::10])


@pytest.fixture(scope="module")
def five_bar() -> assur.Table:
    mech = _load("five_bar_two_cranks")
    return assur.forces(mech, default_positions(mech)[::15])


@pytest.fixture(scope="module")
def six_bar() -> assur.Table:
    mech = _load("six_bar_lecture")
    return assur.forces(mech, default_positions(mech)[::10])


def _revolute_pairs(table: assur.Table) -> int:
    return sum(p.kind == "R" for p in compile_plan(table.mechanism).pairs.values())


def _legend_texts(ax) -> list[str]:
    legend = ax.get_legend()
    return [t.get_text() for t in legend.get_texts()] if legend else []


# ------------------------------------------------------------------------ draw


def test_draw_every_example(example: assur.Mechanism) -> None:
    table = assur.kinematics(example, default_positions(example)[:2])
    ax = plotting.draw(table)
    circles = [p for p in ax.patches if isinstance(p, Circle)]
    # one circle per revolute pair (a slot's pin included), none for anything else
    assert len(circles) == _revolute_pairs(table)
    plan = compile_plan(example)
    assert len(_legend_texts(ax)) == len(plan.drivers) + len(plan.groups)
    assert ax.get_aspect() == 1.0
    assert ax.get_xlabel() == "x [m]"


def test_draw_names_groups_by_class_order_and_kind(tenbar: assur.Table) -> None:
    ax = plotting.draw(tenbar, angle=51.0)
    texts = _legend_texts(ax)
    assert texts[0] == "I, driver (ground, 1)"
    assert "II, order 2, RRR (2, 3)" in texts
    assert "II, order 2, RRP (6, 7)" in texts
    labels = {t.get_text() for t in ax.texts}
    assert {"A", "B", "H", "K", "1", "2", "9"} <= labels
    assert "50.0°" in ax.get_title()
    # each group has its own colour, the driver another one
    colors = [h.get_color() for h in ax.get_legend().legend_handles]
    assert len(set(colors)) == len(colors)


def test_draw_joint_circles_sit_on_the_joints(tenbar: assur.Table) -> None:
    row = 4
    ax = plotting.draw(tenbar, angle=float(tenbar["angle"][row]))
    centres = np.array([p.center for p in ax.patches if isinstance(p, Circle)])
    for joint in ("A", "B", "C", "K", "M"):
        where = np.array([tenbar[f"{joint}.x"][row], tenbar[f"{joint}.y"][row]])
        assert np.min(np.hypot(*(centres - where).T)) < 1e-12


def test_draw_limits_hold_the_whole_mechanism(tenbar: assur.Table) -> None:
    ax = plotting.draw(tenbar, angle=120.0)
    row = int(np.argmin(np.abs(tenbar["angle"] - 120.0)))
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    for joint in ("A", "B", "C", "D", "E", "F", "G", "H", "K", "L", "M", "S"):
        assert x0 < tenbar[f"{joint}.x"][row] < x1
        assert y0 < tenbar[f"{joint}.y"][row] < y1


def test_draw_without_labels_or_groups(tenbar: assur.Table) -> None:
    ax = plotting.draw(tenbar, labels=False, groups=False)
    assert len(ax.texts) == 0
    assert ax.get_legend() is None


def test_draw_slider_and_slot(slot: assur.Table) -> None:
    ax = plotting.draw(slot)
    polygons = [p for p in ax.patches if type(p).__name__ == "Polygon"]
    # the ram's block, the slot's outline and the frame's triangles (O2, O4)
    assert len(polygons) >= 4
    assert "B" in {t.get_text() for t in ax.texts}
    assert not any("~" in t.get_text() for t in ax.texts)


def test_draw_on_given_axes_returns_them(tenbar: assur.Table) -> None:
    fig, ax = plt.subplots()
    assert plotting.draw(tenbar, ax=ax) is ax
    assert len(fig.axes) == 1


def test_nearest_row_compares_angles_modulo_a_turn(tenbar: assur.Table) -> None:
    assert plotting._row(tenbar, None) == 0
    assert plotting._row(tenbar, 42.0) == 4
    assert plotting._row(tenbar, 400.0) == 4
    assert plotting._row(tenbar, -10.0) == 35


def test_nearest_row_with_two_drivers(five_bar: assur.Table) -> None:
    row = 3
    want = np.degrees(five_bar.state.drive[row])
    assert plotting._row(five_bar, want.tolist()) == row
    with pytest.raises(assur.UsageError, match="3 values for 2 driver"):
        plotting._row(five_bar, [1.0, 2.0, 3.0])


def test_titles_word_the_driver_positions(five_bar: assur.Table) -> None:
    from assur._position_titles import position_title

    a, e = five_bar.given[1]
    title = f"A: φ = {a:.1f}°, E: φ = {e:.1f}°"
    assert position_title(["deg", "deg"], [a, e], ["A", "E"]) == title
    assert plotting.draw(five_bar, angle=[a, e]).get_title().endswith(title)
    fig = plotting.draw_decomposition(five_bar, angle=[a, e])
    assert fig.get_suptitle().endswith(title)
    # a table of a few columns still names each driver's position
    plan = five_bar.plan
    points = [f"{p}.{c}" for p in plan.points for c in "xy"]
    few = assur.kinematics(five_bar.mechanism, [[a, e]], columns=points)
    assert "A.drive" not in few
    assert plotting.draw(few).get_title().endswith(title)


def test_table_plot_forwards_to_draw(slider_crank: assur.Table) -> None:
    ax = slider_crank.plot(96.0, forces=True, labels=False)
    assert "95.0°" in ax.get_title()
    assert any(isinstance(p, FancyArrowPatch) for p in ax.patches)


# ---------------------------------------------------------------------- forces


def test_draw_forces_arrows_and_scale(slider_crank: assur.Table) -> None:
    ax = plotting.draw(slider_crank, angle=45.0, forces=True, scale=500.0)
    arrows = [p for p in ax.patches if isinstance(p, FancyArrowPatch)]
    plan = compile_plan(slider_crank.mechanism)
    # a reaction per joint, a balancing torque, inertia force and torque of the rod
    assert len(arrows) >= len(plan.pairs) + 3
    assert "force scale: 1 cm on the axes = 500 N" in _legend_texts(ax)


def test_a_force_scale_that_draws_the_forces_far_too_long_is_refused(
    slider_crank: assur.Table,
) -> None:
    # the mechanism a dot, and the picture's numbers overflowing at 1e-300
    with pytest.raises(UsageError, match=r"^scale: 1e-300 draws the largest force"):
        plotting.draw(slider_crank, angle=45.0, forces=True, scale=1e-300)
    with pytest.raises(UsageError, match=r"expected a force scale of at least"):
        plotting.draw_free_body(slider_crank, 0, angle=45.0, scale=1e-300)
    plt.close("all")
    # a thousand times the automatic length (1000 N per cm) is still drawn
    ax = plotting.draw(slider_crank, angle=45.0, forces=True, scale=1.0)
    assert "force scale: 1 cm on the axes = 1 N" in _legend_texts(ax)


def test_force_arrows_carry_the_table_values(slider_crank: assur.Table) -> None:
    row = 5
    ctx = plotting._context(slider_crank)
    arrows = plotting._overview_arrows(ctx, ctx.pose(row), row)
    reactions = {a.label: a for a in arrows if a.kind == "reaction"}
    a = reactions[_reaction(slider_crank, "A")]
    np.testing.assert_allclose(
        a.force, [slider_crank["A.Fx"][row], slider_crank["A.Fy"][row]], rtol=1e-12
    )
    np.testing.assert_allclose(a.point, [0.0, 0.0], atol=1e-12)
    (torque,) = [a for a in arrows if a.kind == "balancing"]
    assert torque.couple == pytest.approx(slider_crank["driver.torque"][row], rel=1e-12)


def test_default_force_scale_is_round_and_fits(slider_crank: assur.Table) -> None:
    row = 0
    ctx = plotting._context(slider_crank)
    arrows = plotting._overview_arrows(ctx, ctx.pose(row), row)
    scale = plotting._scale(arrows, ctx.size)
    mantissa = scale / 10 ** np.floor(np.log10(scale))
    assert min(abs(mantissa - m) for m in (1.0, 2.0, 5.0)) < 1e-9
    longest = max(np.hypot(*a.force) for a in arrows if a.force is not None)
    length = longest / (scale * 100.0)  # m of drawing
    assert plotting.ARROW_LENGTH * ctx.size / 2.5 <= length
    assert length <= plotting.ARROW_LENGTH * ctx.size * (1 + 1e-9)


@pytest.mark.parametrize(
    "stem", ["whitworth", "five_bar_two_cranks", "scotch_yoke", "class3"]
)
def test_overview_draws_the_applied_loads(stem: str) -> None:
    # the loads drawn on the links, with the reactions of the frame, balance: the
    # external forces and the weights are drawn too, in the legend's load colour
    from assur.plotting._style import LOAD_COLOR

    mech = _load(stem)
    table = assur.forces(mech, default_positions(mech)[::30])
    plan = compile_plan(mech)
    ctx = plotting._context(table)
    pairs = {
        _reaction(table, name): p for name, p in plan.pairs.items() if not p.virtual
    }
    weights = sum(bool(x.mass) for x in mech.links) if mech.gravity else 0
    forces = sum(load.force is not None for load in mech.loads)
    couples = sum(load.torque is not None for load in mech.loads)
    for row in range(len(table)):
        arrows = plotting._overview_arrows(ctx, ctx.pose(row), row)
        applied = [a for a in arrows if a.kind in ("gravity", "load")]
        assert sum(a.force is not None for a in applied) == weights + forces
        assert sum(a.couple is not None for a in applied) == couples
        total, largest = np.zeros(2), 0.0
        for a in arrows:
            if a.force is None:
                continue
            sign = 1.0
            if a.kind == "reaction":
                pair = pairs[a.label]
                if 0 not in (pair.first, pair.second):
                    continue  # between two moving links: drawn on one of them only
                sign = 1.0 if pair.first == 0 else -1.0
            total += sign * np.asarray(a.force)
            largest = max(largest, float(np.hypot(*a.force)))
        assert np.hypot(*total) <= 1e-9 * largest
    row = 1
    ax = plotting.draw(table, angle=float(table["angle"][row]), forces=True)
    assert "gravity, external load" in _legend_texts(ax)
    arrows = plotting._overview_arrows(ctx, ctx.pose(row), row)
    nonzero = sum(
        bool(np.any(a.force)) if a.force is not None else bool(a.couple)
        for a in arrows
        if a.kind in ("gravity", "load")
    )
    drawn = [
        p
        for p in ax.patches
        if isinstance(p, FancyArrowPatch)
        and matplotlib.colors.same_color(p.get_edgecolor(), LOAD_COLOR)
    ]
    assert len(drawn) == nonzero > 0


def _arrow_lengths(ax) -> list[tuple[float, float]]:
    """Return each arrow's length on the page and its head's length, points."""
    ax.figure.canvas.draw()
    points = ax.figure.dpi / 72.0
    lengths = []
    for p in ax.patches:
        if not isinstance(p, FancyArrowPatch):
            continue
        # matplotlib keeps the arrow's ends (or its path) as given, data coordinates
        ends = p._posA_posB if p._posA_posB is not None else p._path_original.vertices
        page = p.get_transform().transform(np.asarray(ends, dtype=float))
        length = float(np.sum(np.hypot(*np.diff(page, axis=0).T))) / points
        lengths.append((length, 0.4 * p.get_mutation_scale()))  # "-|>" head length
    return lengths


def test_a_short_arrow_has_a_head_shorter_than_itself(six_bar) -> None:
    # R_B of the exercise at 60 deg is a few points long: its head shrinks with it
    table = assur.forces(_load("slider_crank_exercise"), [60.0])
    overview = _arrow_lengths(plotting.draw(table, forces=True))
    assert min(length for length, _ in overview) < 10.0  # short ones are there
    for lengths in (
        overview,
        _arrow_lengths(plotting.draw_free_body(table, 0)),
        _arrow_lengths(plotting.draw_free_body(six_bar, 0, angle=60.0)),
    ):
        assert len(lengths) >= 5
        for length, head in lengths:
            assert head <= 0.4 * length * (1 + 1e-9)
            assert head <= 0.4 * 13  # the long ones keep their heads


def test_nice_numbers() -> None:
    assert [plotting._nice(x) for x in (0.7, 1.0, 1.2, 3.0, 7.0, 1234.0)] == [
        1.0,
        1.0,
        2.0,
        5.0,
        10.0,
        2000.0,
    ]
    assert plotting._nice(0.0) == 1.0


def test_draw_forces_needs_a_forces_table(tenbar: assur.Table) -> None:
    with pytest.raises(assur.UsageError, match="needs a forces table"):
        plotting.draw(tenbar, forces=True)


def test_animation_scale_covers_two_drivers(five_bar: assur.Table) -> None:
    ax = plotting.draw(five_bar, forces=True)
    labels = [t.get_text() for t in ax.texts]
    assert any("M_{b,\\text{A}}" in t for t in labels)
    assert any("M_{b,\\text{E}}" in t for t in labels)


# ---------------------------------------------------- decomposition, free body


def test_decomposition_has_a_panel_per_step(tenbar: assur.Table) -> None:
    fig = plotting.draw_decomposition(tenbar, angle=30.0)
    panels = [ax for ax in fig.axes if ax.axison]
    assert len(panels) == 5
    assert panels[0].get_title().startswith("1. I: driver (ground, 1)")
    assert panels[1].get_title().startswith("2. II, order 2, RRR (2, 3)")
    assert "hangs on: 6, 7" in panels[4].get_title()
    assert "I(ground, 1) -> II(2, 3)" in fig.get_suptitle()
    # the first panel draws only the crank's pivots; the group panels theirs
    assert sum(isinstance(p, Circle) for p in panels[0].patches) == 2


def test_decomposition_with_two_drivers_and_a_slot(
    five_bar: assur.Table, slot: assur.Table
) -> None:
    assert (
        len([ax for ax in plotting.draw_decomposition(five_bar).axes if ax.axison]) == 3
    )
    titles = [ax.get_title() for ax in plotting.draw_decomposition(slot).axes]
    assert any("RPR (rocker, B (block))" in t for t in titles)


@pytest.mark.parametrize(
    "name",
    [
        "slider_crank_exercise",
        "six_bar_lecture",
        "slot_mechanism",
        "class3",
        "whitworth",
        "scotch_yoke",
    ],
)
def test_free_body_is_in_equilibrium(name: str) -> None:
    mech = _load(name)
    table = assur.forces(mech, default_positions(mech)[::45])
    for group in range(len(compile_plan(mech).groups)):
        for row in range(len(table)):
            # every arrow drawn: an internal pair's two cancel
            arrows = plotting._free_body_arrows(table, group, row)
            forces = np.array([a.force for a in arrows if a.force is not None])
            moments = [
                a.point[0] * a.force[1] - a.point[1] * a.force[0]
                for a in arrows
                if a.force is not None
            ]
            moments += [a.couple for a in arrows if a.couple is not None]
            big = np.max(np.abs(forces))
            np.testing.assert_allclose(forces.sum(axis=0), 0.0, atol=1e-9 * big)
            assert abs(sum(moments)) < 1e-9 * big * compile_plan(mech).scale


def test_free_body_labels_values(six_bar: assur.Table) -> None:
    ax = plotting.draw_free_body(six_bar, 0, angle=60.0)
    texts = [t.get_text() for t in ax.texts]
    row = plotting._row(six_bar, 60.0)
    value = f"{six_bar['B.F'][row]:.3g} N"
    # B joins the group to the links solved before: its force on the group
    plan = six_bar.plan
    group = {plan.body(x) for x in plan.groups[0].links}
    on_group = _reaction(six_bar, "B", 1.0 if plan.pairs["B"].second in group else -1)
    assert any(t.startswith(on_group) and t.endswith(value) for t in texts)
    internal = _reaction(six_bar, "C")  # the internal pair C: by first on second
    assert any(t.startswith(internal) for t in texts)
    assert any(t.startswith("$m_") and " g" in t for t in texts)  # gravity is on
    assert "RRR (3, 4)" in ax.get_title()
    # cut free: no bearing triangles of the frame
    assert not any(
        type(p).__name__ == "Polygon"
        and len(p.get_xy()) == 4
        and p.get_facecolor()[:3] == (1.0, 1.0, 1.0)
        for p in ax.patches
    )


def test_free_body_without_labels_names_nothing(six_bar: assur.Table) -> None:
    # labels=False was missing: the free body named its joints, links and loads
    ax = plotting.draw_free_body(six_bar, 0, angle=60.0, labels=False)
    assert not [t for t in ax.texts if t.get_visible() and t.get_text()]
    assert any(type(p).__name__ == "FittedArrow" for p in ax.patches)


def test_free_body_title_numbers_the_group_as_the_command_line() -> None:
    # group 1 of the Whitworth mechanism is an RPR dyad of class II: the title names
    # it "group 1", the class in words, not "group II"
    table = assur.forces(_load("whitworth"), [200.0])
    first, second = (plotting.draw_free_body(table, k) for k in (0, 1))
    assert first.get_title().startswith(
        "Free body of group 1 (class II, order 2, RPR (block, lever))\n"
    )
    assert second.get_title().startswith("Free body of group 2 (class II, order 2, ")
    assert "group II" not in first.get_title()


def test_free_body_couple_of_a_guide_in_newton_metres() -> None:
    # the yoke's guide is short: its reaction is drawn as a couple (and a force,
    # here none), each value with its own unit
    table = assur.forces(_load("scotch_yoke"), [210.0])
    arrows = plotting._free_body_arrows(table, 0, 0)
    (guide,) = [a for a in arrows if a.label == _reaction(table, "guide")]
    assert guide.couple == pytest.approx(table["guide.M"][0], rel=1e-12)
    assert guide.units == ("N", "N·m")
    # named as a couple: the force's name over N m read as a force
    assert guide.couple_label == _couple(table, "guide")
    ax = plotting.draw_free_body(table, 0)
    (text,) = [
        t.get_text() for t in ax.texts if t.get_text().startswith(guide.couple_label)
    ]
    assert text == f"{guide.couple_label} = {guide.couple:.3g} N·m"


def test_a_guide_s_couple_drawn_apart_is_named_as_a_couple() -> None:
    # the crank shaper's cut, 0.1 m below the ram's guide, loads the guide with a
    # couple of 200 N m; its normal force would act 1 m away, so the couple is drawn
    # as an arc at the ram: it bore the force's name, twice beside the ram
    path = Path(__file__).parent / "data" / "explain" / "crank_shaper.toml"
    table = assur.forces(assur.load(path), [100.0])
    ax = plotting.draw(table, forces=True)
    texts = [t.get_text() for t in ax.texts if t.get_visible()]
    assert texts.count(_reaction(table, "guide")) == 1
    assert texts.count(_couple(table, "guide")) == 1
    assert abs(table["guide.M"][0]) > 0.0


def test_free_body_errors(six_bar: assur.Table, tenbar: assur.Table) -> None:
    with pytest.raises(
        assur.UsageError,
        match="group_index: 2 is out of range; the mechanism has 2 Assur group",
    ):
        plotting.draw_free_body(six_bar, 2)
    with pytest.raises(assur.UsageError, match="needs a forces table"):
        plotting.draw_free_body(tenbar, 0)


# ---------------------------------------------------------------- sweeps


def test_plot_motion_lines_are_the_columns(tenbar: assur.Table) -> None:
    ax = plotting.plot_motion(tenbar, ["2", "3"], "omega")
    assert [ln.get_label() for ln in ax.lines] == ["2", "3"]
    np.testing.assert_array_equal(ax.lines[1].get_ydata(), tenbar["3.omega"])
    np.testing.assert_array_equal(ax.lines[1].get_xdata(), tenbar["angle"])
    assert ax.get_ylabel() == "omega [rad/s]"
    # same group, same colour, another dash
    assert ax.lines[0].get_color() == ax.lines[1].get_color()
    assert ax.lines[0].get_linestyle() != ax.lines[1].get_linestyle()


def test_plot_motion_defaults_and_points(tenbar: assur.Table) -> None:
    ax = plotting.plot_motion(tenbar, quantity="alpha")
    # every link but the slider 7, which does not turn
    assert [ln.get_label() for ln in ax.lines] == [
        "1",
        "2",
        "3",
        "4",
        "5",
        "6",
        "8",
        "9",
    ]
    ax = plotting.plot_motion(tenbar, ["K", "M"], "v")
    assert len(ax.lines) == 4
    np.testing.assert_array_equal(ax.lines[3].get_ydata(), tenbar["M.vy"])
    assert ax.get_ylabel() == "v [m/s]"
    ax = plotting.plot_motion(tenbar, "guide", "s")
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), tenbar["guide.s"])


def test_plot_motion_unknown_quantity(tenbar: assur.Table) -> None:
    with pytest.raises(
        assur.UnknownNameError,
        match="no quantity 'speed' for '2'; expected alpha, angle, jerk or omega",
    ):
        plotting.plot_motion(tenbar, ["2"], "speed")


def test_plot_paths(tenbar: assur.Table) -> None:
    ax = plotting.plot_paths(tenbar)
    paths = {
        ln.get_label(): ln for ln in ax.lines if not ln.get_label().startswith("_")
    }
    # every moving joint once: the pivots A, D, G stay put, the guide runs with S
    assert set(paths) == {"B", "C", "E", "F", "H", "K", "L", "S", "M"}
    np.testing.assert_array_equal(paths["H"].get_xdata(), tenbar["H.x"])
    with pytest.raises(assur.UnknownNameError, match="no point 'Z'"):
        plotting.plot_paths(tenbar, ["Z"])


def test_plot_torque(slider_crank: assur.Table) -> None:
    ax = plotting.plot_torque(slider_crank)
    torque, check = ax.lines[0], ax.lines[1]
    np.testing.assert_array_equal(torque.get_ydata(), slider_crank["driver.torque"])
    np.testing.assert_allclose(
        check.get_ydata(),
        slider_crank["driver.torque_check"][:: max(1, len(slider_crank) // 36)],
        rtol=1e-12,
    )
    assert "balancing torque (equilibrium)" in _legend_texts(ax)
    assert ax.get_ylabel() == "balancing load [N·m]"


def test_a_sweep_of_many_turns_keeps_few_ticks() -> None:
    # ticked every 90 deg, 100 turns drew 401 labels on top of one another (and
    # 1000 turns took minutes in assur diagrams); a span of 1e20 deg failed
    mech = _load("four_bar")
    for angles, most in ((np.arange(0.0, 36001.0, 30.0), 12), ([0.0, 1e19, 1e20], 12)):
        ax = plotting.plot_torque(assur.forces(mech, angles))
        ax.figure.canvas.draw()
        assert 2 <= len(ax.get_xticks()) <= most
    ax = plotting.plot_torque(assur.forces(mech, np.arange(0.0, 361.0, 10.0)))
    # one turn keeps its eighth turns
    assert set(np.arange(0.0, 361.0, 45.0)) <= set(ax.get_xticks())


def test_plot_torque_two_drivers(five_bar: assur.Table) -> None:
    ax = plotting.plot_torque(five_bar)
    np.testing.assert_array_equal(ax.lines[3].get_ydata(), five_bar["E.torque"])


def test_plot_hodographs(slot: assur.Table) -> None:
    fig = plotting.plot_hodographs(slot)
    panels = [ax for ax in fig.axes if ax.axison]
    plan = compile_plan(slot.mechanism)
    assert len(panels) == sum(not p.virtual for p in plan.pairs.values())
    titles = [ax.get_title() for ax in panels]
    assert any(t.startswith("B: rocker on crank (pin)") for t in titles)
    o4 = panels[[t.split(":")[0] for t in titles].index("O4")]
    np.testing.assert_array_equal(o4.lines[0].get_xdata(), slot["O4.Fx"])
    np.testing.assert_array_equal(o4.lines[0].get_ydata(), slot["O4.Fy"])
    fig = plotting.plot_hodographs(slot, ["E"])
    assert len([ax for ax in fig.axes if ax.axison]) == 1
    with pytest.raises(assur.UnknownNameError, match="no joint 'B~pin'"):
        plotting.plot_hodographs(slot, ["B~pin"])


def test_a_hodograph_s_tick_labels_are_apart() -> None:
    # a student's crank-rocker: the first panel's Fx ticks ran together,
    # "-2500-2000-1500-1000-500", a point apart; a gap of 4 points reads
    mech = assur.load(Path(__file__).parent / "data" / "plans" / "crank_rocker.toml")
    fig = plotting.plot_hodographs(assur.forces(mech, default_positions(mech)))
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    gap = 4.0 * fig.dpi / 72.0
    for ax in (a for a in fig.axes if a.axison):
        for axis, (low, high) in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            boxes = [
                label.get_window_extent(renderer).extents
                for tick, label in zip(
                    axis.get_majorticklocs(), axis.get_ticklabels(), strict=True
                )
                if label.get_visible() and label.get_text() and low <= tick <= high
            ]
            assert len(boxes) >= 2
            for a, b in itertools.pairwise(boxes):
                apart = max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3])
                assert apart > gap, (ax.get_title(), axis.axis_name)


def test_plot_shaking(six_bar: assur.Table) -> None:
    fig = plotting.plot_shaking(six_bar)
    polar, force, moment = fig.axes
    np.testing.assert_array_equal(polar.lines[0].get_ydata(), six_bar["shaking.Fy"])
    np.testing.assert_array_equal(force.lines[0].get_ydata(), six_bar["shaking.Fx"])
    np.testing.assert_array_equal(moment.lines[0].get_ydata(), six_bar["shaking.M"])


@pytest.fixture(scope="module")
def locked_triad() -> assur.Table:
    """A crank whose triad cannot be assembled from 87 to 281 deg: left out."""
    mech = assur.load(
        Path(__file__).parent / "data" / "edge" / "triad_locks_ahead.toml"
    )
    return assur.forces(mech, np.arange(0.0, 360.0, 1.0), skip_unassembled=True)


def _broken_at(drawn: np.ndarray, want: np.ndarray, row: int) -> None:
    """``drawn`` is ``want`` with one NaN (a break in the line) before ``row``."""
    drawn = np.asarray(drawn, dtype=float)
    assert np.flatnonzero(np.isnan(drawn)).tolist() == [row]
    np.testing.assert_array_equal(np.delete(drawn, row), want)


def test_sweep_diagrams_break_where_positions_were_left_out(
    locked_triad: assur.Table,
) -> None:
    # one straight line ran from 86 to 282 deg, as if there were data in between
    t = locked_triad
    row = 87
    assert t["angle"][row - 1 : row + 1].tolist() == [86.0, 282.0]
    ax = plotting.plot_motion(t, ["rod"], "omega")
    _broken_at(ax.lines[0].get_xdata(), t["angle"], row)
    _broken_at(ax.lines[0].get_ydata(), t["rod.omega"], row)
    ax = plotting.plot_motion(t, ["C"], "v")
    for line, part in zip(ax.lines, ("vx", "vy"), strict=True):
        _broken_at(line.get_ydata(), t[f"C.{part}"], row)
    ax = plotting.plot_paths(t, ["C"])
    (path,) = (ln for ln in ax.lines if ln.get_label() == "C")
    _broken_at(path.get_xdata(), t["C.x"], row)
    _broken_at(path.get_ydata(), t["C.y"], row)
    ax = plotting.plot_torque(t)
    _broken_at(ax.lines[0].get_xdata(), t["angle"], row)
    _broken_at(ax.lines[0].get_ydata(), t["driver.torque"], row)
    (panel,) = (a for a in plotting.plot_hodographs(t, ["C"]).axes if a.axison)
    _broken_at(panel.lines[0].get_xdata(), t["C.Fx"], row)
    _broken_at(panel.lines[0].get_ydata(), t["C.Fy"], row)
    polar, force, moment = plotting.plot_shaking(t).axes
    _broken_at(polar.lines[0].get_ydata(), t["shaking.Fy"], row)
    _broken_at(force.lines[0].get_xdata(), t["angle"], row)
    _broken_at(force.lines[1].get_ydata(), t["shaking.Fy"], row)
    _broken_at(moment.lines[0].get_ydata(), t["shaking.M"], row)


@pytest.mark.parametrize(
    "function", [plotting.plot_torque, plotting.plot_hodographs, plotting.plot_shaking]
)
def test_sweep_force_diagrams_need_forces(function, tenbar: assur.Table) -> None:
    with pytest.raises(assur.UsageError, match="needs a forces table"):
        function(tenbar)


# ------------------------------------------------------------------ animation


@pytest.mark.pictures
def test_animate_writes_a_gif(tmp_path: Path, slot: assur.Table) -> None:
    from PIL import Image

    small = assur.forces(slot.mechanism, [30.0, 120.0, 210.0])
    before = plt.get_fignums()
    path = tmp_path / "slot.gif"
    assert plotting.animate(small, path, forces=True, fps=10) == 3
    assert plt.get_fignums() == before
    with Image.open(path) as gif:
        assert gif.format == "GIF"
        assert gif.n_frames == 3
        assert gif.size[0] > 300


def test_animate_needs_forces_for_arrows(tmp_path: Path, tenbar: assur.Table) -> None:
    with pytest.raises(assur.UsageError, match="needs a forces table"):
        plotting.animate(tenbar, tmp_path / "x.gif", forces=True)
    assert not (tmp_path / "x.gif").exists()


def test_animate_holds_the_command_s_bounds(tmp_path: Path) -> None:
    # from Python a film of 10 000 rows at 300 dpi (205 GB of frames) and one at
    # 100 fps (played at 10 in browsers) were begun
    mech = assur.catalog.slider_crank()
    path = tmp_path / "x.gif"
    table = assur.kinematics(mech, [0.0, 90.0])
    with pytest.raises(assur.UsageError, match=r"fps: 100; expected at most 50 \("):
        plotting.animate(table, path, fps=100)
    many = assur.kinematics(mech, np.linspace(0.0, 360.0, 10_000))
    with pytest.raises(
        assur.UsageError, match=r"table: 10000 frames of up to 20.5 MB, 205 GB in all"
    ):
        plotting.animate(many, path, dpi=300)
    assert not path.exists()


# ------------------------------------------- the pictures and the report agree


def _report_data(mech: assur.Mechanism, positions) -> dict:
    """The JSON data embedded in the report of ``mech`` at ``positions``."""
    import json
    import re

    from assur.html import render_report

    page = render_report(mech, positions)
    block = re.search(r'id="assur-data">(.*?)</script>', page, re.S)
    assert block is not None
    return json.loads(block.group(1))


def _link_label_colours(ax) -> dict[str, str]:
    """Each link's name on a drawing, with the colour of its frame."""
    from matplotlib.colors import to_hex

    out = {}
    for text in ax.texts:
        box = text.get_bbox_patch()
        # the link names sit in boxes framed in the link's colour; joints have none
        if box is not None and box.get_edgecolor()[3] > 0:
            out[text.get_text()] = to_hex(box.get_edgecolor())
    return out


def test_links_have_the_report_colours(example: assur.Mechanism) -> None:
    from matplotlib.colors import to_hex

    positions = default_positions(example)[:2]
    data = _report_data(example, positions)
    ax = plotting.draw(assur.kinematics(example, positions))
    assert _link_label_colours(ax) == {x["name"]: x["colour"] for x in data["links"]}
    # the legend: the drivers, then the groups, in the report's order and colours
    handles = ax.get_legend().legend_handles
    assert [to_hex(h.get_color()) for h in handles] == [
        g["colour"] for g in data["groups"]
    ]


def test_one_colour_for_every_driver(five_bar: assur.Table) -> None:
    from matplotlib.colors import to_hex

    from assur._style import DRIVER_COLOUR, GROUP_COLOURS

    ax = plotting.draw(five_bar)
    colours = _link_label_colours(ax)
    drivers = [five_bar.plan.bodies[d.body] for d in five_bar.plan.drivers]
    assert len(drivers) == 2
    assert {colours[x] for x in drivers} == {DRIVER_COLOUR}
    handles = ax.get_legend().legend_handles
    assert [to_hex(h.get_color()) for h in handles[:3]] == [
        DRIVER_COLOUR,
        DRIVER_COLOUR,
        GROUP_COLOURS[0],
    ]
    assert DRIVER_COLOUR not in GROUP_COLOURS
    assert len(set(GROUP_COLOURS)) == len(GROUP_COLOURS)


# ------------------------------------------------------ what pictures read


def test_decomposition_title_is_the_structure_s(example: assur.Mechanism) -> None:
    from assur.plan import plan_of
    from assur.plotting.decomposition import _structure

    assert _structure(plan_of(example)) == assur.structure(example)


RECOMPILERS = (
    ("assur.plan", "compile_plan"),
    ("assur.plan", "plan_of"),
    ("assur._structure", "decompose"),
    ("assur._structure", "structure"),
)
"""What builds a plan or a decomposition from a mechanism."""


def test_pictures_read_only_the_table(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    import importlib

    table = assur.forces(_load("slot_mechanism"), [30.0, 150.0, 270.0])
    for module, name in RECOMPILERS:

        def refuse(*args, _name=name, **kwargs):
            msg = f"a picture called {_name}"
            raise AssertionError(msg)

        monkeypatch.setattr(importlib.import_module(module), name, refuse)
    plotting.draw(table, forces=True)
    plotting.draw_decomposition(table)
    plotting.draw_free_body(table, 1)
    plotting.plot_motion(table)
    plotting.plot_paths(table)
    plotting.plot_torque(table)
    plotting.plot_hodographs(table)
    plotting.plot_shaking(table)
    assert plotting.animate(table, tmp_path / "slot.gif", forces=True) == 3


def test_no_picture_module_imports_a_recompiler() -> None:

    names = {name for _, name in RECOMPILERS}
    for path in sorted(Path(plotting.__file__).parent.glob("*.py")):
        assert not names_imported(path) & names, path.name


# ------------------------------------------------------- units of the schema


def _sweep(mech: assur.Mechanism, step: int = 30) -> assur.Table:
    """A coarse sweep of ``mech``: its forces when it has loads, else kinematics."""
    from assur._loads import compile_loads
    from assur.plan import plan_of

    positions = default_positions(mech)[::step]
    if compile_loads(plan_of(mech)).empty:
        return assur.kinematics(mech, positions)
    return assur.forces(mech, positions)


def _bracket(label: str) -> str:
    """The unit in an axis label such as "omega [rad/s]"."""
    assert label.endswith("]"), label
    return label[label.rindex("[") + 1 : -1]


def _schema_unit(table: assur.Table, name: str) -> str:
    from assur.columns import pretty_unit

    return pretty_unit(table.column(name).unit)


def _check_drawing_axes(ax, table: assur.Table) -> None:
    point = table.plan.points[0]
    assert _bracket(ax.get_xlabel()) == _schema_unit(table, f"{point}.x")
    assert _bracket(ax.get_ylabel()) == _schema_unit(table, f"{point}.y")


def _check_arrow_units(table: assur.Table, arrows, ax=None) -> None:
    """Forces and couples carry the schema's units of forces and moments; so do
    the values written beside them on ``ax``."""
    forces = {
        _schema_unit(table, c.name)
        for c in table.schema
        if c.quantity in ("Fx", "Fy", "F", "Fi.x", "Fi.y", "force")
    }
    moments = {
        _schema_unit(table, c.name)
        for c in table.schema
        if c.quantity in ("M", "Mi", "torque")
    }
    assert forces == {"N"}
    assert moments == {"N·m"}
    for a in arrows:
        if a.force is not None:
            assert a.units[0] in forces
        if a.couple is not None:
            assert a.units[1] in moments
    if ax is not None:
        values = [t.get_text() for t in ax.texts if " = " in t.get_text()]
        assert values
        for text in values:
            assert text.rsplit(" ", 1)[1] in forces | moments, text


def _check_motion_units(table: assur.Table) -> None:
    from assur.columns import LINK_PARTS

    angle = _schema_unit(table, "angle")
    for quantity in (*LINK_PARTS, "x", "v", "a", "j", "vy"):
        ax = plotting.plot_motion(table, quantity=quantity)
        assert _bracket(ax.get_xlabel()) == angle
        columns = [
            ln.get_label().replace(" ", ".")
            if " " in ln.get_label()
            else f"{ln.get_label()}.{quantity}"
            for ln in ax.lines
        ]
        units = {_schema_unit(table, c) for c in columns}
        if columns:
            assert ax.get_ylabel() == f"{quantity} [{' or '.join(units)}]"
        plt.close(ax.figure)


def _check_force_units(table: assur.Table) -> None:
    ax = plotting.plot_torque(table)
    drivers = table.plan.drivers
    owners = ["driver"] if len(drivers) == 1 else [d.pair.name for d in drivers]
    keys = [
        f"{o}.{'torque' if d.kind == 'R' else 'force'}"
        for o, d in zip(owners, drivers, strict=True)
    ]
    units = {_schema_unit(table, k) for k in keys}
    assert _bracket(ax.get_ylabel()) in units
    means = [t for t in _legend_texts(ax) if t.startswith("mean")]
    for text, key in zip(means, keys, strict=True):
        assert f" {_schema_unit(table, key)}" in text
    fig = plotting.plot_hodographs(table)
    for ax in (a for a in fig.axes if a.axison):
        joint = ax.get_title().split(":")[0]
        assert _bracket(ax.get_xlabel()) == _schema_unit(table, f"{joint}.Fx")
        assert _bracket(ax.get_ylabel()) == _schema_unit(table, f"{joint}.Fy")
        assert ax.get_title().endswith(f" {_schema_unit(table, f'{joint}.F')}")
    polar, force, moment = plotting.plot_shaking(table).axes
    assert _bracket(polar.get_xlabel()) == _schema_unit(table, "shaking.Fx")
    assert _bracket(force.get_ylabel()) == _schema_unit(table, "shaking.Fx")
    assert _bracket(moment.get_ylabel()) == _schema_unit(table, "shaking.M")
    plt.close("all")


def test_every_unit_is_the_schema_s(example: assur.Mechanism) -> None:
    table = _sweep(example)
    forced = table.force_state is not None
    drawing = plotting.draw(table, forces=forced)
    _check_drawing_axes(drawing, table)
    _check_drawing_axes(plotting.plot_paths(table), table)
    for ax in plotting.draw_decomposition(table).axes:
        if ax.axison:
            _check_drawing_axes(ax, table)
    _check_motion_units(table)
    if not forced:
        return
    ctx = plotting._context(table)
    _check_arrow_units(table, plotting._overview_arrows(ctx, ctx.pose(1), 1))
    assert _legend_texts(drawing)[-1].endswith(" N")  # the force scale
    for group in range(len(table.plan.groups)):
        ax = plotting.draw_free_body(table, group, angle=table.given[1])
        _check_drawing_axes(ax, table)
        _check_arrow_units(table, plotting._free_body_arrows(table, group, 1), ax)
        plt.close(ax.figure)
    _check_force_units(table)


def test_import_assur_loads_no_matplotlib() -> None:
    code = (
        "import sys, assur, assur.plotting, assur.pictures_cli; "
        "print('matplotlib' in sys.modules)"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    assert out.stdout.strip() == "False"


def test_friction_circles_and_reactions_tangent_to_them():
    from assur.plotting._context import _context

    mech = _load("four_bar_bearings")
    table = assur.forces(mech, [40.0, 130.0])
    ax = plotting.draw(table, forces=True, angle=130.0)
    circles = [
        p for p in ax.patches if (p.get_gid() or "").startswith("friction-circle-")
    ]
    rubbing = [j for j in mech.joints if j.kind == "revolute" and j.friction]
    assert len(circles) == len(rubbing) > 0
    # drawn enlarged, all by one round factor (they were too small to see)
    from assur.plotting._friction import friction_zoom

    zoom = friction_zoom(_context(table, False))
    by_radius = sorted(c.get_radius() for c in circles)
    want = sorted(zoom * j.friction * j.radius for j in rubbing)
    assert by_radius == pytest.approx(want)
    # each reaction's line of action is tangent to its circle, on the side where its
    # moment about the pin is the friction couple
    from assur.plotting._forces import _overview_arrows

    ctx = _context(table, False)
    row = 1
    arrows = {a.label: a for a in _overview_arrows(ctx, ctx.pose(row), row)}
    for joint in rubbing:
        a = arrows[_reaction(table, joint.name)]
        pin = np.array([table[f"{joint.name}.x"][row], table[f"{joint.name}.y"][row]])
        d = a.point - pin
        moment = d[0] * a.force[1] - d[1] * a.force[0]
        assert moment == pytest.approx(table[f"{joint.name}.Mf"][row], rel=1e-9)
        distance = abs(moment) / np.hypot(*a.force)
        assert distance == pytest.approx(joint.friction * joint.radius, rel=1e-9)
        # drawn tangent to the enlarged circle, on the same side
        np.testing.assert_allclose(a.at - pin, zoom * d, rtol=1e-12)
    assert any("friction circle" in t.get_text() for t in ax.get_legend().get_texts())


@pytest.mark.parametrize(
    "stem", ["slider_crank_friction", "four_bar_bearings", "slider_crank_exercise"]
)
def test_a_free_body_is_in_equilibrium_as_drawn(stem):
    # a journal's friction couple is drawn in its reaction's line (tangent to the
    # friction circle): the loads drawn balance, the circle explained in the legend
    from assur.plotting import draw_free_body
    from assur.plotting.decomposition import _free_body_arrows

    table = assur.forces(assur.load(EXAMPLES / f"{stem}.toml"), [45.0])
    force, moment, largest = np.zeros(2), 0.0, 0.0
    for arrow in _free_body_arrows(table, 0, 0):
        # an internal pair's two sides are drawn, and cancel
        if arrow.force is not None:
            force += arrow.force
            (x, y), (fx, fy) = arrow.point, arrow.force
            moment += float(x * fy - y * fx)
            largest = max(largest, float(np.hypot(*arrow.force)))
        moment += arrow.couple or 0.0
    assert np.hypot(*force) <= 1e-9 * largest
    assert abs(moment) <= 1e-9 * largest
    ax = draw_free_body(table, 0)
    entries = [t.get_text() for t in ax.get_legend().get_texts()]
    rubbing = stem != "slider_crank_exercise"
    assert any(e.startswith("friction circle") for e in entries) == rubbing
    plt.close(ax.figure)


def _is_load(text) -> bool:  # type: ignore[no-untyped-def]
    """Whether a label names a load: a reaction, an inertia load, a weight, a torque."""
    return text.get_text().startswith(("$R", "$F", "$M", "$G", "$T", "$Q"))


def _load_label_overlaps(ax) -> list[tuple[str, str]]:  # type: ignore[no-untyped-def]
    """The pairs of labels that overlap, one of them a load's (on the drawing)."""
    ax.figure.canvas.draw()
    renderer = ax.figure.canvas.get_renderer()
    texts = [t for t in ax.texts if t.get_visible() and t.get_text()]
    boxes = [t.get_window_extent(renderer) for t in texts]
    return [
        (texts[i].get_text(), texts[j].get_text())
        for i in range(len(texts))
        for j in range(i + 1, len(texts))
        if (_is_load(texts[i]) or _is_load(texts[j])) and boxes[i].overlaps(boxes[j])
    ]


@pytest.mark.parametrize(
    ("name", "angle", "group"),
    [
        ("slider_crank_exercise", 45.0, None),
        ("class3", 30.0, 0),
        ("six_bar_lecture", 60.0, 1),
    ],
)
def test_the_loads_labels_do_not_overlap(
    name: str, angle: float, group: int | None
) -> None:
    # at a slider its reaction, the guide's and its inertia force were named at one
    # point, one label over another; a rod's inertia force hid under its couple's
    table = assur.forces(assur.load(EXAMPLES / f"{name}.toml"), [angle])
    if group is None:
        ax = plotting.draw(table, forces=True)
    else:
        ax = plotting.draw_free_body(table, group)
    try:
        assert _load_label_overlaps(ax) == []
    finally:
        plt.close(ax.figure)


def test_the_driver_axis_names_the_driver_of_several():
    """A two-crank five-bar's diagrams are drawn against the first crank's angle:
    the axis said "driver angle" alone."""
    import matplotlib.pyplot as plt

    table = assur.forces(
        assur.load(EXAMPLES / "five_bar_two_cranks.toml"),
        np.stack([np.arange(0.0, 360.0, 10.0), np.full(36, 120.0)], axis=1),
    )
    ax = plotting.plot_torque(table)
    assert ax.get_xlabel() == "driver A angle φ [deg]"
    plt.close(ax.figure)
    one = assur.forces(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 10.0))
    ax = plotting.plot_torque(one)
    assert ax.get_xlabel() == "driver angle φ [deg]"
    plt.close(ax.figure)


def test_an_arrow_of_no_length_is_drawn_without_a_warning():
    """A zero force drawn to scale is an arrow of no length: its head's size, a
    third of it, was 0 and matplotlib divided 0 by 0 (a RuntimeWarning)."""
    import matplotlib.pyplot as plt

    from assur.plotting._heads import fitted_arrow

    fig, ax = plt.subplots()
    try:
        ax.add_patch(fitted_arrow([[0.0, 0.0], [0.0, 0.0]], 13.0))
        ax.add_patch(fitted_arrow([[0.0, 0.0], [1.0, 0.5]], 13.0))
        fig.canvas.draw()  # warnings are errors in the tests
    finally:
        plt.close(fig)


def test_a_force_of_round_off_is_not_drawn_with_its_round_off_on_it():
    # at the dead centre the guide's reaction is 1.6e-14 N beside 3266 N: it was
    # drawn and named "1.63e-14 N"
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [0.0])
    assert 0.0 < abs(float(table["guide.F"][0])) < 1e-9 * float(table["B.F"][0])
    ax = plotting.draw_free_body(table, 0)
    try:
        texts = [t.get_text() for t in ax.texts]
        assert not any("ground" in t and "slider" in t for t in texts), texts
        assert not any("e-1" in t for t in texts), texts
    finally:
        plt.close(ax.figure)


def test_a_couple_s_arc_grows_with_it():
    # M_i,crank = -0.0005 N m was drawn as large as M_i,coupler = 0.16 N m
    from matplotlib.patches import FancyArrowPatch

    table = assur.forces(_load("four_bar"), [270.0])
    ax = plotting.draw(table, forces=True)
    try:
        radii = []
        for p in ax.patches:
            if not isinstance(p, FancyArrowPatch) or p._posA_posB is not None:
                continue
            v = np.asarray(p._path_original.vertices, dtype=float)
            gaps = np.hypot(*(v[:, None, :] - v[None, :, :]).transpose(2, 0, 1))
            radii.append(float(gaps.max()) / 2.0)
    finally:
        plt.close(ax.figure)
    crank, coupler = abs(table["crank.Mi"][0]), abs(table["coupler.Mi"][0])
    assert crank < 0.01 * coupler
    # the inertia couples' arcs and the balancing torque's: the crank's, 300 times
    # smaller than the coupler's, is drawn the smallest
    assert len(radii) >= 3
    assert min(radii) < 0.7 * sorted(radii)[-2]


def test_the_legend_shows_an_internal_reaction_dashed():
    from assur.plotting._style import INTERNAL_LEGEND

    table = assur.forces(_load("slider_crank_exercise"), [45.0])
    ax = plotting.draw_free_body(table, 0)
    try:
        legend = ax.get_legend()
        styles = {
            t.get_text(): h.get_linestyle()
            for h, t in zip(legend.legend_handles, legend.get_texts(), strict=True)
        }
    finally:
        plt.close(ax.figure)
    assert styles[INTERNAL_LEGEND] not in ("-", "solid")
