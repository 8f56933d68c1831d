"""Structure of a mechanism: its graph, mobility and Assur-group decomposition.

The frame and the driven links form the class I mechanism; the rest is split into
Assur groups (statically determinate chains, 3k = 2p) attached one after another to
links already known, as the structural theory of Assur and Artobolevsky teaches. The
order found here is the order of the kinematic (forward) and kinetostatic (reverse)
passes.
"""

from __future__ import annotations

import dataclasses
import functools
import heapq
import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

from assur._text import (
    NAME_LIMIT,
    counted,
    listing,
    public_name,
    roman,
    shortened,
)
from assur.errors import DecompositionError, ModelError
from assur.model import GROUND, Driver, Mechanism, mechanism_of, resolve_point

__all__ = [
    "Group",
    "Pair",
    "Structure",
    "Topology",
    "decompose",
    "graph",
    "mobility",
    "structure",
    "topology",
]

MAX_GROUP_LINKS = 8


@dataclass(frozen=True, slots=True)
class Pair:
    """A lower pair of the structural model (slots already replaced).

    ``kind`` is ``"R"`` or ``"P"``; for ``"P"`` the slide line is fixed in
    ``links[0]``. ``at`` and ``axis`` are reference-pose values in m. ``friction`` is
    the pair's Coulomb coefficient and ``radius`` a revolute pair's journal radius (m).
    """

    name: str
    kind: str
    links: tuple[str, str]
    at: tuple[float, float]
    axis: tuple[float, float] | None = None
    virtual: bool = False
    friction: float = 0.0
    radius: float = 0.0


@dataclass(frozen=True, slots=True)
class Topology:
    """Links and lower pairs of a mechanism, each slot replaced by a block.

    The block that replaces slot ``J`` is the massless link ``"J~block"``; it slides in
    the slot through the prismatic pair ``J`` and carries the pin through the revolute
    pair ``"J~pin"``.
    """

    links: tuple[str, ...]
    pairs: tuple[Pair, ...]
    slots: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Group:
    """One step of the decomposition.

    Attributes
    ----------
    group_class, order : int
        Class (I for a driving link, II for a dyad, ...) and order (number of external
        pairs) after Artobolevsky.
    kind : str
        ``"driver"``, a dyad's pair signature (``"RRR"``, ``"RRP"``, ``"RPR"``,
        ``"PRP"``, ``"RPP"``) read from one external pair to the other, ``"triad"`` for
        the class III group of a ternary and three binary links, or ``"general"``
        for any other group. Class II groups are always dyads; triads and general
        groups are of class III or higher.
    links : tuple of str
        The group's links, in solving order (a dyad's first link carries the first
        external pair of its signature).
    internal, external : tuple of str
        Pairs between links of the group; pairs to known links (external pairs of a
        dyad in signature order).
    attached_to : tuple of str
        Known links the group hangs on, each once, in the order of the external
        pairs that join them.
    """

    group_class: int
    order: int
    kind: str
    links: tuple[str, ...]
    internal: tuple[str, ...]
    external: tuple[str, ...]
    attached_to: tuple[str, ...]

    @property
    def label(self) -> str:
        """Short label such as ``"RRR (2, 3)"``; ``"class IV (...)"`` beyond triads."""
        kind = self.kind
        if kind == "general":
            kind = f"class {roman(self.group_class)}"
        return f"{kind} ({', '.join(_public(self.links))})"


