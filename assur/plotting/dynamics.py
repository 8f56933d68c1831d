"""Pictures of the dynamic model: J(phi), the torques, the speed, Wittenbauer, start-up.

Each function takes the result of
:func:`assur.dynamics <assur.dynamics_model.dynamics>` (or of
:func:`assur.startup <assur.dynamics_startup.startup>`) and draws on the given axes
or on new ones; :func:`plot_dynamics` puts the four pictures of the steady state on
one figure.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from assur.columns import pretty_unit
from assur.errors import UsageError
from assur.plotting._axes import _new_axes, labelled_legend, turn_ticks
from assur.plotting._numbers import number, quantity
from assur.plotting._style import BALANCING_COLOR, PATH_COLORS, titled

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from assur.dynamics_model import Dynamics
    from assur.dynamics_startup import Startup

__all__ = [
    "plot_dynamics",
    "plot_energy_mass",
    "plot_reduced_inertia",
    "plot_reduced_torque",
    "plot_speed",
    "plot_startup",
]

SPEED_COLOR = PATH_COLORS[0]
INERTIA_COLOR = PATH_COLORS[2]
LOAD_COLOR = PATH_COLORS[1]
TANGENT_COLORS = ("#d62728", "#1f77b4")
"""Colours of the tangents of the largest and the smallest speed."""


def _expect(result: Any, kind: str, what: str) -> None:
    """Refuse a ``result`` that is not a ``kind`` (``"Dynamics"`` or ``"Startup"``).

    Raises
    ------
    UsageError
        Naming ``what`` and the function whose result it expects: a forces table
        gave an AttributeError from deep inside.
    """
    # told by a field of its own: the pictures' modules import no analysis
    field, maker = {
        "Dynamics": ("energy_swing", "assur.dynamics"),
        "Startup": ("settle_time", "assur.startup"),
    }[kind]
    if not hasattr(result, field):
        msg = f"{what}: expected the result of {maker}, got {type(result).__name__}"
        raise UsageError(msg)


def _angle_axis(ax: Any, result: Dynamics) -> Any:
    """Label the horizontal axis with the crank angle; return the angles (deg)."""
    x = np.asarray(result["angle"])
    ax.set_xlabel("crank angle φ [deg]")
    turn_ticks(ax, x)
    ax.grid(True, lw=0.5, alpha=0.5)
    return x


def _label(result: Dynamics, name: str, text: str) -> str:
    """Return ``text [unit]`` with the column's unit as pictures write it."""
    return f"{text} [{pretty_unit(result.column(name).unit)}]"


