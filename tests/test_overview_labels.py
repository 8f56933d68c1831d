"""Names on the pictures with loads read as their own: each by its own arrow, clear.

The mechanism with its loads (``assur plot --forces``) and a group's free body
(``assur plot --group N``) of a slotted-lever shaper, the lecture's six-bar and
the Whitworth quick return. Every name's box is measured on the figure as drawn:
no two overlap, all are inside the axes, a joint's name is off the arrows, the
sliding blocks and the bearings, and (on the mechanism) a force's name is nearer
its own arrow than any other's.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.plotting import decomposition, mechanism
from assur.plotting._context import _context
from assur.plotting._forces import _overview_arrows, _scale

from .test_plan_labels import _distance, _overlap

matplotlib.use("Agg")

CLEAR = 10.0
"""Points of another force from one point a name may be as near as its own."""
HERE = Path(__file__).parent
CASES = [
    (HERE / "data" / "plans" / "slotted_lever.toml", 70.0),
    (HERE.parent / "examples" / "six_bar_lecture.toml", 30.0),
    (HERE.parent / "examples" / "whitworth.toml", 270.0),
]
"""The pictures checked; the shaper at the angle its crowding was seen at."""


def _boxes(ax) -> dict:
    """Return each name drawn on ``ax`` and its display box with its background."""
    renderer = ax.figure.canvas.get_renderer()
    out = {}
    for text in ax.texts:
        if not (text.get_visible() and text.get_text()):
            continue
        patch = text.get_bbox_patch()
        if patch is not None:
            text.update_bbox_position_size(renderer)
        art = text if patch is None else patch
        out[text] = np.asarray(art.get_window_extent(renderer).extents)
    return out


def _pixels(ax) -> float:
    """Return the pixels in a point on ``ax``'s figure."""
    return ax.figure.dpi / 72.0


