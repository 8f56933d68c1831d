"""Pictures of a mechanism and of its results, drawn with matplotlib.

The mechanism at one driver position (each Assur group in its own colour, forces as
arrows to a stated scale), its decomposition step by step, the free-body diagram of a
group, diagrams over a sweep and an animated GIF. matplotlib is imported inside the
functions only, so ``import assur`` stays free of it.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur.errors import ModelError

if TYPE_CHECKING:
    from assur.analysis import Table
    from assur.plan import Plan

__all__ = [
    "animate",
    "draw",
    "draw_decomposition",
    "draw_free_body",
    "plot_hodographs",
    "plot_motion",
    "plot_paths",
    "plot_shaking",
    "plot_torque",
]

GROUP_COLORS = (
    "#1f77b4",
    "#2ca02c",
    "#ff7f0e",
    "#17becf",
    "#8c564b",
    "#bcbd22",
    "#e377c2",
    "#7f7f7f",
)
"""Colours of the Assur groups, in order of attachment (cycled)."""
DRIVER_COLOR = "#6a3d9a"
GROUND_COLOR = "#333333"
PLAIN_COLOR = "#4d4d4d"
REACTION_COLOR = "#d62728"
INERTIA_COLOR = "#111111"
LOAD_COLOR = "#00838f"
FAINT = 0.22
"""Opacity of the links drawn only for orientation."""
ARROW_LENGTH = 0.28
"""Length of the largest force arrow at the default scale, relative to the mechanism."""
ROMAN = {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V", 6: "VI", 7: "VII", 8: "VIII"}
LINK_UNITS = {"angle": "deg", "omega": "rad/s", "alpha": "rad/s²", "jerk": "rad/s³"}
POINT_PARTS = {"x": ("x", "y"), "v": ("vx", "vy"), "a": ("ax", "ay"), "j": ("jx", "jy")}
POINT_UNITS = {
    "x": "m",
    "y": "m",
    "s": "m",
    "v": "m/s",
    "vx": "m/s",
    "vy": "m/s",
    "a": "m/s²",
    "ax": "m/s²",
    "ay": "m/s²",
    "j": "m/s³",
    "jx": "m/s³",
    "jy": "m/s³",
}


# ---------------------------------------------------------------- geometry at a row


@dataclass(frozen=True)
class _Pose:
    """Every link's placement at one row of a table."""

    plan: Plan
    phi: np.ndarray
    origin: np.ndarray

    def turn(self, body: int, v: Any) -> np.ndarray:
        """Vector ``v`` fixed in ``body``, in the fixed frame."""
        c, s = math.cos(self.phi[body]), math.sin(self.phi[body])
        return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])

    def at(self, body: int, offset: Any) -> np.ndarray:
        """Point of ``body`` at body-fixed ``offset`` from its origin, m."""
        return self.origin[body] + self.turn(body, offset)


@dataclass(frozen=True)
class _Context:
    """What every picture of one table needs: plan, colours, symbol sizes, travel."""

    table: Table
    plan: Plan
    color: dict[int, str]
    legend: list[tuple[str, str, tuple[int, ...]]]
    travel: dict[str, tuple[float, float]]
    size: float
    centroid: np.ndarray

    @property
    def r(self) -> float:
        """Radius of a revolute joint's circle, m."""
        return 0.012 * self.size

    def pose(self, row: int) -> _Pose:
        """Return the links' placement at ``row``."""
        state = self.table.state
        return _Pose(self.plan, state.link[0, row], state.origin[0, row])

    def hidden(self, body: int) -> bool:
        """Whether ``body`` is a virtual block standing for a slot."""
        return "~" in self.plan.bodies[body]


def _context(table: Table, groups: bool = True) -> _Context:
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    color: dict[int, str] = {0: GROUND_COLOR}
    legend = []
    for d in plan.drivers:
        color[d.body] = DRIVER_COLOR if groups else PLAIN_COLOR
        legend.append(
            (f"I, driver (ground, {plan.bodies[d.body]})", color[d.body], (d.body,))
        )
    for k, g in enumerate(plan.groups):
        c = GROUP_COLORS[k % len(GROUP_COLORS)] if groups else PLAIN_COLOR
        bodies = tuple(plan.body(x) for x in g.links)
        for b in bodies:
            color[b] = c
        legend.append(
            (
                f"{ROMAN.get(g.group_class, g.group_class)}, order {g.order}, "
                f"{g.label}",
                c,
                bodies,
            )
        )
    travel = {
        name: (float(np.nanmin(s[0])), float(np.nanmax(s[0])))
        for name, s in table.state.slide.items()
    }
    pts = np.array([p.d_second + plan.origins[p.second] for p in plan.pairs.values()])
    # symbols scale with the picture: the region swept by the points
    swept = table.state.point[0].reshape(-1, 2)
    swept = swept[np.isfinite(swept).all(axis=1)]
    size = max(plan.scale, float(np.ptp(swept, axis=0).max()) if len(swept) else 0.0)
    return _Context(table, plan, color, legend, travel, size, pts.mean(axis=0))


def _row(table: Table, angle: Any) -> int:
    """Index of the row nearest to driver position ``angle`` (deg, or m)."""
    if len(table) == 0:
        msg = "table: no rows to draw; expected at least one driver position"
        raise ModelError(msg)
    if angle is None:
        return 0
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    want = np.atleast_1d(np.asarray(angle, dtype=float))
    drive = table.state.drive
    if want.shape[0] not in (1, drive.shape[1]):
        msg = (
            f"angle: {want.shape[0]} values for {drive.shape[1]} driver(s); expected "
            "one position per driver"
        )
        raise ModelError(msg)
    gap = np.zeros(drive.shape[0])
    for i in range(want.shape[0]):
        if plan.drivers[i].kind == "R":
            diff = np.degrees(drive[:, i]) - want[i]
            gap += ((diff + 180.0) % 360.0 - 180.0) ** 2
        else:
            gap += (drive[:, i] - want[i]) ** 2
    return int(np.argmin(gap))


def _position_text(table: Table, row: int) -> str:
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    drive = table.state.drive[row]
    parts = [
        f"φ = {math.degrees(x):.1f}°" if d.kind == "R" else f"s = {x:.4g} m"
        for d, x in zip(plan.drivers, drive, strict=True)
    ]
    if len(parts) > 1:
        parts = [
            f"{d.pair.name}: {p}" for d, p in zip(plan.drivers, parts, strict=True)
        ]
    return ", ".join(parts)


