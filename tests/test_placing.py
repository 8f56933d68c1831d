"""Names placed at once against every place, line and box: as one at a time did.

:func:`assur.plotting._placing.place_names` tries some hundred places for each
name against every line and every other named side. It measured them one named
side at a time, so that a mechanism with many links took minutes; it now measures
them all at once. The reference below is the measure as it was (one side at a
time, every box against every line), kept here to hold the new one to it bit for
bit: the places chosen for an ordinary mechanism are the same. And the number of
measures taken for a name no longer grows with the number of names.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

from assur.plotting import _placing
from assur.plotting._placing import (
    CLASH,
    PASSES,
    RIVAL,
    Name,
    _box_distances,
    _costs,
    _crossed,
    place_names,
)

matplotlib.use("Agg")


def _old_crossed(low: np.ndarray, high: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """Every box (``low``, ``high``) against every segment, as it was: (boxes, k).

    Each pair clipped, none passed over: the clipping is the one the new measure
    uses (:func:`_placing._clipped`), which the spatial pruning must not change.
    """
    n, k = len(low), len(segments)
    boxes, lines = np.repeat(np.arange(n), k), np.tile(np.arange(k), n)
    met = _placing._clipped(low[boxes], high[boxes], segments[lines])
    return met.reshape(n, k)


_old_distance = _placing._distance
"""Each point's distance from a segment: the measure the vectorisation left as it
was."""


def _old_box_distance(
    low: np.ndarray, high: np.ndarray, ends: np.ndarray
) -> np.ndarray:
    """Each box's distance from one segment, as it was."""
    corners = np.stack(
        [
            low,
            high,
            np.stack([low[:, 0], high[:, 1]], 1),
            np.stack([high[:, 0], low[:, 1]], 1),
        ],
        axis=1,
    )
    near = _old_distance(corners.reshape(-1, 2), ends).reshape(-1, 4).min(axis=1)
    for end in ends:
        near = np.minimum(near, np.hypot(*(end - np.clip(end, low, high)).T))
    crossed = _old_crossed(low, high, ends[None, :, :])[:, 0]
    return np.where(crossed, 0.0, near)


def _old_costs(centres, size, frame, boxes, segments, own, named, clear, half=0.0):
    """A name's cost at each place, one named side at a time, as it was."""
    low, high = centres - size / 2, centres + size / 2
    # the frame and the boxes are measured as they were (the vectorisation left
    # that part alone)
    cost = _placing._framed(low, high, frame, boxes)
    cost += CLASH * _old_crossed(low - half, high + half, segments).sum(axis=1)
    apart = np.array([_old_box_distance(low, high, s) for s in named])
    mine = apart[own]
    if len(named) > 1:
        rival = np.delete(apart, own, axis=0).min(axis=0)
        cost += RIVAL * (rival <= mine)
        cost += 20.0 * np.clip(clear - rival, 0.0, None)
    return (
        cost
        + 0.05 * _old_distance(centres, named[own])
        + np.arange(len(centres)) * 1e-3
    )


def _segments(rng: np.random.Generator, k: int) -> np.ndarray:
    """Return ``k`` segments (display): slanted, level, upright, points, joined."""
    tails = rng.uniform(0.0, 400.0, (k, 2))
    heads = tails + rng.normal(0.0, 60.0, (k, 2))
    kind = rng.integers(0, 5, k)
    heads[kind == 1, 1] = tails[kind == 1, 1]  # level
    heads[kind == 2, 0] = tails[kind == 2, 0]  # upright
    heads[kind == 3] = tails[kind == 3]  # a point
    joined = np.flatnonzero(kind == 4)  # starts where another ends (forces at a joint)
    tails[joined] = heads[rng.integers(0, k, len(joined))]
    return np.round(np.stack([tails, heads], axis=1), rng.integers(0, 3))


