"""Numbers as the text outputs read them before they round: alike on every machine.

The note, the readable tables and the summaries round computed values to a few
digits; :func:`settled` first reads them to 12, so that the last bits the machine's
arithmetic sets (its BLAS kernels, FMA, SIMD, summation order) do not decide a
rounding.
"""

from __future__ import annotations

__all__ = ["settled"]


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
