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

__all__ = ["Running", "lasts", "per_variant", "sums"]


@dataclass
class Running:
    """Per variant: running maximum (and where), minimum, sums and sums of squares.

    ``total`` and ``squares`` are stacked (2, variants): over the positions, then
    weighted by time; ``last`` and ``last_squares`` are the terms of the last
    position added, stacked the same way (see
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

    def add(self, values: Array, where: Array, weights: Array) -> None:
        """Add ``values`` (variants, m) found at driver positions ``where`` (same).

        ``weights`` (same shape) is the time each position stands for (1 at the
        first position's speed).
        """
        if not values.shape[1]:
            return
        rows = np.arange(values.shape[0])
        # a NaN is no number to be largest or smallest: argmax took it for the
        # largest, and the slice's own largest was lost (the sums do carry it)
        k = np.argmax(np.where(np.isnan(values), -np.inf, values), axis=1)
        best = values[rows, k]
        better = best > self.top
        self.top = np.where(better, best, self.top)
        self.at = np.where(better, where[rows, k], self.at)
        self.bottom = np.fmin(self.bottom, np.fmin.reduce(values, axis=1))
        self.total = self.total + sums(values, values.shape, weights)
        square = values * values
        self.squares = self.squares + sums(square, values.shape, weights)
        self.last = lasts(values, values.shape, weights)
        self.last_squares = lasts(square, values.shape, weights)


def lasts(values: Array, shape: tuple[int, int], weights: Array) -> Array:
    """Return each variant's term at its last position, stacked (2, variants).

    The value, then the value times its weight; zeros for no positions.
    """
    if not shape[1]:
        return np.zeros((2, shape[0]))
    last = values.reshape(shape)[:, -1]
    return np.stack([last, last * weights.reshape(shape)[:, -1]])


def sums(values: Array, shape: tuple[int, int], weights: Array) -> Array:
    """Return each variant's sum of values, stacked (2, variants): plain, weighted.

    A weight of exactly 1 everywhere (a constant speed) gives the plain sum twice,
    to the last bit.
    """
    v = values.reshape(shape)
    return np.stack([np.sum(v, axis=1), np.sum(v * weights.reshape(shape), axis=1)])


def per_variant(value: Any, variants: int) -> Array:
    """Return a value as one number per variant (a sum of none is the float 0)."""
    return np.broadcast_to(np.asarray(value, dtype=float), (variants,)).copy()


def time_shares(speed: Array, first: Array) -> tuple[Array, bool]:
    """Return each position's time share and whether the crank stops or turns back.

    ``speed`` (variants, m) is the crank's speed at each position (rad/s),
    ``first`` (variants, 1) its speed at the sweep's first position: the share is
    ``|first| / |speed|``, the time per unit angle relative to the first position's
    (exactly 1 at a constant speed). A speed of zero, not finite, or turning the
    other way from the first has no share: the weights are then 1 there.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.abs(first) / np.abs(speed)
    usable = np.isfinite(w) & (w > 0.0) & (np.sign(speed) == np.sign(first))
    return np.where(usable, w, 1.0), not bool(np.all(usable))
