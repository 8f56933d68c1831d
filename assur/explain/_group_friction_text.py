r"""How a group with friction is solved, as the note writes it: by hand.

The friction loads depend on the reactions being found, so :mod:`assur._friction`
solves a group with friction by Newton's method on its reactions' sizes. The note
shows the hand method instead, repeated substitution from the frictionless sizes, a
row a step (and, where that settles slowly or not at all, the sizes Newton's method
found, with what the steps' ratio says), then writes the friction loads of the
sizes found: the group's equations hold with those loads as known ones.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from assur._friction import Sizing, newton_steps, sizing, solve_sized, substituted
from assur._text import spoken
from assur.explain._friction_text import (
    at_rest,
    friction_lines,
    normal_force,
    rubbing,
    size_symbol,
)
from assur.explain._note import Block, Display, Grid, Para
from assur.explain._position import Position
from assur.explain._tex import num, plain
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Equilibrium, GroupSolver, Wrench
from assur.kinetostatics import Applied, with_friction

__all__ = [
    "frictionless",
    "group_friction_blocks",
    "group_sizing",
    "method",
    "newton_start",
    "steps_ratio",
    "substitution",
    "substitution_caption",
    "substitution_grid",
    "without_own",
]

SETTLED = 1e-6
"""A step of repeated substitution that changes no size by more than this share of
the largest has settled (the note writes four or five digits)."""
MOST_STEPS = 12
"""Most steps of repeated substitution the note writes."""


def group_sizing(pos: Position, solver: GroupSolver, loads: list[Wrench]) -> Sizing:
    """Return the group's system for its sizes, at the note's one position.

    ``loads`` are :func:`without_own`'s. Its solve without the group's friction
    serves Newton's start, Newton's steps and every step of repeated substitution.
    """
    system = sizing(solver, pos.bodies, loads, 1, at_rest(pos))
    # the note writes this only of a group with pairs that rub: it has a system
    assert system is not None
    return system


def newton_start(
    pos: Position,
    rec: Equilibrium,
    solver: GroupSolver,
    loads: list[Wrench],
    system: Sizing,
) -> tuple[dict[str, float], int | None, bool]:
    """Return Newton's start (sizes, N), its steps, and whether it raised friction.

    Friction is raised from zero step by step where Newton from the frictionless
    sizes does not settle, and the steps are then not counted (None). The start
    is :func:`frictionless`, of ``system`` (:func:`group_sizing` of ``loads``);
    the steps are counted to the measure the hand method's are, a step below
    :data:`SETTLED` of the largest size (see :func:`assur._friction.newton_steps`):
    to the solve's own tolerance, near round-off, their count is the machine's
    arithmetic's at a dead centre.
    """
    sizes = frictionless(pos, rec, system)
    if solve_sized(solver, pos.bodies, loads, system).raised:
        return sizes, None, True
    return sizes, newton_steps(system, pos.bodies, rec, SETTLED), False


def frictionless(pos: Position, rec: Equilibrium, system: Sizing) -> dict[str, float]:
    """Return the sizes (N) of the group solved without its own pairs' friction.

    ``system`` is :func:`group_sizing`'s, which keeps that solve: its loads are
    :func:`without_own`'s, the friction the groups solved before passed on kept.
    """
    return _sizes(pos, rec, system.base)


def _sizes(pos: Position, rec: Equilibrium, record: Equilibrium) -> dict[str, float]:
    """Return the sizes (N) friction is taken from, of ``rec``'s pairs in ``record``."""
    return {
        p.name: float(np.hypot(*normal_force(pos, p, record.reactions[p.name])))
        for p in rubbing(rec.pairs)
    }


def without_own(pos: Position, rec: Equilibrium) -> list[Wrench]:
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
    pos: Position,
    rec: Equilibrium,
    solver: GroupSolver,
    loads: list[Wrench],
    system: Sizing,
) -> list[dict[str, float]]:
    """Return the sizes (N) of repeated substitution, step by step.

    Each step takes the friction loads of the sizes before, solves the group with
    them known and takes the sizes of the reactions it gives; it stops once a step
    changes no size by more than :data:`SETTLED` of the largest, or after
    :data:`MOST_STEPS` steps (near self-locking it settles slowly or not at all).
    It starts from :func:`frictionless`; ``system`` (:func:`group_sizing` of
    ``loads``) gives every step the group's pairs, links and friction factors.
    """
    steps = [frictionless(pos, rec, system)]
    for _ in range(MOST_STEPS):
        sizes = _sizes(
            pos, rec, substituted(solver, pos.bodies, loads, steps[-1], system)
        )
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
    loads = without_own(pos, rec)
    system = group_sizing(pos, solver, loads)
    _, steps, raised = newton_start(pos, rec, solver, loads, system)
    final = _sizes(pos, rec, rec)
    lines = [
        line
        for p in pairs
        for line in friction_lines(pos, p, size_symbol(pos, p), final[p.name])
    ]
    tried = substitution(pos, rec, solver, loads, system)
    # settled where the last row reads as the sizes the friction loads below are
    # written from, each to its own digits (a small |N| beside a large journal's)
    settled = all(num(tried[-1][k]) == num(final[k]) for k in final)
    head, rows = substitution_grid(pos, pairs, tried)
    if settled:
        how = (
            "The sizes settle; Newton's method on them, which the analysis uses, "
            f"finds the same{_spaced(_newton_steps(steps, raised))}."
        )
    else:
        rows.append(("found", *(f"${num(final[p.name])}$" for p in pairs)))
        how = _unsettled(tried, _newton_steps(steps, raised))
    return [
        method(pairs),
        Grid(head, tuple(rows), substitution_caption(rec)),
        Para(how + " The friction loads of these sizes:"),
        Display(tuple(lines)),
        Para(
            "They are known loads of the group's links below (a couple on each link "
            "of a revolute pair, a force along the slide on each link of a sliding "
            "pair, opposite on the pair's first link), and the equations hold with "
            "them: the reactions found have the sizes the friction was taken from."
        ),
    ]


