"""The known loads on a link, one by one, and their moments about a point.

A link carries its inertia force and torque, its weight, the external loads of the
file and, in the force analysis, the reactions of the links whose groups were solved
before its own and, with friction, the friction loads of its pairs. Each load is
listed separately so that the note can write every moment of an equilibrium
equation.
"""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass

import numpy as np

from assur._loads import table_reading, table_step, table_values
from assur._points import moves_with
from assur._tables import Reading
from assur._vec import Array
from assur.explain._position import ROUND_OFF, Position, at, cross, value
from assur.explain._tex import FLOOR, kept, name, num, par, point_name, text, vec
from assur.groups._pairs import PairPlan
from assur.model import LoadTable

__all__ = [
    "Load",
    "force_lines",
    "friction_load",
    "inertia_load",
    "joint_text",
    "link_loads",
    "moment",
    "moment_line",
    "own_loads",
    "total",
]


@dataclass(frozen=True, slots=True)
class Load:
    """A force ``force`` (N) at ``point`` (m) and a couple ``couple`` (N m).

    ``tex`` names the load; ``where`` names its point. ``before`` is a tabulated
    load's value just short of a step of its table at this position, in the table's
    order (a force's two components, N, or a couple, N m): the value past the step
    holds here. ``read`` is a tabulated load's reading here: the working of its
    interpolation between two entries (ending before its value, as
    ``Q_a + (x - x_a) / (x_b - x_a) (Q_b - Q_a)``, in TeX) and the words that say so.
    """

    tex: str
    where: str
    point: Array
    force: Array
    couple: float = 0.0
    before: tuple[float, ...] | None = None
    read: tuple[str, str] = ("", "")
    couple_tex: str = ""
    """The couple's own symbol beside a force (a sliding pair's ``M_{slot}``)."""


def inertia_load(pos: Position, body: int) -> tuple[Array, float] | None:
    """Return a link's inertia force (N) and torque (N m), or None without a mass."""
    assert pos.applied is not None
    found = pos.applied.inertia[body]
    if found is None:
        return None
    force, torque = at(found[0], found[1]), value(found[2])
    # a link at rest in its motion (a yoke at mid-stroke) carries round-off: told
    # as the nothing it is, not as 1.5e-11 N
    least = ROUND_OFF * pos.rate_scale(2)
    mass, inertia = float(pos.loads.mass[body]), float(pos.loads.inertia[body])
    force[np.abs(force) < mass * least] = 0.0
    if abs(torque) < inertia * least / pos.size():
        torque = 0.0
    return force, torque


def _centre(pos: Position, body: int) -> Array:
    """Return a link's centre of mass, m."""
    return pos.point(body, pos.loads.center[body])


def own_loads(pos: Position, body: int) -> list[Load]:
    """Return the inertia loads, weight and external loads on ``body``."""
    link = name(pos.link(body))
    where = point_name(f"{pos.link(body)}.G")
    out = []
    found = inertia_load(pos, body)
    if found is not None:
        force, torque = found
        g = _centre(pos, body)
        out.append(Load(f"\\vec F_{{i,{link}}}", where, g, force))
        if torque:
            out.append(Load(f"M_{{i,{link}}}", where, g, np.zeros(2), torque))
        mass = float(pos.loads.mass[body])
        weight = mass * np.asarray(pos.loads.gravity, dtype=float)
        if weight.any():
            out.append(Load(f"m_{{{link}}}\\vec g", where, g, weight))
    state = pos.table.state
    slides = {k: s[0] for k, s in state.slide.items()}
    count = 0
    for b, offset, force, entry in pos.loads.forces:
        if b != body:
            continue
        count += 1
        before, read = None, ("", "")
        if isinstance(force, LoadTable):
            fx, fy = table_values(force, pos.plan, state.drive, slides, entry)
            vector = at(fx, fy)
            before = _short_of(table_step(force, pos.plan, state.drive, slides, entry))
            reading_here = table_reading(force, pos.plan, state.drive, slides, entry)
            read = _read(reading_here, _over(pos, force), before is not None)
        else:
            vector = np.asarray(force, dtype=float)
        p = pos.point(body, offset)
        # Q, not F: F_{i,j} is the force of link i on link j
        tex = f"\\vec Q_{{{link},{count}}}"
        spot = _spot(pos, entry, count)
        out.append(Load(tex, spot, p, vector, before=before, read=read))
    for b, torque, entry in pos.loads.torques:
        if b != body:
            continue
        count += 1
        t, before, read = torque, None, ("", "")
        if isinstance(torque, LoadTable):
            t = table_values(torque, pos.plan, state.drive, slides, entry)[0]
            before = _short_of(table_step(torque, pos.plan, state.drive, slides, entry))
            reading_here = table_reading(torque, pos.plan, state.drive, slides, entry)
            read = _read(reading_here, _over(pos, torque), before is not None)
        tex, origin = f"T_{{{link},{count}}}", pos.origin(body)
        out.append(Load(tex, "", origin, np.zeros(2), value(t), before, read))
    return out


