"""The analysis at one driver position written out as a student writes it by hand.

:func:`explain` solves the mechanism at one position and words every step: the
structure, each group's position, velocity and acceleration equations with their
numbers, the inertia loads, each group's equilibrium in the reverse order, the input
link's balancing load and its check by Zhukovsky's lever. With friction in the
pairs, each group also shows its pairs' friction loads and how their sizes were
found, and the balancing load and the lever count the friction. The :class:`Note`
it returns is Markdown (``str()``), HTML with MathML or LaTeX.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from numpy.typing import ArrayLike

from assur._structure import structure
from assur._text import spoken
from assur._warn import warn
from assur.errors import AssurWarning, SelfLockingError
from assur.explain._answers import answer_blocks, checked_answers, read_answers
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

__all__ = ["Note", "explain", "read_answers"]


def explain(
    mechanism: Mechanism,
    angle: ArrayLike,
    answers: Mapping[str, float] | None = None,
    source: str = "",
) -> Note:
    """Return the analysis of ``mechanism`` at driver position ``angle``, explained.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism, as :func:`assur.load <assur.io.load>` or
        :mod:`assur.catalog` give it.
    angle : float or sequence of float
        Driver position, deg (m for a prismatic driver); one value per driver.
    answers : mapping of str to float, optional
        Given answers to compare with (a textbook's), by table column or magnitude
        (``"rod.G.a"``, ``"rod.Fi"``, ``"C.v"``): see :func:`read_answers`
        (``from assur.explain import read_answers``; ``assur.explain`` is this
        function).
    source : str
        Where the given answers come from, for the note's words.

    Returns
    -------
    Note
        ``str(note)`` is Markdown; ``note.to_html()`` and ``note.to_latex()`` the same
        note as a self-contained page and as a LaTeX report. Where friction locks a
        group at ``angle``, the note goes as far as that group and shows why it
        locks; its ``values`` are then NaN for the forces not reached (that group's
        reactions and those after it, the balancing loads).

    Warns
    -----
    AssurWarning
        Where friction locks a group at ``angle`` (the note has no balancing load
        and no lever there), naming the group.

    Raises
    ------
    AssemblyError
        When the mechanism cannot be assembled at ``angle``.
    ModelError
        When an answer names no quantity of the mechanism.
    UsageError
        When ``answers`` is not a mapping of names to finite numbers.

    Examples
    --------
    >>> from assur import catalog
    >>> note = explain(catalog.slider_crank(), 45.0)
    >>> str(note).startswith("# ")
    True
    """
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
            stacklevel=2,
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
