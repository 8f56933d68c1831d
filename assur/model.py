"""The mechanism model: links, joints, drivers, loads and extra points.

A :class:`Mechanism` is an immutable value. Every point is given where it lies in the
reference pose, an assembled pose of the mechanism; lengths, body-fixed offsets and
the assembly branch of every group are derived from that pose by later stages.
Validation happens here, once, so the numerical core can trust its input.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._text import suggest
from assur.errors import ModelError

__all__ = [
    "GROUND",
    "Driver",
    "Joint",
    "Link",
    "Load",
    "LoadTable",
    "Mechanism",
    "Point",
    "Toward",
    "point_links",
    "resolve_point",
]

GROUND = "ground"
"""Name of the frame, the fixed link every mechanism has."""

JOINT_KINDS = ("revolute", "prismatic", "slot")
RESERVED = ("~", ".", ",")
RESERVED_NAMES = ("angle", "driver", "shaking", "residual")
"""Names the tables use for their own columns."""

Vec2 = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Toward:
    """A point at ``distance`` from point ``start`` in the direction of ``toward``.

    Parameters
    ----------
    start, toward : str
        Names of two distinct points (joints or extra points).
    distance : float
        Distance from ``start``, m (negative goes away from ``toward``).
    """

    start: str
    toward: str
    distance: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "distance", _plain(self.distance))


PointSpec = Vec2 | str | Toward
"""A point of the reference pose: coordinates (m), a point's name, or a Toward."""


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link.

    Parameters
    ----------
    name : str
        Identifier chosen by the user; ``"ground"`` is reserved for the frame.
    axis : tuple of str, optional
        Two points of the link; the link's angle is the direction from the first to
        the second. Without an axis the angle is the rotation from the reference pose.
    mass : float, optional
        Mass, kg. A link without mass is massless.
    center : PointSpec, optional
        Centre of mass in the reference pose.
    inertia : float, optional
        Moment of inertia about the centre of mass, kg m^2.
    """

    name: str
    axis: tuple[str, str] | None = None
    mass: float | None = None
    center: PointSpec | None = None
    inertia: float | None = None

    def __post_init__(self) -> None:
        _tuples(self, "axis", "center")


@dataclass(frozen=True, slots=True)
class Joint:
    """A lower pair between two links, or a pin-in-slot (``"slot"``).

    Parameters
    ----------
    name : str
        Identifier; the joint's name is also a point of both links.
    kind : {"revolute", "prismatic", "slot"}
        ``"prismatic"``: the slide line is fixed in the first link and the joint's
        point moves with the second. ``"slot"``: a pin of the second link sliding in a
        straight slot of the first (a higher pair, replaced for the structure by a
        block with a revolute and a prismatic pair).
    links : tuple of str
        The two links joined, first and second.
    at : PointSpec
        Position in the reference pose, m.
    axis : tuple of float, optional
        Direction of the slide line in the reference pose (prismatic and slot only).
    """

    name: str
    kind: str
    links: tuple[str, str]
    at: PointSpec
    axis: Vec2 | None = None

    def __post_init__(self) -> None:
        _tuples(self, "links", "at", "axis")


@dataclass(frozen=True, slots=True)
class Driver:
    """A joint whose relative motion is prescribed.

    Parameters
    ----------
    joint : str
        A revolute or prismatic joint with the frame.
    omega : float
        Speed at every analysed position, rad/s (m/s for a prismatic joint); its sign
        gives the direction of rotation.
    epsilon : float
        Acceleration at every analysed position, rad/s^2 (m/s^2).
    """

    joint: str
    omega: float
    epsilon: float = 0.0


@dataclass(frozen=True, slots=True)
class LoadTable:
    """A load tabulated against a position, interpolated linearly.

    Parameters
    ----------
    over : str
        ``"driver"`` (the first driver's position, deg or m) or the name of a
        prismatic joint (its slide, m).
    table : tuple of float
        Strictly increasing positions.
    values : tuple of tuple of float
        One sequence per component: ``(x, y)`` for a force (N), ``(torque,)`` for a
        torque (N m).
    """

    over: str
    table: tuple[float, ...]
    values: tuple[tuple[float, ...], ...]

    def __post_init__(self) -> None:
        _tuples(self, "table")
        object.__setattr__(self, "values", tuple(_plain(v) for v in self.values))


@dataclass(frozen=True, slots=True)
class Load:
    """An external force at a point of a link and/or a torque on the link.

    Parameters
    ----------
    link : str
        The loaded link.
    at : PointSpec, optional
        Point of application of the force (required with a force).
    force : tuple of float or LoadTable, optional
        Force, N, in the fixed frame.
    torque : float or LoadTable, optional
        Torque, N m, counter-clockwise positive.
    """

    link: str
    at: PointSpec | None = None
    force: Vec2 | LoadTable | None = None
    torque: float | LoadTable | None = None

    def __post_init__(self) -> None:
        _tuples(self, "at", "force")


@dataclass(frozen=True, slots=True)
class Point:
    """An extra point of a link to report (a coupler point, say)."""

    name: str
    link: str
    at: PointSpec

    def __post_init__(self) -> None:
        _tuples(self, "at")


@dataclass(frozen=True, slots=True)
class Mechanism:
    """A planar mechanism in its reference pose.

    Parameters
    ----------
    links : tuple of Link
        The moving links; the frame ``"ground"`` is implicit.
    joints : tuple of Joint
    drivers : tuple of Driver
    name, description : str
    gravity : tuple of float, optional
        Gravitational acceleration vector, m/s^2, e.g. ``(0.0, -9.81)``.
    loads : tuple of Load
    points : tuple of Point
        Extra points to report.

    Raises
    ------
    ModelError
        When a reference is unknown, a name repeats, or a value is out of range.

    Examples
    --------
    >>> from assur import catalog
    >>> mech = catalog.four_bar()
    >>> [link.name for link in mech.links]
    ['crank', 'coupler', 'rocker']
    """

    links: tuple[Link, ...]
    joints: tuple[Joint, ...]
    drivers: tuple[Driver, ...]
    name: str = ""
    description: str = ""
    gravity: Vec2 | None = None
    loads: tuple[Load, ...] = ()
    points: tuple[Point, ...] = field(default=())
    _hash: int | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for attr in ("links", "joints", "drivers", "loads", "points"):
            object.__setattr__(self, attr, tuple(getattr(self, attr)))
        _tuples(self, "gravity")
        _validate(self)

    def __hash__(self) -> int:
        # a mechanism keys the memoised plans of every sweep: hash its fields once
        if self._hash is None:
            value = hash(
                (
                    self.links,
                    self.joints,
                    self.drivers,
                    self.name,
                    self.description,
                    self.gravity,
                    self.loads,
                    self.points,
                )
            )
            object.__setattr__(self, "_hash", value)
        return self._hash  # type: ignore[return-value]

    def link(self, name: str) -> Link:
        """Return the link called ``name``."""
        for link in self.links:
            if link.name == name:
                return link
        msg = f"unknown link {name!r}"
        raise KeyError(msg)

    def joint(self, name: str) -> Joint:
        """Return the joint called ``name``."""
        for joint in self.joints:
            if joint.name == name:
                return joint
        msg = f"unknown joint {name!r}"
        raise KeyError(msg)


def _plain(value: Any) -> Any:
    """Return lists and arrays as tuples, numpy numbers as Python's (hashable)."""
    if isinstance(value, np.ndarray | list | tuple):
        return tuple(_plain(v) for v in value)
    if isinstance(value, np.generic):
        return value.item()
    return value


def _tuples(obj: Any, *names: str) -> None:
    """Store the fields ``names`` of a frozen dataclass as plain tuples."""
    for name in names:
        value = getattr(obj, name)
        if isinstance(value, np.ndarray | list | tuple | np.generic):
            object.__setattr__(obj, name, _plain(value))


def _fail(entry: str, message: str) -> None:
    msg = f"{entry}: {message}"
    raise ModelError(msg)


def _finite(value: object) -> bool:
    return (
        isinstance(value, int | float)
        and not isinstance(value, bool)
        and math.isfinite(value)
    )


def _check_vec(entry: str, value: object) -> None:
    ok = (
        isinstance(value, tuple | list) and len(value) == 2 and all(map(_finite, value))
    )
    if not ok:
        _fail(entry, f"expected two finite numbers [x, y], got {value!r}")


def _check_name(entry: str, name: object) -> None:
    if not isinstance(name, str) or not name or any(c in name for c in RESERVED):
        _fail(entry, f"expected a non-empty name without '~', '.' or ',', got {name!r}")
    if name in RESERVED_NAMES:
        _fail(
            entry,
            f"the name {name!r} is taken by the result tables; expected "
            f"another name (not {', '.join(RESERVED_NAMES)})",
        )


def _check_point(entry: str, spec: object, points: set[str]) -> None:
    if isinstance(spec, str):
        if spec not in points:
            _fail(entry, f"unknown point {spec!r}{suggest(spec, list(points))}")
    elif isinstance(spec, Toward):
        for key, ref in (("from", spec.start), ("toward", spec.toward)):
            if ref not in points:
                _fail(
                    f"{entry}.{key}",
                    f"unknown point {ref!r}{suggest(ref, list(points))}",
                )
        if spec.start == spec.toward:
            _fail(
                entry,
                f"'from' and 'toward' are the same point {spec.start!r}; "
                "expected two distinct points",
            )
        if not _finite(spec.distance):
            _fail(
                f"{entry}.distance", f"expected a finite number, got {spec.distance!r}"
            )
    else:
        _check_vec(entry, spec)


def _validate(mech: Mechanism) -> None:
    """Check every reference and value of ``mech``; raise on the first fault."""
    if not mech.links:
        _fail("links", "no moving links; expected at least one [links.NAME] entry")
    link_names: list[str] = []
    for link in mech.links:
        entry = f"links.{link.name}"
        _check_name(entry, link.name)
        if link.name == GROUND:
            _fail(entry, "'ground' is the frame and takes no entry")
        if link.name in link_names:
            _fail(entry, "two links with one name")
        link_names.append(link.name)
        for key in ("mass", "inertia"):
            value = getattr(link, key)
            if value is not None and (not _finite(value) or value < 0):
                _fail(f"{entry}.{key}", f"expected a number >= 0, got {value!r}")
    all_links = [GROUND, *link_names]
    joint_names: list[str] = []
    for joint in mech.joints:
        entry = f"joints.{joint.name}"
        _check_name(entry, joint.name)
        if joint.name in joint_names:
            _fail(entry, "two joints with one name")
        joint_names.append(joint.name)
        if joint.kind not in JOINT_KINDS:
            _fail(
                f"{entry}.kind",
                f"unknown kind {joint.kind!r}; expected one of "
                + ", ".join(JOINT_KINDS),
            )
        if len(joint.links) != 2:
            _fail(f"{entry}.links", f"expected two links, got {list(joint.links)!r}")
        for name in joint.links:
            if name not in all_links:
                _fail(
                    f"{entry}.links",
                    f"unknown link {name!r}{suggest(name, all_links)}",
                )
        if joint.links[0] == joint.links[1]:
            _fail(
                f"{entry}.links",
                f"joins link {joint.links[0]!r} to itself; "
                "expected two different links",
            )
        if joint.kind != "revolute":
            if joint.axis is None:
                _fail(entry, f"a {joint.kind} joint needs an 'axis' [x, y]")
            _check_vec(f"{entry}.axis", joint.axis)
            if math.hypot(*joint.axis) < 1e-12:
                _fail(
                    f"{entry}.axis",
                    f"zero axis {list(joint.axis)!r}; expected a nonzero direction",
                )
    point_names = set(joint_names)
    for point in mech.points:
        entry = f"points.{point.name}"
        _check_name(entry, point.name)
        if point.name in point_names:
            _fail(entry, "a point or joint with this name exists already")
        if point.link not in link_names:
            _fail(
                f"{entry}.link",
                f"unknown link {point.link!r}{suggest(point.link, link_names)}",
            )
        point_names.add(point.name)
    for joint in mech.joints:
        _check_point(f"joints.{joint.name}.at", joint.at, point_names - {joint.name})
    for point in mech.points:
        _check_point(f"points.{point.name}.at", point.at, point_names - {point.name})
    used = {name for joint in mech.joints for name in joint.links}
    for link in mech.links:
        entry = f"links.{link.name}"
        if link.name not in used:
            _fail(entry, "a link with no joints; expected it in some joint's links")
        if link.center is not None:
            _check_point(f"{entry}.center", link.center, point_names)
        if link.axis is not None:
            on_link = point_links(mech)
            if len(link.axis) != 2 or link.axis[0] == link.axis[1]:
                _fail(
                    f"{entry}.axis",
                    f"expected two distinct points, got {list(link.axis)!r}",
                )
            for name in link.axis:
                if link.name not in on_link.get(name, ()):
                    _fail(
                        f"{entry}.axis", f"point {name!r} is not on link {link.name!r}"
                    )
    _validate_drivers(mech, all_links)
    if mech.gravity is not None:
        _check_vec("gravity.g", mech.gravity)
    for index, load in enumerate(mech.loads):
        _validate_load(mech, f"loads[{index}]", load, link_names, point_names)
    _check_resolvable(mech)


def _validate_drivers(mech: Mechanism, all_links: list[str]) -> None:
    joints = {joint.name: joint for joint in mech.joints}
    seen = set()
    for index, driver in enumerate(mech.drivers):
        entry = f"drivers[{index}]"
        if driver.joint not in joints:
            _fail(
                f"{entry}.joint",
                f"unknown joint {driver.joint!r}" + suggest(driver.joint, list(joints)),
            )
        if driver.joint in seen:
            _fail(f"{entry}.joint", f"joint {driver.joint!r} is driven twice")
        seen.add(driver.joint)
        joint = joints[driver.joint]
        if joint.kind not in ("revolute", "prismatic"):
            _fail(
                f"{entry}.joint",
                f"joint {driver.joint!r} is a {joint.kind} joint; "
                "expected a revolute or prismatic joint",
            )
        if GROUND not in joint.links:
            _fail(
                f"{entry}.joint",
                f"joint {driver.joint!r} joins {joint.links[0]!r} "
                f"and {joint.links[1]!r}; a driver must act between the frame "
                "('ground') and its input link",
            )
        for key in ("omega", "epsilon"):
            if not _finite(getattr(driver, key)):
                _fail(
                    f"{entry}.{key}",
                    f"expected a finite number, got {getattr(driver, key)!r}",
                )


def _validate_table(entry: str, table: LoadTable, ncomp: int, mech: Mechanism) -> None:
    prismatic = [j.name for j in mech.joints if j.kind != "revolute"]
    if table.over != "driver" and table.over not in prismatic:
        _fail(
            f"{entry}.over",
            f"expected 'driver' or a prismatic joint, got "
            f"{table.over!r}{suggest(table.over, ['driver', *prismatic])}",
        )
    xs = np.asarray(table.table, dtype=float)
    if xs.ndim != 1 or len(xs) < 2 or not np.all(np.isfinite(xs)):
        _fail(f"{entry}.table", "expected at least two finite positions")
    if np.any(np.diff(xs) <= 0):
        _fail(f"{entry}.table", "expected strictly increasing positions")
    if len(table.values) != ncomp:
        _fail(entry, f"expected {ncomp} value sequence(s), got {len(table.values)}")
    for values in table.values:
        if len(values) != len(xs) or not all(map(_finite, values)):
            _fail(
                entry,
                f"expected {len(xs)} finite values, one per table position, "
                f"got {list(values)!r}",
            )


def _validate_load(
    mech: Mechanism,
    entry: str,
    load: Load,
    link_names: list[str],
    point_names: set[str],
) -> None:
    if load.link not in link_names:
        _fail(
            f"{entry}.link",
            f"unknown link {load.link!r}{suggest(load.link, link_names)}",
        )
    if load.force is None and load.torque is None:
        _fail(entry, "expected a 'force' or a 'torque'")
    if load.force is not None:
        if load.at is None:
            _fail(entry, "a force needs its point of application 'at'")
        if isinstance(load.force, LoadTable):
            _validate_table(f"{entry}.force", load.force, 2, mech)
        else:
            _check_vec(f"{entry}.force", load.force)
    if load.at is not None:
        _check_point(f"{entry}.at", load.at, point_names)
    if isinstance(load.torque, LoadTable):
        _validate_table(f"{entry}.torque", load.torque, 1, mech)
    elif load.torque is not None and not _finite(load.torque):
        _fail(f"{entry}.torque", f"expected a finite number, got {load.torque!r}")


def _check_resolvable(mech: Mechanism) -> None:
    """Every point must have coordinates (a from/toward pair must not coincide)."""
    for joint in mech.joints:
        resolve_point(mech, joint.at, f"joints.{joint.name}.at")
    for point in mech.points:
        resolve_point(mech, point.at, f"points.{point.name}.at")
    for link in mech.links:
        if link.center is not None:
            resolve_point(mech, link.center, f"links.{link.name}.center")
    for index, load in enumerate(mech.loads):
        if load.at is not None:
            resolve_point(mech, load.at, f"loads[{index}].at")


def resolve_point(
    mech: Mechanism, spec: PointSpec, entry: str = "point", _depth: int = 0
) -> np.ndarray:
    """Return the reference-pose coordinates (m) of a point specification.

    Parameters
    ----------
    mech : Mechanism
    spec : PointSpec
        Coordinates, a joint's or extra point's name, or a :class:`Toward`.
    entry : str
        Where the specification was found, for error messages.

    Returns
    -------
    numpy.ndarray of shape (2,)
    """
    if _depth > 32:
        _fail(entry, "points refer to each other in a circle")
    if isinstance(spec, str):
        for joint in mech.joints:
            if joint.name == spec:
                return resolve_point(mech, joint.at, entry, _depth + 1)
        for point in mech.points:
            if point.name == spec:
                return resolve_point(mech, point.at, entry, _depth + 1)
        _fail(entry, f"unknown point {spec!r}")
    if isinstance(spec, Toward):
        a = resolve_point(mech, spec.start, entry, _depth + 1)
        b = resolve_point(mech, spec.toward, entry, _depth + 1)
        length = float(np.hypot(*(b - a)))
        if length < 1e-12:
            _fail(
                entry,
                f"points {spec.start!r} and {spec.toward!r} coincide; "
                "expected two distinct points",
            )
        return a + (b - a) * (spec.distance / length)
    return np.asarray(spec, dtype=float)


def point_links(mech: Mechanism) -> dict[str, tuple[str, ...]]:
    """Return, for every named point, the links it belongs to.

    A joint's point belongs to both of its links, an extra point to its link.
    """
    owners: dict[str, tuple[str, ...]] = {j.name: tuple(j.links) for j in mech.joints}
    owners.update({p.name: (p.link,) for p in mech.points})
    return owners
