"""What every dyad (class II group) shares: its coordinates, derivatives and reactions.

Each of a dyad's two links hangs on a known link by an external pair, which leaves it
one coordinate: its rotation (revolute pair, the body's origin is the pin) or its slide
along the guide (prismatic pair, the body turns with the guide). The middle pair gives
two equations in those two coordinates. Positions are closed form, one module per kind
(its ``closure``); velocities, accelerations and jerks solve the same 2x2 Jacobian with
Cramer's rule, element by element over the batch (:mod:`assur.groups._coordinates`);
reactions eliminate the external pairs with one equation per link (the virtual power
along that link's own coordinate).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from assur._quiet import quiet
from assur._vec import add, cross, dot, mul, sub, wrap
from assur.errors import ModelError
from assur.groups._coordinates import (
    conditioning,
    derivative,
    guide,
    jacobian,
    linear_step,
    set_pose,
    signed_conditioning,
    solve2,
)
from assur.groups._motion import Motion, point
from assur.groups._pairs import PairPlan, unit_wrenches
from assur.groups._protocol import (
    Assembly,
    CompileContext,
    Equilibrium,
    Linearization,
    Reaction,
    Wrench,
)

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = [
    "BRANCH_TOLERANCE",
    "DEAD_CENTRE",
    "Closure",
    "DyadSolver",
    "closing_root",
    "compile_dyad",
    "linear_step",
    "reaction",
    "solve2",
]

Closure = Callable[["DyadSolver", list[Motion], Any], tuple[Any, Any]]
"""A dyad kind's closed-form assembly: ``(dyad, bodies, branch) -> (q1, q2)``."""
Discriminant = Callable[["DyadSolver", list[Motion]], Any]
"""A two-branch kind's discriminant: ``(dyad, bodies) -> D``, dimensionless, negative
where the dyad cannot close and zero where its two branches meet."""

ROUNDING = 1e-14
"""Square root's argument, relative to the size of its terms, below zero by which a
dyad still closes: a pose stretched out exactly (a change point) is computed a few
ulps short of closing."""


def closing_root(square: Any, size: Any) -> Any:
    """Return the square root of ``square``; 0 within rounding below 0; NaN beyond.

    ``size`` is that of the terms ``square`` is the difference of.
    """
    with quiet():
        # one reduction (NaN passed over) tells the common case: a dyad that closes
        if not np.fmin.reduce(square, axis=None, initial=np.inf) < 0.0:
            return np.sqrt(square)
        rounded = (square < 0.0) & (square >= -ROUNDING * size)
        return np.sqrt(np.where(rounded, 0.0, square))[()]


DEAD_CENTRE = 1e-6
"""Smallest sine of a dyad's transmission angle accepted in the reference pose (the
conditioning of :func:`~assur.groups._coordinates.conditioning`)."""
APART = 1e-9
"""Outer joints of a dyad closer than this, times the mechanism's size, are one
point."""
BRANCH_TOLERANCE = 1e-7
"""Largest coordinate (rad, or m relative to the mechanism's size) that the chosen
branch may miss the reference pose by."""


