"""Coulomb friction in the pairs, solved group by group.

A revolute pair with friction coefficient f and journal radius r resists the relative
rotation of its links with a couple of magnitude f r |R| (R its reaction force): the
reaction is tangent to the friction circle of radius f r. A prismatic pair resists
the slide with a force f |N| (N its normal force) along the slide line at the pair's
point. Kinetic friction only: a pair whose links do not move relative to each other
has none. "Do not move" has a tolerance, :mod:`assur._still`'s: a relative speed
below a small share of the mechanism's fastest motion at that position is rounding,
not motion, and its sign would pick the friction's sense at random.

Friction makes a group's equilibrium depend on the sizes ``s`` of its own reactions.
Given the senses of the relative motions, the reactions are affine in those sizes:
the frictionless solution plus each pair's response to a unit of its friction, found
by solving the group once per pair with friction. What is left is a small system
``s = |R(s)|`` of one unknown per pair with friction, solved by Newton's method at
every position at once (:mod:`assur._newton`). Of its solutions (a slider may also
wedge in its guide) the one that grows from the frictionless one as the friction
rises is the motion; where it has none with every size positive, no load can drive
the group against its friction: it locks.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence, Set
from dataclasses import dataclass
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._newton import QUICK, TOLERANCE, _norm, _raised, _signs, _sizes, across
from assur._still import Still, rate
from assur._vec import Leaf, Mask, add, cross, dot, full, mul, norm, sub
from assur.groups._motion import Motion, direction, point, rotated
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Equilibrium, Reaction, Wrench

if TYPE_CHECKING:
    from assur.groups._protocol import GroupSolver

__all__ = [
    "GroupFriction",
    "Sizing",
    "friction_wrench",
    "newton_steps",
    "sizing",
    "solve_group",
    "solve_sized",
    "substituted",
]


@dataclass(frozen=True, slots=True)
class GroupFriction:
    """A group's equilibrium with friction.

    ``record`` holds the normal reactions (friction loads counted as known loads of
    the group's links); ``values`` the friction of each pair with friction (couple
    N m on a revolute pair's second link, force N along a prismatic pair's slide
    line); ``wrenches`` the friction wrench on each such pair's second link;
    ``locked`` the positions where the group locks; ``iterations`` how many Newton
    steps it took; ``raised`` whether some position needed the friction raised from
    zero by degrees (Newton from the frictionless sizes did not settle there).
    """

    record: Equilibrium
    values: dict[str, Leaf]
    wrenches: dict[str, Wrench]
    locked: Mask | None
    iterations: int
    raised: bool = False


def friction_wrench(
    pair: PairPlan, bodies: list[Motion], reaction: Reaction, speed: Leaf
) -> tuple[Leaf, Wrench]:
    """Return a pair's friction and its wrench on the pair's second link.

    Revolute: the couple ``-f r |R| sign(w2 - w1)`` (N m). Prismatic: the force
    ``-f |N| sign(v)`` (N) along the slide line, at the pair's point. The wrench's
    moment is about the core's origin.
    """
    sense = np.sign(speed)
    if pair.kind == "R":
        size = norm(reaction.fx, reaction.fy)
        couple = -pair.friction * pair.radius * size * sense
        return couple, [0.0, 0.0, couple]
    nx, ny = rotated(bodies[pair.first], pair.normal)
    normal = dot((reaction.fx, reaction.fy), (nx, ny))
    force = -pair.friction * np.abs(normal) * sense
    assert pair.axis is not None
    ex, ey = direction(bodies[pair.first], pair.axis, 0)
    fx, fy = mul(force, ex), mul(force, ey)
    qx, qy = point(bodies[pair.second], pair.d_second, 0)
    return force, [fx, fy, cross(qx, qy, fx, fy)]


def _with(
    loads: list[Wrench],
    pairs: Sequence[PairPlan],
    wrenches: Mapping[str, Sequence[Leaf]],
    inside: Set[int],
) -> list[Wrench]:
    """Return ``loads`` with each pair's friction on those of its links in the group."""
    out = list(loads)
    for pair in pairs:
        w = wrenches[pair.name]
        if pair.second in inside:
            out[pair.second] = [
                add(a, b) for a, b in zip(out[pair.second], w, strict=True)
            ]
        if pair.first in inside:
            out[pair.first] = [
                sub(a, b) for a, b in zip(out[pair.first], w, strict=True)
            ]
    return out


def _unit(pair: PairPlan, bodies: list[Motion], speed: Leaf) -> Wrench:
    """Return the friction wrench on a pair's second link per unit of reaction."""
    sense = np.sign(speed)
    if pair.kind == "R":
        return [0.0, 0.0, mul(-pair.friction * pair.radius, sense)]
    assert pair.axis is not None
    ex, ey = direction(bodies[pair.first], pair.axis, 0)
    force = mul(-pair.friction, sense)
    fx, fy = mul(force, ex), mul(force, ey)
    qx, qy = point(bodies[pair.second], pair.d_second, 0)
    return [fx, fy, cross(qx, qy, fx, fy)]


