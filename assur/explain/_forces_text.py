"""Each group's equilibrium in the reverse order, in the textbook's sequence.

A dyad with a revolute middle joint (RRR, RRP, PRP): each outer revolute reaction is
split into a normal part along its link and a tangential part across it; the moment
of each link about the middle joint gives the tangential part, the force polygon of
the group the two unknown magnitudes left, one link's force sum the middle reaction,
and a slider's moment where its guide's reaction acts. A dyad with a sliding middle
pair (RPR, RPP): the moments of each link about its outer pin (or a slider's force
sum along its guide) give the middle pair's normal force and couple, then each link's
force sum its outer reaction. Larger groups: the linear system of
:meth:`~assur.groups._protocol.Equilibrium.equations` with its numbers.
"""

from __future__ import annotations

import math

import numpy as np

from assur._vec import Array
from assur.explain._friction_text import normal_symbol, sliding_total
from assur.explain._group_friction_text import group_friction_blocks
from assur.explain._loads_text import (
    Load,
    components,
    force_lines,
    joint_text,
    link_loads,
    moment_line,
    total,
)
from assur.explain._locked_text import locked_blocks
from assur.explain._note import Block, Display, Heading, Para
from assur.explain._position import Position, cross, perp, unit
from assur.explain._tex import cramer, name, num, par, plain, segment, vec
from assur.explain._tex import unit as unit_text
from assur.explain._triad_text import system_blocks
from assur.groups._dyad import DyadSolver
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Equilibrium

__all__ = ["couple_blocks", "force_symbol", "forces_blocks"]

KNOWN = "\\sum \\vec F_{\\mathrm{known}}"
"""The sum of the known forces on a link or group (upright: a word)."""


def force_symbol(pos: Position, by: int, on: int) -> str:
    """Return the symbol of the force of link ``by`` on link ``on``: F_{by,on}."""
    return f"F_{{{name(pos.link(by))},{name(pos.link(on))}}}"


def _known(
    pos: Position, bodies: tuple[int, ...], loads: list[list[Load]]
) -> list[Block]:
    """List the known loads on each link of a group."""
    blocks: list[Block] = []
    for b, known in zip(bodies, loads, strict=True):
        lines = force_lines(known)
        if lines:
            blocks += [
                Para(f"Known loads on {plain(pos.link(b))}:"),
                Display(tuple(lines)),
            ]
    return blocks