def _boxes(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Return ``n`` boxes' low and high corners (display), some on a grid."""
    low = np.round(rng.uniform(-20.0, 420.0, (n, 2)), rng.integers(0, 3))
    return low, low + np.round(rng.uniform(0.0, 40.0, (n, 2)), 1)


@pytest.mark.parametrize("seed", range(12))
def test_crossed_is_every_box_against_every_line_as_it_was(seed: int) -> None:
    rng = np.random.default_rng(seed)
    segments = _segments(rng, 150)
    low, high = _boxes(rng, 120)
    # boxes round the ends exactly, where a line only touches them
    low[:20], high[:20] = segments[:20, 1] - 5.0, segments[:20, 1]
    met = _crossed(low, high, segments)
    assert met.shape == (120, 150)
    np.testing.assert_array_equal(met, _old_crossed(low, high, segments))


@pytest.mark.parametrize("seed", range(12))
def test_box_distances_are_those_one_side_at_a_time_to_the_bit(seed: int) -> None:
    rng = np.random.default_rng(seed)
    segments = _segments(rng, 60)
    low, high = _boxes(rng, 130)
    reference = np.array([_old_box_distance(low, high, s) for s in segments])
    # equal, not close: a rival as near as the name's own is shunned (``<=``)
    np.testing.assert_array_equal(_box_distances(low, high, segments), reference)


@pytest.mark.parametrize("seed", range(12))
def test_costs_are_those_one_side_at_a_time_to_the_bit(seed: int) -> None:
    rng = np.random.default_rng(seed)
    named = _segments(rng, 40)
    segments = np.concatenate([named, _segments(rng, 200)])
    centres = rng.uniform(0.0, 400.0, (120, 2))
    size = np.array([24.0, 11.5])
    boxes = np.concatenate([np.concatenate(_boxes(rng, 30), axis=1),
                            np.full((3, 4), np.nan)])  # fmt: skip
    args = (centres, size, np.array([1.0, 1.0, 399.0, 399.0]), boxes, segments)
    for own in (0, 17, 39):
        new = _costs(*args, own, named, 10.0, 3.0)
        np.testing.assert_array_equal(new, _old_costs(*args, own, named, 10.0, 3.0))


def test_the_measures_taken_for_a_name_do_not_grow_with_the_names(monkeypatch) -> None:
    """Each place of each name is measured in two calls, however many names there
    are; and only the lines near a place are clipped against it."""
    import matplotlib.pyplot as plt

    calls = {"crossed": 0, "pairs": 0, "clipped": 0}
    crossed, clipped = _placing._crossed, _placing._clipped

    def counted(low, high, segments):
        calls["crossed"] += 1
        calls["pairs"] += len(low) * len(segments)
        return crossed(low, high, segments)

    def counted_clip(low, high, ends):
        calls["clipped"] += len(low)
        return clipped(low, high, ends)

    monkeypatch.setattr(_placing, "_crossed", counted)
    monkeypatch.setattr(_placing, "_clipped", counted_clip)
    rng = np.random.default_rng(3)
    fig, ax = plt.subplots(figsize=(12, 12))
    try:
        ax.set_xlim(0.0, 20.0)
        ax.set_ylim(0.0, 20.0)
        tails = rng.uniform(1.0, 19.0, (90, 2))
        heads = tails + rng.normal(0.0, 0.6, (90, 2))
        pairs = enumerate(zip(tails, heads, strict=True))
        names = [Name(ax.text(*t, f"$F_{{{i}}}$"), t, h) for i, (t, h) in pairs]
        lines = np.stack([rng.uniform(0.0, 20.0, (300, 2))] * 2, axis=1)
        lines[:, 1] += rng.normal(0.0, 1.0, (300, 2))
        place_names(ax, names, lines)
        assert calls["crossed"] == 2 * PASSES * len(names)
        assert calls["clipped"] < 0.05 * calls["pairs"]
        frame = ax.bbox.extents
        for name in names:
            x, y = ax.transData.transform(name.text.get_position())
            assert frame[0] < x < frame[2]
            assert frame[1] < y < frame[3]
    finally:
        plt.close(fig)


@pytest.mark.parametrize("seed", range(8))
def test_a_place_is_measured_against_the_named_sides_near_it_only(
    seed: int, monkeypatch
) -> None:
    """The places round one side of a crowd spread far: only the nearby sides are
    measured, and the costs are those of every side measured, to the bit."""
    rng = np.random.default_rng(seed)
    named = _segments(rng, 400) * 10.0  # over 4000 display units
    segments = np.concatenate([named, _segments(rng, 100) * 10.0])
    boxes = np.concatenate(_boxes(rng, 30), axis=1) * 10.0
    frame = np.array([1.0, 1.0, 3999.0, 3999.0])
    size = np.array([24.0, 11.5])
    measured = []
    distances = _placing._box_distances

    def counted(low, high, segments):
        measured.append(len(segments))
        return distances(low, high, segments)

    monkeypatch.setattr(_placing, "_box_distances", counted)
    for own in (0, 123, 399):
        centres = _placing._candidates(named[own], size, None, 4.0)
        args = (centres, size, frame, boxes, segments, own, named, 10.0, 3.0)
        new = _costs(*args)
        np.testing.assert_array_equal(new, _old_costs(*args))
    # the own side and those round it, not the 400
    assert max(measured) < len(named) / 4
