"""Structure of a mechanism: its graph, mobility and Assur-group decomposition.

The frame and the driven links form the class I mechanism; the rest is split into
Assur groups (statically determinate chains, 3k = 2p) attached one after another to
links already known, as the structural theory of Assur and Artobolevsky teaches. The
order found here is the order of the kinematic (forward) and kinetostatic (reverse)
passes.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from dataclasses import dataclass
from typing import Any

from assur._text import roman
from assur.errors import DecompositionError, ModelError
from assur.model import GROUND, Driver, Mechanism, resolve_point

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
    ``links[0]``. ``at`` and ``axis`` are reference-pose values in m.
    """

    name: str
    kind: str
    links: tuple[str, str]
    at: tuple[float, float]
    axis: tuple[float, float] | None = None
    virtual: bool = False


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
        the class III group of a ternary and three binary links, or ``"general"``.
    links : tuple of str
        The group's links, in solving order (a dyad's first link carries the first
        external pair of its signature).
    internal, external : tuple of str
        Pairs between links of the group; pairs to known links (external pairs of a
        dyad in signature order).
    attached_to : tuple of str
        Known links the group hangs on.
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
        """Short label such as ``"RRR (2, 3)"``."""
        return f"{self.kind} ({', '.join(_public(self.links))})"


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
        """Class of the mechanism: the highest class of its groups."""
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
    return tuple(n.replace("~block", " (block)") for n in names)


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
        if joint.kind == "revolute":
            pairs.append(Pair(joint.name, "R", (first, second), at))
        elif joint.kind == "prismatic":
            pairs.append(Pair(joint.name, "P", (first, second), at, axis))
        else:
            block = f"{joint.name}~block"
            links.append(block)
            slots.append(joint.name)
            pairs.append(Pair(joint.name, "P", (first, block), at, axis))
            pairs.append(
                Pair(f"{joint.name}~pin", "R", (block, second), at, virtual=True)
            )
    return Topology(tuple(links), tuple(pairs), tuple(slots))


def _unit(v: tuple[float, float]) -> tuple[float, float]:
    length = math.hypot(*v)
    return (v[0] / length, v[1] / length)


def mobility(mech: Mechanism) -> int:
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
    n = len(mech.links)
    p4 = sum(joint.kind == "slot" for joint in mech.joints)
    p5 = len(mech.joints) - p4
    return 3 * n - 2 * p5 - p4


def graph(mech: Mechanism) -> Any:
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

    g = nx.MultiGraph()
    g.add_node(GROUND)
    g.add_nodes_from(link.name for link in mech.links)
    for joint in mech.joints:
        g.add_edge(*joint.links, key=joint.name, kind=joint.kind)
    return g


def structure(mech: Mechanism, driver: str | None = None) -> Structure:
    """Analyse the structure of ``mech``: mobility and Assur groups.

    Parameters
    ----------
    mech : Mechanism
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
    if driver is not None:
        if driver not in {j.name for j in mech.joints}:
            msg = f"--driver: unknown joint {driver!r}"
            raise DecompositionError(msg)
        omega = mech.drivers[0].omega if mech.drivers else 1.0
        try:
            mech = dataclasses.replace(mech, drivers=(Driver(driver, omega),))
        except ModelError as err:
            msg = f"--driver: {str(err).split(': ', 1)[-1]}"
            raise DecompositionError(msg) from None
    drivers, groups, topo = decompose(mech)
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
    """
    w = mobility(mech)
    if w != len(mech.drivers):
        n = len(mech.links)
        p4 = sum(j.kind == "slot" for j in mech.joints)
        msg = (
            f"drivers: the mechanism has W = 3*{n} - 2*{len(mech.joints) - p4} - {p4}"
            f" = {w} degree(s) of freedom but {len(mech.drivers)} driver(s); "
            "expected one driver per degree of freedom"
        )
        raise DecompositionError(msg)
    topo = topology(mech)
    by_name = {p.name: p for p in topo.pairs}
    drivers = []
    known = {GROUND}
    for d in mech.drivers:
        pair = by_name[d.joint]
        link = pair.links[1] if pair.links[0] == GROUND else pair.links[0]
        drivers.append(Group(1, 0, "driver", (GROUND, link), (d.joint,), (), (GROUND,)))
        known.add(link)
    groups = []
    unknown = [name for name in topo.links if name not in known]
    while unknown:
        found = _find_group(topo.pairs, known, unknown)
        if found is None:
            msg = (
                f"links {', '.join(_public(tuple(unknown)))} are left over: they form "
                "no Assur group (3k = 2p, every part movable) on the known links "
                f"{', '.join(sorted(known))}; expected a chain made of Assur groups"
            )
            raise DecompositionError(msg)
        groups.append(found)
        known.update(found.links)
        unknown = [name for name in unknown if name not in known]
    return tuple(drivers), tuple(groups), topo


