"""The protocol every Assur-group solver answers, and the records its steps return.

The forward pass asks each group, in order of attachment, to assemble itself on the
links already known, to linearise its closure equations there and to solve their time
derivatives; the reverse pass asks each group, in the reverse order, for its
equilibrium. Both passes are plain loops over objects that answer this one protocol,
so a new group family is one module (a ``compile`` function returning such an object)
plus one line in the registry of :mod:`assur.groups`.

Each step returns a frozen record rather than writing into shared lists: an
:class:`Assembly` (which positions failed, the next guess of a continuation), a
:class:`Linearization` (the Jacobian and how well conditioned it is) and an
:class:`Equilibrium` (the group's loads, unknowns, equations and solved reactions).
The explanatory note prints these records; a friction iteration solves them again.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

import numpy as np

from assur._vec import Array, Mask, diameters
from assur.groups._equations import Equations, equations
from assur.groups._motion import Motion

if TYPE_CHECKING:
    from assur._structure import Group
    from assur.groups._pairs import PairPlan

__all__ = [
    "Assembly",
    "CompileContext",
    "Equations",
    "Equilibrium",
    "GroupSolver",
    "Linearization",
    "Reaction",
    "Wrench",
    "group_sizes",
]

Wrench = list[Any]
"""``[F_x, F_y, tau]``: a force (N) and its moment about the core's origin (N m)."""


@dataclass(frozen=True, slots=True)
class CompileContext:
    """What a group family needs to compile one group of a mechanism.

    Attributes
    ----------
    bodies : tuple of str
        Link names by body index; index 0 is the frame.
    index : dict of str to int
        Body index by link name.
    pairs : dict of str to PairPlan
        Every lower pair, by name.
    origins : ndarray (B, 2)
        Each body's origin in the reference pose, m, in the core's coordinates.
    scale : float
        Size of the mechanism, m (largest distance between two pairs): the size its
        coordinates' rounding is told against. A group's own size, against which its
        closeness to a dead centre is told, is :meth:`size`.
    motions : tuple of Motion
        Every body at rest in the reference pose.
    """

    bodies: tuple[str, ...]
    index: dict[str, int]
    pairs: dict[str, PairPlan]
    origins: Array
    scale: float
    motions: tuple[Motion, ...]

    def reference(self) -> list[Motion]:
        """Return every body at rest in the reference pose (a list to assemble in)."""
        return list(self.motions)

    def size(self, group: Group) -> float:
        """Return ``group``'s own size (m): see :func:`group_sizes`."""
        at = [
            self.origins[p.first] + np.asarray(p.d_first)
            for p in (self.pairs[n] for n in group.internal + group.external)
        ]
        return float(group_sizes(np.array(at)[None], np.array([self.scale]))[0])


SMALLEST_GROUP = 1e-9
"""Smallest size of a group, as a fraction of the mechanism's (that of the smallest
link ``compile_plan`` accepts): a group whose pairs all meet has no size of its own."""


def group_sizes(points: Array, scale: Array) -> Array:
    """Return each variant's group size (k,), m: the diameter of its pairs' points.

    ``points`` (k, P, 2) are the group's pairs in the reference pose and ``scale``
    (k,) the mechanism's size (m). A group's conditioning weighs its equations in
    metres against those in radians by this length: the mechanism's size made a
    small group in a large machine look near its dead centre at every position.
    """
    return np.maximum(diameters(points), SMALLEST_GROUP * scale)


@dataclass(frozen=True, slots=True)
class Assembly:
    """Result of assembling a group over a batch.

    ``failed`` marks the positions where the group does not close (its links' poses
    hold NaN there); ``guess`` is what a continuation starts the next step from (None
    for closed forms).
    """

    failed: Mask
    guess: Any = None


@dataclass(frozen=True, slots=True)
class Linearization:
    """The group's Jacobian at the solved pose and its conditioning.

    ``jacobian`` is in the family's own form; ``conditioning`` (n,) is dimensionless,
    1 for a well-posed group and 0 at a dead centre (above the family's ``near``, a
    family may give a lower bound of it that is above ``near`` too: it is read
    against the thresholds only); ``singular`` marks the positions below the family's
    threshold, where derivatives are not defined.
    """

    jacobian: Any
    conditioning: Array
    singular: Mask


