"""Motion over a sweep: quantities of links and points against the driver, paths.

:func:`plot_motion` plots a column of the table against the driver position;
:func:`plot_paths` draws the paths of points over the mechanism drawn faintly.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._gaps import broken, gaps
from assur._listed import listed
from assur._text import spoken
from assur.columns import LINK_PARTS, POINT_PARTS
from assur.errors import UnknownNameError
from assur.plotting._axes import (
    _broken,
    _driver_axis,
    _frame_axes,
    _new_axes,
    labelled_legend,
)
from assur.plotting._context import _Context, _context, _row, _unit, whole
from assur.plotting._style import (
    PATH_COLORS,
    PATH_MARK_SPACING,
    PATH_MARKERS,
    literal,
    titled,
)
from assur.plotting.mechanism import _draw_mechanism

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from assur.analysis import Table
    from assur.plan import Plan

__all__ = ["plot_motion", "plot_paths"]

DASHES = ("-", "--", ":", "-.")
"""Line styles of the links of one group, in order (cycled)."""
VECTORS = dict(zip("xvaj", POINT_PARTS, strict=True))
"""The columns of a point's position and its derivatives, by quantity: ``"v"``
is ``vx`` and ``vy``."""


def plot_motion(
    table: Table,
    names: Sequence[str] | str | None = None,
    quantity: str = "omega",
    ax: Axes | None = None,
) -> Axes:
    """Plot one quantity of links or points against the driver position.

    Parameters
    ----------
    table : Table
    names : str or sequence of str, optional
        Links, or points (joints, extra points, centres ``"L.G"``). Default: every
        moving link for a link quantity, every moving point otherwise.
    quantity : str
        For links ``"angle"`` (deg), ``"omega"``, ``"alpha"``, ``"jerk"``; for points
        ``"x"``, ``"v"``, ``"a"``, ``"j"`` (both components) or one column suffix
        such as ``"vy"``; for prismatic joints also ``"s"`` and, as their slide's
        derivatives, ``"v"``, ``"a"``, ``"j"``.
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    UnknownNameError
        When the table has no such column for one of ``names`` (a
        :class:`~assur.errors.UsageError` and a :class:`KeyError`).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import assur
    >>> t = assur.kinematics(assur.catalog.four_bar(), range(0, 360, 10))
    >>> ax = plot_motion(t, ["coupler", "rocker"], "omega")
    >>> len(ax.lines)
    2
    >>> import matplotlib.pyplot as plt
    >>> plt.close(ax.figure)
    """
    whole(table, "plot_motion")
    names = (
        _moving(table, quantity)
        if names is None
        else listed(names, "names", "link or point")
    )
    ax = _new_axes(ax, (8.0, 4.5))
    # lines break where positions were left out, x and y alike
    x = _broken(table, _driver_axis(ax, table))
    ctx = _context(table)
    plotted = [
        key for name in names for key in _plot_quantity(ax, ctx, x, name, quantity)
    ]
    # the unit of the columns drawn, as the schema gives it
    units = " or ".join(dict.fromkeys(_unit(table, key) for key in plotted))
    ax.set_ylabel(f"{quantity} [{units}]" if units else quantity)
    ax.set_title(f"{titled(table.mechanism)}: {quantity}", fontsize=10)
    labelled_legend(ax, fontsize=8, ncols=2 if len(ax.lines) > 8 else 1)
    return ax


def _moving(table: Table, quantity: str) -> list[str]:
    """Links that turn, for a link ``quantity``; else the points that move."""
    if quantity not in LINK_PARTS:
        return _moving_points(table, extra_first=False)
    # links that only slide (their angle is constant) would add flat lines
    links = _public_links(table.plan)
    return [x for x in links if np.ptp(table[f"{x}.angle"]) > 1e-9]


def _plot_quantity(
    ax: Any, ctx: _Context, x: np.ndarray, name: str, quantity: str
) -> list[str]:
    """Plot ``quantity`` of link or point ``name`` (both components of a vector).

    Returns the columns plotted.
    """
    table = ctx.table
    color, style = _link_style(ctx, name)
    if f"{name}.{quantity}" in table:
        ax.plot(
            x,
            _broken(table, table[f"{name}.{quantity}"]),
            lw=1.6,
            label=literal(name),
            color=color,
            ls=style,
        )
        return [f"{name}.{quantity}"]
    if quantity in VECTORS and f"{name}.{VECTORS[quantity][0]}" in table:
        cx, cy = VECTORS[quantity]
        line = ax.plot(
            x,
            _broken(table, table[f"{name}.{cx}"]),
            lw=1.6,
            label=literal(f"{name} {cx}"),
        )
        ax.plot(
            x,
            _broken(table, table[f"{name}.{cy}"]),
            lw=1.6,
            ls="--",
            color=line[0].get_color(),
            label=literal(f"{name} {cy}"),
        )
        return [f"{name}.{cx}", f"{name}.{cy}"]
    msg = _no_quantity(table, name, quantity)
    raise UnknownNameError(msg)


def _link_style(ctx: _Context, name: str) -> tuple[str | None, str]:
    """Colour and dashes of link ``name``: its group's colour, a dash per link."""
    if name not in ctx.plan.bodies:
        return None, "-"
    body = ctx.plan.body(name)
    color = ctx.color[body]
    # links of one group share its colour; their order in it sets the dashes
    same = [b for b in range(body) if ctx.color[b] == color]
    return color, DASHES[len(same) % len(DASHES)]