def _counted(
    pairs: tuple[Pair, ...], links: frozenset[str], known: set[str]
) -> list[Pair]:
    """Pairs with one end in ``links`` and the other in ``links`` or ``known``."""
    return [
        p
        for p in pairs
        if (p.links[0] in links or p.links[1] in links)
        and all(x in links or x in known for x in p.links)
    ]


def _find_group(
    pairs: tuple[Pair, ...], known: set[str], unknown: list[str]
) -> Group | None:
    """Return the smallest Assur group on ``known``, or None."""
    adjacency: dict[str, set[str]] = {name: set() for name in unknown}
    for p in pairs:
        a, b = p.links
        if a in adjacency and b in adjacency:
            adjacency[a].add(b)
            adjacency[b].add(a)
    rank = {name: i for i, name in enumerate(unknown)}
    for k in range(2, min(len(unknown), MAX_GROUP_LINKS) + 1, 2):
        candidates = sorted(
            _connected_subsets(adjacency, k), key=lambda s: sorted(rank[x] for x in s)
        )
        for subset in candidates:
            counted = _counted(pairs, subset, known)
            if 2 * len(counted) == 3 * k and _determinate(pairs, subset, known):
                return _describe(sorted(subset, key=rank.__getitem__), counted, known)
    return None


def _connected_subsets(adjacency: dict[str, set[str]], k: int) -> set[frozenset[str]]:
    """All connected sets of ``k`` nodes of a small graph."""
    found: set[frozenset[str]] = set()
    frontier = {frozenset([node]) for node in adjacency}
    for _ in range(k - 1):
        grown = set()
        for subset in frontier:
            for node in subset:
                for other in adjacency[node] - subset:
                    grown.add(subset | {other})
        frontier = grown
    found.update(frontier)
    return found


def _determinate(
    pairs: tuple[Pair, ...], subset: frozenset[str], known: set[str]
) -> bool:
    """Every part of the chain keeps mobility >= 0 (no over-constrained part)."""
    items = sorted(subset)
    if all(p.kind == "P" for p in _counted(pairs, subset, known)):
        return False  # a chain of only sliding pairs cannot fix its rotation
    for size in range(1, len(items)):
        for part in itertools.combinations(items, size):
            if 2 * len(_counted(pairs, frozenset(part), known)) > 3 * size:
                return False
    return True


def _describe(links: list[str], counted: list[Pair], known: set[str]) -> Group:
    """Classify a group found by the search."""
    inside = set(links)
    internal = [p for p in counted if p.links[0] in inside and p.links[1] in inside]
    external = [p for p in counted if p not in internal]
    attached = sorted({x for p in external for x in p.links if x in known})
    if len(links) == 2:
        return _describe_dyad(links, internal[0], external, attached)
    import networkx as nx

    g = nx.Graph()
    g.add_nodes_from(links)
    g.add_edges_from(p.links for p in internal)
    longest = max((len(c) for c in nx.simple_cycles(g)), default=0)
    degree = max(dict(g.degree()).values())
    group_class = max(longest, degree, 2)
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
        tuple(attached),
    )


def _describe_dyad(
    links: list[str], middle: Pair, external: list[Pair], attached: list[str]
) -> Group:
    """Order a dyad's links and external pairs so that its signature is canonical."""
    first, second = links
    e1 = next(p for p in external if first in p.links)
    e2 = next(p for p in external if p is not e1)
    forward = e1.kind + middle.kind + e2.kind
    if forward[::-1] > forward:
        first, second, e1, e2 = second, first, e2, e1
    kind = max(forward, forward[::-1])
    return Group(
        2, 2, kind, (first, second), (middle.name,), (e1.name, e2.name), tuple(attached)
    )
