"""Structure of a mechanism: its graph, mobility and Assur-group decomposition.

The frame and the driven links form the class I mechanism; the rest is split into
Assur groups (statically determinate chains, 3k = 2p) attached one after another to
links already known, as the structural theory of Assur and Artobolevsky teaches. The
order found here is the order of the kinematic (forward) and kinetostatic (reverse)
passes.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from assur._diagnosis import _miscount, count_text, no_driver
from assur._group import Group, _describe
from assur._group_search import _attach
from assur._listed import listed
from assur._text import counted, describe, noun_for, roman, suggest
from assur._topology import Pair, Topology, _index, _public, topology
from assur.errors import DecompositionError, ModelError
from assur.model import GROUND, Driver, Mechanism, mechanism_of

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


@dataclass(frozen=True, slots=True)
class Structure:
    """The structural analysis of a mechanism; ``str()`` gives the teaching report.

    Attributes
    ----------
    name : str
        The mechanism's name (empty when it has none).
    links : int
        Number n of moving links, the frame left out (as are the blocks that
        replace slots in the groups).
    lower_pairs : int
        Number p5 of lower pairs: the revolute and prismatic joints.
    higher_pairs : int
        Number p4 of higher pairs: the slots (a pin in a straight slot).
    dof : int
        Degrees of freedom W = 3n - 2p5 - p4 (see `mobility`), which equals the
        number of drivers.
    drivers : tuple of Group
        One class I group per driver (the frame and the input link), in the order
        of the drivers.
    groups : tuple of Group
        The Assur groups in the order they attach, which is the order of the
        kinematic (forward) pass.
    slots : tuple of str
        Names of the slot joints. In the groups, slot ``J`` is a block ``"J~block"``
        sliding in it through the prismatic pair ``J`` and carrying the pin through
        the revolute pair ``"J~pin"``.
    """

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
        return self._formula(_public)

    def _formula(self, names: Callable[[tuple[str, ...]], tuple[str, ...]]) -> str:
        """Return the structure formula with the links named by ``names``."""
        steps = [
            f"{roman(g.group_class)}({', '.join(names(g.links))})"
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
                # class III and higher: what sets the class (see Group.basis)
                **({"base": g.base, "basis": list(g.basis)} if g.basis else {}),
                **({"sliding_pairs": list(g.sliding)} if g.sliding else {}),
            }

        return {
            "name": self.name,
            "links": self.links,
            "lower_pairs": self.lower_pairs,
            "higher_pairs": self.higher_pairs,
            "dof": self.dof,
            "drivers": [group(g) for g in self.drivers],
            "groups": [group(g) for g in self.groups],
            # the names of the JSON's links (a slot's block is B~block there)
            "formula": self._formula(lambda links: links),
            "mechanism_class": self.mechanism_class,
            "slots": list(self.slots),
        }

    def __str__(self) -> str:
        from assur.report import structure_report

        return structure_report(self)

    def _repr_html_(self) -> str:
        """Return the structure as a notebook shows it: W, formula, groups (HTML)."""
        from assur._structure_display import structure_html

        return structure_html(self)


def mobility(mechanism: Mechanism) -> int:
    """Return the degrees of freedom by the Chebyshev-Gruebler formula.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism whose links and joints are counted; its drivers play no part.

    Returns
    -------
    int
        The degrees of freedom W: the number of drivers a mechanism needs. Zero or
        less for a rigid chain; the count cannot see a link that repeats a
        constraint (a third parallel crank of a parallelogram).

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

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism whose links and joints make the graph.

    Returns
    -------
    networkx.MultiGraph
        One node per link, named as the link: the frame ``"ground"`` and every
        moving link. One edge per joint, between the two links it joins, keyed by
        the joint's name and carrying its ``kind`` (``"revolute"``, ``"prismatic"``
        or ``"slot"``); two joints between the same two links are two edges.

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


