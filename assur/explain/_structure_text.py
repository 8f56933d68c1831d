"""The note's first part: degrees of freedom and the Assur groups, with the numbers.

The words are those of the structure report (:mod:`assur.report`); the note adds the
formula with its numbers and the order of the two passes.
"""

from __future__ import annotations

import re

from assur._structure import Group, Structure
from assur._text import noun_for, roman, spelt
from assur.explain._note import Block, Display, Heading, Items, Para
from assur.explain._tex import plain
from assur.report import _apart, _class_why, _members, _pairs_text, _why

__all__ = ["structure_blocks"]

COUNTS = re.compile(r"\b(?:k = \d+|p = \d+|W = 3k - 2p = \d+ - \d+ = 0|W > 0)")
"""The counts of the structure report's words on a group, set as mathematics."""


def _kind(kind: str) -> str:
    """Return a group's kind in words."""
    return {"triad": "triad", "general": "group"}.get(kind, f"dyad {kind}")


def structure_blocks(s: Structure) -> list[Block]:
    """Return the structural analysis: W, the groups in order, why each is one."""
    n, p5, p4 = s.links, s.lower_pairs, s.higher_pairs
    blocks: list[Block] = [
        Heading(2, "1. Structure"),
        Para(
            f"The mechanism has $n = {n}$ moving {noun_for(n, 'link')}, $p_5 = {p5}$ "
            f"lower {noun_for(p5, 'pair')} and $p_4 = {p4}$ higher "
            f"{noun_for(p4, 'pair')}. Chebyshev-Gruebler's formula gives its degrees "
            "of freedom:"
        ),
        Display(
            (f"W = 3n - 2p_5 - p_4 = 3 \\cdot {n} - 2 \\cdot {p5} - {p4} = {s.dof}",)
        ),
    ]
    for slot in s.slots:
        blocks.append(
            Para(
                f"The slot {plain(slot)} (a pin in a slot, a higher pair) is replaced "
                f"by a block sliding in the slot and pinned to the pin: one more link "
                "and two lower pairs leave $W$ as it is."
            )
        )
    items = [
        f"Class I: the frame and the input link {plain(g.links[1])}, driven through "
        f"the pair {plain(g.internal[0])}."
        for g in s.drivers
    ]
    said: dict[tuple[int, int], Group] = {}
    for g in s.groups:
        # the words of the structure report: which pairs are inside the group and
        # which hang it on the known links, why it is a group, why of its class
        numeral = roman(g.group_class)
        text = (
            f"Class {numeral}, order {g.order}, {_kind(g.kind)} "
            f"({_members(g.links)}): {_pairs_text(g)}. "
            f"Why an Assur group: {_why(g, said)}."
        )
        if g.basis:
            text += f" Why class {numeral}: {_class_why(g)}."
        items.append(_typeset(plain(text)))
    inputs = "input link" if len(s.drivers) == 1 else "input links"
    order = (
        "The kinematic analysis goes through the groups in this order, the force "
        f"analysis in the reverse order, ending with the {inputs}."
        if s.groups
        else f"With no Assur group, the kinematic and the force analysis take the "
        f"{inputs} alone."
    )
    apart = "".join(f"{plain(line.strip())} " for line in _apart(s))
    blocks += [
        Para(
            f"As $W = {s.dof}$, {_driving(len(s.drivers))} the mechanism. The "
            f"{inputs} and the Assur groups, in order of attachment:"
        ),
        Items(tuple(items)),
        Para(
            f"Structure formula: {plain(s.formula.replace(' -> ', ' → '))}; a class "
            f"{roman(s.mechanism_class)} mechanism. {apart}{order}"
        ),
    ]
    return blocks


def _driving(count: int) -> str:
    """Return how many drivers move the mechanism, in words: 'one driver moves'."""
    return "one driver moves" if count == 1 else f"{spelt(count)} drivers move"


def _typeset(text: str) -> str:
    """Return a group's words with their counts as inline mathematics.

    The structure report's words are plain text ("W = 3k - 2p = 6 - 6 = 0", with
    hyphens for minus signs); the note sets them as its other formulas.

    Examples
    --------
    >>> _typeset("k = 2 links; W = 3k - 2p = 6 - 6 = 0, and W > 0")
    '$k = 2$ links; $W = 3k - 2p = 6 - 6 = 0$, and $W > 0$'
    """
    return COUNTS.sub(lambda found: f"${found.group(0)}$", text)
