"""RRR dyad: two links pinned to known links and to each other.

The middle pin lies on two circles about the external pins; the branch (which of the
two intersections) is the one of the reference pose.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur._quiet import quiet
from assur.groups._dyad import DyadSolver, closing_root, compile_dyad
from assur.groups._motion import Motion, point
from assur.groups._protocol import CompileContext

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["assemble", "compile_group"]


def assemble(plan: DyadSolver, bodies: list[Motion], branch: Any) -> tuple[Any, Any]:
    r"""Return both links' rotations (rad); NaN where the dyad cannot close.

    Notes
    -----
    With pins :math:`P_1, P_2` a distance :math:`L` apart and link radii
    :math:`r_1, r_2`: :math:`a = (r_1^2 - r_2^2 + L^2)/2L`,
    :math:`h = \sqrt{r_1^2-a^2}`,
    :math:`M = P_1 + a\,\hat D + \beta h\,\hat D^\perp`.
    """
    r1, r2, gx, gy = _pins(plan, bodies)
    d1, d2 = plan.d_mid
    with quiet():
        inv = np.divide(1.0, gx * gx + gy * gy)
        a = 0.5 + 0.5 * (r1 - r2) * inv
        h = branch * closing_root(r1 * inv - a * a, r1 * inv)
    # u1 = M - P1 and u2 = M - P2 in components
    u1x, u1y = a * gx - h * gy, a * gy + h * gx
    u2x, u2y = u1x - gx, u1y - gy
    q1 = np.arctan2(d1[0] * u1y - d1[1] * u1x, d1[0] * u1x + d1[1] * u1y)
    q2 = np.arctan2(d2[0] * u2y - d2[1] * u2x, d2[0] * u2x + d2[1] * u2y)
    return q1, q2


def discriminant(plan: DyadSolver, bodies: list[Motion]) -> Any:
    r"""Return the square of the sine of the angle at the middle pin.

    Negative where the dyad cannot close; zero where its two branches meet.

    Notes
    -----
    With the middle pin at height :math:`h` over the line of the outer pins a
    distance :math:`L` apart: :math:`\sin\mu = h L / (r_1 r_2)`.
    """
    r1, r2, gx, gy = _pins(plan, bodies)
    length = gx * gx + gy * gy
    with quiet():
        a = 0.5 + 0.5 * np.divide(r1 - r2, length)
        return (np.divide(r1, length) - a * a) * length * length / (r1 * r2)


def _pins(plan: DyadSolver, bodies: list[Motion]) -> tuple[Any, Any, Any, Any]:
    """Return what the closure and its discriminant share.

    The links' squared radii (m^2) and ``P_2 - P_1`` (m), from pin to pin.
    """
    x1, y1 = point(bodies[plan.known[0]], plan.d_known[0], 0)
    x2, y2 = point(bodies[plan.known[1]], plan.d_known[1], 0)
    d1, d2 = plan.d_mid
    r1 = d1[0] * d1[0] + d1[1] * d1[1]
    r2 = d2[0] * d2[0] + d2[1] * d2[1]
    return r1, r2, x2 - x1, y2 - y1


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an RRR dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble, discriminant)
