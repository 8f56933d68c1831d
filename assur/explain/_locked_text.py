"""Where friction locks a group: the note's last steps at such a position.

The reverse pass solves each group with its pairs' friction by Newton's method on the
reactions' sizes; where no sizes hold with the links moving as they do, friction
locks the group (:class:`~assur.errors.SelfLockingError`). The note then shows the
hand method running away: repeated substitution from the frictionless sizes, whose
steps grow, and stops there, for the groups left and the input link take the locked
group's reactions, which have no value.
"""

from __future__ import annotations

import math

from assur.explain._friction_text import rubbing
from assur.explain._group_friction_text import (
    group_sizing,
    method,
    steps_ratio,
    substitution,
    substitution_caption,
    substitution_grid,
    without_own,
)
from assur.explain._note import Block, Grid, Para
from assur.explain._position import Position, unit
from assur.explain._tex import ZERO, num, plain
from assur.groups._dyad import DyadSolver
from assur.groups._protocol import Equilibrium, GroupSolver

__all__ = ["locked_blocks"]


def locked_blocks(
    pos: Position, rec: Equilibrium, solver: GroupSolver, later: int
) -> list[Block]:
    """Return repeated substitution in a group friction locks, and what it means.

    ``later`` counts the groups the reverse pass would have solved after it.
    """
    pairs = rubbing(rec.pairs)
    loads = without_own(pos, rec)
    # from the frictionless sizes (Newton's method, which runs away here, not run)
    system = group_sizing(pos, solver, loads)
    tried = substitution(pos, rec, solver, loads, system)
    head, rows = substitution_grid(pos, pairs, tried)
    return [
        method(pairs),
        Grid(head, tuple(rows), substitution_caption(rec)),
        Para(_steps(tried)),
        *_cone(pos, solver),
        Para(
            "So friction locks the group here (self-locking): no driving load, "
            "however large, moves its links the way the motion asks, for the harder "
            "it drives them, the harder it presses the pairs that rub; the analysis "
            "finds no reactions for the group. A real machine would jam on coming "
            "to this position: the motion taken in sections 2 and 3 cannot happen "
            f"this way. {_left(pos, later)} would take "
            "this group's reactions, so the reverse pass stops here: at this "
            "position there is no balancing load and no check by Zhukovsky's "
            "lever. With less friction, or at positions away from this one, the "
            "group can be driven (a sweep names the positions where it locks)."
        ),
    ]


def _cone(pos: Position, solver: GroupSolver) -> list[Block]:
    """Return the textbook's condition where a rod pushes a slider in a guide.

    An RRP dyad whose guide rubs: the rod's push P along BC, at beta to the guide,
    moves the slider with P cos(beta) against the friction f P sin(beta) of the
    normal force it makes. Other groups lock as their own geometry says: the
    steps' ratio alone is written for them.
    """
    if not isinstance(solver, DyadSolver) or solver.kind != "RRP":
        return []
    guide = solver.ext[1]
    if guide.kind != "P" or not guide.friction > 0.0:
        return []
    rod = unit(pos.pair_point(solver.mid) - pos.pair_point(solver.ext[0]))
    along = unit(pos.turned(guide.first, guide.axis or (1.0, 0.0)))
    beta = math.acos(min(1.0, abs(float(rod @ along))))
    f = guide.friction
    lean, phi = math.degrees(beta), math.degrees(math.atan(f))
    gain = f * math.tan(beta)
    product = f"$f\\tan\\beta = {num(f)} \\cdot \\tan {num(lean)}^\\circ = {num(gain)}"
    if gain >= 1.0:
        here = (
            f"Here {product} \\ge 1$: the rod's line lies inside the guide's "
            f"friction cone ($\\beta = {num(lean)}^\\circ \\ge 90^\\circ - \\varphi "
            f"= {num(90.0 - phi)}^\\circ$); the pins' friction moves the steps' "
            "ratio a little from it. A guide friction below $\\cot\\beta = "
            f"{num(1.0 / math.tan(beta))}$ would let the push move the slider here "
            "(a little less, with the pins' friction)."
        )
    else:
        here = (
            f"Here {product} < 1$: the guide alone would let the push move the "
            "slider; the pins' friction tips the group over."
        )
    ends = [plain(p.name) for p in (solver.ext[0], solver.mid)]
    return [
        Para(
            f"Why: the rod pushes the slider along {ends[0]}{ends[1]}, at $\\beta = "
            f"{num(lean)}^\\circ$ to the slide line of {plain(guide.name)}. A "
            "push $P$ drives the slider along the guide with $P\\cos\\beta$ and "
            "presses it on the guide with $P\\sin\\beta$, whose friction is "
            "$f P\\sin\\beta$; so the push can move the slider only while "
            "$P\\cos\\beta > f P\\sin\\beta$, that is while $f\\tan\\beta < 1$, or "
            "$\\beta < 90^\\circ - \\varphi$, with $\\varphi = \\arctan f = "
            f"{num(phi)}^\\circ$ the guide's angle of friction. {here}"
        )
    ]


def _left(pos: Position, later: int) -> str:
    """Name what the reverse pass had still to solve, starting a sentence.

    The groups left after the locked one (``later``), and the input links.
    """
    inputs = "the input links" if len(pos.plan.drivers) > 1 else "the input link"
    if later:
        left = "the group left" if later == 1 else f"the {later} groups left"
        inputs = f"{left} and {inputs}"
    return inputs[0].upper() + inputs[1:]


def _steps(tried: list[dict[str, float]]) -> str:
    """Say what the steps of repeated substitution do where the group locks.

    Growing steps, in a steady ratio of at least 1, are the lock itself: the
    friction each size brings asks for a larger size than that. Otherwise (steps
    that shrink slowly, swing or jump about) Newton's method has not settled in
    its steps, which the words say as the sweep's message does.
    """
    newton = (
        "Newton's method on the sizes, from the frictionless ones and with the "
        "friction raised from zero step by step, finds none that hold"
    )
    if len(tried) < 3:
        return f"{newton}: the group is at self-locking or too near it."
    r, steady, _ = steps_ratio(tried)
    # at the lock's threshold (f tan(beta) = 1) the ratio is 1 but for round-off:
    # 0.9999999999999984 here, 1.0 there, by the last bit of f and the geometry
    if steady and r >= 1.0 - ZERO:
        # at the lock's threshold the steps keep their size: they do not grow
        grow = "grow" if f"{r:.3f}" != "1.000" else "do not shrink"
        return (
            f"The sizes do not settle: each step moves them the same way by about "
            f"{r:.3f} times the step before, so the steps {grow} and the sizes run "
            "away. The friction that a rise of the sizes brings asks for a rise at "
            f"least as large, so the substitution cannot settle. {newton} either."
        )
    if steady and 0.0 < r < 1.0:
        return (
            "The substitution settles slowly here: each step moves the sizes the "
            f"same way by about {r:.3f} times the step before (near 1, near "
            f"self-locking). {newton} within its steps: the group is at "
            "self-locking or too near it for its sizes to be found."
        )
    return (
        f"The substitution does not settle here. {newton} within its steps: the "
        "group is at self-locking or too near it for its sizes to be found."
    )