def substituted(
    solver: GroupSolver,
    bodies: list[Motion],
    loads: list[Wrench],
    sizes: dict[str, float],
    system: Sizing,
) -> Equilibrium:
    """Return a group's equilibrium with its pairs' friction taken from ``sizes``.

    One step of repeated substitution, the hand method the note shows: each pair's
    friction load is its size (N, by pair name) times its law's factor, a known
    load, and the group is solved as without friction. ``loads`` are the links'
    loads without the group's own friction (one position), those ``system`` (its
    :func:`sizing`) was made with: its pairs, links and factors serve every step,
    so that a step solves the group once, with the friction loads.
    """
    pairs = [p for p in system.pairs if p.name in sizes]
    units = system.units
    friction = {p.name: [mul(sizes[p.name], w) for w in units[p.name]] for p in pairs}
    return solver.equilibrium(bodies, _with(loads, pairs, friction, system.inside))


def _reaction(pair: PairPlan, bodies: list[Motion], record: Equilibrium, n: int) -> Any:
    """Return a pair's reaction as its friction sees it.

    Its force (n, 2) for a revolute pair, its normal force (n, 1) for a prismatic one.
    """
    r = record.reactions[pair.name]
    if pair.kind == "R":
        return np.stack((full(r.fx, n), full(r.fy, n)), axis=-1)
    nx, ny = rotated(bodies[pair.first], pair.normal)
    return full(dot((r.fx, r.fy), (nx, ny)), n)[:, None]


@dataclass(frozen=True, slots=True)
class Sizing:
    """A group's system ``s = |R(s)|`` for the sizes of its pairs' reactions.

    ``pairs`` are its pairs with friction; ``inside`` its links; ``units`` each
    pair's friction wrench per unit of its reaction (see :func:`_unit`); ``start``
    each pair's reaction without the group's friction (see :func:`_reaction`);
    ``response[p][q]`` pair q's reaction for a unit of pair p's friction alone;
    ``base`` the group's equilibrium without its own pairs' friction, solved once
    for both the solve and the note. Its arrays are read-only.
    """

    pairs: tuple[PairPlan, ...]
    inside: frozenset[int]
    units: Mapping[str, tuple[Leaf, ...]]
    start: tuple[Any, ...]
    response: tuple[tuple[Any, ...], ...]
    base: Equilibrium

    def __post_init__(self) -> None:
        """Store tuples, read-only views of the arrays and a read-only map of units."""
        object.__setattr__(self, "pairs", tuple(self.pairs))
        object.__setattr__(self, "inside", frozenset(self.inside))
        units = {k: tuple(_fixed(a) for a in w) for k, w in self.units.items()}
        object.__setattr__(self, "units", MappingProxyType(units))
        object.__setattr__(self, "start", tuple(_fixed(a) for a in self.start))
        response = tuple(tuple(_fixed(a) for a in r) for r in self.response)
        object.__setattr__(self, "response", response)


def _fixed(leaf: Leaf) -> Leaf:
    """Return a read-only view of an array (a float as it is)."""
    if not isinstance(leaf, np.ndarray):
        return leaf
    view = leaf.view()
    view.flags.writeable = False
    return view


def sizing(
    solver: GroupSolver,
    bodies: list[Motion],
    loads: list[Wrench],
    n: int,
    rest: Still,
) -> Sizing | None:
    """Return a group's system for its reactions' sizes (None: it has no friction)."""
    base = solver.equilibrium(bodies, loads)
    pairs = tuple(p for p in base.pairs if p.friction > 0.0)
    if not pairs:
        return None
    inside = frozenset(base.bodies)
    units = {p.name: tuple(_unit(p, bodies, rate(p, bodies, rest))) for p in pairs}
    start = tuple(_reaction(p, bodies, base, n) for p in pairs)
    # each pair's reactions for a unit of one pair's friction alone: the reactions
    # are linear in the loads, and constant zero loads keep these solves cheap
    zero: list[Wrench] = [[0.0, 0.0, 0.0] for _ in loads]
    # one solve per pair with friction, read at every pair
    alone = [solver.equilibrium(bodies, _with(zero, [p], units, inside)) for p in pairs]
    response = tuple(
        tuple(_reaction(q, bodies, record, n) for q in pairs) for record in alone
    )
    return Sizing(pairs, inside, units, start, response, base)


def solve_group(
    solver: GroupSolver,
    bodies: list[Motion],
    loads: list[Wrench],
    n: int,
    rest: Still,
) -> GroupFriction | None:
    """Solve a group's equilibrium with the friction of its pairs (None: it has none).

    The friction of the group's own pairs, internal and external, loads its links;
    the known links' share of the external pairs' friction is passed to them with
    their reactions.
    """
    system = sizing(solver, bodies, loads, n, rest)
    return None if system is None else solve_sized(solver, bodies, loads, system)


