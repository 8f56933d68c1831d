"""The note's kinematic part: the input link, then each group in forward order.

For each group: what is known, the position problem, then the velocity and the
acceleration equations, and the motion of every other point of its links.
"""

from __future__ import annotations

import math

from assur.explain._note import Block, Display, Heading, Para
from assur.explain._position import Position
from assur.explain._positions import dyad_positions
from assur.explain._rates import (
    SPEED,
    TURN,
    body_points,
    dyad_rates,
    mid_name,
    point_lines,
)
from assur.explain._tex import LENGTH, deg, name, num, plain, point_name, unit, vec
from assur.groups._dyad import DyadSolver

__all__ = ["kinematics_blocks"]


def _given_angle(pos: Position, i: int) -> str:
    r"""Return crank ``i``'s angle in degrees as its position was given, ``^\circ``.

    The link's angle is put in the turn of the given position (the table's column),
    so 200 prints as 200, not -160.
    """
    angle = math.degrees(pos.angle(pos.plan.drivers[i].body))
    given = float(pos.table.given[0, i])
    return f"{num(angle + 360.0 * round((given - angle) / 360.0))}^\\circ"


def _driver(pos: Position, i: int) -> list[Block]:
    """Return input link ``i``'s motion and that of its points."""
    d = pos.plan.drivers[i]
    body = d.body
    link = name(pos.link(body))
    pivot = pos.pair_point(d.pair)
    j = name(d.pair.name)
    if d.kind == "R":
        w, eps = pos.omega(body), pos.epsilon(body)
        given = [
            f"\\varphi_{{{link}}} = {_given_angle(pos, i)},\\quad \\omega_{{{link}}} "
            f"= {num(w)}\\ \\mathrm{{rad/s}},\\quad \\varepsilon_{{{link}}} = "
            f"{num(eps)}\\ \\mathrm{{rad/s^2}}"
        ]
        text = (
            f"The input link {plain(pos.link(body))} turns about "
            f"{plain(d.pair.name)} at $\\vec r_{{{j}}} = {vec(pivot)}$ m; its "
            "position, speed and acceleration are given:"
        )
    else:
        v = pos.pair_point(d.pair, 1)
        a = pos.pair_point(d.pair, 2)
        given = [
            f"\\vec v_{{{j}}} = {vec(v)}{SPEED[1]},\\quad \\vec a_{{{j}}} = "
            f"{vec(a)}{SPEED[2]}"
        ]
        text = (
            f"The input link {plain(pos.link(body))} slides along the guide "
            f"{plain(d.pair.name)}; its speed and acceleration are given:"
        )
    blocks: list[Block] = [Para(text), Display(tuple(given))]
    skip = {d.pair.name}
    for k, what in ((0, "Positions"), (1, "Velocities"), (2, "Accelerations")):
        if k == 0:
            lines = [
                f"\\vec r_{{{point_name(p)}}} = {vec(pos.point(body, off))}"
                f"{unit(LENGTH[0])}"
                for p, off in body_points(pos, body)
                if p not in skip
            ]
        else:
            lines = point_lines(pos, body, pivot, j, k, skip)
        if lines:
            blocks += [Para(f"{what} of its points:"), Display(tuple(lines))]
    return blocks


def _dyad(pos: Position, s: DyadSolver) -> list[Block]:
    """Return a dyad's positions, velocities and accelerations."""
    blocks: list[Block] = [Heading(4, "Positions"), *dyad_positions(pos, s)]
    for k, what in ((1, "Velocities"), (2, "Accelerations")):
        blocks += [Heading(4, what), *dyad_rates(pos, s, k)]
        blocks += _points(pos, s, k)
    return blocks


def _points(pos: Position, s: DyadSolver, k: int) -> list[Block]:
    """Return the motion of the other points of a dyad's links."""
    lines = []
    m = pos.pair_point(s.mid)
    for b in (0, 1):
        body, pair = s.bodies[b], s.ext[b]
        if pair.kind == "R":
            base, label = pos.point(s.known[b], s.d_known[b]), name(pair.name)
            skip = {pair.name, s.mid.name}
        else:
            # the guide's point under the slider, named as the rates named it
            base, label = m, mid_name(pos, s)
            skip = {s.mid.name}
            if s.mid.kind == "P" and body == s.mid.first:
                label = f"{label}_{{{name(pos.link(body))}}}"
        if s.mid.kind == "R" or body == s.mid.first:
            skip.add(s.mid.name)
        lines += point_lines(pos, body, base, label, k, skip)
    w = [
        f"\\omega_{{{name(pos.link(b))}}} = {num(pos.omega(b))}{TURN[1]}"
        if k == 1
        else f"\\varepsilon_{{{name(pos.link(b))}}} = {num(pos.epsilon(b))}{TURN[2]}"
        for b in s.bodies
    ]
    text = "The group's links turn at" if k == 1 else "Their angular accelerations:"
    blocks: list[Block] = [Para(text), Display((",\\quad ".join(w),))]
    if lines:
        blocks += [Para("Then every other point of the links:"), Display(tuple(lines))]
    return blocks


