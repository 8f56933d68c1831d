"""Forces over a sweep: balancing load, hodographs of the reactions, shaking force.

Each diagram needs a forces table; the hodographs trace the tip of a force vector
over the sweep from the origin.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._listed import listed
from assur.errors import UnknownNameError, UsageError
from assur.plotting._axes import _broken, _driver_axis, _new_axes, labelled_legend
from assur.plotting._context import _context, _need_forces, _unit
from assur.plotting._geometry import _on
from assur.plotting._numbers import quantity
from assur.plotting._style import BALANCING_COLOR, literal, titled

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from assur.analysis import Table

__all__ = ["plot_hodographs", "plot_shaking", "plot_torque"]

BALANCING_COLORS = (BALANCING_COLOR, "#e6550d", "#31a354")
"""Colours of the balancing loads, one per driver (cycled)."""


def plot_torque(table: Table, ax: Axes | None = None) -> Axes:
    """Plot the balancing torque (or force) and its virtual-power check.

    Parameters
    ----------
    table : Table
        A forces table.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    _need_forces(table, "plot_torque")
    plan = table.plan
    ax = _new_axes(ax, (8.0, 4.5))
    x = _driver_axis(ax, table)
    summary = table.summary()  # once: every joint's figures, each driver's mean
    for i, d in enumerate(plan.drivers):
        name = literal(f" at {d.pair.name}") if len(plan.drivers) > 1 else ""
        _plot_balancing(ax, table, x, (i, summary), name)
    ax.axhline(0.0, color="black", lw=0.6)
    keys = [_driver_key(table, i) for i in range(len(plan.drivers))]
    units = " or ".join(dict.fromkeys(_unit(table, key) for key in keys))
    ax.set_ylabel(f"balancing load [{units}]")
    ax.set_title(f"{titled(table.mechanism)}: balancing load", fontsize=10)
    labelled_legend(ax, fontsize=8)
    return ax


def _plot_balancing(
    ax: Any,
    table: Table,
    x: np.ndarray,
    driver: tuple[int, dict[str, float]],
    name: str,
) -> None:
    """Plot a driver's balancing load, its check (dots) and its mean.

    ``driver`` is the driver's index and the table's summary, which gives the mean.
    """
    i, summary = driver
    key = _driver_key(table, i)
    what, unit = table.column(key).quantity, _unit(table, key)
    color = BALANCING_COLORS[i % len(BALANCING_COLORS)]
    balancing = table[key]
    step = max(1, len(x) // 36)
    ax.plot(
        _broken(table, x),
        _broken(table, balancing),
        color=color,
        lw=1.8,
        label=f"balancing {what}{name} (equilibrium)",
    )
    ax.plot(
        x[::step],
        table[_driver_key(table, i, "_check")][::step],
        ls="none",
        marker="o",
        mfc="none",
        color=color,
        ms=5,
        label=f"virtual-power check{name}",
    )
    # the summary's mean: a sweep ending a whole turn on from its start (0:360:5)
    # ends on its first pose, counted once there; np.mean counted it twice
    mean = summary[f"{key}.mean"]
    if abs(mean) < 1e-9 * float(np.max(np.abs(balancing))):
        mean = 0.0  # a full turn of a conservative system: zero up to rounding
    ax.axhline(
        mean, color=color, lw=0.9, ls=":", label=f"mean {quantity(mean, unit)}{name}"
    )


def _locus(ax: Any, table: Table, fx: np.ndarray, fy: np.ndarray, color: str) -> None:
    """Draw the hodograph of a force: its tip's path, the origin, a few marks."""
    ax.plot(_broken(table, fx), _broken(table, fy), color=color, lw=1.5)
    ax.plot([0], [0], marker="+", color="black", ms=9)
    ax.axhline(0.0, color="#999999", lw=0.5)
    ax.axvline(0.0, color="#999999", lw=0.5)
    marks = np.linspace(0, len(fx), 5, dtype=int)[:-1] if len(fx) >= 4 else [0]
    ax.annotate(
        "",
        xy=(fx[0], fy[0]),
        xytext=(0, 0),
        arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.0},
    )
    unit = _unit(table, "angle")
    for k in marks:
        ax.plot([fx[k]], [fy[k]], marker="o", ms=3.5, color=color)
        angle = table["angle"][k]
        ax.annotate(
            f"{angle:.0f}°" if unit == "deg" else f"{angle:.3g} {unit}",
            (fx[k], fy[k]),
            fontsize=7,
            xytext=(3, 3),
            textcoords="offset points",
        )
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.4, alpha=0.5)


