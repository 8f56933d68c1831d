"""RPR dyad: two links pinned to known links, one sliding along the other.

Both links turn together (the prismatic pair keeps their relative rotation); their
rotation makes the slide line pass at the right distance from the other pin.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._quiet import quiet
from assur._vec import norm, wrap
from assur.groups._dyad import DyadSolver, compile_dyad
from assur.groups._motion import Motion, point
from assur.groups._protocol import CompileContext

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["assemble", "compile_group"]


def assemble(plan: DyadSolver, bodies: list[Motion], branch: Any) -> tuple[Any, Any]:
    r"""Return the common rotation (rad) of both links, twice; NaN if it cannot close.

    Notes
    -----
    With :math:`D = P_h - P_g` from the guide link's pin to the other's and the
    reference normal :math:`n_0` at angle :math:`\nu`:
    :math:`|D|\cos(\angle D - \nu - \varphi) = n_0\cdot(d_g - d_h)`.
    """
    gx, gy, n0, c0 = _across(plan, bodies)
    with quiet():
        psi = np.arccos(c0 / norm(gx, gy))
    phi = wrap(np.arctan2(gy, gx) - math.atan2(n0[1], n0[0]) - branch * psi)
    return phi, phi


def discriminant(plan: DyadSolver, bodies: list[Motion]) -> Any:
    """Return the squared sine of the angle between the slide line and the pins' line.

    Negative where the dyad cannot close; zero where its two branches meet.
    """
    gx, gy, _, c0 = _across(plan, bodies)
    with quiet():
        return 1.0 - c0 * c0 / (gx * gx + gy * gy)


def _across(plan: DyadSolver, bodies: list[Motion]) -> tuple[Any, Any, Any, Any]:
    """Return what the closure and its discriminant share.

    ``D = P_h - P_g`` (m, two leaves), the reference normal ``n_0`` and
    ``n_0 . (d_g - d_h)`` (m).
    """
    g = 0 if plan.bodies[0] == plan.mid.first else 1
    h = 1 - g
    pins = [point(bodies[plan.known[b]], plan.d_known[b], 0) for b in (0, 1)]
    gx, gy = pins[h][0] - pins[g][0], pins[h][1] - pins[g][1]
    n0 = plan.mid.normal
    dg, dh = plan.d_mid[g], plan.d_mid[h]
    c0 = n0[0] * (dg[0] - dh[0]) + n0[1] * (dg[1] - dh[1])
    return gx, gy, n0, c0


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an RPR dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble, discriminant)
