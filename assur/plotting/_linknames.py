"""A link's name moved along its bar, or beside it, off the loads' arrows.

A link's name goes on its bar's middle (:func:`assur.plotting._labels._label_link`),
where a uniform bar's centre of mass is, and so where its inertia force and couple
start: on a picture with loads the name's box hid them. :func:`clear_arrows` moves
each link's name an arrow passes under to the first of its places that no arrow,
joint's circle or other name meets.
"""

from __future__ import annotations

import weakref
from typing import Any

import numpy as np

from assur.plotting._bars import (
    BAR_WIDTH,
    HIDDEN_SHARE,
    ROOM,
    bar_seen,
    hidden_length,
    label_box,
    root_figure,
    settled_renderer,
)
from assur.plotting._placing import BARRED, CLASH, _crossed

SPOTS: weakref.WeakKeyDictionary[Any, tuple[np.ndarray, np.ndarray | None, float]] = (
    weakref.WeakKeyDictionary()
)
"""Where each link's name may go (k, 2), m, with its bar's ends (2, 2), m, when
the link is a bar (None for a plate or a block), and its joints' radius, m."""
ALONG = (0.5, 0.36, 0.64, 0.25, 0.75, 0.15, 0.85)
"""Where along its bar a link's name is tried, from the bar's first end."""
MARGIN = 1.0
"""Room kept between a name's box and an arrow, points (an arrow's half-width)."""


def note_spots(text: Any, spots: Any, ends: Any, joint: float) -> None:
    """Note the places (m) ``text`` may go, its bar's ``ends`` (m) and ``joint`` (m)."""
    bar = None if ends is None else np.asarray(ends, dtype=float)
    SPOTS[text] = (np.asarray(spots, dtype=float).reshape(-1, 2), bar, joint)


def clear_arrows(ax: Any, keep: Any = ()) -> None:
    """Move each link's name on ``ax`` that an arrow passes under off the arrows.

    Tried in turn: the places along its bar (:data:`ALONG`), each on the bar and
    then square to it on either side; a plate's or a block's own places. The first
    that meets no arrow, joint's circle or other name wins, else the one meeting
    fewest. Names in ``keep`` (the loads', placed afterwards) are not kept clear of.
    """
    texts = [t for t in ax.texts if t in SPOTS and t.get_visible() and t.get_text()]
    if not texts or not any(hasattr(p, "points") for p in ax.patches):
        return
    # the names moved here and the loads' (placed next) do not resize the axes:
    # had they, the arrows would move from under the places measured
    for text in [*texts, *(t for t in ax.texts if t in keep)]:
        text.set_in_layout(False)
    renderer = settled_renderer(ax)
    # measured once the layout is settled: the display units change with it
    arrows, owner = _arrow_segments(ax)
    pixels = root_figure(ax).dpi / 72.0
    margin = MARGIN * pixels
    for text in texts:
        box = label_box(text, renderer)
        if not _crossed(box[None, :2] - margin, box[None, 2:] + margin, arrows).any():
            continue
        others = [label_box(t, renderer) for t in ax.texts
                  if t is not text and t not in keep and t.get_visible()
                  and t.get_text()]  # fmt: skip
        others += [p.get_window_extent(renderer).extents for p in _circles(ax)]
        centres, on_bar = _places(ax, text, box, pixels)
        size = box[2:] - box[:2]
        low, high = centres - size / 2, centres + size / 2
        met = _crossed(low - margin, high + margin, arrows)
        # an arrow is met once, however many segments of its arc the box meets
        hit = np.array([np.unique(owner[row]).size for row in met])
        cost = CLASH * hit + CLASH * _overlaps(low, high, np.array(others))
        cost += CLASH * _hides(ax, text, low, high) * on_bar
        frame = np.asarray(ax.bbox.extents)
        cost += BARRED * ((low < frame[:2]) | (high > frame[2:])).any(axis=1)
        best = centres[int(np.argmin(cost + np.arange(len(centres)) * 1e-3))]
        at = ax.transData.transform(text.get_position()) + best - (box[:2] + size / 2)
        text.set_position(tuple(ax.transData.inverted().transform(at)))


def _arrow_segments(ax: Any) -> tuple[np.ndarray, np.ndarray]:
    """Return the arrows' segments (k, 2, 2), display, and each one's arrow's index."""
    segments, owner = [], []
    for k, patch in enumerate(p for p in ax.patches if hasattr(p, "points")):
        ends = ax.transData.transform(np.asarray(patch.points, dtype=float))
        segments += [ends[i : i + 2] for i in range(len(ends) - 1)]
        owner += [k] * (len(ends) - 1)
    return np.array(segments).reshape(-1, 2, 2), np.array(owner, dtype=int)


def _circles(ax: Any) -> list[Any]:
    """Return the joints' circles of ``ax``."""
    from matplotlib.patches import Circle

    return [p for p in ax.patches if isinstance(p, Circle)]


def _places(
    ax: Any, text: Any, box: np.ndarray, pixels: float
) -> tuple[np.ndarray, np.ndarray]:
    """Return the centres (display) tried for ``text`` and whether each is on a bar.

    Along a bar, each place on it and then beside it either way, clear of the bar
    by half its width and :data:`assur.plotting._bars.ROOM`.
    """
    spots, ends, _ = SPOTS[text]
    if ends is None:
        centres = ax.transData.transform(spots)
        return centres, np.zeros(len(centres), bool)
    a, b = ax.transData.transform(ends)
    length = float(np.hypot(*(b - a)))
    n = np.array([0.0, 1.0]) if length == 0 else np.array([a[1] - b[1], b[0] - a[0]])
    n = n / max(float(np.hypot(*n)), 1e-12)
    size = box[2:] - box[:2]
    half = 0.5 * (abs(n[0]) * size[0] + abs(n[1]) * size[1])
    off = half + (0.5 * BAR_WIDTH + ROOM) * pixels
    centres, on_bar = [], []
    for t in ALONG:
        p = a + t * (b - a)
        centres += [p, p + off * n, p - off * n]
        on_bar += [True, False, False]
    return np.array(centres), np.array(on_bar)


def _overlaps(low: np.ndarray, high: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Return how many of ``boxes`` (x0, y0, x1, y1) each box (low, high) overlaps."""
    if not len(boxes):
        return np.zeros(len(low))
    wide = np.minimum(high[:, None, 0], boxes[None, :, 2]) - np.maximum(
        low[:, None, 0], boxes[None, :, 0]
    )
    tall = np.minimum(high[:, None, 1], boxes[None, :, 3]) - np.maximum(
        low[:, None, 1], boxes[None, :, 1]
    )
    return ((wide > 0) & (tall > 0)).sum(axis=1)


def _hides(ax: Any, text: Any, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """Return whether each box hides more than its share of ``text``'s bar."""
    _, ends, joint = SPOTS[text]
    if ends is None:
        return np.zeros(len(low), bool)
    a, b = bar_seen(ax, ends[0], ends[1], joint)
    length = float(np.hypot(*(b - a)))
    hidden = [hidden_length(np.concatenate([lo, hi]), a, b)
              for lo, hi in zip(low, high, strict=True)]  # fmt: skip
    return np.array(hidden) > HIDDEN_SHARE * length
