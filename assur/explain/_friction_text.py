r"""Friction in the note: each pair's friction load, its power, the driver's share.

A revolute pair resists the relative rotation of its links with the couple
:math:`M_f = -\rho\,|R|\,\mathrm{sgn}(\omega_2 - \omega_1)`, :math:`\rho = f r` the
radius of its friction circle; a sliding pair resists the slide with the force
:math:`F_f = -f\,|N|\,\mathrm{sgn}\,\dot s` along its slide line. How a group's
sizes are found is :mod:`assur.explain._group_friction_text`'s.
"""

from __future__ import annotations

import math

import numpy as np

from assur._still import Still, rate, still
from assur._vec import Array
from assur.explain._position import Position, at, perp, value
from assur.explain._tex import name, num, par, plain, vec
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Reaction

__all__ = [
    "at_rest",
    "driver_friction",
    "friction_lines",
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
