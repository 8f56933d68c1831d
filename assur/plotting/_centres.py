"""The instant centres drawn on the mechanism, for :func:`plans.instant_centres`.

The view stays on the mechanism and the centres near it; a centre far off (a
link that hardly turns has its own beyond the page) is shown at the frame's edge
by an arrow toward it, named with its coordinates. Every name is put where it is
read as its centre's (:func:`place_names`). matplotlib is imported inside the
functions only.
"""

from __future__ import annotations

import itertools
import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._digits import ROUND_OFF
from assur.explain._position import cross, perp
from assur.plotting._drawing import _place
from assur.plotting._heads import fitted_arrow
from assur.plotting._mathtext import centre_symbol
from assur.plotting._placing import Name, place_names

if TYPE_CHECKING:
    from assur.explain._position import Position

FAR = 2.5
"""A centre farther than this many times the mechanism's frame's half-diagonal
from its middle is shown at the edge of the view, not in it."""
MARGIN = 0.08
"""Room round the mechanism and the centres in view, a share of the view's span."""
SAME_RATE = 1e-9
"""Two links whose angular speeds differ by less than this times the fastest link's
turn together: their relative instant centre is at infinity."""
ABSOLUTE = {"marker": "s", "ms": 6, "color": "#d62728"}
RELATIVE = {"marker": "o", "ms": 4, "color": "#1f77b4"}
"""How an absolute centre (a link's about the frame) and a relative one are drawn."""
KENNEDY = {"ls": (0, (4, 3)), "lw": 0.6, "color": "#b3b3b3", "zorder": 0.8,
           "gid": "kennedy"}  # fmt: skip
"""How a Kennedy line is drawn: thin, light, under the links and the centres (its
``gid`` keeps the centres' names from shunning it as they shun the links)."""
APART = 1e-6
"""Two centres nearer than this times the mechanism's size are one point: no line
through them (and two lines whose directions' sine is below it are one line)."""
AT_INFINITY = 1e3
"""A centre at infinity stands, on its Kennedy line, at a point this many times the
mechanism's size from the line's finite centres: far past any view of it."""
SAME_DOT = 0.003
"""Distance between centres, as a fraction of the mechanism's size, within which
their dots fall on one another and one label names them all."""


def draw_centres(pos: Position, ax: Any) -> Any:
    """Draw the mechanism at ``pos`` with its instant centres on ``ax``; return it."""
    from matplotlib.patches import Polygon

    from assur.plotting.mechanism import draw

    ax = draw(pos.table, ax=ax)
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    middle = np.array([x0 + x1, y0 + y1]) / 2
    reach = FAR * 0.5 * float(np.hypot(x1 - x0, y1 - y0))
    every = relative_centres(pos)
    centres = {k: p for k, p in every.items() if p is not None}
    near = {k: p for k, p in centres.items() if np.hypot(*(p - middle)) <= reach}
    far = centres_at_infinity(pos, every)
    _kennedy_lines(ax, centres, _pins(pos), pos.size(), far)
    places: list[tuple[np.ndarray, list[str]]] = []
    for (i, j), p in near.items():
        ax.plot(*p, ls="none", zorder=9, **(RELATIVE if i else ABSOLUTE))
        # one label for centres whose dots overlap; those merely near get their
        # own (a centre 2 % of the size off was named at another's dot)
        _place(places, p, _name(pos, i, j), SAME_DOT * pos.size())
    _frame(ax, [np.array([[x0, y0], [x1, y1]]), *near.values()])
    names = [
        Name(ax.annotate(", ".join(labels), tuple(p), fontsize=7), p, p)
        for p, labels in places
    ]
    for (i, j), p in centres.items():
        if (i, j) not in near:
            names.append(_far_centre(ax, p, _name(pos, i, j), i == 0))
    for (i, j), d in far.items():
        names.append(_infinite_centre(ax, d, _name(pos, i, j), i == 0))
    bars = [
        np.column_stack([line.get_xdata(), line.get_ydata()])
        for line in ax.lines
        if line.get_linestyle() in ("-", "-.", "--")
        and len(line.get_xdata()) > 1
        and line.get_gid() != KENNEDY["gid"]
    ]
    # a plate's edges too (a patch: its corners closed round)
    bars += [np.vstack([p.get_xy(), p.get_xy()[:1]]) for p in ax.patches
             if isinstance(p, Polygon) and p.get_fill()]  # fmt: skip
    lines = [np.array([a, b]) for bar in bars for a, b in itertools.pairwise(bar)]
    place_names(ax, names, np.array(lines) if lines else None, _small_patches(ax))
    _key(ax, bool(near), bool(centres) or bool(far))
    return ax


