"""The figures of the dynamic model and of a start-up, as labelled lines of text.

The figures ``assur dynamics`` prints (:mod:`assur._dynamics_figures` aligns them)
and a notebook shows as a table (``Dynamics._repr_html_``, ``Startup._repr_html_``),
and the motor torque as the HTML report's figures print it too. Below the dynamic
model (no import of it): its result's methods import this module.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._motor import against_omega
from assur._startup_turns import PERIODIC_RTOL
from assur._text import crank_angle_text, number_text, spoken
from assur._vec import opposed

__all__ = [
    "dynamics_html",
    "figure_lines",
    "motor_shown",
    "motor_text",
    "speed_text",
    "startup_html",
    "startup_lines",
    "swing_text",
]

NO_WORK = 1e-12
"""Work, relative to the kinetic energy, below which a turn's work is round-off."""
NO_MEAN_TORQUE = (
    "No load does net work over a turn: without a flywheel the motor "
    "supplies the balancing torque (column driver.torque), sized on its peak and "
    "RMS (summary of the forces: driver.torque.max, driver.torque.min, "
    "driver.torque.rms)"
)
"""What sizes the motor where the steady state's mean torque is 0."""


def speed_text(omega: float, number: Callable[[float], str] = number_text) -> str:
    """Return the nominal crank speed ``omega`` (rad/s) as a size and a direction.

    ``"5 rad/s, clockwise"`` for ``omega = -5``: the largest and smallest speeds
    beside it are sizes, and a student reads the direction as a word. The tables'
    and the JSON's numbers keep their signs.
    """
    turning = ", clockwise" if omega < 0 else ""
    return f"{number(abs(omega))} rad/s{turning}"


def motor_shown(result: Any) -> float:
    """Return the motor torque to print (N m): 0 where it is the mean's round-off.

    Loads that do no net work (gravity alone) leave a mean of a few ulps of their
    torques: a turn's work that is not 10^-12 of the energy swing is none.
    """
    if abs(result.motor) * 2.0 * math.pi <= 1e-12 * result.energy_swing:
        return 0.0
    return float(result.motor)


def _motor_note(motor: float, result: Any) -> str:
    """Return what the motor torque's sign means, beside "constant"."""
    note = "constant"
    if result.omega < 0:
        # torques are counter-clockwise positive: a clockwise crank's motor
        # drives it with a negative torque
        note += ", counter-clockwise positive"
    # the signs compared (a product of 1e-200 and -1e-200 is -0.0), as in the
    # motor's check (assur._motor.against_omega); a motor of 0 does neither
    if opposed(motor, result.omega):
        note += "; it brakes: the loads drive the crank"
    return note


def motor_text(
    result: Any, unit: str = "N m", number: Callable[[float], str] = number_text
) -> str:
    """Return the motor torque's row: the steady state's, then the file's motor.

    One sentence for the constant torque of the steady state and, where the file
    has a motor, one for it. A mean torque of 0 (loads that give back their work
    over a turn: inertia and gravity alone) sizes no motor: a sentence points to
    the balancing torque's peak and RMS, which do. ``unit`` is the torque's unit as
    the text around it writes it, ``number`` how it writes a number.
    """
    motor = motor_shown(result)
    text = f"{number(motor)} {unit} ({_motor_note(motor, result)})"
    if motor == 0.0:
        text += f". {NO_MEAN_TORQUE}"
    found = result.mechanism.motor
    if found is None:
        return text
    against = against_omega(found, result.omega, unit)
    if against is not None:
        # the start-up warns of it: the report and the notebook have no warnings
        return f"{text}. The file's [motor] drives the start-up alone, but {against}."
    if found.no_load_speed is None:
        return text
    # the steady state is the contract's: a constant torque at the nominal
    # speed; the file's motor, whose torque falls with speed, runs the start-up
    return (
        f"{text}. The file's [motor], {number(found.at(result.omega))} {unit} at "
        f"the nominal {number(abs(result.omega))} rad/s, drives the start-up alone."
    )


def swing_text(result: Any, number: Callable[[float], str] = number_text) -> str:
    """Return the energy swing (J) and, where it is none, why the speed still varies.

    Without loads that do work, the kinetic energy is constant over the turn and
    the speed varies with the links' reduced inertia alone: a delta beside "0 J"
    asks for the reason. A swing below 10^-12 of the kinetic energy is round-off.
    """
    text = f"{number(result.energy_swing)} J"
    if result.speed_max > result.speed_min and (
        result.energy_swing <= NO_WORK * result.energy
    ):
        text += (
            ". No load does work: the speed varies with the links' reduced inertia "
            "alone."
        )
    return text


