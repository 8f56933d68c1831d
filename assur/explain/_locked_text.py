"""Where friction locks a group: the note's last steps at such a position.

The reverse pass solves each group with its pairs' friction by Newton's method on the
reactions' sizes; where no sizes hold with the links moving as they do, friction
locks the group (:class:`~assur.errors.SelfLockingError`). The note then shows the
hand method running away: repeated substitution from the frictionless sizes, whose
steps grow, and stops there, for the groups left and the input link take the locked
group's reactions, which have no value.
"""

from __future__ import annotations

from assur.explain._friction_text import rubbing
from assur.explain._group_friction_text import (
    method,
    newton_start,
    steps_ratio,
    substitution,
    substitution_grid,
    without_own,
)
from assur.explain._note import Block, Grid, Para
from assur.explain._position import Position
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
    start, _, _ = newton_start(pos, rec, solver, loads)
    tried = substitution(pos, rec, solver, loads, start)
    head, rows = substitution_grid(pos, pairs, tried)
    return [
        method(pairs),
        Grid(head, tuple(rows)),
        Para(_steps(tried)),
        Para(
            "So friction locks the group here (self-locking): no driving load, "
            "however large, moves its links the way the motion asks, and the "
            f"analysis finds no reactions for it. {_left(pos, later)} would take "
            "this group's reactions, so the reverse pass stops here: at this "
            "position there is no balancing load and no check by Zhukovsky's "
            "lever. With less friction, or at positions away from this one, the "
            "group can be driven (a sweep names the positions where it locks)."
        ),
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
        "friction raised from zero by degrees, finds none that hold"
    )
    if len(tried) < 3:
        return f"{newton}: the group is at self-locking or too near it."
    r, steady, _ = steps_ratio(tried)
    if steady and r >= 1.0:
        # at the lock's threshold the steps keep their size: they do not grow
        grow = "grow" if f"{r:.2f}" != "1.00" else "do not shrink"
        return (
            f"The sizes do not settle: each step moves them the same way by about "
            f"{r:.2f} times the step before, so the steps {grow} and the sizes run "
            "away. The friction that a rise of the sizes brings asks for a rise at "
            f"least as large: no sizes satisfy the friction laws. {newton} either."
        )
    if steady and 0.0 < r < 1.0:
        return (
            "The substitution settles slowly here: each step moves the sizes the "
            f"same way by about {r:.2f} times the step before (near 1, near "
            f"self-locking). {newton} within its steps: the group is at "
            "self-locking or too near it for its sizes to be found."
        )
    return (
        f"The substitution does not settle here. {newton} within its steps: the "
        "group is at self-locking or too near it for its sizes to be found."
    )
