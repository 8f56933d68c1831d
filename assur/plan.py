"""A mechanism compiled for the numerical core: bodies, offsets and group solvers.

Everything that depends only on the mechanism (the decomposition, body-fixed offsets,
assembly branches) is computed here once, so that a sweep costs only its arithmetic.
Body 0 is the frame; the others follow the order of attachment. The core works in
coordinates whose origin is the first driver's pivot in the reference pose (the
plan's ``shift``), so that a mechanism far from the file's origin loses no digits.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._metres import metres
from assur._structure import Group, Topology, decompose
from assur._topology import topology
from assur._vec import Array
from assur.errors import ModelError
from assur.groups import compile_group
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan
from assur.groups._protocol import CompileContext, GroupSolver
from assur.groups.driver import DriverPlan
from assur.model import GROUND, Mechanism, mechanism_of, resolve_point

__all__ = ["Plan", "cached_plan", "compile_plan", "drawn_size", "plan_of"]


@dataclass(frozen=True, slots=True, eq=False)
class Plan:
    """The compiled mechanism.

    Attributes
    ----------
    mechanism : Mechanism
    topology : Topology
        Links and lower pairs, slots replaced by blocks.
    groups : tuple of Group
        The Assur groups in order of attachment.
    bodies : tuple of str
        Link names; index 0 is the frame.
    origins : ndarray (B, 2)
        Each body's origin in the reference pose, m, core coordinates.
    shift : tuple of float
        Where the core's origin lies in the file's coordinates, m.
    angle0 : ndarray (B,)
        Each link's angle in the reference pose, rad (its axis direction, or 0).
    drivers : tuple of DriverPlan
    solvers : tuple of GroupSolver
        In order of attachment.
    pairs : dict of str to PairPlan
    points : tuple of str
        Names of the reported points: joints (moving with their second link), extra
        points and centres of mass (``"L.G"``).
    point_body : tuple of int
        The body each reported point moves with.
    point_offset : tuple of (float, float)
        Its offset from that body's origin in the reference pose, m.
    scale : float
        Size of the mechanism, m (largest distance between two pairs).
    """

    mechanism: Mechanism
    topology: Topology
    groups: tuple[Group, ...]
    bodies: tuple[str, ...]
    origins: Array
    shift: tuple[float, float]
    angle0: Array
    drivers: tuple[DriverPlan, ...]
    solvers: tuple[GroupSolver, ...]
    pairs: dict[str, PairPlan]
    points: tuple[str, ...]
    point_body: tuple[int, ...]
    point_offset: tuple[tuple[float, float], ...]
    scale: float
    index: dict[str, int] = field(default_factory=dict)
    memo: dict[str, Any] = field(default_factory=dict, repr=False)
    """Things derived from the plan on first use (its loads, its column schema)."""

    @property
    def newton(self) -> bool:
        """Whether a group needs Newton's method (and so a continuation)."""
        return any(s.newton for s in self.solvers)

    def body(self, name: str) -> int:
        """Index of the link called ``name``."""
        return self.index[name]

    def offset(self, body: int, at: Any) -> Array:
        """Body-fixed offset of the reference-pose point ``at`` (file coordinates)."""
        core = np.asarray(at, dtype=float) - np.asarray(self.shift)
        return core - self.origins[body]

    def point_of(self, name: str) -> tuple[int, tuple[float, float]]:
        """Body and offset of the reported point ``name``."""
        i = self.points.index(name)
        return self.point_body[i], self.point_offset[i]


def plan_of(mech: Mechanism) -> Plan:
    """Return the plan of ``mech``, compiled once per mechanism value.

    The entry points (:func:`assur.kinematics <assur.analysis.kinematics>`,
    :func:`assur.forces <assur.analysis.forces>`, ...) call this;
    everything downstream receives the plan itself.

    Raises
    ------
    UsageError
        When ``mech`` is not a Mechanism (a file's path, say).
    """
    # checked before the cache hashes it: a dict gave "unhashable type: 'dict'"
    return cached_plan(mechanism_of(mech))


@functools.lru_cache(maxsize=64)
def cached_plan(mech: Mechanism) -> Plan:
    """Return :func:`compile_plan` of ``mech``, kept for the last 64 mechanisms."""
    return compile_plan(mech)


