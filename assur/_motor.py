"""The motor on the driving crank, and its check.

:class:`Motor` is public as :class:`assur.model.Motor`; only the start-up in time
(:mod:`assur.dynamics_startup`) reads it.
"""

from __future__ import annotations

from dataclasses import dataclass

from assur._checks import _fail, _finite, _number_fault, _tuples
from assur._text import describe


@dataclass(frozen=True, slots=True)
class Motor:
    """The motor on the driving crank: its torque against its speed.

    ``M(w) = torque * (1 - w / no_load_speed)``, the linear characteristic of an
    electric motor; without ``no_load_speed`` the torque is constant. The motor
    turns the crank the way its torque points (counter-clockwise positive).

    Parameters
    ----------
    torque : float
        Torque at standstill (the stall torque), N m; not zero.
    no_load_speed : float, optional
        Speed at which the torque falls to zero, rad/s, of the torque's sign.
    """

    torque: float
    no_load_speed: float | None = None

    def __post_init__(self) -> None:
        _tuples(self, "torque", "no_load_speed")

    def at(self, speed: float) -> float:
        """Return the motor's torque (N m) at the crank's ``speed`` (rad/s)."""
        if self.no_load_speed is None:
            return self.torque
        return self.torque * (1.0 - speed / self.no_load_speed)


def validate_motor(motor: object) -> None:
    """Check the motor: a torque that is not zero, a speed of the same sign."""
    if not isinstance(motor, Motor):
        _fail("motor", f"expected a Motor, got {describe(motor)}")
    if not _finite(motor.torque):
        _fail("motor.torque", _number_fault(motor.torque))
    if motor.torque == 0:
        _fail(
            "motor.torque", "the motor's torque at standstill is 0; expected a torque"
        )
    speed = motor.no_load_speed
    if speed is None:
        return
    if not _finite(speed):
        _fail("motor.no_load_speed", _number_fault(speed))
    # the signs compared, not the product: 1e-300 * 1e-300 is 0
    if speed == 0 or (speed > 0) != (motor.torque > 0):  # type: ignore[operator]
        _fail(
            "motor.no_load_speed",
            f"{describe(speed)} rad/s against a torque of {describe(motor.torque)} "
            "N m; expected a speed of the torque's sign (the way the motor turns)",
        )


def against_omega(motor: Motor, omega: float, unit: str = "N m") -> str | None:
    """Return what a motor turning the crank against ``omega`` (rad/s) does, or None.

    The words of the start-up's warning, which the dynamic model's figures repeat
    beside the file's motor; ``unit`` is the torque's unit as the text around it
    writes it. None for a motor of ``omega``'s sign.
    """
    # the signs compared, not the product: 1e-200 * -1e-200 is -0.0
    if omega == 0 or (omega > 0) == (motor.torque > 0):
        return None
    sense = "counter-clockwise" if motor.torque > 0 else "clockwise"
    return (
        f"the motor turns the crank {sense} (torque {motor.torque:g} {unit}), "
        f"against the driver's omega = {omega:g} rad/s: the start-up runs the other "
        "way than every analysis at omega"
    )
