"""One Assur group: its record and its classification.

A group found by the search (its links, the pairs it counts, the links known) is
classified here: a dyad with its canonical signature, a triad or a general group.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from assur._text import roman, spoken
from assur._topology import Pair, _public
from assur.errors import DecompositionError

__all__ = ["Group"]


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
    base : str
        Class III and higher: the base link whose internal pairs set the class (a
        triad's ternary link), or "" when a closed contour of internal pairs sets
        it.
    basis : tuple of str
        Class III and higher: the internal pairs that set the class, those of the
        base link or those closing the contour, in order round it.
    sliding : tuple of str
        Class III and higher: the group's prismatic pairs, internal and external
        (a dyad's kind names its own).
    carriers : tuple of str
        The known link each external pair joins, in the order of ``external``.
    label : str
        Short label such as ``"RRR (2, 3)"``; ``"class IV (...)"`` beyond triads.
        Made from the fields above, once: every force record of a sweep carries it.
    """

    group_class: int
    order: int
    kind: str
    links: tuple[str, ...]
    internal: tuple[str, ...]
    external: tuple[str, ...]
    attached_to: tuple[str, ...]
    base: str = ""
    basis: tuple[str, ...] = ()
    sliding: tuple[str, ...] = ()
    carriers: tuple[str, ...] = ()
    label: str = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        kind = self.kind
        if kind == "general":
            kind = f"class {roman(self.group_class)}"
        label = f"{kind} ({', '.join(_public(self.links))})"
        object.__setattr__(self, "label", label)


def _describe(links: list[str], counted: list[Pair], known: set[str]) -> Group:
    """Classify a group found by the search."""
    inside = set(links)
    internal = [p for p in counted if p.links[0] in inside and p.links[1] in inside]
    external = [p for p in counted if p not in internal]
    if len(links) == 2:
        return _describe_dyad(links, internal[0], external, known)
    carriers = _carriers(external, known)
    import networkx as nx

    g = nx.Graph()
    g.add_nodes_from(links)
    for p in internal:
        g.add_edge(*p.links, name=p.name)
    # the class: the internal pairs of the most complex link or closed contour
    contour: list[str] = max(nx.simple_cycles(g), key=len, default=[])
    base = max(links, key=g.degree)
    longest, degree = len(contour), g.degree(base)
    group_class = max(longest, degree)
    if longest > degree:
        ring = zip(contour, [*contour[1:], contour[0]], strict=True)
        basis = tuple(g.edges[u, v]["name"] for u, v in ring)
        base = ""
    else:
        basis = tuple(p.name for p in internal if base in p.links)
    if group_class < 3:
        # the search never yields one: such a chain holds a dyad without mobility
        msg = (
            f"links {spoken(_public(tuple(links)))}: a chain of {len(links)} links "
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
        _known_links(carriers),
        base,
        basis,
        tuple(p.name for p in counted if p.kind == "P"),
        carriers,
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
    carriers = _carriers([e1, e2], known)
    return Group(
        2,
        2,
        kind,
        (first, second),
        (middle.name,),
        (e1.name, e2.name),
        _known_links(carriers),
        carriers=carriers,
    )


def _carriers(external: list[Pair], known: set[str]) -> tuple[str, ...]:
    """Return the known link each of the ``external`` pairs joins, in their order."""
    return tuple(next(x for x in p.links if x in known) for p in external)


def _known_links(carriers: tuple[str, ...]) -> tuple[str, ...]:
    """Return the known links of a group's external pairs' ``carriers``, in order.

    Each link once: a dyad on two links reads "on X, Y through P, Q" with P on X.
    """
    return tuple(dict.fromkeys(carriers))
