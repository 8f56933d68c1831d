"""The mechanism at one driver position, each Assur group in its own colour.

:func:`draw` is the picture (:func:`_draw_row` also draws each frame of the
animation); :func:`_draw_mechanism` draws any subset of the links, for the
decomposition, the free-body diagrams and the paths of points as well.
"""

from __future__ import annotations

from collections.abc import Sequence, Set
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._style import REACTION_COLOUR
from assur.plotting._arrows import _draw_arrows
from assur.plotting._axes import _frame_axes, _legend, _new_axes
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
    _overview_arrows,
    _scale,
    _scale_text,
)
from assur.plotting._friction import draw_friction_circles, friction_legend
from assur.plotting._geometry import _extent, _public, _shape, _skeleton
from assur.plotting._labels import _label_joints, _label_link
from assur.plotting._linknames import clear_arrows
from assur.plotting._loadnames import NAMED, place_loads
from assur.plotting._parts import _draw_guide, _draw_joint, _draw_link, _draw_pivot
from assur.plotting._style import (
    BALANCING_COLOR,
    FAINT,
    GROUND_COLOR,
    INERTIA_COLOR,
    LOAD_COLOR,
    REACTION_LEGEND,
    literal,
    titled,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from assur.analysis import Table

__all__ = ["draw"]

Joints = dict[str, tuple[np.ndarray, float]]
"""Where each joint is drawn and how opaquely, by the joint's public name."""


def draw(
    table: Table,
    angle: Any = None,
    ax: Axes | None = None,
    forces: bool = False,
    scale: float | None = None,
    labels: bool = True,
    groups: bool = True,
) -> Axes:
    """Draw the mechanism at one driver position of ``table``.

    Binary links are bars, links with three or more points translucent polygons,
    revolute joints circles, frame pivots hatched triangles, sliders blocks on their
    slide lines and slots open slots on their link. Each Assur group has its own
    colour, named in the legend with its class, order and kind.

    Parameters
    ----------
    table : Table
        A kinematics or forces table.
    angle : float or sequence of float, optional
        Driver position, deg (m for a prismatic driver; one value per driver); the
        nearest row is drawn. Default: the first row.
    ax : matplotlib Axes, optional
        Where to draw; a new figure by default.
    forces : bool
        Also draw the inertia loads, joint reactions (by the first link on the
        second) and balancing loads as arrows; needs a forces table.
    scale : float, optional
        Force scale, N per cm of drawing (the drawing is in metres); chosen so the
        largest arrow is about a quarter of the mechanism by default. One that
        draws it over 10 000 times longer than that is refused.
    labels : bool
        Name the joints and links (and give the forces' values).
    groups : bool
        Colour by Assur group with a legend; otherwise one colour.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    UsageError
        When ``forces`` is asked of a kinematics table; when ``angle`` is not a
        driver position, or has the wrong number of values, or for a ``scale``
        that is not a number above 0 or draws the forces far too long.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import assur
    >>> ax = draw(assur.kinematics(assur.catalog.four_bar(), [30.0]))
    >>> ax.get_aspect()
    1.0
    >>> import matplotlib.pyplot as plt
    >>> plt.close(ax.figure)
    """
    if forces:
        _need_forces(table, "draw(forces=True)")
    ctx = _context(table, groups)
    row = _row(table, angle)
    ax = _new_axes(ax)
    _draw_row(ax, ctx, row, forces, scale, labels, groups)
    if labels:
        clear_bars(ax)
    if forces and labels:
        # the link's names first: the loads' names are then put clear of them
        clear_arrows(ax, NAMED)
        place_loads(ax)
    return ax


def _draw_row(
    ax: Any,
    ctx: _Context,
    row: int,
    forces: bool,
    scale: float | None,
    labels: bool,
    groups: bool,
    limits: Sequence[np.ndarray] | None = None,
    legend: bool = True,
) -> list[tuple[str, str]]:
    """Draw row ``row`` of ``ctx`` on ``ax``; return the legend's entries.

    Used by :func:`draw` and, with fixed ``limits`` and the legend left to the
    caller, by :func:`animate`.
    """
    pose = ctx.pose(row)
    bodies = set(range(len(ctx.plan.bodies)))
    seen = _draw_mechanism(ax, ctx, pose, bodies, labels=labels)
    entries = [(text, c) for text, c, _ in ctx.legend] if groups else []
    if forces:
        arrows = _overview_arrows(ctx, pose, row)
        scale = fitted_scale(scale, arrows, ctx.size) or _scale(arrows, ctx.size)
        seen += _draw_arrows(ax, ctx, arrows, scale, "names" if labels else None)
        applied = any(a.kind in ("gravity", "load") for a in arrows)
        entries += [
            (REACTION_LEGEND, REACTION_COLOUR),
            ("inertia force and torque", INERTIA_COLOR),
            *[("gravity, external load", LOAD_COLOR)] * applied,
            ("balancing load", BALANCING_COLOR),
            (_scale_text(arrows, scale), ""),
        ]
        if draw_friction_circles(ax, ctx, pose):
            entries.insert(-1, (friction_legend(ctx), ""))
    _frame_axes(ax, ctx, list(limits) if limits is not None else seen, ctx.size)
    title = f"{titled(ctx.table.mechanism)}, {literal(_position_title(ctx.table, row))}"
    ax.set_title(title, fontsize=10)
    if entries and legend:
        _legend(ax, entries)
    return entries


def _draw_mechanism(
    ax: Any,
    ctx: _Context,
    pose: _Pose,
    full: set[int],
    faint: Set[int] = frozenset(),
    labels: bool = True,
    frame: bool = True,
) -> list[np.ndarray]:
    """Draw the links ``full`` (and ``faint`` ones lightly); return the points covered.

    The frame's pivots and guides are drawn where they hold a link drawn (unless
    ``frame`` is false, as in a free-body diagram).
    """
    drawn = full | faint
    for body in sorted(drawn):
        if body and not ctx.hidden(body):
            _draw_link(ax, ctx, pose, body, _alpha({body}, full))
    if frame:
        _draw_frame_guides(ax, ctx, pose, full, drawn)
    joints = _draw_pairs(ax, ctx, pose, full, drawn, frame)
    if labels:
        busy = [_skeleton(ctx, pose, drawn)]
        _label_joints(ax, ctx, joints, busy)
        # link names keep off the joints and their names, not off their own bars
        busy = [*busy[1:], np.array([j[0] for j in joints.values()])]
        for body in sorted(drawn):
            if body and not ctx.hidden(body):
                _label_link(ax, ctx, pose, body, _alpha({body}, full), busy)
    return _extent(ctx, pose, drawn)


def _alpha(bodies: set[int], full: set[int]) -> float:
    """Opacity of a part of ``bodies``: solid if one of them is drawn in full."""
    return 1.0 if bodies & full else FAINT


def _draw_frame_guides(
    ax: Any, ctx: _Context, pose: _Pose, full: set[int], drawn: set[int]
) -> None:
    """Draw the frame's slide lines that guide a link drawn."""
    for start, end, name in _shape(ctx, pose, 0).guides:
        second = ctx.plan.pairs[name].second
        if second in drawn:
            alpha = _alpha({second}, full)
            no_points = np.zeros((0, 2))
            _draw_guide(ax, ctx, start, end, name, GROUND_COLOR, alpha, no_points)


def _draw_pairs(
    ax: Any,
    ctx: _Context,
    pose: _Pose,
    full: set[int],
    drawn: set[int],
    frame: bool,
) -> Joints:
    """Draw the revolute joints (and bearings) of the links drawn; return the joints.

    Every pair of a link drawn is returned for labelling, a slot's pin and block
    under the slot's name.
    """
    joints: Joints = {}
    for name, pair in ctx.plan.pairs.items():
        ends = {pair.first, pair.second}
        if not (ends - {0}) & drawn:
            continue
        p = pose.at(pair.second, pair.d_second)
        if pair.kind == "R":
            if 0 in ends and frame:
                _draw_pivot(ax, ctx, p, _alpha(ends - {0}, full))
            _draw_joint(ax, ctx, p, _alpha(ends, full))
        key = _public(name)
        if key not in joints or _alpha(ends, full) > joints[key][1]:
            joints[key] = (p, _alpha(ends, full))
    return joints
