"""RRR dyad: two links pinned to known links and to each other.

The middle pin lies on two circles about the external pins; the branch (which of the
two intersections) is the one of the reference pose.
"""

from __future__ import annotations

import numpy as np

from assur._vec import Array, cross, dot
from assur.groups._dyad import DyadPlan
from assur.groups._motion import Motion, point

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Array, Array]:
    """Return both links' rotations (rad); NaN where the dyad cannot close.

    Notes
    -----
    With pins :math:`P_1, P_2` a distance :math:`L` apart and link radii
    :math:`r_1, r_2`: :math:`a = (r_1^2 - r_2^2 + L^2)/2L`, :math:`h = \\sqrt{r_1^2-a^2}`,
    :math:`M = P_1 + a\\,\\hat D + \\beta h\\,\\hat D^\\perp`.
    """
    p1 = point(bodies[plan.known[0]], plan.d_known[0], 0)
    p2 = point(bodies[plan.known[1]], plan.d_known[1], 0)
    d1, d2 = plan.d_mid
    r1 = float(np.hypot(*d1))
    r2 = float(np.hypot(*d2))
    gap = p2 - p1
    length2 = dot(gap, gap)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = (r1 * r1 - r2 * r2 + length2) / (2.0 * length2)
        h = np.sqrt(r1 * r1 / length2 - a * a)
    m = p1 + a[:, None] * gap + (plan.branch * h)[:, None] * np.stack(
        (-gap[:, 1], gap[:, 0]), axis=-1)
    u1 = m - p1
    u2 = m - p2
    q1 = np.arctan2(cross(d1, u1), dot(d1, u1))
    q2 = np.arctan2(cross(d2, u2), dot(d2, u2))
    return q1, q2
