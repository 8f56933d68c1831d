"""A mechanism compiled for the numerical core: bodies, offsets and group solvers.

Everything that depends only on the mechanism (the decomposition, body-fixed offsets,
assembly branches) is computed here once and memoised, so that a sweep costs only its
arithmetic. Body 0 is the frame; the others follow the order of attachment.
"""

from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._structure import Group, Topology, decompose
from assur._vec import Array, wrap
from assur.errors import ModelError
from assur.groups import DYADS, general
from assur.groups._dyad import DyadPlan
from assur.groups._dyad import conditioning as _conditioning
from assur.groups._dyad import jacobian as _jacobian
from assur.groups._dyad import set_pose as _set_pose
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan
from assur.groups.driver import DriverPlan
from assur.groups.general import GeneralPlan
from assur.model import GROUND, Mechanism, resolve_point

__all__ = ["Plan", "compile_plan"]

DEAD_CENTRE = 1e-6
"""Smallest sine of a dyad's transmission angle accepted in the reference pose."""
BRANCH_TOLERANCE = 1e-7
"""Largest coordinate (rad, or m relative to the mechanism's size) that the chosen
branch may miss the reference pose by."""


@dataclass(frozen=True, slots=True, eq=False)
class Plan:
    """The compiled mechanism.

    Attributes
    ----------
    bodies : tuple of str
        Link names; index 0 is the frame.
    angle0 : ndarray (B,)
        Each link's angle in the reference pose, rad (its axis direction, or 0).
    drivers : tuple of DriverPlan
    solvers : tuple of DyadPlan or GeneralPlan
        In order of attachment.
    pairs : dict of str to PairPlan
    points : tuple of str
        Names of the reported points: joints (moving with their second link), extra
        points and centres of mass (``"L.G"``).
    point_body : ndarray of int (P,)
    point_offset : ndarray (P, 2)
    point_sets : tuple
        The distinct ``(body, offset)`` among the reported points (a joint, a centre
        of mass and a load point often coincide): the slots of a state's points.
    point_index : dict of str to int
        The slot of every reported point, by name.
    scale : float
        Size of the mechanism, m (largest distance between two pairs).
    """

    mechanism: Mechanism
    topology: Topology
    groups: tuple[Group, ...]
    bodies: tuple[str, ...]
    origins: Array
    angle0: Array
    drivers: tuple[DriverPlan, ...]
    solvers: tuple[Any, ...]
    pairs: dict[str, PairPlan]
    points: tuple[str, ...]
    point_body: Array
    point_offset: Array
    scale: float
    point_sets: tuple[tuple[int, tuple[float, float]], ...] = ()
    point_index: dict[str, int] = dataclasses.field(default_factory=dict)

    @property
    def newton(self) -> bool:
        """Whether a group needs Newton's method (and so a continuation)."""
        return any(isinstance(s, GeneralPlan) for s in self.solvers)

    def body(self, name: str) -> int:
        """Index of the link called ``name``."""
        return self.bodies.index(name)

    def offset(self, body: int, at: Array) -> Array:
        """Body-fixed offset of the reference-pose point ``at`` on ``body``."""
        return np.asarray(at, dtype=float) - self.origins[body]


@functools.lru_cache(maxsize=128)
def compile_plan(mech: Mechanism) -> Plan:
    """Compile ``mech`` for the numerical core (memoised per mechanism value).

    Raises
    ------
    DecompositionError
        When the mechanism does not split into Assur groups.
    ModelError
        When a group is at a dead centre in the reference pose.
    """
    drivers, groups, topo = decompose(mech)
    names = (
        [GROUND] + [g.links[1] for g in drivers] + [x for g in groups for x in g.links]
    )
    index = {name: i for i, name in enumerate(names)}
    pair_at = {p.name: np.asarray(p.at) for p in topo.pairs}
    origins = np.zeros((len(names), 2))
    for g in drivers:
        origins[index[g.links[1]]] = pair_at[g.internal[0]]
    for g in groups:
        for link in g.links:
            pair = next(
                p for p in g.external + g.internal if link in _pair(topo, p).links
            )
            origins[index[link]] = pair_at[pair]
    pairs = {}
    for p in topo.pairs:
        i, j = index[p.links[0]], index[p.links[1]]
        pairs[p.name] = PairPlan(
            p.name,
            p.kind,
            i,
            j,
            _pt(pair_at[p.name] - origins[i]),
            _pt(pair_at[p.name] - origins[j]),
            None if p.axis is None else _pt(p.axis),
            p.virtual,
        )
    scale = max(
        [float(np.hypot(*(a - b))) for a in pair_at.values() for b in pair_at.values()]
        + [1e-12]
    )
    angle0 = _angles0(mech, names)
    plan = Plan(
        mech,
        topo,
        groups,
        tuple(names),
        origins,
        angle0,
        (),
        (),
        pairs,
        (),
        np.zeros(0, dtype=int),
        np.zeros((0, 2)),
        scale,
    )
    driver_plans = tuple(_driver(plan, mech, g, index) for g in drivers)
    solvers = tuple(_solver(plan, g, index) for g in groups)
    points, body, offset = _points(mech, plan, index)
    offsets = tuple(_pt(d) for d in offset)
    slots: dict[tuple[int, tuple[float, float]], int] = {}
    for b, d in zip(body.tolist(), offsets, strict=True):
        slots.setdefault((b, d), len(slots))
    return dataclasses.replace(
        plan,
        drivers=driver_plans,
        solvers=solvers,
        points=points,
        point_body=body,
        point_offset=offset,
        point_sets=tuple(slots),
        point_index={
            name: slots[(b, d)]
            for name, b, d in zip(points, body.tolist(), offsets, strict=True)
        },
    )


