"""A link's name beside its bar where, on it, the name would hide the bar.

A name goes on its bar's middle (:func:`assur.plotting._labels._label_link`): on a
long bar it hides a little of it, on a short one (the ten-bar's link 5, a few
millimetres of drawing) all of it. Measured on the drawing as it is seen, a name
that hides more than :data:`HIDDEN_SHARE` of its bar is moved off it, square to it.
"""

from __future__ import annotations

import contextlib
import weakref
from typing import Any

import numpy as np

HIDDEN_SHARE = 0.5
"""Largest share of its bar's length a name may hide, on the drawing."""
BAR_WIDTH = 5.0
"""Width of a link's bar, points (:func:`assur.plotting._parts._bar`'s)."""
ROOM = 3.0
"""Gap between a name moved off its bar and the bar's edge, points."""
BAR_LABELS: weakref.WeakKeyDictionary[Any, tuple[np.ndarray, np.ndarray, float]] = (
    weakref.WeakKeyDictionary()
)
"""The names set on a bar, with the bar's ends and its joints' radius (m), which
hide its ends: :func:`clear_bars` moves them."""


def root_figure(ax: Any) -> Any:
    """Return the Figure that holds ``ax``, through the SubFigures it may be in.

    A SubFigure has no canvas of its own to draw, lay out or measure with; its
    root Figure has.
    """
    try:
        return ax.get_figure(root=True)  # matplotlib >= 3.10
    except TypeError:
        # before 3.10, a SubFigure's ``figure`` is its root Figure, a Figure's itself
        return ax.figure.figure


def settled_renderer(ax: Any) -> Any:
    """Return a renderer of ``ax``'s figure once its layout is settled.

    The layout runs twice: a legend beside the axes shrinks them, which moves the
    labels it made room for; the second run finds where they are seen. Only the
    layout engine runs, then each axes' aspect is applied, as a draw does first:
    measures are taken live from the positions these set, so the rest of a draw
    (walking every artist, even without painting) was most of the time spent
    here, and a picture is laid out twice more when it is saved. A figure with no
    layout engine (one the caller made) is drawn twice instead. A figure made
    without pyplot (the report's SVG) measures its text as Agg.
    """
    fig = root_figure(ax)
    canvas = fig.canvas
    if not hasattr(canvas, "get_renderer"):
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        canvas = FigureCanvasAgg(fig)
    engine = fig.get_layout_engine()
    if engine is None:
        fig.draw_without_rendering()
        fig.draw_without_rendering()
        return canvas.get_renderer()
    renderer = canvas.get_renderer()
    for _ in range(2):
        lay_out(fig, engine)
    for each in fig.axes:
        locator = each.get_axes_locator()
        each.apply_aspect(locator(each, renderer) if locator else None)
    return renderer


def settle_without(ax: Any, texts: list[Any]) -> Any:
    """Return a settled renderer of ``ax``'s figure, ``texts`` left out of its layout.

    Names placed on the drawing do not resize the axes: they are placed in the
    layout made without them, which placing them (each inside its axes) leaves as
    it is.
    """
    for text in texts:
        text.set_in_layout(False)
    return settled_renderer(ax)


def lay_out(fig: Any, engine: Any) -> None:
    """Run the layout ``engine`` on ``fig`` as ``Figure.draw`` does.

    A figure too small for its layout is no error: it is then not tightened.
    """
    with contextlib.suppress(ValueError):
        engine.execute(fig)


def hidden_length(box: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """Return the length of the segment ``a``-``b`` inside ``box`` (x0, y0, x1, y1).

    The segment is clipped to the box (Liang and Barsky's parameters).
    """
    d = b - a
    low, high = 0.0, 1.0
    for k in range(2):
        if abs(d[k]) < 1e-12:
            if not box[k] <= a[k] <= box[k + 2]:
                return 0.0
            continue
        t0, t1 = sorted(((box[k] - a[k]) / d[k], (box[k + 2] - a[k]) / d[k]))
        low, high = max(low, t0), min(high, t1)
    return max(high - low, 0.0) * float(np.hypot(*d))


def label_box(text: Any, renderer: Any) -> np.ndarray:
    """Return the extents of a label with its box (x0, y0, x1, y1), display units."""
    patch = text.get_bbox_patch()
    if patch is None:
        return np.asarray(text.get_window_extent(renderer).extents)
    text.update_bbox_position_size(renderer)
    return np.asarray(patch.get_window_extent(renderer).extents)


def bar_seen(
    ax: Any, a: np.ndarray, b: np.ndarray, joint: float
) -> tuple[np.ndarray, np.ndarray]:
    """Return the part of the bar ``a``-``b`` (m) seen between its joints' circles.

    In display units: the circles hide ``joint`` (m) of each end (nothing of a bar
    shorter than their two radii is seen).
    """
    p, q = ax.transData.transform(np.array([a, b]))
    ends = ax.transData.transform(np.array([a, a + np.array([joint, 0.0])]))
    r = float(np.hypot(*(ends[1] - ends[0])))
    length = float(np.hypot(*(q - p)))
    if length <= 2 * r:
        middle = 0.5 * (p + q)
        return middle, middle
    u = (q - p) / length
    return p + r * u, q - r * u


def clear_bars(ax: Any) -> None:
    """Move each name that hides most of its short bar off it, square to the bar.

    To the side the name's centre already leans to (upward for one centred), by
    half the name's width across the bar, half the bar's width and :data:`ROOM`.
    """
    texts = [t for t in ax.texts if t in BAR_LABELS and t.get_visible()]
    if not texts:
        return
    renderer = settled_renderer(ax)
    pixels = root_figure(ax).dpi / 72.0
    for text in texts:
        a, b = bar_seen(ax, *BAR_LABELS[text])
        box = label_box(text, renderer)
        length = float(np.hypot(*(b - a)))
        if length == 0 or hidden_length(box, a, b) <= HIDDEN_SHARE * length:
            continue
        u = (b - a) / length
        n = np.array([-u[1], u[0]])
        centre = 0.5 * (box[:2] + box[2:])
        lean = float(np.dot(centre - a, n))
        side = np.sign(lean) if abs(lean) > 1e-9 else (1.0 if n[1] >= 0 else -1.0)
        half = 0.5 * (abs(n[0]) * (box[2] - box[0]) + abs(n[1]) * (box[3] - box[1]))
        bar = 0.5 * BAR_WIDTH * pixels
        step = side * (half + bar + ROOM * pixels) - lean
        at = ax.transData.transform(text.get_position()) + step * n
        text.set_position(tuple(ax.transData.inverted().transform(at)))
