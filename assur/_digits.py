"""Numbers as the text outputs read them before they round: alike on every machine.

The note, the readable tables and the summaries round computed values to a few
digits; :func:`settled` first reads them to 12, so that the last bits the machine's
arithmetic sets (its BLAS kernels, FMA, SIMD, summation order) do not decide a
rounding.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["ROUND_OFF", "by_unit", "cleaned", "largest", "settled"]

ROUND_OFF = 1e-9
"""A value below this fraction of the largest of its unit in the same table is
round-off and shows as 0 (the readable tables, the HTML report's): a slider's speed
at its dead centre, 1.6e-14 m/s beside 22 m/s, has the sign and the digits of the
machine's arithmetic."""


def settled(value: float) -> float:
    """Return ``value`` read to 12 significant digits: the same double everywhere.

    A value that is a decimal tie in exact arithmetic (0.147 * 22.5 = 3.3075,
    364.0575 N) is an ulp either side of it by the machine's arithmetic, and
    ``"%.3f"`` wrote 3.307 on one machine and 3.308 on another. Read to 12 digits
    first, it is the tie's own double on every machine, and rounds alike. Minus
    zero becomes +0.

    Examples
    --------
    >>> f"{3.3074999999999997:.3f}", f"{settled(3.3074999999999997):.3f}"
    ('3.307', '3.308')
    >>> settled(-0.0), settled(float("inf"))
    (0.0, inf)
    """
    return float(f"{value:.12g}") + 0.0  # -0.0 + 0.0 is +0.0


def largest(values: Any) -> float:
    """Return the largest finite magnitude among ``values`` (0 for none)."""
    found = np.abs(np.asarray(values, dtype=float))
    return float(np.max(found, where=np.isfinite(found), initial=0.0))


def by_unit(units: list[str], values: list[Any]) -> list[float]:
    """Return, for each of ``values``, the largest magnitude among those of its unit.

    What a value is told from round-off by: a joint's reaction of 1e-14 N beside
    others' 3000 N, not a small mechanism's 1e-10 N.
    """
    most: dict[str, float] = {}
    for unit, value in zip(units, values, strict=True):
        most[unit] = max(most.get(unit, 0.0), largest(value))
    return [most[unit] for unit in units]


def cleaned(
    units: list[str], columns: list[Any], scales: list[float] | None = None
) -> list[Any]:
    """Return ``columns`` with their round-off set to +0, as the HTML report does.

    Round-off is below :data:`ROUND_OFF` of the largest magnitude of its unit among
    the ``columns`` (what the command line's readable table and a notebook's
    display show alike), or among the whole columns ``columns`` were cut from:
    their ``scales`` (:func:`by_unit`).
    """
    if scales is None:
        scales = by_unit(units, columns)
    return [
        np.where(np.abs(values) < ROUND_OFF * scale, 0.0, values)
        for values, scale in zip(columns, scales, strict=True)
    ]
