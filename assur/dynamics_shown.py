"""Which steady state the pictures and the HTML report show.

The mechanism alone when it runs at its nominal speed; otherwise (a light linkage
under heavy loads would stop) with the flywheel that holds its speed fluctuation to
:data:`SHOWN_DELTA`, named in the picture's titles and the report's figures; and
the motor torque as the figures of both the report and the command line print it.
"""

from __future__ import annotations

import math
from typing import Any

from assur._dynamic_checks import check_dynamic
from assur._text import number_text
from assur.dynamics_flywheel import flywheel
from assur.dynamics_model import Dynamics, dynamics
from assur.errors import ModelError
from assur.model import Mechanism

__all__ = ["SHOWN_DELTA", "has_dynamics", "motor_note", "motor_shown", "shown"]

SHOWN_DELTA = 0.05
"""Coefficient of speed fluctuation of the flywheel shown when one is needed."""


def has_dynamics(mechanism: Mechanism) -> bool:
    """Whether the mechanism has a dynamic model: one crank, masses."""
    try:
        check_dynamic(mechanism)
    except ModelError:
        return False
    return True


def shown(mechanism: Mechanism, angles: Any) -> Dynamics:
    """Return the steady state to show at ``angles`` (deg).

    Raises
    ------
    AssurError
        When the mechanism has no dynamic model or its crank cannot turn round.
    """
    try:
        return dynamics(mechanism, angles)
    except ModelError:
        if not has_dynamics(mechanism):
            raise
        inertia = flywheel(mechanism, SHOWN_DELTA)
    return dynamics(mechanism, angles, flywheel=inertia)


def motor_shown(result: Any) -> float:
    """Return the motor torque to print (N m): 0 where it is the mean's round-off.

    Loads that do no net work (gravity alone) leave a mean of a few ulps of their
    torques: a turn's work that is not 10^-12 of the energy swing is none.
    """
    if abs(result.motor) * 2.0 * math.pi <= 1e-12 * result.energy_swing:
        return 0.0
    return float(result.motor)


def motor_note(motor: float, result: Any, unit: str = "N m") -> str:
    """Return what the motor torque's sign means, beside "constant".

    ``unit`` is the torque's unit as the text around it writes it.
    """
    note = "constant"
    if result.omega < 0:
        # torques are counter-clockwise positive: a clockwise crank's motor
        # drives it with a negative torque
        note += ", counter-clockwise positive"
    if motor * result.omega < 0:
        note += "; it brakes: the loads drive the crank"
    found = result.mechanism.motor
    if found is not None and found.no_load_speed is not None:
        # the steady state is the contract's: a constant torque at the nominal
        # speed; the file's motor, whose torque falls with speed, runs the start-up
        w = abs(result.omega)
        note += (
            f"; it balances the loads' work over a turn at the nominal {w:.6g} "
            f"rad/s; the file's [motor], {number_text(found.at(result.omega))} "
            f"{unit} at that speed, drives the start-up alone"
        )
    return note
