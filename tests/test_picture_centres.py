"""The instant centres' picture: names with subscripts, Kennedy's lines drawn."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.explain._solve import position
from assur.plotting import plans
from assur.plotting._centres import _pins, kennedy_lines

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"


def _on_one_line(points: np.ndarray, size: float) -> bool:
    """Whether the three ``points`` (m) are on one line, to round-off."""
    a, b, c = points
    d = b - a
    gap = abs(d[0] * (c - a)[1] - d[1] * (c - a)[0]) / np.hypot(*d)
    return bool(gap <= 1e-9 * max(size, float(np.abs(points).max())))


def test_a_four_bar_s_centres_are_found_from_its_pins() -> None:
    pos = position(assur.load(EXAMPLES / "four_bar.toml"), 60.0)
    centres = {k: p for k, p in plans.relative_centres(pos).items() if p is not None}
    pins = _pins(pos)
    # ground 0, crank 1, coupler 2, rocker 3: I13 from I01, I03 and I12, I23
    lines = kennedy_lines((1, 3), centres, pins, pos.size())
    found = [{tuple(line[0]), tuple(line[1])} for line in lines]
    assert {tuple(centres[(0, 1)]), tuple(centres[(0, 3)])} in found
    assert {tuple(centres[(1, 2)]), tuple(centres[(2, 3)])} in found
    assert len(lines) == 2


@pytest.mark.parametrize("stem", ["four_bar", "six_bar_lecture", "tenbar"])
def test_every_centre_not_a_pin_has_two_kennedy_lines_through_it(stem: str) -> None:
    pos = position(assur.load(EXAMPLES / f"{stem}.toml"), 45.0)
    centres = {k: p for k, p in plans.relative_centres(pos).items() if p is not None}
    pins = _pins(pos)
    for key in set(centres) - pins:
        lines = kennedy_lines(key, centres, pins, pos.size())
        assert lines, key
        for line in lines:
            np.testing.assert_array_equal(line[2], centres[key])
            assert _on_one_line(line, pos.size()), key


def test_the_picture_draws_kennedy_lines_and_names_with_subscripts() -> None:
    import matplotlib.pyplot as plt

    # the names read "Icrank-coupler" as plain text, and no line showed how
    # I_crank,rocker and I_coupler were found
    table = assur.kinematics(assur.load(EXAMPLES / "four_bar.toml"), [60.0])
    ax = plans.instant_centres(table)
    try:
        dashed = [line for line in ax.lines if line.get_gid() == "kennedy"]
        # two centres not at a pin (I_coupler, I_crank,rocker), two lines each
        assert len(dashed) == 4
        points = [line for line in ax.lines if line.get_zorder() == 9]
        assert all(line.get_zorder() < points[0].get_zorder() for line in dashed)
        names = [t.get_text() for t in ax.texts if t.get_text().startswith("$I")]
        assert r"$I_{\text{crank},\text{coupler}}$" in names
        assert r"$I_{\text{crank}}$" in names
        assert not [t.get_text() for t in ax.texts if "-" in t.get_text()]
    finally:
        plt.close(ax.figure)