def _key(ax: Any, centres: bool, lines: bool) -> None:
    """Add to the legend what the squares, dots and dashed lines are."""
    from matplotlib import lines as mlines

    # the markers' styles are plain dicts of keywords, as ax.plot takes them
    Line2D: Any = mlines.Line2D
    legend = ax.get_legend()
    handles = list(legend.legend_handles) if legend is not None else []
    handles += [
        Line2D([], [], ls="none", label="absolute centre: a link about the frame",
               **ABSOLUTE),
        Line2D([], [], ls="none", label="relative centre of two links", **RELATIVE),
    ] * centres  # fmt: skip
    if lines:
        style = {k: v for k, v in KENNEDY.items() if k not in ("zorder", "gid")}
        handles.append(
            Line2D([], [], label="Kennedy: three centres on a line", **style)
        )
    ax.legend(handles=handles, fontsize=8, frameon=False, loc="upper left",
              bbox_to_anchor=(1.02, 1.0))  # fmt: skip


def _name(pos: Position, i: int, j: int) -> str:
    """Return the name of the centre of bodies ``i`` and ``j`` (0: the frame)."""
    return centre_symbol(pos.link(j), pos.link(i) if i else None)


def _pins(pos: Position) -> set[tuple[int, int]]:
    """Return the pairs of bodies joined by a pin: their centre is a primary one."""
    return {
        (min(pair.first, pair.second), max(pair.first, pair.second))
        for pair in pos.plan.pairs.values()
        if pair.kind == "R"
    }


def _kennedy_lines(
    ax: Any,
    centres: dict[tuple[int, int], np.ndarray],
    pins: set[tuple[int, int]],
    size: float,
    directions: dict[tuple[int, int], np.ndarray],
) -> None:
    """Draw the Kennedy lines of every centre that is not a pin, dashed and light.

    Drawn whole, through the centre and the two it is found from: the view,
    set after, cuts those running out of it (a line through a centre at
    infinity runs out of it toward that centre).
    """
    for key in centres:
        if key not in pins:
            for line in kennedy_lines(key, centres, pins, size, directions):
                # from one end of the three points to the other, along the line
                t = (line - line[0]) @ (line[1] - line[0])
                ends = line[[int(np.argmin(t)), int(np.argmax(t))]]
                ax.plot(ends[:, 0], ends[:, 1], **KENNEDY)


def kennedy_lines(
    key: tuple[int, int],
    centres: dict[tuple[int, int], np.ndarray],
    pins: set[tuple[int, int]],
    size: float,
    directions: dict[tuple[int, int], np.ndarray] | None = None,
) -> list[np.ndarray]:
    """Return the (at most two) lines that find the centre of bodies ``key``, m.

    Kennedy's theorem: the centres of bodies j, k and any third body i are on
    one line, so I_jk is where the line of I_ij, I_ik meets another such line.
    Each line is the three points ``[I_ij, I_ik, I_jk]`` (shape (3, 2)); the
    third bodies whose two centres are pins come first, as a textbook finds
    them, then the others. A centre at infinity, with its direction in
    ``directions`` (a sliding pair's: square to the slide), is on the line
    through the other centre parallel to that direction: it stands there at
    :data:`AT_INFINITY` times ``size`` beyond I_jk from that centre. Such a
    line comes after every line of finite centres.
    """
    j, k = key
    p = centres[key]
    far = directions or {}
    tried = []
    for i in {b for pair in (*centres, *far) for b in pair} - {j, k}:
        ij, ik = (min(i, j), max(i, j)), (min(i, k), max(i, k))
        a, b = centres.get(ij), centres.get(ik)
        infinite = (a is None) != (b is None)
        if a is None and b is not None and ij in far:
            a = _beyond(b, p, far[ij], size)
        elif b is None and a is not None and ik in far:
            b = _beyond(a, p, far[ik], size)
        if a is not None and b is not None and np.hypot(*(b - a)) > APART * size:
            score = -(ij in pins) - (ik in pins)
            tried.append((infinite, score, i, np.array([a, b, p])))
    lines: list[np.ndarray] = []
    for *_, line in sorted(tried, key=lambda t: t[:3]):
        if all(abs(cross(_unit(line), _unit(other))) > APART for other in lines):
            lines.append(line)
        if len(lines) == 2:
            break
    return lines


