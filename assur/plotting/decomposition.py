"""The decomposition into Assur groups, step by step, and a group's free-body diagram.

:func:`draw_decomposition` shows how the mechanism is built, driver first, each group
on the links it hangs on; :func:`draw_free_body` cuts one group free and draws every
load on it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._structure import Group, Structure
from assur._style import REACTION_COLOUR
from assur._text import counted, describe
from assur._vec import integer
from assur.errors import UsageError
from assur.model import GROUND
from assur.plotting._arrows import INTERNAL_DASH, _draw_arrows
from assur.plotting._axes import _frame_axes, _legend, _new_axes, fill_box, fit_height
from assur.plotting._bars import clear_bars
from assur.plotting._context import (
    _Context,
    _context,
    _need_forces,
    _Pose,
    _position_title,
    _row,
    fitted_scale,
)
from assur.plotting._forces import (
    _applied_arrows,
    _Arrow,
    _inertia_arrows,
    _reaction_arrow,
    _scale,
    _scale_text,
)
from assur.plotting._friction import draw_friction_circles, friction_legend
from assur.plotting._geometry import _extent, _public
from assur.plotting._linknames import clear_arrows
from assur.plotting._loadnames import NAMED, place_loads
from assur.plotting._style import (
    INERTIA_COLOR,
    INTERNAL_LEGEND,
    LOAD_COLOR,
    REACTION_LEGEND,
    literal,
    titled,
)
from assur.plotting.mechanism import _draw_mechanism

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from assur.analysis import Table
    from assur.plan import Plan

__all__ = ["draw_decomposition", "draw_free_body"]


def draw_decomposition(table: Table, angle: Any = None) -> Figure:
    """Draw the decomposition into Assur groups, one panel per step.

    The driving links come first, then each Assur group in order of attachment,
    drawn in full with the known links it hangs on drawn faintly.

    Parameters
    ----------
    table : Table
    angle : float, optional
        Driver position, deg (nearest row; default the first).

    Returns
    -------
    matplotlib.figure.Figure
    """
    ctx = _context(table)
    row = _row(table, angle)
    pose = ctx.pose(row)
    steps = _steps(ctx)
    every = _extent(ctx, pose)
    fig, axes = _panels(ctx, every, len(steps))
    for k, ax in enumerate(axes.flat):
        if k >= len(steps):
            ax.set_axis_off()
            continue
        text, full, faint = steps[k]
        _draw_mechanism(ax, ctx, pose, full, faint - full)
        _frame_axes(ax, ctx, every, ctx.size, margin=0.08)
        on = sorted(_public(ctx.plan.bodies[b]) for b in faint)
        ax.set_title(literal(f"{k + 1}. {text}\nhangs on: {', '.join(on)}"), fontsize=9)
    fig.suptitle(
        f"{titled(table.mechanism)}: {literal(_structure(ctx.plan).formula)}\n"
        f"{literal(_position_title(table, row))}",
        fontsize=10,
    )
    return fig


def _structure(plan: Plan) -> Structure:
    """Return the structure the plan was compiled from, without decomposing again.

    The plan keeps the Assur groups; each driver is the class I group of the frame
    and its input link.
    """
    drivers = tuple(
        Group(
            1, 0, "driver", (GROUND, plan.bodies[d.body]), (d.pair.name,), (), (GROUND,)
        )
        for d in plan.drivers
    )
    mech, slots = plan.mechanism, plan.topology.slots
    return Structure(
        mech.name,
        len(mech.links),
        len(mech.joints) - len(slots),
        len(slots),
        len(plan.drivers),
        drivers,
        plan.groups,
        slots,
    )


def _steps(ctx: _Context) -> list[tuple[str, set[int], set[int]]]:
    """Return the steps: title, bodies added, the bodies they hang on."""
    plan = ctx.plan
    steps = [
        (f"I: driver (ground, {plan.bodies[d.body]})", {d.body}, {0})
        for d in plan.drivers
    ]
    for g, (text, _, bodies) in zip(
        plan.groups, ctx.legend[len(plan.drivers) :], strict=True
    ):
        steps.append((text, set(bodies), {plan.body(x) for x in g.attached_to}))
    return steps


def _panels(ctx: _Context, every: list[np.ndarray], count: int) -> tuple[Any, Any]:
    """Return a figure and a grid of ``count`` panels (or a few more), three a row."""
    import matplotlib.pyplot as plt

    ncols = min(3, count)
    nrows = math.ceil(count / ncols)
    span = np.ptp(np.array(every), axis=0)
    span = span + 0.16 * max(ctx.size, *span)
    # the panels keep the drawing's proportions: about 3.4 in of axes per panel width
    height = float(np.clip(3.4 * span[1] / span[0], 0.8, 5.5)) + 1.1
    return plt.subplots(
        nrows,
        ncols,
        figsize=(4.2 * ncols, height * nrows + 0.6),
        layout="constrained",
        squeeze=False,
    )


def draw_free_body(
    table: Table,
    group_index: int,
    angle: Any = None,
    ax: Axes | None = None,
    scale: float | None = None,
    labels: bool = True,
) -> Axes:
    """Draw the free-body diagram of one Assur group at one driver position.

    The group is cut free from the links it hangs on; the arrows are its inertia
    loads, gravity and external loads, the reactions of the known links at its
    external pairs (acting on the group) and, dashed, those at its internal pairs:
    equal and opposite, one on each of the pair's links. Each is labelled with its
    value; the arrows drawn balance.

    Parameters
    ----------
    table : Table
        A forces table.
    group_index : int
        Index of the group in the order of attachment (0: the first Assur group;
        drivers are not counted). The title numbers the groups from 1, as
        ``assur plot --group N`` does.
    angle : float, optional
        Driver position, deg (nearest row; default the first).
    ax : matplotlib Axes, optional
    scale : float, optional
        Force scale, N per cm of drawing; one that draws the largest force over
        10 000 times longer than the automatic scale is refused.
    labels : bool
        Name the joints and links, and the loads with their values.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    UsageError
        For a kinematics table or a group index out of range.
    """
    _need_forces(table, "draw_free_body")
    ctx = _context(table)
    group_index = _group(ctx, group_index)
    row = _row(table, angle)
    pose = ctx.pose(row)
    group = ctx.plan.groups[group_index]
    bodies = {ctx.plan.body(x) for x in group.links}
    own = ax is None
    ax = _new_axes(ax, (9.0, 6.5))
    seen = _draw_mechanism(ax, ctx, pose, bodies, labels=labels, frame=False)
    arrows = _free_body_arrows(table, group_index, row)
    scale = fitted_scale(scale, arrows, 0.8 * ctx.size) or _scale(
        arrows, 0.8 * ctx.size
    )
    seen += _draw_arrows(ax, ctx, arrows, scale, "values" if labels else None)
    seen += [a.at for a in arrows]
    # a journal's friction couple is in its reaction's line, tangent to this circle
    rubbing = draw_friction_circles(ax, ctx, pose, bodies)
    _frame_axes(ax, ctx, seen, 0.5 * ctx.size, margin=0.12)
    text, color, _ = ctx.legend[len(ctx.plan.drivers) + group_index]
    # the legend names only the kinds of load drawn (a slider-crank's group has
    # no gravity and no external load), as the mechanism's picture does
    applied = any(a.kind in ("gravity", "load") for a in arrows)
    inner = any(a.kind == "internal" for a in arrows)
    # numbered from 1 as `assur plot --group N` is; the class comes after, in words
    heading = f"Free body of group {group_index + 1} (class {text})"
    ax.set_title(
        literal(f"{heading}\n{_position_title(table, row)}"),
        fontsize=10,
    )
    _legend(
        ax,
        [
            (text, color),
            (REACTION_LEGEND, REACTION_COLOUR),
            *[(INTERNAL_LEGEND, REACTION_COLOUR)] * inner,
            ("inertia force and torque", INERTIA_COLOR),
            *[("gravity, external load", LOAD_COLOR)] * applied,
            *[(friction_legend(ctx), "")] * bool(rubbing),
            (_scale_text(arrows, scale), ""),
        ],
    )
    legend = ax.get_legend()
    assert legend is not None  # drawn by _legend just above
    for handle, words in zip(legend.legend_handles, legend.get_texts(), strict=True):
        if words.get_text() == INTERNAL_LEGEND:
            handle.set_linestyle(INTERNAL_DASH)  # the entry shows its dash
    if own:
        fit_height(ax)
    # the loads' names, with their values, need the room beside a tall group
    fill_box(ax)
    if labels:
        clear_bars(ax)
        # the link's names first: the loads' names are then put clear of them
        clear_arrows(ax, NAMED)
        place_loads(ax)
    return ax


def _group(ctx: _Context, group_index: int) -> int:
    """Check ``group_index`` (negative counts from the end); return it from 0."""
    count = len(ctx.plan.groups)
    if integer(group_index) is None:
        msg = f"group_index: expected a group's number, got {describe(group_index)}"
        raise UsageError(msg)
    if not -count <= group_index < count:
        msg = (
            f"group_index: {group_index} is out of range; the mechanism has "
            f"{counted(count, 'Assur group')}; expected 0 to {count - 1}"
        )
        raise UsageError(msg)
    return group_index % count


def _free_body_arrows(table: Table, group_index: int, row: int) -> list[_Arrow]:
    """Return the loads on Assur group ``group_index`` at ``row`` (N, N m).

    External reactions act on the group; internal ones on the pair's second link.
    """
    ctx = _context(table)
    group = ctx.plan.groups[group_index]
    links = [x for x in group.links if "~" not in x]
    bodies = {ctx.plan.body(x) for x in group.links}
    pose = ctx.pose(row)
    return (
        _inertia_arrows(ctx, row, links)
        + _applied_arrows(ctx, pose, row, links, bodies)
        + _pair_arrows(ctx, pose, row, bodies)
    )


def _pair_arrows(
    ctx: _Context, pose: _Pose, row: int, bodies: set[int]
) -> list[_Arrow]:
    """Return the reactions at the pairs of ``bodies``: on the group, or inside it.

    A pair inside the group gives two arrows, equal and opposite, one on each of
    its links (the second named, see :class:`_Arrow`): drawn on one link alone it
    left the group's arrows out of balance.
    """
    plan = ctx.plan
    arrows = []
    for name, pair in plan.pairs.items():
        inside = (pair.first in bodies, pair.second in bodies)
        if not any(inside):
            continue
        if all(inside):
            # named once, on the pair's second link: its other side is that force
            arrows.append(_reaction_arrow(ctx, pose, row, name, 1.0, "internal"))
            arrows.append(_reaction_arrow(ctx, pose, row, name, -1.0, "opposite"))
            continue
        # the force on the group of the link outside it
        sign = 1.0 if inside[1] else -1.0
        arrows.append(_reaction_arrow(ctx, pose, row, name, sign, "reaction"))
    return arrows
