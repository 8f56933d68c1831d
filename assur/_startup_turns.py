"""How a start-up's run of turns ends: each turn made, and the motion periodic.

A crank that stalls or creeps instead of turning, or whose speed still changes after
the last turn allowed, is a :class:`~assur.errors.ModelError`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._text import counted
from assur.dynamics_reduced import Reduced
from assur.errors import ModelError
from assur.model import Motor

if TYPE_CHECKING:
    from assur.dynamics_startup import _Curves, _Runs


PERIODIC_RTOL = 1e-8
"""The motion is periodic when the speed at the reference pose, extrapolated from the
last turns, changes by less than this fraction of itself."""
WINDOW = 8
"""Most turns the ratio of successive changes is taken over (their geometric mean),
which damps the noise of single turns' changes near the periodic motion."""
TRUST = 0.1
"""The turns still needed are told only while the ratio of successive changes would
move by less than this fraction of ``1 - r`` over the rest of the approach."""


def _check_turned(sol: Any, model: Reduced, curves: _Curves, motor: Motor) -> None:
    """Raise when the crank stalled or crept to a halt instead of turning."""
    if sol.status == 1 and len(sol.t_events[0]):
        return
    if sol.status < 0:
        msg = f"startup: the time integration failed: {sol.message}"
        raise ModelError(msg)
    if not len(sol.t_events[1]):  # the time limit: still moving, ever so slowly
        phi, w, when = float(sol.y[0, -1]), float(sol.y[1, -1]), float(sol.t[-1])
        msg = (
            f"startup: the crank creeps: {when - float(sol.t[0]):.6g} s after its "
            f"last turn it has not made another (at crank angle "
            f"{math.degrees(phi):.6g} deg, {w:.6g} rad/s); expected a motor or "
            "flywheel that turns it at a pace"
        )
        raise ModelError(msg)
    phi, when = float(sol.y_events[1][0][0]), float(sol.t_events[1][0])
    _, _, load = curves(phi)
    where = math.degrees(phi)
    msg = (
        f"startup: the crank stalls at crank angle {where:.6g} deg (at t = "
        f"{when:.6g} s): the motor cannot carry it past its peak load (load torque "
        f"{load:.6g} N m there, motor torque at standstill {motor.torque:.6g} N m)"
    )
    raise ModelError(msg)


def _periodic(crossings: list[float]) -> bool:
    """Whether the speeds at the reference pose have stopped changing.

    The changes from turn to turn are taken to shrink geometrically; what is left of
    them must be below ``PERIODIC_RTOL`` of the speed.
    """
    if len(crossings) < 3:
        return False
    last, before, earlier = crossings[-1], crossings[-2], crossings[-3]
    change, previous = abs(last - before), abs(before - earlier)
    limit = PERIODIC_RTOL * abs(last)
    if change > limit:
        return False
    if change == 0 or previous == 0:
        return True
    ratio = change / previous
    return ratio < 1 and change * ratio / (1 - ratio) <= limit


def _not_settled(
    runs: _Runs, motor: Motor, model: Reduced, turns: int, omega0: float
) -> None:
    """Raise: the speed still changes after ``turns`` turns.

    The change is the last turn's; after a single turn, from the speed at the start.
    """
    speeds = [omega0, *runs.crossings]
    last, before = speeds[-1], speeds[-2]
    change = abs(last - before) / abs(last)
    hint = ""
    if motor.no_load_speed is None:
        hint = (
            f"; a constant torque settles only where it balances the mean load, at "
            f"{model.motor:.6g} N m (the motor torque of assur.dynamics), so give "
            "the motor a no_load_speed"
        )
    else:
        more = _turns_left(runs.crossings)
        if more is None:
            hint = (
                "; its change a turn does not shrink at a steady ratio yet (the "
                "crank still gathering speed, say), so the turns it needs cannot be "
                "told; expected a larger 'turns' (--turns on the command line)"
            )
        else:
            hint = (
                f"; at its pace it settles in about {turns + more} turns (expected "
                "a larger 'turns', --turns on the command line)"
            )
    msg = (
        f"startup: the motion does not settle in {counted(turns, 'turn')} (the speed, "
        f"{last:.6g} rad/s, still changes by {100 * change:.3g} % a turn){hint}"
    )
    raise ModelError(msg)


def _turns_left(crossings: list[float]) -> int | None:
    """Return about how many more turns :func:`_periodic` needs, or None.

    The change of the speed at the reference pose from turn to turn, shrinking
    geometrically by the ratio ``r`` of the last ``m`` turns (their geometric
    mean), leaves ``change * r / (1 - r)`` to come. That holds once the speed is
    near its periodic value; while the crank still gathers speed ``r`` creeps
    towards 1 and the count comes out far too low (1427 turns said after 50, 10555
    needed). So None unless the ratio, at its drift over the last ``2 m`` turns,
    moves by less than ``TRUST`` of ``1 - r`` over the rest of the approach (about
    ``r / (1 - r)`` turns, the drift shrinking with the change).
    """
    m = min(WINDOW, (len(crossings) - 2) // 2)
    if m < 1:
        return None
    changes = np.diff(crossings[-(2 * m + 2) :])[-(2 * m + 1) :]
    if not (changes * changes[-1] > 0).all():
        return None
    size = np.abs(changes)
    before = (size[m] / size[0]) ** (1.0 / m)
    ratio = (size[2 * m] / size[m]) ** (1.0 / m)
    if not ratio < 1:
        return None
    drift = abs(ratio - before) / m * ratio / (1.0 - ratio)
    if drift > TRUST * (1.0 - ratio):
        return None
    goal = PERIODIC_RTOL * abs(crossings[-1]) * (1 - ratio) / ratio
    return max(1, math.ceil(math.log(goal / size[-1]) / math.log(ratio)))
