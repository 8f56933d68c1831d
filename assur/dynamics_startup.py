"""The start-up in time: the crank driven by its motor from rest to its periodic motion.

:func:`startup` integrates the equation of motion of the mechanism reduced to its
crank, ``J(phi) phi'' + 0.5 J'(phi) phi'^2 = M_motor(phi') + M(phi)``, with
:func:`scipy.integrate.solve_ivp`, one turn after another, until the speed at the
reference pose repeats from turn to turn; then it reports the time to settle and the
periodic motion's figures. A crank whose motor cannot carry it past its peak load
stalls, and the error says where.
Its parts: what it is given, checked (``assur._startup_checks``), the model's curves
(``assur._startup_curves``), one turn integrated (``assur._startup_steps``), how its
run of turns ends (``assur._startup_turns``) and when it settles
(``assur._startup_settle``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._dynamic_checks import check_dynamic
from assur._progress import BAR_DELAY, Callback
from assur._progress import progress as show_progress
from assur._startup_checks import (
    _against_omega,
    _gains,
    _motor,
    _speed,
    _starts,
    _turns,
)
from assur._startup_curves import Curves
from assur._startup_settle import extreme, periodic_speed, settle_time
from assur._startup_steps import stepper
from assur._startup_turns import (
    _check_turned,
    _multiplier,
    _not_settled,
    _periodic,
)
from assur._vec import Array
from assur.dynamics_model import checked_flywheel
from assur.dynamics_reduced import Reduced, reduce
from assur.dynamics_steady import check_inertia
from assur.errors import UsageError
from assur.model import Mechanism, Motor

__all__ = ["Startup", "startup"]

SETTLE_BAND = 0.02
"""The time to settle is the time after which the speed stays within this fraction
of the mean speed of the periodic motion at the same crank angle."""
MAX_TURNS = 2000
"""Most turns integrated before the motion is declared not to settle."""
SAMPLES = 90
"""Samples kept of every turn, evenly spaced in time."""
FINE = 2048
"""Samples of the last turn that give its extreme speeds."""


@dataclass(frozen=True, eq=False)
class Startup:
    """The start-up of a crank under its motor, and the periodic motion it settles in.

    Attributes
    ----------
    mechanism : Mechanism
    motor : Motor
    flywheel : float
        Inertia added on the crank, kg m^2.
    time : ndarray (n,)
        Time from the start, s (samples of every turn, evenly spaced in time).
    angle : ndarray (n,)
        Crank angle, deg, continuous (no jump at 360).
    omega : ndarray (n,)
        Crank speed, rad/s.
    settle_time : float
        Time after which the speed stays within ``SETTLE_BAND`` of the mean
        speed around the periodic motion's speed at its crank angle, s; found on
        the continuous solution, not on the samples.
    turns : int
        Turns integrated.
    period : float
        Duration of a turn of the periodic motion, s.
    mean_speed : float
        ``2 pi / period``, rad/s, signed.
    speed_max, speed_min : float
        Largest and smallest speed of the periodic motion, rad/s (magnitudes).
    """

    # the repr is the start-up's figures: the mechanism's spelt out 1200 characters
    mechanism: Mechanism = field(repr=False)
    motor: Motor
    flywheel: float
    time: Array = field(repr=False)
    angle: Array = field(repr=False)
    omega: Array = field(repr=False)
    settle_time: float
    turns: int
    period: float
    mean_speed: float
    speed_max: float
    speed_min: float

    @property
    def delta(self) -> float:
        """The periodic motion's ``(max w - min w) / ((max w + min w) / 2)``."""
        return (
            2.0 * (self.speed_max - self.speed_min) / (self.speed_max + self.speed_min)
        )

    def _repr_html_(self) -> str:
        """Return the start-up as a notebook shows it: its figures (HTML)."""
        from assur._dynamics_text import startup_html

        return startup_html(self)

    def plot(self, **kwargs: Any) -> Any:
        """Draw the speed against time (see :func:`assur.plotting.plot_startup`)."""
        from assur.plotting import plot_startup

        return plot_startup(self, **kwargs)


