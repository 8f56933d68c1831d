"""The parts of a mechanism drawing: bars, plates, guides, slots, blocks, bearings.

Each function draws one part on matplotlib axes ``ax`` at points in m; matplotlib is
imported inside the functions only.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur.plotting._geometry import BLOCK_HALF, _area, _farthest, _hull, _shape
from assur.plotting._style import FAINT, GROUND_COLOR

if TYPE_CHECKING:
    from assur.plotting._context import _Context, _Pose


def _bar(
    ax: Any, a: np.ndarray, b: np.ndarray, color: str, alpha: float, width: float = 5.0
) -> None:
    """Draw a bar from ``a`` to ``b``, ``width`` points thick."""
    ax.plot(
        [a[0], b[0]],
        [a[1], b[1]],
        color=color,
        lw=width,
        alpha=alpha,
        solid_capstyle="round",
        zorder=2,
    )


def _draw_link(ax: Any, ctx: _Context, pose: _Pose, body: int, alpha: float) -> None:
    """Draw ``body``: a plate, or a bar, with its guides and sliding blocks."""
    color = ctx.color[body]
    shape = _shape(ctx, pose, body)
    pts = np.array(shape.points).reshape(-1, 2)
    hull = _hull(pts) if len(pts) >= 3 else None
    if hull is not None and _area(hull) > 1e-4 * ctx.size**2:
        _draw_plate(ax, hull, color, alpha)
    elif len(pts) >= 2:
        # points in a line make a bar between the outermost two
        _bar(ax, *_farthest(pts), color, alpha)
    for start, end, name in shape.guides:
        _draw_guide(ax, ctx, start, end, name, color, alpha, pts)
    for centre, e in shape.blocks:
        _draw_block(ax, ctx, centre, e, color, alpha)


def _draw_plate(ax: Any, hull: np.ndarray, color: str, alpha: float) -> None:
    """Draw a link with three or more joints: a translucent polygon, outlined."""
    from matplotlib.patches import Polygon

    ax.add_patch(
        Polygon(
            hull,
            closed=True,
            facecolor=color,
            alpha=0.28 * alpha,
            edgecolor="none",
            zorder=1.5,
        )
    )
    ax.add_patch(
        Polygon(
            hull,
            closed=True,
            fill=False,
            edgecolor=color,
            lw=2.5,
            alpha=alpha,
            joinstyle="round",
            zorder=2,
        )
    )


def _draw_guide(
    ax: Any,
    ctx: _Context,
    start: np.ndarray,
    end: np.ndarray,
    name: str,
    color: str,
    alpha: float,
    points: np.ndarray,
) -> None:
    """Draw a slide line on its link: a bar, a slot, or on the frame a track."""
    slot = name in ctx.plan.topology.slots
    if ctx.plan.pairs[name].first == 0 and not slot:
        _draw_track(ax, ctx, start, end, alpha)
        return
    if len(points):
        _tie(ax, ctx, start, end, color, alpha, points)
    if slot:
        _draw_slot(ax, ctx, start, end, color, alpha)
    else:
        _bar(ax, start, end, color, alpha)


def _along_across(start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return unit vectors along and (counter-clockwise) across ``start``-``end``."""
    e = (end - start) / max(np.hypot(*(end - start)), 1e-12)
    return e, np.array([-e[1], e[0]])


def _draw_track(
    ax: Any, ctx: _Context, start: np.ndarray, end: np.ndarray, alpha: float
) -> None:
    """Draw a slide line of the frame: its centre line and the hatched surface."""
    _, n = _along_across(start, end)
    ax.plot(
        *np.transpose([start, end]),
        color=GROUND_COLOR,
        lw=0.8,
        ls="-.",
        alpha=alpha,
        zorder=1,
    )
    # the surface lies on the side away from the mechanism
    side = -1.0 if np.dot(n, ctx.centroid - start) > 0 else 1.0
    shift = side * n * 0.024 * ctx.size
    _hatched_line(ax, ctx, start + shift, end + shift, side * n, alpha)


def _tie(
    ax: Any,
    ctx: _Context,
    start: np.ndarray,
    end: np.ndarray,
    color: str,
    alpha: float,
    points: np.ndarray,
) -> None:
    """Tie a slide line to the rest of its link at the nearest of ``points``."""
    e, _ = _along_across(start, end)
    proj = [
        (start + np.clip(np.dot(p - start, e), 0, np.hypot(*(end - start))) * e, p)
        for p in points
    ]
    foot, p = min(proj, key=lambda fp: np.hypot(*(fp[0] - fp[1])))
    if np.hypot(*(foot - p)) > 1e-6 * ctx.size:
        _bar(ax, foot, p, color, alpha)


