"""RRP dyad: a link pinned to a known link and to a slider on a known guide.

The middle pin lies on a circle about the external pin and on the slider's line; the
branch is the intersection of the reference pose.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur.groups._dyad import DyadSolver, compile_dyad, guide
from assur.groups._motion import Motion, point, rotated
from assur.groups._protocol import CompileContext

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["assemble", "compile_group"]


def assemble(plan: DyadSolver, bodies: list[Motion], branch: Any) -> tuple[Any, Any]:
    r"""Return the first link's rotation (rad) and the slider's slide (m); NaN if open.

    Notes
    -----
    The middle pin is :math:`M = G + \sigma e` on the slider's line and
    :math:`|M - P| = r`: :math:`\sigma = -w\cdot e + \beta\sqrt{(w\cdot e)^2 -
    |w|^2 + r^2}` with :math:`w = G - P`.
    """
    px, py = point(bodies[plan.known[0]], plan.d_known[0], 0)
    slider = bodies[plan.known[1]]
    ex, ey = guide(plan, bodies, 1)
    gx, gy = point(slider, plan.d_known[1], 0)
    ux, uy = rotated(slider, plan.d_mid[1])
    d1 = plan.d_mid[0]
    wx, wy = gx + ux - px, gy + uy - py
    b = wx * ex + wy * ey
    with np.errstate(invalid="ignore"):
        sigma = (
            branch * np.sqrt(b * b - wx * wx - wy * wy + d1[0] * d1[0] + d1[1] * d1[1])
            - b
        )
    vx, vy = wx + sigma * ex, wy + sigma * ey
    return np.arctan2(d1[0] * vy - d1[1] * vx, d1[0] * vx + d1[1] * vy), sigma


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an RRP dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble)