def _hull(points: np.ndarray) -> np.ndarray:
    """Convex hull of a few points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(map(tuple, points))
    if len(pts) < 3:
        return np.array(pts)

    def half(seq: Iterable[tuple[float, float]]) -> list[tuple[float, float]]:
        out: list[tuple[float, float]] = []
        for p in seq:
            while (
                len(out) >= 2
                and (
                    (out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                    - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])
                )
                <= 0
            ):
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(reversed(pts))
    return np.array(lower[:-1] + upper[:-1])


def _distinct(points: list[np.ndarray], tol: float) -> list[np.ndarray]:
    out: list[np.ndarray] = []
    for p in points:
        if all(np.hypot(*(p - q)) > tol for q in out):
            out.append(p)
    return out


@dataclass
class _Shape:
    """What one link looks like at a pose: its points, guides and sliding blocks."""

    points: list[np.ndarray]
    guides: list[tuple[np.ndarray, np.ndarray, str]]
    blocks: list[tuple[np.ndarray, np.ndarray]]


def _shape(ctx: _Context, pose: _Pose, body: int) -> _Shape:
    plan = ctx.plan
    shape = _Shape([], [], [])
    pad = 0.05 * ctx.size
    for pair in plan.pairs.values():
        if body not in (pair.first, pair.second):
            continue
        if pair.kind == "R":
            d = pair.d_first if body == pair.first else pair.d_second
            shape.points.append(pose.at(body, d))
            continue
        e = pose.turn(pair.first, pair.axis)
        if body == pair.second and not ctx.hidden(body):
            centre = pose.at(body, pair.d_second)
            shape.points.append(centre)
            shape.blocks.append((centre, e))
        if body == pair.first:
            base = pose.at(body, pair.d_first)
            low, high = ctx.travel.get(pair.name, (0.0, 0.0))
            shape.guides.append(
                (base + (low - pad) * e, base + (high + pad) * e, pair.name)
            )
    for k, name in enumerate(plan.points):
        if (
            plan.point_body[k] == body
            and not name.endswith(".G")
            and name not in plan.pairs
        ):
            shape.points.append(pose.at(body, plan.point_offset[k]))
    shape.points = _distinct(shape.points, 1e-6 * ctx.size)
    return shape


# ------------------------------------------------------------------ drawing pieces


def _bar(
    ax: Any, a: np.ndarray, b: np.ndarray, color: str, alpha: float, width: float = 5.0
) -> None:
    ax.plot(
        [a[0], b[0]],
        [a[1], b[1]],
        color=color,
        lw=width,
        alpha=alpha,
        solid_capstyle="round",
        zorder=2,
    )


def _draw_link(ax: Any, ctx: _Context, pose: _Pose, body: int, alpha: float) -> None:
    from matplotlib.patches import Polygon

    color = ctx.color[body]
    shape = _shape(ctx, pose, body)
    pts = np.array(shape.points).reshape(-1, 2)
    if len(pts) >= 3:
        hull = _hull(pts)
        area = 0.5 * abs(
            np.dot(hull[:, 0], np.roll(hull[:, 1], 1))
            - np.dot(hull[:, 1], np.roll(hull[:, 0], 1))
        )
        if area > 1e-4 * ctx.size**2:
            ax.add_patch(
                Polygon(
                    hull,
                    closed=True,
                    facecolor=color,
                    alpha=0.28 * alpha,
                    edgecolor="none",
                    zorder=1.5,
                )
            )
            ax.add_patch(
                Polygon(
                    hull,
                    closed=True,
                    fill=False,
                    edgecolor=color,
                    lw=2.5,
                    alpha=alpha,
                    joinstyle="round",
                    zorder=2,
                )
            )
        else:
            far = max(
                ((p, q) for p in pts for q in pts),
                key=lambda pq: np.hypot(*(pq[0] - pq[1])),
            )
            _bar(ax, far[0], far[1], color, alpha)
    elif len(pts) == 2:
        _bar(ax, pts[0], pts[1], color, alpha)
    for start, end, name in shape.guides:
        _draw_guide(ax, ctx, start, end, name, color, alpha, pts)
    for centre, e in shape.blocks:
        _draw_block(ax, ctx, centre, e, color, alpha)


def _draw_guide(
    ax: Any,
    ctx: _Context,
    start: np.ndarray,
    end: np.ndarray,
    name: str,
    color: str,
    alpha: float,
    points: np.ndarray,
) -> None:
    """Draw a slide line on its link: a bar, a slot, or on the frame a track."""
    from matplotlib.patches import Polygon

    e = (end - start) / max(np.hypot(*(end - start)), 1e-12)
    n = np.array([-e[1], e[0]])
    if ctx.plan.pairs[name].first == 0 and name not in ctx.plan.topology.slots:
        ax.plot(
            *np.transpose([start, end]),
            color=GROUND_COLOR,
            lw=0.8,
            ls="-.",
            alpha=alpha,
            zorder=1,
        )
        side = -1.0 if np.dot(n, ctx.centroid - start) > 0 else 1.0
        shift = side * n * 0.024 * ctx.size
        _hatched_line(ax, ctx, start + shift, end + shift, side * n, alpha)
        return
    if len(points):
        # tie the slide line to the rest of its link at the nearest point
        proj = [
            (start + np.clip(np.dot(p - start, e), 0, np.hypot(*(end - start))) * e, p)
            for p in points
        ]
        foot, p = min(proj, key=lambda fp: np.hypot(*(fp[0] - fp[1])))
        if np.hypot(*(foot - p)) > 1e-6 * ctx.size:
            _bar(ax, foot, p, color, alpha)
    if name in ctx.plan.topology.slots:
        w = 1.25 * ctx.r
        _bar(ax, start, end, color, alpha, width=9.0)
        t = np.linspace(-0.5 * math.pi, 0.5 * math.pi, 12)
        cap = np.outer(np.cos(t), e) + np.outer(np.sin(t), n)
        outline = np.vstack([end + w * cap, start - w * cap])
        ax.add_patch(
            Polygon(
                outline,
                closed=True,
                facecolor="white",
                edgecolor=color,
                lw=1.4,
                alpha=alpha,
                zorder=2.5,
            )
        )
    else:
        _bar(ax, start, end, color, alpha)


def _hatched_line(
    ax: Any, ctx: _Context, a: np.ndarray, b: np.ndarray, away: np.ndarray, alpha: float
) -> None:
    """Draw the frame's surface from ``a`` to ``b``, hatched on the ``away`` side."""
    from matplotlib.collections import LineCollection

    ax.plot(*np.transpose([a, b]), color=GROUND_COLOR, lw=1.6, alpha=alpha, zorder=1.2)
    length = np.hypot(*(b - a))
    e = (b - a) / max(length, 1e-12)
    step = 0.022 * ctx.size
    count = max(2, int(length / step))
    starts = a + np.outer(np.linspace(0.0, 1.0, count + 1)[1:], b - a)
    tips = starts + (away - e) * 0.6 * step
    ax.add_collection(
        LineCollection(
            np.stack([starts, tips], axis=1),
            colors=GROUND_COLOR,
            linewidths=0.8,
            alpha=alpha,
            zorder=1.2,
        )
    )


