r"""Friction in the note: each pair's friction load, and how a group was solved.

A revolute pair resists the relative rotation of its links with the couple
:math:`M_f = -\rho\,|R|\,\mathrm{sgn}(\omega_2 - \omega_1)`, :math:`\rho = f r` the
radius of its friction circle; a sliding pair resists the slide with the force
:math:`F_f = -f\,|N|\,\mathrm{sgn}\,\dot s` along its slide line. Both depend on the
reactions being found, so :mod:`assur._friction` solves a group with friction by
Newton's method on its reactions' sizes. The note shows the hand method instead,
repeated substitution from the frictionless sizes, a row a step (and, where that
settles slowly, near self-locking, the sizes Newton's method found), then writes the
friction loads of the sizes found: the group's equations hold with those loads as
known ones.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from assur._friction import Still, rate, solve_group, still, substituted
from assur._newton import QUICK
from assur._vec import Array
from assur.explain._note import Block, Display, Grid, Para
from assur.explain._position import Position, at, perp, value
from assur.explain._tex import name, num, par, plain, vec
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Equilibrium, GroupSolver, Reaction, Wrench
from assur.kinetostatics import Applied, with_friction

SETTLED = 1e-6
"""A step of repeated substitution that changes no size by more than this share of
the largest has settled (the note writes four or five digits)."""
MOST_STEPS = 12
"""Most steps of repeated substitution the note writes."""

__all__ = [
    "at_rest",
    "driver_friction",
    "friction_lines",
    "group_friction_blocks",
    "newton_start",
    "normal_force",
    "normal_symbol",
    "power_rows",
    "rate_line",
    "rubbing",
    "size_symbol",
    "sliding_total",
]


def rubbing(pairs: tuple[PairPlan, ...] | list[PairPlan]) -> list[PairPlan]:
    """Return the pairs with friction."""
    return [p for p in pairs if p.friction > 0.0]


def normal_force(pos: Position, pair: PairPlan, reaction: Reaction) -> Array:
    """Return a reaction's force without its friction, N (a revolute one whole)."""
    f = at(reaction.fx, reaction.fy)
    if pair.kind == "R":
        return f
    n = perp(pos.turned(pair.first, pair.axis or (1.0, 0.0)))
    return float(np.dot(f, n)) * n


def at_rest(pos: Position) -> Still:
    """Return the speeds below which a pair is at rest, as the reverse pass has them."""
    return still(pos.bodies, pos.plan.scale)


def _rate(pos: Position, pair: PairPlan) -> float:
    """Return the relative rotation (rad/s) or slide speed (m/s) friction opposes.

    Zero where the pair is at rest (below the reverse pass's threshold): it then has
    no friction.
    """
    return value(rate(pair, pos.bodies, at_rest(pos)))


def rate_line(pos: Position, pair: PairPlan) -> str:
    """Return the relative motion a pair's friction opposes, with its numbers."""
    if pair.kind == "P":
        return (
            f"\\dot s_{{{name(pair.name)}}} = {num(_rate(pos, pair))}\\ \\mathrm{{m/s}}"
        )
    second, first = (name(pos.link(b)) for b in (pair.second, pair.first))
    w2, w1 = pos.omega(pair.second), pos.omega(pair.first)
    return (
        f"\\omega_{{{second}}} - \\omega_{{{first}}} = {num(w2)} - {par(w1)} = "
        f"{num(w2 - w1)}\\ \\mathrm{{rad/s}}"
    )


def friction_lines(pos: Position, pair: PairPlan, size: str, known: float) -> list[str]:
    """Return a pair's friction load with its numbers.

    ``size`` is the TeX of the size of the pair's reaction (``F_{crank,rod}``, or
    ``|N_{guide}|``) the friction is taken from and ``known`` its value (N): the final
    reaction's.
    """
    assert pos.result is not None
    j = name(pair.name)
    sense = float(np.sign(_rate(pos, pair)))
    found = value(pos.result.friction.get(pair.name, 0.0))
    f = num(pair.friction)
    # a pair whose links do not move on each other: the law gives 0, said why
    still = (
        r"\quad \text{(no relative motion: no kinetic friction)}" if not sense else ""
    )
    if pair.kind == "R":
        rho = pair.friction * pair.radius
        second, first = (name(pos.link(b)) for b in (pair.second, pair.first))
        return [
            f"\\rho_{{{j}}} = f_{{{j}}} r_{{{j}}} = {f} \\cdot {num(pair.radius)} = "
            f"{num(rho)}\\ \\mathrm{{m}}",
            rate_line(pos, pair),
            f"M_{{f,{j}}} = -\\rho_{{{j}}}\\,{size}\\,\\mathrm{{sgn}}"
            f"(\\omega_{{{second}}} - \\omega_{{{first}}}) = -{num(rho)} \\cdot "
            f"{num(known)} \\cdot {par(sense)} = {num(found)}\\ \\mathrm{{N\\,m}}"
            + still,
        ]
    return [
        rate_line(pos, pair),
        f"F_{{f,{j}}} = -f_{{{j}}}\\,{size}\\,\\mathrm{{sgn}}\\,\\dot s_{{{j}}} = "
        f"-{f} \\cdot {num(known)} \\cdot {par(sense)} = {num(found)}"
        "\\ \\mathrm{N}" + still,
    ]