def _short(ax, a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the arrow ``a``-``b`` (display) is read as a point (6 points).

    Its name is read by the point it is at; it is checked only for overlaps.
    """
    return bool(np.hypot(*(b - a)) < 6.0 * _pixels(ax))


def _problems(ax, arrows, scale: float, nearest: bool = True) -> list[str]:
    """Return what is wrong with the names on ``ax`` (nothing, when all is well).

    Overlaps, names cut off at the frame, joints' names over the arrows, blocks
    and bearings, and (when ``nearest``) forces' names nearer another's arrow.
    """
    ax.figure.canvas.draw()
    boxes = _boxes(ax)
    frame = np.asarray(ax.bbox.extents)
    wrong = []
    items = list(boxes.items())
    for i, (text, box) in enumerate(items):
        if not ((box[:2] >= frame[:2] - 1).all() and (box[2:] <= frame[2:] + 1).all()):
            wrong.append(f"{text.get_text()} outside the axes")
        wrong += [
            f"{text.get_text()} over {other.get_text()}"
            for other, seen in items[i + 1 :]
            if _overlap(box, seen)
        ]
    to_display = ax.transData.transform
    forces = {a.label: to_display(ends) for a, ends in _drawn(ax, arrows, scale)}
    for text, box in boxes.items() if nearest else ():
        label = text.get_text().split(" = ")[0]
        if label not in forces or _short(ax, *forces[label]):
            continue
        a, b = forces[label]
        mine = _distance(box, a, b)
        for other, (c, d) in forces.items():
            if other == label or _short(ax, c, d):
                continue
            if np.hypot(*(c - a)) < 1.0:
                # forces from one point (a centre of mass, a slider's pin): beside
                # that point, and along the part of the other alongside its own,
                # a name is as near one as the other; it is read by its own
                # further out, ten points clear of that part
                length = np.hypot(*(d - c))
                u = (d - c) / max(length, 1e-9)
                part = CLEAR * _pixels(ax) + max(float(np.dot(u, b - a)), 0.0)
                c = c + min(1.0, part / max(length, 1e-9)) * (d - c)
            if _distance(box, c, d) < mine:
                wrong.append(f"{label} nearer {other}'s arrow")
    return wrong + _joint_problems(ax, boxes, forces)


def _drawn(ax, arrows, scale: float) -> list:
    """Return each force of ``arrows`` with the ends (data) of the arrow drawn for it.

    An arrow that lay on another was drawn a little aside: it is found among the
    straight arrows on ``ax`` by its length and direction, the nearest its point.
    """
    from matplotlib.patches import FancyArrowPatch

    pool = [
        np.asarray(p._posA_posB, dtype=float)
        for p in ax.patches
        if isinstance(p, FancyArrowPatch) and p._posA_posB is not None
    ]
    out = []
    for a in arrows:
        if a.force is None or not np.hypot(*a.force) > 0:
            continue
        vector = a.force / (scale * 100.0)
        size = float(np.hypot(*vector))
        same = [
            i for i, e in enumerate(pool)
            if np.hypot(*(e[1] - e[0] - vector)) <= 1e-9 * max(size, 1e-300)
        ]  # fmt: skip
        if not same:  # a force of round-off, not drawn
            continue
        i = min(same, key=lambda k: float(np.hypot(*(pool[k][0] - a.at))))
        out.append((a, pool.pop(i)))
    sizes = [np.hypot(*a.force) for a in arrows if a.force is not None]
    seen = [s for s in sizes if s > 1e-6 * max(sizes, default=0.0)]
    assert len(out) >= len(seen)  # every force that is more than round-off
    return out


def _joint_problems(ax, boxes: dict, forces: dict) -> list[str]:
    """Return the joints' names (bold) over an arrow, a block or a bearing."""
    from matplotlib.patches import Polygon
    from matplotlib.path import Path as Outline
    from matplotlib.transforms import Bbox

    view = np.prod(np.ptp(ax.transData.transform(ax.viewLim.get_points()), axis=0))
    solid = [ax.transData.transform(p.get_xy()) for p in ax.patches
             if isinstance(p, Polygon)]  # fmt: skip
    solid = [p for p in solid if np.prod(np.ptp(p, axis=0)) < view / 50]
    wrong = []
    for text, box in boxes.items():
        if text.get_fontweight() != "bold":
            continue
        inner = Bbox.from_extents(*(box + np.array([1.0, 1.0, -1.0, -1.0])))
        wrong += [
            f"{text.get_text()} over {label}'s arrow"
            for label, (a, b) in forces.items()
            if Outline([a, b]).intersects_bbox(inner, filled=False)
        ]
        wrong += [
            f"{text.get_text()} over a block or bearing"
            for outline in solid
            if Outline(outline, closed=True).intersects_bbox(inner, filled=True)
        ]
    return wrong


@pytest.mark.parametrize(("path", "angle"), CASES, ids=lambda c: getattr(c, "stem", c))
def test_the_names_of_the_loads_are_apart_and_by_their_arrows(path, angle) -> None:
    import matplotlib.pyplot as plt

    # the shaper's joint name "F, ways" lay on the ram's block, F_lever,rod's name
    # on the ram block, M_b's over the crank's weight's and F_ground,crank; the
    # six-bar's names lay on the links' names and on each other
    table = assur.forces(assur.load(path), [angle])
    ctx = _context(table)
    arrows = _overview_arrows(ctx, ctx.pose(0), 0)
    scale = _scale(arrows, ctx.size)
    ax = mechanism.draw(table, forces=True, scale=scale)
    try:
        assert _problems(ax, arrows, scale) == []
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize(("path", "angle"), CASES, ids=lambda c: getattr(c, "stem", c))
def test_a_free_body_s_names_are_apart_and_by_their_arrows(path, angle) -> None:
    import matplotlib.pyplot as plt

    table = assur.forces(assur.load(path), [angle])
    ctx = _context(table)
    for group in range(len(ctx.plan.groups)):
        arrows = decomposition._free_body_arrows(table, group, 0)
        scale = _scale(arrows, 0.8 * ctx.size)
        ax = decomposition.draw_free_body(table, group, scale=scale)
        try:
            # with their values the names are long: in a crowded group some are
            # still nearer a neighbour's arrow than their own, not checked here
            assert _problems(ax, arrows, scale, nearest=False) == [], group
        finally:
            plt.close(ax.figure)


def _link_names_over_inertia(ax) -> list[str]:
    """Return the links' names (boxed, edged in their colour) over an inertia arrow."""
    from matplotlib.colors import same_color
    from matplotlib.path import Path as Outline
    from matplotlib.transforms import Bbox

    from assur.plotting._style import INERTIA_COLOR

    ax.figure.canvas.draw()
    boxes = _boxes(ax)
    arrows = [p for p in ax.patches if hasattr(p, "points")
              and same_color(p.get_edgecolor(), INERTIA_COLOR)]  # fmt: skip
    assert arrows
    wrong = []
    for text, box in boxes.items():
        patch = text.get_bbox_patch()
        if patch is None or not patch.get_edgecolor()[3]:
            continue
        inner = Bbox.from_extents(*box)
        for arrow in arrows:
            # drawn under the arrows, never over them
            if text.get_zorder() >= arrow.get_zorder():
                wrong.append(f"{text.get_text()} drawn over an inertia arrow")
            seen = ax.transData.transform(np.asarray(arrow.points, float))
            if Outline(seen).intersects_bbox(inner, filled=False):
                wrong.append(f"{text.get_text()} over an inertia arrow")
    return wrong


def test_the_links_names_keep_off_the_inertia_arrows() -> None:
    import matplotlib.pyplot as plt

    # a student's crank-rocker (centres of mass at the bars' middles): the names
    # "coupler" and "rocker" lay on their bars' middles, over the inertia forces
    # and couples drawn from there, and hid them
    path = HERE / "data" / "plans" / "crank_rocker.toml"
    table = assur.forces(assur.load(path), [30.0])
    ax = mechanism.draw(table, forces=True)
    try:
        assert _link_names_over_inertia(ax) == []
    finally:
        plt.close(ax.figure)
    ax = decomposition.draw_free_body(table, 0)
    try:
        assert _link_names_over_inertia(ax) == []
    finally:
        plt.close(ax.figure)


def test_the_loads_are_named_as_the_note_names_them() -> None:
    # the note and the polygons number a link's loads (Q_{slider,1}, Q_{slider,2},
    # then its couples); the mechanism's picture wrote Q_{slider} for each of them
    from assur.explain import explain

    text = (HERE.parent / "examples" / "slider_crank_exercise.toml").read_text(
        encoding="utf-8"
    )
    text += """
[[loads]]
link = "slider"
at = "C"
torque = 2.0
[[loads]]
link = "slider"
at = "C"
force = [-300.0, 0.0]
[[loads]]
link = "rod"
at = "B"
force = [0.0, -40.0]
[[loads]]
link = "slider"
at = "C"
force = [0.0, -20.0]
"""
    mech = assur.loads(text)
    table = assur.forces(mech, [60.0])
    ax = mechanism.draw(table, forces=True)
    names = {t.get_text() for t in ax.texts if t.get_text().startswith(("$Q", "$T"))}
    matplotlib.pyplot.close(ax.figure)
    assert names == {
        r"$Q_{\text{slider},1}$",
        r"$Q_{\text{slider},2}$",
        r"$T_{\text{slider},3}$",
        r"$Q_{\text{rod},1}$",
    }
    note = str(explain(mech, 60.0))
    for name in names:
        # the note's TeX sets a name upright with \mathrm, matplotlib's with \text
        assert name.strip("$").replace(r"\text", r"\mathrm") in note, name
