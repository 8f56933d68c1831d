"""One turn of a start-up: the integration of the crank's motion over a turn.

Each turn is integrated from its own start (its angle from zero), with an explicit
method, or an implicit one under a motor that holds its speed far faster than a turn
takes, until the turn is made, the crank stalls, or a time limit passes.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from assur._startup_curves import Curves
from assur._vec import Array
from assur.dynamics_reduced import Reduced
from assur.model import Motor

__all__ = ["RTOL", "stepper"]

RTOL = 1e-10
"""Relative tolerance of the time integration (scipy's DOP853, or Radau under a stiff
motor)."""


def stepper(model: Reduced, motor: Motor, curves: Curves) -> Any:
    """Return ``turn(t, state, k)``, the integration of the crank's ``k``-th turn.

    From the time ``t`` (s) and ``state`` (rad, rad/s) to the end of that turn, or
    the crank's stall, or the time limit.
    """
    from scipy.integrate import solve_ivp

    sense = math.copysign(1.0, motor.torque)
    torque, free = motor.torque, motor.no_load_speed

    def rhs(_t: float, y: Any) -> list[float]:
        phi, w = y
        inertia, slope, load = curves(phi)
        drive = torque if free is None else torque * (1.0 - w / free)
        return [w, (drive + load - 0.5 * slope * w * w) / inertia]

    def stall(_t: float, y: Array) -> float:
        return float(sense * y[1])

    stall.terminal, stall.direction = True, -1.0  # type: ignore[attr-defined]
    scale = _speed_scale(model, motor, curves)
    limit = _time_limit(scale, model, motor, curves)
    method = "Radau" if _stiff(model, motor, curves) else "DOP853"

    def turn(t: float, state: list[float], k: int) -> Any:
        # the angle is integrated from the turn's start: the relative tolerance on
        # an angle counted from the reference pose loosened turn by turn (1e-6 rad
        # after 1400 turns), and the speed at the pose jumped by 1e-7 of itself
        base = model.start + sense * 2.0 * math.pi * (k - 1)
        end = sense * 2.0 * math.pi

        def local(_t: float, y: Array) -> list[float]:
            return rhs(_t, (y[0] + base, y[1]))

        def turned(_t: float, y: Array) -> float:
            return float(sense * (y[0] - end))

        turned.terminal, turned.direction = True, 1.0  # type: ignore[attr-defined]
        # a trial step may overflow (a motor of 1e10 N m): the integrator refuses
        # it and shortens the step, with no word to the user
        with np.errstate(over="ignore", invalid="ignore"):
            sol = solve_ivp(
                local,
                (t, t + limit),
                [state[0] - base, state[1]],
                method=method,
                rtol=RTOL,
                atol=[RTOL, RTOL * scale],
                events=(turned, stall),
                dense_output=True,
            )
        return _absolute(sol, base)

    return turn


def _absolute(sol: Any, base: float) -> Any:
    """Return ``sol``, a turn's integration, with its angles (rad) plus ``base``."""
    sol.y[0] += base
    for found in sol.y_events:
        if len(found):
            found[:, 0] += base
    dense = sol.sol

    def absolute(t: Any) -> Array:
        values = dense(t)
        values[0] += base
        return values  # type: ignore[no-any-return]

    sol.sol = absolute
    return sol


def _stiff(model: Reduced, motor: Motor, curves: Curves) -> bool:
    """Whether an electric motor holds the speed far faster than a turn takes.

    Its torque falls by ``T / w0`` per rad/s: the speed relaxes at the rate
    ``T / (w0 J)``. An explicit method steps at that pace all along; beyond a
    thousand relaxations a turn an implicit one (Radau) takes far fewer steps.
    """
    if motor.no_load_speed is None:
        return False
    inertia = float(np.min(model.inertia)) + curves.flywheel
    rate = abs(motor.torque / motor.no_load_speed) / inertia
    return rate * 2.0 * math.pi / abs(motor.no_load_speed) > 1e3


def _speed_scale(model: Reduced, motor: Motor, curves: Curves) -> float:
    """Return a speed (rad/s) to scale tolerances and time limits.

    The motor's (its no-load speed, or what a turn of its stall torque gives from
    rest), or what a turn of the peak load torque gives, the larger: the loads may
    drive the crank far faster than a weak motor would (under 1e-300 N m and a
    30 N m load the speed's tolerance was 1e-160 rad/s, and scipy's error norms
    overflowed).
    """
    inertia = float(np.mean(model.inertia)) + curves.flywheel
    peak = float(np.max(np.abs(model.torque)))
    # the speed a turn of a torque alone would give from rest
    loads = math.sqrt(4.0 * math.pi * peak / inertia)
    if motor.no_load_speed is not None:
        return max(abs(motor.no_load_speed), loads)
    return max(math.sqrt(4.0 * math.pi * abs(motor.torque) / inertia), loads)


def _time_limit(scale: float, model: Reduced, motor: Motor, curves: Curves) -> float:
    """Return the time (s) a turn may take before the crank counts as stopped.

    Ten thousand turns at the speed scale, and at least a hundred times the time
    the stall torque alone takes to turn the crank once from rest: a heavy
    flywheel turns slowly, not never.
    """
    inertia = float(np.mean(model.inertia)) + curves.flywheel
    first = math.sqrt(4.0 * math.pi * inertia / abs(motor.torque))
    return max(1e4 * 2.0 * math.pi / scale, 100.0 * first)
