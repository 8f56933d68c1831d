"""How a start-up's run of turns ends: each turn made, and the motion periodic.

A crank that stalls or creeps instead of turning, or whose speed still changes after
the last turn allowed, is a :class:`~assur.errors.ModelError`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._startup_checks import MOST_TURNS
from assur._text import counted, crank_angle_text
from assur._vec import Array
from assur.dynamics_reduced import Reduced
from assur.errors import ModelError
from assur.model import Motor

if TYPE_CHECKING:
    from assur._startup_curves import Curves
    from assur.dynamics_startup import _Runs


PERIODIC_RTOL = 1e-8
"""The motion is periodic when the speed at the reference pose, extrapolated from the
last turns, changes by less than this fraction of itself."""
WINDOW = 8
"""Most turns the ratio of successive changes is taken over (their geometric mean),
which damps the noise of single turns' changes near the periodic motion."""
MULTIPLIER_SAMPLES = 512
"""Samples of a turn the multiplier's integral is taken over (trapezoids)."""
NOISE_MOST = 1e-6
"""Changes below this fraction of the speed may be the integration's scatter (a
relative tolerance of 1e-10 a step): of either sign, the motion is then periodic; of
one sign, not shrinking steadily, they are told as likely scatter when the start-up
stops. Larger ones are never taken for scatter."""
TRUST = 0.1
"""The turns still needed are told only while the ratio of successive changes would
move by less than this fraction of ``1 - r`` over the rest of the approach."""


def _check_turned(sol: Any, model: Reduced, curves: Curves, motor: Motor) -> None:
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
            "last turn it has not made another (at crank angle "
            f"{crank_angle_text(math.degrees(phi))}, {w:.6g} rad/s); expected a "
            "motor or flywheel that turns it at a pace"
        )
        raise ModelError(msg)
    phi, when = float(sol.y_events[1][0][0]), float(sol.t_events[1][0])
    _, _, load = curves(phi)
    where = math.degrees(phi)
    msg = (
        f"startup: the crank stalls at crank angle {crank_angle_text(where)} (at t = "
        f"{when:.6g} s): the motor cannot carry it past its peak load (load torque "
        f"{load:.6g} N m there, motor torque at standstill {motor.torque:.6g} N m)"
    )
    raise ModelError(msg)


def _periodic(crossings: list[float], multiplier: Callable[[], float]) -> bool:
    """Whether the speeds at the reference pose have stopped changing.

    Near its periodic motion the speed at the reference pose comes back each turn
    ``multiplier()`` times as far from its limit (:func:`_multiplier`, asked for
    only near it): what is left of the changes must be below ``PERIODIC_RTOL`` of
    the speed. The ratio of the last two changes is too noisy for that: on the
    slider-crank one came out 0.43 amid 0.72s (the multiplier: 0.7135), and the
    motion was taken as periodic 3.9e-8 of its speed from its limit.

    The flow keeps the order of speeds, so the changes keep one sign until they
    are the integration's own scatter (2e-8 to 9e-8 of the speed on the six-bar
    under a motor, whose steps span many knots of the model's splines). Changes of
    either sign are that scatter: the speed is periodic once what the approach
    leaves, at most the scatter carried on by the multiplier, is below the
    tolerance or below the scatter the periodic speed has itself.
    """
    if len(crossings) < 3:
        return False
    changes = np.diff(crossings[-(WINDOW + 1) :])
    limit = PERIODIC_RTOL * abs(crossings[-1])
    if changes[-1] == 0:
        return True
    mixed = not (changes * changes[-1] > 0).all()
    if not mixed and abs(changes[-1]) > limit:
        return False
    if mixed and np.max(np.abs(changes)) <= limit:
        return True
    ratio = multiplier()
    if not math.isfinite(ratio):  # the crank stops for an instant each turn
        ratio = float(np.abs(changes[-1] / changes[0])) ** (1.0 / (len(changes) - 1))
    if not 0 <= ratio < 1:
        return False
    if mixed:
        scatter = _scatter(changes)
        if scatter > NOISE_MOST * abs(crossings[-1]):
            return False  # not an integration's scatter: no periodic motion yet
        own = scatter / math.sqrt(1.0 - ratio * ratio)
        return scatter * ratio / (1.0 - ratio) <= max(limit, own)
    # where each of the last turns' speeds, carried on by its change, says the
    # limit is: their mean damps one turn's error, which shifts its speed and its
    # change
    ahead = ratio / (1.0 - ratio)
    window = np.asarray(crossings[-changes.shape[0] :])
    limit_speed = float(np.mean(window + ahead * changes))
    return abs(limit_speed - crossings[-1]) <= limit


