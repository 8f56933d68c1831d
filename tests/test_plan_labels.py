"""Names on the plans read as their own: force polygons, instant centres, lever.

The mechanisms are a teacher's trial's (``tests/data/plans``): a slotted-lever
shaper, a Scotch yoke, an inclined slider-crank and a six-bar of two RRR dyads.
Every name's box is measured on the figure as drawn.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.plotting import lever, plans, polygons

matplotlib.use("Agg")

TRIAL = Path(__file__).parent / "data" / "plans"
EXAMPLES = Path(__file__).parent.parent / "examples"


def _box(fig, text) -> np.ndarray:
    """Return the display box (x0, y0, x1, y1) of ``text`` as drawn."""
    return np.asarray(text.get_window_extent(fig.canvas.get_renderer()).extents)


def _meets(box: np.ndarray, a: np.ndarray, b: np.ndarray, inset: float = 1.0) -> bool:
    """Whether the segment ``a``-``b`` (display) passes through ``box``, inset."""
    t = np.linspace(0.0, 1.0, 400)[:, None]
    points = a + t * (b - a)
    low, high = box[:2] + inset, box[2:] - inset
    return bool(np.all((points > low) & (points < high), axis=1).any())


def _distance(box: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """Return the distance from ``box`` to the segment ``a``-``b`` (sampled)."""
    t = np.linspace(0.0, 1.0, 2000)[:, None]
    points = a + t * (b - a)
    return float(np.hypot(*(points - np.clip(points, box[:2], box[2:])).T).min())


def _overlap(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two boxes overlap by more than half a pixel each way."""
    return bool(
        min(a[2], b[2]) - max(a[0], b[0]) > 0.5
        and min(a[3], b[3]) - max(a[1], b[1]) > 0.5
    )


def _inside(box: np.ndarray, frame: np.ndarray) -> bool:
    """Whether ``box`` lies within ``frame`` (to a pixel)."""
    return bool((box[:2] >= frame[:2] - 1).all() and (box[2:] <= frame[2:] + 1).all())


@pytest.mark.parametrize(
    ("stem", "angle"),
    [("slotted_lever", 70.0), ("yoke", 70.0), ("fourbar", 60.0), ("inverted", 230.0)],
)
def test_a_polygon_s_side_is_named_beside_itself_alone(stem: str, angle: float) -> None:
    import matplotlib.pyplot as plt

    # the shaper's F_lever,rod was named on the line of Q_ram,1 and Q's name lay
    # across F_lever,rod; the yoke's F_ground,yoke was cut off at the frame
    table = assur.forces(assur.load(TRIAL / f"{stem}.toml"), [angle])
    fig = polygons.force_polygons(table)
    try:
        fig.canvas.draw()
        for ax in fig.axes:
            texts = [t for t in ax.texts if t.get_text()]
            ends = [np.array(p._posA_posB) for p in ax.patches]
            assert len(texts) == len(ends) >= 3
            sides = [ax.transData.transform(e) for e in ends]
            boxes = [_box(fig, t) for t in texts]
            frame = ax.bbox.extents
            for i, (text, box) in enumerate(zip(texts, boxes, strict=True)):
                name = text.get_text()
                assert _inside(box, frame), name
                mine = _distance(box, *sides[i])
                # a side shorter than its name is named as a point, at a corner
                # whose other sides come as near
                long = np.hypot(*np.subtract(*sides[i])) > max(box[2:] - box[:2])
                for j, side in enumerate(sides):
                    if j == i:
                        continue
                    assert not _meets(box, *side), (name, texts[j].get_text())
                    if long:
                        assert mine < _distance(box, *side), (name, texts[j].get_text())
                    assert not _overlap(box, boxes[j]), (name, texts[j].get_text())
    finally:
        plt.close(fig)


