"""Arrows whose heads fit them: a short arrow gets a smaller head.

A head of fixed size (points) on an arrow drawn to a force scale (metres of the
drawing) can be as long as the arrow or longer, which hides its direction. The
arrows here shrink their heads, when drawn, to at most :data:`HEAD_FRACTION` of
their length on the page. matplotlib is imported inside the functions only.
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np

HEAD_FRACTION = 1.0 / 3.0
"""Longest head, as a fraction of its arrow's length on the page."""

HEAD_LENGTH = 0.4
"""Head length of the ``"-|>"`` style, in units of the mutation scale."""


def fitted_arrow(points: Any, head: float, **kw: Any) -> Any:
    """Return a ``"-|>"`` arrow along ``points`` (data coordinates, tail to tip).

    Two points make a straight arrow, more a polyline (an arc); ``head`` is the
    largest mutation scale, points, the one a long arrow gets. ``kw`` go to
    :class:`matplotlib.patches.FancyArrowPatch`.
    """
    return _arrow_class()(np.asarray(points, dtype=float), head, **kw)


def head_scale(length: float, head: float) -> float:
    """Return the mutation scale of an arrow ``length`` pt long, at most ``head``."""
    return min(head, HEAD_FRACTION * length / HEAD_LENGTH)


@functools.cache
def _arrow_class() -> type:
    """Return the arrow class, made on first use (matplotlib is imported here)."""
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.path import Path

    class FittedArrow(FancyArrowPatch):
        """A ``"-|>"`` arrow whose head is at most a fraction of its length."""

        def __init__(self, points: np.ndarray, head: float, **kw: Any) -> None:
            if len(points) == 2:
                super().__init__(
                    tuple(points[0]), tuple(points[1]), shrinkA=0, shrinkB=0, **kw
                )
            else:
                super().__init__(path=Path(points), **kw)
            self.set_arrowstyle("-|>", head_length=HEAD_LENGTH, head_width=0.2)
            self.set_mutation_scale(head)
            self.points = points
            self.head = head

        def length(self, renderer: Any) -> float:
            """Return the arrow's length on the page, points."""
            ends = self.get_transform().transform(self.points)
            pixels = float(np.sum(np.hypot(*np.diff(ends, axis=0).T)))
            return pixels / renderer.points_to_pixels(1.0)

        def draw(self, renderer: Any) -> None:
            length = self.length(renderer)
            if not length > 0.0:
                return  # an arrow of no length has no direction to show
            self.set_mutation_scale(head_scale(length, self.head))
            super().draw(renderer)

    return FittedArrow
