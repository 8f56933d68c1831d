"""The instant centres' picture: names with subscripts, Kennedy's lines drawn."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.explain._solve import position
from assur.plotting import plans
from assur.plotting._centres import _pins, centres_at_infinity, kennedy_lines

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"
TRIAL = Path(__file__).parent / "data" / "plans"


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


def test_centres_merely_near_are_named_each_at_its_own_dot() -> None:
    import matplotlib.pyplot as plt

    # I_crank,left_rocker 6.7 mm (2 % of the size) from I_crank,rod was named in
    # the latter's label, its own dot left unnamed
    pos = position(assur.load(EXAMPLES / "class3.toml"), 40.0)
    ax = plans.instant_centres(pos.table)
    try:
        names = [t.get_text() for t in ax.texts if t.get_text().startswith("$I")]
        assert r"$I_{\text{crank},\text{rod}}$" in names
        assert r"$I_{\text{crank},\text{left_rocker}}$" in names
        assert not [n for n in names if ", $I" in n]
    finally:
        plt.close(ax.figure)


def test_centres_at_infinity_are_named_with_their_direction() -> None:
    import matplotlib.pyplot as plt

    # the Scotch yoke showed three of its six centres: those at infinity had no
    # mark, name or note
    pos = position(assur.load(EXAMPLES / "scotch_yoke.toml"), 30.0)
    ax = plans.instant_centres(pos.table)
    try:
        named = [t for t in ax.texts if "at infinity" in t.get_text()]
        said = sorted(t.get_text() for t in named)
        # each arrow at the frame's edge along the direction its name gives
        for text in named:
            (arrow,) = [
                p
                for p in ax.patches
                if hasattr(p, "_posA_posB") and np.allclose(p._posA_posB[0], text.xy)
            ]
            tail, tip = np.array(arrow._posA_posB)
            angle = float(text.get_text().rpartition(", ")[2].rstrip("°"))
            way = np.degrees(np.arctan2(*(tip - tail)[::-1]))
            assert way == pytest.approx(angle, abs=1e-6)
    finally:
        plt.close(ax.figure)
    # the yoke translates along the guide, the block with the crank's pin, and the
    # block slides in the yoke's upright slot
    assert said == [
        r"$I_{\text{block},\text{yoke}}$ at infinity, 0°",
        r"$I_{\text{block}}$ at infinity, 30°",
        r"$I_{\text{yoke}}$ at infinity, 90°",
    ]


def _sliding(path: Path, angle: float):
    """The solved mechanism, its finite centres, their pins, the infinite ones."""
    pos = position(assur.load(path), angle)
    every = plans.relative_centres(pos)
    centres = {k: p for k, p in every.items() if p is not None}
    return pos, centres, _pins(pos), centres_at_infinity(pos, every)


def _sine(a: np.ndarray, b: np.ndarray) -> float:
    """The sine of the angle between directions ``a`` and ``b``."""
    return float(abs(a[0] * b[1] - a[1] * b[0]) / np.hypot(*a) / np.hypot(*b))


@pytest.mark.parametrize("angle", [30.0, 45.0, 120.0, 250.0])
def test_a_slider_crank_s_rod_centre_is_square_above_its_slider(angle: float) -> None:
    # Aronhold-Kennedy with the guide's centre at infinity: I_rod is on the line
    # through C square to the slide, I_crank,slider on the one through A
    path = EXAMPLES / "slider_crank_exercise.toml"
    table = assur.kinematics(assur.load(path), [angle])
    np.testing.assert_allclose(table["rod.ic.x"], table["C.x"], atol=1e-12)
    assert np.isnan(table["slider.ic.x"]).all()
    _, centres, _, far = _sliding(path, angle)
    # ground 0, crank 1, rod 2, slider 3
    assert set(far) == {(0, 3)}
    np.testing.assert_allclose(np.abs(far[(0, 3)]), [0.0, 1.0], atol=1e-12)
    np.testing.assert_allclose(centres[(1, 3)][0], 0.0, atol=1e-12)


SLIDING = [
    (EXAMPLES / "slider_crank_exercise.toml", 45.0),
    (EXAMPLES / "offset_slider_crank.toml", 70.0),
    (EXAMPLES / "scotch_yoke.toml", 70.0),
    (TRIAL / "inclined.toml", 70.0),
    (TRIAL / "inverted.toml", 70.0),
    (EXAMPLES / "lever_var9.toml", 70.0),
]
"""Mechanisms with a sliding pair, and a position where a centre is found by a
line through a centre at infinity."""


@pytest.mark.parametrize(
    ("path", "angle"),
    [*SLIDING, (EXAMPLES / "whitworth.toml", 45.0)],
    ids=lambda v: getattr(v, "stem", v),
)
def test_a_centre_at_infinity_is_on_one_line_with_two_others(
    path: Path, angle: float
) -> None:
    # Aronhold-Kennedy: I_jk, I_im and I_ij at infinity (direction d) are on one
    # line, so I_jk - I_im is parallel to d
    pos, centres, _, far = _sliding(path, angle)
    checked = 0
    for (j, k), p in centres.items():
        for f, d in far.items():
            if len(set(f) & {j, k}) != 1:
                continue
            (i,) = set(f) - {j, k}
            (m,) = {j, k} - set(f)
            q = centres.get((min(i, m), max(i, m)))
            if q is not None and np.hypot(*(p - q)) > 1e-6 * pos.size():
                assert _sine(p - q, d) < 1e-7, ((j, k), f)
                checked += 1
    assert checked


@pytest.mark.parametrize(
    ("path", "angle"), SLIDING, ids=lambda v: getattr(v, "stem", v)
)
def test_a_kennedy_line_through_a_centre_at_infinity_is_parallel_to_it(
    path: Path, angle: float
) -> None:
    # a sliding pair's centre, at infinity square to the slide, gave no line: the
    # slider-crank's I_rod and I_crank,slider were each found by one line only
    pos, centres, pins, far = _sliding(path, angle)
    size = pos.size()
    finite = [tuple(c) for c in centres.values()]
    through = 0
    for key in set(centres) - pins:
        lines = kennedy_lines(key, centres, pins, size, far)
        assert lines, key
        for line in lines:
            np.testing.assert_array_equal(line[2], centres[key])
            assert _on_one_line(line, size), key
            ends = [p for p in line[:2] if tuple(p) not in finite]
            if ends:
                # it stands far off, along the direction of a centre at infinity
                way = ends[0] - line[2]
                assert np.hypot(*way) > 100 * size
                assert min(_sine(way, d) for d in far.values()) < 1e-9, key
                through += 1
        # the lines of finite centres alone come first, as they were
        alone = kennedy_lines(key, centres, pins, size)
        for old, new in zip(alone, lines, strict=False):
            np.testing.assert_array_equal(old, new)
    assert through


def test_the_slider_crank_s_picture_draws_the_lines_through_the_slide() -> None:
    import matplotlib.pyplot as plt

    path = EXAMPLES / "slider_crank_exercise.toml"
    ax = plans.instant_centres(assur.kinematics(assur.load(path), [45.0]))
    try:
        dashed = [ln.get_xydata() for ln in ax.lines if ln.get_gid() == "kennedy"]
        # I_rod and I_crank,slider, each found by two lines: one of them runs
        # through the guide's centre, square to the slide (here upright)
        assert len(dashed) == 4
        up = np.array([0.0, 1.0])
        upright = sorted(
            (d for d in dashed if _sine(d[1] - d[0], up) < 1e-12), key=lambda d: d[0, 0]
        )
        # through A and I_crank,slider; through C and I_rod (ground 0, crank 1,
        # rod 2, slider 3)
        _, centres, *_ = _sliding(path, 45.0)
        assert len(upright) == 2
        for d, keys in zip(upright, [((0, 1), (1, 3)), ((2, 3), (0, 2))], strict=True):
            for key in keys:
                np.testing.assert_allclose(d[:, 0], centres[key][0], atol=1e-12)
                assert d[:, 1].min() <= centres[key][1] <= d[:, 1].max()
            # from the finite centre through the one it finds, and out of the view
            assert d[:, 1].max() > ax.get_ylim()[1]
        # drawn as the other Kennedy lines are: thin, light, dashed, under the rest
        styles = {(ln.get_linewidth(), ln.get_color(), ln.get_zorder())
                  for ln in ax.lines if ln.get_gid() == "kennedy"}  # fmt: skip
        assert len(styles) == 1
    finally:
        plt.close(ax.figure)