def test_a_side_of_round_off_is_neither_drawn_nor_named() -> None:
    import matplotlib.pyplot as plt

    # the yoke at mid-stroke: its inertia force is 1e-11 N, named with an arrow
    table = assur.forces(assur.load(TRIAL / "yoke.toml"), [70.0])
    fig = polygons.force_polygons(table)
    try:
        (ax,) = fig.axes
        names = [t.get_text() for t in ax.texts]
        assert not [n for n in names if "i," in n and "yoke" in n]
        assert any("block" in n for n in names)
        lengths = [np.hypot(*np.subtract(*p._posA_posB)) for p in ax.patches]
        assert min(lengths) > 1e-6 * max(lengths)
        # the polygon still closes: the sides left out are nothing (the note's
        # inertia force of round-off is zero, the table's reactions hold 1e-11 N)
        assert ax.get_title().endswith(": the polygon closes")
    finally:
        plt.close(fig)


def _texts(ax) -> list:
    """Return the texts of ``ax`` with something written."""
    return [t for t in ax.texts if t.get_visible() and t.get_text()]


@pytest.mark.parametrize("stem", ["slotted_lever", "inclined", "sixbar"])
def test_the_instant_centres_names_are_apart_inside_the_frame(stem: str) -> None:
    import matplotlib.pyplot as plt

    # the shaper had some 20 names over one another, the six-bar 8; the slider-
    # crank's "C, guide" ran past the frame and Irod-slider lay on the slider
    table = assur.kinematics(assur.load(TRIAL / f"{stem}.toml"), [70.0])
    ax = plans.instant_centres(table)
    fig = ax.figure
    try:
        fig.canvas.draw()
        texts = _texts(ax)
        boxes = [_box(fig, t) for t in texts]
        frame = ax.bbox.extents
        for i, (text, box) in enumerate(zip(texts, boxes, strict=True)):
            assert _inside(box, frame), text.get_text()
            for j in range(i + 1, len(texts)):
                pair = (text.get_text(), texts[j].get_text())
                # the drawing's own names are draw()'s: a centre's is not on any
                if any(n.startswith("$I_") for n in pair):
                    assert not _overlap(box, boxes[j]), pair
        # a centre's name lies on no small patch: a joint's circle, the block
        blocks = [p.get_window_extent().extents for p in ax.patches]
        small = [b for b in blocks if (b[2] - b[0]) * (b[3] - b[1]) < 2000]
        for text, box in zip(texts, boxes, strict=True):
            if text.get_text().startswith("$I_"):
                assert not any(_overlap(box, b) for b in small), text.get_text()
    finally:
        plt.close(fig)


def test_a_far_centre_s_coordinate_that_is_round_off_is_written_0() -> None:
    # the four-bar at 90 deg: the coupler's centre is straight above the crank's
    # pivot, x = 0 but for round-off, and was named "(3.47e-18, 1.41) m"
    import matplotlib.pyplot as plt

    from assur.explain._solve import position

    mech = assur.load(EXAMPLES / "four_bar.toml")
    far = plans.relative_centres(position(mech, 90.0))[(0, 2)]
    assert far is not None
    assert abs(far[0]) < 1e-12 * abs(far[1])
    ax = plans.instant_centres(assur.kinematics(mech, [90.0]))
    try:
        named = [t.get_text() for t in _texts(ax) if t.get_text().endswith(") m")]
        assert named == [rf"$I_{{\text{{coupler}}}}$ (0, {far[1]:.3g}) m"]
    finally:
        plt.close(ax.figure)


def test_a_far_centre_is_shown_at_the_edge_with_its_coordinates() -> None:
    import matplotlib.pyplot as plt

    from assur.explain._solve import position
    from assur.plotting import draw

    # the shaper's rod turns slowly: its centre, at y = 1.18 m, squeezed the
    # mechanism (0.4 m tall) into a strip
    mech = assur.load(TRIAL / "slotted_lever.toml")
    table = assur.kinematics(mech, [70.0])
    ax = plans.instant_centres(table)
    alone = draw(table)
    try:
        far = plans.relative_centres(position(mech, 70.0))[(0, 4)]
        assert far is not None
        assert far[1] > 1.0
        (y0, y1), (a0, a1) = ax.get_ylim(), alone.get_ylim()
        assert y1 < far[1]
        assert y1 - y0 < 1.5 * (a1 - a0)
        rod = r"$I_{\text{rod}}$ ("
        (named,) = [t for t in _texts(ax) if t.get_text().startswith(rod)]
        assert f"{far[0]:.3g}, {far[1]:.3g}) m" in named.get_text()
        # the arrow at the edge, where its name is, points at it (the centres at
        # infinity have arrows of their own)
        (arrow,) = [
            p
            for p in ax.patches
            if hasattr(p, "_posA_posB") and np.allclose(p._posA_posB[0], named.xy)
        ]
        tail, tip = np.array(arrow._posA_posB)
        way = (tip - tail) / np.hypot(*(tip - tail))
        toward = (far - tip) / np.hypot(*(far - tip))
        assert np.dot(way, toward) > 0.99
    finally:
        plt.close(ax.figure)
        plt.close(alone.figure)


