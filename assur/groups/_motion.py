"""Motion of one body over a batch of driver positions, and its points' derivatives.

A body's motion is its rotation from the reference pose and the path of its origin,
each with three time derivatives. Every point of the body follows from them; these
formulas are the only place where rigid-body kinematics is written out.
"""

from __future__ import annotations

import numpy as np

from assur._vec import Array, perp, rotate

__all__ = ["Motion", "direction", "point"]


class Motion:
    """Rotation ``phi[k]`` (rad, rad/s, ...) and origin ``o[k]`` (m, m/s, ...), k = 0..3.

    A mutable record used only while a sweep is being solved; the solved motion is
    copied into read-only arrays afterwards. ``c`` and ``s`` cache cos and sin of the
    rotation.
    """

    __slots__ = ("c", "o", "phi", "q", "s")

    def __init__(self, phi: list[Array], o: list[Array]) -> None:
        self.phi = phi
        self.o = o
        self.q: list[Array] = []  # a group's own coordinate of this body, by order
        self.c = np.cos(phi[0])
        self.s = np.sin(phi[0])

    def set_pose(self, phi: Array, o: Array) -> None:
        """Replace the position level and refresh the cached cosine and sine."""
        self.phi[0] = phi
        self.o[0] = o
        self.c = np.cos(phi)
        self.s = np.sin(phi)

    @classmethod
    def fixed(cls, n: int, origin: Array) -> Motion:
        """A body at rest at ``origin`` (the frame)."""
        zero = np.zeros(n)
        zero2 = np.zeros((n, 2))
        return cls([zero, zero, zero, zero],
                   [np.broadcast_to(origin, (n, 2)), zero2, zero2, zero2])


def _relative(m: Motion, u: Array, k: int) -> Array:
    """k-th derivative of a body-fixed vector whose current value is ``u``."""
    if k == 0:
        return u
    pu = perp(u)
    w = m.phi[1][:, None]
    if k == 1:
        return w * pu
    a = m.phi[2][:, None]
    if k == 2:
        return a * pu - (w * w) * u
    z = m.phi[3][:, None]
    return (z - w * w * w) * pu - 3.0 * w * a * u


def point(m: Motion, d: Array, k: int, u: Array | None = None) -> Array:
    """Return the k-th time derivative of the body point with local offset ``d``.

    Parameters
    ----------
    m : Motion
    d : ndarray of shape (2,)
        Offset of the point from the body's origin in the reference pose, m.
    k : int
        0 position (m), 1 velocity, 2 acceleration, 3 jerk.
    u : ndarray of shape (n, 2), optional
        The rotated offset, when already known.

    Notes
    -----
    With :math:`u = R(\\varphi) d`, :math:`\\dot u = \\omega u^\\perp`,
    :math:`\\ddot u = \\alpha u^\\perp - \\omega^2 u` and
    :math:`\\dddot u = (\\dot\\alpha - \\omega^3) u^\\perp - 3\\omega\\alpha u`.
    """
    if u is None:
        u = rotate(m.c, m.s, d)
    return m.o[k] + _relative(m, u, k)


def direction(m: Motion, e: Array, k: int) -> Array:
    """Return the k-th time derivative of the body-fixed direction ``e`` (2,)."""
    return _relative(m, rotate(m.c, m.s, e), k)