def startup(
    mechanism: Mechanism,
    flywheel: float = 0.0,
    *,
    motor: Motor | None = None,
    omega0: float = 0.0,
    turns: int = MAX_TURNS,
    progress: bool | Callback = False,
) -> Startup:
    """Integrate the crank's motion in time from the reference pose until periodic.

    Parameters
    ----------
    mechanism : Mechanism
        One revolute driver, masses; its ``[motor]`` unless ``motor`` is given.
    flywheel : float
        Inertia added on the crank, kg m^2.
    motor : Motor, optional
        The motor; default: the mechanism's.
    omega0 : float
        Crank speed at the start, rad/s: 0 (from rest) or of the motor's sense.
    turns : int
        Most turns to integrate, 1 to 100 000.
    progress : bool or callable
        True: a bar of the turns integrated on standard error (the command line
        shows one on a terminal); a callable ``(done, total)`` is told after each
        turn instead. The total is ``turns``: the motion may settle sooner.

    Returns
    -------
    Startup

    Raises
    ------
    ModelError
        Without a motor; when the motor cannot start or carry the crank past its
        peak load (the crank stalls, at the crank angle named); when the motion does
        not settle within ``turns`` turns (a constant torque above the mean load's).
    UsageError
        For a negative flywheel, an ``omega0`` against the motor, or a ``motor``
        argument that is not a motor (a torque of 0, say).
    AssemblyError
        When the crank cannot make a whole turn.

    Notes
    -----
    The state is the crank angle and speed; the reduced inertia ``J``, its slope and
    the reduced torque ``M`` are the periodic interpolants of
    :func:`assur.dynamics_reduced.reduce`. The integration (DOP853, or Radau
    under a motor whose speed relaxes a thousand times a turn; relative
    tolerance 1e-10, each turn's angle counted from its start:
    :mod:`assur._startup_steps`) stops at every turn; the motion is periodic when
    the speed there is within ``PERIODIC_RTOL`` of its limit, told by the turn
    map's multiplier (:mod:`assur._startup_turns`). The time to settle is where the
    continuous solution enters the band for good
    (:mod:`assur._startup_settle`).

    Examples
    --------
    >>> import assur
    >>> mech = assur.catalog.slider_crank()
    >>> run = startup(mech, 0.01, motor=assur.Motor(10.0, 60.0))
    >>> bool(50.0 < run.mean_speed < 60.0)
    True
    """
    check_dynamic(mechanism, "startup")
    engine = _motor(mechanism, motor)
    _against_omega(mechanism, engine)
    inertia = checked_flywheel(flywheel)
    sense = math.copysign(1.0, engine.torque)
    omega0 = _speed(omega0)
    turns = _turns(turns)
    if omega0 * sense < 0 or not math.isfinite(omega0):
        msg = (
            f"omega0: {omega0:g} rad/s; expected 0 or a speed of the motor's sense "
            f"({'counter-clockwise' if sense > 0 else 'clockwise'})"
        )
        raise UsageError(msg)
    model = reduce(mechanism)
    check_inertia(model, model.inertia + inertia, inertia)
    curves = Curves(model, inertia)
    _starts(model, engine, omega0, curves)
    # the turns are at most so many (most motions settle long before): the bar
    # only for a start-up that takes a while, as the sweeps' bars
    shown = show_progress("startup", turns, progress, BAR_DELAY, " turns at most")
    with shown as bar:
        runs = _integrate(model, engine, curves, omega0, turns, bar.advance)
    return _result(mechanism, engine, inertia, model, runs)


@dataclass
class _Runs:
    """The samples of the turns integrated, where each began, its dense solution.

    The dense solution is the last turn's; ``turn`` integrates any turn again (the
    same steps, so the same solution).
    """

    time: list[Array] = field(default_factory=list)
    angle: list[Array] = field(default_factory=list)
    omega: list[Array] = field(default_factory=list)
    crossings: list[float] = field(default_factory=list)
    starts: list[tuple[float, list[float]]] = field(default_factory=list)
    turn: Any = None
    last: Any = None
    span: tuple[float, float] = (0.0, 0.0)


def _integrate(
    model: Reduced,
    motor: Motor,
    curves: Curves,
    omega0: float,
    turns: int,
    advance: Callable[[int], None] | None = None,
) -> _Runs:
    """Integrate turn by turn until the speed at the reference pose repeats.

    ``advance(1)`` is called after each turn (a progress bar's).
    """
    sense = math.copysign(1.0, motor.torque)
    runs = _Runs(turn=stepper(model, motor, curves))
    state, t = [model.start, omega0], 0.0
    for k in range(1, turns + 1):
        sol = runs.turn(t, state, k)
        _check_turned(sol, model, curves, motor)
        runs.starts.append((t, state))
        target = model.start + sense * 2.0 * math.pi * k
        t, state = float(sol.t_events[0][0]), [target, float(sol.y_events[0][0][1])]
        _keep(runs, sol, t)
        if advance is not None:
            advance(1)
        if k == 1:
            # a whole turn made, each next one gains as much: a constant torque
            # above the mean load is told now, not after every turn asked for
            _gains(model, motor)
        if _periodic(
            runs.crossings,
            lambda: _multiplier(runs.last, runs.span, model, curves.flywheel, motor),
        ):
            break
    else:
        _not_settled(runs, motor, model, turns, omega0)
    return runs


def _keep(runs: _Runs, sol: Any, end: float) -> None:
    """Keep samples of a turn (evenly spaced in time) and its dense solution."""
    begin = float(sol.t[0])
    times = np.linspace(begin, end, SAMPLES + 1)[:-1]
    values = sol.sol(times)
    runs.time.append(times)
    runs.angle.append(values[0])
    runs.omega.append(values[1])
    runs.crossings.append(float(sol.sol(end)[1]))
    runs.last, runs.span = sol.sol, (begin, end)


def _result(
    mech: Mechanism, motor: Motor, flywheel: float, model: Reduced, runs: _Runs
) -> Startup:
    """Gather the samples and the periodic motion's figures."""
    time = np.concatenate(runs.time)
    angle = np.concatenate(runs.angle)
    omega = np.concatenate(runs.omega)
    begin, end = runs.span
    times = np.linspace(begin, end, FINE + 1)
    fine = runs.last(times)
    speeds = np.abs(fine[1])
    fastest = extreme(runs.last, times, speeds, 1.0)
    slowest = extreme(runs.last, times, speeds, -1.0)
    period = end - begin
    sense = math.copysign(1.0, motor.torque)
    mean = sense * 2.0 * math.pi / period
    speed = periodic_speed(fine, sense)
    band = SETTLE_BAND * abs(mean)
    settle = settle_time(runs, (time, angle, omega), speed, band)
    degrees = np.degrees(angle)
    for a in (time, degrees, omega):
        a.flags.writeable = False
    return Startup(
        mech,
        motor,
        flywheel,
        time,
        degrees,
        omega,
        settle,
        len(runs.crossings),
        period,
        mean,
        fastest,
        slowest,
    )
