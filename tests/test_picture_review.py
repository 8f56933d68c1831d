"""Defects a visual review of the pictures found: scales, means, frames, labels.

Each test names the picture as it was wrong and checks it as drawn (Agg).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.plotting import lever

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"
ANGLES = np.arange(0.0, 360.0, 1.0)


def _arrows(ax, color: str) -> list[float]:
    """Return the lengths, mm of the drawing, of the arrows of ``color`` on ``ax``."""
    from matplotlib.colors import to_hex

    return [
        float(np.hypot(*np.subtract(*p.points)))
        for p in ax.patches
        if hasattr(p, "points") and to_hex(p.get_edgecolor()) == color
    ]


def _forces(ax) -> list[float]:
    """Return the lengths of the lever's forces: inertia forces, gravity and loads."""
    from assur.plotting._style import INERTIA_COLOR, LOAD_COLOR

    return _arrows(ax, INERTIA_COLOR) + _arrows(ax, LOAD_COLOR)


def test_the_lever_draws_couples_to_the_forces_scale() -> None:
    import matplotlib.pyplot as plt

    # the slotted lever's couples (0.1 % of the torque) were its biggest arrows,
    # drawn to 1 mm = 0.001 N beside the forces' 1 mm = 10 N
    table = assur.forces(assur.load(EXAMPLES / "slot_mechanism.toml"), [30.0])
    ax = lever.zhukovsky_lever(table)
    try:
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert sum("1 mm =" in t for t in legend) == 1, legend
        assert any("couple" in t and "same scale" in t for t in legend)
        assert any("*: below the scale, drawn 3 mm long" in t for t in legend)
        couples = _arrows(ax, lever.COUPLE)
        assert couples
        assert max(couples) <= lever.MARK * (1 + 1e-9)
        assert max(couples) < max(_forces(ax))
    finally:
        plt.close(ax.figure)


def test_a_couple_larger_than_the_forces_sets_the_lever_s_scale() -> None:
    import matplotlib.pyplot as plt

    # the bearings four-bar's resisting torque on its rocker (4 N m) drew a pair
    # 125 mm long, the forces setting the scale for a 40 mm lever
    table = assur.forces(assur.load(EXAMPLES / "four_bar_bearings.toml"), [30.0])
    ax = lever.zhukovsky_lever(table)
    try:
        couples = _arrows(ax, lever.COUPLE)
        forces = _forces(ax)
        longest = max(couples + forces)
        assert max(couples) == pytest.approx(longest)
        assert longest < 60.0  # mm of the drawing, as a force's longest is
    finally:
        plt.close(ax.figure)


def test_the_torque_diagram_states_the_summary_s_mean() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import force_diagrams

    # 0:360:5 ends on its first pose: the picture wrote mean 12.85 N·m (that pose
    # counted twice), the summary 12.82
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    table = assur.forces(mech, np.arange(0.0, 361.0, 5.0))
    ax = force_diagrams.plot_torque(table)
    try:
        want = table.summary()["driver.torque.mean"]
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        (label,) = [t for t in labels if t.startswith("mean ")]
        assert float(label.split()[1]) == pytest.approx(want, abs=0.01)
        assert label.startswith("mean 12.82 ")
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize(
    ("angles", "want"),
    [
        (None, 45.0 + 30.0 * np.arange(12)),  # the default 45..404 in steps of 1
        ("0:360:5", 30.0 * np.arange(12)),  # a turn with its end, the start again
        ("360:0:-5", 360.0 - 30.0 * np.arange(12)),
        ("0:180:5", np.linspace(0, 36, 12).round() * 5.0),  # no turn: spread
    ],
)
def test_an_animation_of_a_turn_loops_evenly(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, angles, want
) -> None:
    import assur.plotting
    from assur.cli import main

    # whitworth's 12 frames were 32.6 degrees apart, and 1 degree from the last
    # (404) back to the first (45): the loop stuttered
    drawn = []
    monkeypatch.setattr(
        assur.plotting, "animate", lambda table, *a, **k: drawn.append(table) or 12
    )
    argv = ["animate", str(EXAMPLES / "whitworth.toml"), "--frames", "12", "-q"]
    argv += ["-o", str(tmp_path / "a.gif")] + (["--angles", angles] if angles else [])
    assert main(argv) == 0
    np.testing.assert_allclose(drawn[0]["angle"], want, atol=1e-9)


def test_the_pictures_write_forces_in_plain_digits() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import force_diagrams

    # the crank's pin: "max 1.127e+04 N", where an engineer reads "11266 N"
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), ANGLES)
    fig = force_diagrams.plot_hodographs(table)
    try:
        titles = [ax.get_title() for ax in fig.axes]
        assert any(t.endswith("max 11266 N") for t in titles), titles
        assert not any("e+" in t for t in titles)
    finally:
        plt.close(fig)


