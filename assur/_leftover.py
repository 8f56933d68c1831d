"""Why links are left over: the message of a decomposition that stops short.

The search for Assur groups attaches groups until none fits; the links left over are
named with the first reason found: two joints between two links, a loop of sliding
pairs alone, a rigid part, drivers on the wrong part, a link held twice or hanging on
one joint, or a group larger than the search takes.
"""

from __future__ import annotations

from assur._diagnosis import (
    _links_text,
    _parallel_text,
    _Rigid,
    _sliding_loop,
)
from assur._text import NAME_LIMIT, listing, public_name, shortened, spoken
from assur._topology import Pair, _component, _Index, _public
from assur.model import GROUND

__all__ = ["LINE", "_leftover"]

LINE = 400
"""Most characters of an error's message: one line a reader takes in."""


def _leftover(
    index: _Index,
    unknown: set[str],
    known: set[str],
    rigid: list[_Rigid],
    largest: int,
) -> str:
    """Return the message of a decomposition that stops with links left over.

    ``largest`` is the most links the search gives a group. The links are named,
    a few and cut short, or counted where names would run the line past
    :data:`LINE` characters.
    """
    left = tuple(name for name in index.links if name in unknown)
    shown = [shortened(x, NAME_LIMIT) for x in _public(left)]
    named = listing([shortened(x, NAME_LIMIT) for x in sorted(known)])
    rest, larger = _leftover_reason(index, unknown, known, rigid, largest, False)
    if larger:
        # the links may be one group, larger than the search takes: not "no group"
        head = (
            f"links {listing(shown)} are left over: no Assur group of at most "
            f"{largest} links attaches to the known links {named}"
        )
    else:
        head = (
            f"links {listing(shown)} are left over: they form no Assur group (one "
            f"needs 3k = 2p, no smaller group) on the known links {named}"
        )
    if len(head) + len(rest) < LINE:
        return head + rest
    # long names: the links counted, not named, so the line stays one to read
    return (
        f"{len(left)} links are left over, in no Assur group on the {len(known)} "
        f"known links{_leftover_reason(index, unknown, known, rigid, largest, True)[0]}"
    )


def _leftover_reason(
    index: _Index,
    unknown: set[str],
    known: set[str],
    rigid: list[_Rigid],
    largest: int,
    brief: bool,
) -> tuple[str, bool]:
    """Return why the links left over form no group, after the message's head.

    ``brief``: the parts of drivers on the wrong part counted, not named. The flag
    says the links may form one group larger than the search takes.
    """
    left = tuple(name for name in index.links if name in unknown)
    # two joints between known links (the frame and an input link) do not stop a
    # group by themselves, but the joint entered twice is missing from the chain
    parallel = _parallel_text(index, unknown) or _parallel_text(index, set(index.links))
    if parallel is not None:
        return (
            f", because {parallel}; expected one joint between two links (or one link "
            "in place of two welded ones)",
            False,
        )
    pairs = [p for p in index.pairs if unknown.intersection(p.links)]
    loop = _sliding_loop(pairs, known)
    if loop is not None:
        return f", because {_sliding_text(loop, known)}", False
    stuck = [r for r in rigid if unknown.issuperset(r.links)]
    if stuck:
        r = min(stuck, key=lambda r: (len(r.links), [index.rank[x] for x in r.links]))
        k, p = len(r.links), len(r.pairs)
        return (
            f", because joints {listing(_public(r.pairs))} make links "
            f"{listing(_public(r.links))} rigid (k = {k}, p = {p}: 2p >= 3(k - 1)); "
            "expected one link in their place, or fewer joints between them",
            False,
        )
    misdriven = _misdriven_text(index, left, brief)
    if misdriven is not None:
        return f", because {misdriven}", False
    misheld = _misheld_text(index, left, known)
    if misheld is not None:
        return f", because {misheld}", False
    if len(left) > largest and 3 * len(left) == 2 * len(pairs):
        # the links left over may be one group too large for the search
        return (
            f", and together (k = {len(left)}, p = {len(pairs)}: 3k = 2p) they may "
            "form one larger group, which assur does not solve; expected groups of at "
            f"most {largest} links",
            True,
        )
    return "; expected a chain made of Assur groups", False


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
    move = spoken([shortened(x, NAME_LIMIT) for x in _public(tuple(frame[:3]))], "or")
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
        f"its two links' rotations; those of {_links_text(links)} are tied once too "
        "often, which W = 3n - 2p5 - p4 miscounts; expected a revolute pair in place "
        "of one of them"
    )