def _beyond(
    finite: np.ndarray, p: np.ndarray, direction: np.ndarray, size: float
) -> np.ndarray:
    """Return where a centre at infinity along ``direction`` stands on its line, m.

    On the line through ``finite`` along ``direction``, on the side of ``p``
    (the centre the line finds), so that the line runs from ``finite`` through
    ``p`` on to the centre at infinity.
    """
    sense = -1.0 if float(direction @ (p - finite)) < 0.0 else 1.0
    return finite + sense * AT_INFINITY * size * direction


def _unit(line: np.ndarray) -> np.ndarray:
    """Return the unit direction of ``line`` from its first point to its second."""
    return (line[1] - line[0]) / np.hypot(*(line[1] - line[0]))


def _frame(ax: Any, points: list[np.ndarray]) -> None:
    """Set the limits of ``ax`` round ``points`` (m), with :data:`MARGIN` to spare."""
    pts = np.vstack([np.reshape(p, (-1, 2)) for p in points])
    low, high = pts.min(axis=0), pts.max(axis=0)
    pad = MARGIN * float(max(high - low))
    ax.set_xlim(low[0] - pad, high[0] + pad)
    ax.set_ylim(low[1] - pad, high[1] + pad)


def _far_centre(ax: Any, p: np.ndarray, label: str, absolute: bool) -> Name:
    """Draw an arrow at the frame's edge toward the far centre ``p``; return its name.

    The arrow points from the middle of the view toward ``p``; its name gives
    ``p``'s coordinates, m.
    """
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    middle = np.array([x0 + x1, y0 + y1]) / 2
    u = (p - middle) / float(np.hypot(*(p - middle)))
    # a coordinate of round-off beside the centre's distance from the origin is 0:
    # the four-bar's coupler centre at 90 deg was named "(3.47e-18, 1.41) m"
    x, y = np.where(np.abs(p) < ROUND_OFF * float(np.hypot(*p)), 0.0, p) + 0.0
    return _edge_arrow(ax, u, f"{label} ({x:.3g}, {y:.3g}) m", absolute)


def _infinite_centre(ax: Any, d: np.ndarray, label: str, absolute: bool) -> Name:
    """Draw an arrow at the frame's edge toward a centre at infinity; return its name.

    ``d`` is its direction (a slider's centre, a translating link's). The name
    says it is at infinity, with the direction's angle (deg, within a half turn:
    the centre is as far one way as the other).
    """
    # rounded first, and the arrow drawn along the angle named: a direction a hair
    # below the axis is 0°, not 180° (or 180° drawn to the left)
    angle = round(math.degrees(math.atan2(d[1], d[0])), 1) % 180.0 + 0.0
    u = np.array([math.cos(math.radians(angle)), math.sin(math.radians(angle))])
    return _edge_arrow(ax, u, f"{label} at infinity, {angle:g}°", absolute)