def compile_plan(mech: Mechanism) -> Plan:
    """Compile ``mech`` for the numerical core.

    Raises
    ------
    DecompositionError
        When the mechanism does not split into Assur groups.
    ModelError
        When a group is at a dead centre in the reference pose.
    """
    drivers, groups, topo = decompose(mech)
    names = [GROUND] + [g.links[1] for g in drivers]
    names += [x for g in groups for x in g.links]
    index = {name: i for i, name in enumerate(names)}
    by_name = {p.name: p for p in topo.pairs}
    pair_at = {p.name: np.asarray(p.at, dtype=float) for p in topo.pairs}
    shift = _shift(drivers, pair_at)
    for name in pair_at:
        pair_at[name] = pair_at[name] - shift
    origins = np.zeros((len(names), 2))
    for g in drivers:
        origins[index[g.links[1]]] = pair_at[g.internal[0]]
    for g in groups:
        for link in g.links:
            pair = next(p for p in g.external + g.internal if link in by_name[p].links)
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
            float(p.friction),
            float(p.radius),
        )
    scale = _diameter(np.array(list(pair_at.values())))
    drawn = drawn_size(mech, topo)
    _near_enough(topo, drawn)
    _big_enough(topo, pair_at, scale)
    metres(drawn)
    context = CompileContext(
        tuple(names),
        index,
        pairs,
        origins,
        scale,
        tuple(Motion.fixed(float(x), float(y)) for x, y in origins),
    )
    angle0 = _angles0(mech, index)
    driver_plans = tuple(
        _driver(mech, g, pairs, index, angle0, origins) for g in drivers
    )
    solvers = tuple(compile_group(context, g) for g in groups)
    points, body, offset = _points(mech, pairs, index, origins, shift)
    return Plan(
        mech,
        topo,
        groups,
        tuple(names),
        origins,
        _pt(shift),
        angle0,
        driver_plans,
        solvers,
        pairs,
        points,
        body,
        offset,
        scale,
        index,
    )


FAR = 1e7
"""Farthest a mechanism may lie from the file's origin, in mechanism sizes: its
coordinates then keep nine significant digits of its shape."""


def drawn_size(mech: Mechanism, topo: Topology | None = None) -> float:
    """Return the size of ``mech`` as its file draws it (m): the diameter of its points.

    The size :func:`compile_plan` reads for its warning of lengths in millimetres;
    ``topo``, the mechanism's topology where it is at hand.
    """
    at = _drawn(mech, topology(mech) if topo is None else topo)
    return _diameter(np.array(at))


def _drawn(mech: Mechanism, topo: Topology) -> list[Array]:
    """Every point the file places: joints, centres of mass and named points (m).

    A mechanism whose joints all meet near one point (slide lines through a pivot)
    still has the size its centres and named points give it.
    """
    at = [np.asarray(p.at, dtype=float) for p in topo.pairs]
    for link in mech.links:
        if link.center is not None:
            at.append(resolve_point(mech, link.center, f"links.{link.name}.center"))
    at += [resolve_point(mech, p.at, f"points.{p.name}") for p in mech.points]
    return at


def _near_enough(topo: Topology, scale: float) -> None:
    """Refuse a mechanism so far from the origin that its coordinates lose its shape."""
    far = max((max(abs(p.at[0]), abs(p.at[1])) for p in topo.pairs), default=0.0)
    # every joint at one point (a size of 1e-12) has no shape to lose
    if far > FAR * scale and scale > SIZELESS:
        digits = max(0, int(16 - math.log10(far / scale)))
        msg = (
            f"joints: the mechanism ({scale:.3g} m across) lies {far:.3g} m from the "
            f"origin, where its coordinates keep about {digits} significant digits of "
            f"its shape; expected it within {FAR:g} times its size of the origin "
            "(move the origin near it)"
        )
        raise ModelError(msg)


SMALL = 1e-9
"""Smallest link, as a fraction of the mechanism's size: its coordinates then keep
seven significant digits of its length."""


def _big_enough(topo: Topology, pair_at: dict[str, Array], scale: float) -> None:
    """Refuse a link so small beside the mechanism that its coordinates lose it."""
    points: dict[str, list[Array]] = {}
    # only pins fix a link's size: a slide line may pass as near a pin as it likes
    for pair in topo.pairs:
        if pair.kind != "R":
            continue
        for link in pair.links:
            points.setdefault(link, []).append(pair_at[pair.name])
    for link, at in points.items():
        if link == GROUND or len(at) < 2:
            continue
        size = _diameter(np.array(at))
        # a link whose joints all stand at one point (a slider's pin) has no length
        if 1e-12 < size < SMALL * scale:
            msg = (
                f"links.{link}: its joints are {size:.3g} m apart in a mechanism "
                f"{scale:.3g} m across, where coordinates keep about "
                f"{max(0, int(16 + math.log10(size / scale)))} significant digits of "
                f"it; expected links at least {SMALL:g} times the mechanism's size"
            )
            raise ModelError(msg)


