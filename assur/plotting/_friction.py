"""Friction circles on a force drawing, enlarged where they are too small to see.

A journal's friction circle has the radius f r, often under a millimetre on a
mechanism of decimetres: drawn to scale it hides inside the joint's circle. As the
books do, the circles of a mechanism are drawn enlarged by one round factor, the
same in every picture of it, and each reaction is drawn tangent to its enlarged
circle, on the side its friction couple puts it; the legend states the factor.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._style import REACTION_COLOUR
from assur.plotting._geometry import _nice

if TYPE_CHECKING:
    from assur.plotting._context import _Context, _Pose

SMALLEST_CIRCLE = 2.0
"""Radius of the smallest friction circle drawn, in radii of a joint's circle: it
shows outside the joint it belongs to."""


def friction_zoom(ctx: _Context) -> float:
    """Return how much the friction circles are enlarged: 1, 2, 5, 10, ... times.

    The smallest circle of the mechanism is drawn at least :data:`SMALLEST_CIRCLE`
    joint radii; 1 when it is that large already or there is none.
    """
    radii = [
        p.friction * p.radius
        for p in ctx.plan.pairs.values()
        if p.kind == "R" and p.friction * p.radius > 0.0 and not p.virtual
    ]
    if not radii:
        return 1.0
    need = SMALLEST_CIRCLE * ctx.r / min(radii)
    return _nice(need) if need > 1.0 else 1.0


def shown_point(ctx: _Context, pin: np.ndarray, point: np.ndarray) -> np.ndarray:
    """Return where a reaction through ``point`` is drawn: tangent to the drawn circle.

    Its offset from the pin (f r at most) grows by :func:`friction_zoom`, as the
    circle it touches does; its direction stays.
    """
    return pin + friction_zoom(ctx) * (point - pin)


def friction_circles(
    ctx: _Context, pose: _Pose, bodies: Collection[int] | None = None
) -> list[tuple[np.ndarray, float]]:
    """Return the centre and radius f r (m) of each revolute pair's friction circle.

    With ``bodies``, those of the pairs of these bodies only.
    """
    return [
        (pose.at(p.second, p.d_second), p.friction * p.radius)
        for p in ctx.plan.pairs.values()
        if p.kind == "R" and p.friction > 0.0 and not p.virtual
        if bodies is None or p.first in bodies or p.second in bodies
    ]


def draw_friction_circles(
    ax: Any, ctx: _Context, pose: _Pose, bodies: Collection[int] | None = None
) -> int:
    """Draw the friction circles, dashed and enlarged alike; return how many.

    With ``bodies``, those of the pairs of these bodies only (a group's free body).
    """
    from matplotlib.patches import Circle

    zoom = friction_zoom(ctx)
    circles = friction_circles(ctx, pose, bodies)
    for k, (centre, radius) in enumerate(circles):
        ax.add_patch(
            Circle(
                tuple(centre),
                zoom * radius,
                fill=False,
                ls="--",
                lw=0.8,
                color=REACTION_COLOUR,
                zorder=6,
                gid=f"friction-circle-{k}",  # an SVG id: one of its own each
            )
        )
    return len(circles)


def friction_legend(ctx: _Context) -> str:
    """Return the legend's entry for the friction circles, with their enlargement."""
    zoom = friction_zoom(ctx)
    # short: the legend beside the axes takes its width from the drawing
    drawn = f" ×{zoom:g}" if zoom > 1.0 else ""
    return f"friction circle{drawn} (dashed), reaction tangent"
