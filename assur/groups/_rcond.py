"""The reciprocal condition number of a batch of square matrices, read at thresholds.

The groups solved by Newton's method tell a dead centre by the reciprocal of the
2-norm condition number of their equations, ``sigma_min / sigma_max`` from the
singular values. numpy finds those by an SVD of every matrix, at about six times the
cost of the LU factorisation behind an inverse. Norms bound it from below:

    sigma_min / sigma_max >= 1 / (||A||_F ||A^-1||_F),

since ``sigma_max <= ||A||_F`` and ``1 / sigma_min = ||A^-1||_2 <= ||A^-1||_F``. Where
that bound already reaches the threshold the value is read against, the SVD could
only confirm it, and the bound stands in for the value; everywhere else the SVD
gives it. Every comparison with a threshold at or below ``above`` comes out as with
the exact value.
"""

from __future__ import annotations

import numpy as np

from assur._quiet import quiet
from assur._vec import Array

__all__ = ["reciprocal_condition"]

TRUSTED = 1e-4
"""Least bound taken for the value, whatever the threshold: the inverse of a matrix
conditioned so well (cond at most 1e4 times its order) is exact to some 1e-10, and
so is the SVD's value. Worse conditioned, both carry errors near ``cond * 1e-16``
(1e-4 at the threshold 1e-12): only the SVD then says which side the value is on,
as it did before the bound."""
MARGIN = 1e-6
"""Share by which the bound must clear the threshold, beyond the rounding of the
inverse and its norms at :data:`TRUSTED`."""
SANE = 1e100
"""Largest norm (and reciprocal of the smallest) trusted: beyond it the squares
summed could overflow, or underflow to nothing."""


def reciprocal_condition(a: Array, above: float | None = None) -> Array:
    """Return ``1 / cond(a)`` (2-norm), exactly wherever it may lie below ``above``.

    Parameters
    ----------
    a : ndarray, shape (n, m, m)
        The matrices.
    above : float, optional
        The largest threshold the result is compared with. Where the bound shows
        the value at least ``above`` (and at least :data:`TRUSTED`), the result is
        that bound, which is no larger than the value. None: the exact value
        everywhere.

    Returns
    -------
    ndarray, shape (n,)
        Dimensionless, 1 for an orthogonal matrix, 0 for a singular one.

    Examples
    --------
    >>> a = np.array([[[2.0, 0.0], [0.0, 1.0]], [[1.0, 1.0], [1.0, 1.0 + 1e-9]]])
    >>> r = reciprocal_condition(a, above=1e-3)
    >>> bool(r[0] >= 1e-3), bool(r[0] <= 0.5)
    (True, True)
    >>> bool(r[1] == 1.0 / np.linalg.cond(a[1]))
    True
    """
    if above is None or not a.shape[0]:
        return 1.0 / np.linalg.cond(a)
    with quiet():
        try:
            inverse = np.linalg.inv(a)
        except np.linalg.LinAlgError:  # a matrix exactly singular: the SVD for all
            return 1.0 / np.linalg.cond(a)
        big = np.sqrt(np.einsum("nij,nij->n", a, a))
        small = np.sqrt(np.einsum("nij,nij->n", inverse, inverse))
        bound = 1.0 / (big * small)
    sane = (big < SANE) & (big > 1.0 / SANE) & (small < SANE) & (small > 1.0 / SANE)
    sure = sane & (bound >= max(above, TRUSTED) * (1.0 + MARGIN))
    out = np.empty(a.shape[0])
    out[sure] = bound[sure]
    rest = ~sure
    if rest.any():
        out[rest] = 1.0 / np.linalg.cond(a[rest])
    return out
