"""Why a decomposition fails: the parts and joints its message names.

Two joints between the same two links, a part not joined to the frame, a link on one
joint or held twice by known links, a rigid part, a loop of sliding pairs alone. The
search for Assur groups asks it too: a candidate with a rigid part or a sliding loop
is no group, and the rigid parts it met explain a search that stops.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from assur._checks import _coincide
from assur._freedom import none_text, structure_text
from assur._points import resolve_point
from assur._text import NAME_LIMIT, listing, public_name, shortened
from assur._topology import Pair, Topology, _component, _Index, _index, _public
from assur.model import GROUND, Mechanism

PER_FREEDOM = "one driver per degree of freedom"
LINE = 400
"""Most characters of an error's message: one line a reader takes in."""


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


def _leftover(
    index: _Index,
    unknown: set[str],
    known: set[str],
    rigid: list[_Rigid],
    largest: int,
) -> str:
    """Return the message of a decomposition that stops with links left over.

    ``largest`` is the most links the search gives a group.
    """
    left = tuple(name for name in index.links if name in unknown)
    # a few names of each, cut short: the reason that follows must fit the line too
    shown = [shortened(x, NAME_LIMIT) for x in _public(left)]
    head = (
        f"links {listing(shown)} are left over: they form no Assur group "
        "(3k = 2p, every smaller part with 3k' - 2p' > 0) on the known links "
        f"{listing([shortened(x, NAME_LIMIT) for x in sorted(known)])}"
    )
    # two joints between known links (the frame and an input link) do not stop a
    # group by themselves, but the joint entered twice is missing from the chain
    parallel = _parallel_text(index, unknown) or _parallel_text(index, set(index.links))
    if parallel is not None:
        return (
            f"{head}, because {parallel}; expected one joint between two links (or "
            "one link in place of two welded ones)"
        )
    pairs = [p for p in index.pairs if unknown.intersection(p.links)]
    loop = _sliding_loop(pairs, known)
    if loop is not None:
        return f"{head}, because {_sliding_text(loop, known)}"
    stuck = [r for r in rigid if unknown.issuperset(r.links)]
    if stuck:
        r = min(stuck, key=lambda r: (len(r.links), [index.rank[x] for x in r.links]))
        k, p = len(r.links), len(r.pairs)
        return (
            f"{head}, because joints {listing(_public(r.pairs))} make links "
            f"{listing(_public(r.links))} rigid (k = {k}, p = {p}: 2p >= 3(k - 1)); "
            "expected one link in their place, or fewer joints between them"
        )
    misdriven = _misdriven_text(index, left)
    if misdriven is not None:
        if len(head) + len(misdriven) < LINE - 10:
            return f"{head}, because {misdriven}"
        # long names: the parts counted, not named, so the line stays one to read
        return (
            f"{len(left)} links are left over, in no Assur group on the "
            f"{len(known)} known links, because {_misdriven_text(index, left, True)}"
        )
    misheld = _misheld_text(index, left, known)
    if misheld is not None:
        return f"{head}, because {misheld}"
    if len(left) > largest and 3 * len(left) == 2 * len(pairs):
        # the links left over may be one group too large for the search
        return (
            f"links {listing(_public(left))} are left over: no Assur group of at "
            f"most {largest} links attaches to the known links "
            f"{listing(sorted(known))}, and together (k = {len(left)}, p = "
            f"{len(pairs)}: 3k = 2p) they may form one larger group, which assur does "
            f"not solve; expected groups of at most {largest} links"
        )
    return f"{head}; expected a chain made of Assur groups"