def size_symbol(pos: Position, pair: PairPlan) -> str:
    """Return the TeX of the size friction is taken from: ``F_{a,b}`` or ``|N_J|``."""
    if pair.kind == "P":
        return f"|N_{{{name(pair.name)}}}|"
    return f"F_{{{name(pos.link(pair.first))},{name(pos.link(pair.second))}}}"


def newton_start(
    pos: Position, rec: Equilibrium, solver: GroupSolver
) -> tuple[dict[str, float], int]:
    """Return the sizes Newton's method started from (N) and its number of steps.

    The start is the group solved without its own pairs' friction (the friction
    the groups solved before passed on is kept): ``rec.loads`` less those pairs'
    friction. The iteration is run again from there, as the reverse pass ran it.
    """
    loads = _without_own(pos, rec)
    base = solver.equilibrium(pos.bodies, loads)
    found = solve_group(solver, pos.bodies, loads, 1, at_rest(pos))
    sizes = {
        p.name: float(np.hypot(*normal_force(pos, p, base.reactions[p.name])))
        for p in rubbing(rec.pairs)
    }
    return sizes, 0 if found is None else found.iterations


def _without_own(pos: Position, rec: Equilibrium) -> list[Wrench]:
    """Return the loads on every link, the group's own pairs' friction taken off."""
    assert pos.result is not None
    count = len(pos.plan.bodies)
    loads: list[Wrench] = [[0.0, 0.0, 0.0] for _ in range(count)]
    for body, load in zip(rec.bodies, rec.loads, strict=True):
        loads[body] = list(load)
    own = {
        p.name: -np.asarray(pos.result.friction[p.name], dtype=float)
        for p in rubbing(rec.pairs)
        if p.name in pos.result.friction
    }
    # the friction of the group's own pairs taken off its links' loads
    start = with_friction(pos.plan, pos.bodies, Applied(tuple(loads), ()), own)
    return list(start.wrenches)


def substitution(
    pos: Position, rec: Equilibrium, solver: GroupSolver, start: dict[str, float]
) -> list[dict[str, float]]:
    """Return the sizes (N) of repeated substitution from ``start``, step by step.

    Each step takes the friction loads of the sizes before, solves the group with
    them known and takes the sizes of the reactions it gives; it stops once a step
    changes no size by more than :data:`SETTLED` of the largest, or after
    :data:`MOST_STEPS` steps (near self-locking it settles slowly or not at all).
    """
    loads, rest = _without_own(pos, rec), at_rest(pos)
    pairs = rubbing(rec.pairs)
    steps = [start]
    for _ in range(MOST_STEPS):
        found = substituted(solver, pos.bodies, loads, steps[-1], rest)
        sizes = {
            p.name: float(np.hypot(*normal_force(pos, p, found.reactions[p.name])))
            for p in pairs
        }
        steps.append(sizes)
        change = max(abs(sizes[k] - steps[-2][k]) for k in sizes)
        if not change > SETTLED * max(max(sizes.values()), 1e-300):
            break
    return steps