def _draw_block(
    ax: Any, ctx: _Context, centre: np.ndarray, e: np.ndarray, color: str, alpha: float
) -> None:
    from matplotlib.patches import Polygon

    n = np.array([-e[1], e[0]])
    half_l, half_h = 0.05 * ctx.size, 0.024 * ctx.size
    corners = [
        centre + sl * half_l * e + sh * half_h * n
        for sl, sh in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    ax.add_patch(
        Polygon(
            corners,
            closed=True,
            facecolor=_light(color),
            edgecolor=color,
            lw=1.8,
            alpha=alpha,
            zorder=3,
        )
    )


def _light(color: str) -> tuple[float, ...]:
    from matplotlib.colors import to_rgb

    return tuple(0.35 * c + 0.65 for c in to_rgb(color))


def _draw_pivot(ax: Any, ctx: _Context, p: np.ndarray, alpha: float) -> None:
    """Draw the frame's bearing at ``p``: a triangle, its base and hatching."""
    from matplotlib.patches import Polygon

    away = p - ctx.centroid
    # a bearing stands on the floor, unless it sits clearly above the mechanism
    down = np.array([0.0, 1.0 if away[1] > 0.5 * abs(away[0]) else -1.0])
    side = np.array([-down[1], down[0]])
    h = 0.042 * ctx.size
    tri = [p, p + h * down + 0.6 * h * side, p + h * down - 0.6 * h * side]
    ax.add_patch(
        Polygon(
            tri,
            closed=True,
            facecolor="white",
            edgecolor=GROUND_COLOR,
            lw=1.4,
            alpha=alpha,
            zorder=1.3,
        )
    )
    base = p + h * down
    _hatched_line(ax, ctx, base - 0.95 * h * side, base + 0.95 * h * side, down, alpha)


def _draw_joint(ax: Any, ctx: _Context, p: np.ndarray, alpha: float) -> None:
    from matplotlib.patches import Circle

    ax.add_patch(
        Circle(
            tuple(p),
            ctx.r,
            facecolor="white",
            edgecolor="#1a1a1a",
            lw=1.4,
            alpha=max(alpha, FAINT),
            zorder=4,
        )
    )


def _public(name: str) -> str:
    return name.split("~")[0]


def _on(plan: Plan, name: str) -> str:
    """Who pushes whom at pair ``name``: "rocker on crank (pin)" for a slot."""
    pair = plan.pairs[name]
    second = plan.bodies[pair.second]
    if "~" in second:
        # the slot's block is massless: the slot pushes the pin through it
        second = f"{plan.bodies[plan.pairs[name + '~pin'].second]} (pin)"
    return f"{plan.bodies[pair.first]} on {second}"


def _extent(
    ctx: _Context, pose: _Pose, bodies: set[int] | None = None
) -> list[np.ndarray]:
    """Points that a drawing of ``bodies`` (default: all) covers."""
    if bodies is None:
        bodies = set(range(len(ctx.plan.bodies)))
    seen: list[np.ndarray] = []
    for body in sorted(bodies):
        shape = _shape(ctx, pose, body)
        if body and not ctx.hidden(body):
            seen += shape.points + [g[k] for g in shape.guides for k in (0, 1)]
    for start, end, name in _shape(ctx, pose, 0).guides:
        if ctx.plan.pairs[name].second in bodies:
            seen += [start, end]
    for pair in ctx.plan.pairs.values():
        if {pair.first, pair.second} & bodies:
            seen.append(pose.at(pair.second, pair.d_second))
    return seen


def _draw_mechanism(
    ax: Any,
    ctx: _Context,
    pose: _Pose,
    full: set[int],
    faint: set[int] = frozenset(),
    labels: bool = True,
    frame: bool = True,
) -> list[np.ndarray]:
    """Draw the links ``full`` (and ``faint`` ones lightly); return the points covered.

    The frame's pivots and guides are drawn where they hold a link drawn (unless
    ``frame`` is false, as in a free-body diagram).
    """
    plan = ctx.plan
    drawn = full | faint

    def alpha(bodies: set[int]) -> float:
        return 1.0 if bodies & full else FAINT

    for body in sorted(drawn):
        if body and not ctx.hidden(body):
            _draw_link(ax, ctx, pose, body, alpha({body}))
    for start, end, name in _shape(ctx, pose, 0).guides:
        if frame and plan.pairs[name].second in drawn:
            _draw_guide(
                ax,
                ctx,
                start,
                end,
                name,
                GROUND_COLOR,
                alpha({plan.pairs[name].second}),
                np.zeros((0, 2)),
            )
    joints: dict[str, tuple[np.ndarray, float]] = {}
    for name, pair in plan.pairs.items():
        ends = {pair.first, pair.second}
        if not (ends - {0}) & drawn:
            continue
        p = pose.at(pair.second, pair.d_second)
        if pair.kind == "R":
            if 0 in ends and frame:
                _draw_pivot(ax, ctx, p, alpha(ends - {0}))
            _draw_joint(ax, ctx, p, alpha(ends))
        key = _public(name)
        if key not in joints or alpha(ends) > joints[key][1]:
            joints[key] = (p, alpha(ends))
    if labels:
        busy = [_skeleton(ctx, pose, drawn)]
        _label_joints(ax, ctx, joints, busy)
        busy = [*busy[1:], np.array([j[0] for j in joints.values()])]
        for body in sorted(drawn):
            if body and not ctx.hidden(body):
                _label_link(ax, ctx, pose, body, alpha({body}), busy)
    return _extent(ctx, pose, drawn)


def _skeleton(ctx: _Context, pose: _Pose, bodies: set[int]) -> np.ndarray:
    """Sample points along every bar, edge and guide drawn (to keep labels off them)."""
    samples = []
    for body in bodies:
        if body == 0 or ctx.hidden(body):
            continue
        shape = _shape(ctx, pose, body)
        segments = [
            (a, b) for i, a in enumerate(shape.points) for b in shape.points[i + 1 :]
        ]
        segments += [(g[0], g[1]) for g in shape.guides]
        for a, b in segments:
            count = max(2, int(np.hypot(*(b - a)) / ctx.r) + 1)
            samples.append(a + np.outer(np.linspace(0.0, 1.0, count), b - a))
        samples += [np.array(shape.points).reshape(-1, 2)]
    return np.vstack(samples) if samples else np.zeros((0, 2))


def _clearance(at: np.ndarray, busy: list[np.ndarray]) -> float:
    pts = np.vstack(busy) if busy else np.zeros((0, 2))
    return float(np.min(np.hypot(*(pts - at).T))) if len(pts) else math.inf


def _label_joints(
    ax: Any,
    ctx: _Context,
    joints: dict[str, tuple[np.ndarray, float]],
    busy: list[np.ndarray],
) -> None:
    """Name the joints, each on the side of its circle with the most room."""
    merged: list[list[Any]] = []
    for name, (p, alpha) in joints.items():
        for m in merged:
            if np.hypot(*(m[0] - p)) < 0.5 * ctx.r:
                m[1].append(name)
                m[2] = max(m[2], alpha)
                break
        else:
            merged.append([p, [name], alpha])
    turns = np.radians([45, 135, 90, 0, 180, 225, 315, 270])
    for p, names, alpha in merged:
        best = max(
            (
                (
                    _clearance(
                        p + 2.6 * ctx.r * np.array([math.cos(t), math.sin(t)]), busy
                    ),
                    -k,
                    t,
                )
                for k, t in enumerate(turns)
            )
        )
        d = np.array([math.cos(best[2]), math.sin(best[2])])
        at = p + 2.0 * ctx.r * d
        busy.append(at[None, :])
        ax.text(
            at[0],
            at[1],
            ", ".join(names),
            fontsize=9,
            fontweight="bold",
            ha="left" if d[0] > 0.3 else "right" if d[0] < -0.3 else "center",
            va="bottom" if d[1] > 0.3 else "top" if d[1] < -0.3 else "center",
            color="#1a1a1a",
            alpha=max(alpha, 0.35),
            zorder=7,
        )


def _label_link(
    ax: Any, ctx: _Context, pose: _Pose, body: int, alpha: float, busy: list[np.ndarray]
) -> None:
    """Name a link on its bar or plate, where it is farthest from other labels."""
    shape = _shape(ctx, pose, body)
    pts = np.array(shape.points).reshape(-1, 2)
    if len(pts) > 2:
        c = pts.mean(axis=0)
        candidates = [c] + [c + 0.4 * (q - c) for q in pts]
    elif len(pts) == 2 or shape.guides:
        a, b = (pts[0], pts[1]) if len(pts) == 2 else shape.guides[0][:2]
        candidates = [a + t * (b - a) for t in (0.5, 0.36, 0.64, 0.25, 0.75)]
    elif shape.blocks:
        centre, e = shape.blocks[0]
        n = np.array([-e[1], e[0]])
        candidates = [centre + 0.07 * ctx.size * s * n for s in (1, -1)]
    else:
        return
    scores = [_clearance(q, busy) for q in candidates]
    good = [k for k, v in enumerate(scores) if v > 4.0 * ctx.r]
    at = candidates[good[0] if good else int(np.argmax(scores))]
    busy.append(at[None, :])
    ax.text(
        at[0],
        at[1],
        ctx.plan.bodies[body],
        fontsize=8.5,
        ha="center",
        va="center",
        color=ctx.color[body],
        alpha=max(alpha, 0.35),
        zorder=6.5,
        bbox={
            "boxstyle": "round,pad=0.25",
            "facecolor": "white",
            "edgecolor": ctx.color[body],
            "lw": 1.0,
            "alpha": max(alpha, 0.35),
        },
    )


def _frame_axes(
    ax: Any, points: Sequence[np.ndarray], size: float, margin: float = 0.1
) -> None:
    pts = np.array(points).reshape(-1, 2)
    pts = pts[np.isfinite(pts).all(axis=1)]
    low, high = pts.min(axis=0), pts.max(axis=0)
    pad = margin * max(size, *(high - low))
    ax.set_xlim(low[0] - pad, high[0] + pad)
    ax.set_ylim(low[1] - pad, high[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")


def _new_axes(ax: Any, figsize: tuple[float, float] = (9.0, 6.0)) -> Any:
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


# ------------------------------------------------------------------------- forces


@dataclass(frozen=True)
class _Arrow:
    """One load of a picture: a force at a point or a couple (N, N m).

    ``value`` is the unit; ``kind`` one of "inertia", "gravity", "load", "reaction"
    (on the body or group drawn), "internal" (between two links of a group) and
    "balancing".
    """

    label: str
    point: np.ndarray
    force: np.ndarray | None
    couple: float | None
    color: str
    value: str
    kind: str


def _tex(name: str) -> str:
    safe = "".join(c if c.isalnum() else "\\_" if c == "_" else "." for c in name)
    return f"\\mathrm{{{safe}}}"


def _reaction(
    ctx: _Context, pose: _Pose, row: int, name: str, sign: float = 1.0
) -> tuple[np.ndarray, np.ndarray, float | None]:
    """Reaction of pair ``name`` on its second link (``sign`` -1: on its first).

    A prismatic pair's normal force is placed where it balances the pair's couple;
    the couple is returned separately when that point lies too far away.
    """
    pair = ctx.plan.pairs[name]
    force, couple = ctx.table.force_state.reactions[name]
    f = sign * np.asarray(force[row], dtype=float)
    q = pose.at(pair.second, pair.d_second)
    if pair.kind == "R":
        return q, f, None
    e = pose.turn(pair.first, pair.axis)
    normal = float(np.dot(f, np.array([-e[1], e[0]])))
    m = sign * float(couple[row])
    if abs(normal) > 1e-9 and abs(m / normal) < 0.5 * ctx.size:
        return q + (m / normal) * e, f, None
    return q, f, m


def _centre(table: Table, link: str, row: int) -> np.ndarray:
    """Centre of mass of ``link`` at ``row``, m."""
    return np.array([table[f"{link}.G.x"][row], table[f"{link}.G.y"][row]])


def _inertia_arrows(ctx: _Context, row: int, links: Iterable[str]) -> list[_Arrow]:
    """Inertia force at the centre of mass and inertia torque of each massive link."""
    fs = ctx.table.force_state
    arrows = []
    for link in links:
        if not ctx.table.mechanism.link(link).mass:
            continue
        b, g, name = ctx.plan.body(link), _centre(ctx.table, link, row), _tex(link)
        arrows.append(
            _Arrow(
                f"$F_{{i,{name}}}$",
                g,
                fs.inertia_force[row, b],
                None,
                INERTIA_COLOR,
                "N",
                "inertia",
            )
        )
        arrows.append(
            _Arrow(
                f"$M_{{i,{name}}}$",
                g,
                None,
                float(fs.inertia_torque[row, b]),
                INERTIA_COLOR,
                "N m",
                "inertia",
            )
        )
    return arrows


def _overview_arrows(ctx: _Context, pose: _Pose, row: int) -> list[_Arrow]:
    """Inertia loads, reactions and balancing loads at ``row`` for :func:`draw`."""
    plan, fs = ctx.plan, ctx.table.force_state
    arrows = _inertia_arrows(
        ctx, row, [link.name for link in ctx.table.mechanism.links]
    )
    for name, pair in plan.pairs.items():
        if not pair.virtual:
            q, f, m = _reaction(ctx, pose, row, name)
            arrows.append(
                _Arrow(
                    f"$R_{{{_tex(name)}}}$", q, f, m, REACTION_COLOR, "N", "reaction"
                )
            )
    for i, d in enumerate(plan.drivers):
        p = pose.at(d.pair.second, d.pair.d_second)
        value = float(fs.balancing[row, i])
        label = f"$T_{{b,{_tex(d.pair.name)}}}$" if len(plan.drivers) > 1 else "$T_b$"
        if d.kind == "R":
            arrows.append(
                _Arrow(label, p, None, value, DRIVER_COLOR, "N m", "balancing")
            )
        else:
            e = pose.turn(d.pair.first, d.pair.axis)
            arrows.append(
                _Arrow(
                    label.replace("T", "F"),
                    p,
                    value * e,
                    None,
                    DRIVER_COLOR,
                    "N",
                    "balancing",
                )
            )
    return arrows


def _nice(x: float) -> float:
    """Return the smallest of 1, 2, 5 times a power of ten not below ``x``."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 5.0, 10.0):
        if m * 10.0**k >= x * (1 - 1e-12):
            return m * 10.0**k
    return 10.0 ** (k + 1)  # pragma: no cover


def _scale(arrows: Iterable[_Arrow], size: float) -> float:
    """Return the default force scale, N per cm: the largest arrow 28 % of ``size``."""
    big = max(
        (float(np.hypot(*a.force)) for a in arrows if a.force is not None), default=0.0
    )
    return _nice(big / (ARROW_LENGTH * size * 100.0))


def _draw_arrows(
    ax: Any, ctx: _Context, arrows: list[_Arrow], scale: float, text: str | None
) -> list[np.ndarray]:
    """Draw ``arrows`` at ``scale`` N per cm; return their extreme points.

    ``text`` is ``"values"`` (name and value), ``"names"`` or None (no labels).
    """
    from matplotlib.patches import FancyArrowPatch
    from matplotlib.path import Path

    seen = []
    per_metre = scale * 100.0
    tiny = 1e-9 * max([abs(a.couple or 0) for a in arrows] + [1.0])
    box = {
        "boxstyle": "round,pad=0.1",
        "facecolor": "white",
        "edgecolor": "none",
        "alpha": 0.75,
    }
    for a in arrows:
        if a.force is not None and float(np.hypot(*a.force)) > 0:
            mag = float(np.hypot(*a.force))
            tip = a.point + a.force / per_metre
            ax.add_patch(
                FancyArrowPatch(
                    tuple(a.point),
                    tuple(tip),
                    arrowstyle="-|>",
                    mutation_scale=13,
                    color=a.color,
                    lw=1.7,
                    shrinkA=0,
                    shrinkB=0,
                    zorder=6,
                )
            )
            seen.append(tip)
            if text:
                u = a.force / mag
                words = (
                    f"{a.label} = {mag:.3g} {a.value}" if text == "values" else a.label
                )
                ax.text(
                    *(tip + 0.5 * ctx.r * u),
                    words,
                    fontsize=7.5,
                    color=a.color,
                    ha="left" if u[0] >= 0 else "right",
                    va="bottom" if u[1] >= 0 else "top",
                    zorder=7,
                    bbox=box,
                )
        if a.couple is not None and abs(a.couple) > tiny:
            rad = (3.4 if a.color == DRIVER_COLOR else 2.3) * ctx.r
            t = np.linspace(math.radians(-100), math.radians(150), 40)
            if a.couple < 0:
                t = t[::-1]
            arc = a.point + rad * np.column_stack([np.cos(t), np.sin(t)])
            ax.add_patch(
                FancyArrowPatch(
                    path=Path(arc),
                    arrowstyle="-|>",
                    mutation_scale=11,
                    color=a.color,
                    lw=1.5,
                    zorder=6,
                )
            )
            seen += [a.point - rad, a.point + rad]
            if text == "values" or (text and a.color == DRIVER_COLOR):
                at = a.point + rad * np.array([0.7, 0.8])
                ax.text(
                    *at,
                    f"{a.label} = {a.couple:.3g} {a.value}",
                    fontsize=7.5,
                    color=a.color,
                    ha="left",
                    va="bottom",
                    zorder=7,
                    bbox=box,
                )
            elif text:
                at = a.point + rad * np.array([0.7, 0.8])
                ax.text(
                    *at,
                    a.label,
                    fontsize=7.5,
                    color=a.color,
                    ha="left",
                    va="bottom",
                    zorder=7,
                    bbox=box,
                )
    return seen


def _need_forces(table: Table, what: str) -> None:
    if table.force_state is None:
        msg = (
            f"{what}: needs a forces table (assur.forces); this table holds "
            "kinematics only"
        )
        raise ModelError(msg)


def _handles(entries: list[tuple[str, str]]) -> list[Any]:
    """Legend handles: a thick line in each colour (none for a note such as a scale)."""
    from matplotlib.lines import Line2D

    return [
        Line2D([], [], color=c or "none", lw=4 if c else 0, label=text)
        for text, c in entries
    ]


def _legend(
    ax: Any,
    entries: list[tuple[str, str]],
    title: str | None = None,
    outside: bool = True,
) -> None:
    kw = {"loc": "upper left", "bbox_to_anchor": (1.02, 1.0)} if outside else {}
    ax.legend(
        handles=_handles(entries),
        fontsize=8,
        title=title,
        title_fontsize=8,
        frameon=False,
        **kw,
    )


# ------------------------------------------------------------------ public pictures


def draw(
    table: Table,
    angle: Any = None,
    ax: Any = None,
    forces: bool = False,
    scale: float | None = None,
    labels: bool = True,
    groups: bool = True,
) -> Any:
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
        largest arrow is about a quarter of the mechanism by default.
    labels : bool
        Name the joints and links (and give the forces' values).
    groups : bool
        Colour by Assur group with a legend; otherwise one colour.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ModelError
        When ``forces`` is asked of a kinematics table, or ``angle`` has the wrong
        number of values.

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
        scale = scale or _scale(arrows, ctx.size)
        seen += _draw_arrows(ax, ctx, arrows, scale, "names" if labels else None)
        entries += [
            ("reaction, by first link on second", REACTION_COLOR),
            ("inertia force and torque", INERTIA_COLOR),
            ("balancing load", DRIVER_COLOR),
            (f"force scale: 1 cm = {scale:g} N", ""),
        ]
    _frame_axes(ax, list(limits) if limits is not None else seen, ctx.size)
    name = ctx.table.mechanism.name or "Mechanism"
    ax.set_title(f"{name}, {_position_text(ctx.table, row)}", fontsize=10)
    if entries and legend:
        _legend(ax, entries)
    return entries


def draw_decomposition(table: Table, angle: Any = None) -> Any:
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
    import matplotlib.pyplot as plt

    from assur.structure import structure

    ctx = _context(table)
    row = _row(table, angle)
    pose = ctx.pose(row)
    plan = ctx.plan
    steps = [
        (f"I: driver (ground, {plan.bodies[d.body]})", {d.body}, {0})
        for d in plan.drivers
    ]
    for g, (text, _, bodies) in zip(
        plan.groups, ctx.legend[len(plan.drivers) :], strict=True
    ):
        steps.append((text, set(bodies), {plan.body(x) for x in g.attached_to}))
    ncols = min(3, len(steps))
    nrows = math.ceil(len(steps) / ncols)
    every = _extent(ctx, pose)
    span = np.ptp(np.array(every), axis=0)
    span = span + 0.16 * max(ctx.size, *span)
    # the panels keep the drawing's proportions: about 3.4 in of axes per panel width
    height = float(np.clip(3.4 * span[1] / span[0], 0.8, 5.5)) + 1.1
    fig, axes = plt.subplots(
        nrows,
        ncols,
        figsize=(4.2 * ncols, height * nrows + 0.6),
        layout="constrained",
        squeeze=False,
    )
    for k, ax in enumerate(axes.flat):
        if k >= len(steps):
            ax.set_axis_off()
            continue
        text, full, faint = steps[k]
        _draw_mechanism(ax, ctx, pose, full, faint - full)
        _frame_axes(ax, every, ctx.size, margin=0.08)
        on = sorted(_public(plan.bodies[b]) for b in faint)
        ax.set_title(f"{k + 1}. {text}\nhangs on: {', '.join(on)}", fontsize=9)
    formula = structure(table.mechanism).formula
    fig.suptitle(
        f"{table.mechanism.name or 'Mechanism'}: {formula}\n"
        f"{_position_text(table, row)}",
        fontsize=10,
    )
    return fig


def _anchor(ctx: _Context, pose: _Pose, body: int) -> np.ndarray:
    """Return a point to hang a couple on: the middle of the link's points."""
    pts = np.array(_shape(ctx, pose, body).points).reshape(-1, 2)
    return pts.mean(axis=0) if len(pts) else pose.origin[body]


def _free_body_arrows(table: Table, group_index: int, row: int) -> list[_Arrow]:
    """Return the loads on Assur group ``group_index`` at ``row`` (N, N m).

    External reactions act on the group; internal ones on the pair's second link.
    """
    from assur.loads import table_values
    from assur.model import LoadTable, resolve_point

    ctx = _context(table)
    plan, mech = ctx.plan, table.mechanism
    group = plan.groups[group_index]
    bodies = {plan.body(x) for x in group.links}
    pose = ctx.pose(row)
    arrows = _inertia_arrows(ctx, row, [x for x in group.links if "~" not in x])
    if mech.gravity is not None and any(mech.gravity):
        for x in group.links:
            mass = mech.link(x).mass if "~" not in x else None
            if mass:
                arrows.append(
                    _Arrow(
                        f"$G_{{{_tex(x)}}}$",
                        _centre(table, x, row),
                        mass * np.asarray(mech.gravity, dtype=float),
                        None,
                        LOAD_COLOR,
                        "N",
                        "gravity",
                    )
                )
    drive = table.state.drive[row : row + 1]
    slides = {k: v[0, row : row + 1] for k, v in table.state.slide.items()}

    def value(v: Any, entry: str) -> np.ndarray:
        if isinstance(v, LoadTable):
            return np.array([c[0] for c in table_values(v, plan, drive, slides, entry)])
        return np.atleast_1d(np.asarray(v, dtype=float))

    for i, load in enumerate(mech.loads):
        b = plan.body(load.link)
        if b not in bodies:
            continue
        name = _tex(load.link)
        if load.force is not None:
            at = pose.at(b, plan.offset(b, resolve_point(mech, load.at)))
            arrows.append(
                _Arrow(
                    f"$F_{{{name}}}$",
                    at,
                    value(load.force, f"loads[{i}].force"),
                    None,
                    LOAD_COLOR,
                    "N",
                    "load",
                )
            )
        if load.torque is not None:
            arrows.append(
                _Arrow(
                    f"$T_{{{name}}}$",
                    _anchor(ctx, pose, b),
                    None,
                    float(value(load.torque, f"loads[{i}].torque")[0]),
                    LOAD_COLOR,
                    "N m",
                    "load",
                )
            )
    for name, pair in plan.pairs.items():
        inside = (pair.first in bodies, pair.second in bodies)
        if not any(inside):
            continue
        label = _tex(_public(name))
        if all(inside):
            first, second = (
                _tex(_public(plan.bodies[x])) for x in (pair.first, pair.second)
            )
            label = f"{label},{first}\\to {second}"
        q, f, m = _reaction(ctx, pose, row, name, 1.0 if inside[1] else -1.0)
        arrows.append(
            _Arrow(
                f"$R_{{{label}}}$",
                q,
                f,
                m,
                REACTION_COLOR,
                "N",
                "internal" if all(inside) else "reaction",
            )
        )
    return arrows


def draw_free_body(
    table: Table,
    group_index: int,
    angle: Any = None,
    ax: Any = None,
    scale: float | None = None,
) -> Any:
    """Draw the free-body diagram of one Assur group at one driver position.

    The group is cut free from the links it hangs on; the arrows are its inertia
    loads, gravity and external loads, the reactions of the known links at its
    external pairs (acting on the group) and those at its internal pairs (by the
    pair's first link on its second), each labelled with its value.

    Parameters
    ----------
    table : Table
        A forces table.
    group_index : int
        Index of the group in the order of attachment (0: the first Assur group;
        drivers are not counted).
    angle : float, optional
        Driver position, deg (nearest row; default the first).
    ax : matplotlib Axes, optional
    scale : float, optional
        Force scale, N per cm of drawing.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    ModelError
        For a kinematics table or a group index out of range.
    """
    _need_forces(table, "draw_free_body")
    ctx = _context(table)
    count = len(ctx.plan.groups)
    if not -count <= group_index < count:
        msg = (
            f"group_index: {group_index} is out of range; the mechanism has {count} "
            f"Assur group(s), expected 0 to {count - 1}"
        )
        raise ModelError(msg)
    group_index %= count
    row = _row(table, angle)
    pose = ctx.pose(row)
    group = ctx.plan.groups[group_index]
    bodies = {ctx.plan.body(x) for x in group.links}
    ax = _new_axes(ax, (9.0, 6.5))
    seen = _draw_mechanism(ax, ctx, pose, bodies, frame=False)
    arrows = _free_body_arrows(table, group_index, row)
    scale = scale or _scale(arrows, 0.8 * ctx.size)
    seen += _draw_arrows(ax, ctx, arrows, scale, "values")
    seen += [a.point for a in arrows]
    _frame_axes(ax, seen, 0.5 * ctx.size, margin=0.12)
    text, color, _ = ctx.legend[len(ctx.plan.drivers) + group_index]
    ax.set_title(
        f"Free body of group {text}\n{_position_text(table, row)}", fontsize=10
    )
    _legend(
        ax,
        [
            (text, color),
            ("reaction", REACTION_COLOR),
            ("inertia force and torque", INERTIA_COLOR),
            ("gravity, external load", LOAD_COLOR),
            (f"force scale: 1 cm = {scale:g} N", ""),
        ],
    )
    return ax


# ------------------------------------------------------------ diagrams over a sweep


def _driver_axis(ax: Any, table: Table) -> np.ndarray:
    """Label the horizontal axis with the driver position; return its values."""
    from matplotlib.ticker import MultipleLocator

    from assur.plan import compile_plan

    x = np.asarray(table["angle"])
    if compile_plan(table.mechanism).drivers[0].kind == "R":
        ax.set_xlabel("driver angle φ [deg]")
        if np.ptp(x) >= 180.0:
            ax.xaxis.set_major_locator(
                MultipleLocator(90.0 if np.ptp(x) > 400 else 45.0)
            )
    else:
        ax.set_xlabel("driver position s [m]")
    ax.grid(True, lw=0.5, alpha=0.5)
    return x


def _public_links(plan: Plan) -> list[str]:
    return [b for b in plan.bodies[1:] if "~" not in b]


def _moving_points(table: Table, extra_first: bool = True) -> list[str]:
    """Return the reported points that move (joints, extra points; no centres)."""
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    extra = [p.name for p in table.mechanism.points]
    joints = [n for n, pair in plan.pairs.items() if not pair.virtual]
    names, paths = [], []
    for name in (extra + joints) if extra_first else (joints + extra):
        path = np.column_stack([table[f"{name}.x"], table[f"{name}.y"]])
        if np.ptp(path, axis=0).max() <= 1e-9 * plan.scale:
            continue  # a pivot on the frame has no path
        if any(np.allclose(path, q, rtol=0, atol=1e-9 * plan.scale) for q in paths):
            continue  # a slider's guide point runs with its pin
        names.append(name)
        paths.append(path)
    return names


def plot_motion(
    table: Table,
    names: Sequence[str] | str | None = None,
    quantity: str = "omega",
    ax: Any = None,
) -> Any:
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
    ModelError
        When the table has no such column for one of ``names``.

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
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    if names is None:
        # links that only slide (their angle is constant) would add flat lines
        names = (
            [x for x in _public_links(plan) if np.ptp(table[f"{x}.angle"]) > 1e-9]
            if quantity in LINK_UNITS
            else _moving_points(table, extra_first=False)
        )
    elif isinstance(names, str):
        names = [names]
    ax = _new_axes(ax, (8.0, 4.5))
    x = _driver_axis(ax, table)
    ctx = _context(table)
    styles = ("-", "--", ":", "-.")
    for name in names:
        color, style = None, "-"
        if name in plan.bodies:
            body = plan.body(name)
            color = ctx.color[body]
            # links of one group share its colour; their order in it sets the dashes
            same = [b for b in range(body) if ctx.color[b] == color]
            style = styles[len(same) % len(styles)]
        if f"{name}.{quantity}" in table:
            line = ax.plot(
                x,
                table[f"{name}.{quantity}"],
                lw=1.6,
                label=name,
                color=color,
                ls=style,
            )
        elif quantity in POINT_PARTS and f"{name}.{POINT_PARTS[quantity][0]}" in table:
            cx, cy = POINT_PARTS[quantity]
            line = ax.plot(x, table[f"{name}.{cx}"], lw=1.6, label=f"{name} {cx}")
            ax.plot(
                x,
                table[f"{name}.{cy}"],
                lw=1.6,
                ls="--",
                color=line[0].get_color(),
                label=f"{name} {cy}",
            )
        else:
            have = sorted(
                {
                    c.rsplit(".", 1)[1]
                    for c in table.columns
                    if c.rsplit(".", 1)[0] == name
                }
            )
            have += [q for q in POINT_PARTS if f"{name}.x" in table]
            msg = (
                f"plot_motion: no quantity {quantity!r} for {name!r}; expected one of "
                f"{', '.join(have)}"
                if have
                else f"plot_motion: no link or point {name!r} in the table"
            )
            raise ModelError(msg)
    unit = LINK_UNITS.get(quantity) or POINT_UNITS.get(quantity, "")
    ax.set_ylabel(f"{quantity} [{unit}]")
    ax.set_title(f"{table.mechanism.name or 'Mechanism'}: {quantity}", fontsize=10)
    ax.legend(fontsize=8, ncols=2 if len(ax.lines) > 8 else 1)
    return ax


def plot_paths(
    table: Table, points: Sequence[str] | None = None, angle: Any = None, ax: Any = None
) -> Any:
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
    names = list(points) if points is not None else _moving_points(table)
    colors = (
        "#1f77b4",
        "#d62728",
        "#2ca02c",
        "#9467bd",
        "#ff7f0e",
        "#17becf",
        "#8c564b",
        "#e377c2",
        "#bcbd22",
        "#7f7f7f",
    )
    for k, name in enumerate(names):
        if f"{name}.x" not in table:
            msg = f"plot_paths: no point {name!r}; expected a joint or an extra point"
            raise ModelError(msg)
        xy = np.column_stack([table[f"{name}.x"], table[f"{name}.y"]])
        color = colors[k % len(colors)]
        coupler = name in extra
        ax.plot(
            xy[:, 0],
            xy[:, 1],
            color=color,
            lw=2.4 if coupler else 1.4,
            zorder=5,
            label=f"{name} (coupler curve)" if coupler else name,
        )
        _direction(ax, xy, color)
        seen += list(xy)
    _frame_axes(ax, seen, ctx.size, margin=0.06)
    ax.set_title(f"{table.mechanism.name or 'Mechanism'}: paths of points", fontsize=10)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), frameon=False)
    return ax


def _direction(ax: Any, xy: np.ndarray, color: str) -> None:
    """Draw an arrowhead a third of the way along a path: the sense of motion."""
    from matplotlib.patches import FancyArrowPatch

    k = len(xy) // 3
    if len(xy) < 3 or not np.all(np.isfinite(xy[k : k + 2])):
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


def plot_torque(table: Table, ax: Any = None) -> Any:
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
    from assur.plan import compile_plan

    plan = compile_plan(table.mechanism)
    ax = _new_axes(ax, (8.0, 4.5))
    x = _driver_axis(ax, table)
    fs = table.force_state
    colors = (DRIVER_COLOR, "#e6550d", "#31a354")
    step = max(1, len(x) // 36)
    for i, d in enumerate(plan.drivers):
        what, unit = ("torque", "N m") if d.kind == "R" else ("force", "N")
        name = f" at {d.pair.name}" if len(plan.drivers) > 1 else ""
        color = colors[i % len(colors)]
        ax.plot(
            x,
            fs.balancing[:, i],
            color=color,
            lw=1.8,
            label=f"balancing {what}{name} (equilibrium)",
        )
        ax.plot(
            x[::step],
            fs.check[::step, i],
            ls="none",
            marker="o",
            mfc="none",
            color=color,
            ms=5,
            label=f"virtual-power check{name}",
        )
        mean = float(np.mean(fs.balancing[:, i]))
        if abs(mean) < 1e-9 * float(np.max(np.abs(fs.balancing[:, i]))):
            mean = 0.0  # a full turn of a conservative system: zero up to rounding
        ax.axhline(
            mean, color=color, lw=0.9, ls=":", label=f"mean {mean:.4g} {unit}{name}"
        )
    ax.axhline(0.0, color="black", lw=0.6)
    unit = "N m" if plan.drivers[0].kind == "R" else "N"
    ax.set_ylabel(f"balancing load [{unit}]")
    ax.set_title(f"{table.mechanism.name or 'Mechanism'}: balancing load", fontsize=10)
    ax.legend(fontsize=8)
    return ax


def _locus(ax: Any, table: Table, fx: np.ndarray, fy: np.ndarray, color: str) -> None:
    """Draw the hodograph of a force: its tip's path, the origin, a few marks."""
    ax.plot(fx, fy, color=color, lw=1.5)
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
    for k in marks:
        ax.plot([fx[k]], [fy[k]], marker="o", ms=3.5, color=color)
        ax.annotate(
            f"{table['angle'][k]:.0f}°"
            if _revolute(table)
            else f"{table['angle'][k]:.3g} m",
            (fx[k], fy[k]),
            fontsize=7,
            xytext=(3, 3),
            textcoords="offset points",
        )
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.4, alpha=0.5)


def _revolute(table: Table) -> bool:
    from assur.plan import compile_plan

    return compile_plan(table.mechanism).drivers[0].kind == "R"


def plot_hodographs(table: Table, joints: Sequence[str] | None = None) -> Any:
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

    _need_forces(table, "plot_hodographs")
    ctx = _context(table)
    names = (
        list(joints)
        if joints is not None
        else [n for n, p in ctx.plan.pairs.items() if not p.virtual]
    )
    for name in names:
        if name not in ctx.plan.pairs or ctx.plan.pairs[name].virtual:
            msg = (
                f"plot_hodographs: no joint {name!r}; expected one of the file's joints"
            )
            raise ModelError(msg)
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
        pair = ctx.plan.pairs[name]
        force = ctx.table.force_state.reactions[name][0]
        _locus(ax, table, force[:, 0], force[:, 1], ctx.color[pair.second])
        ax.set_title(
            f"{name}: {_on(ctx.plan, name)}\n"
            f"max {np.nanmax(np.hypot(force[:, 0], force[:, 1])):.4g} N",
            fontsize=8.5,
        )
        ax.set_xlabel("Fx [N]", fontsize=8)
        ax.set_ylabel("Fy [N]", fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(names) :]:
        ax.set_axis_off()
    fig.suptitle(
        f"{table.mechanism.name or 'Mechanism'}: hodographs of the joint reactions",
        fontsize=10,
    )
    return fig


def plot_shaking(table: Table) -> Any:
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
    shaking = table.force_state.shaking
    fig = plt.figure(figsize=(11.0, 4.8), layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.0, 1.4))
    polar = fig.add_subplot(grid[:, 0])
    _locus(polar, table, shaking[:, 0], shaking[:, 1], "#1f77b4")
    polar.set_xlabel("Fx [N]")
    polar.set_ylabel("Fy [N]")
    polar.set_title("hodograph of the shaking force", fontsize=9)
    force = fig.add_subplot(grid[0, 1])
    x = _driver_axis(force, table)
    force.plot(x, shaking[:, 0], label="Fx", lw=1.5)
    force.plot(x, shaking[:, 1], label="Fy", lw=1.5)
    force.plot(
        x, np.hypot(shaking[:, 0], shaking[:, 1]), label="|F|", lw=1.5, color="black"
    )
    force.set_ylabel("force [N]")
    force.legend(fontsize=8, ncols=3)
    force.set_xlabel("")
    moment = fig.add_subplot(grid[1, 1], sharex=force)
    _driver_axis(moment, table)
    moment.plot(x, shaking[:, 2], color="#d62728", lw=1.5, label="M about the origin")
    moment.set_ylabel("moment [N m]")
    moment.legend(fontsize=8)
    fig.suptitle(
        f"{table.mechanism.name or 'Mechanism'}: shaking force and moment on the frame",
        fontsize=10,
    )
    return fig


