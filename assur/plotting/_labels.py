"""Names on a mechanism drawing: joints beside their circles, links on their bars.

Each label goes where it is farthest from what is drawn already; the list ``busy``
of points to keep clear of grows with every label placed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur.plotting._bars import BAR_LABELS
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
