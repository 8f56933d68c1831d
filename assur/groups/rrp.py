"""RRP dyad: a link pinned to a known link and to a slider on a known guide.

The middle pin lies on a circle about the external pin and on the slider's line; the
branch is the intersection of the reference pose.
"""

from __future__ import annotations

import numpy as np

from assur._vec import Array, cross, dot, rotate
from assur.groups._dyad import DyadPlan, guide
from assur.groups._motion import Motion, point

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Array, Array]:
    """Return the first link's rotation (rad) and the slider's slide (m); NaN if open.

    Notes
    -----
    The middle pin is :math:`M = G + \\sigma e` on the slider's line and
    :math:`|M - P| = r`: :math:`\\sigma = -w\\cdot e + \\beta\\sqrt{(w\\cdot e)^2 -
    |w|^2 + r^2}` with :math:`w = G - P`.
    """
    pin = point(bodies[plan.known[0]], plan.d_known[0], 0)
    slider = bodies[plan.known[1]]
    e = guide(plan, bodies, 1)
    base = point(slider, plan.d_known[1], 0) + rotate(slider.c, slider.s, plan.d_mid[1])
    d1 = plan.d_mid[0]
    w = base - pin
    b = dot(w, e)
    with np.errstate(invalid="ignore"):
        sigma = -b + plan.branch * np.sqrt(b * b - dot(w, w) + dot(d1, d1))
    u1 = w + sigma[:, None] * e
    return np.arctan2(cross(d1, u1), dot(d1, u1)), sigma