def _over(pos: Position, table: LoadTable) -> tuple[str, str, str]:
    """Return what a load table runs over: words, the unit, the coordinate read.

    Over the driver: no words (the note's position is the driver's), deg over a
    crank (the coordinate: where the driver is, when a turn away from the table's
    turn), m over a sliding driver; over a joint's slide: its name, m, its ``s``.
    """
    if table.over != "driver":
        return (
            f" over the slide of {text(table.over)}",
            "m",
            f"s_{{{name(table.over)}}}",
        )
    if pos.plan.drivers[0].kind != "R":
        return "", "m", ""
    return "", "deg", num(float(pos.table.given[0, 0]))


def _read(found: Reading, over: tuple[str, str, str], steps: bool) -> tuple[str, str]:
    """Return a tabulated load's working here and the words that say where it is read.

    On an entry (or at a step, whose words are said apart) there is no working:
    the entry's value holds.
    """
    if steps:
        return "", ""
    words, unit, coordinate = over
    u = f"\\ \\mathrm{{{unit}}}"
    if found.fraction in (0.0, 1.0):
        x = found.low if found.fraction == 0.0 else found.high
        return (
            "",
            f"\\text{{(the entry of its table{words} at }} {num(x)}{u}\\text{{)}}",
        )
    if found.held is not None:
        # a flat stretch of the table, over a crank perhaps across its turn's end
        low, high, through = found.held
        across = "" if through is None else f"\\text{{ through }} {num(through)} "
        return "", (
            f"\\text{{(its table{words} holds this value from }} {num(low)} "
            f"{across}\\text{{ to }} {num(high)}{u}\\text{{)}}"
        )

    def value_(v: tuple[float, ...], lead: bool = False) -> str:
        # a couple leading the sum is written bare, in a difference in brackets
        return vec(np.array(v)) if len(v) == 2 else (num if lead else par)(v[0])

    if unit == "deg":
        # a crank's angle is read within the table's turn: -100 deg at 260
        at = num(found.at)
        coordinate = "" if coordinate == at else f"{coordinate}{u} \\to "
    elif coordinate:
        coordinate += " = "
    working = (
        f"{value_(found.below, lead=True)} + "
        f"\\frac{{{num(found.at)} - {par(found.low)}}}"
        f"{{{num(found.high)} - {par(found.low)}}} \\cdot \\left({value_(found.above)}"
        f" - {value_(found.below)}\\right)"
    )
    said = (
        f"\\text{{(its table{words}, read at }} {coordinate}{num(found.at)}{u}"
        "\\text{: "
        f"linear between its entries at }} {num(found.low)} \\text{{ and }} "
        f"{num(found.high)}{u}"
        "\\text{)}"
    )
    return working, said


def _short_of(before: list[float] | None) -> tuple[float, ...] | None:
    """Return a load's values just short of a step here, as a tuple; None if none."""
    return None if before is None else tuple(before)


def _spot(pos: Position, entry: str, count: int) -> str:
    """Return the name of an external force's point: the file's, else P_count."""
    mech = pos.plan.mechanism
    load = mech.loads[int(entry.partition("[")[2].partition("]")[0])]
    # a name for a point that does not move with the link (a slide's first link, a
    # joint elsewhere) stands for where it was in the reference pose: another point
    if isinstance(load.at, str) and moves_with(mech, load.at, load.link):
        return point_name(load.at)
    return f"P_{{{count}}}"