def plot_hodographs(table: Table, joints: Sequence[str] | None = None) -> Figure:
    """Plot the hodograph (polar diagram) of every joint reaction: Fy against Fx.

    Each panel traces the tip of the reaction vector (by the joint's first link on
    its second) over the sweep, from the origin; dots mark four driver positions.

    Parameters
    ----------
    table : Table
        A forces table.
    joints : sequence of str, optional
        Joints to show; default every joint.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt
    from matplotlib.ticker import MaxNLocator

    forces = _need_forces(table, "plot_hodographs")
    ctx = _context(table)
    pairs = ctx.plan.pairs
    names = _joints(pairs, joints)
    ncols = min(4, len(names))
    nrows = math.ceil(len(names) / ncols)
    fig, axes = plt.subplots(
        nrows,
        ncols,
        figsize=(3.4 * ncols, 3.3 * nrows + 0.4),
        layout="constrained",
        squeeze=False,
    )
    for ax, name in zip(axes.flat, names, strict=False):
        force = forces.reaction(name, len(table))[0]
        _locus(ax, table, force[:, 0], force[:, 1], ctx.color[pairs[name].second])
        most = np.nanmax(np.hypot(force[:, 0], force[:, 1]))
        ax.set_title(
            f"{literal(name)}: {literal(_on(ctx.plan, name))}\n"
            f"max {quantity(most, _unit(table, f'{name}.F'))}",
            fontsize=8.5,
        )
        ax.set_xlabel(f"Fx [{_unit(table, f'{name}.Fx')}]", fontsize=8)
        ax.set_ylabel(f"Fy [{_unit(table, f'{name}.Fy')}]", fontsize=8)
        ax.tick_params(labelsize=7)
        # a panel is narrow: matplotlib's default of up to nine ticks ran
        # "-2500-2000-1500" together along Fx
        ax.xaxis.set_major_locator(MaxNLocator(nbins=4, steps=[1, 2, 2.5, 5, 10]))
    for ax in list(axes.flat)[len(names) :]:
        ax.set_axis_off()
    fig.suptitle(
        f"{titled(table.mechanism)}: hodographs of the joint reactions",
        fontsize=10,
    )
    return fig


def _joints(pairs: dict[str, Any], joints: Sequence[str] | None) -> list[str]:
    """Return ``joints`` (default: every joint) once checked against ``pairs``."""
    if joints is None:
        return [n for n, p in pairs.items() if not p.virtual]
    names = listed(joints, "joints", "joint")
    if not names:
        # the grid of no panels divided by zero
        msg = "joints: no names; expected at least one joint, or None (every joint)"
        raise UsageError(msg)
    for name in names:
        if name not in pairs or pairs[name].virtual:
            msg = (
                f"plot_hodographs: no joint {name!r}; expected one of the file's joints"
            )
            raise UnknownNameError(msg)
    return names


def plot_shaking(table: Table) -> Figure:
    """Plot the shaking force (its hodograph and components) and shaking moment.

    The shaking force and moment are the resultant of every load the moving links
    put on the frame (moment about the origin).

    Parameters
    ----------
    table : Table
        A forces table.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    _need_forces(table, "plot_shaking")
    shaking = np.column_stack([table[f"shaking.{part}"] for part in ("Fx", "Fy", "M")])
    fig = plt.figure(figsize=(11.0, 4.8), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.0, 1.4))
    polar = fig.add_subplot(grid[:, 0])
    _locus(polar, table, shaking[:, 0], shaking[:, 1], "#1f77b4")
    polar.set_xlabel(f"Fx [{_unit(table, 'shaking.Fx')}]")
    polar.set_ylabel(f"Fy [{_unit(table, 'shaking.Fy')}]")
    polar.set_title("hodograph of the shaking force", fontsize=9)
    force = fig.add_subplot(grid[0, 1])
    # lines break where positions were left out; the hodograph breaks in _locus
    x = _broken(table, _driver_axis(force, table))
    lines = _broken(table, shaking)
    force.plot(x, lines[:, 0], label="Fx", lw=1.5)
    force.plot(x, lines[:, 1], label="Fy", lw=1.5)
    force.plot(
        x, np.hypot(lines[:, 0], lines[:, 1]), label="|F|", lw=1.5, color="black"
    )
    force.set_ylabel(f"force [{_unit(table, 'shaking.Fx')}]")
    labelled_legend(force, fontsize=8, ncols=3)
    force.set_xlabel("")
    moment = fig.add_subplot(grid[1, 1], sharex=force)
    _driver_axis(moment, table)
    moment.plot(x, lines[:, 2], color="#d62728", lw=1.5, label="M about the origin")
    moment.set_ylabel(f"moment [{_unit(table, 'shaking.M')}]")
    labelled_legend(moment, fontsize=8)
    fig.suptitle(
        f"{titled(table.mechanism)}: shaking force and moment on the frame",
        fontsize=10,
    )
    return fig


def _driver_key(table: Table, i: int, suffix: str = "") -> str:
    """Return the column of driver ``i``'s balancing load (or its "_check")."""
    d = table.plan.drivers[i]
    what = "torque" if d.kind == "R" else "force"
    owner = "driver" if len(table.plan.drivers) == 1 else d.pair.name
    return f"{owner}.{what}{suffix}"