def _shift(drivers: tuple[Group, ...], pair_at: dict[str, Array]) -> Array:
    """Return the core's origin in file coordinates: the first driver's pivot."""
    if not drivers:
        return np.zeros(2)
    return np.array(pair_at[drivers[0].internal[0]], dtype=float)


FEW = 64
"""Points compared pair by pair without looking for their convex hull first."""


SIZELESS = 1e-12
"""The size of a mechanism whose joints all lie at one point (m): its plan's floor."""


def _diameter(points: Array) -> float:
    """Largest distance between two of ``points`` (m), at least :data:`SIZELESS`.

    The farthest pair lies on the convex hull (Andrew's monotone chain), so of many
    points only the hull's few corners are compared with each other; a few points
    are compared directly (finding their hull costs more).
    """
    corners = np.asarray(points, dtype=float).reshape(-1, 2)
    if len(corners) > FEW:
        corners = np.unique(corners, axis=0)
        corners = _hull(corners) if len(corners) > 3 else corners
    gap = corners[:, None, :] - corners[None, :, :]
    return max(SIZELESS, float(np.sqrt((gap * gap).sum(axis=-1)).max()))


def _hull(points: Array) -> Array:
    """Return the corners of the convex hull of sorted, distinct ``points``."""

    def half(ordered: Array) -> list[Array]:
        chain: list[Array] = []
        for p in ordered:
            while len(chain) >= 2:
                a, b = chain[-2], chain[-1]
                if (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) > 0:
                    break
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(points), half(points[::-1])
    return np.array(lower[:-1] + upper[:-1])


def _pt(v: Any) -> tuple[float, float]:
    """Return a 2-vector as a tuple of floats (cheap constants in the kernels)."""
    return (float(v[0]), float(v[1]))


def _angles0(mech: Mechanism, index: dict[str, int]) -> Array:
    """Return each link's angle in the reference pose (rad, in (-pi, pi])."""
    angle0 = np.zeros(len(index))
    for link in mech.links:
        if link.axis is not None:
            a = resolve_point(mech, link.axis[0])
            b = resolve_point(mech, link.axis[1])
            angle = math.atan2(b[1] - a[1], b[0] - a[0])
            # in (-180, 180] deg: atan2 gives -180 for a direction whose y is -0.0
            angle0[index[link.name]] = math.pi if angle == -math.pi else angle
    return angle0


def _driver(
    mech: Mechanism,
    group: Group,
    pairs: dict[str, PairPlan],
    index: dict[str, int],
    angle0: Array,
    origins: Array,
) -> DriverPlan:
    driver = next(d for d in mech.drivers if d.joint == group.internal[0])
    pair = pairs[driver.joint]
    body = index[group.links[1]]
    reference = float(angle0[body]) if pair.kind == "R" else 0.0
    return DriverPlan(
        pair,
        body,
        float(driver.omega),
        float(driver.epsilon),
        float(angle0[body]),
        _pt(origins[body]),
        reference,
    )


def _points(
    mech: Mechanism,
    pairs: dict[str, PairPlan],
    index: dict[str, int],
    origins: Array,
    shift: Array,
) -> tuple[tuple[str, ...], tuple[int, ...], tuple[tuple[float, float], ...]]:
    """Names, bodies and offsets of the reported points, in table order."""
    names, body, offset = [], [], []

    def add(name: str, b: int, at: Any) -> None:
        names.append(name)
        body.append(b)
        offset.append(_pt(np.asarray(at, dtype=float) - shift - origins[b]))

    for pair in pairs.values():
        if not pair.virtual:
            names.append(pair.name)
            body.append(pair.second)
            offset.append(pair.d_second)
    for point in mech.points:
        add(point.name, index[point.link], resolve_point(mech, point.at))
    for link in mech.links:
        if link.center is not None:
            add(f"{link.name}.G", index[link.name], resolve_point(mech, link.center))
    return tuple(names), tuple(body), tuple(offset)