def link_loads(
    pos: Position, body: int, solved: set[int], pairs: Collection[str] = ()
) -> list[Load]:
    """Return every known load on ``body``: applied, and reactions of ``solved`` links.

    A reaction is written as the force of the other link on ``body`` (and the couple
    of a sliding pair, about its point). With friction, the friction load of each
    pair whose reaction is known, and of each pair named in ``pairs`` (those of the
    group being solved), is listed after the reactions.
    """
    out = own_loads(pos, body)
    assert pos.result is not None
    reactions = pos.reactions()
    rubbing = []
    for pair in pos.pairs_of(body):
        pair_name = pair.name
        other = pair.first if pair.second == body else pair.second
        if other in solved or pair_name in pairs:
            rubbing.append(friction_load(pos, pair, body))
        if other not in solved:
            continue
        r = reactions[pair_name]
        sign = 1.0 if pair.second == body else -1.0
        force = sign * at(r.fx, r.fy)
        couple = sign * value(r.couple) if pair.kind == "P" else 0.0
        p = pos.pair_point(pair)
        # a slot's pin carries none: the solve leaves round-off (8.9e-16 N m beside
        # 18.78 N at 0.23 m), of the machine's sign and digits
        arm = max(pos.size(), *map(abs, p))
        if abs(couple) <= ROUND_OFF * arm * float(np.hypot(*force)):
            couple = 0.0
        label = f"\\vec F_{{{name(pos.link(other))},{name(pos.link(body))}}}"
        if pair.kind == "P" and pair.friction > 0.0:
            # the friction force along the slide is listed apart: the normal part
            label = f"\\vec N_{{{name(pair_name)}}}"
            if sign < 0:
                label = "-" + label
        # the pair's couple is its first link's on its second: minus it on the first
        said = f"{'' if sign > 0 else '-'}M_{{{name(pair_name)}}}" if couple else ""
        out.append(Load(label, name(pair_name), p, force, couple, couple_tex=said))
    return out + [x for x in rubbing if x is not None]


def friction_load(pos: Position, pair: PairPlan, body: int) -> Load | None:
    """Return the friction load of ``pair`` on ``body``; None where it has none.

    Revolute: the couple ``M_f`` (N m) of the pair's first link on its second.
    Prismatic: the force ``F_f`` (N) along the slide line, at the pair's point. On
    the pair's first link both act the other way, written with a minus sign.
    """
    assert pos.result is not None
    found = pos.result.friction.get(pair.name)
    size = 0.0 if found is None else value(found)
    if size == 0.0:
        return None  # no friction, or none where the pair does not move
    sign = 1.0 if pair.second == body else -1.0
    j = name(pair.name)
    minus = "" if sign > 0 else "-"
    if pair.kind == "R":
        zero = np.zeros(2)
        return Load(f"{minus}M_{{f,{j}}}", "", pos.pair_point(pair), zero, sign * size)
    e = pos.turned(pair.first, pair.axis or (1.0, 0.0))
    return Load(f"{minus}\\vec F_{{f,{j}}}", j, pos.pair_point(pair), sign * size * e)


def total(loads: list[Load]) -> Array:
    """Return the sum of the loads' forces, N."""
    return sum((x.force for x in loads), np.zeros(2))


def components(loads: list[Load], u: Array) -> str:
    """Return ``sum F.u`` term by term, ``[F_x u_x + F_y u_y + ...]``, or ``0``.

    The guide's direction or normal ``u`` as numbers: each product can be checked.
    """
    terms = [
        f"{par(float(f[0]))} \\cdot {par(float(u[0]))} + {par(float(f[1]))} \\cdot "
        f"{par(float(u[1]))}"
        for f in (x.force for x in loads)
        if math.hypot(*f) > 0
    ]
    return f"[{' + '.join(terms)}]" if terms else "0"