def test_force_arrows_lie_above_the_links_with_a_light_outline() -> None:
    import matplotlib.pyplot as plt
    from matplotlib.patheffects import Stroke

    from assur import plotting

    # F_i,crank was drawn black on the dark-slate crank, and could not be seen
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [45.0])
    bare = plotting.draw(table)
    top = max(a.get_zorder() for a in [*bare.lines, *bare.patches])
    plt.close(bare.figure)
    ax = plotting.draw(table, forces=True)
    try:
        arrows = [p for p in ax.patches if hasattr(p, "points")]
        assert len(arrows) >= 5
        for arrow in arrows:
            assert arrow.get_zorder() > top
            (halo, *_) = arrow.get_path_effects()
            assert isinstance(halo, Stroke)
    finally:
        plt.close(ax.figure)


def _overlap(p: np.ndarray, q: np.ndarray) -> float:
    """Return how long arrows ``p`` and ``q`` (2 by 2, mm) run over each other."""
    d = p[1] - p[0]
    u = d / np.hypot(*d)
    off = max(abs(u[0] * (end - p[0])[1] - u[1] * (end - p[0])[0]) for end in q)
    if off > 0.2:
        return 0.0
    low, high = sorted(float(np.dot(u, end - p[0])) for end in q)
    return max(0.0, min(high, float(np.hypot(*d))) - max(low, 0.0))


def test_no_term_of_a_plan_hides_another() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import plans

    # whitworth's slot passes through the lever's pivot: the tangential term lay
    # exactly under the Coriolis one, both perpendicular to the slot
    table = assur.forces(assur.load(EXAMPLES / "whitworth.toml"), [45.0])
    ax = plans.acceleration_plan(table)
    try:
        from matplotlib.colors import to_hex

        # the tangential (red) and Coriolis (violet) terms of the dyad's sides
        terms = {"#d62728": [], "#9467bd": []}
        for p in ax.patches:
            if hasattr(p, "points") and to_hex(p.get_edgecolor()) in terms:
                terms[to_hex(p.get_edgecolor())].append(np.asarray(p.points))
        assert all(terms.values())
        for p in terms["#d62728"]:
            for q in terms["#9467bd"]:
                assert _overlap(p, q) < 1.0, (p, q)
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize(
    ("stem", "loaded"), [("slider_crank_exercise", False), ("whitworth", True)]
)
def test_a_free_body_s_legend_names_only_the_loads_drawn(
    stem: str, loaded: bool
) -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import draw_free_body

    # the slider-crank's group has no gravity and no external load, yet its legend
    # listed "gravity, external load"
    table = assur.forces(assur.load(EXAMPLES / f"{stem}.toml"), [60.0])
    ax = draw_free_body(table, 0)
    try:
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert ("gravity, external load" in legend) is loaded
    finally:
        plt.close(ax.figure)


def test_the_lever_s_loads_in_the_colours_of_the_other_pictures() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting._style import INERTIA_COLOR, LOAD_COLOR

    # every load on the lever was red, the colour of reactions everywhere else
    table = assur.forces(assur.load(EXAMPLES / "six_bar_lecture.toml"), [60.0])
    ax = lever.zhukovsky_lever(table)
    try:
        from matplotlib.colors import to_hex

        drawn = [p for p in ax.patches if hasattr(p, "points")]
        colours = {to_hex(p.get_edgecolor()) for p in drawn}
        # the weights in the loads' colour, the inertia forces in theirs, the
        # couples' pairs in violet, the images' rays in grey
        assert {INERTIA_COLOR, LOAD_COLOR, lever.COUPLE} <= colours
        assert "#d62728" not in colours  # the reactions' red
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert legend[:2] == ["inertia force", "gravity, external load"]
        names = {t.get_text(): to_hex(t.get_color()) for t in ax.texts}
        weights = {c for text, c in names.items() if text.startswith("$m_")}
        inertia = {c for text, c in names.items() if text.startswith("$\\vec F_{i,")}
        assert weights == {LOAD_COLOR}
        assert inertia == {INERTIA_COLOR}
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_a_dead_centre_s_lever_writes_its_shares_of_round_off_0(
    angle: float,
) -> None:
    import matplotlib.pyplot as plt

    # at a dead centre every share is round-off (1e-13 N m): they were written
    # "+0.000000000", eight decimals of nothing
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [angle])
    ax = lever.zhukovsky_lever(table)
    try:
        (listed,) = [t.get_text() for t in ax.texts if "balancing load" in t.get_text()]
        lines = listed.splitlines()
        shares = [line.rsplit(":", 1)[1].strip() for line in lines[2:-1]]
        assert shares == ["0"] * 3, lines
        assert lines[-1] == "sum = balancing load: 0 N·m"
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_forces_on_one_line_at_one_joint_are_drawn_apart(angle: float) -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import draw_free_body
    from assur.plotting._arrows import APART
    from assur.plotting._context import _context

    from .test_plans import _segments

    # at a dead centre the slider's inertia force lay under the rod's reaction on
    # the slider's other side (dashed, on the rod): one black arrow not seen
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [angle])
    ax = draw_free_body(table, 0)
    try:
        r = _context(table).r
        arrows = _segments(ax)
        assert len(arrows) == 5  # at B, the inertia forces, the reaction at C twice
        # all along the rod's line (y = 0): two at one height share no span
        assert all(abs(a[1, 1] - a[0, 1]) < 1e-12 for a in arrows)
        for i, a in enumerate(arrows):
            for b in arrows[i + 1 :]:
                if abs(a[0, 1] - b[0, 1]) < 0.1 * r:
                    shared = min(a[:, 0].max(), b[:, 0].max()) - max(
                        a[:, 0].min(), b[:, 0].min()
                    )
                    assert shared < 0.1 * r, (a, b)
        # each moved no farther than a step from its load's line
        assert max(abs(a[0, 1]) for a in arrows) == pytest.approx(APART * r)
    finally:
        plt.close(ax.figure)


