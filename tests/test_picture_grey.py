"""Pictures read on grey paper or by a colour-blind reader.

Series of one picture that a legend tells apart must differ by more than hue: the
paths of points share no marks with their neighbours.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib as mpl
import pytest

import assur
from assur import plotting
from assur.plotting._style import PATH_MARK_SPACING

mpl.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"


@pytest.fixture
def six_bar() -> assur.Table:
    """The lecture's six-bar over a coarse sweep."""
    return assur.kinematics(
        assur.load(EXAMPLES / "six_bar_lecture.toml"), [30.0, 120.0, 210.0, 300.0]
    )


def test_the_paths_of_points_differ_by_their_marks(six_bar: assur.Table) -> None:
    # the paths of B, C, E and F were all plain lines in blue, red, green and
    # purple: red and green (C, E), blue and purple (B, F) look alike to a
    # deuteranope, and all four print as nearly one grey
    import matplotlib.pyplot as plt

    ax = plotting.plot_paths(six_bar)
    try:
        paths = [ln for ln in ax.lines if not ln.get_label().startswith("_")]
        assert [ln.get_label() for ln in paths] == ["B", "C", "E", "F"]
        marks = [ln.get_marker() for ln in paths]
        assert len(set(marks)) == 4
        # spaced along the path, not one on each of the sweep's positions
        assert {ln.get_markevery() for ln in paths} == {PATH_MARK_SPACING}
        # the legend draws each key as its path, with its mark
        keys = [ln.get_marker() for ln in ax.get_legend().get_lines()]
        assert keys == marks
    finally:
        plt.close(ax.figure)