def _revolute_middle(
    pos: Position, s: DyadSolver, loads: list[list[Load]]
) -> list[Block]:
    """RRR, RRP, PRP: tangential parts, the force polygon, the middle reaction."""
    big = pos.force_scale()  # round-off of a force is told by it
    m = pos.pair_point(s.mid)
    mid = name(s.mid.name)
    blocks: list[Block] = []
    known_t = np.zeros(2)
    dirs, names = [], []
    parts: list[tuple[str, Array, Array]] = []
    for b in (0, 1):
        body, pair, known = s.bodies[b], s.ext[b], s.known[b]
        symbol = force_symbol(pos, known, body)
        if pair.kind == "R":
            p = pos.point(known, s.d_known[b])
            u = unit(m - p)
            t = perp(u)
            length = math.hypot(*(m - p))
            line, total_m = moment_line(loads[b], m, mid)
            ft = total_m / length
            known_t += ft * t
            j = name(pair.name)
            blocks += [
                Para(
                    f"Moments of {plain(pos.link(body))} about {plain(s.mid.name)}: "
                    "the "
                    f"normal part $\\vec {symbol}^{{n}}$ (along "
                    f"{segment(plain(pair.name), plain(s.mid.name))}) and the "
                    f"reaction in {plain(s.mid.name)} "
                    f"pass through {plain(s.mid.name)}; the tangential part "
                    f"$\\vec {symbol}^{{t}} = {symbol}^{{t}}\\,\\vec t$, "
                    f"$\\vec t = {vec(t)}$ (the link's direction $\\vec u = {vec(u)}$ "
                    "turned by +90°), has the moment "
                    f"$-{symbol}^{{t}}\\,l_{{{j}{mid}}}$:"
                ),
                Display(
                    (
                        line,
                        f"{symbol}^{{t}} = \\frac{{\\sum M_{{{mid}}}}}"
                        f"{{l_{{{j}{mid}}}}}"
                        f" = \\frac{{{num(total_m)}}}{{{num(length)}}} = {num(ft)}\\ "
                        "\\mathrm{N}",
                    )
                ),
            ]
            dirs.append(u)
            names.append(f"{symbol}^{{n}}")
            parts.append((symbol, u, t * ft))
        else:
            e = pos.turned(known, pair.axis or (1.0, 0.0))
            n = perp(e)
            dirs.append(n)
            names.append(f"N_{{{name(pair.name)}}}")
            parts.append((symbol, n, np.zeros(2)))
    every = loads[0] + loads[1]
    rhs = -(total(every) + known_t)
    a = np.column_stack(dirs)
    lines, values = cramer(names, a, rhs, (unit_text("N"), unit_text("N")))
    # a PRP dyad's outer pairs slide: no tangential part was found
    turning = any(pair.kind == "R" for pair in s.ext)
    blocks += [
        Para(
            "Force polygon of the group: the known forces"
            + (", the tangential parts, and " if turning else " and ")
            + "two unknown magnitudes along known directions ("
            + ", ".join(
                f"${x}$ along ${vec(d)}$" for x, d in zip(names, dirs, strict=True)
            )
            + "):"
        ),
        Display(
            (
                KNOWN
                + (" + \\sum \\vec F^{t}" if turning else "")
                + f" = {vec(-rhs, big)}\\ \\mathrm{{N}}",
                *lines,
            )
        ),
    ]
    outer = []
    forces: list[Array] = []
    labels = []
    for b, ((symbol, d, tangential), x) in enumerate(zip(parts, values, strict=True)):
        f: Array = x * d + tangential
        forces.append(f)
        pair, body = s.ext[b], s.bodies[b]
        if pair.kind == "P" and pair.friction > 0.0:
            # the unknown was the normal force; the friction force adds along the slide
            outer.append(sliding_total(pos, pair, body, f, symbol))
            labels.append(normal_symbol(pair, body))
            continue
        labels.append(f"\\vec {symbol}")
        outer.append(
            f"\\vec {symbol} = {vec(f, big)}\\ \\mathrm{{N}},\\quad {symbol} = "
            f"{num(math.hypot(*f), big)}\\ \\mathrm{{N}}"
        )
    first = s.bodies[0]
    inner = -(total(loads[0]) + forces[0])
    sym = force_symbol(pos, s.bodies[1], first)
    blocks += [
        Display(tuple(outer)),
        Para(
            f"Force sum of {plain(pos.link(first))} gives the reaction in "
            f"{plain(s.mid.name)}:"
        ),
        Display(
            (
                f"\\vec {sym} = -\\left({KNOWN} + {labels[0]}"
                "\\right) = -\\left("
                f"{vec(total(loads[0]), big)}"
                f" + {vec(forces[0], big)}\\right) = {vec(inner, big)}\\ "
                "\\mathrm{N},\\quad "
                f"{sym} = {num(math.hypot(*inner), big)}\\ \\mathrm{{N}}",
            )
        ),
    ]
    for b in (0, 1):
        if s.ext[b].kind == "P":
            on_slider = -inner if b == 1 else inner
            middle = Load("", mid, m, on_slider)
            blocks += couple_blocks(pos, s.ext[b], s.bodies[b], loads[b] + [middle])
    return blocks


