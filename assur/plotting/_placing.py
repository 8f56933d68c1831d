"""Names put where they are read as their own: beside their side or point, clear.

Each name tries places round what it names (a side of a force polygon, an image,
an instant centre) and takes the one that costs least: a place past the axes'
frame, over another name or across a line drawn is (nearly) barred, one nearer to
another side or point than its own is shunned, and of the rest the nearest wins.
Measured on the drawing as it will be seen, in display units.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur.plotting._bars import label_box, root_figure, settle_without

BARRED = 1e6
"""Cost of a place that cuts a name off at the axes' frame."""
CLASH = 1e4
"""Cost of each name overlapped, or line crossed, by a name at a place."""
RIVAL = 3e3
"""Cost of a place nearer another named side or point than the name's own."""
GAP = 4.0
"""Room left between a name and what it names, points."""
SPACE = 2.0
"""Room left between two names, points: boxes that touch read as one name."""
RINGS = (1.0, 3.0, 7.0, 14.0)
"""The distances tried (times :data:`GAP`, past the name's own half-size)."""
CLEAR = 10.0
"""A name nearer than this (points) to another side or point than its own is
shunned, the more the nearer."""
PASSES = 2
"""Rounds in which every name is put at its best place, the others where they are."""
LEADER = 14.0
"""A name farther than this (points) from what it names is joined to it by a line."""
ALONG = (0.5, 0.38, 0.62, 0.26, 0.74, 0.14, 0.86)
"""Where along a side its name is tried, from its tail (its middle first)."""


@dataclass(frozen=True, slots=True)
class Name:
    """A name to place: its text and what it names, a segment (data coordinates).

    A point is a segment of no length. ``away``, when given, is a point (data)
    the name rather stands away from (a polygon's centroid: its sides' names go
    outside it). A name whose ``rival`` is false (a joint's, beside the forces
    at it) does not keep the others from coming near what it names; one that
    ``shuns`` nothing (a joint's again) may come nearer the others' than its own.
    A name with a ``tip`` (an arrow's, at ``end``) is tried round it too.
    """

    text: Any
    start: np.ndarray
    end: np.ndarray
    away: np.ndarray | None = None
    rival: bool = True
    shuns: bool = True
    tip: bool = False


def place_names(
    ax: Any,
    names: list[Name],
    lines: np.ndarray | None = None,
    avoid: list[Any] | None = None,
    width: float = 0.0,
    renderer: Any = None,
) -> None:
    """Put every name of ``names`` at its best place on ``ax``, in turn (twice).

    ``lines`` are segments (k, 2, 2), data coordinates, that no name may cross,
    beside the named sides themselves; the other texts of ``ax``, its legend and
    the artists ``avoid`` (markers, small patches) are kept clear of, and the
    lines by half their ``width`` (points: a link's bar is broad). The names do
    not resize the axes. ``renderer``, when given, is a renderer of the figure
    laid out without ``names`` (``_bars.settle_without``'s): the names of many
    axes of one figure are then placed in one layout.
    """
    if not names:
        return
    if renderer is None:
        renderer = settle_without(ax, [n.text for n in names])
    to_display = ax.transData.transform
    own = np.array([to_display([n.start, n.end]) for n in names])
    others = np.empty((0, 2, 2)) if lines is None else np.asarray(lines, float)
    segments = np.concatenate(
        [own, to_display(others.reshape(-1, 2)).reshape(-1, 2, 2)]
    )
    placed = {id(n.text) for n in names}
    fixed = [label_box(t, renderer) for t in ax.texts
             if t.get_visible() and t.get_text() and id(t) not in placed]  # fmt: skip
    legend = ax.get_legend()
    if legend is not None:
        fixed.append(np.asarray(legend.get_window_extent(renderer).extents))
    fixed += [np.asarray(a.get_window_extent(renderer).extents) for a in avoid or ()]
    kept = np.array(fixed, float).reshape(-1, 4)
    sizes = np.array([_size(n.text, renderer) for n in names])
    rivals = np.array([n.rival for n in names])
    boxes = np.full((len(names), 4), np.nan)
    pixels = root_figure(ax).dpi / 72.0
    frame = np.asarray(ax.bbox.extents) + np.array([1.0, 1.0, -1.0, -1.0])
    for _ in range(PASSES):
        for i, name in enumerate(names):
            away = None if name.away is None else to_display(name.away)
            centres = _candidates(own[i], sizes[i], away, GAP * pixels, name.tip)
            others_boxes = np.concatenate([kept, np.delete(boxes, i, axis=0)])
            others_boxes += SPACE * pixels * np.array([-1.0, -1.0, 1.0, 1.0])
            shunned = rivals.copy() if name.shuns else np.zeros(len(names), bool)
            shunned[i] = True
            cost = _costs(
                centres,
                sizes[i],
                frame,
                others_boxes,
                segments,
                int(shunned[:i].sum()),
                _from_apart(own, i, shunned, CLEAR * pixels),
                CLEAR * pixels,
                0.5 * width * pixels,
            )
            best = centres[int(np.argmin(cost))]
            boxes[i] = np.concatenate([best - sizes[i] / 2, best + sizes[i] / 2])
    for name, box, ends in zip(names, boxes, own, strict=True):
        _put(ax, name.text, 0.5 * (box[:2] + box[2:]))
        near = _nearest(0.5 * (box[:2] + box[2:]), ends)
        if _gap(box, near) > LEADER * pixels:
            _leader(ax, name.text, near, box)


