"""The position problem of a dyad, in the closed form of its kind, with the numbers.

Each kind's closed form is the one its solver uses (:mod:`assur.groups.rrr` and its
siblings); the numbers are read from the solved motions, so every equation printed
holds for the pose the tables give.
"""

from __future__ import annotations

import math

import numpy as np

from assur._vec import Array
from assur.explain._note import Block, Display, Para
from assur.explain._position import Position, cross, perp
from assur.explain._tex import (
    LENGTH,
    deg,
    half_turn,
    name,
    num,
    par,
    plain,
    squared,
    unit,
    vec,
)
from assur.groups._dyad import DyadSolver

__all__ = ["dyad_positions"]

M = unit(LENGTH[0])
"""The unit of a length or a position, after a result."""


def _sq(x: float) -> str:
    """Return ``x`` squared as TeX (see :func:`~assur.explain._tex.squared`)."""
    return squared(x)


def _called(kind: str, name: str) -> str:
    """Return "the guide A", or "the guide" alone for a guide named "guide"."""
    return f"the {kind}" if name.lower() == kind else f"the {kind} {plain(name)}"


def _known(pos: Position, s: DyadSolver) -> list[Block]:
    """Say what is known: the outer joints' positions."""
    parts = []
    for b in (0, 1):
        pair = s.ext[b]
        p = pos.point(s.known[b], s.d_known[b])
        on = plain(pos.link(s.known[b]))
        if pair.kind == "R":
            parts.append(
                f"the pin $\\vec r_{{{name(pair.name)}}} = {vec(p)}$ m on {on}"
            )
        else:
            e = pos.turned(s.known[b], pair.axis or (1.0, 0.0))
            parts.append(
                f"{_called('guide', pair.name)} of {on} through ${vec(p)}$ m along "
                f"$\\vec e_{{{name(pair.name)}}} = {vec(e)}$"
            )
    return [Para("Known from the links before: " + "; ".join(parts) + ".")]


def _rrr(pos: Position, s: DyadSolver) -> list[Block]:
    b, d, c = (name(x) for x in (s.ext[0].name, s.ext[1].name, s.mid.name))
    pb = pos.point(s.known[0], s.d_known[0])
    pd = pos.point(s.known[1], s.d_known[1])
    pc = pos.pair_point(s.mid)
    l1, l2 = (math.hypot(*x) for x in s.d_mid)
    g = pd - pb
    dist = math.hypot(*g)
    e = g / dist
    a = (l1 * l1 - l2 * l2 + dist * dist) / (2 * dist)
    h = float(np.dot(pc - pb, perp(e)))
    sign = "+" if h >= 0 else "-"
    return [
        Para(
            f"The pin {plain(s.mid.name)} lies on two circles, of radius "
            f"$l_{{{b}{c}}} = {num(l1)}$ m about {plain(s.ext[0].name)} and "
            f"$l_{{{d}{c}}} = {num(l2)}$ m about {plain(s.ext[1].name)}; the branch "
            "is the reference pose's."
        ),
        Display(
            (
                f"d = |{b}{d}| = \\sqrt{{{_sq(g[0])} + {_sq(g[1])}}} = {num(dist)}{M}",
                f"a = \\frac{{l_{{{b}{c}}}^2 - l_{{{d}{c}}}^2 + d^2}}{{2d}} = "
                f"\\frac{{{_sq(l1)} - {_sq(l2)} + {_sq(dist)}}}{{2 \\cdot {num(dist)}}}"
                f" = {num(a)}{M}",
                f"h = {sign}\\sqrt{{l_{{{b}{c}}}^2 - a^2}} = {sign}\\sqrt{{{_sq(l1)} - "
                f"{_sq(a)}}} = {num(h)}{M}",
                f"\\vec e = \\frac{{\\vec r_{{{d}}} - \\vec r_{{{b}}}}}{{d}} = "
                f"{vec(e)}",
                f"\\vec r_{{{c}}} = \\vec r_{{{b}}} + a\\,\\vec e + "
                "h\\,\\vec e^{\\perp}"
                f" = {vec(pb)} + {par(a)} \\cdot {vec(e)} + {par(h)} \\cdot "
                f"{vec(perp(e))} = {vec(pc)}{M}",
            )
        ),
    ]


