"""Velocities and accelerations of a dyad as vector equations, solved with numbers.

The middle joint's motion is written twice, once along each link from the joint by
which it hangs on a known link (``v_C = v_B + v_CB``), plus the relative motion of a
sliding middle pair; the two unknown magnitudes (angular velocities, or slide rates)
follow from the components by Cramer's rule. Every term is computed from the solved
motions, so the sums printed equal the tables' values.
"""

from __future__ import annotations

import math
from typing import TypeAlias

import numpy as np

from assur._vec import Array
from assur.explain._note import Block, Display, Para
from assur.explain._position import Position, perp
from assur.explain._terms import LEVEL, SPEED, TURN, Term, sliding
from assur.explain._tex import (
    cramer,
    name,
    num,
    par,
    point_name,
    squared,
    text,
    vec,
)
from assur.groups._dyad import DyadSolver

__all__ = [
    "SPEED",
    "TURN",
    "Term",
    "body_points",
    "dyad_rates",
    "mid_name",
    "point_lines",
]


def _slide_sign(s: DyadSolver, b: int) -> float:
    """+1 when the slider of external pair ``b`` is the pair's second link."""
    return 1.0 if s.ext[b].second == s.bodies[b] else -1.0


def _rotation(s: DyadSolver, b: int, k: int, pos: Position) -> str | None:
    """Return the symbol of link b's unknown rotation rate, or None when known."""
    symbol = "\\omega" if k == 1 else "\\varepsilon"
    if s.mid.kind == "R":
        return f"{symbol}_{{{name(pos.link(s.bodies[b]))}}}"
    if s.ext[0].kind == "R" and s.ext[1].kind == "R":
        return f"{symbol}_{{{name(pos.link(s.mid.first))}}}"
    return None  # it turns with a guide already known


def _chain(
    pos: Position,
    s: DyadSolver,
    b: int,
    k: int,
    label: str | None = None,
    point: str | None = None,
) -> list[Term]:
    """Terms of the middle point's motion along link ``b`` from its outer joint.

    ``label`` names the middle point in the terms' symbols when it is not the
    joint's own name: the guide's point under a sliding middle pair (``B_{rocker}``,
    the textbook's B3 beside the slider's B2).
    """
    body, known, pair = s.bodies[b], s.known[b], s.ext[b]
    m = pos.pair_point(s.mid)
    j = name(pair.name)
    # the point's own name for lengths and directions, the label for vectors
    point = name(s.mid.name) if point is None else point
    mid = point if label is None else label
    letter = LEVEL[k][0]
    link = name(pos.link(body))
    w, eps = pos.omega(body), pos.epsilon(body)
    if pair.kind == "R":
        p = pos.point(known, s.d_known[b])
        r = m - p
        length = math.hypot(*r)
        base = Term(f"\\vec {letter}_{{{j}}}", pos.point(known, s.d_known[b], k))
        if length <= 1e-12 * pos.size():
            # the joint is at the pin itself: no arm, no motion relative to it
            return [base]
        if k == 1:
            return [
                base,
                Term(
                    f"\\vec v_{{{mid}{j}}}",
                    w * perp(r),
                    f"\\perp {j}{point}",
                    _rotation(s, b, 1, pos),
                    perp(r),
                    f"v_{{{mid}{j}}} = |\\omega_{{{link}}}| \\cdot l_{{{j}{point}}} = "
                    f"{num(abs(w))} \\cdot {num(length)} = "
                    f"{num(abs(w) * length)}{SPEED[1]}",
                ),
            ]
        return [
            base,
            Term(
                f"\\vec a^{{n}}_{{{mid}{j}}}",
                -w * w * r,
                f"\\text{{from }} {point} \\text{{ to }} {j},\\ a^n = "
                f"\\omega_{{{link}}}^2 l_{{{j}{point}}} = {squared(w)} \\cdot "
                f"{num(length)} = {num(w * w * length)}{SPEED[2]}",
            ),
            Term(
                f"\\vec a^{{t}}_{{{mid}{j}}}",
                eps * perp(r),
                f"\\perp {j}{point}",
                _rotation(s, b, 2, pos),
                perp(r),
                f"a^t_{{{mid}{j}}} = |\\varepsilon_{{{link}}}| \\cdot "
                f"l_{{{j}{point}}} = {num(abs(eps))} \\cdot {num(length)} = "
                f"{num(abs(eps) * length)}{SPEED[2]}",
            ),
        ]
    e = _slide_sign(s, b) * pos.turned(known, pair.axis or (1.0, 0.0))
    base_name = f"{point}_{{{name(pos.link(known))}}}"
    return sliding(pos, known, body, m, e, j, base_name, k)


