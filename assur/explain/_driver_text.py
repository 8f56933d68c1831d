"""The input link's equilibrium, as the note writes it: section 5.

The frame's reaction follows from the input link's force sum and the balancing load
from its moments about the driving pair (a crank) or its forces along the guide (a
slider), friction in the driving pair included.
"""

from __future__ import annotations

import math

import numpy as np

from assur._vec import opposed
from assur.explain._forces_text import couple_blocks, force_symbol
from assur.explain._friction_text import driver_friction, sliding_total
from assur.explain._lever import _balancing, _size, _speed, _symbol
from assur.explain._loads_text import (
    Load,
    components,
    force_lines,
    link_loads,
    moment_line,
    total,
)
from assur.explain._note import Block, Display, Heading, Para
from assur.explain._position import Position
from assur.explain._tex import (
    ZERO,
    name,
    num,
    par,
    plain,
    vec,
)

__all__ = ["driver_blocks"]

IDEAL = "^{\\mathrm{ideal}}"
"""The superscript of a balancing load without friction (upright: a word)."""


def driver_blocks(pos: Position) -> list[Block]:
    """Return each input link's equilibrium: the frame's reaction, balancing load."""
    plan = pos.plan
    solved = {b for s in plan.solvers for b in s.bodies}
    many = len(plan.drivers) > 1
    blocks: list[Block] = [
        Heading(2, "5. The input links" if many else "5. The input link")
    ]
    for i, d in enumerate(plan.drivers):
        body = d.body
        loads = link_loads(pos, body, solved | {x.body for x in plan.drivers} - {body})
        blocks += [
            Para(f"Known loads on {plain(pos.link(body))}:"),
            Display(tuple(force_lines(loads))),
        ]
        if d.kind == "R":
            blocks += _crank(pos, i, loads)
        else:
            blocks += _slider(pos, i, loads)
        value = _balancing(pos, i)
        sym = _symbol(d, many)
        # the unit in the mathematics, as in every other line of the note
        unit = "\\ \\mathrm{N\\,m}" if d.kind == "R" else "\\ \\mathrm{N}"
        said = f"So ${sym} = {num(value)}{unit}$." + _sense(pos, i, value)
        blocks.append(Para(said + _ideal(pos, i, sym, unit)))
    return blocks


def _sense(pos: Position, i: int, value: float) -> str:
    """Return whether the balancing load drives the input link or brakes it.

    Its sign alone does not tell: a clockwise crank is driven by a negative torque.
    """
    d = pos.plan.drivers[i]
    speed = _speed(pos, d)
    if not speed or abs(value) <= ZERO * _size(pos, i):
        return ""
    if not opposed(value, speed):
        return " It drives the link: it acts the way the link moves."
    return " It brakes the link: it acts against the way the link moves."


def _ideal(pos: Position, i: int, sym: str, unit: str) -> str:
    """Return the words comparing the balancing load with the frictionless one.

    Every operation is written with numbers that redo it: each result is the
    rounding of the operation on the numbers written before it, not of the exact
    values, so a reader who redoes it by hand gets its last digit.
    """
    assert pos.result is not None
    if not pos.result.ideal:
        return ""
    ideal = float(np.ravel(pos.result.ideal[i])[0])
    value = _balancing(pos, i)
    d = pos.plan.drivers[i]
    speed = _speed(pos, d)
    # the difference cancels the loads' leading digits, and its product with the
    # speed needs more of its own than the note's two decimals: the operands are
    # written with those digits, so that the subtraction gives them
    places = _decimals(speed)
    minuend, subtrahend = num(value, least=places), par(ideal, least=places)
    extra = _written(minuend) - _written(subtrahend)
    # written once, with those digits: 16.2 and 16.19731 read as two torques
    change = num(extra, least=places)
    words = (
        f" Without friction the same motion needs ${sym}{IDEAL} = {num(ideal)}"
        f"{unit}$ (read off the lever below); friction changes it by ${sym} - "
        f"{sym}{IDEAL} = {minuend} - {subtrahend} = {change}{unit}$"
    )
    # a frictionless load that is round-off (at a dead centre) has no size to compare
    # the share of the same two numbers as the subtraction's
    share, whole = change.lstrip("-"), subtrahend.strip("()").lstrip("-")
    if abs(ideal) > ZERO * _size(pos, i) and _written(whole):
        words += (
            f" ($100 \\cdot \\frac{{{share}}}{{{whole}}} = "
            f"{num(100.0 * _written(share) / _written(whole))}\\,\\%$ of "
            f"$|{sym}{IDEAL}|$)"
        )
    if not speed:
        return words + "."
    return words + _friction_power(pos, i, sym, change)


