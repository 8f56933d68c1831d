"""Where the lines of a sweep break: after the positions left out of it.

A sweep with ``skip_unassembled`` keeps the positions that can be drawn; a line drawn
through them would cross the positions left out as if it had data there. The report
(:mod:`assur.html`) and the diagrams (:mod:`assur.plotting`) break their lines at
the rows :func:`gaps` names.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._vec import Array

if TYPE_CHECKING:
    from assur.table import Table

__all__ = ["broken", "gaps"]


def gaps(table: Table) -> list[int]:
    """Return the rows after which positions were left out (the lines break there).

    Each row ``i`` follows a left-out position: one of the table's ``skipped``
    lies between its first driver's positions at rows ``i - 1`` and ``i``.
    """
    kept = np.asarray(table.given[:, 0], dtype=float)
    left = np.ravel(table.skipped) if table.skipped.ndim == 1 else table.skipped[:, 0]
    if len(kept) < 2 or not len(left):
        return []
    step = np.diff(kept)
    if not (np.all(step > 0) or np.all(step < 0)):
        return []  # a sweep that turns back: no order to place them in
    order = kept if step[0] > 0 else kept[::-1]
    at = np.searchsorted(order, left)
    rows = at if step[0] > 0 else len(kept) - at
    return np.unique(rows[(rows > 0) & (rows < len(kept))]).tolist()


def broken(values: Any, rows: Sequence[int]) -> Array:
    """Return ``values`` (one per row, shape (n, ...)) with a NaN row before ``rows``.

    matplotlib leaves a line's NaN points out and does not join across them, so a
    line through the result breaks before each of ``rows``; with no ``rows``,
    ``values`` come back as they are (as floats).

    Examples
    --------
    >>> broken([1.0, 2.0, 5.0], [2]).tolist()
    [1.0, 2.0, nan, 5.0]
    """
    found = np.asarray(values, dtype=float)
    if not len(rows):
        return found
    return np.insert(found, list(rows), np.nan, axis=0)