def _misdriven_text(
    index: _Index, left: tuple[str, ...], brief: bool = False
) -> str | None:
    """Return a part left over that moves with no driver beside one held too much.

    The count W matched the drivers, so a part of the links left over with freedom
    on the known links (3k - 2p > 0) beside one with less than none says that the
    drivers sit on the wrong part: two on one loop, none on another. ``brief``:
    the parts' links counted, not named.
    """
    unknown = set(left)
    parts: list[tuple[list[str], int]] = []
    for name in left:
        if any(name in part for part, _ in parts):
            continue
        part = _component(index, name, unknown)
        pairs = {i for x in part for i in index.incident[x]}
        ordered = sorted(part, key=index.rank.__getitem__)
        parts.append((ordered, 3 * len(part) - 2 * len(pairs)))
    # a part that a driver can move: a joint to the frame, no link on one joint
    free = [
        (part, w)
        for part, w in parts
        if w > 0
        and all(len(index.incident[x]) >= 2 for x in part)
        and any(GROUND in index.pairs[i].links for x in part for i in index.incident[x])
    ]
    held = [(part, w) for part, w in parts if w < 0]
    if not free or not held:
        return None
    (loose, w), (fixed, less) = free[0], held[0]
    # joints a driver may take: to the frame, neither a slot's nor its pin's
    frame = [
        p.name
        for x in loose
        for p in (index.pairs[i] for i in index.incident[x])
        if GROUND in p.links
        and not p.virtual
        and not any(y.endswith("~block") for y in p.links)
    ]
    if not frame:
        return None
    # a few of the joints, names cut short: the message stays one readable line
    move = " or ".join(shortened(x, NAME_LIMIT) for x in _public(tuple(frame[:3])))
    if brief:
        return (
            f"{len(loose)} of them can move (3k - 2p = {w}) with no input, while "
            f"{len(fixed)} {'is' if len(fixed) == 1 else 'are'} over-constrained "
            f"(3k - 2p = {less}): the drivers are on the wrong part; expected a "
            f"driver moved to joint {move}"
        )
    return (
        f"{_links_text(loose, limit=3)} can move (3k - 2p = {w}) with no input, while "
        f"{_links_text(fixed, limit=3)} {'is' if len(fixed) == 1 else 'are'} "
        f"over-constrained (3k - 2p = {less}): the drivers are on the wrong part; "
        f"expected a driver moved to joint {move}"
    )


def _misheld_text(index: _Index, left: tuple[str, ...], known: set[str]) -> str | None:
    """Return the link left over held to known links twice, the one on one joint.

    Neither can be in an Assur group: the first is a part without mobility on the
    known links (2p >= 3k with k = 1), and without the second the rest of the group
    would have 3k' - 2p' = -1.
    """
    held = []
    for name in left:
        pairs = [index.pairs[i] for i in index.incident[name]]
        fixed = [p for p in pairs if all(x == name or x in known for x in p.links)]
        if len(fixed) >= 2:
            names = listing(_public(tuple(p.name for p in fixed)))
            held.append(
                f"{_links_text([name])} is held to the known links by joints "
                f"{names}, which fix it"
            )
            break
    for name in left:
        if len(index.incident[name]) == 1:
            pair = public_name(index.pairs[index.incident[name][0]].name)
            held.append(f"{_links_text([name])} hangs on joint {pair} alone")
            break
    if not held:
        return None
    return (
        f"{', and '.join(held)}; expected every link of a group held by two joints "
        "at least, at most one of them to a known link"
    )


def _sliding_text(loop: list[Pair], known: set[str]) -> str:
    """Return what a loop of sliding pairs alone does, and what was expected."""
    names = listing(_public(tuple(p.name for p in loop)))
    ends = sorted({x for p in loop for x in p.links if x in known})
    through = f" through the {_links_text(ends, 'known ')}" if ends else ""
    links = tuple(dict.fromkeys(x for p in loop for x in p.links if x not in known))
    if len(loop) == 3 and len(links) == 2:
        return (
            f"joints {names} are three sliding pairs, which cannot fix the rotation "
            f"of the dyad {listing(_public(links))} (they tie it twice over, to the "
            f"{_links_text(ends, 'known ')}, and leave it free to slide); expected a "
            "revolute pair in place of one of them"
        )
    return (
        f"joints {names} close a loop of sliding pairs alone{through}: each ties "
        "the rotations of its two links, so the loop ties those of "
        f"{_links_text(links)} once too often and W = 3n - 2p5 - p4 miscounts; "
        "expected a revolute pair in place of one of them"
    )


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