def _friction_power(pos: Position, i: int, sym: str, change: str) -> str:
    """Return the power friction takes: the written change times the driver's speed.

    The speed is written as everywhere else in the note (209.44, not 209.4395
    beside it), and the product is that of the written factors.
    """
    d = pos.plan.drivers[i]
    speed = _speed(pos, d)
    value = _balancing(pos, i)
    rate = "\\omega" if d.kind == "R" else "v"
    whose = "" if len(pos.plan.drivers) == 1 else " this driver's share of"
    factor = par(speed)
    # the difference times the driver's speed is the power friction takes from it,
    # whatever the signs of the load and the speed; a driver that brakes (its
    # power negative) takes that much less back: "supplies more" read as if it
    # drove
    brakes = opposed(value, speed)
    how = "takes" if brakes else "supplies"
    less = "less back" if brakes else "more"
    return (
        f", and the driver {how} $({sym} - {sym}{IDEAL})\\,{rate} = "
        f"{change} \\cdot {factor} = "
        f"{num(_written(change) * _written(factor))}$ W {less}:{whose} the power "
        "friction takes. (At one position the power may flow either way, so an "
        "efficiency means little there: the cycle's is given by the summary, "
        "assur forces FILE --summary.)"
    )


def _written(text: str) -> float:
    r"""Return the value a number written by :func:`num` or :func:`par` reads as.

    ``"(-1.5 \cdot 10^{-5})"`` reads as -1.5e-5: an operation is redone on it.
    """
    if "undefined" in text:
        return math.nan
    mantissa, _, power = text.strip("()").partition(" \\cdot 10^{")
    return float(mantissa) * 10.0 ** int(power.rstrip("}") or 0)


def _decimals(other: float) -> int:
    """Return the decimals a factor of ``other`` needs for their product by hand.

    Its rounding times ``other`` stays under a quarter of the product's last
    written digit (0.01): 16.2 written for 16.19731 made 16.2 * 200 read 3240
    beside 3239.46 written.
    """
    return max(0, math.ceil(math.log10(400.0 * abs(other)))) if other else 0


def _crank(pos: Position, i: int, loads: list[Load]) -> list[Block]:
    """Return a crank's moments about its pivot and force sum, with its friction."""
    d = pos.plan.drivers[i]
    sym = _symbol(d, len(pos.plan.drivers) > 1)
    j = name(d.pair.name)
    symbol = force_symbol(pos, 0, d.body)
    frame = -total(loads)
    line, m = moment_line(loads, pos.pair_point(d.pair), j)
    big = pos.force_scale()  # round-off of a force is told by it
    reaction = (
        f"\\vec {symbol} = -\\sum \\vec F = {vec(frame, big)}\\ \\mathrm{{N}},\\quad "
        f"{symbol} = {num(math.hypot(*frame), big)}\\ \\mathrm{{N}}"
    )
    rubbing = driver_friction(pos, i)
    words = (
        f"Moments about {plain(d.pair.name)} (the frame's reaction passes through "
        f"it) give the balancing torque ${sym}$ on the link (the motor's, through "
        "its shaft); its force sum gives the frame's reaction"
    )
    if rubbing is None:
        return [
            Para(words + ":"),
            Display(
                (
                    line,
                    f"{sym} = -\\sum M_{{{j}}} = {num(-m)}\\ \\mathrm{{N\\,m}}",
                    reaction,
                )
            ),
        ]
    lines, couple, term = rubbing
    return [
        Para(
            words + ", whose size sets the friction couple in "
            f"{plain(d.pair.name)}; the balancing torque overcomes that couple too:"
        ),
        Display((line, reaction, *lines)),
        Display(
            (
                f"{sym} = -\\sum M_{{{j}}} {term} = {num(-m)} - {par(couple)} = "
                f"{num(-m - couple)}\\ \\mathrm{{N\\,m}}",
            )
        ),
    ]


def _slider(pos: Position, i: int, loads: list[Load]) -> list[Block]:
    """Return an input slider's forces along and across its guide, with friction."""
    d = pos.plan.drivers[i]
    sym = _symbol(d, len(pos.plan.drivers) > 1)
    symbol = force_symbol(pos, 0, d.body)
    e = np.asarray(d.pair.axis, dtype=float)
    along = float(np.dot(total(loads), e))
    rest = -total(loads) + along * e
    rubbing = driver_friction(pos, i)
    # the balancing force and the friction force act along the guide through the
    # pair's point: its moments there give the guide's couple
    couple = couple_blocks(pos, d.pair, d.body, loads, normal=True)
    if rubbing is None:
        return [
            Para(
                f"Forces along the guide give the balancing force ${sym}$; across "
                "it, the frame's normal reaction:"
            ),
            Display(
                (
                    f"{sym} = -\\sum \\vec F \\cdot \\vec e = "
                    f"-{components(loads, e)} = "
                    f"{num(-along)}\\ \\mathrm{{N}}",
                    f"\\vec {symbol} = {vec(rest, pos.force_scale())}\\ \\mathrm{{N}}",
                )
            ),
            *couple,
        ]
    lines, force, term = rubbing
    # the normal reaction first (with the guide's couple), then the friction its
    # size sets, the balancing force and the whole reaction: each from the ones
    # before
    return [
        *couple,
        Para(
            f"The size of the normal reaction sets the friction in "
            f"{plain(d.pair.name)}; forces along the guide give the balancing force "
            f"${sym}$, which overcomes the friction too, and the frame's reaction is "
            "the normal one and the friction together:"
        ),
        Display(
            (
                *lines,
                f"{sym} = -\\sum \\vec F \\cdot \\vec e {term} = "
                f"-{components(loads, e)} - "
                f"{par(force)} = {num(-along - force)}\\ \\mathrm{{N}}",
                sliding_total(pos, d.pair, d.body, rest, symbol),
            )
        ),
    ]
