"""Reverse pass: inertia loads, joint reactions group by group, balancing loads.

Every link gets its d'Alembert loads (``-m a_G`` at the centre of mass and ``-J_G
alpha``), gravity and external loads. The groups are then solved in the reverse order
of attachment, each statically determinate and receiving the reactions of the groups
solved before it; the driving links come last and give the balancing torque (or force).
Each step returns a record (an ``Equilibrium`` per group, a ``Balance`` per driver).
The principle of virtual power gives the same balancing loads independently
(:func:`virtual_power`), and every link's equilibrium can be checked again from the
reactions (:func:`residual`).

Everything here reads the links' motions only; they come from the forward pass or are
rebuilt from a frozen :class:`~assur._kinematics.KinematicState`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._crosscheck import residual, virtual_power
from assur._friction import friction_wrench, solve_group
from assur._kinematics import KinematicState
from assur._loads import LoadPlan, table_values
from assur._quiet import quiet
from assur._still import Still, rate, still
from assur._vec import Array, Leaf, Mask, add, cross, dot, full, mul, sub, take_rows
from assur.groups._motion import Motion, direction, point, rotated
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Equilibrium, Wrench
from assur.groups.driver import Balance, DriverPlan, balance
from assur.model import LoadTable
from assur.plan import Plan

FAR_FORCE = 1e12
"""A prismatic pair's normal force acting farther than this many mechanism sizes
from its point is a pure couple: its offset is NaN."""
NO_FORCE = 1e-12
"""A prismatic pair's normal force below this fraction of the largest reaction at the
same position is no force: rounding is all it holds."""

__all__ = [
    "Applied",
    "ForceState",
    "Reverse",
    "applied_loads",
    "has_friction",
    "offset",
    "residual",
    "reverse",
    "solve",
    "virtual_power",
    "with_friction",
]


@dataclass(frozen=True, slots=True)
class Applied:
    """Every link's applied loads over a batch.

    ``wrenches`` holds per body ``[F_x, F_y, tau]`` (N, N m about the core's origin):
    inertia loads, gravity and external loads. ``inertia`` holds per body the inertia
    force ``(F_x, F_y)`` (N) and torque (N m), or None for a massless body.
    """

    wrenches: tuple[Wrench, ...]
    inertia: tuple[tuple[Any, Any, Any] | None, ...]


@dataclass(frozen=True, slots=True)
class Reverse:
    """The records of one reverse pass: each group's equilibrium and each driver's.

    ``groups`` are in the order they were solved (the reverse of attachment);
    ``frame`` is the resultant load on the frame (N, N m about the core's origin).
    """

    groups: tuple[Equilibrium, ...]
    drivers: tuple[Balance, ...]
    frame: Wrench
    friction: dict[str, Leaf] = field(default_factory=dict)
    """The friction of each pair with friction: the couple on a revolute pair's
    second link (N m), the force along a prismatic pair's slide line (N)."""
    locked: tuple[tuple[str, Mask], ...] = ()
    """The groups, by label, with the positions where their friction locks them."""
    ideal: tuple[Leaf, ...] = ()
    """Each driver's balancing load without friction (with friction only)."""


@dataclass(frozen=True, slots=True)
class ForceState:
    """Loads and reactions over a sweep, as leaves (an array, or a constant).

    Attributes
    ----------
    inertia : tuple
        Per body, ``(F_x, F_y, M)``: the inertia force ``-m a_G`` (N) and torque
        ``-J_G alpha`` (N m); None for a massless body.
    reactions : dict of str to tuple
        Per pair, ``(F_x, F_y, M)``: the force exerted by its first link on its second
        (N) and, for a prismatic pair, the couple about the pair's point moving with
        the second link (N m; 0 for a revolute pair).
    balancing : tuple
        Balancing torque (N m) or force (N) per driver.
    shaking : tuple
        ``(F_x, F_y, M)``: resultant force (N) and moment about the file's origin
        (N m) of all loads on the frame.
    friction : dict of str to leaf
        Per pair with friction: the friction couple on a revolute pair's second link
        (N m) or the friction force along a prismatic pair's slide line (N), which
        the pair's reaction force includes.
    ideal : tuple
        Per driver, the balancing load the same mechanism needs without friction.
    """

    inertia: tuple[tuple[Leaf, Leaf, Leaf] | None, ...]
    reactions: dict[str, tuple[Leaf, Leaf, Leaf]]
    balancing: tuple[Leaf, ...]
    shaking: tuple[Leaf, Leaf, Leaf]
    friction: dict[str, Leaf] = field(default_factory=dict)
    ideal: tuple[Leaf, ...] = ()

    def rows(self, rows: Any) -> ForceState:
        """Return the force state at ``rows`` (a slice gives views, a mask copies)."""
        return ForceState(*take_rows(self.fields(), rows))

    def reaction(self, name: str, n: int) -> tuple[Array, Array]:
        """Return pair ``name``'s force (n, 2), N, and couple (n,), N m, as arrays."""
        fx, fy, couple = self.reactions[name]
        return np.column_stack((full(fx, n), full(fy, n))), full(couple, n)

    def inertia_load(self, body: int, n: int) -> tuple[Array, Array]:
        """Return a body's inertia force (n, 2), N, and torque (n,), N m, as arrays."""
        values = self.inertia[body] or (0.0, 0.0, 0.0)
        return np.column_stack((full(values[0], n), full(values[1], n))), full(
            values[2], n
        )

    def fields(self) -> tuple[Any, ...]:
        """Return the fields as a tuple (a tree of leaves)."""
        return (
            self.inertia,
            self.reactions,
            self.balancing,
            self.shaking,
            self.friction,
            self.ideal,
        )


def applied_loads(
    plan: Plan,
    loads: LoadPlan,
    bodies: list[Motion],
    state: KinematicState,
    known: tuple[tuple[Any, Any, Any] | None, ...] | None = None,
) -> Applied:
    """Return every link's applied loads: inertia, gravity and external loads.

    ``state`` gives the driver positions and slides of the batch (for tabulated
    loads); the motions give everything else. ``known`` holds the inertia loads
    already computed for these motions (a force state's ``inertia``), which are then
    taken as they are.
    """
    count = len(plan.bodies)
    wrenches: list[Wrench] = [[0.0, 0.0, 0.0] for _ in range(count)]
    inertia: list[tuple[Any, Any, Any] | None] = [None] * count
    gx, gy = loads.gravity
    for b, mass, moment in loads.bodies():
        m = bodies[b]
        px, py = point(m, loads.center[b], 0)
        given = None if known is None else known[b]
        if given is None:
            ax, ay = point(m, loads.center[b], 2)
            fx, fy = mul(-mass, ax), mul(-mass, ay)
            torque = mul(-moment, m.phi[2])
        else:
            fx, fy, torque = given
        inertia[b] = (fx, fy, torque)
        fx, fy = add(fx, mass * gx), add(fy, mass * gy)
        wrenches[b] = [fx, fy, add(cross(px, py, fx, fy), torque)]
    slides: dict[str, Array] | None = None
    for b, offset_, value, entry in loads.forces:
        px, py = point(bodies[b], offset_, 0)
        if not isinstance(value, LoadTable):
            fx, fy = value  # a constant, or one per row of stacked variants
        else:
            slides = slides or {name: s[0] for name, s in state.slide.items()}
            fx, fy = table_values(value, plan, state.drive, slides, entry)
        w = wrenches[b]
        wrenches[b] = [add(w[0], fx), add(w[1], fy), add(w[2], cross(px, py, fx, fy))]
    for b, value, entry in loads.torques:
        t: Any
        if not isinstance(value, LoadTable):
            t = value  # a constant, or one per row of stacked variants
        else:
            slides = slides or {name: s[0] for name, s in state.slide.items()}
            t = table_values(value, plan, state.drive, slides, entry)[0]
        w = wrenches[b]
        wrenches[b] = [w[0], w[1], add(w[2], t)]
    return Applied(tuple(wrenches), tuple(inertia))


def reverse(
    plan: Plan, bodies: list[Motion], applied: Applied, friction: bool = True
) -> Reverse:
    """Solve the groups in the reverse order of attachment, then the drivers.

    Each group receives its links' applied loads plus the reactions of the groups
    solved before it; what it passes to the links it hangs on is added to theirs.
    With friction in the pairs (and ``friction``) each group is solved by the
    iteration of ``assur._friction``, and the balancing loads overcome the
    driving pairs' friction too.
    """
    rubbing = friction and has_friction(plan)
    loads: list[Wrench] = list(applied.wrenches)
    n = _size(plan, bodies) if rubbing else 1  # for friction's iteration alone
    groups, values, locked = [], {}, []
    rest = still(bodies, plan.scale) if rubbing else None
    for solver in reversed(plan.solvers):
        found = solve_group(solver, bodies, loads, n, rest) if rest else None
        if found is None:
            record = solver.equilibrium(bodies, loads)
            passed = list(record.passed)
        else:
            record = found.record
            passed = list(record.passed) + _shares(record, found.wrenches)
            values.update(found.values)
            if found.locked is not None:
                locked.append((solver.label, found.locked))
        for body, wrench in passed:
            loads[body] = [add(a, b) for a, b in zip(loads[body], wrench, strict=True)]
        groups.append(record)
    drivers = []
    for d in plan.drivers:
        record_ = balance(d, bodies, loads)
        if rest and d.pair.friction > 0.0:
            record_ = _rubbing(d, bodies, record_, values, rest)
        loads[0] = [add(a, b) for a, b in zip(loads[0], record_.load, strict=True)]
        drivers.append(record_)
    ideal: tuple[Leaf, ...] = ()
    if rubbing:
        ideal = tuple(
            b.balancing for b in reverse(plan, bodies, applied, False).drivers
        )
    return Reverse(
        tuple(groups), tuple(drivers), loads[0], values, tuple(locked), ideal
    )


def with_friction(
    plan: Plan,
    bodies: list[Motion],
    applied: Applied,
    friction: dict[str, Leaf],
    kinds: str = "RP",
) -> Applied:
    """Return the applied loads with the pairs' friction (of ``kinds``) added.

    The friction acts on a pair's second link and, opposite, on its first: for the
    principle of virtual power, friction is a load like any other.
    """
    wrenches = list(applied.wrenches)
    for name, value in friction.items():
        pair = plan.pairs[name]
        if pair.kind not in kinds:
            continue
        if pair.kind == "R":
            wrench: Wrench = [0.0, 0.0, value]
        else:
            assert pair.axis is not None
            ex, ey = direction(bodies[pair.first], pair.axis, 0)
            fx, fy = mul(value, ex), mul(value, ey)
            qx, qy = point(bodies[pair.second], pair.d_second, 0)
            wrench = [fx, fy, cross(qx, qy, fx, fy)]
        second, first = wrenches[pair.second], wrenches[pair.first]
        wrenches[pair.second] = [add(a, b) for a, b in zip(second, wrench, strict=True)]
        wrenches[pair.first] = [sub(a, b) for a, b in zip(first, wrench, strict=True)]
    return Applied(tuple(wrenches), applied.inertia)


def has_friction(plan: Plan) -> bool:
    """Whether some pair of ``plan`` has friction (looked at once per plan)."""
    found = plan.memo.get("friction")
    if found is None:
        found = plan.memo["friction"] = any(
            p.friction > 0.0 for p in plan.pairs.values()
        )
    return bool(found)


def _size(plan: Plan, bodies: list[Motion]) -> int:
    """Return the number of positions the motions hold."""
    sizes = [
        v.size
        for m in bodies
        for v in (m.phi[0], m.ox[0], m.oy[0])
        if v.__class__ is np.ndarray
    ]
    return max(sizes, default=1)


def _shares(record: Equilibrium, wrenches: dict[str, Wrench]) -> list[Any]:
    """Return the known links' share of the friction of a group's external pairs."""
    inside = set(record.bodies)
    out = []
    for pair in record.pairs:
        wrench = wrenches.get(pair.name)
        if wrench is None:
            continue
        if pair.second not in inside:
            out.append((pair.second, wrench))
        elif pair.first not in inside:
            out.append((pair.first, [mul(-1.0, w) for w in wrench]))
    return out


def _rubbing(
    d: DriverPlan,
    bodies: list[Motion],
    record: Balance,
    values: dict[str, Leaf],
    rest: Still,
) -> Balance:
    """Return a driver's balance with its own pair's friction overcome too."""
    value, wrench = friction_wrench(
        d.pair, bodies, record.reaction, rate(d.pair, bodies, rest)
    )
    values[d.pair.name] = value
    # the friction on the input link, which the balancing load must also hold
    sign = d.sign
    if d.kind == "R":
        balancing = sub(record.balancing, mul(sign, wrench[2]))
    else:
        balancing = sub(record.balancing, mul(sign, value))
    return Balance(record.label, record.body, record.load, record.reaction, balancing)


def solve(
    plan: Plan, loads: LoadPlan, bodies: list[Motion], state: KinematicState
) -> tuple[ForceState, Reverse]:
    """Solve the kinetostatics of a batch whose motions are ``bodies``.

    ``state`` is the batch's kinematic state (for its driver positions and slides).
    Returns the force state (its arrays are the records' own) and the records.
    """
    applied = applied_loads(plan, loads, bodies, state)
    result = reverse(plan, bodies, applied)
    reactions: dict[str, tuple[Leaf, Leaf, Leaf]] = {}
    for record in result.groups:
        for name, r in record.reactions.items():
            reactions[name] = (r.fx, r.fy, r.couple)
    for d, balance_ in zip(plan.drivers, result.drivers, strict=True):
        r = balance_.reaction
        reactions[d.pair.name] = (r.fx, r.fy, r.couple)
    for name, value in result.friction.items():
        pair = plan.pairs[name]
        if pair.kind == "P":
            # a prismatic pair's friction force is part of its reaction force
            assert pair.axis is not None
            ex, ey = direction(bodies[pair.first], pair.axis, 0)
            fx, fy, couple = reactions[name]
            reactions[name] = (add(fx, mul(value, ex)), add(fy, mul(value, ey)), couple)
    fx, fy, tau = result.frame
    sx, sy = plan.shift
    if sx or sy:
        tau = tau + (sx * fy - sy * fx)
    forces = ForceState(
        applied.inertia,
        {name: reactions[name] for name in plan.pairs},
        tuple(b.balancing for b in result.drivers),
        (fx, fy, tau),
        {name: result.friction[name] for name in plan.pairs if name in result.friction},
        result.ideal,
    )
    return forces, result


def offset(
    pair: PairPlan,
    bodies: list[Motion],
    fx: Any,
    fy: Any,
    couple: Any,
    scale: Any,
    size: float = 1.0,
) -> Array:
    """Where a prismatic pair's normal force acts: distance along the axis (m).

    The couple about the pair's point moves the resultant normal force ``N`` by
    ``M / N`` along the slide line. NaN where there is no normal force: where ``|N|``
    is below ``NO_FORCE`` times ``scale``, the largest reaction of the mechanism
    at that position (N), as rounding leaves it; and where the force would act more
    than ``FAR_FORCE`` times the mechanism's ``size`` (m) away, a pure couple.
    """
    nx, ny = rotated(bodies[pair.first], pair.normal)
    normal = np.asarray(dot((fx, fy), (nx, ny)), dtype=float)
    couple = np.asarray(couple, dtype=float)
    with quiet():
        none = ~(np.abs(normal) > NO_FORCE * np.asarray(scale))
        none |= ~(np.abs(couple) <= FAR_FORCE * size * np.abs(normal))
        return np.where(none, np.nan, couple / np.where(none, 1.0, normal))