Guide: TypeAlias = tuple[str, list[Term]] | None
"""The guide's point under a sliding middle pair, named, and the terms it sums."""


def _sides(
    pos: Position, s: DyadSolver, k: int
) -> tuple[list[Term], list[Term], Guide]:
    """Return the two sides of the middle joint's equation at level ``k``.

    With a sliding middle pair, also the guide link's point under it and its terms
    (the textbook's B3, whose motion the guide's other points start from).
    """
    if s.mid.kind == "R":
        return _chain(pos, s, 0, k), _chain(pos, s, 1, k), None
    g = 0 if s.bodies[0] == s.mid.first else 1
    m = pos.pair_point(s.mid)
    e = pos.turned(s.mid.first, s.mid.axis or (1.0, 0.0))
    j = name(s.mid.name)
    rel = sliding(pos, s.mid.first, s.mid.second, m, e, j, j, k)
    point = mid_name(pos, s)
    on_guide = f"{point}_{{{name(pos.link(s.mid.first))}}}"
    chain = _chain(pos, s, g, k, on_guide, point)
    return _chain(pos, s, 1 - g, k), chain + rel[1:], (on_guide, chain)


def mid_name(pos: Position, s: DyadSolver) -> str:
    """Return the middle point's name, the slider's pin's where it is at the slot.

    A block pinned at the slot's point (the Whitworth block's B in the lever's
    slot) is that pin: the point is B, the lever's point under it B_lever, not
    the sliding joint's name beside the pin's.
    """
    if s.mid.kind == "P":
        b = 1 if s.bodies[0] == s.mid.first else 0
        pair = s.ext[b]
        if pair.kind == "R":
            gap = pos.pair_point(s.mid) - pos.point(s.known[b], s.d_known[b])
            if math.hypot(*gap) <= 1e-12 * pos.size():
                return name(pair.name)
    return name(s.mid.name)


def _solve(left: list[Term], right: list[Term]) -> tuple[list[str], Array, Array]:
    """Return the unknowns, the 2x2 matrix and the right-hand side of the equation."""
    names: list[str] = []
    for t in left + right:
        if t.unknown is not None and t.unknown not in names:
            names.append(t.unknown)
    a = np.zeros((2, len(names)))
    rhs = np.zeros(2)
    for sign, side in ((1.0, left), (-1.0, right)):
        for t in side:
            if t.unknown is None:
                rhs -= sign * t.value
            else:
                assert t.column is not None
                a[:, names.index(t.unknown)] += sign * t.column
    return names, a, rhs


def _known_lines(t: Term, scale: float, k: int) -> list[str]:
    """Return the line of a known term: its working, value and what it is.

    A Coriolis term says its rule, direction and size on a line of its own, under
    its value: beside it, the line ran past the page's width.
    """
    line = (
        f"{t.tex} = "
        + (f"{t.working} = " if t.working else "")
        + f"{vec(t.value, scale)}{SPEED[k]}"
    )
    if not t.note:
        return [line]
    if t.own_line:
        return [line, f"\\qquad {t.note}"]
    return [f"{line},\\quad {t.note}"]


def _sum(terms: list[Term]) -> str:
    """Return the symbols of the terms joined by plus signs."""
    return " + ".join(t.tex for t in terms)


