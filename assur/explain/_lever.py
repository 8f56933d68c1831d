"""The input link's equilibrium, then the check by Zhukovsky's lever.

The frame's reaction follows from the input link's force sum and the balancing load
from its moments about the driving pair. Zhukovsky's lever (the velocity plan turned
by 90 degrees, every load at its point's image) is the principle of virtual power:
the sum of every load's power and the balancing load's is zero, so the balancing
load follows from the powers alone, without one reaction.
"""

from __future__ import annotations

import math

import numpy as np

from assur._kinematics import velocity_coefficients
from assur.explain._forces_text import force_symbol
from assur.explain._loads_text import (
    force_lines,
    link_loads,
    moment_line,
    own_loads,
    total,
)
from assur.explain._note import Block, Display, Grid, Heading, Para
from assur.explain._position import Position, at
from assur.explain._tex import name, num, par, plain, vec
from assur.groups._motion import Motion
from assur.groups.driver import DriverPlan

__all__ = ["driver_blocks", "lever_blocks"]


def _balancing(pos: Position, i: int) -> float:
    """Return driver ``i``'s balancing load from the reverse pass (N m or N)."""
    assert pos.result is not None
    return float(np.ravel(pos.result.drivers[i].balancing)[0])


def _symbol(d: DriverPlan, many: bool) -> str:
    """Return the balancing load's symbol: M_b (torque) or F_b (force)."""
    letter = "M" if d.kind == "R" else "F"
    return f"{letter}_{{b,{name(d.pair.name)}}}" if many else f"{letter}_{{b}}"


def driver_blocks(pos: Position) -> list[Block]:
    """Return each input link's equilibrium: the frame's reaction, balancing load."""
    plan = pos.plan
    solved = {b for s in plan.solvers for b in s.bodies}
    blocks: list[Block] = [Heading(2, "5. The input link")]
    many = len(plan.drivers) > 1
    for i, d in enumerate(plan.drivers):
        body = d.body
        loads = link_loads(pos, body, solved | {x.body for x in plan.drivers} - {body})
        pivot = pos.pair_point(d.pair)
        j = name(d.pair.name)
        frame = -total(loads)
        symbol = force_symbol(pos, 0, body)
        value = _balancing(pos, i)
        sym = _symbol(d, many)
        blocks += [
            Para(f"Known loads on {plain(pos.link(body))}:"),
            Display(tuple(force_lines(loads))),
        ]
        if d.kind == "R":
            line, m = moment_line(loads, pivot, j)
            blocks += [
                Para(
                    f"Moments about {plain(d.pair.name)} (the frame's reaction passes "
                    f"through it) give the balancing torque ${sym}$ the frame applies "
                    "to the link; its force sum gives the frame's reaction:"
                ),
                Display(
                    (
                        line,
                        f"{sym} = -\\sum M_{{{j}}} = {num(-m)}\\ \\mathrm{{N\\,m}}",
                        f"\\vec {symbol} = -\\sum \\vec F = {vec(frame)}"
                        "\\ \\mathrm{N}"
                        f",\\quad {symbol} = {num(math.hypot(*frame))}\\ \\mathrm{{N}}",
                    )
                ),
            ]
        else:
            e = np.asarray(d.pair.axis, dtype=float)
            along = float(np.dot(total(loads), e))
            rest = frame + along * e
            blocks += [
                Para(
                    f"Forces along the guide give the balancing force ${sym}$; across "
                    "it, the frame's normal reaction:"
                ),
                Display(
                    (
                        f"{sym} = -\\sum \\vec F \\cdot \\vec e = -{par(along)} = "
                        f"{num(-along)}\\ \\mathrm{{N}}",
                        f"\\vec {symbol} = {vec(rest)}\\ \\mathrm{{N}}",
                    )
                ),
            ]
        blocks.append(
            Para(f"So ${sym} = {num(value)}$ {'N m' if d.kind == 'R' else 'N'}.")
        )
    return blocks


