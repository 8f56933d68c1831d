"""The steady state of a crank under a constant motor torque: the energy equation.

Over a turn the motor's constant torque does the work the loads take, so the
kinetic energy ``0.5 J(phi) w^2 = E0 + W(phi)`` is periodic; :func:`steady_state`
finds the energy ``E0`` at the reference pose for which the mean of the largest and
the smallest speed is the crank's nominal speed, and where those extremes occur.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._running import TIE
from assur._text import crank_angle_text
from assur._vec import Array
from assur.dynamics_reduced import Reduced
from assur.errors import ModelError

__all__ = ["Steady", "check_inertia", "steady_state"]

NO_INERTIA = 1e-12
"""A reduced inertia below this fraction of its largest value counts as zero."""
ANGLE_ATOL = 1e-11
"""Tolerance (rad) of the crank angles where the speed is largest and smallest."""
RTOL = 1e-15
"""Relative tolerance of the energy ``E0`` found by Brent's method."""


@dataclass(frozen=True, slots=True)
class Steady:
    """The periodic motion of the energy equation.

    Attributes
    ----------
    omega : float
        The nominal speed, rad/s (signed: the sense of rotation).
    flywheel : float
        Inertia added on the crank, kg m^2.
    energy : float
        Kinetic energy at the reference pose, J (``E0``).
    speed_max, speed_min : float
        Largest and smallest speed over a turn, rad/s (magnitudes).
    angle_max, angle_min : float
        Crank angles where they occur, rad, within the turn from the reference pose
        counter-clockwise (that of the default sweep, whichever way the crank turns).
    """

    omega: float
    flywheel: float
    energy: float
    speed_max: float
    speed_min: float
    angle_max: float
    angle_min: float

    @property
    def delta(self) -> float:
        """The coefficient of speed fluctuation, ``(max w - min w) / |omega|``."""
        return (self.speed_max - self.speed_min) / abs(self.omega)


def steady_state(model: Reduced, omega: float, flywheel: float = 0.0) -> Steady:
    r"""Return the steady state whose mean of extreme speeds is ``|omega|``.

    Parameters
    ----------
    model : Reduced
        The reduced model over a turn.
    omega : float
        Nominal crank speed, rad/s; its sign is the sense of rotation.
    flywheel : float
        Inertia added on the crank, kg m^2.

    Raises
    ------
    ModelError
        When ``omega`` is zero, when the reduced inertia vanishes somewhere, or when
        no steady state has that mean speed (the crank would come to rest).

    Notes
    -----
    The speed at crank angle :math:`\varphi` is
    :math:`w^2 = 2 (E_0 + W(\varphi)) / (J(\varphi) + J_f)`, increasing with
    :math:`E_0`, so the mean of its extremes is too: Brent's method finds
    :math:`E_0` between the energy at which the crank just comes to rest and one at
    which even the smallest speed exceeds ``|omega|``. The extremes are found on the
    grid, then on the interpolants to ``ANGLE_ATOL``.
    """
    from scipy.optimize import brentq

    target = abs(omega)
    if not target * target > 0:  # a speed whose square underflows is zero too
        what = "is zero" if target == 0 else "is too small: its square underflows"
        msg = (
            f"drivers[0].omega: {omega:g} rad/s {what}; expected the crank's nominal "
            "speed (the steady state's mean of its largest and smallest speed), at "
            "least 1e-160 rad/s"
        )
        raise ModelError(msg)
    inertia = model.inertia + flywheel
    check_inertia(model, inertia, flywheel)
    rest_angle = _extreme(model.work_at, model, _first(model.work, -1.0))
    lowest = -float(model.work_at(rest_angle))

    def gap(energy: float) -> float:
        fast, slow = _grid_extremes(model, inertia, energy)
        return 0.5 * (fast + slow) - target

    if gap(lowest) > 0:
        _comes_to_rest(model, omega, rest_angle, lowest, flywheel)
    highest = 0.5 * float(np.max(inertia)) * target**2 - float(np.min(model.work))
    highest = max(highest, lowest + 1e-300)
    energy = brentq(gap, lowest, highest, xtol=1e-300, rtol=RTOL)
    return _refined(model, omega, flywheel, energy, (lowest, highest))


def check_inertia(model: Reduced, inertia: Array, flywheel: float) -> None:
    """Refuse a reduced inertia that vanishes (a turn without mass in motion).

    ``inertia`` is ``J`` on the grid of ``model``, flywheel included. Zero is below
    ``NO_INERTIA`` of the largest value, or below the fourth power of the grid's
    step (rad) times it, which is what the minimum between grid points is known to.

    Raises
    ------
    ModelError
        Naming the crank angle where it vanishes.
    """
    least, where = _least(model, inertia)
    # the parabola misses the curve by about the fourth power of the grid's step
    # (relative): a smaller minimum cannot be told from zero
    step = 2.0 * math.pi / inertia.shape[0]
    if least > max(NO_INERTIA, step**4) * float(np.max(np.abs(inertia))):
        return
    where = math.degrees(where)
    msg = (
        f"dynamics: the reduced inertia is zero at crank angle "
        f"{crank_angle_text(where)} (no "
        f"mass moves there, flywheel {flywheel:g} kg m^2); expected a flywheel "
        "(flywheel > 0)"
    )
    raise ModelError(msg)