@dataclass(frozen=True, slots=True)
class Structure:
    """The structural analysis of a mechanism; ``str()`` gives the teaching report."""

    name: str
    links: int
    lower_pairs: int
    higher_pairs: int
    dof: int
    drivers: tuple[Group, ...]
    groups: tuple[Group, ...]
    slots: tuple[str, ...]

    @property
    def mechanism_class(self) -> int:
        """Class of the mechanism: the highest class of its groups (I without any)."""
        return max((g.group_class for g in self.groups), default=1)

    @property
    def formula(self) -> str:
        """Structure formula, e.g. ``I(ground, 1) -> II(2, 3)``."""
        steps = [
            f"{roman(g.group_class)}({', '.join(_public(g.links))})"
            for g in (*self.drivers, *self.groups)
        ]
        return " -> ".join(steps)

    def to_dict(self) -> dict[str, Any]:
        """Return the structure as plain JSON-ready data."""

        def group(g: Group) -> dict[str, Any]:
            return {
                "class": g.group_class,
                "class_roman": roman(g.group_class),
                "order": g.order,
                "kind": g.kind,
                "links": list(g.links),
                "internal_pairs": list(g.internal),
                "external_pairs": list(g.external),
                "attached_to": list(g.attached_to),
            }

        return {
            "name": self.name,
            "links": self.links,
            "lower_pairs": self.lower_pairs,
            "higher_pairs": self.higher_pairs,
            "dof": self.dof,
            "drivers": [group(g) for g in self.drivers],
            "groups": [group(g) for g in self.groups],
            "formula": self.formula,
            "mechanism_class": self.mechanism_class,
            "slots": list(self.slots),
        }

    def __str__(self) -> str:
        from assur.report import structure_report

        return structure_report(self)


def _public(names: tuple[str, ...]) -> tuple[str, ...]:
    """Return names as a reader sees them: a slot's block and pin are "J (block)"."""
    return tuple(public_name(n) for n in names)


def topology(mech: Mechanism) -> Topology:
    """Return the links and lower pairs of ``mech``, slots replaced by blocks."""
    links = [link.name for link in mech.links]
    pairs = []
    slots = []
    for joint in mech.joints:
        x, y = resolve_point(mech, joint.at)
        at = (float(x), float(y))
        axis = None if joint.axis is None else _unit(joint.axis)
        first, second = joint.links
        f, r = float(joint.friction), float(joint.radius or 0.0)
        if joint.kind == "revolute":
            pairs.append(Pair(joint.name, "R", (first, second), at, None, False, f, r))
        elif joint.kind == "prismatic":
            pairs.append(Pair(joint.name, "P", (first, second), at, axis, False, f))
        else:
            block = f"{joint.name}~block"
            links.append(block)
            slots.append(joint.name)
            # the pin slides along the slot: friction acts in its prismatic pair
            pairs.append(Pair(joint.name, "P", (first, block), at, axis, False, f))
            pairs.append(
                Pair(f"{joint.name}~pin", "R", (block, second), at, virtual=True)
            )
    return Topology(tuple(links), tuple(pairs), tuple(slots))


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    length = math.hypot(*v)
    return (v[0] / length, v[1] / length)


def mobility(mechanism: Mechanism) -> int:
    """Return the degrees of freedom by the Chebyshev-Gruebler formula.

    Notes
    -----
    :math:`W = 3n - 2p_5 - p_4` with n moving links, p5 lower pairs (revolute and
    prismatic) and p4 higher pairs (slots: a pin in a straight slot).

    Examples
    --------
    >>> from assur import catalog
    >>> mobility(catalog.four_bar())
    1
    """
    mech = mechanism_of(mechanism)
    n = len(mech.links)
    p4 = sum(joint.kind == "slot" for joint in mech.joints)
    p5 = len(mech.joints) - p4
    return 3 * n - 2 * p5 - p4


def graph(mechanism: Mechanism) -> Any:
    """Return the mechanism as a networkx multigraph: links as nodes, joints edges.

    Each edge is keyed by the joint's name and carries its ``kind``.

    Examples
    --------
    >>> from assur import catalog
    >>> g = graph(catalog.four_bar())
    >>> sorted(g.nodes), g.number_of_edges()
    (['coupler', 'crank', 'ground', 'rocker'], 4)
    """
    import networkx as nx

    mech = mechanism_of(mechanism)
    g = nx.MultiGraph()
    g.add_node(GROUND)
    g.add_nodes_from(link.name for link in mech.links)
    for joint in mech.joints:
        g.add_edge(*joint.links, key=joint.name, kind=joint.kind)
    return g


