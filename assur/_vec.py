"""Private 2-D vector helpers on batches of shape ``(n, 2)``.

Vectors are the last axis of an array; every helper broadcasts, so a single ``(2,)``
vector works against a batch.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def cross(a: Array, b: Array) -> Array:
    """Return the z component of ``a x b`` (the 2-D cross product)."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: Array, b: Array) -> Array:
    """Return the dot product over the last axis."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def perp(a: Array) -> Array:
    """Return ``a`` turned by +90 degrees: ``(-a_y, a_x)``."""
    return np.stack((-a[..., 1], a[..., 0]), axis=-1)


def rotate(c: Array, s: Array, d: Array) -> Array:
    """Rotate the vector(s) ``d`` by the angle whose cosine and sine are ``c``, ``s``.

    ``c`` and ``s`` have shape ``(n,)``; ``d`` has shape ``(2,)`` or ``(m, 2)``. The
    result has shape ``(n, 2)`` or ``(n, m, 2)``.
    """
    if d.ndim == 1:
        return np.stack((c * d[0] - s * d[1], s * d[0] + c * d[1]), axis=-1)
    c = c[:, None]
    s = s[:, None]
    return np.stack((c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]), axis=-1)


def angle(a: Array) -> Array:
    """Return the direction of ``a`` in radians, in (-pi, pi]."""
    return np.arctan2(a[..., 1], a[..., 0])


def norm(a: Array) -> Array:
    """Return the length of ``a``."""
    return np.hypot(a[..., 0], a[..., 1])


def wrap(phi: Array) -> Array:
    """Wrap angles to (-pi, pi]."""
    return np.pi - np.mod(np.pi - phi, 2.0 * np.pi)
