"""Names on a mechanism with its loads: each by its own arrow, joint or arc, clear.

The forces' and couples' names (:mod:`assur.plotting._forces`) and the joints'
(:mod:`assur.plotting._labels`) are put down where first drawn, and noted in
:data:`NAMED` with what they name; :func:`place_loads` then moves them all with
:func:`assur.plotting._placing.place_names`, off the links' bars, guides and
blocks, the arrows and the couples' arcs, and off each other.
"""

from __future__ import annotations

import weakref
from itertools import pairwise
from typing import Any

import numpy as np

from assur.plotting._bars import BAR_WIDTH, root_figure
from assur.plotting._placing import Name, place_names

NAMED: weakref.WeakKeyDictionary[Any, tuple[np.ndarray, np.ndarray, np.ndarray]] = (
    weakref.WeakKeyDictionary()
)
"""What each name drawn names (m): the ends of a segment, a force's tail and tip
(a point twice for a joint's or a couple's name), and a line (k, 2) that the
names keep off besides, a couple's arc (none, (0, 2), for the others).
(Held aside, not as a ``gid``: an SVG writes a gid as an element's id.)"""
SEEN = 6.0
"""Length of a force's arrow, points, below which it is read as a point: its
head is a speck, shorter than its name is high."""


def name_load(text: Any, start: Any, end: Any, line: Any = None) -> None:
    """Note that ``text`` names ``start``-``end`` (m) and keeps off ``line`` (m)."""
    path = np.zeros((0, 2)) if line is None else np.asarray(line, dtype=float)
    NAMED[text] = (np.asarray(start, float), np.asarray(end, float), path)


def place_loads(ax: Any) -> None:
    """Put the loads' and joints' names drawn on ``ax`` each beside its own.

    Joints first, then the forces and couples as drawn. Kept off: every line
    drawn (bars, guides, tracks), the edges of every polygon (plates, slots,
    blocks, bearings) and the arcs of the couples; kept out of: the joints'
    circles and the blocks and bearings.
    """
    texts = [t for t in ax.texts if t in NAMED and t.get_visible() and t.get_text()]
    if not texts:
        return
    names = [_name(ax, t) for t in texts]
    # a joint's name first: it has few places, beside its circle
    names.sort(key=lambda n: n.shuns)
    arcs = [NAMED[t][2] for t in texts]
    lines = _drawn_lines(ax) + [np.array(p) for a in arcs for p in pairwise(a)]
    segments = np.array(lines) if lines else None
    place_names(ax, names, segments, _solid_parts(ax), BAR_WIDTH)


def _name(ax: Any, text: Any) -> Name:
    """Return the name ``text`` to place, with what it names.

    Only a force seen is a rival: a name nearer its arrow is read as its own.
    An arrow shorter than :data:`SEEN` is read as a point, and a couple by its
    letter. A joint's name shuns nothing: the forces at a joint start
    beside it.
    """
    start, end, arc = NAMED[text]
    seen = np.hypot(*np.subtract(*ax.transData.transform([start, end])))
    force = len(arc) == 0 and not np.array_equal(start, end)
    rival = force and seen >= SEEN * root_figure(ax).dpi / 72.0
    joint = len(arc) == 0 and not force
    return Name(text, start, end, rival=bool(rival), shuns=not joint, tip=force)


def _drawn_lines(ax: Any) -> list[np.ndarray]:
    """Return the segments (2, 2) of the lines and polygon edges on ``ax``, m."""
    from matplotlib.patches import Polygon

    paths = [
        np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float)
        for line in ax.lines
        if len(line.get_xdata()) > 1
    ]
    # a polygon's edges, closed round
    paths += [np.vstack([p.get_xy(), p.get_xy()[:1]]) for p in ax.patches
              if isinstance(p, Polygon)]  # fmt: skip
    return [np.array([a, b]) for path in paths for a, b in pairwise(path)]


def _solid_parts(ax: Any) -> list[Any]:
    """Return the joints' circles and the small polygons (blocks, bearings) of ``ax``.

    A polygon smaller than a fiftieth of the view; a plate is larger, and its
    name may sit inside it, clear of its edges.
    """
    from matplotlib.patches import Circle, Polygon

    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    view = (x1 - x0) * (y1 - y0)
    parts: list[Any] = []
    for patch in ax.patches:
        if isinstance(patch, Circle):
            parts.append(patch)
        elif isinstance(patch, Polygon):
            low, high = patch.get_xy().min(axis=0), patch.get_xy().max(axis=0)
            if float(np.prod(high - low)) < view / 50:
                parts.append(patch)
    return parts