def group_friction_blocks(
    pos: Position, rec: Equilibrium, solver: GroupSolver
) -> list[Block]:
    """Return how a group with friction was solved, and its pairs' friction loads."""
    pairs = rubbing(rec.pairs)
    if not pairs:
        return []
    start, steps = newton_start(pos, rec, solver)
    listed = ", ".join(plain(p.name) for p in pairs)
    lines: list[str] = []
    final = {}
    for p in pairs:
        symbol = size_symbol(pos, p)
        final[p.name] = float(np.hypot(*normal_force(pos, p, rec.reactions[p.name])))
        lines += friction_lines(pos, p, symbol, final[p.name])
    tried = substitution(pos, rec, solver, start)
    gap = max(abs(tried[-1][k] - final[k]) for k in final)
    settled = gap <= 1e-4 * max(max(final.values()), 1e-300)
    # each law the group's pairs have: a group rubbing in guides alone has no couple
    laws = []
    if any(p.kind == "R" for p in pairs):
        laws.append(
            "a revolute pair's couple of its first link on its second $M_f = "
            "-\\rho\\,|R|\\,\\mathrm{sgn}(\\omega_2 - \\omega_1)$ ($\\rho = f r$, "
            "the radius of its friction circle, to which the reaction's line is "
            "then tangent; $\\omega_2 - \\omega_1$ the rotation of its second link "
            "relative to its first)"
        )
    if any(p.kind == "P" for p in pairs):
        laws.append(
            "a sliding pair's force of its first link on its second $F_f = "
            "-f\\,|N|\\,\\mathrm{sgn}\\,\\dot s$ along its slide line ($\\dot s$ "
            "the slide of its second link relative to its first; its couple $M$ "
            "makes none in this model)"
        )
    head = ("step", *(f"${size_symbol(pos, p)}$" for p in pairs))
    rows = [
        (
            "0 (frictionless)" if i == 0 else str(i),
            *(f"${num(sizes[p.name])}$" for p in pairs),
        )
        for i, sizes in enumerate(tried)
    ]
    if settled:
        how = (
            "The sizes settle; Newton's method on them, which the analysis uses, "
            f"finds the same in {_newton_steps(steps)}."
        )
    else:
        rows.append(("found", *(f"${num(final[p.name])}$" for p in pairs)))
        how = _unsettled(tried, steps)
    return [
        Para(
            f"Friction in {listed}: {', '.join(laws)} (kinetic friction only: a "
            "pair at rest has none). Each depends on the size of a reaction not "
            "yet known. With the senses of the relative motions known, each "
            "friction load is its size times a known factor, and the reactions "
            "are linear in the friction loads; but a reaction's size is not linear "
            "in its components, so the sizes are found by repeated substitution. "
            "Start from the sizes without this group's friction, take the friction "
            "loads of those sizes as known loads, solve the group as without "
            "friction, take the sizes of the reactions it gives, and repeat (sizes "
            "in N):"
        ),
        Grid(head, tuple(rows)),
        Para(how + " The friction loads of these sizes:"),
        Display(tuple(lines)),
        Para(
            "They are known loads of the group's links below (a couple on each link "
            "of a revolute pair, a force along the slide on each link of a sliding "
            "pair, opposite on the pair's first link), and the equations hold with "
            "them: the reactions found have the sizes the friction was taken from."
        ),
    ]


def _newton_steps(steps: int) -> str:
    """Return how many steps Newton's method took, and how, in words."""
    if steps > QUICK:
        # from the frictionless sizes it did not settle: the friction was raised
        return f"{steps} steps, the friction raised by degrees"
    return f"{steps} step{'s' if steps != 1 else ''}"


def _unsettled(tried: list[dict[str, float]], steps: int) -> str:
    """Return what the note says where repeated substitution has not settled.

    The ratio of its last steps (of the size that moves most) tells the case: near
    +1 the steps shrink slowly the same way (near self-locking, with the steps
    still needed); below 0 they overshoot and swing back, which says nothing of
    locking; not steady, they jump about.
    """
    key = max(tried[-1], key=lambda k: abs(tried[-1][k] - tried[-2][k]))
    moves = [tried[i][key] - tried[i - 1][key] for i in range(1, len(tried))][-4:]
    ratios = [b / a for a, b in itertools.pairwise(moves) if a != 0]
    steady = len(ratios) >= 3 and max(ratios) - min(ratios) < 0.05
    r = ratios[-1] if ratios else math.nan
    found = (
        f" The sizes found (last row) are those of Newton's method on them "
        f"({_newton_steps(steps)}), which the analysis uses: of the solutions "
        "Coulomb's law allows (a slider may jam in its guide too), the one reached "
        "from the frictionless solution as the friction is raised from zero."
    )
    if steady and 0 < r < 1:
        more = math.ceil(
            math.log(SETTLED * max(tried[-1].values()) / abs(moves[-1])) / math.log(r)
        )
        return (
            f"The substitution settles slowly here: each step moves the sizes the "
            f"same way by about {r:.2f} times the step before (near 1, the group is "
            f"near self-locking), about {more} steps more." + found
        )
    if steady and -1 < r < 0:
        return (
            "The substitution settles slowly here: each step overshoots and swings "
            f"back, by about {abs(r):.2f} times the step before (ratio {r:.2f}; a "
            "swing says nothing of self-locking)." + found
        )
    if steady:
        return (
            f"The substitution does not settle here: each step is about {r:.2f} "
            "times the step before, and the steps grow." + found
        )
    return "The substitution does not settle here: its steps jump about." + found