def _pt(v: Any) -> tuple[float, float]:
    """Return a 2-vector as a tuple of floats (cheap constants in the kernels)."""
    return (float(v[0]), float(v[1]))


def _pair(topo: Topology, name: str) -> Any:
    return next(p for p in topo.pairs if p.name == name)


def _angles0(mech: Mechanism, names: list[str]) -> Array:
    angle0 = np.zeros(len(names))
    for link in mech.links:
        if link.axis is not None:
            a = resolve_point(mech, link.axis[0])
            b = resolve_point(mech, link.axis[1])
            angle0[names.index(link.name)] = math.atan2(b[1] - a[1], b[0] - a[0])
    return angle0


def _driver(
    plan: Plan, mech: Mechanism, group: Group, index: dict[str, int]
) -> DriverPlan:
    driver = next(d for d in mech.drivers if d.joint == group.internal[0])
    pair = plan.pairs[driver.joint]
    body = index[group.links[1]]
    reference = float(plan.angle0[body]) if pair.kind == "R" else 0.0
    return DriverPlan(
        pair,
        body,
        float(driver.omega),
        float(driver.epsilon),
        float(plan.angle0[body]),
        _pt(plan.origins[body]),
        reference,
    )


def _solver(plan: Plan, group: Group, index: dict[str, int]) -> Any:
    bodies = tuple(index[x] for x in group.links)
    if group.group_class == 2:
        return _dyad(plan, group, bodies)
    solver = GeneralPlan(
        group.kind,
        group.label,
        bodies,
        tuple(_pt(plan.origins[b]) for b in bodies),
        tuple(plan.pairs[p] for p in group.internal + group.external),
        plan.scale,
    )
    reference = [Motion.fixed(*o) for o in plan.origins]
    jac = general.jacobian(solver, reference, 1)
    if not general.conditioning(solver, jac)[0] >= DEAD_CENTRE:
        _dead_centre(group)
    return solver


def _dead_centre(group: Group) -> None:
    """Raise the error of a reference pose at a group's dead centre."""
    msg = (
        f"group {group.label}: the reference pose is at a dead centre of this group, "
        "where its branch is undefined; expected a reference pose away from dead "
        "centres"
    )
    raise ModelError(msg)


def _dyad(plan: Plan, group: Group, bodies: tuple[int, int]) -> DyadPlan:
    ext = tuple(plan.pairs[p] for p in group.external)
    mid = plan.pairs[group.internal[0]]
    known = tuple(
        e.first if e.second == b else e.second
        for e, b in zip(ext, bodies, strict=False)
    )
    d_known = tuple(
        e.d_first if e.first == k else e.d_second
        for e, k in zip(ext, known, strict=False)
    )
    d_mid = tuple(mid.d_first if mid.first == b else mid.d_second for b in bodies)
    dyad = DyadPlan(group.kind, group.label, bodies, ext, mid, known, d_known, d_mid)
    module = DYADS[group.kind]
    reference = [Motion.fixed(*o) for o in plan.origins]
    best = None
    for branch in (1.0, -1.0):
        candidate = dataclasses.replace(dyad, branch=branch)
        q = module.assemble(candidate, list(reference))
        miss = [
            float(np.abs(wrap(x))) if e.kind == "R" else float(np.abs(x)) / plan.scale
            for x, e in zip(q, ext, strict=False)
        ]
        if best is None or max(miss) < best[0]:
            best = (max(miss), candidate, sorted(miss))
    assert best is not None
    dyad = best[1]
    bodies = list(reference)
    _set_pose(dyad, bodies, *module.assemble(dyad, bodies))
    if not _conditioning(dyad, _jacobian(dyad, bodies), plan.scale) >= DEAD_CENTRE:
        _dead_centre(group)
    if not best[0] <= BRANCH_TOLERANCE:
        msg = (
            f"group {group.label}: the reference pose is not an assembled pose of this "
            f"group or sits at its dead centre (closes {best[0]:.3g} away); expected "
            "every point where it is in one assembled pose"
        )
        raise ModelError(msg)
    return best[1]


def _points(
    mech: Mechanism, plan: Plan, index: dict[str, int]
) -> tuple[tuple[str, ...], Array, Array]:
    names, body, offset = [], [], []
    for pair in plan.pairs.values():
        if not pair.virtual:
            names.append(pair.name)
            body.append(pair.second)
            offset.append(pair.d_second)
    for point in mech.points:
        b = index[point.link]
        names.append(point.name)
        body.append(b)
        offset.append(plan.offset(b, resolve_point(mech, point.at)))
    for link in mech.links:
        if link.center is not None:
            b = index[link.name]
            names.append(f"{link.name}.G")
            body.append(b)
            offset.append(plan.offset(b, resolve_point(mech, link.center)))
    return tuple(names), np.asarray(body, dtype=int), np.asarray(offset).reshape(-1, 2)
