"""Force arrows drawn: a force as a straight arrow to scale, a couple as an arc.

Each with its name (and value) in a light box, noted for the placing of names
(:mod:`assur.plotting._loadnames`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur.plotting._apart import moved
from assur.plotting._heads import fitted_arrow
from assur.plotting._loadnames import name_load
from assur.plotting._numbers import quantity

if TYPE_CHECKING:
    from assur.plotting._context import _Context
    from assur.plotting._forces import _Arrow

__all__ = ["INTERNAL_DASH", "LABEL_BOX", "_draw_arrows"]

LABEL_BOX = {
    "boxstyle": "round,pad=0.1",
    "facecolor": "white",
    "edgecolor": "none",
    "alpha": 0.75,
}
"""Background of a force's label."""
HALO = 1.0
"""Width, points, of the light outline round a force arrow beyond its line: a
black inertia force on the dark crank, or a short reaction over a joint's ring or a
slider's box, would otherwise not be seen."""
INTERNAL_DASH = (0, (3.0, 1.6))
"""The dash of a reaction inside a group, drawn on both of its pair's links."""
ARROW_ZORDER = 6
"""Force arrows lie above the links (<= 3), the joints (4) and the paths (5)."""
APART = 1.0
"""How far apart, in joint radii, forces on one line at one place are drawn: at a
dead centre a slider's inertia force and the rod's reaction on it lie on each other
(and the reaction's other side, on the rod)."""


def _halo(lw: float) -> list[Any]:
    """Return the path effects of a light outline round a line ``lw`` points wide."""
    from matplotlib.patheffects import Normal, Stroke

    return [Stroke(linewidth=lw + 2 * HALO, foreground="white", alpha=0.85), Normal()]


def _draw_arrows(
    ax: Any, ctx: _Context, arrows: list[_Arrow], scale: float, text: str | None
) -> list[np.ndarray]:
    """Draw ``arrows`` at ``scale`` N per cm; return their extreme points.

    ``text`` is ``"values"`` (name and value), ``"names"`` or None (no labels).
    """
    seen = []
    # a force of round-off (a guide's at a dead centre, 1.6e-14 N beside 3266 N)
    # is none: not an arrow with "1.63e-14 N" on it
    sizes = [float(np.hypot(*a.force)) for a in arrows if a.force is not None]
    largest_force = max([*sizes, 0.0])
    least = 1e-9 * largest_force
    # a couple's round-off is the forces' times the drawing's size, not 1e-9 N m:
    # a watch's balancing torque of 9e-14 N m is drawn
    moments = [abs(a.couple or 0.0) for a in arrows]
    tiny = 1e-9 * max([*moments, largest_force * ctx.size])
    # a couple's arc grows with it: one of 0.0005 N m beside 0.16 N m was drawn
    # as large (no scale gives a couple a length; the size tells which matter)
    largest = max([*moments, 0.0])
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    for a in arrows:
        if a.force is not None and float(np.hypot(*a.force)) > least:
            tip = a.at + a.force / (scale * 100.0)
            start, moved_tip = moved(
                drawn, a.at, tip, APART * ctx.r, 0.2 * APART * ctx.r
            )
            drawn.append((start, moved_tip))
            seen.append(_draw_force(ax, ctx, a, a.force, scale, text, start))
        if a.couple is not None and abs(a.couple) > tiny:
            share = abs(a.couple) / largest
            seen += _draw_couple(ax, ctx, a, a.couple, text, share)
    return seen


def _draw_force(
    ax: Any,
    ctx: _Context,
    a: _Arrow,
    force: np.ndarray,
    scale: float,
    text: str | None,
    start: np.ndarray | None = None,
) -> np.ndarray:
    """Draw the force of ``a`` (``force``) as a straight arrow; return its tip.

    ``start`` is where the arrow starts, if not at the load's point (moved
    sideways off another, :func:`assur.plotting._apart.moved`).
    """
    mag = float(np.hypot(*force))
    at = a.at if start is None else start
    tip = at + force / (scale * 100.0)
    # a short arrow's head shrinks with it: its direction stays readable
    dash = INTERNAL_DASH if a.kind in ("internal", "opposite") else "solid"
    ax.add_patch(
        fitted_arrow(
            [at, tip], 13, color=a.color, lw=1.7, zorder=ARROW_ZORDER,
            path_effects=_halo(1.7), linestyle=dash,
        )
    )  # fmt: skip
    if text and a.kind != "opposite":
        u = force / mag
        words = (
            f"{a.label} = {quantity(mag, a.units[0], 3)}"
            if text == "values"
            else a.label
        )
        label = ax.text(
            *(tip + 0.5 * ctx.r * u),
            words,
            fontsize=7.5,
            color=a.color,
            ha="left" if u[0] >= 0 else "right",
            va="bottom" if u[1] >= 0 else "top",
            zorder=7,
            bbox=LABEL_BOX,
        )
        name_load(label, at, tip)
    return tip


def _draw_couple(
    ax: Any, ctx: _Context, a: _Arrow, couple: float, text: str | None, share: float
) -> list[np.ndarray]:
    """Draw the couple of ``a`` (``couple``) as a curved arrow; return its box.

    ``share`` is its size against the largest couple drawn, the balancing torque's
    among them: the arc's radius runs from 1.2 to 2.3 joint radii (the balancing
    torque's, round the driver's pivot and its other arcs, from 2.6 to 3.4).
    """
    grow = math.sqrt(min(1.0, share))
    size = 2.6 + 0.8 * grow if a.kind == "balancing" else 1.2 + 1.1 * grow
    rad = size * ctx.r
    t = np.linspace(math.radians(-100), math.radians(150), 40)
    if couple < 0:
        t = t[::-1]
    arc = a.point + rad * np.column_stack([np.cos(t), np.sin(t)])
    # the name is read as the couple's by its arc's upper right
    ax.add_patch(
        fitted_arrow(
            arc, 11, color=a.color, lw=1.5, zorder=ARROW_ZORDER,
            path_effects=_halo(1.5),
        )
    )  # fmt: skip
    if text:
        # the balancing torque always shows its value
        value = text == "values" or a.kind == "balancing"
        name = a.label if a.couple_label is None else a.couple_label
        words = f"{name} = {quantity(couple, a.units[1], 3)}" if value else name
        label = ax.text(
            *(a.point + rad * np.array([0.7, 0.8])),
            words,
            fontsize=7.5,
            color=a.color,
            ha="left",
            va="bottom",
            zorder=7,
            bbox=LABEL_BOX,
        )
        q = a.point + rad * np.array([math.cos(0.9), math.sin(0.9)])
        name_load(label, q, q, arc)
    return [a.point - rad, a.point + rad]
