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
from assur.plotting import polygons

matplotlib.use("Agg")

TRIAL = Path(__file__).parent / "data" / "plans"


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
        # the polygon still closes: the sides left out are nothing
        assert "closes within 0.0e+00 mm" in ax.get_title()
    finally:
        plt.close(fig)