def _scatter(changes: Array) -> float:
    """Return the scatter of speeds whose turn-to-turn ``changes`` are noise.

    Their rms over root 2: two independent scatters of size s make a change of
    size s times root 2.
    """
    return float(np.sqrt(np.mean(changes * changes) / 2.0))


def _multiplier(
    solution: Any,
    span: tuple[float, float],
    model: Reduced,
    flywheel: float,
    motor: Motor,
) -> float:
    """How much nearer its periodic motion a turn brings the speed, a ratio.

    The speed against the crank angle obeys ``dw/dphi = g = N / (J w)`` with
    ``N = T(w) + M - J' w^2 / 2``; a small change of the speed at the start of a
    turn comes back ``exp(int dg/dw dphi)`` times as large at its end, the
    integral taken along the turn ``solution`` (dense, over the times ``span``, s)
    in time as ``int (dg/dw) w dt``, where ``(dg/dw) w = (N_w w - N) / (J w)`` and
    ``N_w = T'(w) - J' w``. ``J`` is the model's with the ``flywheel`` (kg m^2).
    NaN when the crank stops for an instant in the turn.
    """
    begin, end = span
    times = np.linspace(begin, end, MULTIPLIER_SAMPLES + 1)
    angle, speed = solution(times)
    if not np.all(speed):
        return math.nan  # dg/dw is unbounded where the crank stops
    slope_motor = 0.0
    if motor.no_load_speed is not None:
        slope_motor = -motor.torque / motor.no_load_speed
    inertia = model.inertia_at(angle) + flywheel
    slope = model.slope_at(angle)
    net = motor.at(speed) + model.torque_at(angle) - 0.5 * slope * speed * speed
    values = ((slope_motor - slope * speed) * speed - net) / (inertia * speed)
    step = (end - begin) / MULTIPLIER_SAMPLES
    return math.exp(step * float(np.sum(values) - 0.5 * (values[0] + values[-1])))


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
            f"{model.motor:.6g} N m (the steady state's motor torque, as assur "
            "dynamics prints it), so give the motor a no_load_speed"
        )
    else:
        more = _turns_left(runs.crossings)
        changes = np.diff(runs.crossings[-(WINDOW + 1) :])
        if changes.size > 1 and not (changes * changes[-1] > 0).all():
            hint = (
                "; its changes a turn go either way: the integration's scatter, "
                f"about {_scatter(changes) / abs(last):.2g} of the speed, hides "
                "where its periodic speed lies at the pace it approaches it"
            )
        elif more is None and change < NOISE_MOST:
            # a crank still gathering speed changes by more: this is near the
            # integration's scatter (a reduced model that turns sharply near a
            # change point held a four-bar at 4e-8 a turn for 2000 turns)
            hint = (
                "; a change this small that does not shrink at a steady ratio is "
                "likely the integration's own scatter (of a reduced model that turns "
                "sharply, near a change point, say), not a crank still gathering "
                "speed; expected a mechanism further from a change point, or its "
                "steady state, which needs no start-up (assur.dynamics; assur "
                "dynamics without --startup)"
            )
        elif more is None:
            hint = (
                "; its change a turn does not shrink at a steady ratio yet (the "
                "crank still gathering speed, say), so the turns it needs cannot be "
                "told; expected a larger 'turns' (--turns on the command line)"
            )
        else:
            hint = (
                f"; at its pace it settles in about {turns + more} turns (expected "
                "a larger 'turns', --turns on the command line)"
                if turns + more <= MOST_TURNS
                else f"; at its pace it settles in about {turns + more} turns, more "
                f"than the {MOST_TURNS} a start-up may take"
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
