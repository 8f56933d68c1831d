"""Running figures of a quantity over positions added slice by slice, per variant.

The largest value and where it occurs, the smallest, the sum and the sum of squares:
what a summary needs of a sweep too long to hold in memory (:mod:`assur.summary`).
Every sum is kept twice, stacked: over the positions (row 0) and over time (row 1),
each position weighted by the time it stands for (see
:meth:`assur.summary.Summary.timed`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array

__all__ = [
    "TIE",
    "Running",
    "lasts",
    "peaks",
    "per_variant",
    "settled_mean",
    "sums",
]

TIE = 1e-12
"""Largest values closer than this share of their size are a tie, and the first
position of them is where the largest occurs."""


@dataclass
class Running:
    """Per variant: running maximum (and where), minimum, sums and sums of squares.

    ``total`` and ``squares`` are stacked (2, variants): over the positions, then
    weighted by time (see :func:`sums`); ``last`` and ``last_squares`` are the
    terms of the last position added, stacked the same way (see
    :meth:`assur.summary.Summary.results`).
    """

    top: Array
    at: Array
    bottom: Array
    total: Array
    squares: Array
    last: Array
    last_squares: Array

    @classmethod
    def start(cls, variants: int) -> Running:
        """Return the running values of ``variants`` variants before any position."""
        return cls(
            np.full(variants, -math.inf),
            np.full(variants, math.nan),
            np.full(variants, math.inf),
            np.zeros((2, variants)),
            np.zeros((2, variants)),
            np.zeros((2, variants)),
            np.zeros((2, variants)),
        )

    def add(
        self,
        values: Array,
        where: Array,
        weights: Array | None,
        last: Array,
        floor: Any = 0.0,
    ) -> None:
        """Add ``values`` (variants, m) found at driver positions ``where`` (same).

        ``weights`` (2, variants, m) is each value's share over the positions and
        over time (see :func:`sums`); ``last`` holds the indices of the values of
        the last position added. ``floor`` (one per variant, or one) is the size
        the values' round-off is a share of where it is larger than their own: a
        small couple's, 5.5e-4 N m, is that of the reactions of 2800 N it is
        found beside, times the mechanism's size.
        """
        if not values.shape[1]:
            return
        rows = np.arange(values.shape[0])
        # a NaN is no number to be largest or smallest: argmax took it for the
        # largest, and the slice's own largest was lost (the sums do carry it)
        clean = np.where(np.isnan(values), -np.inf, values)
        best = np.max(clean, axis=1)
        # the first position within round-off of the largest: poses alike by
        # symmetry (a centred slider-crank's guide at 41 and 319 deg) tie but for
        # the last bit, which the machine's arithmetic gives to either
        tie = _less_tie(best, floor)
        k = np.argmax(clean >= tie[:, None], axis=1)
        better = tie > self.top
        self.at = np.where(better, where[rows, k], self.at)
        self.top = np.fmax(self.top, best)
        self.bottom = np.fmin(self.bottom, np.fmin.reduce(values, axis=1))
        self.total = self.total + sums(values, weights)
        square = values * values
        self.squares = self.squares + sums(square, weights)
        self.last = lasts(values, weights, last)
        self.last_squares = lasts(square, weights, last)


def _less_tie(best: Array, floor: Any = 0.0) -> Array:
    """Return the least value that ties with ``best`` (see :data:`TIE`).

    Within ``TIE`` of the larger of ``|best|`` and ``floor`` (see
    :meth:`Running.add`).
    """
    size = np.fmax(np.abs(best), floor)
    with np.errstate(invalid="ignore"):  # an infinite best ties with itself alone
        return np.where(np.isfinite(best), best - TIE * size, best)


def lasts(values: Array, weights: Array | None, last: Array) -> Array:
    """Return the terms of the last position added, stacked as :func:`sums` gives.

    ``last`` holds the indices of its values among ``values`` (variants, m): its
    value, and at a step of a load table its value before the step too.
    """
    return sums(values[:, last], None if weights is None else weights[:, :, last])


def sums(values: Array, weights: Array | None) -> Array:
    """Return each variant's weighted sum of ``values`` (variants, m), stacked (2, v).

    ``weights`` (2, variants, m): row 0 each value's share of its position (1, or
    a half each side of a load table's step), row 1 that times the time the
    position stands for; None where every weight is 1 (a constant speed, no
    step): the plain sum, twice.
    """
    if weights is None:
        total = values.sum(axis=1)
        return np.array((total, total))
    return np.einsum("vm,wvm->wv", values, weights)


def peaks(values: Array) -> Array:
    """Return each variant's largest of ``values`` (variants, m): 0 for none."""
    return np.fmax.reduce(values, axis=1, initial=0.0)


def per_variant(value: Any, variants: int) -> Array:
    """Return a value as one number per variant (a sum of none is the float 0)."""
    return np.broadcast_to(np.asarray(value, dtype=float), (variants,)).copy()


def settled_mean(mean: Array, low: Array, high: Array, share: float) -> Array:
    """Return ``mean``, 0 where it is round-off of values from ``low`` to ``high``.

    The mean is also kept between ``low`` and ``high``: the sum of a constant's
    values, divided by their count, came out one rounding step above the largest
    (793.1034482758622 W against 793.1034482758621 W).

    A turn's mean of a load that does no net work (the driving torque of a
    mechanism with inertia loads alone, 0.23 N m at its peak) sums terms that
    cancel: -1.5e-16 N m on one machine, +3e-17 on another, by the summation
    order and the BLAS kernels of each. Below ``share`` of the largest
    magnitude, ``max(|low|, |high|)``, it is that round-off and is +0.

    Parameters
    ----------
    mean, low, high : ndarray, shape (variants,)
        The mean, the smallest and the largest value, one per variant, in the
        quantity's unit (N m, N or W).
    share : float
        The fraction of the largest magnitude below which the mean is round-off.

    Returns
    -------
    ndarray, shape (variants,)
        The mean, with +0.0 where it is round-off (NaN stays NaN).

    Examples
    --------
    >>> settled_mean(np.array([-1.5e-16, 0.05]), np.array([-0.1, -0.1]),
    ...              np.array([0.2, 0.2]), 1e-12)
    array([0.  , 0.05])
    """
    size = np.maximum(np.abs(low), np.abs(high))
    # NaN stays NaN: np.maximum and np.minimum carry it through
    inside = np.minimum(np.maximum(mean, low), high)
    return np.where(np.abs(inside) <= share * size, 0.0, inside)