def moment(load: Load, about: Array) -> float:
    """Return the moment of ``load`` about ``about``, N m (counter-clockwise)."""
    return cross(load.point - about, load.force) + load.couple


def moment_line(loads: list[Load], about: Array, label: str) -> tuple[str, float]:
    """Return the sum of the loads' moments about a point, term by term; its value.

    Each force's moment is written ``(x_p - x)(F_y) - (y_p - y)(F_x)``.
    """
    parts = []
    total_moment = 0.0
    # what the sum is told from round-off by: the size of its terms
    scale = 0.0
    for x in loads:
        m = moment(x, about)
        total_moment += m
        # the arm's round-off is its points' (a force at the point summed about,
        # 1e-17 m off it): an arm no shorter than they are far from the origin
        arm = max(math.hypot(*(x.point - about)), *map(abs, x.point), *map(abs, about))
        scale = max(scale, arm * math.hypot(*x.force))
        scale = max(scale, abs(x.couple))
        pieces = []
        if math.hypot(*x.force) > 0:
            r = x.point - about
            pieces.append(
                f"{par(r[0])} \\cdot {par(x.force[1])} - {par(r[1])} \\cdot "
                f"{par(x.force[0])}"
            )
        if x.couple:  # a load's own couple, however small
            pieces.append(par(x.couple, abs(x.couple)))
        if pieces:
            parts.append(" + ".join(pieces))
    if not parts:  # no load on the link: nothing to sum ("= 0 = 0")
        return f"\\sum M_{{{label}}} = 0", total_moment
    body = " + ".join(f"[{p}]" for p in parts)
    return f"\\sum M_{{{label}}} = {body} = {num(total_moment, scale)}", total_moment


def force_lines(loads: list[Load]) -> list[str]:
    """Return one line per load: its force (N) and couple (N m) with their points."""
    lines = []
    for x in loads:
        working, words = x.read
        text = x.tex + (f" = {working}" if working else "")
        if math.hypot(*x.force) > 0:
            text += f" = {vec(x.force)}\\ \\mathrm{{N}}"
            if x.where:
                # a coordinate of round-off (a yoke's centre on the axis,
                # -1.4e-17 m) is 0 beside the mechanism's size, not beside itself
                at = vec(x.point, max(FLOOR.get(), *map(abs, x.point)))
                text += f",\\quad \\text{{at}}\\ {x.where} = {at}"
        if x.couple:  # a load's own couple (cleaned, or a datum), however small
            text += (
                f" = {kept(x.couple)}\\ \\mathrm{{N\\,m}}"
                if not math.hypot(*x.force)
                else f",\\ {x.couple_tex + ' = ' if x.couple_tex else ''}"
                f"{kept(x.couple)}\\ \\mathrm{{N\\,m}}"
            )
        elif not math.hypot(*x.force):  # a load that is zero here is written so
            zero = (
                "(0,\\ 0)\\ \\mathrm{N}" if "\\vec" in x.tex else "0\\ \\mathrm{N\\,m}"
            )
            text += f" = {zero}"
        if x.before is not None:
            # its table steps here: which side of the step the note takes
            was = (
                f"{vec(np.array(x.before))}\\ \\mathrm{{N}}"
                if len(x.before) == 2
                else f"{kept(x.before[0])}\\ \\mathrm{{N\\,m}}"
            )
            # in the table's order, whichever way the driver moves: the value
            # at the step's position is the one on the side of larger positions
            said = "(its table steps here, from "
            rest = " below this position to the value above it, which holds here)"
            # set off as a table's reading is (",\quad"), whichever it is
            text += f",\\quad \\text{{{said}}}{was}\\text{{{rest}}}"
        if words:
            text += f",\\quad {words}"
        lines.append(text)
    return lines


def joint_text(pos: Position, pair: str) -> str:
    r"""Return which joint a pair is, for ``\text``: a slot's two pairs told apart."""
    if pair.endswith("~pin"):
        return f"joint {text(pair)}: the pin in the block"
    if f"{pair}~pin" in pos.plan.pairs:
        return f"joint {text(pair)}: the block in the slot"
    return f"joint {text(pair)}"