def structure(mechanism: Mechanism, driver: str | None = None) -> Structure:
    """Analyse the structure of ``mechanism``: mobility and Assur groups.

    Parameters
    ----------
    mechanism : Mechanism
    driver : str, optional
        Analyse with this joint as the only input instead of the file's drivers (the
        class of a mechanism depends on its input link).

    Returns
    -------
    Structure

    Raises
    ------
    DecompositionError
        When the mobility differs from the number of drivers or links are left over.

    Examples
    --------
    >>> from assur import catalog
    >>> s = structure(catalog.four_bar())
    >>> s.formula
    'I(ground, crank) -> II(coupler, rocker)'
    """
    mech = mechanism_of(mechanism)
    if driver is not None:
        if driver not in {j.name for j in mech.joints}:
            msg = f"driver: unknown joint {driver!r}"
            raise DecompositionError(msg)
        omega = mech.drivers[0].omega if mech.drivers else 1.0
        try:
            mech = dataclasses.replace(mech, drivers=(Driver(driver, omega),))
        except ModelError as err:
            msg = f"driver: {str(err).split(': ', 1)[-1]}"
            raise DecompositionError(msg) from None
    try:
        drivers, groups, topo = decompose(mech)
    except DecompositionError as err:
        if driver is None or not str(err).startswith("drivers:"):
            raise
        # the count of inputs is the option's doing, not the file's
        msg = (
            f"driver: {str(err).split(': ', 1)[-1]} (driver= sets one input; "
            "without it the file's drivers are used)"
        )
        raise DecompositionError(msg) from None
    n = len(mech.links)
    p4 = len(topo.slots)
    return Structure(
        mech.name,
        n,
        len(mech.joints) - p4,
        p4,
        mobility(mech),
        drivers,
        groups,
        topo.slots,
    )


def decompose(mech: Mechanism) -> tuple[tuple[Group, ...], tuple[Group, ...], Topology]:
    """Split ``mech`` into driving links and Assur groups in order of attachment.

    Returns
    -------
    drivers : tuple of Group
        One class I group per driver.
    groups : tuple of Group
        Assur groups in the order they attach.
    topology : Topology

    Raises
    ------
    DecompositionError
        When the mobility differs from the number of drivers (the message then
        names two joints between the same two links, a part not joined to the frame
        or a link on one joint, when there is one), or links are left over (the
        message then names two joints between the same two links, a loop of sliding
        pairs alone, a rigid part, or a link held twice by known links or on one
        joint, when there is one).

    Notes
    -----
    Each step attaches the smallest Assur group on the links known so far (the
    frame, the input links and the groups before it); among groups of one size, the
    one whose links come first in the mechanism's order. An Assur group of k links
    and p lower pairs (those among its links and to known links) has 3k = 2p, every
    proper part of it keeps a positive mobility 3k' - 2p' > 0, no part of its own
    links is rigid (2p'' < 3(k'' - 1) for the pairs p'' among k'' of its links), and
    its prismatic pairs close no loop, the known links taken as one (each ties the
    rotations of its two links: a loop of them ties one twice, and the count
    3k = 2p is then wrong; the three pairs of a PPP dyad are such a loop).
    Candidates are connected sets of unknown links; only those next to a link that
    became known are examined again, so a chain of small groups decomposes in time
    about linear in its length.
    """
    w = mobility(mech)
    topo = topology(mech)
    if w != len(mech.drivers):
        n = len(mech.links)
        p4 = sum(j.kind == "slot" for j in mech.joints)
        why, expected = _miscount(topo, w, mech)
        msg = (
            f"drivers: the mechanism has W = 3*{n} - 2*{len(mech.joints) - p4} - {p4}"
            f" = {counted(w, 'degree', 'degrees')} of freedom but "
            f"{counted(len(mech.drivers), 'driver')}{why}; expected {expected}"
        )
        raise DecompositionError(msg)
    by_name = {p.name: p for p in topo.pairs}
    drivers = []
    known = {GROUND}
    for d in mech.drivers:
        pair = by_name[d.joint]
        link = pair.links[1] if pair.links[0] == GROUND else pair.links[0]
        drivers.append(Group(1, 0, "driver", (GROUND, link), (d.joint,), (), (GROUND,)))
        known.add(link)
    shape = (topo.links, tuple((p.name, p.kind, p.links) for p in topo.pairs))
    key = (shape, frozenset(known))
    groups = _DECOMPOSED.get(key)
    if groups is None:
        groups = tuple(_attach(_index(topo), known))
        if len(_DECOMPOSED) >= 256:
            _DECOMPOSED.clear()
        _DECOMPOSED[key] = groups
    return tuple(drivers), groups, topo


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
        why = (
            " (none: a rigid chain, or a link repeating a constraint, such as a "
            "third parallel crank of a parallelogram, which the count cannot see)"
        )
        return why, f"links that can move (W >= 1), {PER_FREEDOM}"
    if w > len(mech.drivers):
        loose = _loose_text(index, mech)
        if loose is not None:
            return loose
    return "", PER_FREEDOM


