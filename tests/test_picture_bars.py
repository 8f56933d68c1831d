"""A link's name does not hide its bar: on a short bar it goes beside it.

The ten-bar's link 5 (G to F) is a few millimetres of drawing: its name, set on
the bar's middle, hid all of it between the joints' circles.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur import plotting
from assur.plotting._bars import BAR_LABELS, hidden_length, label_box

matplotlib.use("Agg")
import matplotlib.pyplot as plt

EXAMPLES = Path(__file__).parent.parent / "examples"


def _seen(ax, table, first: str, second: str) -> tuple[np.ndarray, np.ndarray]:  # type: ignore[no-untyped-def]
    """The part of bar ``first``-``second`` seen between its joints' circles, px."""
    p, q = (
        ax.transData.transform([table[f"{j}.x"][0], table[f"{j}.y"][0]])
        for j in (first, second)
    )
    # the joints' circles: 1.2 % of the mechanism's size (the drawing's ctx.r)
    r_data = 0.012 * float(table.plan.scale)
    r = abs(ax.transData.transform([r_data, 0])[0] - ax.transData.transform([0, 0])[0])
    u = (q - p) / np.hypot(*(q - p))
    return p + r * u, q - r * u


def test_hidden_length_by_hand() -> None:
    box = np.array([0.0, 0.0, 10.0, 10.0])
    a, b = np.array([-5.0, 5.0]), np.array([15.0, 5.0])
    assert hidden_length(box, a, b) == pytest.approx(10.0)
    assert hidden_length(box, a, np.array([5.0, 5.0])) == pytest.approx(5.0)
    assert hidden_length(box, np.array([-5.0, 20.0]), np.array([15.0, 20.0])) == 0.0
    # along an edge's direction, outside: nothing hidden
    assert hidden_length(box, np.array([20.0, -5.0]), np.array([20.0, 15.0])) == 0.0


def test_a_short_bar_keeps_its_name_beside_it() -> None:
    table = assur.kinematics(assur.load(EXAMPLES / "tenbar.toml"), [0.0])
    ax = plotting.draw(table)
    try:
        renderer = ax.figure.canvas.get_renderer()
        ax.figure.canvas.draw()
        (name,) = [t for t in ax.texts if t.get_text() == "5"]
        a, b = _seen(ax, table, "G", "F")
        assert hidden_length(label_box(name, renderer), a, b) == 0.0
    finally:
        plt.close(ax.figure)


@pytest.mark.parametrize(("stem", "angle"), [("tenbar", 0.0), ("whitworth", 60.0)])
def test_no_name_hides_most_of_its_bar(stem: str, angle: float) -> None:
    table = assur.kinematics(assur.load(EXAMPLES / f"{stem}.toml"), [angle])
    ax = plotting.draw(table)
    try:
        ax.figure.canvas.draw()
        renderer = ax.figure.canvas.get_renderer()
        names = [t for t in ax.texts if t in BAR_LABELS]
        assert names
        for name in names:
            ends = ax.transData.transform(np.array(BAR_LABELS[name][:2]))
            length = float(np.hypot(*(ends[1] - ends[0])))
            hidden = hidden_length(label_box(name, renderer), *ends)
            # the joints' circles hide the ends; the name may hide at most half
            # of the whole bar, circles included
            assert hidden <= 0.5 * length, name.get_text()
    finally:
        plt.close(ax.figure)


def test_a_joint_name_keeps_off_the_sliding_block() -> None:
    # "C, guide" was set over the slider's block, the block left out of what a
    # joint's name keeps clear of
    from assur.plotting._geometry import BLOCK_HALF

    table = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [45.0])
    ax = plotting.draw(table, forces=True)
    try:
        ax.figure.canvas.draw()
        renderer = ax.figure.canvas.get_renderer()
        (name,) = [t for t in ax.texts if t.get_text() == "C, guide"]
        size = float(table.plan.scale)
        # the guide is along x: the block is a rectangle about C, axis-aligned
        c = np.array([table["C.x"][0], table["C.y"][0]])
        half = np.array(BLOCK_HALF) * size
        low, high = ax.transData.transform(np.array([c - half, c + half]))
        box = label_box(name, renderer)
        apart = (
            box[2] <= low[0]
            or high[0] <= box[0]
            or box[3] <= low[1]
            or high[1] <= box[1]
        )
        assert apart, (box, low, high)
    finally:
        plt.close(ax.figure)
