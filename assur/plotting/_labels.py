"""Names on a mechanism drawing: joints beside their circles, links on their bars.

Each label goes where it is farthest from what is drawn already; the list ``busy``
of points to keep clear of grows with every label placed.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING, Any

import numpy as np

from assur.plotting._bars import BAR_LABELS, settled_renderer
from assur.plotting._geometry import (
    _joint_direction,
    _link_spot,
    _link_spots,
    _merge_joints,
    _shape,
)
from assur.plotting._linknames import note_spots
from assur.plotting._loadnames import name_load
from assur.plotting._style import literal

if TYPE_CHECKING:
    from assur.plotting._context import _Context, _Pose


def _label_joints(
    ax: Any,
    ctx: _Context,
    joints: dict[str, tuple[np.ndarray, float]],
    busy: list[np.ndarray],
) -> None:
    """Name the joints, each on the side of its circle with the most room."""
    for p, names, alpha in _merge_joints(joints, 0.5 * ctx.r):
        d = _joint_direction(p, ctx.r, busy)
        at = p + 2.0 * ctx.r * d
        busy.append(at[None, :])
        text = ax.text(
            at[0],
            at[1],
            literal(", ".join(names)),
            fontsize=9,
            fontweight="bold",
            ha="left" if d[0] > 0.3 else "right" if d[0] < -0.3 else "center",
            va="bottom" if d[1] > 0.3 else "top" if d[1] < -0.3 else "center",
            color="#1a1a1a",
            alpha=max(alpha, 0.35),
            zorder=7,
        )
        # a picture with loads moves it clear of them (place_loads)
        name_load(text, p, p)


def _label_link(
    ax: Any, ctx: _Context, pose: _Pose, body: int, alpha: float, busy: list[np.ndarray]
) -> None:
    """Name a link on its bar or plate, where it is farthest from other labels."""
    spots = _link_spots(ctx, pose, body)
    if not spots:
        return
    at = _link_spot(spots, ctx.r, busy)
    busy.append(at[None, :])
    text = ax.text(
        at[0],
        at[1],
        literal(ctx.plan.bodies[body]),
        fontsize=8.5,
        ha="center",
        va="center",
        color=ctx.color[body],
        alpha=max(alpha, 0.35),
        # under the loads' arrows, which start at a bar's middle too
        zorder=5.5,
        bbox={
            "boxstyle": "round,pad=0.25",
            "facecolor": "white",
            "edgecolor": ctx.color[body],
            "lw": 1.0,
            "alpha": max(alpha, 0.35),
        },
    )
    points = _shape(ctx, pose, body).points
    bar = len(points) == 2
    if bar:
        # a bar: clear_bars moves the name off it if it hides most of it
        BAR_LABELS[text] = (np.asarray(points[0]), np.asarray(points[1]), ctx.r)
    # and clear_arrows off the loads' arrows, on a picture with loads
    note_spots(text, spots, np.asarray(points, float) if bar else None, ctx.r)


LOAD_LABELS: weakref.WeakSet[Any] = weakref.WeakSet()
"""The images' names on the velocity and acceleration plans: :func:`spread_labels`
may move them. The pictures with loads (:mod:`assur.plotting._loadnames`), the
force polygons, Zhukovsky's lever and the instant centres place theirs with
:func:`assur.plotting._placing.place_names`, which keeps them off the lines too.
(Held aside, not as a ``gid``: an SVG writes a gid as an element's id, which must
be unique in a page.)"""
SPREAD_STEPS = 40
"""Most rounds in which :func:`spread_labels` pushes overlapping labels apart."""
LEADER = 12.0
"""A label moved farther than this (points) is joined to its load by a thin line."""


def spread_labels(ax: Any) -> None:
    """Move the loads' labels apart where they overlap each other or other labels.

    Loads meet at the joints: at a slider its reaction, the guide's and its inertia
    force are named at one point. Each round takes every overlapping pair in turn
    and pushes the load labels in it clear (half each for two load labels, all of
    it for one beside a joint's or a link's name, which stay), until none overlaps
    or :data:`SPREAD_STEPS` rounds have passed. The layout is settled first: the
    overlaps are measured on the drawing as it will be seen.
    """
    texts = [t for t in ax.texts if t.get_visible() and t.get_text()]
    movable = np.array([t in LOAD_LABELS for t in texts])
    if not movable.any():
        return
    # the labels moved do not resize the axes
    for text, load in zip(texts, movable, strict=True):
        if load:
            text.set_in_layout(False)
    renderer = settled_renderer(ax)
    # the boxes (x0, y0, x1, y1, display units) move with their labels
    start = np.array([t.get_window_extent(renderer).extents for t in texts])
    boxes = start.copy()
    for step in range(SPREAD_STEPS):
        clear = True
        for i, j in _overlapping(boxes):
            # a pair cleared by an earlier push of this round is left alone; the
            # room left grows round by round, so that a label caught between two
            # others is not pushed to and fro for ever
            push = _push(boxes[i], boxes[j], 1.0 + step)
            if push is None or not (movable[i] or movable[j]):
                continue
            clear = False
            share = 0.5 if movable[i] and movable[j] else 1.0
            for k, sign in ((i, 1.0), (j, -1.0)):
                if movable[k]:
                    boxes[k] += np.tile(sign * share * push, 2)
        _keep_inside(boxes, movable, ax.bbox.extents)
        if clear:
            break
    far = LEADER * ax.figure.dpi / 72.0
    for text, box, old in zip(texts, boxes, start, strict=True):
        step = box[:2] - old[:2]
        if step.any():
            was = _move(ax, text, step)
            if float(np.hypot(*step)) > far:
                _leader(ax, text, was, box)


def _move(ax: Any, text: Any, step: np.ndarray) -> np.ndarray:
    """Move ``text`` by ``step`` (display units); return where it points (display).

    A label set off its point by so many points (a plan's image's name) keeps its
    point and changes its offset; any other is in data units.
    """
    if getattr(text, "anncoords", None) == "offset points":
        text.xyann = tuple(np.add(text.xyann, step * 72.0 / ax.figure.dpi))
        return ax.transData.transform(text.xy)
    was = ax.transData.transform(text.get_position())
    text.set_position(tuple(ax.transData.inverted().transform(was + step)))
    return was


def _leader(ax: Any, text: Any, was: np.ndarray, box: np.ndarray) -> None:
    """Join a label moved far to where it was put (display ``was``) by a thin line.

    The line ends at the label box's nearest point, so it does not cross the name.
    """
    near = np.clip(was, box[:2], box[2:])
    ends = ax.transData.inverted().transform(np.array([was, near]))
    ax.plot(*ends.T, color=text.get_color(), lw=0.5, alpha=0.7, zorder=6.8)


def _keep_inside(boxes: np.ndarray, movable: np.ndarray, frame: np.ndarray) -> None:
    """Shift the movable boxes back inside ``frame`` (x0, y0, x1, y1), in place.

    A label past the axes' edge ran into the legend beside them.
    """
    low = np.maximum(frame[:2] - boxes[:, :2], 0.0)
    high = np.minimum(frame[2:] - boxes[:, 2:], 0.0)
    # a box wider than the frame keeps its left (or lower) edge inside
    shift = np.where(low > 0, low, high) * movable[:, None]
    boxes += np.tile(shift, 2)


def _overlapping(boxes: np.ndarray) -> list[tuple[int, int]]:
    """Return the pairs of boxes (rows x0, y0, x1, y1) that overlap."""
    x0, y0, x1, y1 = boxes.T
    cross = (
        (x0[:, None] < x1[None, :])
        & (x0[None, :] < x1[:, None])
        & (y0[:, None] < y1[None, :])
        & (y0[None, :] < y1[:, None])
    )
    i, j = np.nonzero(np.triu(cross, 1))
    return list(zip(i.tolist(), j.tolist(), strict=True))


def _push(a: np.ndarray, b: np.ndarray, spare: float = 1.0) -> np.ndarray | None:
    """Return the shift (display units) that takes box ``a`` clear of box ``b``.

    Along the axis of the smaller overlap, away from ``b``'s centre (upward or to
    the right for boxes centred alike), with ``spare`` pixels to spare; None when
    the boxes do not overlap.
    """
    dx = min(a[2], b[2]) - max(a[0], b[0])
    dy = min(a[3], b[3]) - max(a[1], b[1])
    if not (dx > 0 and dy > 0):
        return None
    away = a[:2] + a[2:] - b[:2] - b[2:]
    if dx < dy:
        return np.array([np.copysign(dx + spare, away[0] or 1.0), 0.0])
    return np.array([0.0, np.copysign(dy + spare, away[1] or 1.0)])
