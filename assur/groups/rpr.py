"""RPR dyad: two links pinned to known links, one sliding along the other.

Both links turn together (the prismatic pair keeps their relative rotation); their
rotation makes the slide line pass at the right distance from the other pin.
"""

from __future__ import annotations

import numpy as np

from assur._vec import Array, wrap
from assur.groups._dyad import DyadPlan
from assur.groups._motion import Motion, point

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Array, Array]:
    """Return the common rotation (rad) of both links, twice; NaN where it cannot close.

    Notes
    -----
    With :math:`D = P_h - P_g` from the guide link's pin to the other's and the
    reference normal :math:`n_0` at angle :math:`\\nu`:
    :math:`|D|\\cos(\\angle D - \\nu - \\varphi) = n_0\\cdot(d_g - d_h)`.
    """
    g = 0 if plan.bodies[0] == plan.mid.first else 1
    h = 1 - g
    pins = [point(bodies[plan.known[b]], plan.d_known[b], 0) for b in (0, 1)]
    gap = pins[h] - pins[g]
    n0 = plan.mid.normal
    c0 = float(n0 @ (plan.d_mid[g] - plan.d_mid[h]))
    with np.errstate(invalid="ignore", divide="ignore"):
        psi = np.arccos(c0 / np.hypot(gap[:, 0], gap[:, 1]))
    phi = wrap(np.arctan2(gap[:, 1], gap[:, 0]) - np.arctan2(n0[1], n0[0])
               - plan.branch * psi)
    return phi, phi