def test_a_flat_group_s_free_body_is_drawn_lower() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import draw_free_body

    # the slider-crank's group lies along the guide at 0 deg: its free body was a
    # 9 x 6.5 in picture, two thirds of it empty above and below the rod
    flat = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [0.0])
    tall = assur.forces(assur.load(EXAMPLES / "six_bar_lecture.toml"), [30.0])
    sizes = []
    for table in (flat, tall):
        ax = draw_free_body(table, 0)
        sizes.append(tuple(ax.figure.get_size_inches()))
        # the view still fills the axes, the group inside it
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        box = ax.get_window_extent()
        assert (x1 - x0) / (y1 - y0) == pytest.approx(box.width / box.height, 0.02)
        plt.close(ax.figure)
    assert sizes[0] == (9.0, 3.6)
    assert sizes[1] == (9.0, 6.5)
    # a figure of the caller's keeps its size
    fig, ax = plt.subplots(figsize=(8.0, 6.0), layout="constrained")
    draw_free_body(flat, 0, ax=ax)
    assert tuple(fig.get_size_inches()) == (8.0, 6.0)
    plt.close(fig)


def test_the_lever_s_small_loads_are_drawn_long_enough_to_be_seen() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting._style import INERTIA_COLOR

    # the Scotch yoke's block and crank at 0 deg: inertia forces of 0.3 and 0.7 mm
    # were names beside nothing, under the plan's ray
    table = assur.forces(assur.load(EXAMPLES / "scotch_yoke.toml"), [0.0])
    ax = lever.zhukovsky_lever(table)
    try:
        forces = _arrows(ax, INERTIA_COLOR)
        assert len(forces) == 3
        assert min(forces) == pytest.approx(lever.MARK)
        named = [t.get_text() for t in ax.texts if t.get_text().startswith("$\\vec")]
        assert len(named) == 4  # the three inertia forces and the load
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize(("stem", "angle"), [("slider_crank_exercise", 0.0),
                                             ("scotch_yoke", 0.0),
                                             ("slot_mechanism", 180.0)])  # fmt: skip
def test_the_lever_s_loads_kept_apart_keep_their_moments(
    stem: str, angle: float
) -> None:
    import matplotlib.pyplot as plt

    from assur.explain._position import perp
    from assur.plotting.plans import _scale, images

    from .test_plans import _segments

    def _cross(a, b) -> float:
        return float(a[0] * b[1] - a[1] * b[0])

    # stepped sideways off one another, loads on the lever showed arms they do not
    # have (Q_ram at 20.4 mm for 19.2, a dead centre's loads a moment for 0): slid
    # along their own lines, each keeps its moment about the pole
    table = assur.forces(assur.load(EXAMPLES / f"{stem}.toml"), [angle])
    ax = lever.zhukovsky_lever(table)
    try:
        drawn = _segments(ax)
        pos = lever._lever_position(table, None, 0, "test")
        bodies, _, _ = lever.lever_rates(pos, 0)
        turned = dataclasses.replace(pos, bodies=bodies)
        terms = lever.lever_parts(pos, bodies)
        arrows = lever._lever_arrows(turned, terms, lever._apart(turned, terms))
        found = [perp(v) for v in images(turned, 1).values()]
        mu = _scale(found)
        largest = max(np.hypot(*f) for _, f, _, _ in arrows)
        fmu = _scale([f for _, f, _, _ in arrows]) * 2.0
        for at, force, _, _ in arrows:
            if not np.hypot(*force) > 1e-9 * largest:
                continue  # round-off: not drawn
            u = force / np.hypot(*force)
            length = max(np.hypot(*force) / fmu, lever.MARK)
            # an arrow of its length drawn on this load's line of action, its way
            on_line = [
                d for d in drawn
                if abs(_cross(u, (d[1] - d[0]) / np.hypot(*(d[1] - d[0])))) < 1e-9
                and np.dot(u, d[1] - d[0]) > 0
                and abs(_cross(u, d[0] - at / mu)) < 1e-6
                and abs(np.hypot(*(d[1] - d[0])) - length) < 1e-6
            ]  # fmt: skip
            assert on_line, (at, force)
    finally:
        plt.close(ax.figure)
