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
from typing import Any

from assur._vec import add, cross, dot, mul, sub, wrap
from assur.groups._motion import Motion, Vec, direction, point, rotated

__all__ = ["PairPlan", "partials", "residual", "slide", "unit_wrenches"]


@dataclass(frozen=True, slots=True)
class PairPlan:
    """A pair between bodies ``first`` and ``second`` (indices into the body list).

    ``d_first`` and ``d_second`` are the offsets (m) of the pair's reference point from
    each body's origin; ``axis`` is the unit slide direction in the reference pose and
    ``normal`` the axis turned by +90 degrees (prismatic pairs only). ``friction`` is
    the Coulomb coefficient and ``radius`` a revolute pair's journal radius (m).
    """

    name: str
    kind: str
    first: int
    second: int
    d_first: tuple[float, float]
    d_second: tuple[float, float]
    axis: tuple[float, float] | None = None
    virtual: bool = False
    friction: float = 0.0
    radius: float = 0.0

    @property
    def normal(self) -> tuple[float, float]:
        """Unit normal of the slide line in the reference pose."""
        assert self.axis is not None
        return (-self.axis[1], self.axis[0])


def _dot_leibniz(
    pair: PairPlan, bodies: list[Motion], e: tuple[float, float], k: int
) -> Any:
    """k-th derivative of ``e(t) . (q2 - q1)`` with ``e`` fixed in the first link."""
    m1, m2 = bodies[pair.first], bodies[pair.second]
    total: Any = 0.0
    for m in range(k + 1):
        ex, ey = direction(m1, e, m)
        if m and ex.__class__ is float and ey.__class__ is float and not (ex or ey):
            continue  # the first link does not turn: e's derivatives are zero
        p2 = point(m2, pair.d_second, k - m)
        p1 = point(m1, pair.d_first, k - m)
        term = dot((ex, ey), (sub(p2[0], p1[0]), sub(p2[1], p1[1])))
        total = add(total, mul(float(comb(k, m)), term))
    return total


def residual(pair: PairPlan, bodies: list[Motion], k: int) -> Vec:
    r"""Return the k-th time derivative of the pair's two constraint equations.

    Notes
    -----
    Revolute: :math:`p_1 - p_2 = 0`. Prismatic: :math:`\varphi_2 - \varphi_1 = 0` and
    :math:`n \cdot (q_2 - q_1) = 0` with :math:`n` fixed in the first link; the k-th
    derivative of the product follows Leibniz's rule.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    if pair.kind == "R":
        x1, y1 = point(m1, pair.d_first, k)
        x2, y2 = point(m2, pair.d_second, k)
        return sub(x1, x2), sub(y1, y2)
    rot = sub(m2.phi[k], m1.phi[k])
    if k == 0:
        rot = wrap(rot)
    return rot, _dot_leibniz(pair, bodies, pair.normal, k)


def partials(
    pair: PairPlan, bodies: list[Motion], body: int
) -> tuple[tuple[Any, ...], ...]:
    """Return d(residual)/d(o_x, o_y, phi) of one of the pair's bodies, per equation.

    The result is two rows (one per equation), each a tuple of three entries: the
    sensitivities to the body's top-order origin derivative (x, y) and rotation
    derivative. They are the same at every derivative order.
    """
    m1, m2 = bodies[pair.first], bodies[pair.second]
    is_first = body == pair.first
    if pair.kind == "R":
        m, d, sign = (m1, pair.d_first, 1.0) if is_first else (m2, pair.d_second, -1.0)
        ux, uy = rotated(m, d)
        return ((sign, 0.0, mul(-sign, uy)), (0.0, sign, mul(sign, ux)))
    nx, ny = rotated(m1, pair.normal)
    if is_first:
        ux, uy = rotated(m1, pair.d_first)
        px, py = point(m2, pair.d_second, 0)
        gx, gy = sub(px, add(m1.ox[0], ux)), sub(py, add(m1.oy[0], uy))
        dphi = add(cross(nx, ny, gx, gy), cross(nx, ny, ux, uy))
        return ((0.0, 0.0, -1.0), (mul(-1.0, nx), mul(-1.0, ny), dphi))
    ux, uy = rotated(m2, pair.d_second)
    return ((0.0, 0.0, 1.0), (nx, ny, cross(ny, nx, uy, ux)))


def unit_wrenches(pair: PairPlan, bodies: list[Motion]) -> tuple[tuple[Any, ...], ...]:
    """Return the wrenches on the second link per unit reaction unknown.

    Each wrench is ``(F_x, F_y, tau)`` with the moment ``tau`` taken about the fixed
    origin. Revolute unknowns: the force components (N). Prismatic unknowns: the
    normal force along the slide line's normal (N) acting at the joint's point moving
    with the second link, and the couple (N m). The first link receives the opposite.
    """
    qx, qy = point(bodies[pair.second], pair.d_second, 0)
    if pair.kind == "R":
        return ((1.0, 0.0, mul(-1.0, qy)), (0.0, 1.0, qx))
    nx, ny = rotated(bodies[pair.first], pair.normal)
    return ((nx, ny, cross(qx, qy, nx, ny)), (0.0, 0.0, 1.0))


def slide(pair: PairPlan, bodies: list[Motion], k: int) -> Any:
    """Return the k-th derivative of a prismatic pair's slide (m, m/s, ...).

    The slide is the displacement of the second link's point relative to the first
    link's, along the axis fixed in the first link, zero in the reference pose.
    """
    assert pair.axis is not None
    return _dot_leibniz(pair, bodies, pair.axis, k)
