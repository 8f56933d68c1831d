"""What a start-up is given, checked: the starting speed, the turns and the motor.

And a start from rest refused where the motor's torque does not beat the load's.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from assur._motor import against_omega, validate_motor
from assur._text import describe
from assur._vec import integer, real
from assur._warn import warn
from assur.dynamics_reduced import Reduced
from assur.errors import AssurWarning, ModelError, UsageError
from assur.model import Mechanism, Motor

if TYPE_CHECKING:
    from assur._startup_curves import Curves


def _speed(omega0: Any) -> float:
    """Return the starting speed as a float (rad/s); a UsageError if not a number."""
    number = real(omega0)
    if number is None:
        msg = f"omega0: expected a crank speed in rad/s, got {describe(omega0)}"
        raise UsageError(msg)
    return number


MOST_TURNS = 100_000
"""Most turns a start-up may integrate: each turn's samples are kept (about 2 kB),
and a turn takes about 10 ms, so 100 000 take some 200 MB and 20 minutes."""


def _turns(turns: Any) -> int:
    """Return the most turns to integrate, checked: a whole number, 1 to 100 000."""
    number = integer(turns)
    if number is None or number < 1:
        msg = f"turns: expected a whole number of turns from 1, got {describe(turns)}"
        raise UsageError(msg)
    if number > MOST_TURNS:
        # 1e11 turns were taken: decades of work, memory that runs out first
        msg = (
            f"turns: {describe(number)}; expected at most {MOST_TURNS} (each turn's "
            "samples are kept): a motion that has not settled by then is told so"
        )
        raise UsageError(msg)
    return number


def _motor(mechanism: Mechanism, motor: Motor | None) -> Motor:
    """Return the motor to use: the one given, or the mechanism's."""
    if motor is not None:
        if not isinstance(motor, Motor):
            msg = f"motor: expected an assur.Motor, got {type(motor).__name__}"
            raise UsageError(msg)
        try:
            # the checks of a file's [motor]: a torque, a speed of its sense
            validate_motor(motor)
        except ModelError as err:
            raise UsageError(str(err)) from None
        return motor
    if mechanism.motor is None:
        msg = (
            "startup: the mechanism has no motor; expected a [motor] table with "
            "'torque' (N m at standstill) and, for an electric motor, "
            "'no_load_speed' (rad/s)"
        )
        raise ModelError(msg)
    return mechanism.motor


def _against_omega(mechanism: Mechanism, motor: Motor) -> None:
    """Warn when the motor turns the crank against the driver's ``omega``.

    The start-up then runs the other way than the steady state, the flywheel's
    sizing and the forces at ``omega``, all shown beside it by ``assur dynamics``.
    """
    said = against_omega(motor, float(mechanism.drivers[0].omega))
    if said is None:
        return
    msg = f"startup: {said}; expected a motor of omega's sign"
    warn(msg, AssurWarning, stacklevel=3)


BALANCED = 1e-9
"""Share of the torques at play within which a constant motor torque balances the
mean load (round-off of the mean): the start-up is then integrated."""


def _gains(model: Reduced, motor: Motor) -> None:
    """Refuse a constant torque larger than the mean load: its speed grows for good.

    Asked once the crank has made a whole turn (before, it may stall short of its
    peak load). The reduced model's torque depends on the crank angle alone, and
    its inertia terms do no work over a turn: each turn the crank gains
    ``2 pi (torque - model.motor)`` joules, the same every turn, so it makes every
    next turn and never settles. It ran every turn asked for first (2 000 turns,
    40 s).
    """
    if motor.no_load_speed is not None:
        return
    sense = math.copysign(1.0, motor.torque)
    surplus = sense * (motor.torque - model.motor)
    if not surplus > BALANCED * max(abs(motor.torque), abs(model.motor)):
        return
    msg = (
        f"startup: a constant torque of {motor.torque:.6g} N m does "
        f"{2.0 * math.pi * surplus:.6g} J more work a turn than the loads take, "
        "so the crank's speed grows every turn without end; a constant torque "
        f"settles only where it balances the mean load, at {model.motor:.6g} N m "
        "(the steady state's motor torque, as assur dynamics prints it), so give "
        "the motor a no_load_speed"
    )
    raise ModelError(msg)


def _starts(model: Reduced, motor: Motor, omega0: float, curves: Curves) -> None:
    """Refuse a start from rest where the motor's torque does not beat the load's."""
    if omega0 != 0:
        return
    _, _, load = curves(model.start)
    sense = math.copysign(1.0, motor.torque)
    if sense * (motor.torque + load) > 0:
        return
    msg = (
        f"startup: the motor cannot start the crank: at crank angle "
        f"{math.degrees(model.start):.6g} deg its torque at standstill "
        f"({motor.torque:.6g} N m) does not overcome the load torque there "
        f"({load:.6g} N m)"
    )
    raise ModelError(msg)
