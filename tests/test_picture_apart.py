"""Arrows on one line drawn apart (assur.plotting._apart), checked by hand."""

from __future__ import annotations

import itertools

import numpy as np

from assur.plotting._apart import moved


def _chain(points: list[tuple[float, float]], step: float) -> list[np.ndarray]:
    """Draw the chain of arrows through ``points``, each moved as it must be."""
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    for a, b in itertools.pairwise(points):
        drawn.append(moved(drawn, np.array(a), np.array(b), step, 0.2 * step))
    return [np.array(ends) for ends in drawn]


def _apart_on_one_line(arrows: list[np.ndarray], near: float) -> None:
    """Horizontal arrows at one height (within ``near``) share no span."""
    for i, a in enumerate(arrows):
        for b in arrows[i + 1 :]:
            if abs(a[0, 1] - b[0, 1]) < near:
                low = max(a[:, 0].min(), b[:, 0].min())
                high = min(a[:, 0].max(), b[:, 0].max())
                assert high - low < near, (a, b)


def test_four_sides_on_one_line_each_at_a_height_of_its_own() -> None:
    # a step aside once put the 2nd and the 4th side on each other at -1.2
    arrows = _chain([(0, 0), (10, 0), (3, 0), (8, 0), (2, 0)], 1.2)
    _apart_on_one_line(arrows, 0.24)
    assert np.allclose(arrows[0], [[0, 0], [10, 0]])  # the first stays
    heights = sorted(a[0, 1] for a in arrows)
    assert all(abs(h) <= 3 * 1.2 + 1e-12 for h in heights)


def test_a_short_arrow_back_over_a_long_one_at_a_slight_angle_is_moved() -> None:
    # 0.07 mm off at one end and on the line at the other: it was not seen as on
    # the long one because the distance was taken at the long one's far ends
    long = (np.array([0.0, 0.0]), np.array([10.0, 0.0]))
    start, end = np.array([6.0, 0.07]), np.array([2.0, 0.0])
    moved_start, moved_end = moved([long], start, end, 1.2, 0.24)
    offset = moved_start - start
    assert np.allclose(moved_end - end, offset)
    assert np.hypot(*offset) > 1.0  # a step aside, not where it was
    # and the long one drawn second is moved off the short one as well
    drawn = [(start, end)]
    moved_long = moved(drawn, *long, 1.2, 0.24)
    assert not np.allclose(moved_long[0], long[0])


def test_arrows_apart_or_short_stay_where_they_are() -> None:
    a = (np.array([0.0, 0.0]), np.array([10.0, 0.0]))
    # beside it by more than near, end to end, across it, shorter than near
    for start, end in (
        ((0.0, 1.0), (10.0, 1.0)),
        ((10.0, 0.0), (15.0, 0.0)),
        ((5.0, -3.0), (5.0, 3.0)),
        ((4.0, 0.0), (4.1, 0.0)),
    ):
        s, e = np.array(start), np.array(end)
        got = moved([a], s, e, 1.2, 0.24)
        assert np.allclose(got[0], s)
        assert np.allclose(got[1], e)


def test_arrows_on_a_slanted_line():
    """By hand, off the axes (where a sign of the cross product cannot show): a
    short arrow on the diagonal lies on a long one; one 0.15 off at its start and
    on the line at its end does not, within 0.11."""
    from assur.plotting._apart import lies_on

    diagonal = (np.array([0.0, 0.0]), np.array([1.0, 1.0]))
    on = (np.array([0.2, 0.2]), np.array([0.8, 0.8]))
    assert lies_on(diagonal, on, 0.01)
    level = (np.array([0.0, 0.0]), np.array([10.0, 0.0]))
    leaning = (np.array([2.0, 0.15]), np.array([8.0, 0.0]))
    assert not lies_on(level, leaning, 0.11)
    assert lies_on(level, leaning, 0.16)
