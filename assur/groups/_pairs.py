"""Constraint equations of the lower pairs, shared by every group solver.

A revolute pair keeps a point of its first link on a point of its second; a prismatic
pair keeps their relative rotation at its reference value (zero) and the second link's
point on the slide line fixed in the first. For each pair this module gives the k-th
time derivative of those equations (the residual), their partial derivatives with
respect to a body's top-order unknowns (the Jacobian, the same at every order) and
the unit wrenches of the pair's reaction unknowns.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import comb

import numpy as np

from assur._vec import Array, rotate, wrap
from assur.groups._motion import Motion, direction, point

__all__ = ["PairPlan", "partials", "residual", "slide", "unit_wrenches"]


@dataclass(frozen=True, slots=True)
class PairPlan:
    """A pair between bodies ``first`` and ``second`` (indices into the body list).

    ``d_first`` and ``d_second`` are the offsets (m) of the pair's reference point from
    each body's origin; ``axis`` is the unit slide direction in the reference pose
    (prismatic pairs only).
    """

    name: str
    kind: str
    first: int
    second: int
    d_first: Array
    d_second: Array
    axis: Array | None = None
    virtual: bool = False

    @property
    def normal(self) -> Array:
        """Unit normal of the slide line in the reference pose."""
        assert self.axis is not None
        return np.array([-self.axis[1], self.axis[0]])


def residual(pair: PairPlan, bodies: list[Motion], k: int) -> tuple[Array, Array]:
    """Return the k-th time derivative of the pair's two constraint equations.

    Notes
    -----
    Revolute: :math:`p_1 - p_2 = 0`. Prismatic: :math:`\\varphi_2 - \\varphi_1 = 0` and
    :math:`n \\cdot (q_2 - q_1) = 0` with :math:`n` fixed in the first link; the k-th
    derivative of the product follows Leibniz's rule.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    if pair.kind == "R":
        r = point(m1, pair.d_first, k) - point(m2, pair.d_second, k)
        return r[:, 0], r[:, 1]
    rot = m2.phi[k] - m1.phi[k]
    if k == 0:
        rot = wrap(rot)
    n0 = pair.normal
    normal = 0.0
    for m in range(k + 1):
        gap = point(m2, pair.d_second, k - m) - point(m1, pair.d_first, k - m)
        dn = direction(m1, n0, m)
        normal = normal + comb(k, m) * (dn[:, 0] * gap[:, 0] + dn[:, 1] * gap[:, 1])
    return rot, normal


def partials(pair: PairPlan, bodies: list[Motion], body: int) -> tuple[tuple[Array, ...], ...]:
    """Return d(residual)/d(o_x, o_y, phi) of one of the pair's bodies, per equation.

    The result is two rows (one per equation), each a tuple of three arrays (n,):
    the sensitivities to the body's top-order origin derivative (x, y) and rotation
    derivative. They are the same at every derivative order.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    n = m1.c.shape[0] if np.ndim(m1.c) else m2.c.shape[0]
    one = np.ones(n)
    zero = np.zeros(n)
    is_first = body == pair.first
    if pair.kind == "R":
        m, d, sign = (m1, pair.d_first, 1.0) if is_first else (m2, pair.d_second, -1.0)
        u = rotate(m.c, m.s, d)
        return ((sign * one, zero, -sign * u[:, 1]), (zero, sign * one, sign * u[:, 0]))
    nv = rotate(m1.c, m1.s, pair.normal)
    if is_first:
        u1 = rotate(m1.c, m1.s, pair.d_first)
        gap = point(m2, pair.d_second, 0) - (m1.o[0] + u1)
        dphi = (-nv[:, 1] * gap[:, 0] + nv[:, 0] * gap[:, 1]
                - (nv[:, 0] * -u1[:, 1] + nv[:, 1] * u1[:, 0]))
        return ((zero, zero, -one), (-nv[:, 0], -nv[:, 1], dphi))
    u2 = rotate(m2.c, m2.s, pair.d_second)
    dphi = nv[:, 0] * -u2[:, 1] + nv[:, 1] * u2[:, 0]
    return ((zero, zero, one), (nv[:, 0], nv[:, 1], dphi))


def unit_wrenches(pair: PairPlan, bodies: list[Motion]) -> tuple[tuple[Array, ...], ...]:
    """Return the wrenches on the second link per unit reaction unknown.

    Each wrench is ``(F_x, F_y, tau)`` with the moment ``tau`` taken about the fixed
    origin. Revolute unknowns: the force components (N). Prismatic unknowns: the
    normal force along the slide line's normal (N) acting at the joint's point moving
    with the second link, and the couple (N m). The first link receives the opposite.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    q = point(m2, pair.d_second, 0)
    zero = np.zeros(q.shape[0])
    one = np.ones(q.shape[0])
    if pair.kind == "R":
        return ((one, zero, -q[:, 1]), (zero, one, q[:, 0]))
    nv = rotate(m1.c, m1.s, pair.normal)
    return ((nv[:, 0], nv[:, 1], q[:, 0] * nv[:, 1] - q[:, 1] * nv[:, 0]), (zero, zero, one))


def slide(pair: PairPlan, bodies: list[Motion], k: int) -> Array:
    """Return the k-th derivative of a prismatic pair's slide (m, m/s, ...).

    The slide is the displacement of the second link's point relative to the first
    link's, along the axis fixed in the first link, zero in the reference pose.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    assert pair.axis is not None
    total = 0.0
    for m in range(k + 1):
        gap = point(m2, pair.d_second, k - m) - point(m1, pair.d_first, k - m)
        de = direction(m1, pair.axis, m)
        total = total + comb(k, m) * (de[:, 0] * gap[:, 0] + de[:, 1] * gap[:, 1])
    return total
