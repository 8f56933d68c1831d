"""A cycle's mechanical efficiency, from the mean powers with and without friction."""

from __future__ import annotations

import math

__all__ = ["efficiency"]


def efficiency(power: float, ideal: float, lost: float) -> float:
    """Return the cycle's mechanical efficiency, ``ideal / power``.

    The share of the driver's work over a cycle that reaches the loads.

    ``power`` is the driver's mean power with friction, ``ideal`` the same without
    friction (the work the loads take from the driver, inertia's work cancelling over
    a cycle) and ``lost`` the mean power lost to friction (W); over a steady cycle
    ``power = ideal + lost``. A cycle in which the driver only overcomes friction
    (``ideal`` zero within rounding) has efficiency 0. NaN where efficiency is not
    defined: the driver does no net work (``power <= 0``, the loads drive the
    mechanism), or the loads give back work the driver still has to supply.
    """
    if not power > 0.0:
        return math.nan
    # ``ideal`` cancels over a cycle of inertia loads alone: rounding then leaves
    # a few ulps of the powers at play, not a negative efficiency
    if abs(ideal) <= 1e-9 * (abs(power) + abs(lost)):
        return 0.0
    if ideal < 0.0:
        return math.nan
    return ideal / power