def couple_blocks(
    pos: Position, pair: PairPlan, body: int, loads: list[Load], normal: bool = False
) -> list[Block]:
    """Return the moment equation of a slider about its guide's point: the couple.

    With ``normal``, the normal force is derived here too (a group's was found by
    its force polygon before).
    """
    q = pos.pair_point(pair)
    j = name(pair.name)
    sign = 1.0 if pair.second == body else -1.0
    line, m = moment_line(loads, q, j)
    # the pair's couple and normal force are those of its first link on its second
    couple = -sign * m
    e = pos.turned(pair.first, pair.axis or (1.0, 0.0))
    force = -total(loads)
    across = sign * float(np.dot(force, perp(e)))
    minus = "-" if sign > 0 else ""
    shown = [
        line,
        f"M_{{{j}}} = {minus}\\sum M_{{{j}}} = {num(couple)}\\ \\mathrm{{N\\,m}}",
    ]
    # round-off is told against the loads at play, not against 1 N: a watch's
    # guide pressed by 4e-10 N (or a crank turning at 1e-3 rad/s) is pressed
    pressed = abs(across) > 1e-9 * max(pos.force_scale(), math.hypot(*force))
    if pressed:
        if normal:
            # the normal force, across the guide (n = k x e), said before it divides
            n = perp(e)
            shown.append(
                f"N_{{{j}}} = {minus}\\sum \\vec F \\cdot \\vec n = "
                f"{minus}{components(loads, n)} = {num(across)}\\ \\mathrm{{N}},"
                f"\\quad \\vec n = \\vec k \\times \\vec e = {vec(n)}"
            )
        shown.append(
            f"x_{{{j}}} = \\frac{{M_{{{j}}}}}{{N_{{{j}}}}} = \\frac{{{num(couple)}}}"
            f"{{{num(across)}}} = {num(couple / across)}\\ \\mathrm{{m}}"
        )
    return [
        Para(
            f"Moments of {plain(pos.link(body))} about the point of "
            f"{plain(pair.name)}: "
            f"the couple $M_{{{j}}}$ of the guide's reaction "
            + (
                f"(the normal force $N_{{{j}}}$ then acts $x_{{{j}}}$ along the guide "
                "from that point)"
                if pressed
                else f"(the normal force $N_{{{j}}}$ is zero here: the guide's "
                "reaction is that couple alone, borne as two equal and opposite "
                "normal forces at the slider's ends)"
                if num(couple, pos.force_scale() * pos.size()) != "0"
                else f"(the normal force $N_{{{j}}}$ is zero here, and so is the "
                "couple: the guide carries no load)"
            )
            + (
                ""
                if sign > 0
                else "; the slider is the pair's first link: the couple on it "
                f"is $-M_{{{j}}}$"
            )
            + ":"
        ),
        Display(tuple(shown)),
    ]


def _sliding_middle(
    pos: Position, s: DyadSolver, loads: list[list[Load]]
) -> list[Block]:
    """RPR, RPP: the middle pair's normal force and couple, then outer reactions."""
    big = pos.force_scale()  # round-off of a force is told by it
    q = pos.pair_point(s.mid)
    e = pos.turned(s.mid.first, s.mid.axis or (1.0, 0.0))
    nm = perp(e)
    j = name(s.mid.name)
    rows, rhs, lines = [], [], []
    for b in (0, 1):
        body, pair, known = s.bodies[b], s.ext[b], s.known[b]
        sgn = 1.0 if body == s.mid.second else -1.0
        if pair.kind == "R":
            p = pos.point(known, s.d_known[b])
            line, total_m = moment_line(loads[b], p, name(pair.name))
            arm = cross(q - p, nm)
            rows.append([sgn * arm, sgn])
            rhs.append(-total_m)
            lines += [
                line,
                f"{par(sgn * arm)}\\,N_{{{j}}} + {par(sgn)}\\,M_{{{j}}} = "
                f"{num(-total_m)}",
            ]
        else:
            eb = pos.turned(known, pair.axis or (1.0, 0.0))
            along = float(np.dot(total(loads[b]), eb))
            rows.append([sgn * float(np.dot(nm, eb)), 0.0])
            rhs.append(-along)
            lines.append(
                f"\\sum F \\cdot \\vec e = {num(along)},\\quad "
                f"{par(sgn * float(np.dot(nm, eb)))}\\,N_{{{j}}} + 0\\,M_{{{j}}} = "
                f"{num(-along)}"
            )
    solved_lines, (normal, couple) = cramer(
        [f"N_{{{j}}}", f"M_{{{j}}}"],
        np.array(rows),
        np.array(rhs),
        (unit_text("N"), unit_text("N\\,m")),
    )
    blocks: list[Block] = [
        Para(
            f"The sliding pair {plain(s.mid.name)} presses across its slide line "
            f"(normal $\\vec n = {vec(nm)}$, force $N_{{{j}}}$ of "
            f"{plain(pos.link(s.mid.first))} on {plain(pos.link(s.mid.second))} at "
            f"$\\vec r_{{{j}}} = {vec(q)}$) with a couple $M_{{{j}}}$. One equation "
            "per link leaves the outer reactions out: moments about its outer pin, or "
            "forces along its guide:"
        ),
        Display(tuple(lines)),
        Display(tuple(solved_lines[2:])),
    ]
    for b in (0, 1):
        body, pair, known = s.bodies[b], s.ext[b], s.known[b]
        sgn = 1.0 if body == s.mid.second else -1.0
        middle = Load("", j, q, sgn * normal * nm, sgn * couple)
        f = -(total(loads[b]) + middle.force)
        symbol = force_symbol(pos, known, body)
        # the middle pair pushes its first link with -N n
        pushed = f"{'+' if sgn > 0.0 else '-'} N_{{{j}}}\\vec n"
        sums: tuple[str, ...] = (
            f"\\vec {symbol} = -\\left({KNOWN} {pushed}\\right) = "
            f"{vec(f, big)}\\ \\mathrm{{N}},\\quad {symbol} = "
            f"{num(math.hypot(*f), big)}\\ \\mathrm{{N}}",
        )
        if pair.kind == "P" and pair.friction > 0.0:
            # the known loads hold the guide's friction: what is left is its normal
            sums = (
                f"{normal_symbol(pair, body)} = -\\left({KNOWN} "
                f"{pushed}\\right) = {vec(f, big)}\\ \\mathrm{{N}}",
                sliding_total(pos, pair, body, f, symbol),
            )
        blocks += [Para(f"Force sum of {plain(pos.link(body))}:"), Display(sums)]
        if pair.kind == "P":
            blocks += couple_blocks(pos, pair, body, [*loads[b], middle])
    return blocks


