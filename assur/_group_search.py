"""The search for Assur groups: the smallest one on the known links, step by step.

Candidates are connected sets of unknown links, grown only while they may still
close (3k = 2p) and examined again only next to a link that became known; a
candidate passes the test of an Assur group in `_is_group`.
"""

from __future__ import annotations

import functools
import heapq
from collections.abc import Iterator

from assur._diagnosis import _Rigid, _sliding_loop
from assur._leftover import _leftover
from assur._topology import Pair, _component, _Index
from assur.errors import DecompositionError

MAX_GROUP_LINKS = 8


def _attach(
    index: _Index, known: set[str]
) -> Iterator[tuple[list[str], list[Pair], set[str]]]:
    """Yield the Assur groups on ``known`` one after another (``known`` grows).

    Each as its links in the mechanism's order, its pairs (see `_counted`) and the
    links known before it, a set the next step grows.

    A heap per group size holds every candidate found to be a group, keyed by the
    ranks of its links; a candidate is examined again only when a link next to it
    becomes known (its stamp then outdates the heap entry).
    """
    known = set(known)
    unknown = {name for name in index.links if name not in known}
    sizes = range(2, MAX_GROUP_LINKS + 1, 2)
    heaps: dict[int, list[tuple[tuple[int, ...], int, frozenset[str]]]] = {
        k: [] for k in sizes
    }
    pending: dict[int, set[str]] = {k: set() for k in sizes}
    stamp: dict[str, int] = {}
    rigid: list[_Rigid] = []
    clock = 0

    def touch(new: set[str]) -> None:
        nonlocal clock
        clock += 1
        near = {x for n in new for x in index.neighbours[n] if x in unknown}
        for name in near:
            stamp[name] = clock
        for k in sizes:
            pending[k] |= near

    touch(known)
    while unknown:
        found = None
        for k in sizes:
            if k > len(unknown):
                break
            seeds = pending[k] & unknown
            pending[k] = set()
            for subset in _connected(index, unknown, seeds, k, known):
                group, part = _is_group(index, subset, known)
                if group:
                    key = tuple(sorted(index.rank[x] for x in subset))
                    heapq.heappush(heaps[k], (key, clock, subset))
                elif part is not None:
                    rigid.append(part)
            found = _pop(heaps[k], unknown, stamp)
            if found is not None:
                break
        if found is None:
            msg = _leftover(index, unknown, known, rigid, MAX_GROUP_LINKS)
            raise DecompositionError(msg)
        links = sorted(found, key=index.rank.__getitem__)
        yield links, _counted(index, found, known), known
        known.update(found)
        unknown -= found
        touch(set(found))


def _pop(
    heap: list[tuple[tuple[int, ...], int, frozenset[str]]],
    unknown: set[str],
    stamp: dict[str, int],
) -> frozenset[str] | None:
    """Return the first candidate of ``heap`` still a group (drop stale ones)."""
    while heap:
        _, when, subset = heap[0]
        if subset <= unknown and all(stamp.get(x, 0) <= when for x in subset):
            return subset
        heapq.heappop(heap)
    return None


def _connected(
    index: _Index,
    unknown: set[str],
    seeds: set[str],
    k: int,
    known: set[str] | None = None,
) -> set[frozenset[str]]:
    """All connected sets of ``k`` unknown links holding at least one of ``seeds``.

    Given the ``known`` links, only those that may be Assur groups on them: a set
    is not grown past a part with no mobility on the known links (2p >= 3k), which
    would be a proper part of every larger set, nor past one that cannot reach
    3k = 2p in ``k`` links (see `_may_close`). Without that, a link held twice
    (a pin doubled) next to a link with many neighbours made the search of a
    failing decomposition grow every set around it, for seconds to minutes; and a
    hub of sixteen spokes, one of them pinned twice, took six seconds.
    """
    frontier = {frozenset([seed]) for seed in seeds}
    trees: dict[str, bool] = {}
    for _ in range(k - 1):
        if known is not None:
            frontier = {
                s for s in frontier if _may_close(index, s, unknown, known, k, trees)
            }
        grown = set()
        for subset in frontier:
            for node in subset:
                for other in index.neighbours[node]:
                    if other in unknown and other not in subset:
                        grown.add(subset | {other})
        frontier = grown
    return frontier