def _no_quantity(table: Table, name: str, quantity: str) -> str:
    """Return the message for a missing ``quantity`` of ``name``, with those it has."""
    have = sorted(
        {c.rsplit(".", 1)[1] for c in table.columns if c.rsplit(".", 1)[0] == name}
    )
    have += [q for q in VECTORS if f"{name}.x" in table and q not in have]
    if not have:
        return f"plot_motion: no link or point {name!r} in the table"
    return (
        f"plot_motion: no quantity {quantity!r} for {name!r}; expected "
        f"{spoken(have, 'or')}"
    )


def _public_links(plan: Plan) -> list[str]:
    """Return the moving links as the file names them (no slot blocks)."""
    return [b for b in plan.bodies[1:] if "~" not in b]


def _moving_points(table: Table, extra_first: bool = True) -> list[str]:
    """Return the reported points that move (joints, extra points; no centres)."""
    plan = table.plan
    extra = [p.name for p in table.mechanism.points]
    joints = [n for n, pair in plan.pairs.items() if not pair.virtual]
    names: list[str] = []
    paths: list[np.ndarray] = []
    for name in (extra + joints) if extra_first else (joints + extra):
        path = np.column_stack([table[f"{name}.x"], table[f"{name}.y"]])
        if np.ptp(path, axis=0).max() <= 1e-9 * plan.scale:
            continue  # a pivot on the frame has no path
        if any(np.allclose(path, q, rtol=0, atol=1e-9 * plan.scale) for q in paths):
            continue  # a slider's guide point runs with its pin
        names.append(name)
        paths.append(path)
    return names


def plot_paths(
    table: Table,
    points: Sequence[str] | None = None,
    angle: Any = None,
    ax: Axes | None = None,
) -> Axes:
    """Plot the paths of points over the sweep, over the mechanism drawn faintly.

    Parameters
    ----------
    table : Table
    points : sequence of str, optional
        Point names (joints, extra points, centres ``"L.G"``). Default: every extra
        point (coupler curves, drawn thicker) and every moving joint.
    angle : float, optional
        Driver position of the faint mechanism, deg (default: the first row).
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    ctx = _context(table)
    row = _row(table, angle)
    ax = _new_axes(ax)
    seen = _draw_mechanism(
        ax, ctx, ctx.pose(row), set(), set(range(len(ctx.plan.bodies)))
    )
    extra = {p.name for p in table.mechanism.points}
    if points is None:
        names = _moving_points(table)
    else:
        names = listed(points, "points", "point")
    rows = gaps(table)
    for k, name in enumerate(names):
        if f"{name}.x" not in table:
            msg = f"plot_paths: no point {name!r}; expected a joint or an extra point"
            raise UnknownNameError(msg)
        xy = np.column_stack([table[f"{name}.x"], table[f"{name}.y"]])
        color = PATH_COLORS[k % len(PATH_COLORS)]
        coupler = name in extra
        line = broken(xy, rows)
        ax.plot(
            line[:, 0],
            line[:, 1],
            color=color,
            marker=PATH_MARKERS[k % len(PATH_MARKERS)],
            markersize=4.5,
            markevery=PATH_MARK_SPACING,
            lw=2.4 if coupler else 1.4,
            zorder=5,
            label=literal(f"{name} (coupler curve)" if coupler else name),
        )
        _sense(ax, xy, color, rows)
        seen += list(xy)
    _frame_axes(ax, ctx, seen, ctx.size, margin=0.06)
    ax.set_title(f"{titled(table.mechanism)}: paths of points", fontsize=10)
    labelled_legend(
        ax, fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False
    )
    return ax


def _sense(ax: Any, xy: np.ndarray, color: str, rows: Sequence[int] = ()) -> None:
    """Draw an arrowhead a third of the way along a path: the sense of motion.

    ``rows``: the rows after positions left out; the arrow is not drawn across them.
    """
    from matplotlib.patches import FancyArrowPatch

    k = len(xy) // 3
    while k + 1 in rows:  # a step across positions left out has no direction
        k += 1
    if len(xy) < 3 or k + 2 > len(xy) or not np.all(np.isfinite(xy[k : k + 2])):
        return
    ax.add_patch(
        FancyArrowPatch(
            tuple(xy[k]),
            tuple(xy[k + 1]),
            arrowstyle="-|>",
            mutation_scale=14,
            color=color,
            lw=0,
            zorder=5.5,
            shrinkA=0,
            shrinkB=0,
        )
    )
