"""The check of the balancing loads by Zhukovsky's lever: section 6.

Zhukovsky's lever (the velocity plan turned by 90 degrees, every load at its point's
image) is the principle of virtual power: the sum of every load's power and the
balancing load's is zero, so the balancing load follows from the powers alone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assur._kinematics import velocity_coefficients
from assur._vec import Array
from assur.explain._friction_text import power_rows
from assur.explain._loads_text import Load, own_loads
from assur.explain._note import Block, Display, Grid, Heading, Para
from assur.explain._position import Position, at
from assur.explain._tex import ZERO, kept, name, num, par, plain, vec
from assur.groups._motion import Motion
from assur.groups.driver import DriverPlan

__all__ = [
    "LeverTerm",
    "lever_blocks",
    "lever_load",
    "lever_parts",
    "lever_rates",
    "lever_terms",
]

LEVER = "^{\\mathrm{lever}}"
"""The superscript of a balancing load read off the lever (upright: a word)."""
IDEAL = "^{\\mathrm{ideal}}"
"""The superscript of a balancing load without friction."""


def _balancing(pos: Position, i: int) -> float:
    """Return driver ``i``'s balancing load from the reverse pass (N m or N)."""
    assert pos.result is not None
    return float(np.ravel(pos.result.drivers[i].balancing)[0])


def _symbol(d: DriverPlan, many: bool) -> str:
    """Return the balancing load's symbol: M_b (torque) or F_b (force)."""
    letter = "M" if d.kind == "R" else "F"
    return f"{letter}_{{b,{name(d.pair.name)}}}" if many else f"{letter}_{{b}}"


def _speed(pos: Position, d: DriverPlan) -> float:
    """Return a driver's speed (rad/s, or m/s along its guide)."""
    if d.kind == "R":
        return float(pos.omega(d.body))
    return float(np.dot(pos.pair_point(d.pair, 1), np.asarray(d.pair.axis)))


def lever_rates(pos: Position, i: int) -> tuple[list[Motion], float, str]:
    """Return the velocities used on the lever, the driver's speed and a note.

    One driver moving: the velocities themselves and its speed. Otherwise the
    velocities per unit speed of driver ``i`` (the others held), and speed 1.
    """
    plan = pos.plan
    d = plan.drivers[i]
    speed = _speed(pos, d)
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
            "Turn the velocity plan by 90° counter-clockwise and apply every load at "
            "its point's image: "
            "the plan, taken as a lever pivoted at the pole, is in equilibrium. Its "
            "moment equation is the principle of virtual power, $\\sum (\\vec F_k "
            "\\cdot \\vec v_k + M_k \\omega_k) + P_b = 0$, where $P_b$ is the "
            "balancing load's power. No reaction enters it (they do no work). A "
            "force's arm $h = |\\vec F \\cdot \\vec v| / F$ is the distance of its "
            "line from the pole on the turned plan (in the plan's units, m/s, before "
            "its scale): its moment about the pole, $F h$, is as large as its power "
            "and turns the lever clockwise when the power is positive. A couple "
            "$M$ on link $L$ counts as $M \\omega_L$."
        ),
    ]
    if many:
        blocks.append(
            Para(
                f"With {len(plan.drivers)} drivers each balancing load has its own "
                "lever: the velocity plan for a unit speed of that driver with the "
                "others held still. The other drivers' loads then do no work, and "
                "the powers (written with a prime) are per unit speed."
            )
        )
    for i in range(len(plan.drivers)):
        blocks += _driver_lever(pos, i)
    return blocks


def _driver_lever(pos: Position, i: int) -> list[Block]:
    """Return driver ``i``'s balancing load by the lever, with friction's power.

    With several drivers the velocities are those per unit speed of driver ``i``
    (the others held): the powers are then per unit speed, written with a prime,
    and the balancing load is minus their sum.
    """
    d = pos.plan.drivers[i]
    bodies, speed, note = lever_rates(pos, i)
    actual = bodies is pos.bodies
    rows, power = lever_terms(pos, bodies)
    sym = _symbol(d, len(pos.plan.drivers) > 1)
    tick = "" if actual else "'"
    rate = ("\\omega" if d.kind == "R" else "v") + tick
    # the balancing load's own unit: a couple on a crank, a force on a slider
    load_unit = "\\ \\mathrm{N\\,m}" if d.kind == "R" else "\\ \\mathrm{N}"
    # a power per unit speed is in W per rad/s (N m) or W per m/s (N): the load's
    unit = "\\ \\mathrm{W}" if actual else load_unit
    per = "N m" if d.kind == "R" else "N"
    head = "power (W)" if actual else f"power per unit speed ({per})"
    # the arm is a length of the plan: a velocity, or a velocity per unit speed
    per_speed = "m" if d.kind == "R" else "m/s per m/s"
    arm = "arm h (m/s)" if actual else f"arm h per unit speed ({per_speed})"
    blocks: list[Block] = [
        Para(f"With {note} (driver {plain(d.pair.name)}):"),
        Grid(
            ("load", "force (N) or couple (N·m)", "velocity", arm, head),
            tuple(rows),
            f"Power of each load on the lever of driver {plain(d.pair.name)}",
        ),
    ]
    lines = [f"\\sum P{tick} = {num(power)}{unit}"]
    rubbed, lost = power_rows(pos, bodies, actual)
    top, shown = f"\\sum P{tick}", num(power)
    if rubbed:
        blocks += [
            Para(
                "Friction does work too: each pair's friction load times the "
                "relative motion it opposes"
                + (
                    " (a loss, so negative):"
                    if actual
                    else " (the loads of the actual motion, the motion per unit "
                    "speed of this driver: of either sign):"
                )
            ),
            Grid(
                ("pair", "friction load", "relative motion", head),
                tuple(rubbed),
                f"Power of friction in each pair for driver {plain(d.pair.name)}",
            ),
        ]
        lines += [
            f"{sym}{IDEAL} = -\\frac{{\\sum P{tick}}}{{{rate}}} = -\\frac{{"
            f"{num(power)}}}{{{num(speed)}}} = {num(-power / speed)}{load_unit}",
            f"\\sum P_{{f}}{tick} = {num(lost)}{unit}",
        ]
        top = f"\\sum P{tick} + \\sum P_{{f}}{tick}"
        shown = f"{num(power)} + {par(lost)}"
        power += lost
    lever = -power / speed
    value = _balancing(pos, i)
    lines.append(
        f"{sym}{LEVER} = -\\frac{{{top}}}{{{rate}}} = -\\frac{{{shown}}}"
        f"{{{num(speed)}}} = {num(lever)}{load_unit}"
    )
    size = _size(pos, i)
    if abs(value) > ZERO * size:
        # two ways that agree but for round-off differ by 1e-14 of the load or by
        # nothing, as the machine's arithmetic has it: 0 %, as at a dead centre
        gap = abs(lever - value)
        diff = 0.0 if gap <= ZERO * size else 100.0 * gap / abs(value)
        lines.append(
            f"\\frac{{|{sym}{LEVER} - {sym}|}}{{|{sym}|}} = {_percent(diff)}\\,\\%"
        )
    else:
        # a balancing load that is round-off (a dead centre) has no size to compare
        # with: the difference itself is told, against the loads' shares
        lines.append(
            f"|{sym}{LEVER} - {sym}| = {num(abs(lever - value), size)}{load_unit}"
        )
    return [*blocks, Display(tuple(lines))]