def _rates(pos: Position, i: int) -> tuple[list[Motion], float, str]:
    """Return the velocities used on the lever, the driver's speed and a note.

    One driver moving: the velocities themselves and its speed. Otherwise the
    velocities per unit speed of driver ``i`` (the others held), and speed 1.
    """
    plan = pos.plan
    d = plan.drivers[i]
    speed = (
        pos.omega(d.body)
        if d.kind == "R"
        else float(np.dot(pos.pair_point(d.pair, 1), np.asarray(d.pair.axis)))
    )
    if len(plan.drivers) == 1 and abs(speed) > 1e-12:
        return pos.bodies, speed, "the velocities found above"
    bodies = velocity_coefficients(plan, pos.bodies, i)
    return bodies, 1.0, "the velocities per unit speed of this driver, the others held"


def lever_blocks(pos: Position) -> list[Block]:
    """Return the check of every balancing load by virtual power (Zhukovsky)."""
    plan = pos.plan
    many = len(plan.drivers) > 1
    blocks: list[Block] = [
        Heading(2, "6. Check by Zhukovsky's lever"),
        Para(
            "Turn the velocity plan by 90° and apply every load at its point's image: "
            "the plan, taken as a lever pivoted at the pole, is in equilibrium. Its "
            "moment equation is the principle of virtual power, $\\sum (\\vec F_k "
            "\\cdot \\vec v_k + M_k \\omega_k) + P_b = 0$, where $P_b$ is the "
            "balancing load's power. No reaction enters it (they do no work)."
        ),
    ]
    for i, d in enumerate(plan.drivers):
        bodies, speed, note = _rates(pos, i)
        rows, power = _terms(pos, bodies)
        sym = _symbol(d, many)
        rate = "\\omega" if d.kind == "R" else "v"
        lever = -power / speed
        value = _balancing(pos, i)
        diff = 100.0 * abs(lever - value) / max(abs(value), 1e-300)
        blocks += [
            Para(f"With {note} (driver {plain(d.pair.name)}):"),
            Grid(("load", "force or couple", "velocity", "power (W)"), tuple(rows)),
            Display(
                (
                    f"\\sum P = {num(power)}\\ \\mathrm{{W}}",
                    f"{sym}^{{lever}} = -\\frac{{\\sum P}}{{{rate}}} = -\\frac{{"
                    f"{num(power)}}}{{{num(speed)}}} = {num(lever)}",
                    f"\\frac{{|{sym}^{{lever}} - {sym}|}}{{|{sym}|}} = "
                    f"{_percent(diff)}\\,\\%",
                )
            ),
        ]
    return blocks


def _percent(x: float) -> str:
    """Return a small percentage in a readable form."""
    return "0" if x == 0 else f"{x:.1e}".replace("e", "\\cdot 10^{") + "}"


def _terms(pos: Position, bodies: list[Motion]) -> tuple[list[tuple[str, ...]], float]:
    """Return the table rows of every load's power and their sum (W)."""
    rows: list[tuple[str, ...]] = []
    total_power = 0.0
    for b in range(1, len(pos.plan.bodies)):
        m = bodies[b]
        w = float(np.ravel(m.phi[1])[0])
        o = at(m.ox[0], m.oy[0]) + pos.shift()
        vo = at(m.ox[1], m.oy[1])
        for load in own_loads(pos, b):
            if math.hypot(*load.force) > 0:
                r = load.point - o
                v = vo + w * np.array([-r[1], r[0]])
                p = float(np.dot(load.force, v))
                rows.append(
                    (
                        f"${load.tex}$",
                        f"${vec(load.force)}$",
                        f"$\\vec v = {vec(v)}$",
                        f"${num(p)}$",
                    )
                )
                total_power += p
            if load.couple:
                p = load.couple * w
                rows.append(
                    (
                        f"${load.tex}$",
                        f"${num(load.couple)}$",
                        f"$\\omega = {num(w)}$",
                        f"${num(p)}$",
                    )
                )
                total_power += p
    return rows, total_power