def method(pairs: list[PairPlan]) -> Para:
    """Return the friction laws of ``pairs`` and the hand method that sizes them."""
    listed = spoken([plain(p.name) for p in pairs])
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
            "adds no friction in this model)"
        )
    return Para(
        # each law holds commas of its own: the laws are apart by a semicolon;
        # the last law ends in brackets: the kinetic rule is a sentence of its own
        f"Friction in {listed}: {'; '.join(laws)}. The friction is kinetic only: "
        "a pair at rest has none. Each friction load depends on the size of a "
        "reaction not yet known. With the senses of the relative motions known, each "
        "friction load is its size times a known factor, and the reactions "
        "are linear in the friction loads; but a reaction's size is not linear "
        "in its components, so the sizes are found by repeated substitution. "
        "Start from the sizes without this group's friction, take the friction "
        "loads of those sizes as known loads, solve the group as without "
        "friction, take the sizes of the reactions it gives, and repeat (sizes "
        "in N):"
    )


def substitution_grid(
    pos: Position, pairs: list[PairPlan], tried: list[dict[str, float]]
) -> tuple[tuple[str, ...], list[tuple[str, ...]]]:
    """Return the head and rows of the table of repeated substitution's steps."""
    head = ("step", *(f"${size_symbol(pos, p)}$" for p in pairs))
    rows = [
        (
            "0 (frictionless)" if i == 0 else str(i),
            *(f"${num(sizes[p.name])}$" for p in pairs),
        )
        for i, sizes in enumerate(tried)
    ]
    return head, rows


def substitution_caption(rec: Equilibrium) -> str:
    """Return the caption of the table of repeated substitution in ``rec``'s group."""
    return f"Repeated substitution in group {plain(rec.label)}: the sizes at each step"


def _newton_steps(steps: int | None, raised: bool = False) -> str:
    """Return how Newton's method found the sizes, in words ("in 3 steps").

    Empty where its steps from the frictionless sizes, counted as the note counts
    them (see :func:`newton_start`), do not settle and the analysis did not raise
    the friction either: it found them on its second try.
    """
    if raised:
        # from the frictionless sizes it did not settle: the friction was raised
        return "with the friction raised from zero step by step"
    if steps is None:
        return ""
    return f"in {steps} step{'s' if steps != 1 else ''}"


def _spaced(words: str) -> str:
    """Return ``words`` after a space, or nothing for none."""
    return f" {words}" if words else ""


def steps_ratio(tried: list[dict[str, float]]) -> tuple[float, bool, list[float]]:
    """Return the ratio of the last steps, whether it is steady, and the last moves.

    The steps are those of the size that moves most in the last step; steady: the
    last three ratios lie within 0.05 of one another.
    """
    key = max(tried[-1], key=lambda k: abs(tried[-1][k] - tried[-2][k]))
    moves = [tried[i][key] - tried[i - 1][key] for i in range(1, len(tried))][-4:]
    ratios = [b / a for a, b in itertools.pairwise(moves) if a != 0]
    steady = len(ratios) >= 3 and max(ratios) - min(ratios) < 0.05
    return (ratios[-1] if ratios else math.nan), steady, moves


def _unsettled(tried: list[dict[str, float]], newton: str) -> str:
    """Return what the note says where repeated substitution has not settled.

    The ratio of its last steps (of the size that moves most) tells the case: near
    +1 the steps shrink slowly the same way (near self-locking, with the steps
    still needed); below 0 they overshoot and swing back, which says nothing of
    locking; not steady, they jump about.
    """
    r, steady, moves = steps_ratio(tried)
    how = f" ({newton})" if newton else ""
    found = (
        f" The sizes found (last row) are those of Newton's method on them{how}, "
        "which the analysis uses: of the solutions "
        "Coulomb's law allows (with large friction it can allow two), the one reached "
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