class DriverChoiceError(DecompositionError):
    """A decomposition that fails for the input ``structure(driver=...)`` chose.

    ``reason`` says why, without the argument's name; with ``counted`` the count of
    inputs is at fault, which the one input the argument sets explains. The message
    names the argument as the library spells it (:meth:`spelled` as another does).
    """

    def __init__(self, reason: str, counted: bool = False, inputs: int = 1) -> None:
        self.reason = reason
        self.counted = counted
        self.inputs = inputs
        super().__init__(self.spelled("driver", "driver="))

    def spelled(self, name: str, setting: str) -> str:
        """Return the message with the argument named ``name`` (set as ``setting``)."""
        sets = "one input" if self.inputs == 1 else f"{self.inputs} inputs"
        note = (
            f" ({setting} sets {sets}; without it the file's drivers are used)"
            if self.counted
            else ""
        )
        return f"{name}: {self.reason}{note}"


def _chosen(driver: Any) -> list[str] | None:
    """Return the joints ``driver=`` names; refuse what names none (5, b"A")."""
    return None if driver is None else listed(driver, "driver", "joint")


def structure(
    mechanism: Mechanism, driver: str | Sequence[str] | None = None
) -> Structure:
    """Analyse the structure of ``mechanism``: mobility and Assur groups.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism to analyse, with one driver per degree of freedom.
    driver : str or sequence of str, optional
        Analyse with this joint as the only input instead of the file's drivers (the
        class of a mechanism depends on its input link); with several degrees of
        freedom, a joint for each (``["A", "E"]``).

    Returns
    -------
    Structure
        The counts of links and pairs, the mobility, the driving links and the Assur
        groups in the order they attach; ``str()`` of it is the teaching report and
        ``to_dict()`` the same as JSON-ready data.

    Raises
    ------
    DecompositionError
        When the mobility differs from the number of drivers, links are left over,
        or the file has no driver and its links cannot move (a rigid structure,
        which is no mechanism).
    UsageError
        When ``driver`` is no joint name nor a list of them (a number, bytes).

    Examples
    --------
    >>> from assur import catalog
    >>> s = structure(catalog.four_bar())
    >>> s.formula
    'I(ground, crank) -> II(coupler, rocker)'
    """
    mech = mechanism_of(mechanism)
    chosen = _chosen(driver)
    if chosen is not None:
        joints = {j.name for j in mech.joints}
        for name in chosen:
            if name not in joints:
                known = [j.name for j in mech.joints if GROUND in j.links]
                hint = suggest(str(name), known, label="joints with the frame")
                msg = f"unknown joint {describe(name)}{hint}"
                raise DriverChoiceError(msg)
        omega = mech.drivers[0].omega if mech.drivers else 1.0
        try:
            inputs = tuple(Driver(name, omega) for name in chosen)
            mech = dataclasses.replace(mech, drivers=inputs)
        except ModelError as err:
            raise DriverChoiceError(str(err).split(": ", 1)[-1]) from None
    if not mech.drivers and mobility(mech) <= 0:
        # a rigid chain on the frame (a truss) decomposes into groups, but it is a
        # structure, not a mechanism: it has no input and no class
        raise DecompositionError(no_driver(mech, mobility(mech)))
    try:
        drivers, groups, topo = decompose(mech)
    except DecompositionError as err:
        if driver is None or not str(err).startswith("drivers:"):
            raise
        # the count of inputs is the option's doing, not the file's
        reason = str(err).split(": ", 1)[-1]
        raise DriverChoiceError(reason, True, len(chosen or ())) from None
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
        why, expected = _miscount(topo, w, mech)
        msg = (
            f"drivers: the mechanism has W = {count_text(mech, w)} "
            f"{noun_for(w, 'degree', 'degrees')} of freedom but "
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
        groups = tuple(_describe(*step) for step in _attach(_index(topo), known))
        if len(_DECOMPOSED) >= 256:
            _DECOMPOSED.clear()
        _DECOMPOSED[key] = groups
    return tuple(drivers), groups, topo


_DECOMPOSED: dict[Any, tuple[Group, ...]] = {}
"""The groups found for each shape of mechanism (links, pairs' names, kinds and links,
known links): the search reads nothing else once it succeeds, so the variants of a
study (and a mechanism analysed again) skip it."""