def figure_lines(
    result: Any,
    sizing: Any = None,
    run: Any = None,
    unit: Callable[[str], str] = str,
) -> list[tuple[str, str]]:
    """Return the figures of the steady state (and start-up), as (label, value) lines.

    What ``assur dynamics`` prints (aligned) and a notebook shows (a table).
    ``sizing`` is a flywheel's sizing (``assur dynamics --delta``), ``run`` a
    start-up; a line with an empty label goes on from the one above. ``unit``
    writes a plain ASCII unit (``"kg m^2"``) as the table beside the figures does:
    unchanged on the command line, whose units rows are ASCII.
    """
    kgm2 = unit("kg m^2")
    lines: list[tuple[str, str]] = [
        ("nominal crank speed", speed_text(result.omega)),
        ("flywheel", f"{result.flywheel:.6g} {kgm2}"),
        ("motor torque", motor_text(result, unit("N m"))),
        ("coefficient of speed fluctuation", f"delta = {_delta(result.delta)}"),
        (
            "largest speed",
            f"{result.speed_max:.6g} rad/s at {crank_angle_text(result.angle_max)}",
        ),
        (
            "smallest speed",
            f"{result.speed_min:.6g} rad/s at {crank_angle_text(result.angle_min)}",
        ),
        ("energy swing", swing_text(result)),
        ("kinetic energy at the reference pose", f"{result.energy:.6g} J"),
        (
            "internal grid",
            f"{result.grid} positions a turn (the work's relative error "
            f"{result.tolerance:.1g})",
        ),
    ]
    if not result.speed_max > result.speed_min:
        # nothing varies over the turn: no place of the largest or smallest speed
        lines[4:6] = [("crank speed", f"constant, {abs(result.omega):.6g} rad/s")]
    if sizing is not None:
        gaps = {k: f"{100 * v:+.3g} %" for k, v in sizing.differences().items()}
        lines[1] = (
            "flywheel",
            f"{sizing.exact:.6g} {kgm2} (exact, for delta = {_delta(sizing.delta)})",
        )
        # the classical estimates drop terms of the order of the mechanism's own
        # fluctuation: close to it they fail, even below zero
        names = {
            "wittenbauer": "Wittenbauer",
            "mertsalov": "Mertsalov",
            "energy_swing": "energy swing",
        }
        good = [
            f"{label} {getattr(sizing, k):.6g} ({gaps[k]})"
            for k, label in names.items()
            if getattr(sizing, k) >= 0
        ]
        failed = [label for k, label in names.items() if not getattr(sizing, k) >= 0]
        if failed:
            good.append(
                f"{spoken(failed)} none (below zero this close to the "
                "mechanism's own delta)"
            )
        lines.insert(2, ("classical estimates", ", ".join(good)))
    if run is not None:
        lines += startup_lines(run, result)
    return lines


def startup_lines(run: Any, result: Any = None) -> list[tuple[str, str]]:
    """Return the figures of a start-up, as (label, value) lines.

    A periodic motion whose mean speed is not the steady state's nominal one (a
    motor whose torque falls with speed) is set against it.
    """
    # the crank's turns until it settles, not those integrated to tell it has
    turned = abs(float(np.interp(run.settle_time, run.time, run.angle)) - run.angle[0])
    middle = 0.5 * (run.speed_max + run.speed_min)
    lines = [
        (
            "start-up",
            f"settles in {run.settle_time:.6g} s ({turned / 360.0:.3g} turns; "
            f"{run.turns} turns integrated)",
        ),
        (
            "periodic motion",
            # magnitudes, as the steady state's extremes are
            f"speed {run.speed_min:.6g} to {run.speed_max:.6g} rad/s, time-mean "
            f"{abs(run.mean_speed):.6g} rad/s (2 pi / period {run.period:.6g} s)"
            + (", clockwise" if run.mean_speed < 0 else ""),
        ),
        (
            "",
            # the steady state's definition: over the mean of the extreme speeds
            f"delta = {_run_delta(run.delta)} (max - min over w_m = (max + min) / 2 "
            f"= {middle:.6g} rad/s)",
        ),
    ]
    if result is None:  # the start-up alone: no steady state to set it against
        return lines
    gap = abs(run.mean_speed) / abs(result.omega) - 1.0
    if abs(gap) > 0.005:
        lines.append(
            (
                "",
                f"the time-mean speed is {100.0 * gap:+.3g} % from the nominal "
                f"{abs(result.omega):.6g} rad/s, at which the steady state above "
                "and its delta hold",
            )
        )
    return lines


def _run_delta(value: float) -> str:
    """Return a periodic motion's delta: none where the integration cannot tell it.

    The periodic speed is found to ``PERIODIC_RTOL`` of itself: a fluctuation below
    ten times that is the integration's, not the machine's.
    """
    if value < 10.0 * PERIODIC_RTOL:
        return f"{value:.2g}, none within the periodic speed's tolerance"
    return _delta(value)


def _delta(value: float) -> str:
    """Return a coefficient of speed fluctuation with 6 significant digits.

    More where those round it up to 2, the crank at rest, which no steady motion
    reaches and ``--delta`` refuses: ``--delta 1.999999`` was told "delta = 2".
    """
    text = f"{value:.6g}"
    digits = 6
    while float(text) >= 2.0 > value and digits < 17:
        digits += 1
        text = f"{value:.{digits}g}"
    return text


def dynamics_html(result: Any) -> str:
    """Return the steady state's figures as a notebook shows them (HTML)."""
    from assur._display import figures_html
    from assur.columns import pretty_unit

    name = result.mechanism.name or "Mechanism"
    caption = f"{name}: dynamic model reduced to the crank"
    # the units of the table below the figures: "kg·m²", not "kg m^2"
    return figures_html(caption, figure_lines(result, unit=pretty_unit))


def startup_html(run: Any) -> str:
    """Return a start-up's figures as a notebook shows them (HTML)."""
    from assur._display import figures_html

    name = run.mechanism.name or "Mechanism"
    return figures_html(f"{name}: start-up of the crank", startup_lines(run))