def _loose_text(index: _Index, mech: Mechanism) -> tuple[str, str] | None:
    """Return the links not joined to the frame, or else those on one joint alone."""
    joined = {GROUND}
    todo = [GROUND]
    while todo:
        for other in index.neighbours[todo.pop()]:
            if other not in joined:
                joined.add(other)
                todo.append(other)
    apart = [x for x in index.links if x not in joined]
    if apart:
        return (
            f", as {_links_text(apart)} {'is' if len(apart) == 1 else 'are'} joined "
            "to the frame by no chain of joints",
            "every link joined to the frame through joints",
        )
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
        return None
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


_DECOMPOSED: dict[Any, tuple[Group, ...]] = {}
"""The groups found for each shape of mechanism (links, pairs' names, kinds and links,
known links): the search reads nothing else once it succeeds, so the variants of a
study (and a mechanism analysed again) skip it."""


@dataclass(frozen=True, slots=True)
class _Index:
    """Pairs indexed by link, built once per decomposition."""

    pairs: tuple[Pair, ...]
    links: tuple[str, ...]
    rank: dict[str, int]
    incident: dict[str, tuple[int, ...]]
    neighbours: dict[str, frozenset[str]]
    ends: dict[str, tuple[str, ...]]
    """The link at the other end of each pair on a link (one entry a pair)."""


def _index(topo: Topology) -> _Index:
    """Index the pairs of ``topo`` by the links they join."""
    incident: dict[str, list[int]] = {GROUND: []}
    incident.update({name: [] for name in topo.links})
    neighbours: dict[str, set[str]] = {name: set() for name in incident}
    ends: dict[str, list[str]] = {name: [] for name in incident}
    for i, pair in enumerate(topo.pairs):
        a, b = pair.links
        incident[a].append(i)
        incident[b].append(i)
        neighbours[a].add(b)
        neighbours[b].add(a)
        ends[a].append(b)
        ends[b].append(a)
    return _Index(
        topo.pairs,
        topo.links,
        {name: i for i, name in enumerate(topo.links)},
        {name: tuple(v) for name, v in incident.items()},
        {name: frozenset(v) for name, v in neighbours.items()},
        {name: tuple(v) for name, v in ends.items()},
    )


@dataclass(frozen=True, slots=True)
class _Rigid:
    """Links of a candidate joined so tightly that no motion is left between them."""

    links: tuple[str, ...]
    pairs: tuple[str, ...]


