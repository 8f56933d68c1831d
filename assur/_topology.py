"""The structural model of a mechanism: its links and lower pairs, slots replaced.

A slot (a pin in a straight slot, a higher pair) becomes a block that slides in the
slot and carries the pin, so the search for Assur groups and the diagnosis of a
failed one see lower pairs only; the index answers which pairs hold a link.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from assur._text import public_name
from assur.model import GROUND, Mechanism, resolve_point


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
    """Return ``v`` scaled to length 1."""
    length = math.hypot(*v)
    return (v[0] / length, v[1] / length)


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


def _component(index: _Index, start: str, within: set[str] | None = None) -> set[str]:
    """Return the links joined to ``start`` by chains of joints, itself included.

    With ``within``, the chains go through links of ``within`` alone.
    """
    part = {start}
    todo = [start]
    while todo:
        for other in index.neighbours[todo.pop()]:
            if other not in part and (within is None or other in within):
                part.add(other)
                todo.append(other)
    return part