def solve_sized(
    solver: GroupSolver, bodies: list[Motion], loads: list[Wrench], system: Sizing
) -> GroupFriction:
    """Solve a group's equilibrium with friction from its :func:`sizing` ``system``.

    ``loads`` are the ones ``system`` was made with.
    """
    pairs, inside, units = system.pairs, system.inside, system.units
    start, response = system.start, system.response
    first = np.stack([_norm(r.T) for r in start], axis=-1)
    scale = across(np.maximum, first) + 1e-300
    # Coulomb's law may hold twice: beside the solution that grows from the
    # frictionless one, a jammed one (a slider wedged in its guide, its normal
    # force reversed). The first is sought with each sliding pair's normal force
    # kept on its frictionless side, where the size is linear in it; it has the
    # Jacobian's determinant of the frictionless system's sign (1 there)
    signed, held_start, held_response = _signs(start, response)
    sizes, settled, growing, count = _sizes(
        held_start, held_response, first.copy(), scale, 1.0, signed
    )
    limit = TOLERANCE * np.maximum(scale, across(np.maximum, np.abs(sizes)))
    finite = across(np.logical_and, np.isfinite(sizes))
    ordinary = settled & growing & across(np.logical_and, sizes >= -limit[:, None])
    # elsewhere (a normal force that friction turns over, near where it is zero
    # without friction) the sizes themselves, then the friction raised from zero
    doubtful = np.flatnonzero(finite & ~ordinary)
    if doubtful.size:
        some_start = [a[doubtful] for a in start]
        some_response = [[a[doubtful] for a in r] for r in response]
        # a position that has not settled in a few steps is left to the raising
        found, kept, growing, more = _sizes(
            some_start, some_response, first[doubtful].copy(), scale[doubtful],
            most=QUICK,
        )  # fmt: skip
        kept &= growing
        sizes[doubtful], settled[doubtful] = found, kept
        count += more
        doubtful = doubtful[~kept]
    raised = bool(doubtful.size)
    if raised:
        found, kept, more = _raised(
            [a[doubtful] for a in start],
            [[a[doubtful] for a in r] for r in response],
            first[doubtful],
            scale[doubtful],
        )
        sizes[doubtful], settled[doubtful] = found, kept
        count += more
    finite = across(np.logical_and, np.isfinite(sizes))
    limit = TOLERANCE * np.maximum(scale, across(np.maximum, np.abs(sizes)))
    # no solution with every size positive: nothing drives the group (self-locking)
    locked = finite & (~settled | across(np.logical_or, sizes < -limit[:, None]))
    friction = {
        p.name: [mul(sizes[:, k], w) for w in units[p.name]]
        for k, p in enumerate(pairs)
    }
    record = solver.equilibrium(bodies, _with(loads, pairs, friction, inside))
    # the friction the record was solved with: equal to f times the final reactions'
    # sizes within the tolerance, and consistent with the record exactly
    values = {
        p.name: mul(
            sizes[:, k],
            units[p.name][2] if p.kind == "R" else _along(p, bodies, units[p.name]),
        )
        for k, p in enumerate(pairs)
    }
    return GroupFriction(
        record, values, friction, locked if locked.any() else None, count, raised
    )


def _along(pair: PairPlan, bodies: list[Motion], unit: Sequence[Leaf]) -> Leaf:
    """Return a prismatic pair's unit friction force along its slide line (N)."""
    assert pair.axis is not None
    ex, ey = direction(bodies[pair.first], pair.axis, 0)
    return dot((unit[0], unit[1]), (ex, ey))


def newton_steps(
    system: Sizing, bodies: list[Motion], found: Equilibrium, tolerance: float
) -> int | None:
    """Return how many Newton steps lead from the frictionless sizes to ``found``'s.

    One position. The steps are :func:`solve_group`'s at full friction, each
    sliding pair's normal force held on the side it has in ``found``, the
    solution: the frictionless one's side is round-off at a dead centre (1.6e-14
    N beside 1622 N), the machine's to choose, and on the wrong side the analysis
    solved a second time. A step that moves no size by more than ``tolerance``
    of the largest ends the count, a share well above round-off; steps to one
    near it (the solve's :data:`assur._newton.TOLERANCE`) are as many as its
    last bits allow. None where the steps do not settle on a solution that grows
    from the frictionless one (the analysis raised the friction from zero there).
    """
    held = [_reaction(p, bodies, found, 1) if p.kind == "P" else None
            for p in system.pairs]  # fmt: skip
    signed, start, response = _signs(system.start, system.response, held)
    first = np.stack([_norm(r.T) for r in system.start], axis=-1)
    scale = across(np.maximum, first) + 1e-300
    _, settled, growing, count = _sizes(
        start, response, first.copy(), scale, 1.0, signed, tolerance=tolerance
    )
    return count if bool(settled[0] and growing[0]) else None
