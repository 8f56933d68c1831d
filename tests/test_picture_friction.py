"""Friction circles are drawn large enough to see, and the legend says by how much.

On the slider-crank with friction (radii f r of 0.6 to 1 mm on a 0.25 m drawing)
the circles were drawn to scale: about a pixel, inside the joints' circles.
"""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur import plotting

matplotlib.use("Agg")
import matplotlib.pyplot as plt

EXAMPLES = Path(__file__).parent.parent / "examples"
SMALLEST_POINTS = 4.0
"""Radius a friction circle must have on the page, points (1/72 inch)."""


def _circles(ax):  # type: ignore[no-untyped-def]
    """The friction circles drawn on ``ax``."""
    return [p for p in ax.patches if (p.get_gid() or "").startswith("friction-circle")]


def _radius_points(ax, circle) -> float:  # type: ignore[no-untyped-def]
    """The radius of ``circle`` on the page, points."""
    fig = ax.figure
    fig.canvas.draw()
    centre = np.asarray(circle.center)
    ends = ax.transData.transform([centre, centre + np.array([circle.get_radius(), 0])])
    return float(np.hypot(*(ends[1] - ends[0]))) * 72.0 / fig.dpi


@pytest.mark.parametrize("group", [None, 0])
def test_friction_circles_are_seen(group: int | None) -> None:
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_friction.toml"), [45.0])
    if group is None:
        ax = plotting.draw(table, forces=True)
    else:
        ax = plotting.draw_free_body(table, group)
    try:
        circles = _circles(ax)
        assert circles
        for circle in circles:
            assert _radius_points(ax, circle) >= SMALLEST_POINTS
        entries = [t.get_text() for t in ax.get_legend().get_texts()]
        (entry,) = [e for e in entries if e.startswith("friction circle")]
        # by a round factor, stated: the slider-crank's 0.6 mm need ten times
        assert entry.startswith("friction circle ×10 ")
    finally:
        plt.close(ax.figure)


def test_a_large_friction_circle_is_drawn_to_scale(tmp_path: Path) -> None:
    # a circle already large enough is not enlarged, nor said to be
    text = (EXAMPLES / "slider_crank_friction.toml").read_text(encoding="utf-8")
    path = tmp_path / "big.toml"
    path.write_text(re.sub(r"radius = [0-9.]+", "radius = 0.1", text), encoding="utf-8")
    mech = assur.load(path)
    table = assur.forces(mech, [45.0])
    ax = plotting.draw(table, forces=True)
    try:
        rubbing = [j for j in mech.joints if j.kind == "revolute" and j.friction]
        got = sorted(c.get_radius() for c in _circles(ax))
        assert got == pytest.approx(sorted(j.friction * j.radius for j in rubbing))
        entries = [t.get_text() for t in ax.get_legend().get_texts()]
        assert "friction circle (dashed), reaction tangent" in entries
    finally:
        plt.close(ax.figure)
