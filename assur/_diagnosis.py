"""Why a decomposition fails: the parts and joints its message names.

Two joints between the same two links, a part not joined to the frame, a link on one
joint or held twice by known links, a rigid part, a loop of sliding pairs alone. The
search for Assur groups asks it too: a candidate with a rigid part or a sliding loop
is no group, and the rigid parts it met explain a search that stops
(:mod:`assur._leftover` words that message).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from assur._checks import _coincide
from assur._freedom import none_text, structure_text
from assur._points import resolve_point
from assur._text import NAME_LIMIT, listing, public_name, shortened
from assur._topology import (
    Pair,
    Topology,
    _component,
    _Index,
    _index,
    _public,
    topology,
)
from assur.model import GROUND, Mechanism

PER_FREEDOM = "one driver per degree of freedom"


def _miscount(topo: Topology, w: int, mech: Mechanism) -> tuple[str, str]:
    """Return why the degrees of freedom may differ from the drivers; what was expected.

    A joint counted twice is named; a count of none or fewer is said to be one. A
    count above the drivers names a part not joined to the frame, or a link that
    hangs on one joint: their freedom is one no driver can take (a driver acts
    between the frame and its input link).
    """
    index = _index(topo)
    parallel = _parallel_text(index, set(index.links))
    if parallel is not None:
        return f", as {parallel}", PER_FREEDOM
    if w <= 0:
        # a part apart from the frame moves as a whole, whatever the count says
        unjoined = unjoined_text(index)
        if unjoined is not None:
            return unjoined
        moving = none_text(topo, w)
        if moving is not None:
            why, expected = moving
            return f", {why}", f"{expected}, then {PER_FREEDOM}"
        return f": {structure_text(w)}", f"links that can move (W >= 1), {PER_FREEDOM}"
    if w > len(mech.drivers):
        loose = _loose_text(index, mech)
        if loose is not None:
            return loose
    return "", PER_FREEDOM


def unjoined_text(index: _Index) -> tuple[str, str] | None:
    """Return the links no chain of joints joins to the frame; what was expected."""
    joined = _component(index, GROUND)
    apart = [x for x in index.links if x not in joined]
    if not apart:
        return None
    return (
        f", as {_links_text(apart)} {'is' if len(apart) == 1 else 'are'} joined "
        "to the frame by no chain of joints",
        "every link joined to the frame through joints",
    )


def _loose_text(index: _Index, mech: Mechanism) -> tuple[str, str] | None:
    """Return the links not joined to the frame, or else those on one joint alone."""
    unjoined = unjoined_text(index)
    if unjoined is not None:
        return unjoined
    drivers = {d.joint for d in mech.drivers}
    driven = {x for p in index.pairs if p.name in drivers for x in p.links}
    # a link on one joint to the frame is a crank that a driver may take: not named
    hanging = [
        (x, index.pairs[index.incident[x][0]])
        for x in index.links
        if len(index.incident[x]) == 1 and x not in driven
    ]
    hanging = [(x, p) for x, p in hanging if GROUND not in p.links]
    if not hanging:
        return _spinning_text(index, mech, driven)
    expected = "every link held by two joints at least (an input link by its driver)"
    if len(hanging) == 1:
        ((link, pair),) = hanging
        moves = "turns about it" if pair.kind == "R" else "slides along it"
        why = (
            f", as {_links_text([link])} hangs on joint {public_name(pair.name)} "
            f"alone and {moves} freely"
        )
        return why, expected
    links = _links_text([x for x, _ in hanging])
    pairs = listing(_public(tuple(p.name for _, p in hanging)))
    return f", as {links} hang on one joint each ({pairs}) and move freely", expected


def _spinning_text(
    index: _Index, mech: Mechanism, driven: set[str]
) -> tuple[str, str] | None:
    """Return the links held by two pins at one point: each spins about it freely.

    A passive freedom, as a roller on its pin is: it counts in W, and no driver
    takes it.
    """
    joints = {j.name: j for j in mech.joints}
    spinning = []
    for x in index.links:
        pairs = [index.pairs[i] for i in index.incident[x]]
        if x in driven or len(pairs) != 2 or any(p.kind != "R" for p in pairs):
            continue
        if not all(p.name in joints for p in pairs):
            continue  # a slot's own pin and block
        a, b = (resolve_point(mech, joints[p.name].at) for p in pairs)
        if _coincide(a, b):
            spinning.append((x, pairs))
    if not spinning:
        return None
    x, pairs = spinning[0]
    first, second = _public(tuple(p.name for p in pairs))
    more = "" if len(spinning) == 1 else f" ({len(spinning) - 1} more so)"
    why = (
        f", as {_links_text([x])} is held by joints {first} and {second} at one point "
        f"and spins about it freely{more}, a freedom no driver can take"
    )
    return why, "the two joints of a link apart (or the link left out, its joints one)"


@dataclass(frozen=True, slots=True)
class _Rigid:
    """Links of a candidate joined so tightly that no motion is left between them."""

    links: tuple[str, ...]
    pairs: tuple[str, ...]


def _sliding_loop(pairs: list[Pair], known: set[str]) -> list[Pair] | None:
    """Return prismatic ``pairs`` that close a loop, known links taken as one.

    A prismatic pair ties the rotations of its two links. Around a loop of them
    one tie repeats the others, and between known links (whose rotations are given)
    every tie repeats: the equations the count 3k = 2p relies on are dependent. The
    loop's pairs come in order around it, from a known link when it passes one, the
    pair that closes it last.
    """
    tree: dict[str, list[tuple[str, Pair]]] = {}
    for pair in pairs:
        if pair.kind != "P":
            continue
        a, b = (GROUND if x in known else x for x in pair.links)
        if b == GROUND:
            a, b = b, a  # the loop then reads from a known link
        path = _path(tree, a, b)
        if path is not None:
            return [*path, pair]
        tree.setdefault(a, []).append((b, pair))
        tree.setdefault(b, []).append((a, pair))
    return None


def _path(
    tree: dict[str, list[tuple[str, Pair]]], start: str, end: str
) -> list[Pair] | None:
    """Return the pairs of the forest ``tree`` on the way from start to end, or None."""
    if start == end:
        return []
    way: dict[str, tuple[str, Pair] | None] = {start: None}
    todo = [start]
    while todo:
        node = todo.pop()
        for other, pair in tree.get(node, ()):
            if other not in way:
                way[other] = (node, pair)
                todo.append(other)
    if end not in way:
        return None
    path = []
    step = way[end]
    while step is not None:
        node, pair = step
        path.append(pair)
        step = way[node]
    return path[::-1]


def _links_text(names: Sequence[str], adjective: str = "", limit: int = 6) -> str:
    """Return "link a" or "links a, b" (as a reader sees them).

    At most ``limit`` names, each cut short: the message stays one readable line.
    """
    noun = "link" if len(names) == 1 else "links"
    shown = [shortened(x, NAME_LIMIT) for x in _public(tuple(names))]
    return f"{adjective}{noun} {listing(shown, limit)}"


def _parallel_text(index: _Index, unknown: set[str]) -> str | None:
    """Return what the first two pairs between the same two links do, or None."""
    parallel = _parallel(index, unknown)
    if parallel is None:
        return None
    first, second = parallel
    # names cut short: a name of hundreds of characters would make the line a page
    a, b = (shortened(x, NAME_LIMIT) for x in _public(first.links))
    one, two = (shortened(p.name, NAME_LIMIT) for p in (first, second))
    return (
        f"joints {one} and {two} both join {a} and {b}: "
        f"{_parallel_reason(index, first, second)}"
    )


def _parallel(index: _Index, unknown: set[str]) -> tuple[Pair, Pair] | None:
    """Return the first two pairs between the same two links, one in ``unknown``."""
    for name in index.links:
        if name not in unknown:
            continue
        seen: dict[str, Pair] = {}
        for i in index.incident[name]:
            pair = index.pairs[i]
            other = pair.links[1] if pair.links[0] == name else pair.links[0]
            if other in seen:
                return seen[other], pair
            seen[other] = pair
    return None


SAME_POINT = 1e-9
"""Two revolute pairs closer than this, relative to the mechanism's size, coincide."""


