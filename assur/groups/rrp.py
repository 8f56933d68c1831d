"""RRP dyad: a link pinned to a known link and to a slider on a known guide.

The middle pin lies on a circle about the external pin and on the slider's line; the
branch is the intersection of the reference pose.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur._vec import add, cross, dot, mul, sub
from assur.groups._dyad import DyadSolver, closing_root, compile_dyad, guide
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
    ex, ey, wx, wy, d1 = _reach(plan, bodies)
    b = dot((wx, wy), (ex, ey))
    # |w|^2 - (w.e)^2 is the squared distance of P from the slider's line
    normal = cross(ex, ey, wx, wy)
    reach = d1[0] * d1[0] + d1[1] * d1[1]
    root = closing_root(reach - normal * normal, reach)
    sigma = sub(mul(branch, root), b)
    vx, vy = add(wx, mul(sigma, ex)), add(wy, mul(sigma, ey))
    return np.arctan2(cross(d1[0], d1[1], vx, vy), dot(d1, (vx, vy))), sigma


def discriminant(plan: DyadSolver, bodies: list[Motion]) -> Any:
    """Return the square of the cosine of the angle between the link and the guide.

    Negative where the dyad cannot close; zero where its two branches meet (the link
    square to the guide).
    """
    ex, ey, wx, wy, d1 = _reach(plan, bodies)
    normal = cross(ex, ey, wx, wy)
    return 1.0 - normal * normal / (d1[0] * d1[0] + d1[1] * d1[1])


def _reach(plan: DyadSolver, bodies: list[Motion]) -> tuple[Any, ...]:
    """Return what the closure and its discriminant share.

    The guide's direction ``e``, ``w = G - P`` (m) from the first link's pin to the
    slider line's point at the middle pin's offset, and that link's offset ``d_1``.
    """
    px, py = point(bodies[plan.known[0]], plan.d_known[0], 0)
    slider = bodies[plan.known[1]]
    ex, ey = guide(plan, bodies, 1)
    gx, gy = point(slider, plan.d_known[1], 0)
    ux, uy = rotated(slider, plan.d_mid[1])
    wx, wy = sub(add(gx, ux), px), sub(add(gy, uy), py)
    return ex, ey, wx, wy, plan.d_mid[0]


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an RRP dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble, discriminant)
