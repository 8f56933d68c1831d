"""Motion of one body over a batch of driver positions, and its points' derivatives.

A body's motion is its rotation from the reference pose and the path of its origin,
each with three time derivatives. Every point of the body follows from them; these
formulas are the only place where rigid-body kinematics is written out. Vectors are
pairs ``(x, y)`` of arrays of shape (n,) (or plain floats for what does not move, such
as the frame): separate components keep every operation on contiguous memory, and
constants cost nothing.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._vec import add, is_array

__all__ = ["Motion", "direction", "point", "point_into", "rotated"]

Vec = tuple[Any, Any]
"""A vector as ``(x, y)``, each an array (n,) or a float."""
ORIGIN = (0.0, 0.0)
"""The offset of a body's origin from itself."""


class Motion:
    """Rotation ``phi[k]`` (rad, rad/s, ...) and origin ``ox[k], oy[k]`` (m, m/s, ...).

    A mutable record used only while a sweep is being solved, k = 0..3; the solved
    motion is copied into read-only arrays afterwards. ``c`` and ``s`` cache the cosine
    and sine of the rotation, ``rot`` the rotated body-fixed offsets, ``q`` the group's
    own coordinate of the body by order.
    """

    __slots__ = ("c", "memo", "ox", "oy", "phi", "q", "rot", "s")

    def __init__(self, phi: list[Any], ox: list[Any], oy: list[Any]) -> None:
        self.phi = phi
        self.ox = ox
        self.oy = oy
        self.q: list[Any] = []
        # points' derivatives, kept once the motion is final (see ``finish``)
        self.memo: dict[tuple[tuple[float, float], int], Vec] | None = None
        self.set_pose(phi[0], ox[0], oy[0])

    def finish(self) -> None:
        """Declare every level solved: from now on points' derivatives are kept."""
        self.memo = {}

    def set_pose(self, phi: Any, ox: Any, oy: Any) -> None:
        """Replace the position level; refresh the cached cosine, sine and offsets."""
        self.phi[0], self.ox[0], self.oy[0] = phi, ox, oy
        if np.ndim(phi):
            self.c, self.s = np.cos(phi), np.sin(phi)
        else:
            self.c, self.s = float(np.cos(phi)), float(np.sin(phi))
        self.rot: dict[tuple[float, float], Vec] = {}
        self.memo = None  # a new pose is not final

    @classmethod
    def restore(
        cls, phi: list[Any], ox: list[Any], oy: list[Any], c: Any, s: Any
    ) -> Motion:
        """Return a motion whose rotation's cosine ``c`` and sine ``s`` are known."""
        m = cls.__new__(cls)
        m.phi, m.ox, m.oy, m.c, m.s = phi, ox, oy, c, s
        m.q = []
        m.rot = {}
        m.memo = None
        return m

    @classmethod
    def fixed(cls, x: float = 0.0, y: float = 0.0) -> Motion:
        """Return a body at rest with its origin at ``(x, y)`` (the frame)."""
        m = cls([0.0, 0.0, 0.0, 0.0], [x, 0.0, 0.0, 0.0], [y, 0.0, 0.0, 0.0])
        m.finish()
        return m


def rotated(m: Motion, d: tuple[float, float]) -> Vec:
    """Return the body-fixed offset ``d`` (m, reference pose) turned with the body."""
    u = m.rot.get(d)
    if u is None:
        c, s = m.c, m.s
        u = m.rot[d] = (c * d[0] - s * d[1], s * d[0] + c * d[1])
    return u


def _relative(m: Motion, u: Vec, k: int) -> Vec:
    """k-th derivative (k >= 1) of a body-fixed vector whose current value is ``u``."""
    ux, uy = u
    w = m.phi[1]
    if k == 1:
        return -w * uy, w * ux
    a = m.phi[2]
    if k == 2:
        w2 = w * w
        if a.__class__ is float and not a:  # a crank at constant speed
            return -w2 * ux, -w2 * uy
        return -a * uy - w2 * ux, a * ux - w2 * uy
    c1 = m.phi[3] - w * w * w
    c2 = 3.0 * w * a
    if c2.__class__ is float and not c2:
        return -c1 * uy, c1 * ux
    return -c1 * uy - c2 * ux, c1 * ux - c2 * uy


