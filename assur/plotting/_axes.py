"""Axes and legends shared by the pictures: new axes, framing, driver axis, legend.

matplotlib is imported inside the functions only.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._gaps import broken, gaps
from assur.errors import UsageError
from assur.plotting._context import _revolute, _unit
from assur.plotting._style import literal

if TYPE_CHECKING:
    from assur.analysis import Table
    from assur.plotting._context import _Context


def _new_axes(ax: Any, figsize: tuple[float, float] = (9.0, 6.0)) -> Any:
    """Return ``ax``, or new axes on a new figure of ``figsize`` (in)."""
    if ax is not None:
        return given_axes(ax)
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


def given_axes(ax: Any) -> Any:
    """Return ``ax``, checked to be matplotlib axes.

    Raises
    ------
    UsageError
        For anything else (a string, a figure): it failed deep in the drawing.
    """
    from matplotlib.axes import Axes

    if not isinstance(ax, Axes):
        kind = type(ax).__name__
        if hasattr(ax, "add_subplot"):
            kind = "a Figure (expected one of its axes)"
        msg = f"ax: expected matplotlib axes, or None for a new figure; got {kind}"
        raise UsageError(msg)
    return ax


def _frame_axes(
    ax: Any,
    ctx: _Context,
    points: Sequence[np.ndarray],
    size: float,
    margin: float = 0.1,
) -> None:
    """Fit equal-aspect axes to ``points`` with a ``margin`` of ``size`` (m).

    The axes are labelled with the unit of the points' coordinates in ``ctx``'s table.
    """
    pts = np.array(points).reshape(-1, 2)
    pts = pts[np.isfinite(pts).all(axis=1)]
    low, high = pts.min(axis=0), pts.max(axis=0)
    pad = margin * max(size, *(high - low))
    ax.set_xlim(low[0] - pad, high[0] + pad)
    ax.set_ylim(low[1] - pad, high[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    point = ctx.plan.points[0]
    ax.set_xlabel(f"x [{_unit(ctx.table, f'{point}.x')}]")
    ax.set_ylabel(f"y [{_unit(ctx.table, f'{point}.y')}]")


TURN_TICKS_SPAN = 3600.0
"""Widest span of crank angles (deg) ticked every 45 or 90 deg: ten turns, 41 ticks.

Wider, matplotlib's own ticks: 90 deg over 1000 turns drew 4001 ticks and labels
on top of one another (minutes for ``assur diagrams``), and over a span of 1e20
deg failed ("Maximum allowed size exceeded")."""


def turn_ticks(ax: Any, x: np.ndarray) -> None:
    """Tick an axis of crank angles ``x`` (deg) at quarter or eighth turns.

    Only over half a turn to :data:`TURN_TICKS_SPAN`; other spans keep
    matplotlib's ticks.
    """
    from matplotlib.ticker import MultipleLocator

    # ptp in halves: a span of positions near the largest float overflows
    span = 2.0 * float(np.max(x) / 2 - np.min(x) / 2) if len(x) else 0.0
    if 180.0 <= span <= TURN_TICKS_SPAN:
        ax.xaxis.set_major_locator(MultipleLocator(90.0 if span > 400 else 45.0))


def _driver_axis(ax: Any, table: Table) -> np.ndarray:
    """Label the horizontal axis with the driver position; return its values."""
    x = np.asarray(table["angle"])
    unit = _unit(table, "angle")
    drivers = table.mechanism.drivers
    # with several drivers the axis is the first one's: it is named
    whose = f" {drivers[0].joint}" if len(drivers) > 1 else ""
    if _revolute(table):
        ax.set_xlabel(f"driver{whose} angle φ [{unit}]")
        turn_ticks(ax, x)
    else:
        ax.set_xlabel(f"driver{whose} position s [{unit}]")
    ax.grid(True, lw=0.5, alpha=0.5)
    return x


def _broken(table: Table, values: Any) -> np.ndarray:
    """Return ``values``, one per row of ``table``, with NaN where its lines break.

    A NaN row goes between two positions kept with positions left out between them
    (``skip_unassembled``), so that a line does not cross them as if it had data
    there; a sweep with none left out gives ``values`` as they are.
    """
    return broken(values, gaps(table))


def _handles(entries: list[tuple[str, str]]) -> list[Any]:
    """Legend handles: a thick line in each colour (none for a note such as a scale)."""
    from matplotlib.lines import Line2D

    return [
        Line2D([], [], color=c or "none", lw=4 if c else 0, label=literal(text))
        for text, c in entries
    ]


def _legend(ax: Any, entries: list[tuple[str, str]]) -> None:
    """Put a legend of ``entries`` (text, colour) right of ``ax``."""
    ax.legend(
        handles=_handles(entries),
        fontsize=8,
        frameon=False,
        loc="upper left",
        bbox_to_anchor=(1.02, 1.0),
    )


def labelled_legend(ax: Any, **kwargs: Any) -> None:
    """Put the legend of ``ax``'s labelled artists, if it has any.

    A sweep of one position draws no line (matplotlib would warn of an empty legend).
    """
    if ax.get_legend_handles_labels()[0]:
        ax.legend(**kwargs)


def fit_height(ax: Any, least: float = 3.6) -> None:
    """Make the figure of a flat equal-aspect view (a group lying along a line) lower.

    The axes keep their width; the figure loses the height the view would have
    filled with nothing, down to ``least`` inches (room for a legend beside and
    the loads' names above and below). For a figure made for ``ax`` alone: a
    caller's figure keeps its size.
    """
    from assur.plotting._bars import settled_renderer

    settled_renderer(ax)
    fig = ax.figure
    room = ax.get_position(original=True).transformed(fig.transSubfigure)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    wanted = room.width * (y1 - y0) / (x1 - x0)  # pixels
    spare = (room.height - wanted) / fig.dpi  # inches
    width, height = fig.get_size_inches()
    if spare > 0.0 and height > least:
        fig.set_size_inches(width, max(least, height - spare), forward=False)


def fill_box(ax: Any) -> None:
    """Widen (or heighten) the view of equal-aspect ``ax`` to fill the room laid out.

    An equal-aspect picture of a tall group leaves its axes a narrow strip of the
    room the layout gave them; the view grows about its middle instead, so that
    the axes take all of it. Measured once the layout (a legend beside) settles.
    """
    from assur.plotting._bars import settled_renderer

    settled_renderer(ax)
    # the position is a share of the (sub)figure that holds the axes
    room = ax.get_position(original=True).transformed(ax.figure.transSubfigure)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    wide, tall = x1 - x0, y1 - y0
    shape = room.width / room.height
    if wide / tall < shape:
        grow = 0.5 * (tall * shape - wide)
        ax.set_xlim(x0 - grow, x1 + grow)
    else:
        grow = 0.5 * (wide / shape - tall)
        ax.set_ylim(y0 - grow, y1 + grow)
