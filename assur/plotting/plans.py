"""Plans drawn as a student draws them, from the solved values (so they are exact).

The velocity plan (pole ``p``, every point's image), the acceleration plan (normal,
tangential, Coriolis and relative parts as separate arrows, along the chains of the
note), the force polygon of every group, Zhukovsky's lever (the velocity plan turned
by 90 degrees with every force at its image point, every couple as a pair of forces
at two joints' images, each load's share of the balancing load listed) and the
instant centres on the mechanism. Each plan states its scale as a student does: so
many units per mm of the drawing. matplotlib is imported inside the functions only.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING, Any

import numpy as np

from assur.explain._position import Position, from_table, perp
from assur.explain._rates import _sides
from assur.explain._tex import name as tex_name
from assur.groups._dyad import DyadSolver
from assur.plotting._centres import draw_centres, relative_centres
from assur.plotting._drawing import (
    _arrow,
    _arrow_apart,
    _axes,
    _images_plot,
    _legend,
)
from assur.plotting._geometry import _nice
from assur.plotting._key import keys_clear
from assur.plotting._mathtext import _symbol
from assur.plotting._numbers import number, quantity
from assur.plotting._placing import Name, place_names
from assur.plotting._style import (
    titled,
)

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from assur.table import Table

__all__ = [
    "acceleration_plan",
    "images",
    "instant_centres",
    "relative_centres",
    "velocity_plan",
]

PLAN_SIZE = 80.0
"""Length of the longest vector of a plan, mm of the drawing (about)."""
IMAGE_NAMES: weakref.WeakSet[Any] = weakref.WeakSet()
"""The images' names on the velocity and acceleration plans, which
:func:`_name_images` places. (Held aside, not as a ``gid``: an SVG writes a gid as
an element's id, which must be unique in a page.)"""


def images(pos: Position, k: int) -> dict[str, np.ndarray]:
    """Return the image of every named point on the plan of level ``k`` (1 or 2).

    The image of point P is its velocity (m/s) or acceleration (m/s^2) drawn from
    the pole; the names are the table's (joints, extra points, ``L.G``).
    """
    plan = pos.plan
    out: dict[str, np.ndarray] = {}
    for name, body, offset in zip(
        plan.points, plan.point_body, plan.point_offset, strict=True
    ):
        if "~" not in name:
            out[name] = pos.point(body, offset, k)
    return out


def _scale(vectors: list[np.ndarray]) -> float:
    """Return a plan's scale, units per mm: a round number, longest about 80 mm."""
    big = max((float(np.hypot(*v)) for v in vectors), default=0.0)
    return _nice(big / PLAN_SIZE) if big > 0 else 1.0


def _chains(
    ax: Any, pos: Position, k: int, mu: float, shown: list[np.ndarray]
) -> list[tuple[str, str]]:
    """Draw each dyad's vector equation as arrows tip to tail; return the legend.

    A chain starts at a point's image (``shown``); one that starts from the motion
    of a guide's point under a slider, which is no named point, starts with that
    motion drawn from the pole.
    """
    legend: list[tuple[str, str]] = []
    kinds: dict[str, str] = {}
    palette = {"base": "#555555", "n": "#1f77b4", "t": "#d62728", "k": "#9467bd",
               "r": "#2ca02c", "v": "#d62728"}  # fmt: skip
    size = max((float(np.hypot(*v)) for v in shown), default=0.0)
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    if k == 2:
        _crank_parts(ax, pos, mu, palette, kinds)
    for s in pos.plan.solvers:
        if not isinstance(s, DyadSolver):
            # a triad's equations are solved together: its links' rigid-body
            # relations are drawn, the triangles a student checks
            for a, b, part in _rigid_parts(pos, s.bodies, k, mu):
                if _arrow_apart(ax, drawn, a, b, palette[part], lw=1.8):
                    kinds[part] = palette[part]
            continue
        for side in _sides(pos, s, k)[:2]:
            tip = np.zeros(2)
            for i, term in enumerate(side):
                part = "base" if i == 0 and term.unknown is None else _part(term.tex)
                color = palette.get(part, "#555555")
                end = tip + term.value / mu
                if i and part in "rk" and _part(side[i - 1].tex) not in "rk":
                    # the tip before the slide is the guide's point under the slider
                    _name_guide_point(ax, pos, s, tip, mu, shown)
                if part != "base":
                    # the legend names the parts drawn: a Coriolis term of nothing
                    # (a slider on a guide that does not turn) is not
                    if _arrow_apart(ax, drawn, tip, end, color, lw=1.8):
                        kinds[part] = color
                elif not any(np.hypot(*(term.value - v)) <= 1e-9 * size for v in shown):
                    _arrow(ax, tip, end, color, lw=1.8)
                    ax.annotate(_symbol(term.tex), end, fontsize=8, color=color)
                    kinds["base"] = color
                tip = end
    names = {"n": "normal", "t": "tangential", "k": "Coriolis", "r": "relative",
             "v": "relative (rotation)",
             "base": "the guide's point under the slider"}  # fmt: skip
    for part, color in kinds.items():
        legend.append((names.get(part, part), color))
    return legend


def _rigid_parts(
    pos: Position, bodies: tuple[int, ...], k: int, mu: float
) -> list[tuple[np.ndarray, np.ndarray, str]]:
    """Return each link's relative motion of its pins, as arrows (mm) and parts.

    From the image of a link's pin to the group's known links (its first pin
    else) to that of each other pin: the relative velocity ``omega x PQ`` ("v"),
    or the relative acceleration's normal part ``-omega^2 PQ`` ("n") then its
    tangential part ``epsilon x PQ`` ("t"), which ends at the other pin's image.
    """
    out: list[tuple[np.ndarray, np.ndarray, str]] = []
    for b in bodies:
        pins: dict[str, tuple[float, float]] = {}
        known: dict[str, tuple[float, float]] = {}
        for pair in pos.pairs_of(b):
            if pair.kind == "R":
                offset = pair.d_first if pair.first == b else pair.d_second
                other = pair.second if pair.first == b else pair.first
                pins.setdefault(pair.name.split("~")[0], offset)
                if other not in bodies:
                    known.setdefault(pair.name.split("~")[0], offset)
        offsets = list((known | pins).values())
        if len(offsets) < 2:
            continue
        base = offsets[0]
        start = pos.point(b, base, k) / mu
        for offset in offsets[1:]:
            end = pos.point(b, offset, k) / mu
            if k == 1:
                out.append((start, end, "v"))
                continue
            # the relative acceleration: -w^2 r along the link, then eps x r
            r = pos.point(b, offset) - pos.point(b, base)
            middle = start - pos.omega(b) ** 2 * r / mu
            out += [(start, middle, "n"), (middle, end, "t")]
    return out


def _crank_parts(
    ax: Any, pos: Position, mu: float, palette: dict[str, str], kinds: dict[str, str]
) -> None:
    """Draw the acceleration of each point of an accelerating crank in two parts.

    The normal part ``-omega^2 r`` toward the pivot, then the tangential one
    ``epsilon x r``, ending at the point's image (a crank at constant speed has
    the normal part alone, its image).
    """
    plan = pos.plan
    for d in plan.drivers:
        eps = pos.epsilon(d.body)
        # a crank on the frame: its pivot stands still
        if d.kind != "R" or not eps or 0 not in (d.pair.first, d.pair.second):
            continue
        pivot, w = pos.pair_point(d.pair), pos.omega(d.body)
        # the crank's own points, and its joints (kept on the links they join)
        places = [
            pos.point(body, offset)
            for name, body, offset in zip(
                plan.points, plan.point_body, plan.point_offset, strict=True
            )
            if body == d.body and "~" not in name
        ]
        places += [
            pos.pair_point(p)
            for p in plan.pairs.values()
            if d.body in (p.first, p.second) and "~" not in p.name
        ]
        for r in {tuple(place - pivot) for place in places}:
            if not any(r):
                continue
            normal, tangential = -w * w * np.array(r), eps * perp(np.array(r))
            if _arrow(ax, np.zeros(2), normal / mu, palette["n"], lw=1.8):
                kinds["n"] = palette["n"]
            if _arrow(
                ax, normal / mu, (normal + tangential) / mu, palette["t"], lw=1.8
            ):
                kinds["t"] = palette["t"]


def _name_guide_point(
    ax: Any, pos: Position, s: DyadSolver, tip: np.ndarray, mu: float, shown: list
) -> None:
    """Name the image ``tip`` (mm) of the guide's point under the middle slider.

    Not where a named image is already (a guide's point that is a joint).
    """
    size = max((float(np.hypot(*v)) for v in shown), default=0.0)
    if any(np.hypot(*(tip * mu - v)) <= 1e-9 * size for v in shown):
        return
    guide = tex_name(pos.link(s.mid.first))
    label = _symbol(f"{tex_name(s.mid.name.lower())}_{{{guide}}}")
    ax.plot(*tip, "o", ms=3.5, color="#333333")
    text = ax.annotate(
        label, tip, xytext=(4, 4), textcoords="offset points", fontsize=8
    )
    IMAGE_NAMES.add(text)  # _name_images places it with the images' names


def _part(tex: str) -> str:
    """Return which part a term is: n, t, k (Coriolis), r (relative) or v."""
    for part in ("n", "t", "k", "r"):
        if f"^{{{part}}}" in tex:
            return part
    return "v"


def _title(pos: Position, what: str) -> str:
    """Return a plan's title: the mechanism, the plan and the driver position."""
    angle = ", ".join(number(float(x), 6) for x in pos.table.given[0])
    unit = "°" if pos.plan.drivers[0].kind == "R" else " m"
    return f"{titled(pos.mechanism)}: {what} at {angle}{unit}"


def velocity_plan(table: Table, angle: Any = None, ax: Axes | None = None) -> Axes:
    """Draw the velocity plan at one driver position.

    Parameters
    ----------
    table : Table
        A kinematics or forces table (a forces table for the polygons and lever).
    angle : float or sequence of float, optional
        Driver position, deg (m for a prismatic driver): the nearest row (default
        the first).
    ax : matplotlib Axes, optional

    Returns
    -------
    matplotlib.axes.Axes
    """
    return _plan(table, angle, ax, 1)


def acceleration_plan(table: Table, angle: Any = None, ax: Axes | None = None) -> Axes:
    """Draw the acceleration plan: images, and each dyad's parts as arrows.

    Parameters and Returns are those of :func:`velocity_plan`.
    """
    return _plan(table, angle, ax, 2)


PLANS = {
    1: ("velocity plan", "μv", "(m/s)/mm"),
    2: ("acceleration plan", "μa", "(m/s²)/mm"),
}
"""Per level: the plan's name, its scale's symbol and the scale's unit."""


def _plan(table: Table, angle: Any, ax: Any, level: int) -> Any:
    """Draw the velocity (``level`` 1) or acceleration (2) plan; return the axes."""
    what, symbol, unit = PLANS[level]
    pos = _pos(table, angle)
    found = images(pos, level)
    mu = _scale(list(found.values()))
    own = ax is None  # a figure made here may grow by its key
    ax = _axes(ax, _title(pos, what))
    IMAGE_NAMES.update(_images_plot(ax, found, mu, "#333333"))
    legend = _chains(ax, pos, level, mu, list(found.values()))
    _legend(ax, legend, f"scale: {symbol} = {quantity(mu, unit, 6)}")
    _name_images(ax, own)
    return ax


def _name_images(ax: Any, widen: bool) -> None:
    """Put each image's name by its own image, off the arrows, dots and other names.

    Images close together (a link nearly still has its points' images by the
    pole) had their names pushed apart only until their boxes touched, over the
    arrows and the dots beside them. A key over the arrows is moved beside the
    axes first, the figure grown by it with ``widen`` (see
    :func:`assur.plotting._key.keys_clear`).
    """
    texts = [t for t in ax.texts if t in IMAGE_NAMES and t.get_text()]
    names = [Name(t, np.asarray(t.xy, float), np.asarray(t.xy, float)) for t in texts]
    arrows = [np.asarray(p.points, float) for p in ax.patches if hasattr(p, "points")]
    dots = [line for line in ax.lines if line.get_marker() == "o"]
    # a key over the arrows goes beside the plan (in the layout the names are put in)
    renderer = keys_clear([ax], [n.text for n in names], widen)
    place_names(
        ax, names, np.array(arrows) if arrows else None, dots, renderer=renderer
    )


def instant_centres(table: Table, angle: Any = None, ax: Axes | None = None) -> Axes:
    """Draw the mechanism with its instant centres: absolute and relative (Kennedy).

    The absolute centre of a link is where its velocity is zero; the relative centre
    of two links is their common point of equal velocity. Each centre not at a pin
    is on lines through two other centres (Kennedy's theorem: the centres of any
    three links are on one line); the two lines that find it, from the pins first,
    are drawn thin and dashed. A centre at infinity (a sliding pair's, square to
    the slide) is on the line through the other centre in its direction: where
    the finite centres give fewer than two lines, such a line is drawn from that
    centre on out of the view. The names are :math:`I_{crank}` (absolute) and
    :math:`I_{crank,coupler}` (relative), as the forces are named. The view
    stays on the mechanism: a centre far from it is shown by an arrow at the
    frame's edge pointing toward it, named with its coordinates.

    Returns
    -------
    matplotlib.axes.Axes
    """
    pos = _pos(table, angle)
    ax = draw_centres(pos, ax)
    ax.set_title(_title(pos, "instant centres"), fontsize=10)
    return ax


def _pos(table: Table, angle: Any) -> Position:
    """Return the solved mechanism at the row of ``table`` nearest to ``angle``."""
    from assur.plotting._context import _row, whole

    whole(table, "the plans")
    return from_table(table, _row(table, angle))