def _rrp(pos: Position, s: DyadSolver) -> list[Block]:
    b, c = name(s.ext[0].name), name(s.mid.name)
    pb = pos.point(s.known[0], s.d_known[0])
    pc = pos.pair_point(s.mid)
    e = pos.turned(s.known[1], s.ext[1].axis or (1.0, 0.0))
    c0 = pos.point(s.known[1], s.d_known[1]) + pos.turned(s.bodies[1], s.d_mid[1])
    length = math.hypot(*s.d_mid[0])
    w = c0 - pb
    we, ww = float(np.dot(w, e)), float(np.dot(w, w))
    slide = float(np.dot(pc - c0, e))
    root = math.sqrt(max(we * we - ww + length * length, 0.0))
    sign = "+" if slide + we >= 0 else "-"
    return [
        Para(
            f"The pin {plain(s.mid.name)} lies on the circle of radius "
            f"$l_{{{b}{c}}} = {num(length)}$ m about {plain(s.ext[0].name)} and on "
            f"the line $\\vec r_{{{c}}} = \\vec r_{{{c}_0}} + s\\,\\vec e$ that "
            f"{_called('slider', pos.link(s.bodies[1]))} runs along, with "
            f"$\\vec r_{{{c}_0}} = {vec(c0)}$ m (where the pin is at $s = 0$) and "
            f"$\\vec e = {vec(e)}$."
        ),
        Display(
            (
                f"\\vec w = \\vec r_{{{c}_0}} - \\vec r_{{{b}}} = {vec(w)}{M},\\quad "
                f"\\vec w \\cdot \\vec e = {num(we)}{M},\\quad {{|\\vec w|}}^2 = "
                f"{num(ww)}{unit('m^2')}",
                f"s = -\\vec w \\cdot \\vec e {sign} \\sqrt{{"
                f"{{(\\vec w \\cdot \\vec e)}}^2 - {{|\\vec w|}}^2 + "
                f"l_{{{b}{c}}}^2}} = -{par(we)} {sign} \\sqrt{{"
                f"{_sq(we)} - {num(ww)} + {_sq(length)}}} = {num(slide)}{M}",
                f"\\vec r_{{{c}}} = \\vec r_{{{c}_0}} + s\\,\\vec e = {vec(c0)} + "
                f"{par(slide)} \\cdot {vec(e)} = {vec(pc)}{M}",
            )
        ),
        Para(
            f"The sign before the root (${sign}$, the root being ${num(root)}$ m) is "
            "the reference pose's branch."
        ),
    ]


def _prp(pos: Position, s: DyadSolver) -> list[Block]:
    c = name(s.mid.name)
    pc = pos.pair_point(s.mid)
    starts, dirs = [], []
    for b in (0, 1):
        start = pos.point(s.known[b], s.d_known[b]) + pos.turned(
            s.bodies[b], s.d_mid[b]
        )
        starts.append(start)
        dirs.append(pos.turned(s.known[b], s.ext[b].axis or (1.0, 0.0)))
    w = starts[1] - starts[0]
    det = cross(dirs[0], dirs[1])
    s1, s2 = cross(w, dirs[1]) / det, cross(w, dirs[0]) / det
    return [
        Para(
            f"The pin {plain(s.mid.name)} is where the two slide lines cross: "
            f"$\\vec r_{{{c}}} = \\vec r_1 + s_1 \\vec e_1 = \\vec r_2 + s_2 "
            f"\\vec e_2$ with $\\vec r_1 = {vec(starts[0])}$, $\\vec e_1 = "
            f"{vec(dirs[0])}$, $\\vec r_2 = {vec(starts[1])}$, $\\vec e_2 = "
            f"{vec(dirs[1])}$; crossing with $\\vec e_2$ and $\\vec e_1$:"
        ),
        Display(
            (
                f"\\vec w = \\vec r_2 - \\vec r_1 = {vec(w)}{M},\\quad "
                f"\\vec e_1 \\times \\vec e_2 = {num(det)}",
                "s_1 = \\frac{\\vec w \\times \\vec e_2}"
                "{\\vec e_1 \\times \\vec e_2}"
                f" = \\frac{{{num(cross(w, dirs[1]))}}}{{{num(det)}}} = {num(s1)}{M},"
                "\\quad"
                " s_2 = \\frac{\\vec w \\times \\vec e_1}"
                "{\\vec e_1 \\times \\vec e_2}"
                f" = \\frac{{{num(cross(w, dirs[0]))}}}{{{num(det)}}} = {num(s2)}{M}",
                f"\\vec r_{{{c}}} = \\vec r_1 + s_1 \\vec e_1 = {vec(pc)}{M}",
            )
        ),
    ]