def plot_reduced_inertia(result: Dynamics, ax: Axes | None = None) -> Axes:
    """Plot the reduced inertia ``J(phi)`` (flywheel included) against the crank angle.

    Parameters
    ----------
    result : Dynamics
        The result of :func:`assur.dynamics <assur.dynamics_model.dynamics>`.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    _expect(result, "Dynamics", "plot_reduced_inertia")
    ax = _new_axes(ax, (8.0, 4.5))
    x = _angle_axis(ax, result)
    ax.plot(x, result["reduced.inertia"], color=INERTIA_COLOR, lw=1.8)
    ax.set_ylabel(_label(result, "reduced.inertia", "reduced inertia J"))
    # a flywheel lifts the curve: its share said, and the values written whole,
    # not as small numbers over an offset that read as a spike
    ax.ticklabel_format(axis="y", useOffset=False)
    title = "Reduced inertia"
    if result.flywheel > 0:
        flywheel = quantity(result.flywheel, pretty_unit("kg m^2"))
        title += f" (the flywheel's {flywheel} included)"
    ax.set_title(title, fontsize=10)
    return ax


def plot_reduced_torque(result: Dynamics, ax: Axes | None = None) -> Axes:
    """Plot the reduced torque of the loads and the constant motor torque.

    Parameters are those of :func:`plot_reduced_inertia`.
    """
    _expect(result, "Dynamics", "plot_reduced_torque")
    ax = _new_axes(ax, (8.0, 4.5))
    x = _angle_axis(ax, result)
    unit = pretty_unit(result.column("reduced.torque").unit)
    ax.plot(x, result["reduced.torque"], color=LOAD_COLOR, lw=1.8, label="loads M(φ)")
    ax.axhline(
        result.motor,
        color=BALANCING_COLOR,
        lw=1.4,
        ls="--",
        label=f"motor {quantity(result.motor, unit)}",
    )
    ax.axhline(0.0, color="black", lw=0.6)
    scale = _kinetic(result)  # N m per rad: the torques' own scale
    if _nothing(result["reduced.torque"], scale):
        ax.set_ylim(-0.05 * scale, 0.05 * scale)
        _say_nothing(ax, "no loads: the reduced torque is zero at every angle")
    ax.set_ylabel(f"reduced torque [{unit}]")
    ax.set_title("Reduced torque of the loads and the motor", fontsize=10)
    labelled_legend(ax, fontsize=8)
    return ax


NOTHING = 1e-9
"""Values below this fraction of the mechanism's kinetic energy (J, or N m a radian)
are round-off: a panel of them says there is nothing to show, at a readable scale."""


def _kinetic(result: Dynamics) -> float:
    """Return the kinetic energy at the largest reduced inertia and mean speed, J."""
    return float(0.5 * np.max(result["reduced.inertia"]) * result.omega**2)


def _nothing(values: Any, scale: float) -> bool:
    """Whether ``values`` are all round-off against ``scale``."""
    return bool(np.max(np.abs(values)) <= NOTHING * scale)


def _say_nothing(ax: Any, text: str) -> None:
    """Write ``text`` across the middle of a panel that shows nothing."""
    ax.text(0.5, 0.62, text, transform=ax.transAxes, ha="center", fontsize=9,
            color="#555555")  # fmt: skip


def plot_speed(result: Dynamics, ax: Axes | None = None) -> Axes:
    """Plot the crank speed of the steady state, its mean and its extremes.

    Parameters are those of :func:`plot_reduced_inertia`.
    """
    _expect(result, "Dynamics", "plot_speed")
    ax = _new_axes(ax, (8.0, 4.5))
    x = _angle_axis(ax, result)
    sign = 1.0 if result.omega > 0 else -1.0
    ax.plot(x, result["driver.omega"], color=SPEED_COLOR, lw=1.8, label="ω(φ)")
    ax.axhline(result.omega, color="black", lw=0.8, ls=":", label="mean ω")
    for speed, name in ((result.speed_max, "max"), (result.speed_min, "min")):
        ax.axhline(sign * speed, color=SPEED_COLOR, lw=0.6, ls="--")
        ax.annotate(
            f"{name} {speed:.5g} rad/s",
            (x[0], sign * speed),
            fontsize=7,
            xytext=(2, 2),
            textcoords="offset points",
        )
    ax.set_ylabel(_label(result, "driver.omega", "crank speed ω"))
    ax.set_title(
        f"Steady state: δ = {number(result.delta)}, flywheel "
        f"{quantity(result.flywheel, pretty_unit('kg m^2'))}",
        fontsize=10,
    )
    labelled_legend(ax, fontsize=8)
    return ax


def plot_energy_mass(result: Dynamics, ax: Axes | None = None) -> Axes:
    """Draw the energy-mass (Wittenbauer) diagram and its two tangents.

    The work done since the reference pose, ``reduced.work``, against the
    mechanism's reduced inertia (without the flywheel); the tangents of slopes
    ``w_max^2 / 2`` and ``w_min^2 / 2`` pass through the pole ``(-J_f, -E_0)``.

    Parameters are those of :func:`plot_reduced_inertia`.
    """
    _expect(result, "Dynamics", "plot_energy_mass")
    ax = _new_axes(ax, (6.0, 5.0))
    inertia = np.asarray(result["reduced.inertia"]) - result.flywheel
    work = np.asarray(result["reduced.work"])
    ax.plot(inertia, work, color=INERTIA_COLOR, lw=1.6, label="W against J")
    ax.plot(inertia[:1], work[:1], marker="o", color=INERTIA_COLOR, ms=4)
    span = np.array([inertia.min(), inertia.max()])
    span = span + np.array([-0.15, 0.15]) * max(float(np.ptp(span)), 1e-12)
    for speed, name, color in zip(
        (result.speed_max, result.speed_min),
        ("max", "min"),
        TANGENT_COLORS,
        strict=True,
    ):
        slope = 0.5 * speed * speed
        ax.plot(
            span,
            slope * (span + result.flywheel) - result.energy,
            color=color,
            lw=1.0,
            ls="--",
            label=f"tangent ω {name} = {speed:.5g} rad/s",
        )
    low, high = float(work.min()), float(work.max())
    pad = 0.2 * max(high - low, 1e-12 * max(abs(high), 1.0))
    scale = _kinetic(result)
    if _nothing(work, scale):
        # no loads: the work is zero, not a curve of round-off (+-2e-13 J)
        low, high, pad = 0.0, 0.0, 0.05 * scale
        _say_nothing(ax, "no loads: no work is done, the curve is J alone")
    ax.set_ylim(low - pad, high + pad)
    ax.set_xlim(*span)
    ax.set_xlabel(f"reduced inertia of the mechanism J [{pretty_unit('kg m^2')}]")
    ax.set_ylabel(_label(result, "reduced.work", "work W"))
    ax.set_title("Energy-mass (Wittenbauer) diagram", fontsize=10)
    ax.grid(True, lw=0.5, alpha=0.5)
    labelled_legend(ax, fontsize=8)
    return ax


def plot_dynamics(result: Dynamics) -> Figure:
    """Draw the four pictures of the steady state on one figure.

    ``J(phi)``, the torques, the speed and the energy-mass diagram.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import assur
    >>> fig = plot_dynamics(assur.dynamics(assur.catalog.slider_crank()))
    >>> len(fig.axes)
    4
    >>> import matplotlib.pyplot as plt
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    _expect(result, "Dynamics", "plot_dynamics")
    fig, axes = plt.subplots(2, 2, figsize=(12.0, 8.0), layout="constrained")
    plot_reduced_inertia(result, axes[0, 0])
    plot_reduced_torque(result, axes[0, 1])
    plot_speed(result, axes[1, 0])
    plot_energy_mass(result, axes[1, 1])
    fig.suptitle(
        f"{titled(result.mechanism)}: dynamic model reduced to the crank",
        fontsize=11,
    )
    return fig


def plot_startup(run: Startup, ax: Axes | None = None) -> Axes:
    """Plot the crank speed against time at start-up, and the time to settle.

    Parameters
    ----------
    run : Startup
        The result of :func:`assur.startup <assur.dynamics_startup.startup>`.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    _expect(run, "Startup", "plot_startup")
    ax = _new_axes(ax, (8.0, 4.5))
    ax.plot(run.time, run.omega, color=SPEED_COLOR, lw=1.2, label="ω(t)")
    ax.axhline(run.mean_speed, color="black", lw=0.8, ls=":", label="periodic mean")
    ax.axvline(
        run.settle_time,
        color=BALANCING_COLOR,
        lw=1.0,
        ls="--",
        label=f"settled at {quantity(run.settle_time, 's')}",
    )
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("crank speed ω [rad/s]")
    ax.set_title(
        f"Start-up: periodic after {run.turns} turns, δ = {number(run.delta)}",
        fontsize=10,
    )
    ax.grid(True, lw=0.5, alpha=0.5)
    labelled_legend(ax, fontsize=8)
    return ax