def _totals(pos: Position, rec: Equilibrium) -> list[str]:
    """Return every reaction the group solved, as the force of one link on another."""
    big = pos.force_scale()  # round-off of a force is told by it
    lines = []
    for pair in rec.pairs:
        r = rec.reactions[pair.name]
        f = np.array([float(np.ravel(r.fx)[0]), float(np.ravel(r.fy)[0])])
        symbol = force_symbol(pos, pair.first, pair.second)
        if pair.kind == "P" and pair.friction > 0.0:
            line = sliding_total(pos, pair, pair.second, f, symbol)
        else:
            line = (
                f"\\vec {symbol} = {vec(f, big)}\\ \\mathrm{{N}},\\quad {symbol} = "
                f"{num(math.hypot(*f), big)}\\ \\mathrm{{N}}"
            )
        if pair.kind == "P":
            line += (
                f",\\quad M_{{{name(pair.name)}}} = "
                f"{num(float(np.ravel(r.couple)[0]))}\\ \\mathrm{{N\\,m}}"
            )
        lines.append(line + f"\\quad \\text{{({joint_text(pos, pair.name)})}}")
    return lines


def forces_blocks(pos: Position) -> list[Block]:
    """Return the reverse pass: each group's equilibrium, last group first."""
    assert pos.result is not None
    plan = pos.plan
    blocks: list[Block] = [
        Heading(2, "4. Reactions, group by group in the reverse order"),
        Para(
            "$\\vec F_{i,j}$ is the force of link $i$ on link $j$ ($\\vec F_{j,i} = "
            "-\\vec F_{i,j}$); a sliding pair's couple $M$ is taken about its point "
            "(moving with its second link). Moments are counter-clockwise positive. "
            "Among the known loads, $\\vec F_{i,L}$ and $M_{i,L}$ are link $L$'s "
            "inertia force and torque (the $i$ for inertia, not a link), and "
            "$\\vec Q_{L,k}$ and $T_{L,k}$ the file's $k$-th external force or "
            "torque on $L$."
        ),
    ]
    solver_of = {s.bodies: s for s in plan.solvers}
    solved: set[int] = set()
    for k, rec in enumerate(pos.result.groups):
        solver = solver_of[rec.bodies]
        blocks.append(Heading(3, f"Group {plain(solver.label)}"))
        if rec.label == pos.locked:
            # its own friction has no size: the known loads without it
            loads = [link_loads(pos, b, solved) for b in rec.bodies]
            later = len(pos.result.groups) - k - 1
            blocks += _known(pos, rec.bodies, loads)
            blocks += locked_blocks(pos, rec, solver, later)
            break
        blocks += group_friction_blocks(pos, rec, solver)
        names = {p.name for p in rec.pairs}
        loads = [link_loads(pos, b, solved, names) for b in rec.bodies]
        blocks += _known(pos, rec.bodies, loads)
        if isinstance(solver, DyadSolver) and solver.mid.kind == "R":
            blocks += _revolute_middle(pos, solver, loads)
        elif isinstance(solver, DyadSolver):
            blocks += _sliding_middle(pos, solver, loads)
        else:
            blocks += system_blocks(pos, rec)
        blocks += [Para("The group's reactions:"), Display(tuple(_totals(pos, rec)))]
        solved |= set(rec.bodies)
    return blocks