def _edge_arrow(ax: Any, u: np.ndarray, text: str, absolute: bool) -> Name:
    """Draw an arrow at the frame's edge along the unit vector ``u``, named ``text``."""
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    middle = np.array([x0 + x1, y0 + y1]) / 2
    half = 0.96 * np.array([x1 - x0, y1 - y0]) / 2
    with np.errstate(divide="ignore"):
        reach = float(np.min(half / np.abs(u)))
    tip = middle + reach * u
    tail = tip - 0.07 * float(max(half)) * u
    style = ABSOLUTE if absolute else RELATIVE
    ax.add_patch(fitted_arrow([tail, tip], 9.0, color=style["color"], lw=1.2,
                              zorder=9))  # fmt: skip
    ax.plot(*tail, ls="none", zorder=9, mfc="white", **style)
    name = ax.annotate(text, tuple(tail), fontsize=7, color=style["color"])
    return Name(name, tail, tail)


def _small_patches(ax: Any) -> list[Any]:
    """Return what the names keep clear of: small patches, the centres' markers.

    A patch smaller than a fiftieth of the view: a joint's circle, a block.
    """
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    view = (x1 - x0) * (y1 - y0)
    small = []
    for patch in ax.patches:
        box = patch.get_extents().transformed(ax.transData.inverted())
        if box.width * box.height < view / 50:
            small.append(patch)
    return small + [line for line in ax.lines if line.get_zorder() == 9]


def centres_at_infinity(
    pos: Position, centres: dict[tuple[int, int], np.ndarray | None]
) -> dict[tuple[int, int], np.ndarray]:
    """Return the direction of each centre at infinity of ``centres``, a unit vector.

    ``centres`` is :func:`relative_centres`'s. A sliding pair's relative centre
    is at infinity square to its slide; two links turning at the same rate have
    theirs square to their relative velocity (none where that is round-off
    too: the two move together, and their centre is anywhere).
    """
    slides = {
        (min(pair.first, pair.second), max(pair.first, pair.second)): perp(
            pos.turned(pair.first, pair.axis)
        )
        for pair in pos.plan.pairs.values()
        if pair.kind != "R" and pair.axis is not None
    }
    out: dict[tuple[int, int], np.ndarray] = {}
    for (i, j), p in centres.items():
        if p is not None:
            continue
        d = slides.get((i, j))
        if d is None:
            o = pos.origin(j)
            d = perp(pos.coincident(j, o, 1) - pos.coincident(i, o, 1))
            if not np.hypot(*d) > SAME_RATE * pos.rate_scale(1):
                continue
        out[(i, j)] = d / np.hypot(*d)
    return out


def relative_centres(pos: Position) -> dict[tuple[int, int], np.ndarray | None]:
    """Return the instant centre of every two bodies (0: the frame), m.

    The primary centres first: the pin of a revolute pair, and at infinity (None)
    for a sliding pair. Every other is the point where both bodies' velocities are
    equal; None where they turn at the same rate (to :data:`SAME_RATE` of the
    fastest link's speed: two links that both translate, say).
    """
    out: dict[tuple[int, int], np.ndarray | None] = {}
    count = len(pos.plan.bodies)
    for pair in pos.plan.pairs.values():
        i, j = sorted((pair.first, pair.second))
        if "~" not in pos.link(i) + pos.link(j):
            out[(i, j)] = pos.pair_point(pair) if pair.kind == "R" else None
    fastest = max(abs(pos.omega(b)) for b in range(count))
    for i in range(count):
        for j in range(i + 1, count):
            if "~" in pos.link(i) + pos.link(j) or (i, j) in out:
                continue
            wi, wj = pos.omega(i), pos.omega(j)
            if not abs(wi - wj) > SAME_RATE * fastest:
                out[(i, j)] = None
                continue
            oi, oj = pos.origin(i), pos.origin(j)
            # v_oi + wi perp(P - oi) = v_oj + wj perp(P - oj)
            vi = pos.coincident(i, oi, 1)
            vj = pos.coincident(j, oj, 1)
            rhs = vj - vi - wj * perp(oj) + wi * perp(oi)
            q = rhs / (wi - wj)  # = perp(P)
            out[(i, j)] = np.array([q[1], -q[0]])
    return out
