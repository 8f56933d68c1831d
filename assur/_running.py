"""Running figures of a quantity over positions added slice by slice, per variant.

The largest value and where it occurs, the smallest, the sum and the sum of squares:
what a summary needs of a sweep too long to hold in memory (:mod:`assur.summary`).
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
    """Per variant: running maximum (and where), minimum, sum and sum of squares."""

    top: Array
    at: Array
    bottom: Array
    total: Array
    squares: Array
    last: Array
    """The values at the last position added (see
    :meth:`assur.summary.Summary.results`)."""

    @classmethod
    def start(cls, variants: int) -> Running:
        """Return the running values of ``variants`` variants before any position."""
        return cls(
            np.full(variants, -math.inf),
            np.full(variants, math.nan),
            np.full(variants, math.inf),
            np.zeros(variants),
            np.zeros(variants),
            np.zeros(variants),
        )

    def add(self, values: Array, where: Array) -> None:
        """Add ``values`` (variants, m) found at driver positions ``where`` (same)."""
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
        self.total = self.total + np.sum(values, axis=1)
        self.squares = self.squares + np.einsum("ij,ij->i", values, values)
        self.last = values[:, -1]


def lasts(values: Array, shape: tuple[int, int]) -> Array:
    """Return each variant's value at its last position (a table of variants).

    Zeros for a table of no positions.
    """
    if not shape[1]:
        return np.zeros(shape[0])
    return values.reshape(shape)[:, -1]


def sums(values: Array, shape: tuple[int, int]) -> Array:
    """Return the sum of each variant's values (a table of ``shape[0]`` variants)."""
    return np.sum(values.reshape(shape), axis=1)


def per_variant(value: Any, variants: int) -> Array:
    """Return a value as one number per variant (a sum of none is the float 0)."""
    return np.broadcast_to(np.asarray(value, dtype=float), (variants,)).copy()
