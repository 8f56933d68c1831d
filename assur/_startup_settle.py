"""When a start-up settles, and the periodic motion's extreme speeds.

It settles where its speed enters the band around the periodic speed at the same
crank angle: the samples (90 a turn) only say in which interval it last enters it;
the time itself, like the extremes, is found on the integrator's continuous solution.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._vec import Array

if TYPE_CHECKING:
    from assur.dynamics_startup import _Runs

SCAN = 2048
"""Points a turn the continuous solution is scanned at, from the last sample out of
the band to the end of its turn (the samples are 90 a turn)."""


def periodic_speed(fine: Array, sense: float) -> Any:
    """Return the periodic speed (rad/s) as a function of the crank angle (rad).

    ``fine`` is the last turn, ``(angles, speeds)`` at evenly spaced times from its
    start to its end (the start's pose again, left out), turning the way of
    ``sense``; a periodic cubic spline in the angle turned.
    """
    from scipy.interpolate import CubicSpline

    phi0, full = float(fine[0][0]), 2.0 * math.pi
    x = np.append(sense * (fine[0][:-1] - phi0), full)
    spline = CubicSpline(x, np.append(fine[1][:-1], fine[1][0]), bc_type="periodic")

    def speed(phi: Any) -> Any:
        return spline((sense * (phi - phi0)) % full)

    return speed


def settle_time(
    runs: _Runs, samples: tuple[Array, Array, Array], speed: Any, band: float
) -> float:
    """Return the time (s) after which ``|omega - speed(angle)| <= band`` for good.

    ``samples`` are the time (s), crank angle (rad) and speed (rad/s) of every
    turn. The last sample outside the band names the turn; that turn is integrated
    again (the same steps, so the same continuous solution), scanned from that
    sample to its end at ``SCAN`` points a turn, and the last crossing into the
    band refined by Brent's method.
    """
    time, angle, omega = samples
    off = np.flatnonzero(np.abs(omega - speed(angle)) > band)
    if off.size == 0:
        return 0.0
    begin = float(time[off[-1]])
    k = int(np.searchsorted([s[0] for s in runs.starts], begin, "right")) - 1
    sol = runs.turn(*runs.starts[k], k + 1)
    first, end = float(sol.t[0]), float(sol.t_events[0][0])
    count = max(2, math.ceil(SCAN * (end - begin) / (end - first)))
    return _crossing(sol.sol, speed, band, np.linspace(begin, end, count + 1))


def _crossing(motion: Any, speed: Any, band: float, times: Array) -> float:
    """Return the last time of ``times``' span the speed comes into the band."""
    from scipy.optimize import brentq

    def outside(t: Any) -> Any:
        phi, w = motion(t)
        return np.abs(w - speed(phi)) - band

    out = outside(times) > 0
    if out[-1]:  # out by a hair at the turn's end, in at the next turn's start
        return float(times[-1])
    i = int(np.flatnonzero(out)[-1]) if out.any() else 0
    low, high = float(times[i]), float(times[i + 1])
    if not out[i]:  # the sample out by a hair, the continuous solution not
        return low
    return float(
        brentq(lambda t: float(outside(t)), low, high, xtol=1e-12 * (high - low))
    )


def extreme(motion: Any, times: Array, speeds: Array, sign: float) -> float:
    """Return the largest (``sign`` 1) or smallest (-1) speed of the last turn, rad/s.

    The best sample of ``times``, refined between its neighbours on the dense
    solution ``motion`` (samples alone miss the peak by up to 1e-5 of it).
    """
    from scipy.optimize import minimize_scalar

    i = int(np.argmax(sign * speeds))
    low, high = times[max(i - 1, 0)], times[min(i + 1, len(times) - 1)]
    found = minimize_scalar(
        lambda t: -sign * abs(float(motion(t)[1])),
        bounds=(low, high),
        method="bounded",
        options={"xatol": 1e-12 * max(abs(high), 1.0)},
    )
    best = abs(float(motion(found.x)[1]))
    # never worse than the sample itself
    return max(best, float(speeds[i])) if sign > 0 else min(best, float(speeds[i]))