def animate(
    table: Table, path: Any, forces: bool = False, fps: float = 20, dpi: float = 80
) -> int:
    """Write an animated GIF of the sweep, one frame per row of ``table``.

    Parameters
    ----------
    table : Table
    path : str or path-like
        The GIF file to write.
    forces : bool
        Draw the joint reactions and the other loads too, at one scale for the whole
        sweep (needs a forces table).
    fps : float
        Frames per second.
    dpi : float
        Resolution of the frames, dots per inch (the drawing is 6 inches wide).

    Returns
    -------
    int
        The number of frames written.
    """
    import matplotlib.pyplot as plt
    from matplotlib.animation import PillowWriter

    if forces:
        _need_forces(table, "animate(forces=True)")
    ctx = _context(table)
    rows = range(len(table))
    limits = [p for r in rows for p in _extent(ctx, ctx.pose(r))]
    scale = None
    if forces:
        # one scale and one frame for the whole film, so arrows compare across frames
        arrows = [a for r in rows for a in _overview_arrows(ctx, ctx.pose(r), r)]
        scale = _scale(arrows, ctx.size)
        limits += [
            a.point + a.force / (scale * 100.0) for a in arrows if a.force is not None
        ]
    corners = [np.nanmin(limits, axis=0), np.nanmax(limits, axis=0)]
    # a fixed layout sized to the drawing: the axes must not jump between frames
    span = corners[1] - corners[0] + 0.2 * max(ctx.size, *(corners[1] - corners[0]))
    width, height = 6.0, float(np.clip(6.0 * span[1] / span[0], 2.0, 6.0))
    size = (width + 4.2, height + 1.1)
    fig, ax = plt.subplots(figsize=size)
    fig.subplots_adjust(
        left=0.8 / size[0],
        right=(0.8 + width) / size[0],
        bottom=0.7 / size[1],
        top=1.0 - 0.4 / size[1],
    )
    try:
        writer = PillowWriter(fps=fps)
        with writer.saving(fig, str(path), dpi):
            for r in rows:
                ax.clear()
                entries = _draw_row(
                    ax, ctx, r, forces, scale, True, True, corners, False
                )
                if r == 0:
                    # one legend for the whole film, outside the axes that are redrawn
                    fig.legend(
                        handles=_handles(entries),
                        loc="upper left",
                        fontsize=8,
                        bbox_to_anchor=((1.0 + width) / size[0], 1.0 - 0.4 / size[1]),
                        frameon=False,
                    )
                writer.grab_frame()
    finally:
        plt.close(fig)
    return len(table)