def _draw_slot(
    ax: Any,
    ctx: _Context,
    start: np.ndarray,
    end: np.ndarray,
    color: str,
    alpha: float,
) -> None:
    """Draw a slot: a wide bar with an open, round-ended groove along it."""
    from matplotlib.patches import Polygon

    e, n = _along_across(start, end)
    w = 1.25 * ctx.r
    _bar(ax, start, end, color, alpha, width=9.0)
    t = np.linspace(-0.5 * math.pi, 0.5 * math.pi, 12)
    cap = np.outer(np.cos(t), e) + np.outer(np.sin(t), n)
    outline = np.vstack([end + w * cap, start - w * cap])
    ax.add_patch(
        Polygon(
            outline,
            closed=True,
            facecolor="white",
            edgecolor=color,
            lw=1.4,
            alpha=alpha,
            zorder=2.5,
        )
    )


def _hatched_line(
    ax: Any, ctx: _Context, a: np.ndarray, b: np.ndarray, away: np.ndarray, alpha: float
) -> None:
    """Draw the frame's surface from ``a`` to ``b``, hatched on the ``away`` side."""
    from matplotlib.collections import LineCollection

    ax.plot(*np.transpose([a, b]), color=GROUND_COLOR, lw=1.6, alpha=alpha, zorder=1.2)
    length = np.hypot(*(b - a))
    e = (b - a) / max(length, 1e-12)
    step = 0.022 * ctx.size
    count = max(2, int(length / step))
    starts = a + np.outer(np.linspace(0.0, 1.0, count + 1)[1:], b - a)
    tips = starts + (away - e) * 0.6 * step
    ax.add_collection(
        LineCollection(
            list(zip(starts, tips, strict=True)),
            colors=GROUND_COLOR,
            linewidths=0.8,
            alpha=alpha,
            zorder=1.2,
        )
    )


def _draw_block(
    ax: Any, ctx: _Context, centre: np.ndarray, e: np.ndarray, color: str, alpha: float
) -> None:
    """Draw a slider's block at ``centre``, its long side along unit vector ``e``."""
    from matplotlib.patches import Polygon

    n = np.array([-e[1], e[0]])
    half_l, half_h = BLOCK_HALF[0] * ctx.size, BLOCK_HALF[1] * ctx.size
    corners = [
        centre + sl * half_l * e + sh * half_h * n
        for sl, sh in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    ax.add_patch(
        Polygon(
            corners,
            closed=True,
            facecolor=_light(color),
            edgecolor=color,
            lw=1.8,
            alpha=alpha,
            zorder=3,
        )
    )


def _light(color: str) -> tuple[float, ...]:
    """Return a pale tint of ``color`` (RGB)."""
    from matplotlib.colors import to_rgb

    return tuple(0.35 * c + 0.65 for c in to_rgb(color))


def _draw_pivot(ax: Any, ctx: _Context, p: np.ndarray, alpha: float) -> None:
    """Draw the frame's bearing at ``p``: a triangle, its base and hatching."""
    from matplotlib.patches import Polygon

    away = p - ctx.centroid
    # a bearing stands on the floor, unless it sits clearly above the mechanism
    down = np.array([0.0, 1.0 if away[1] > 0.5 * abs(away[0]) else -1.0])
    side = np.array([-down[1], down[0]])
    h = 0.042 * ctx.size
    tri = [p, p + h * down + 0.6 * h * side, p + h * down - 0.6 * h * side]
    ax.add_patch(
        Polygon(
            tri,
            closed=True,
            facecolor="white",
            edgecolor=GROUND_COLOR,
            lw=1.4,
            alpha=alpha,
            zorder=1.3,
        )
    )
    base = p + h * down
    _hatched_line(ax, ctx, base - 0.95 * h * side, base + 0.95 * h * side, down, alpha)


def _draw_joint(ax: Any, ctx: _Context, p: np.ndarray, alpha: float) -> None:
    """Draw a revolute joint at ``p``: a small white circle."""
    from matplotlib.patches import Circle

    ax.add_patch(
        Circle(
            tuple(p),
            ctx.r,
            facecolor="white",
            edgecolor="#1a1a1a",
            lw=1.4,
            alpha=max(alpha, FAINT),
            zorder=4,
        )
    )