@dataclass(frozen=True, slots=True)
class DyadSolver:
    """A compiled dyad: the :class:`~assur.groups._protocol.GroupSolver` of class II.

    ``bodies`` are the two links' indices in signature order, ``ext`` their external
    pairs, ``mid`` the middle pair, ``known`` the known links the external pairs join,
    ``d_known`` the external pairs' offsets on those links, ``d_mid`` the middle pair's
    offsets on the two links, ``closure`` the kind's closed-form assembly, ``branch``
    the assembly branch of the reference pose (+1 or -1), ``scale`` the mechanism's
    size (m), against which rounding of its coordinates is told, and ``size`` the
    group's own (m, the diameter of its pairs in the reference pose), against which
    its closeness to a dead centre is told.
    """

    group: Group
    bodies: tuple[int, int]
    ext: tuple[PairPlan, PairPlan]
    mid: PairPlan
    known: tuple[int, int]
    d_known: tuple[tuple[float, float], tuple[float, float]]
    d_mid: tuple[tuple[float, float], tuple[float, float]]
    closure: Closure
    scale: float
    size: float
    branch: float = 1.0
    gap: Discriminant | None = None

    newton: ClassVar[bool] = False
    singular: ClassVar[float] = 1e-6
    """Sine of the angle between the Jacobian's columns (a prismatic middle pair's
    normal equation in units of the group's size) below which a pose is a dead
    centre, where velocities are undefined. A closed form's square root leaves about
    the root of the rounding error (1e-8) at an exact dead centre: no smaller sine
    can be told from zero."""
    near: ClassVar[float] = 0.035
    """Below this (about 2 degrees of transmission angle) a pose is near-singular."""

    @property
    def kind(self) -> str:
        """The dyad's signature, e.g. ``"RRP"``."""
        return self.group.kind

    @property
    def label(self) -> str:
        """Short label such as ``"RRR (coupler, rocker)"``."""
        return self.group.label

    def assemble(
        self, bodies: list[Motion], n: int, guess: Any = None, branch: Any = None
    ) -> Assembly:
        """Set both links' poses in closed form; NaN where the dyad cannot close."""
        q1, q2 = self.closure(self, bodies, self.branch if branch is None else branch)
        q1, q2 = _batch(q1, n), _batch(q2, n)
        set_pose(self, bodies, q1, q2)
        return Assembly(~(np.isfinite(q1) & np.isfinite(q2)))

    def linearize(self, bodies: list[Motion]) -> Linearization:
        """Return the 2x2 Jacobian and the sine of the angle between its columns."""
        jac = jacobian(self, bodies)
        cond = conditioning(self, jac)
        return Linearization(jac, cond, ~(cond >= self.singular))

    def derivative(self, bodies: list[Motion], k: int, lin: Linearization) -> None:
        """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of both links."""
        derivative(self, bodies, k, lin.jacobian)

    def signed_conditioning(self, bodies: list[Motion]) -> Any:
        """Return the conditioning with its determinant's sign (see assur._reach).

        Optional in the protocol: a closed-form family that offers it has the
        dead centres it passes between two positions found.
        """
        return signed_conditioning(self, jacobian(self, bodies))

    def equilibrium(self, bodies: list[Motion], loads: list[Wrench]) -> Equilibrium:
        """Solve the dyad's three reactions in closed form."""
        return equilibrium(self, bodies, loads)

    def discriminant(self, bodies: list[Motion]) -> Any:
        """Return the kind's discriminant (None for a kind with a single branch)."""
        return None if self.gap is None else self.gap(self, bodies)

    def own_slides(self) -> dict[str, tuple[int, float]]:
        """External prismatic pairs whose slide is a link's own coordinate.

        Maps the pair's name to the link and the sign relating the two.
        """
        return {
            pair.name: (body, 1.0 if pair.second == body else -1.0)
            for body, pair in zip(self.bodies, self.ext, strict=True)
            if pair.kind == "P"
        }


def _batch(q: Any, n: int) -> Any:
    """Return ``q`` as n values (a group hanging on the frame alone is constant)."""
    return q if np.ndim(q) else np.full(n, float(q))


def _eliminator(plan: DyadSolver, bodies: list[Motion], b: int) -> tuple[Any, Any, Any]:
    """Weights (w_x, w_y, w_tau) of the equation of link b free of its external pair.

    Revolute: moments about the pin. Prismatic: forces along the guide.
    """
    if plan.ext[b].kind == "R":
        m = bodies[plan.bodies[b]]
        return m.oy[0], mul(-1.0, m.ox[0]), 1.0
    ex, ey = guide(plan, bodies, b)
    return ex, ey, 0.0


def equilibrium(
    plan: DyadSolver, bodies: list[Motion], loads: list[Wrench]
) -> Equilibrium:
    """Solve the dyad's three reactions; return them and the loads on the known links.

    Notes
    -----
    One equation per link is free of that link's external pair (moments about its pin,
    or forces along its guide); together they give the middle pair's two unknowns by
    Cramer's rule. Each link's force and moment sums then give its external reaction.
    """
    cols = unit_wrenches(plan.mid, bodies)
    rows, rhs, signs = [], [], []
    for b in (0, 1):
        wx, wy, wt = _eliminator(plan, bodies, b)
        sign = 1.0 if plan.bodies[b] == plan.mid.second else -1.0
        rows.append([mul(sign, dot((wx, wy, wt), c)) for c in cols])
        rhs.append(dot((wx, wy, wt), loads[plan.bodies[b]]))
        signs.append(sign)
    lam0, lam1 = solve2(
        (rows[0][0], rows[0][1], rows[1][0], rows[1][1]), rhs[0], rhs[1]
    )
    mid = [dot((lam0, lam1), (cols[0][i], cols[1][i])) for i in range(3)]
    reactions = {plan.mid.name: reaction(plan.mid, bodies, mid)}
    passed = []
    for b in (0, 1):
        body = plan.bodies[b]
        add_or_sub = add if signs[b] > 0 else sub
        total = [add_or_sub(loads[body][i], mid[i]) for i in range(3)]
        passed.append((plan.known[b], total))
        pair = plan.ext[b]
        on_second = total if pair.second != body else [mul(-1.0, t) for t in total]
        reactions[pair.name] = reaction(pair, bodies, on_second)
    return Equilibrium(
        plan.label,
        plan.bodies,
        (loads[plan.bodies[0]], loads[plan.bodies[1]]),
        (plan.mid, *plan.ext),
        reactions,
        tuple(passed),
        plan.d_mid,
    )


