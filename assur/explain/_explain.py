"""The explanatory note made: the analysis at one position, solved, then worded.

:func:`assur.explain` (this package's function, documented there) calls
:func:`explained`; the package loads this module, and with it the analysis, at
the first note it makes.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from numpy.typing import ArrayLike

from assur._structure import structure
from assur._text import spoken
from assur._warn import warn
from assur.errors import AssurWarning, SelfLockingError
from assur.explain._answers import answer_blocks, checked_answers
from assur.explain._driver_text import driver_blocks
from assur.explain._forces_text import forces_blocks
from assur.explain._inertia_text import inertia_blocks
from assur.explain._kinematics_text import kinematics_blocks
from assur.explain._lever import lever_blocks
from assur.explain._note import Block, Heading, Note, Para
from assur.explain._position import Position
from assur.explain._solve import locked_position, position
from assur.explain._structure_text import structure_blocks
from assur.explain._tex import FLOOR, plain
from assur.model import Mechanism

__all__ = ["explained"]


def explained(
    mechanism: Mechanism,
    angle: ArrayLike,
    answers: Mapping[str, float] | None = None,
    source: str = "",
) -> Note:
    """Return the note of :func:`assur.explain`, which documents it."""
    if answers is not None:
        answers = checked_answers(answers)
    try:
        pos = position(mechanism, angle)
    except SelfLockingError as err:
        pos = locked_position(mechanism, angle, err)
        warn(
            f"group {pos.locked}: its friction locks it at {_where(pos.table)}: the "
            "note shows the analysis as far as that group, and why it locks (no "
            "balancing load, no lever)",
            AssurWarning,
            stacklevel=3,  # the caller of assur.explain
        )
    # the note's numbers told from round-off at its mechanism's own scale
    token = FLOOR.set(_floor(pos))
    try:
        blocks = _blocks(mechanism, pos, answers, source)
    finally:
        FLOOR.reset(token)
    name = plain(mechanism.name or "Mechanism")
    title = f"{name} at {_where(pos.table)}: the analysis explained"
    table = pos.table
    values = {
        c: float(v[0]) for c, v in zip(table.columns, table.arrays(), strict=True)
    }
    return Note(title, tuple(blocks), values)


def _floor(pos: Position) -> float:
    """Return what a number is told from round-off by where its line gives no scale.

    The least of 1 (the cut of SI before: no more than it), the mechanism's size
    (m), its speeds (m/s), its loads (N), their moments (N m) and powers (W): a
    watch's 1e-11 N m is its balancing torque, not round-off. For the bundled
    examples, a few tenths: their notes the same as with 1.
    """
    size, speed = pos.size(), pos.rate_scale(1)
    found = [1.0, size, speed]
    if pos.applied is not None:
        force = pos.force_scale()
        found += [force, force * size, force * speed]
    return min(v for v in found if v > 0.0)


def _blocks(
    mechanism: Mechanism,
    pos: Position,
    answers: Any,
    source: str,
) -> list[Block]:
    """Return the note's blocks, its sections numbered."""
    blocks: list[Block] = []
    if pos.locked is not None:
        blocks.append(
            Para(
                f"At this position friction locks group {plain(pos.locked)}: the note "
                "stops at that group, in section 4, and shows why."
            )
        )
    blocks += structure_blocks(structure(mechanism))
    blocks += kinematics_blocks(pos)
    if pos.result is None:
        blocks.append(
            Para(
                "No link has a mass and no load is applied: the force analysis has "
                "nothing to find."
            )
        )
    else:
        blocks += inertia_blocks(pos)
        blocks += forces_blocks(pos)
        if pos.locked is None:
            blocks += driver_blocks(pos)
            blocks += lever_blocks(pos)
    if answers:
        blocks += answer_blocks(pos, answers, source)
    return _numbered(blocks)


def _numbered(blocks: list[Block]) -> list[Block]:
    """Return ``blocks`` with their sections numbered in order.

    A note without forces, or one that stops where friction locks a group, leaves
    sections out; the answers' section follows on from the last one written.
    """
    out: list[Block] = []
    count = 0
    for block in blocks:
        if isinstance(block, Heading) and block.level == 2:
            count += 1
            block = Heading(2, f"{count}. {block.text.partition('. ')[2]}")
        out.append(block)
    return out


def _where(table: Any) -> str:
    """Return the note's driver positions for its title: "crank angle 100 deg".

    An angle is in deg, a slide in m, as the note gives them; with several
    drivers each follows its input link's name.
    """
    plan = table.plan
    values = [
        f"{x + 0.0:.6g} deg" if d.kind == "R" else f"{x + 0.0:.6g} m"  # -0: 0
        for d, x in zip(plan.drivers, table.given[0].tolist(), strict=True)
    ]
    if len(values) == 1:
        what = "crank angle" if plan.drivers[0].kind == "R" else "driver position"
        return f"{what} {values[0]}"
    names = [plain(plan.bodies[d.body]) for d in plan.drivers]
    # "2 at 0 deg": a link named by a number would else read as part of the value
    named = [f"{n} at {v}" for n, v in zip(names, values, strict=True)]
    return "driver positions " + spoken(named)