def _may_close(
    index: _Index,
    subset: frozenset[str],
    unknown: set[str],
    known: set[str],
    k: int,
    trees: dict[str, bool],
) -> bool:
    """Return whether ``subset`` may grow into a set of ``k`` links with 3k = 2p.

    The subset S must keep a mobility m = 3s - 2p_S > 0 (else it is a part without
    mobility of every larger set). Adding links R gives a set of mobility at least
    m - sum(2a + b - 3) over R, for a link with a pairs to S and the known links and
    b pairs to other unknown links (a pair inside R counts half at each end), so
    the k - s best such gains must reach m; R lies within k - s joints of S. In a
    tree of unknown links (see `_tree`) R holds no link with two pairs to known
    links either: alone it is a part without mobility, so a set holding it is no
    group, and a tree holds no rigid part that such a set could name when the
    search fails.
    """
    mobile = 3 * len(subset) - 2 * len(_counted(index, subset, known))
    if mobile <= 0:
        return False
    missing = k - len(subset)
    gains = []
    free = []  # the gains of links with fewer than two pairs to known links
    seen = set(subset)
    ring: set[str] = set(subset)
    for _ in range(missing):
        ring = {
            x
            for name in ring
            for x in index.neighbours[name]
            if x in unknown and x not in seen
        }
        seen |= ring
        for name in ring:
            ends = index.ends[name]
            fixed = sum(x in known for x in ends)
            held = fixed + sum(x in subset for x in ends)
            gains.append(2 * held + (len(ends) - held) - 3)
            if fixed < 2:
                free.append(gains[-1])
    if not _reaches(gains, missing, mobile):
        return False
    return _reaches(free, missing, mobile) or not _tree(index, unknown, subset, trees)


def _reaches(gains: list[int], count: int, mobile: int) -> bool:
    """Return whether ``count`` of ``gains`` may add up to ``mobile`` or more."""
    return len(gains) >= count and sum(sorted(gains, reverse=True)[:count]) >= mobile


def _tree(
    index: _Index, unknown: set[str], subset: frozenset[str], trees: dict[str, bool]
) -> bool:
    """Return whether the unknown links joined to ``subset`` form a tree (no loop).

    A rigid part has as many pairs as links at least, hence a loop. ``trees`` keeps
    the answer for every link of a part already examined.
    """
    first = next(iter(subset))
    if first not in trees:
        part = _component(index, first, unknown)
        pairs = {i for name in part for i in index.incident[name]}
        inside = sum(all(x in part for x in index.pairs[i].links) for i in pairs)
        trees.update(dict.fromkeys(part, inside == len(part) - 1))
    return trees[first]


def _counted(index: _Index, links: frozenset[str], known: set[str]) -> list[Pair]:
    """Pairs with one end in ``links`` and the other in ``links`` or ``known``.

    In the order of the topology's pairs.
    """
    found = {
        i
        for name in links
        for i in index.incident[name]
        if all(x in links or x in known for x in index.pairs[i].links)
    }
    return [index.pairs[i] for i in sorted(found)]


def _is_group(
    index: _Index, subset: frozenset[str], known: set[str]
) -> tuple[bool, _Rigid | None]:
    """Return whether ``subset`` is an Assur group on ``known`` (see `decompose`).

    Also return the smallest rigid part of a chain with 3k = 2p, which explains a
    failure if the decomposition stops.
    """
    counted = _counted(index, subset, known)
    k = len(subset)
    if 2 * len(counted) != 3 * k:
        return False, None
    if _sliding_loop(counted, known) is not None:
        return False, None  # rotations tied twice: the count 3k = 2p is wrong
    links = sorted(subset, key=index.rank.__getitem__)
    bit = {name: 1 << i for i, name in enumerate(links)}
    masks = [sum(bit[x] for x in p.links if x in bit) for p in counted]
    minimal = True
    for part in _parts(k):
        inside = [m for m in masks if m & part == m]
        own = [m for m in inside if m.bit_count() == 2]
        size = part.bit_count()
        if size > 1 and 2 * len(own) >= 3 * (size - 1):
            names = tuple(x for x in links if bit[x] & part)
            pairs = tuple(
                p.name
                for p, m in zip(counted, masks, strict=True)
                if m.bit_count() == 2 and m & part == m
            )
            return False, _Rigid(names, pairs)
        if size < k and 2 * len(inside) >= 3 * size:
            minimal = False  # a proper part without mobility
    return minimal, None


@functools.cache
def _parts(k: int) -> tuple[int, ...]:
    """Bit masks of the nonempty parts of a set of ``k`` links, smallest first."""
    return tuple(sorted(range(1, 1 << k), key=lambda m: (m.bit_count(), m)))