def _parallel_reason(index: _Index, first: Pair, second: Pair) -> str:
    """Return what two lower pairs between the same two links do to them."""
    kinds = first.kind + second.kind
    if kinds == "RR":
        scale = max([abs(c) for p in index.pairs for c in p.at] + [1.0])
        if math.dist(first.at, second.at) <= SAME_POINT * scale:
            return "two revolute pairs at one point are one pair counted twice"
        return "two revolute pairs at two points weld the links into one rigid body"
    if kinds == "PP":
        (ax, ay), (bx, by) = first.axis or (1.0, 0.0), second.axis or (1.0, 0.0)
        cross = ax * by - ay * bx
        if abs(cross) <= SAME_POINT:
            return (
                "two prismatic pairs along parallel lines are one sliding pair "
                "counted twice"
            )
        return (
            "two prismatic pairs along different lines weld the links into one "
            "rigid body"
        )
    return "a revolute and a prismatic pair together weld the links into one rigid body"


def no_driver(mech: Mechanism, w: int) -> str:
    """Return the error of a file with no driver whose count ``w`` is 0 or less.

    Its links cannot move (a rigid structure), or a constraint repeats another,
    which the count cannot see.
    """
    head = f"drivers: the mechanism has no driver, and W = {count_text(mech, w)}"
    each = "a [[drivers]] entry for each degree of freedom"
    topo = topology(mech)
    index = _index(topo)
    # a joint entered twice is named, as where there are drivers
    parallel = _parallel_text(index, set(index.links))
    if parallel is not None:
        return f"{head}, as {parallel}; expected one joint between two links"
    unjoined = unjoined_text(index)
    if unjoined is not None:
        return f"{head}{unjoined[0]}; expected {unjoined[1]}"
    moving = none_text(topo, w)
    if moving is not None:
        return f"{head}, {moving[0]}; expected {moving[1]}, then {each}"
    return f"{head}: {structure_text(w)}; expected links that can move, with {each}"


def count_text(mech: Mechanism, w: int) -> str:
    """Return the count of degrees of freedom worked out: ``3*n - 2*p5 - p4 = W``."""
    p4 = sum(j.kind == "slot" for j in mech.joints)
    return f"3*{len(mech.links)} - 2*{len(mech.joints) - p4} - {p4} = {w}"