def dyad_rates(pos: Position, s: DyadSolver, k: int) -> list[Block]:
    """Return the velocity (k = 1) or acceleration (k = 2) analysis of dyad ``s``."""
    left, right, guide = _sides(pos, s, k)
    letter = LEVEL[k][0]
    mid = mid_name(pos, s)
    names, a, rhs = _solve(left, right)
    units = tuple(
        TURN[k] if n.startswith(("\\omega", "\\varepsilon")) else SPEED[k]
        for n in names
    )
    lines = cramer(names, a, rhs, (units[0], units[-1]))[0] if len(names) == 2 else []
    # every vector of the equation is judged against its largest term: one that
    # sums or solves to round-off of them is 0
    scale = max(math.hypot(*t.value) for t in left + right)
    blocks: list[Block] = [
        Para(f"The {LEVEL[k][1]} of the joint {text(s.mid.name)}, along each link:"),
        Display((f"{_sum(left)} = {_sum(right)}",)),
        Display(
            tuple(
                line
                for t in left + right
                if t.unknown is None
                for line in _known_lines(t, scale, k)
            )
            + tuple(
                f"{t.tex}:\\ {t.note}" for t in left + right if t.unknown is not None
            )
        ),
    ]
    if lines:
        blocks += [
            Para(
                "The unknowns are "
                + " and ".join(f"${n}$" for n in names)
                + "; in components, the known terms moved to the right:"
            ),
            Display(tuple(lines)),
        ]
    unknown = [t for t in left + right if t.unknown is not None]
    results = [
        f"{t.tex} = {vec(t.value, scale)}{SPEED[k]}"
        + (f",\\quad {t.size}" if t.size else "")
        for t in unknown
    ]
    if guide is not None and len(guide[1]) > 1:
        # the guide's point under the slider, which its other points start from
        point, chain = guide
        under = sum((t.value for t in chain), np.zeros(2))
        shown = f"{vec(under, scale)}{SPEED[k]}"
        results.append(f"\\vec {letter}_{{{point}}} = {_sum(chain)} = {shown}")
    # the middle point's motion summed along the side that has working to show: a
    # slider on a pin of a known link has its pin's motion alone on its side
    side = right if len(left) == 1 else left
    total = sum((t.value for t in side), np.zeros(2))
    results.append(
        f"\\vec {letter}_{{{mid}}} = {_sum(side)} = {vec(total, scale)}{SPEED[k]},"
        f"\\quad {letter}_{{{mid}}} = {num(math.hypot(*total), scale)}{SPEED[k]}"
    )
    blocks.append(Display(tuple(results)))
    return blocks


def body_points(pos: Position, body: int) -> list[tuple[str, tuple[float, float]]]:
    """Return the named points of ``body``: reported points and pins it carries.

    Each is ``(name, offset)``; a pin whose reported point moves with its other link
    is named too, since the next group needs its motion.
    """
    return pos.points_of(body)


def point_lines(
    pos: Position, body: int, base: Array, label: str, k: int, skip: set[str]
) -> list[str]:
    """Return the motion of each named point of ``body`` from its point ``base``.

    ``label`` names the base point in TeX; points named in ``skip`` are left out.
    """
    w, eps = pos.omega(body), pos.epsilon(body)
    link = name(pos.link(body))
    here = pos.coincident(body, base, k)
    lines = []
    for point, offset in body_points(pos, body):
        p = pos.point(body, offset)
        r = p - base
        if point in skip or math.hypot(*r) <= 1e-12 * pos.size():
            continue
        x = point_name(point)
        value = pos.point(body, offset, k)
        # the sum is judged against its terms: a fixed pivot reached through its
        # link sums to round-off, which is 0, not a vector of its own size
        arm = math.hypot(*r)
        terms = (abs(w),) if k == 1 else (abs(eps), w * w)
        scale = max(math.hypot(*here), *(t * arm for t in terms))
        if k == 1:
            lines.append(
                f"\\vec v_{{{x}}} = \\vec v_{{{label}}} + \\omega_{{{link}}}\\,\\vec k "
                f"\\times \\vec r_{{{label}{x}}} = {vec(here)} + {par(w)} \\cdot "
                f"\\vec k \\times {vec(r)} = {vec(value, scale)}{SPEED[1]},\\quad "
                f"v_{{{x}}} = "
                f"{num(math.hypot(*value), scale)}{SPEED[1]}"
            )
        else:
            lines.append(
                f"\\vec a_{{{x}}} = \\vec a_{{{label}}} + \\varepsilon_{{{link}}}\\,"
                f"\\vec k \\times \\vec r_{{{label}{x}}} - \\omega_{{{link}}}^2 "
                f"\\vec r_{{{label}{x}}} = {vec(here)} + {par(eps)} \\cdot \\vec k "
                f"\\times {vec(r)} - {squared(w)} "
                f"\\cdot {vec(r)} = {vec(value, scale)}{SPEED[2]},\\quad a_{{{x}}} = "
                f"{num(math.hypot(*value), scale)}{SPEED[2]}"
            )
    return lines