def _from_apart(
    own: np.ndarray, i: int, shunned: np.ndarray, clear: float
) -> np.ndarray:
    """Return the named segments (display) the ``i``-th name is measured against.

    Those ``shunned`` only; a rival that starts where the ``i``-th starts (forces
    at one point) less its part alongside the ``i``-th and ``clear`` more: there
    a name is as near one as the other, and is read by its own further out.
    """
    named = own.copy()
    shared = np.hypot(*(named[:, 0] - own[i, 0]).T) < 1.0
    shared[i] = False
    d = named[:, 1] - named[:, 0]
    length = np.hypot(*d.T)
    u = d / np.where(length > 0, length, 1.0)[:, None]
    alongside = np.clip(u @ (own[i, 1] - own[i, 0]), 0.0, None)
    cut = np.minimum(clear + alongside, length) / np.where(length > 0, length, 1.0)
    named[shared, 0] += (cut[:, None] * d)[shared]
    return named[shunned]


def _size(text: Any, renderer: Any) -> np.ndarray:
    """Return the width and height of ``text`` with its box, display units."""
    x0, y0, x1, y1 = label_box(text, renderer)
    return np.array([x1 - x0, y1 - y0])


def _candidates(
    ends: np.ndarray,
    size: np.ndarray,
    away: np.ndarray | None,
    gap: float,
    tip: bool = False,
) -> np.ndarray:
    """Return the centres (display) tried for a name of ``size`` beside ``ends``.

    Beside a side: along it, on the side away from ``away`` first; round a point:
    in sixteen directions, right and up first; then, for a ``tip``, round the
    side's end as round a point. Each ring a little farther out.
    """
    a, b = ends
    d = b - a
    length = float(np.hypot(*d))
    # round a point, and round a short side's middle too (a corner is crowded)
    turns = np.deg2rad(np.arange(16) * 22.5 + 45.0)
    units = np.stack([np.cos(turns), np.sin(turns)], axis=1)
    bases = np.repeat(0.5 * (a + b)[None, :], len(units), axis=0)
    if length >= 1.0:
        n = np.array([-d[1], d[0]]) / length
        if away is not None and float(np.dot(0.5 * (a + b) - away, n)) < 0:
            n = -n
        along = np.array([side * n for _ in ALONG for side in (1.0, -1.0)])
        units = np.concatenate([along, units])
        bases = np.concatenate(
            [np.array([a + t * d for t in ALONG for _ in (1.0, -1.0)]), bases]
        )
        if tip:
            units = np.concatenate([units, units[-16:]])
            bases = np.concatenate([bases, np.repeat(b[None, :], 16, axis=0)])
    # the distance from a box's centre to its edge along each direction
    half = 0.5 * (np.abs(units[:, 0]) * size[0] + np.abs(units[:, 1]) * size[1])
    rings = [bases + units * (half + ring * gap)[:, None] for ring in RINGS]
    return np.concatenate(rings)