def _general(pos: Position, solver: object) -> list[Block]:
    """Return a triad's (or larger group's) solved motion."""
    bodies: tuple[int, ...] = getattr(solver, "bodies", ())
    blocks: list[Block] = [
        Para(
            "The group's links have three coordinates each and every pair gives two "
            "equations: positions are found by Newton's method from the reference "
            "pose, velocities and accelerations from the linear systems with the "
            "same matrix (the Jacobian of the closure equations). The solution:"
        )
    ]
    lines = [
        f"\\varphi_{{{name(pos.link(b))}}} = {deg(pos.angle(b))},\\quad "
        f"\\omega_{{{name(pos.link(b))}}} = {num(pos.omega(b))}{TURN[1]},\\quad "
        f"\\varepsilon_{{{name(pos.link(b))}}} = {num(pos.epsilon(b))}{TURN[2]}"
        for b in bodies
    ]
    blocks.append(Display(tuple(lines)))
    starts = _starts(pos, bodies)
    blocks.append(
        Para(
            "Every other point of a link follows from its angular motion, starting "
            "from a pin whose motion is known from the links before, or found "
            "already on another link of the group:"
        )
    )
    for k, what in ((1, "Velocities"), (2, "Accelerations")):
        lines = []
        done: set[str] = set()
        for b in sorted(bodies, key=lambda b: b not in starts):
            points = body_points(pos, b)
            if not points:
                continue  # no named point: its angular motion above is all it has
            if b in starts:
                base_name, offset, known = starts[b]
            else:
                # a link with no pin outside the group (a triad's base link)
                # starts from a point found on a link before it
                base_name, offset = next(
                    ((p, d) for p, d in points if p in done), next(iter(points))
                )
                known = ""
            label = point_name(base_name)
            if base_name not in done:
                lines.append(
                    f"\\vec {'v' if k == 1 else 'a'}_{{{label}}} = "
                    f"{vec(pos.point(b, offset, k))}{SPEED[k]}{known}"
                )
            done.add(base_name)
            lines += point_lines(pos, b, pos.point(b, offset), label, k, set(done))
            done.update(p for p, _ in points)
        blocks += [Heading(4, what), Display(tuple(lines))]
    return blocks


def _starts(
    pos: Position, bodies: tuple[int, ...]
) -> dict[int, tuple[str, tuple[float, float], str]]:
    """Return each link's pin to a link known before the group: a point to start from.

    Each is ``(name, offset on the link, the TeX saying where it is known from)``.
    """
    group = set(bodies)
    # the links known before the group: the frame, the input links and the links of
    # the groups attached before it (a pin to a later group's link is not known yet)
    plan = pos.plan
    known = {0, *(d.body for d in plan.drivers)}
    for solver in plan.solvers:
        if group & set(solver.bodies):
            break
        known.update(solver.bodies)
    found: dict[int, tuple[str, tuple[float, float], str]] = {}
    for pair in pos.plan.pairs.values():
        if pair.kind != "R":
            continue
        for body, other, d in (
            (pair.first, pair.second, pair.d_first),
            (pair.second, pair.first, pair.d_second),
        ):
            if body in group and other in known:
                where = f",\\quad \\text{{known: a point of {plain(pos.link(other))}}}"
                found.setdefault(body, (pair.name.split("~")[0], d, where))
    return found


def kinematics_blocks(pos: Position) -> list[Block]:
    """Return the kinematic analysis: the input links, then each group in order."""
    plan = pos.plan
    blocks: list[Block] = [
        Heading(2, "2. Kinematics, group by group"),
        Para(
            "Vectors are written $(x,\\ y)$ in the frame's axes; $\\vec k$ is the "
            "unit vector out of the plane, so that $\\vec k \\times (x,\\ y) = "
            "(-y,\\ x)$, the vector turned by $90^\\circ$ counter-clockwise."
        ),
    ]
    for i, d in enumerate(plan.drivers):
        blocks += [
            Heading(3, f"Input link {plain(pos.link(d.body))}"),
            *_driver(pos, i),
        ]
    for g, solver in zip(plan.groups, plan.solvers, strict=True):
        blocks.append(Heading(3, f"Group {plain(g.label)}"))
        if isinstance(solver, DyadSolver):
            blocks += _dyad(pos, solver)
        else:
            blocks += _general(pos, solver)
    return blocks