def normal_symbol(pair: PairPlan, body: int) -> str:
    r"""Return the TeX of a sliding pair's normal force on ``body``: ``\vec N_J``.

    ``\vec N_J`` acts on the pair's second link; on its first, ``-\vec N_J``.
    """
    sign = "" if pair.second == body else "-"
    return f"{sign}\\vec N_{{{name(pair.name)}}}"


def sliding_total(
    pos: Position, pair: PairPlan, body: int, normal: Array, symbol: str
) -> str:
    """Return a sliding pair's reaction on ``body``: its normal force plus friction.

    ``normal`` is the normal force on ``body`` (N); ``symbol`` the TeX of the force of
    the pair's other link on ``body``.
    """
    assert pos.result is not None
    sign = 1.0 if pair.second == body else -1.0
    found = value(pos.result.friction.get(pair.name, 0.0))
    e = pos.turned(pair.first, pair.axis or (1.0, 0.0))
    friction = sign * found * e
    f = normal + friction
    j = name(pair.name)
    minus = "" if sign > 0 else "-"
    big = pos.force_scale()  # round-off of a force is told by it
    return (
        f"\\vec {symbol} = {normal_symbol(pair, body)} {minus or '+'} \\vec F_{{f,{j}}}"
        f" = {vec(normal, big)} + {vec(friction, big)} = {vec(f, big)}\\ "
        f"\\mathrm{{N}},\\quad {symbol} = {num(math.hypot(*f), big)}\\ \\mathrm{{N}}"
    )


def power_rows(
    pos: Position, bodies: list[Motion], actual: bool
) -> tuple[list[tuple[str, ...]], float]:
    """Return the lever's rows of every pair's friction power, and their sum (W).

    ``bodies`` are the velocities the lever uses: the actual ones (``actual``), or
    those per unit speed of one driver, written with a prime.
    """
    assert pos.result is not None
    rows: list[tuple[str, ...]] = []
    total = 0.0
    tick = "" if actual else "'"
    for pair in pos.plan.pairs.values():
        if pair.name not in pos.result.friction or pair.friction <= 0.0:
            continue
        j = name(pair.name)
        load = value(pos.result.friction[pair.name])
        # the lever's velocities as they are: a virtual speed is not motion to be
        # told from rest (a pair at rest has no friction load to multiply anyway)
        speed = value(rate(pair, bodies, Still(0.0, pos.plan.scale)))
        if pair.kind == "R":
            second, first = (name(pos.link(b)) for b in (pair.second, pair.first))
            symbol = f"M_{{f,{j}}}"
            relative = f"\\omega_{{{second}}} - \\omega_{{{first}}}"
            relative = f"({relative}){tick}" if tick else relative
        else:
            symbol = f"F_{{f,{j}}}"
            relative = f"\\dot s_{{{j}}}{tick}"
        power = load * speed
        total += power
        rows.append(
            (
                plain(pair.name),
                f"${symbol} = {num(load)}$",
                f"${relative} = {num(speed)}$",
                f"$P_{{f,{j}}}{tick} = {num(load)} \\cdot {par(speed)} = {num(power)}$",
            )
        )
    return rows, total


def driver_friction(pos: Position, i: int) -> tuple[list[str], float, str] | None:
    """Return the friction in driver ``i``'s own pair: lines, load on the link, TeX.

    The frame's reaction on the input link (its normal part, for a slider) sets the
    friction. The load is the friction couple (N m) or force along the guide (N) on
    the input link; the TeX writes it as a term of the balancing load's equation.
    None without friction.
    """
    assert pos.result is not None
    d = pos.plan.drivers[i]
    pair = d.pair
    if pair.friction <= 0.0 or pair.name not in pos.result.friction:
        return None
    found = value(pos.result.friction[pair.name])
    sign = 1.0 if pair.second == d.body else -1.0
    symbol = size_symbol(pos, pair)
    size = float(np.hypot(*normal_force(pos, pair, pos.result.drivers[i].reaction)))
    letter = "M" if pair.kind == "R" else "F"
    term = f"{'-' if sign > 0 else '+'} {letter}_{{f,{name(pair.name)}}}"
    return friction_lines(pos, pair, symbol, size), sign * found, term
