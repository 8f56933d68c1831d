"""Pure geometry of the pictures: link outlines, hulls, label spots, round numbers.

Nothing here draws; the functions return points (m, in the fixed frame) that the
drawing modules hand to matplotlib.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from assur.plan import Plan
    from assur.plotting._context import _Context, _Pose

BLOCK_HALF = (0.05, 0.024)
"""Half length and half height of a sliding block, in sizes of the mechanism."""
JOINT_TURNS = np.radians([45, 135, 90, 0, 180, 225, 315, 270])
"""Directions tried for a joint's label, in order of preference, rad."""


@dataclass
class _Shape:
    """What one link looks like at a pose: its points, guides and sliding blocks."""

    points: list[np.ndarray]
    guides: list[tuple[np.ndarray, np.ndarray, str]]
    blocks: list[tuple[np.ndarray, np.ndarray]]


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


def _area(polygon: np.ndarray) -> float:
    """Area of a simple polygon (shoelace formula), m²."""
    return 0.5 * abs(
        np.dot(polygon[:, 0], np.roll(polygon[:, 1], 1))
        - np.dot(polygon[:, 1], np.roll(polygon[:, 0], 1))
    )


def _farthest(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the two of ``points`` farthest apart."""
    return max(
        ((p, q) for p in points for q in points),
        key=lambda pq: np.hypot(*(pq[0] - pq[1])),
    )


def _distinct(points: list[np.ndarray], tol: float) -> list[np.ndarray]:
    """Drop the points within ``tol`` of an earlier one."""
    out: list[np.ndarray] = []
    for p in points:
        if all(np.hypot(*(p - q)) > tol for q in out):
            out.append(p)
    return out


def _shape(ctx: _Context, pose: _Pose, body: int) -> _Shape:
    """Return the points, guides and blocks of ``body`` at ``pose``."""
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
            seen += shape.points + [p for g in shape.guides for p in g[:2]]
    for start, end, name in _shape(ctx, pose, 0).guides:
        if ctx.plan.pairs[name].second in bodies:
            seen += [start, end]
    for pair in ctx.plan.pairs.values():
        if {pair.first, pair.second} & bodies:
            seen.append(pose.at(pair.second, pair.d_second))
    return seen


def _skeleton(ctx: _Context, pose: _Pose, bodies: set[int]) -> np.ndarray:
    """Sample points along every bar, edge and guide drawn (to keep labels off them)."""
    samples = []
    segments = [(g[0], g[1]) for g in _shape(ctx, pose, 0).guides]
    for body in bodies:
        if body == 0 or ctx.hidden(body):
            continue
        shape = _shape(ctx, pose, body)
        segments += [
            (a, b) for i, a in enumerate(shape.points) for b in shape.points[i + 1 :]
        ]
        segments += [(g[0], g[1]) for g in shape.guides]
        # a sliding block's outline: a joint's name was set over the block
        segments += _block_edges(ctx, shape.blocks)
        samples += [np.array(shape.points).reshape(-1, 2)]
    for a, b in segments:
        count = max(2, int(np.hypot(*(b - a)) / ctx.r) + 1)
        samples.append(a + np.outer(np.linspace(0.0, 1.0, count), b - a))
    return np.vstack(samples) if samples else np.zeros((0, 2))


def _block_edges(
    ctx: _Context, blocks: list[tuple[np.ndarray, np.ndarray]]
) -> list[tuple[np.ndarray, np.ndarray]]:
    """Return the four edges of each sliding block (as :func:`_draw_block` draws it)."""
    edges = []
    for centre, e in blocks:
        n = np.array([-e[1], e[0]])
        half_l, half_h = BLOCK_HALF[0] * ctx.size, BLOCK_HALF[1] * ctx.size
        corners = [
            centre + sl * half_l * e + sh * half_h * n
            for sl, sh in ((1, 1), (-1, 1), (-1, -1), (1, -1))
        ]
        edges += [(corners[k - 1], corners[k]) for k in range(4)]
    return edges


def _anchor(ctx: _Context, pose: _Pose, body: int) -> np.ndarray:
    """Return a point to hang a couple on: the middle of the link's points."""
    pts = np.array(_shape(ctx, pose, body).points).reshape(-1, 2)
    return pts.mean(axis=0) if len(pts) else pose.origin[body]


def _clearance(at: np.ndarray, busy: list[np.ndarray]) -> float:
    """Distance from ``at`` to the nearest of the ``busy`` points, m."""
    pts = np.vstack(busy) if busy else np.zeros((0, 2))
    return float(np.min(np.hypot(*(pts - at).T))) if len(pts) else math.inf


def _merge_joints(
    joints: dict[str, tuple[np.ndarray, float]], tol: float
) -> list[list[Any]]:
    """Group the joints closer than ``tol``: ``[point, names, opacity]`` each."""
    merged: list[list[Any]] = []
    for name, (p, alpha) in joints.items():
        for m in merged:
            if np.hypot(*(m[0] - p)) < tol:
                m[1].append(name)
                m[2] = max(m[2], alpha)
                break
        else:
            merged.append([p, [name], alpha])
    return merged


def _joint_direction(p: np.ndarray, r: float, busy: list[np.ndarray]) -> np.ndarray:
    """Return the unit vector from joint ``p`` (radius ``r``) toward the most room."""
    best = max(
        (
            _clearance(p + 2.6 * r * np.array([math.cos(t), math.sin(t)]), busy),
            -k,
            t,
        )
        for k, t in enumerate(JOINT_TURNS)
    )
    return np.array([math.cos(best[2]), math.sin(best[2])])


def _link_spots(ctx: _Context, pose: _Pose, body: int) -> list[np.ndarray]:
    """Places for the name of ``body``, on its plate, bar, guide or block."""
    shape = _shape(ctx, pose, body)
    pts = np.array(shape.points).reshape(-1, 2)
    if len(pts) > 2:
        c = pts.mean(axis=0)
        return [c] + [c + 0.4 * (q - c) for q in pts]
    if len(pts) == 2 or shape.guides:
        a, b = (pts[0], pts[1]) if len(pts) == 2 else shape.guides[0][:2]
        return [a + t * (b - a) for t in (0.5, 0.36, 0.64, 0.25, 0.75)]
    if shape.blocks:
        centre, e = shape.blocks[0]
        n = np.array([-e[1], e[0]])
        return [centre + 0.07 * ctx.size * s * n for s in (1, -1)]
    return []


def _link_spot(spots: list[np.ndarray], r: float, busy: list[np.ndarray]) -> np.ndarray:
    """Return the first of ``spots`` clear of ``busy`` points, else the clearest."""
    scores = [_clearance(q, busy) for q in spots]
    good = [k for k, v in enumerate(scores) if v > 4.0 * r]
    return spots[good[0] if good else int(np.argmax(scores))]


def _public(name: str) -> str:
    """Name as the file spells it, without the "~" suffix of a slot's virtual parts."""
    return name.split("~")[0]


def _on(plan: Plan, name: str) -> str:
    """Who pushes whom at pair ``name``: "rocker on crank (pin)" for a slot."""
    pair = plan.pairs[name]
    second = plan.bodies[pair.second]
    if "~" in second:
        # the slot's block is massless: the slot pushes the pin through it
        second = f"{plan.bodies[plan.pairs[name + '~pin'].second]} (pin)"
    return f"{plan.bodies[pair.first]} on {second}"


def _nice(x: float) -> float:
    """Return the smallest of 1, 2, 5 times a power of ten not below ``x``."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 5.0):
        if m * 10.0**k >= x * (1 - 1e-12):
            return m * 10.0**k
    return 10.0 * 10.0**k