def _rpr(pos: Position, s: DyadSolver) -> list[Block]:
    g = 0 if s.bodies[0] == s.mid.first else 1
    h = 1 - g
    pg = pos.point(s.known[g], s.d_known[g])
    ph = pos.point(s.known[h], s.d_known[h])
    dvec = ph - pg
    dist = math.hypot(*dvec)
    n0 = s.mid.normal
    dg, dh = s.d_mid[g], s.d_mid[h]
    c0 = n0[0] * (dg[0] - dh[0]) + n0[1] * (dg[1] - dh[1])
    psi = math.acos(max(-1.0, min(1.0, c0 / dist)))
    # as the line below writes it: the sum with psi starts from the same angle
    theta = half_turn(math.atan2(dvec[1], dvec[0]))
    nu = math.atan2(n0[1], n0[0])
    turn = pos.angle(s.bodies[g]) - float(pos.plan.angle0[s.bodies[g]])
    normal = theta - psi
    sign = "-"
    if abs(math.remainder(normal - nu - turn, 2 * math.pi)) > 1e-6:
        normal, sign = theta + psi, "+"
    lg = plain(pos.link(s.bodies[g]))
    pgn, phn = name(s.ext[g].name), name(s.ext[h].name)
    # the links' names in the formula are set as names, not words
    ng, nh = (name(pos.link(s.bodies[x])) for x in (g, h))
    return [
        Para(
            f"Both links turn together (the sliding pair {plain(s.mid.name)} keeps "
            "the angle between them: their angles below differ by a constant, each "
            "measured along its own axis, or as its turn from the reference pose for "
            "a link without one). Across the slide line, along its normal (fixed in "
            f"{lg}), "
            f"the pins {plain(s.ext[g].name)} and {plain(s.ext[h].name)} stay "
            f"$c_0 = \\vec n_0 \\cdot (\\vec d_{{{ng}}} - \\vec d_{{{nh}}}) = "
            f"{num(c0)}$ m apart (the offsets $\\vec d$ of the pair's point from each "
            "pin, and the slide line's normal $\\vec n_0$, at angle "
            f"$\\nu = {deg(nu)}$, in the reference pose):"
        ),
        Display(
            (
                f"\\vec D = \\vec r_{{{phn}}} - \\vec r_{{{pgn}}} = "
                f"{vec(dvec)}{M},\\quad "
                f"|\\vec D| = {num(dist)}{M},\\quad \\theta_D = {deg(theta)}",
                "\\psi = \\arccos\\frac{c_0}{|\\vec D|} = "
                f"\\arccos\\frac{{{num(c0)}}}"
                f"{{{num(dist)}}} = {deg(psi)}",
                f"\\theta_n = \\theta_D {sign} \\psi = "
                f"{_angle_sum(theta, sign, psi, wrap=False)},\\quad "
                "\\Delta\\varphi = \\theta_n - \\nu = "
                f"{_angle_sum(normal, '-', nu, wrap=True)}",
            )
        ),
        Para(
            "$\\Delta\\varphi$ is the turn of both links from the reference pose; the "
            "sign before $\\psi$ is the reference pose's branch."
        ),
    ]