def reaction(pair: PairPlan, bodies: list[Motion], wrench: Wrench) -> Reaction:
    """Return the reaction of ``pair`` from the wrench on its second link.

    The wrench's moment is about the core's origin; a prismatic pair's couple is
    taken about the pair's point.
    """
    fx, fy, tau = wrench
    if pair.kind == "R":
        return Reaction(fx, fy)
    qx, qy = point(bodies[pair.second], pair.d_second, 0)
    return Reaction(fx, fy, sub(tau, cross(qx, qy, fx, fy)))


def offsets(
    ext: tuple[PairPlan, PairPlan],
    mid: PairPlan,
    bodies: tuple[int, int],
    known: tuple[int, int],
) -> tuple[tuple[Any, Any], tuple[Any, Any]]:
    """Return a dyad's body-fixed offsets (m).

    Those of its outer pairs on the known links, and of its middle pair on each of
    its two links.
    """
    d_known = (
        ext[0].d_first if ext[0].first == known[0] else ext[0].d_second,
        ext[1].d_first if ext[1].first == known[1] else ext[1].d_second,
    )
    d_mid = (
        mid.d_first if mid.first == bodies[0] else mid.d_second,
        mid.d_first if mid.first == bodies[1] else mid.d_second,
    )
    return d_known, d_mid


def compile_dyad(
    context: CompileContext,
    group: Group,
    closure: Closure,
    discriminant: Discriminant | None = None,
) -> DyadSolver:
    """Compile a dyad of ``group``'s kind: offsets, and the reference pose's branch.

    Raises
    ------
    ModelError
        When the reference pose is not an assembled pose of the dyad or sits at its
        dead centre.
    """
    bodies = (context.index[group.links[0]], context.index[group.links[1]])
    ext = (context.pairs[group.external[0]], context.pairs[group.external[1]])
    mid = context.pairs[group.internal[0]]
    known = (
        ext[0].first if ext[0].second == bodies[0] else ext[0].second,
        ext[1].first if ext[1].second == bodies[1] else ext[1].second,
    )
    d_known, d_mid = offsets(ext, mid, bodies, known)
    dyad = DyadSolver(
        group,
        bodies,
        ext,
        mid,
        known,
        d_known,
        d_mid,
        closure,
        context.scale,
        context.size(group),
        gap=discriminant,
    )
    _apart(context, group, dyad)
    best: tuple[float, DyadSolver] | None = None
    for branch in (1.0, -1.0):
        candidate = dataclasses.replace(dyad, branch=branch)
        q = closure(candidate, context.reference(), branch)
        miss = max(
            float(np.abs(wrap(x)))
            if e.kind == "R"
            else float(np.abs(x)) / context.scale
            for x, e in zip(q, ext, strict=True)
        )
        if best is None or miss < best[0]:
            best = (miss, candidate)
    assert best is not None
    miss, dyad = best
    reference = context.reference()
    dyad.assemble(reference, 1)
    if not conditioning(dyad, jacobian(dyad, reference)) >= DEAD_CENTRE:
        dead_centre(group)
    if not miss <= BRANCH_TOLERANCE:
        msg = (
            f"group {group.label}: the reference pose is not an assembled pose of this "
            f"group or sits at its dead centre (closes {miss:.3g} away); expected "
            "every point where it is in one assembled pose"
        )
        raise ModelError(msg)
    return dyad


def _apart(context: CompileContext, group: Group, dyad: DyadSolver) -> None:
    """Refuse a dyad whose two outer revolute joints are one point."""
    if dyad.ext[0].kind != "R" or dyad.ext[1].kind != "R":
        return
    ends = [
        context.origins[k] + np.asarray(d)
        for k, d in zip(dyad.known, dyad.d_known, strict=True)
    ]
    gap = float(np.hypot(*(ends[1] - ends[0])))
    if gap <= APART * context.scale:
        names = " and ".join(p.name for p in dyad.ext)
        msg = (
            f"group {group.label}: its outer joints {names} are {gap:.3g} m apart in "
            f"a mechanism {context.scale:.3g} m across, one point as far as its "
            "coordinates tell, so the dyad does not hold its links; expected them "
            "apart"
        )
        raise ModelError(msg)


def dead_centre(group: Group) -> None:
    """Raise the error of a reference pose at a group's dead centre."""
    msg = (
        f"group {group.label}: the reference pose is at a dead centre of this group, "
        "where its branch is undefined; expected a reference pose away from dead "
        "centres"
    )
    raise ModelError(msg)
