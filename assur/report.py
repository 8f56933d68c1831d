"""Readable reports: the structural analysis explained step by step.

Text only; the numerical core builds the data and this module words it for a
student's eyes.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from assur._text import counted, public_name, roman, spelt, spoken

if TYPE_CHECKING:
    from assur._structure import Group, Structure

__all__ = ["freedom_lines", "structure_report"]


def _names(items: tuple[str, ...]) -> str:
    """Return names as a sentence lists them: "links 3 and 4", "pairs B, D and E"."""
    return spoken([public_name(x) for x in items])


def _members(items: tuple[str, ...]) -> str:
    """Return a group's links as its formula writes them: "II(3, 4)"."""
    return ", ".join(public_name(x) for x in items)


def _counted(noun: str, items: tuple[str, ...]) -> str:
    """Return ``noun`` (in the plural for several items) and the items' names."""
    return f"{noun}{'' if len(items) == 1 else 's'} {_names(items)}"


def _links_text(links: tuple[str, ...]) -> str:
    """Return known links as a sentence names them: "links 2 and ground"."""
    noun = "link" if len(links) == 1 else "links"
    return f"{noun} {spoken([public_name(x) for x in links])}"


def _pairs_text(g: Group) -> str:
    """Return a group's internal and external pairs, and its sliding ones by name.

    A dyad's kind names its prismatic pairs; a larger group's are listed.
    """
    # the pairs that set the class first, in order round their contour
    internal = (*g.basis, *(x for x in g.internal if x not in g.basis))
    known = _counted("known link", g.attached_to)
    carried = len(g.carriers) == len(g.external)  # a Group made by hand may lack them
    if carried and len(g.external) > len(g.attached_to) > 1:
        # three pairs on two links do not pair off in order: each link's are named
        known = _counted("known link", tuple(_carried(g, x) for x in g.attached_to))
    text = (
        f"{_counted('internal pair', internal)}; "
        f"{_counted('external pair', g.external)} on the {known}"
    )
    if g.sliding:
        text += f"; {_counted('prismatic pair', g.sliding)}, the others revolute"
    return text


def _carried(g: Group, link: str) -> str:
    """Return a known link and the group's external pairs on it: "ground (F and G)"."""
    on = tuple(p for p, x in zip(g.external, g.carriers, strict=True) if x == link)
    return f"{link} ({_names(on)})"


def _why(g: Group, said: dict[tuple[int, int], Group] | None = None) -> str:
    """Return why ``g`` is an Assur group, its count worked out.

    ``said`` holds the groups already explained, by their counts (k, p): a group
    counted as one of them refers to it, where the whole reason came again (a
    ten-bar's four dyads said it four times over).
    """
    k = len(g.links)
    p = len(g.internal) + len(g.external)
    first = None if said is None else said.setdefault((k, p), g)
    if first is not None and first is not g:
        return (
            f"the same counts as for links {_names(first.links)} above: "
            f"k = {k}, p = {p}, W = 3k - 2p = {3 * k} - {2 * p} = 0, "
            "and every smaller part keeps W > 0"
        )
    return (
        f"k = {k} links, p = {p} lower pairs; with its external pairs on the known "
        f"links, W = 3k - 2p = {3 * k} - {2 * p} = 0, and every smaller part of it "
        "keeps W > 0 (it cannot be split into simpler groups)"
    )


def _class_why(g: Group) -> str:
    """Return what sets the class of a group of class III or higher."""
    count = spelt(len(g.basis))
    pairs = _names(g.basis)
    if g.base:
        return (
            f"its base link {public_name(g.base)} carries {count} internal pairs, "
            f"{pairs} ({CLASS_RULE})"
        )
    return f"its internal pairs {pairs} close a contour of {count} links ({CLASS_RULE})"


CLASS_RULE = (
    "above class II, the class is the number of internal pairs of the most complex "
    "closed contour they form; a base link carrying three internal pairs counts as a "
    "contour of three"
)
"""What sets the class of a group of class III or higher, in the words said."""


def _apart(s: Structure) -> list[str]:
    """Return lines for the groups that do not hang on the group before them.

    The formula's arrows give the order of attachment; a group that hangs only on
    links known before the group ahead of it could come first as well.
    """
    lines = []
    for before, g in itertools.pairwise(s.groups):
        if set(g.attached_to).isdisjoint(before.links):
            lines.append(
                f"  {roman(g.group_class)}({_members(g.links)}) is attached to "
                f"{_links_text(g.attached_to)}, not to {roman(before.group_class)}"
                f"({_members(before.links)}): the two groups could be attached in "
                "either order."
            )
    return lines


def _class_reason(s: Structure) -> str:
    """Return where the class of the mechanism comes from."""
    if s.groups:
        return "the highest class of its groups"
    inputs = "its input link" if len(s.drivers) == 1 else "its input links"
    return f"the frame and {inputs} alone, no Assur group"


def freedom_lines(s: Structure) -> list[str]:
    """Return the degrees of freedom counted, and what was counted (two lines)."""
    n, p5, p4 = s.links, s.lower_pairs, s.higher_pairs
    return [
        f"Degrees of freedom (Chebyshev-Gruebler): W = 3n - 2p5 - p4 = 3*{n} - "
        f"2*{p5} - {p4} = {s.dof}",
        f"  n = {counted(n, 'moving link')}, p5 = {counted(p5, 'lower pair')}, p4 = "
        f"{counted(p4, 'higher pair')}; {counted(len(s.drivers), 'driver')}.",
    ]


def structure_report(s: Structure) -> str:
    """Return the teaching report of a structural analysis."""
    lines = [f"Structure of {s.name or 'the mechanism'}", ""]
    lines += freedom_lines(s)
    for slot in s.slots:
        lines.append(
            f"  Slot {slot} (a pin in a slot, a higher pair) is replaced by an "
            f"equivalent block, {slot} (block), with a prismatic pair {slot} and a "
            f"revolute pair {slot} (pin): one more link and two lower pairs keep W "
            f"(in the JSON output: {slot}~block and {slot}~pin)."
        )
    lines += [
        "",
        "Decomposition into the input "
        + ("link" if len(s.drivers) == 1 else "links")
        + " (class I) and Assur groups, in order of attachment:",
    ]
    step = 0
    for g in s.drivers:
        step += 1
        lines.append(
            f"  {step}. Class I: the frame and the input link {g.links[1]} "
            f"(driven through pair {g.internal[0]})."
        )
    said: dict[tuple[int, int], Group] = {}
    for g in s.groups:
        step += 1
        numeral = roman(g.group_class)
        kind = {"triad": "triad", "general": "group"}.get(g.kind, f"dyad {g.kind}")
        lines.append(
            f"  {step}. Class {numeral}, order {g.order}, {kind}: "
            f"links {_names(g.links)}"
        )
        lines.append(f"     {_pairs_text(g)}.")
        lines.append(f"     Why an Assur group: {_why(g, said)}.")
        if g.basis:
            lines.append(f"     Why class {numeral}: {_class_why(g)}.")
    lines += [
        "",
        f"Structure formula: {s.formula}",
        *_apart(s),
        f"Class of the mechanism: {roman(s.mechanism_class)} ({_class_reason(s)})",
    ]
    if s.groups:
        lines.append(
            "Kinematics runs through the groups in this order; the force analysis "
            "in the reverse order."
        )
    else:
        inputs = "link" if len(s.drivers) == 1 else "links"
        lines.append(
            f"Kinematics and the force analysis take the input {inputs} alone."
        )
    return "\n".join(lines)