def _angle_sum(a: float, sign: str, b: float, wrap: bool) -> str:
    r"""Return ``a + b`` (``sign`` "+") or ``a - b`` in degrees, worked out.

    The operands (``b`` within (-180, 180], ``a`` as the line before left it), their
    plain sum, and with ``wrap``, where that leaves (-180, 180], the same turn with
    the whole turn that brings it back: a reader adding 92.5 and 90 must find 182.5,
    not the -177.5 it stands for. The whole turn is added after the sum, as a turn
    of its own ("-186.78, the same turn as -186.78 + 360 = 173.22"): written on in
    the chain of equalities, "= -186.78 + 360 = 173.22" equated two angles a whole
    turn apart.
    """
    b = half_turn(b)  # summed as it is written: -180 is written and summed 180
    total = a + b if sign == "+" else a - b
    first = f"{num(math.degrees(a))}^\\circ"
    second = deg(b)
    if second.startswith("-"):
        second = f"({second})"
    text = f"{first} {sign} {second} = {num(math.degrees(total))}^\\circ"
    turns = math.degrees(total - math.remainder(total, 2 * math.pi))
    if wrap and abs(turns) > 1.0:  # a whole turn, never a fraction of one
        back = "-" if turns > 0 else "+"
        summed = f"{num(math.degrees(total))}^\\circ"
        text += (
            f",\\ \\text{{the same turn as}}\\ {summed} {back} "
            f"{num(abs(turns))}^\\circ = {deg(total)}"
        )
    return text


def _rpp(pos: Position, s: DyadSolver) -> list[Block]:
    k = s.known[1]
    turn = pos.angle(k) - float(pos.plan.angle0[k])
    first, second = s.mid.first, s.mid.second
    n = pos.turned(first, s.mid.normal)
    e = pos.turned(k, s.ext[1].axis or (1.0, 0.0))
    slide = _own(pos, s.bodies[1])
    q2 = pos.point(second, s.mid.d_second) - _moved(pos, s, second, slide, e)
    q1 = pos.point(first, s.mid.d_first) - _moved(pos, s, first, slide, e)
    r0 = float(np.dot(n, q2 - q1))
    # the slide moves the pair's point on the slider: its gap grows by +n.e per
    # unit of s when the slider is the pair's second link, by -n.e when its first
    ahead = second == s.bodies[1]
    ne = float(np.dot(n, e)) * (1.0 if ahead else -1.0)
    return [
        Para(
            f"Both links turn with the guide of {plain(pos.link(k))} (the two sliding "
            f"pairs keep their angles): $\\Delta\\varphi = {deg(turn)}$. The slide "
            f"$s$ of {plain(pos.link(s.bodies[1]))} along $\\vec e = {vec(e)}$ must "
            f"bring the pair {plain(s.mid.name)} onto its slide line, normal "
            f"$\\vec n = {vec(n)}$: the gap at $s = 0$ is $r_0 = {num(r0)}$ m, so"
        ),
        Display(
            (
                f"s = -\\frac{{r_0}}{{{'' if ahead else '-'}\\vec n \\cdot \\vec e}} = "
                f"-\\frac{{{num(r0)}}}{{{num(ne)}}} = {num(slide)}{M}",
            )
        ),
    ]


def _own(pos: Position, body: int) -> float:
    """Return a slider's own coordinate (its slide along its guide), m."""
    m = pos.bodies[body]
    return float(np.asarray(m.q[0], dtype=float).reshape(-1)[0]) if m.q else 0.0


def _moved(pos: Position, s: DyadSolver, body: int, slide: float, e: Array) -> Array:
    """Return how far ``body`` has moved with the slide ``slide`` (the slider only)."""
    return slide * e if body == s.bodies[1] else np.zeros(2)


KINDS = {"RRR": _rrr, "RRP": _rrp, "PRP": _prp, "RPR": _rpr, "RPP": _rpp}


def dyad_positions(pos: Position, s: DyadSolver) -> list[Block]:
    """Return the position problem of dyad ``s`` with its numbers and the angles."""
    blocks = _known(pos, s) + KINDS[s.kind](pos, s)
    angles = [
        f"\\varphi_{{{name(pos.link(b))}}} = {deg(pos.angle(b))}" for b in s.bodies
    ]
    blocks.append(Display((",\\quad ".join(angles),)))
    return blocks