def _least(model: Reduced, inertia: Array) -> tuple[float, float]:
    """Return the smallest reduced inertia over the turn and where it is (rad).

    ``J`` is a sum of squares of velocity ratios: where every moving mass comes to
    rest at once (the yoke of a Scotch yoke with a massless crank), it touches zero
    between grid points as a parabola does, and the grid's smallest value can be a
    millionth of the largest. The parabola through the grid's smallest value and its
    two neighbours (the grid closes on itself over the turn) gives the minimum.
    """
    i = _first(inertia, -1.0)
    here, angle = float(inertia[i]), float(model.angle[i])
    low, shift = _vertex(inertia, i)
    if not low <= here:  # the parabola has its top there, or no number
        return here, angle
    return low, angle + shift * 2.0 * math.pi / inertia.shape[0]


def _speeds(model: Reduced, inertia: Any, energy: float, phi: Any = None) -> Any:
    """Return the squared speeds ``2 (E0 + W) / J`` on the grid or at ``phi``."""
    work = model.work if phi is None else model.work_at(phi)
    return np.maximum(2.0 * (energy + work) / inertia, 0.0)


def _grid_extremes(
    model: Reduced, inertia: Array, energy: float
) -> tuple[float, float]:
    """Return the largest and smallest speed, a parabola through the grid's extremes."""
    square = _speeds(model, inertia, energy)
    top = _vertex(square, int(np.argmax(square)))[0]
    bottom = _vertex(square, int(np.argmin(square)))[0]
    return math.sqrt(max(top, 0.0)), math.sqrt(max(bottom, 0.0))


def _first(values: Array, sign: float) -> int:
    """Return the index of the first largest (``sign`` 1) or smallest (-1) value.

    Values within :data:`~assur._running.TIE` (the summary's share) of the grid's
    largest magnitude from the extreme tie with it: poses alike by symmetry (a
    centred slider-crank at its slowest, 73 and 287 deg) differ in their last bits
    alone, which the machine's arithmetic gives to either.
    """
    signed = sign * np.asarray(values, dtype=float)
    # told by the size of the values, not of the extreme: a work of 0 at the
    # turn's start ties with the round-off of the work at its end
    size = float(np.max(np.abs(signed)))
    return int(np.argmax(signed >= float(np.max(signed)) - TIE * size))


def _vertex(values: Array, i: int) -> tuple[float, float]:
    """Return the extreme of the parabola through a grid point and its neighbours.

    Also where it is, in grid steps from point ``i`` (0 for a straight line). The
    grid closes on itself over the turn.
    """
    n = values.shape[0]
    before, here, after = (float(values[j % n]) for j in (i - 1, i, i + 1))
    curve = before - 2.0 * here + after
    if curve == 0:
        return here, 0.0
    # the square of the difference would overflow first for huge speeds
    change = after - before
    return here - change * (change / (8.0 * curve)), -0.5 * change / curve


def _extreme(function: Any, model: Reduced, i: int, sign: float = 1.0) -> float:
    """Return the crank angle (rad) of the extreme of ``function`` near grid point i.

    ``sign`` +1 looks for a minimum, -1 for a maximum.
    """
    from scipy.optimize import minimize_scalar

    h = model.step
    centre = float(model.angle[i])
    found = minimize_scalar(
        lambda phi: sign * float(function(phi)),
        bounds=(centre - h, centre + h),
        method="bounded",
        options={"xatol": ANGLE_ATOL},
    )
    best = float(found.x)
    if sign * float(function(best)) > sign * float(function(centre)):
        best = centre  # the bounded search ended on a worse point than the grid's
    return best


def _refined(
    model: Reduced,
    omega: float,
    flywheel: float,
    energy: float,
    bracket: tuple[float, float],
) -> Steady:
    """Locate the extremes on the interpolants, then solve for ``E0`` again."""
    from scipy.optimize import brentq

    def square(phi: Any, e: float) -> Any:
        return _speeds(model, model.inertia_at(phi) + flywheel, e, phi)

    grid = _speeds(model, model.inertia + flywheel, energy)
    top = _extreme(lambda phi: square(phi, energy), model, _first(grid, 1.0), -1.0)
    bottom = _extreme(lambda phi: square(phi, energy), model, _first(grid, -1.0), 1.0)

    def gap(e: float) -> float:
        mean = 0.5 * (math.sqrt(square(top, e)) + math.sqrt(square(bottom, e)))
        return mean - abs(omega)

    if gap(bracket[0]) < 0 < gap(bracket[1]):
        energy = brentq(gap, *bracket, xtol=1e-300, rtol=RTOL)
    return Steady(
        omega,
        flywheel,
        energy,
        math.sqrt(float(square(top, energy))),
        math.sqrt(float(square(bottom, energy))),
        on_turn(model.start, top),
        on_turn(model.start, bottom),
    )


def on_turn(start: float, angle: float) -> float:
    """Return ``angle`` (rad) within the turn from ``start`` counter-clockwise.

    The turn of the default sweep, whichever way the crank turns.
    """
    return (angle - start) % (2.0 * math.pi) + start


def _comes_to_rest(
    model: Reduced, omega: float, angle: float, lowest: float, flywheel: float
) -> None:
    """Raise: no steady state has the mean speed ``|omega|``; the crank would stop."""
    top, _ = _grid_extremes(model, model.inertia + flywheel, lowest)
    where = math.degrees(on_turn(model.start, angle))
    swing = float(np.max(model.work) - np.min(model.work))
    faster = "a larger 'omega'" if omega > 0 else "a faster 'omega' (more negative)"
    msg = (
        f"dynamics: at a mean speed of {abs(omega):.6g} rad/s the crank would come to "
        f"rest at crank angle {crank_angle_text(where)}: the energy swing of the loads "
        f"and the motor ({swing:.6g} J) needs a speed of at least {0.5 * top:.6g} "
        f"rad/s; expected {faster} or a flywheel (--flywheel or --delta on the "
        "command line)"
    )
    raise ModelError(msg)