@pytest.mark.parametrize("stem", ["sixbar", "slotted_lever"])
def test_the_lever_s_names_are_apart_and_off_the_arrows(stem: str) -> None:
    import matplotlib.pyplot as plt

    # the six-bar's three couples' names piled up at c, the shaper's loads'
    # names at e and f lay on each other and on the arrows
    table = assur.forces(assur.load(TRIAL / f"{stem}.toml"), [70.0])
    ax = lever.zhukovsky_lever(table)
    fig = ax.figure
    try:
        fig.canvas.draw()
        texts = [t for t in _texts(ax) if "sum = balancing load" not in t.get_text()]
        boxes = [_box(fig, t) for t in texts]
        arrows = [ax.transData.transform(np.array(p._posA_posB)) for p in ax.patches]
        frame = ax.bbox.extents
        for i, (text, box) in enumerate(zip(texts, boxes, strict=True)):
            name = text.get_text()
            assert _inside(box, frame), name
            for j in range(i + 1, len(texts)):
                assert not _overlap(box, boxes[j]), (name, texts[j].get_text())
            # a name crosses no arrow but (at most) its own; the pole's name is
            # where every image's arrow starts
            crossed = [k for k, a in enumerate(arrows) if _meets(box, *a)]
            assert len(crossed) <= 1 or name == "pole", name
    finally:
        plt.close(fig)


@pytest.mark.parametrize(
    "draw", [plans.velocity_plan, plans.acceleration_plan, lever.zhukovsky_lever]
)
def test_a_crank_rocker_s_plans_names_are_apart(draw) -> None:
    import matplotlib.pyplot as plt

    # a student's crank-rocker at 30 degrees: on the lever "g(coupler)" lay on
    # "g(crank)" and "m_crank g" on "m_coupler g", and at the pole (the rocker
    # nearly still) "o1 = o2", "b", "g(rocker)" and "m_rocker g" piled up; on
    # the velocity plan "b", "g(rocker)" and "o1 = o2" (boxes a pixel apart or
    # touching)
    table = assur.forces(assur.load(TRIAL / "crank_rocker.toml"), [30.0])
    ax = draw(table)
    fig = ax.figure
    try:
        fig.canvas.draw()
        texts = [t for t in _texts(ax) if "sum = balancing load" not in t.get_text()]
        boxes = [_box(fig, t) for t in texts]
        frame = ax.bbox.extents
        wrong = [t.get_text() for t, box in zip(texts, boxes, strict=True)
                 if not _inside(box, frame)]  # fmt: skip
        # boxes that touch read as one name: a point and a half apart at least
        space = 1.5 * fig.dpi / 72.0
        wrong += [
            (text.get_text(), texts[j].get_text())
            for i, (text, box) in enumerate(zip(texts, boxes, strict=True))
            for j in range(i + 1, len(texts))
            if _overlap(box + np.array([-space, -space, space, space]), boxes[j])
        ]
        # and none lies on an image's dot
        dots = [ax.transData.transform(np.column_stack(line.get_data()))[0]
                for line in ax.lines if line.get_marker() == "o"]  # fmt: skip
        wrong += [
            text.get_text()
            for text, box in zip(texts, boxes, strict=True)
            for dot in dots
            if _overlap(box, np.concatenate([dot - 2.0, dot + 2.0]))
        ]
        assert wrong == []
    finally:
        plt.close(fig)