def _size(pos: Position, i: int) -> float:
    """Return the size of driver ``i``'s balancing load (N m or N).

    Every load's share on the lever added up without its direction or sign (force
    times speed, couple times angular speed), friction's power too: the scale the
    round-off of the balancing load is measured against.
    """
    bodies, speed, _ = lever_rates(pos, i)
    total = abs(power_rows(pos, bodies, bodies is pos.bodies)[1])
    for t in lever_parts(pos, bodies):
        if t.couple:
            total += abs(t.load.couple * t.omega)
        else:
            total += math.hypot(*t.load.force) * math.hypot(*t.velocity)
    return total / abs(speed)


def lever_load(
    pos: Position, i: int, rates: tuple[list[Motion], float] | None = None
) -> float:
    """Return driver ``i``'s balancing load read off the lever, friction's power in.

    N m or N: what :func:`lever_blocks` finds, without the working. ``rates`` are
    the velocities and the speed of :func:`lever_rates`, if found already.
    """
    bodies, speed = lever_rates(pos, i)[:2] if rates is None else rates
    power = 0.0
    for t in lever_parts(pos, bodies):
        power += t.power  # in the order lever_terms sums them: the same bits
    _, lost = power_rows(pos, bodies, bodies is pos.bodies)
    return -(power + lost) / speed


def _percent(x: float) -> str:
    """Return a small percentage in a readable form."""
    if x == 0:
        return "0"
    mantissa, exponent = f"{x:.1e}".split("e")
    return f"{mantissa} \\cdot 10^{{{int(exponent)}}}"


@dataclass(frozen=True, slots=True)
class LeverTerm:
    """One load's power on the lever: a force at its point, or a couple on its link.

    ``load`` acts on link ``body``. For a force (``couple`` false) ``velocity`` is
    its point's (m/s); for a couple ``omega`` is the link's angular velocity
    (rad/s). ``power`` is ``F . v`` or ``M omega`` (W): minus its moment about the
    pole of the lever (the velocity plan turned by +90 degrees).
    """

    load: Load
    body: int
    couple: bool
    velocity: Array
    omega: float
    power: float


def lever_parts(pos: Position, bodies: list[Motion]) -> list[LeverTerm]:
    r"""Return every load's term on the lever: forces and couples, link by link.

    ``bodies`` are the velocities the lever uses (:func:`lever_rates`). A load with
    a force and a couple gives two terms; a couple acts as its power
    :math:`M_L \omega_L`, whatever the points of the link.
    """
    out: list[LeverTerm] = []
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
                out.append(LeverTerm(load, b, False, v, w, p))
            if load.couple:
                out.append(LeverTerm(load, b, True, np.zeros(2), w, load.couple * w))
    return out


def lever_terms(
    pos: Position, bodies: list[Motion]
) -> tuple[list[tuple[str, ...]], float]:
    """Return the table rows of every load's power and their sum (W)."""
    rows: list[tuple[str, ...]] = []
    total_power = 0.0
    parts = lever_parts(pos, bodies)
    # the round-off of a speed at rest (a slider at its dead centre: 5e-16 m/s) is
    # told by the fastest, as the round-off of a force by the largest
    fastest = max((math.hypot(*t.velocity) for t in parts), default=0.0)
    turning = max((abs(t.omega) for t in parts), default=0.0)
    # a power is told from round-off by the largest force times the fastest speed
    # (at a dead centre every power is round-off)
    powers = pos.force_scale() * fastest
    for t in parts:
        if t.couple:
            given, rate = kept(t.load.couple), f"\\omega = {num(t.omega, turning)}"
            arm = ""  # a couple has no line, and no arm
        else:
            given = vec(t.load.force, pos.force_scale())
            rate = f"\\vec v = {vec(t.velocity, fastest)}"
            size = math.hypot(*t.load.force)
            arm = f"${num(abs(t.power) / size, fastest)}$"
        power = num(t.power, powers)
        rows.append((f"${t.load.tex}$", f"${given}$", f"${rate}$", arm, f"${power}$"))
        total_power += t.power
    return rows, total_power