@dataclass(frozen=True, slots=True)
class Reaction:
    """A pair's reaction: force by its first link on its second, and a couple.

    ``fx``, ``fy`` in N; ``couple`` in N m about the pair's point moving with the
    second link (zero for a revolute pair).
    """

    fx: Any
    fy: Any
    couple: Any = 0.0


@dataclass(frozen=True, slots=True)
class Equilibrium:
    """The record of one group's equilibrium step.

    Attributes
    ----------
    label : str
        The group, e.g. ``"RRR (coupler, rocker)"``.
    bodies : tuple of int
        The group's links.
    loads : tuple of Wrench
        The known loads on each of the group's links when it was solved (applied
        loads, inertia loads and the reactions of groups solved before it).
    pairs : tuple of PairPlan
        The pairs whose reactions the step solved (internal, then external).
    reactions : dict of str to Reaction
        The solved reaction of each of those pairs.
    passed : tuple of (int, Wrench)
        The load each known link receives from the group.
    moment_points : tuple of (float, float)
        For each link, the body-fixed offset of the point its textbook moment
        equation is taken about.
    """

    label: str
    bodies: tuple[int, ...]
    loads: tuple[Wrench, ...]
    pairs: tuple[PairPlan, ...]
    reactions: dict[str, Reaction]
    passed: tuple[tuple[int, Wrench], ...]
    moment_points: tuple[tuple[float, float], ...]

    @property
    def unknowns(self) -> tuple[str, ...]:
        """Return the unknowns' names.

        ``J.Fx, J.Fy`` per revolute pair; ``J.N, J.M`` per prismatic pair (normal
        force, N; couple, N m).
        """
        names: list[str] = []
        for pair in self.pairs:
            names += (
                [f"{pair.name}.Fx", f"{pair.name}.Fy"]
                if pair.kind == "R"
                else [f"{pair.name}.N", f"{pair.name}.M"]
            )
        return tuple(names)

    def equations(self, bodies: list[Motion], names: tuple[str, ...]) -> Equations:
        """Return the equations: each link's force sums and moment equation.

        Parameters
        ----------
        bodies : list of Motion
            The links' motions the step was solved on.
        names : tuple of str
            Link names by body index, for the rows' names.
        """
        return equations(self, bodies, names)


class GroupSolver(Protocol):
    """What the forward and reverse passes ask of every Assur group.

    Attributes
    ----------
    group : Group
        The group of the decomposition this solver solves.
    bodies : tuple of int
        Its links' body indices.
    newton : bool
        Whether positions are found iteratively (and so need a continuation).
    singular, near : float
        Conditioning below which a pose is a dead centre, and below which it is
        near one (a warning).
    """

    newton: ClassVar[bool]
    singular: ClassVar[float]
    near: ClassVar[float]

    @property
    def group(self) -> Group:
        """The group of the decomposition."""
        ...

    @property
    def bodies(self) -> tuple[int, ...]:
        """The group's links, by body index."""
        ...

    @property
    def label(self) -> str:
        """Short label such as ``"RRR (coupler, rocker)"``."""
        ...

    @property
    def branch(self) -> float:
        """The reference pose's branch of a two-branch closed form (+1 or -1)."""
        ...

    def assemble(
        self, bodies: list[Motion], n: int, guess: Any = None, branch: Any = None
    ) -> Assembly:
        """Set the position level of the group's links in ``bodies``."""
        ...

    def linearize(self, bodies: list[Motion]) -> Linearization:
        """Return the Jacobian of the closure equations at the solved pose."""
        ...

    def derivative(self, bodies: list[Motion], k: int, lin: Linearization) -> None:
        """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of the links."""
        ...

    def equilibrium(self, bodies: list[Motion], loads: list[Wrench]) -> Equilibrium:
        """Solve the group's reactions under the known ``loads`` of every body."""
        ...

    def discriminant(self, bodies: list[Motion]) -> Any:
        """Return where the group's two closed-form branches meet, or None.

        Dimensionless, over the batch: negative where the group cannot close, zero
        where its two assembly branches meet (a change point when it only touches
        zero). None for a group with one branch or followed by continuation.
        """
        ...

    def own_slides(self) -> dict[str, tuple[int, float]]:
        """Prismatic pairs whose slide is one of the group's own coordinates.

        Maps the pair's name to the link carrying that coordinate and the sign that
        relates the two (the slide's derivatives are then read, not recomputed).
        """
        ...
