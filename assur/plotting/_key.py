"""A plan's key kept off its drawing: moved beside the axes where it would hide arrows.

matplotlib's ``loc="best"`` puts a legend in the place over the fewest artists,
which is still over some when the drawing fills its axes to every corner (a class
III group's force polygon had two of its sides under the key). Such a key goes
beside the axes, where the layout engine makes room for it.
"""

from __future__ import annotations

import itertools
from typing import Any

import numpy as np

from assur.plotting._bars import hidden_length, root_figure, settle_without

__all__ = ["keys_clear"]


def keys_clear(axes: list[Any], texts: list[Any], widen: bool) -> Any:
    """Move each key of ``axes`` that covers a drawn line beside its axes.

    ``texts`` are left out of the layout (the names placed afterwards, see
    :func:`assur.plotting._bars.settle_without`). With ``widen`` (a figure made
    here) the figure grows by the keys moved, so the drawings keep their size.
    Returns the settled renderer, laid out again where a key moved. A figure
    without a layout engine (one the caller made) keeps its keys where they are:
    nothing there makes room for one beside the axes.
    """
    renderer = settle_without(axes[0], texts)
    fig = root_figure(axes[0])
    if fig.get_layout_engine() is None:
        return renderer
    moved = [ax for ax in axes if covers(ax, renderer)]
    if not moved:
        return renderer
    if widen:
        # the keys' widths (inches) and the gap before each (0.02 of its axes)
        extra = sum(
            ax.get_legend().get_window_extent(renderer).width + 0.02 * ax.bbox.width
            for ax in moved
        )
        width, height = fig.get_size_inches()
        fig.set_size_inches(width + extra / fig.dpi, height)
    for ax in moved:
        legend = ax.get_legend()
        legend.set_loc("lower left")
        legend.set_bbox_to_anchor((1.02, 0.0))  # axes coordinates: the foot, right
    return settle_without(axes[0], texts)


def covers(ax: Any, renderer: Any) -> bool:
    """Whether the key of ``ax`` lies over an arrow or a line drawn on it.

    Arrows are read from their points (:func:`assur.plotting._heads.fitted_arrow`),
    lines from their data; both in data coordinates. A key already outside the
    axes covers nothing.
    """
    legend = ax.get_legend()
    if legend is None:
        return False
    box = np.asarray(legend.get_window_extent(renderer).extents)
    drawn = [np.asarray(p.points, float) for p in ax.patches if hasattr(p, "points")]
    drawn += [np.asarray(line.get_xydata(), float) for line in ax.lines]
    to_display = ax.transData.transform
    for points in drawn:
        ends = to_display(points.reshape(-1, 2))
        if len(ends) == 1:  # a dot
            ends = np.concatenate([ends, ends])
        for a, b in itertools.pairwise(ends):
            inside = (box[:2] <= a).all() and (a <= box[2:]).all()
            if inside or hidden_length(box, a, b) > 0.0:
                return True
    return False