def _attach(index: _Index, known: set[str]) -> Iterator[Group]:
    """Yield the Assur groups on ``known`` one after another (``known`` grows).

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
            raise DecompositionError(_leftover(index, unknown, known, rigid))
        links = sorted(found, key=index.rank.__getitem__)
        yield _describe(links, _counted(index, found, known), known)
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
        part = {first}
        todo = [first]
        while todo:
            for other in index.neighbours[todo.pop()]:
                if other in unknown and other not in part:
                    part.add(other)
                    todo.append(other)
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


@functools.cache
def _parts(k: int) -> tuple[int, ...]:
    """Bit masks of the nonempty parts of a set of ``k`` links, smallest first."""
    return tuple(sorted(range(1, 1 << k), key=lambda m: (m.bit_count(), m)))


def _leftover(
    index: _Index, unknown: set[str], known: set[str], rigid: list[_Rigid]
) -> str:
    """Return the message of a decomposition that stops with links left over."""
    left = tuple(name for name in index.links if name in unknown)
    head = (
        f"links {listing(_public(left))} are left over: they form no Assur group "
        "(3k = 2p, every part movable) on the known links "
        f"{listing(sorted(known))}"
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
    misheld = _misheld_text(index, left, known)
    if misheld is not None:
        return f"{head}, because {misheld}"
    if len(left) > MAX_GROUP_LINKS and 3 * len(left) == 2 * len(pairs):
        # the links left over may be one group too large for the search
        return (
            f"links {listing(_public(left))} are left over: no Assur group of at "
            f"most {MAX_GROUP_LINKS} links attaches to the known links "
            f"{listing(sorted(known))}, and together (k = {len(left)}, p = "
            f"{len(pairs)}: 3k = 2p) they may form one larger group, which assur does "
            f"not solve; expected groups of at most {MAX_GROUP_LINKS} links"
        )
    return f"{head}; expected a chain made of Assur groups"


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


def _links_text(names: Sequence[str], adjective: str = "") -> str:
    """Return "link a" or "links a, b" (as a reader sees them)."""
    noun = "link" if len(names) == 1 else "links"
    return f"{adjective}{noun} {listing(_public(tuple(names)))}"


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


def _describe(links: list[str], counted: list[Pair], known: set[str]) -> Group:
    """Classify a group found by the search."""
    inside = set(links)
    internal = [p for p in counted if p.links[0] in inside and p.links[1] in inside]
    external = [p for p in counted if p not in internal]
    if len(links) == 2:
        return _describe_dyad(links, internal[0], external, known)
    attached = _known_links(external, known)
    import networkx as nx

    g = nx.Graph()
    g.add_nodes_from(links)
    g.add_edges_from(p.links for p in internal)
    longest = max((len(c) for c in nx.simple_cycles(g)), default=0)
    degree = max(dict(g.degree()).values())
    group_class = max(longest, degree)
    if group_class < 3:
        # the search never yields one: such a chain holds a dyad without mobility
        msg = (
            f"links {', '.join(_public(tuple(links)))}: a chain of {len(links)} links "
            "whose joints among them form an open path is no minimal Assur group (a "
            "class II group is a dyad); expected a dyad or a group of class III or "
            "higher"
        )
        raise DecompositionError(msg)
    kind = (
        "triad"
        if (group_class == 3 and len(links) == 4 and len(external) == 3)
        else "general"
    )
    return Group(
        group_class,
        len(external),
        kind,
        tuple(links),
        tuple(p.name for p in internal),
        tuple(p.name for p in external),
        attached,
    )


def _describe_dyad(
    links: list[str], middle: Pair, external: list[Pair], known: set[str]
) -> Group:
    """Order a dyad's links and external pairs so that its signature is canonical."""
    first, second = links
    e1 = next(p for p in external if first in p.links)
    e2 = next(p for p in external if p is not e1)
    forward = e1.kind + middle.kind + e2.kind
    if forward[::-1] > forward:
        first, second, e1, e2 = second, first, e2, e1
    kind = max(forward, forward[::-1])
    attached = _known_links([e1, e2], known)
    return Group(
        2, 2, kind, (first, second), (middle.name,), (e1.name, e2.name), attached
    )


def _known_links(external: list[Pair], known: set[str]) -> tuple[str, ...]:
    """Return the known links the ``external`` pairs join, in the pairs' order.

    Each link once: a dyad on two links reads "on X, Y through P, Q" with P on X.
    """
    found = (x for p in external for x in p.links if x in known)
    return tuple(dict.fromkeys(found))