def _framed(
    low: np.ndarray, high: np.ndarray, frame: np.ndarray, boxes: np.ndarray
) -> np.ndarray:
    """Return the cost of each box (``low``, ``high``) out of ``frame`` or on ``boxes``.

    :data:`BARRED` for a box out of the frame, and :data:`CLASH` for each of the
    boxes (x0, y0, x1, y1; NaN ones passed over) it overlaps, plus the area shared.
    """
    out = (low < frame[:2]).any(axis=1) | (high > frame[2:]).any(axis=1)
    cost = np.zeros(len(low))
    cost += BARRED * out
    boxes = boxes[~np.isnan(boxes).any(axis=1)] if len(boxes) else boxes.reshape(0, 4)
    if len(boxes):
        wide = np.minimum(high[:, None, 0], boxes[None, :, 2]) - np.maximum(
            low[:, None, 0], boxes[None, :, 0]
        )
        tall = np.minimum(high[:, None, 1], boxes[None, :, 3]) - np.maximum(
            low[:, None, 1], boxes[None, :, 1]
        )
        area = np.clip(wide, 0, None) * np.clip(tall, 0, None)
        cost += CLASH * (area > 0).sum(axis=1) + area.sum(axis=1)
    return cost


def _costs(
    centres: np.ndarray,
    size: np.ndarray,
    frame: np.ndarray,
    boxes: np.ndarray,
    segments: np.ndarray,
    own: int,
    named: np.ndarray,
    clear: float,
    half: float = 0.0,
) -> np.ndarray:
    """Return the cost of a name of ``size`` centred at each of ``centres``.

    ``segments`` (display) are the named ones (``named``, the name's own the
    ``own``-th) and then the other lines; a place nearer than ``clear`` to
    another named side or point costs more the nearer it is; a line is crossed
    within ``half`` of it.
    """
    low, high = centres - size / 2, centres + size / 2
    cost = _framed(low, high, frame, boxes)
    cost += CLASH * _crossed(low - half, high + half, segments).sum(axis=1)
    # how far each place's box is from its own side or point, and from the others
    # that may be nearer than it or than clear (a box is no farther from its own
    # side than its centre is): a farther one costs no place anything
    centred = _distance(centres, named[own])
    reach = max(centred.max(), clear)
    others = _within(low, high, np.delete(named, own, axis=0), reach)
    apart = _box_distances(low, high, np.concatenate([named[own : own + 1], others]))
    mine = apart[0]
    if len(apart) > 1:
        rival = apart[1:].min(axis=0)
        cost += RIVAL * (rival <= mine)
        # where two sides cross, a name by either is read as the other's too
        cost += 20.0 * np.clip(clear - rival, 0.0, None)
    return cost + 0.05 * centred + np.arange(len(centres)) * 1e-3


def _within(
    low: np.ndarray, high: np.ndarray, segments: np.ndarray, reach: float
) -> np.ndarray:
    """Return those of ``segments`` that may come within ``reach`` of a box.

    One whose bounds are farther than ``reach`` (and a display unit for rounding)
    from those of all the boxes (``low``, ``high``) is farther from each: with
    ``reach`` past :data:`CLEAR` and a place's own side, it costs no place
    anything: a name among many is measured against those round it only.
    """
    if not np.isfinite(reach):
        return segments
    first, last = segments.min(axis=1), segments.max(axis=1)
    gap = np.maximum(np.maximum(first - high.max(axis=0), low.min(axis=0) - last), 0)
    return segments[np.hypot(gap[:, 0], gap[:, 1]) <= reach + 1.0]