def point(m: Motion, d: tuple[float, float], k: int) -> Vec:
    r"""Return the k-th time derivative of the body point with local offset ``d``.

    Parameters
    ----------
    m : Motion
    d : tuple of float
        Offset of the point from the body's origin in the reference pose, m.
    k : int
        0 position (m), 1 velocity (m/s), 2 acceleration (m/s^2), 3 jerk (m/s^3).

    Notes
    -----
    With :math:`u = R(\varphi) d`, :math:`\dot u = \omega u^\perp`,
    :math:`\ddot u = \alpha u^\perp - \omega^2 u` and
    :math:`\dddot u = (\dot\alpha - \omega^3) u^\perp - 3\omega\alpha u`.
    """
    if d == ORIGIN:
        return m.ox[k], m.oy[k]  # the body's origin itself: nothing to compute
    memo = m.memo
    if memo is not None:
        found = memo.get((d, k))
        if found is not None:
            return found
    u = rotated(m, d)
    if k == 0:
        value = add(m.ox[0], u[0]), add(m.oy[0], u[1])
    else:
        rx, ry = _relative(m, u, k)
        value = add(m.ox[k], rx), add(m.oy[k], ry)
    if memo is not None:
        memo[(d, k)] = value
    return value


def point_into(
    m: Motion,
    d: tuple[float, float],
    k: int,
    x: Any,
    y: Any,
    spare: Any,
    keep: bool = False,
) -> None:
    """Write what :func:`point` returns into the arrays ``x`` and ``y``.

    The same arithmetic to the last bit, with every product written into the
    targets or ``spare`` (an array of their size): a long sweep's columns are filled
    slice by slice without a temporary array per operation. With ``keep``, a final
    motion keeps ``x`` and ``y`` as the point's value (they must not change after).
    """
    memo = m.memo
    if d == ORIGIN or not is_array(m.phi[0]):
        x[...], y[...] = point(m, d, k)
        return
    if memo is not None:
        found = memo.get((d, k))
        if found is not None:
            x[...], y[...] = found
            return
        if keep:
            memo[(d, k)] = (x, y)
    ux, uy = rotated(m, d)
    if k == 0:
        _shifted(m.ox[0], ux, x, 1.0)
        _shifted(m.oy[0], uy, y, 1.0)
        return
    # _relative's derivative is (-(p uy + q ux), p ux - q uy), the origin's added
    w = m.phi[1]
    if k == 1:
        p, q = w, 0.0
    elif k == 2:
        p, q = m.phi[2], w * w
    else:
        p, q = m.phi[3] - w * w * w, 3.0 * w * m.phi[2]
    if k == 2 and p.__class__ is float and not p:  # a crank at constant speed
        np.multiply(q, ux, out=x)
        np.multiply(q, uy, out=y)
        _shifted(m.ox[k], x, x, -1.0)
        _shifted(m.oy[k], y, y, -1.0)
        return
    np.multiply(p, uy, out=x)
    np.multiply(p, ux, out=y)
    if not (q.__class__ is float and not q):
        x += np.multiply(q, ux, out=spare)
        y -= np.multiply(q, uy, out=spare)
    _shifted(m.ox[k], x, x, -1.0)
    _shifted(m.oy[k], y, y, 1.0)


def _shifted(origin: Any, u: Any, out: Any, sign: float) -> None:
    """Write ``origin + sign * u`` into ``out`` as :func:`assur._vec.add` rounds it."""
    if origin.__class__ is float and not origin:
        if sign < 0.0:
            np.negative(u, out=out)
        elif u is not out:
            out[...] = u
    elif sign < 0.0:
        np.subtract(origin, u, out=out)
    else:
        np.add(origin, u, out=out)


def direction(m: Motion, e: tuple[float, float], k: int) -> Vec:
    """Return the k-th time derivative of the body-fixed direction ``e``."""
    u = rotated(m, e)
    return u if k == 0 else _relative(m, u, k)