def _crossed(low: np.ndarray, high: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """Return whether each box (``low``, ``high``) meets each segment: (boxes, k).

    Only the pairs whose bounds come within a display unit of each other are
    clipped (:func:`_clipped`): the others are apart, rounding and all, and a
    large mechanism's many lines are each near few of the places a name tries.
    """
    ends = segments.reshape(-1, 2, 2)
    first, last = ends.min(axis=1), ends.max(axis=1)
    lo, hi = low - 1.0, high + 1.0
    # those near the span of all the boxes first, then those near each box
    span = np.flatnonzero(((last >= lo.min(axis=0)) & (first <= hi.max(axis=0))).all(1))
    first, last = first[span].T, last[span].T
    near = (last[0] >= lo[:, 0, None]) & (first[0] <= hi[:, 0, None])
    near &= (last[1] >= lo[:, 1, None]) & (first[1] <= hi[:, 1, None])
    boxes, lines = np.nonzero(near)
    met = np.zeros((len(low), len(ends)), bool)
    met[boxes, span[lines]] = _clipped(low[boxes], high[boxes], ends[span[lines]])
    return met


def _clipped(low: np.ndarray, high: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Return whether each box (``low``, ``high``) meets its segment of ``ends``.

    Liang and Barsky's clipping: the segment's parameters inside every slab.
    """
    a = ends[:, 0, :]
    d = ends[:, 1, :] - a
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (low - a) / d
        t2 = (high - a) / d
    flat = np.abs(d) < 1e-9
    inside = (a >= low) & (a <= high)
    enter = np.where(flat, np.where(inside, -np.inf, np.inf), np.minimum(t1, t2))
    leave = np.where(flat, np.where(inside, np.inf, -np.inf), np.maximum(t1, t2))
    start = np.maximum(enter.max(axis=1), 0.0)
    stop = np.minimum(leave.min(axis=1), 1.0)
    return start <= stop


def _distance(points: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Return the distance of each of ``points`` from the segment ``ends``."""
    a, b = ends
    d = b - a
    square = float(np.dot(d, d))
    t = np.zeros(len(points)) if square == 0 else (points - a) @ d / square
    foot = a + np.clip(t, 0.0, 1.0)[:, None] * d
    return np.hypot(*(points - foot).T)


def _box_distances(
    low: np.ndarray, high: np.ndarray, segments: np.ndarray
) -> np.ndarray:
    """Return each box's (``low``, ``high``) distance from each segment: (k, boxes).

    Nothing for a box the segment meets; else the least of its corners' distances
    from the segment and the segment's ends' from the box. All at once, in the
    very operations one segment's alone would take (the products of two by a
    batched ``matmul``, as ``@`` and ``np.dot`` take them), so that a place's
    cost, and the place chosen, are those of one segment at a time to the bit.
    """
    corners = np.stack(
        [
            low,
            high,
            np.stack([low[:, 0], high[:, 1]], 1),
            np.stack([high[:, 0], low[:, 1]], 1),
        ],
        axis=1,
    ).reshape(-1, 2)
    a = segments[:, 0, :]
    d = segments[:, 1, :] - a
    square = np.matmul(d[:, None, :], d[:, :, None])[:, 0, 0]
    reach = np.matmul(corners[None, :, :] - a[:, None, :], d[:, :, None])[..., 0]
    point = square == 0
    t = np.where(point[:, None], 0.0, reach / np.where(point, 1.0, square)[:, None])
    foot = a[:, None, :] + np.clip(t, 0.0, 1.0)[..., None] * d[:, None, :]
    gap = corners[None, :, :] - foot
    near = np.hypot(gap[..., 0], gap[..., 1]).reshape(len(segments), -1, 4).min(axis=2)
    for k in range(2):  # the two ends, each against every box
        end = segments[:, k, None, :]
        off = end - np.clip(end, low[None], high[None])
        near = np.minimum(near, np.hypot(off[..., 0], off[..., 1]))
    return np.where(_crossed(low, high, segments).T, 0.0, near)


def _nearest(point: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Return the point of the segment ``ends`` nearest to ``point``."""
    a, b = ends
    d = b - a
    square = float(np.dot(d, d))
    t = 0.0 if square == 0 else float(np.clip(np.dot(point - a, d) / square, 0, 1))
    return a + t * d


def _gap(box: np.ndarray, point: np.ndarray) -> float:
    """Return the distance from ``point`` to the box (x0, y0, x1, y1)."""
    return float(np.hypot(*(point - np.clip(point, box[:2], box[2:]))))


def _put(ax: Any, text: Any, centre: np.ndarray) -> None:
    """Centre ``text`` at ``centre`` (display), in the units of its coordinates."""
    text.set_horizontalalignment("center")
    text.set_verticalalignment("center")
    if getattr(text, "anncoords", None) == "offset points":
        anchor = ax.transData.transform(text.xy)
        text.xyann = tuple((centre - anchor) * 72.0 / root_figure(ax).dpi)
        return
    text.set_position(tuple(ax.transData.inverted().transform(centre)))


def _leader(ax: Any, text: Any, near: np.ndarray, box: np.ndarray) -> None:
    """Join a name put far off to what it names by a thin line, to its box's edge.

    Added as an artist, not plotted: the limits, which the names were placed
    within, stay.
    """
    from matplotlib.lines import Line2D

    edge = np.clip(near, box[:2], box[2:])
    ends = ax.transData.inverted().transform(np.array([near, edge]))
    line = Line2D(*ends.T, color=text.get_color(), lw=0.5, alpha=0.7, zorder=6.8,
                  transform=ax.transData)  # fmt: skip
    line.set_in_layout(False)
    ax.add_artist(line)
