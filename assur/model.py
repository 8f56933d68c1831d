"""The mechanism model: links, joints, drivers, loads and extra points.

A :class:`Mechanism` is an immutable value. Every point is given where it lies in the
reference pose, an assembled pose of the mechanism; lengths, body-fixed offsets and
the assembly branch of every group are derived from that pose by later stages.
Validation happens here, once, so the numerical core can trust its input.
"""

from __future__ import annotations

import math
import unicodedata
from collections.abc import Iterable
from dataclasses import dataclass, field
from os import PathLike
from typing import Any, NoReturn

import numpy as np

from assur._tables import disagreement
from assur._text import describe, key_text, listing, suggest
from assur.errors import ModelError, UsageError

__all__ = [
    "GROUND",
    "Driver",
    "Joint",
    "Link",
    "Load",
    "LoadTable",
    "Mechanism",
    "Motor",
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
LARGEST = 1e15
"""Largest magnitude of a number in a mechanism (m, kg, N, rad/s, ...): products of
a few such numbers (an acceleration, a jerk, a moment) stay far from overflow."""
MOST_FRICTION = 1e6
"""Largest friction coefficient: beyond it the friction of a pair whose normal force
it all but cancels is lost in the rounding of the reactions (no real pair comes
near: a coefficient above 1 is rare)."""
COINCIDENT = 1e-12
"""Distance under which two points coincide, m (relative to the coordinates' size
beyond 1 m, where round-off grows with them)."""

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
        _tuples(self, "distance")


PointSpec = Vec2 | str | Toward
"""A point of the reference pose: coordinates (m), a point's name, or a Toward."""


@dataclass(frozen=True, slots=True)
class Link:
    """A rigid link.

    Parameters
    ----------
    name : str
        Identifier chosen by the user; ``"ground"`` is reserved for the frame.
    axis : tuple of two PointSpec, optional
        Two distinct points; the link's angle is the direction from the first to the
        second in the reference pose, turning with the link. A name stands for where
        that point is in the reference pose, on this link or not. Without an axis the
        angle is the rotation from the reference pose.
    mass : float, optional
        Mass, kg. A link without mass is massless.
    center : PointSpec, optional
        Centre of mass in the reference pose: coordinates (m), a point's name or a
        :class:`Toward`.
    inertia : float, optional
        Moment of inertia about the centre of mass, kg m^2.
    """

    name: str
    axis: tuple[PointSpec, PointSpec] | None = None
    mass: float | None = None
    center: PointSpec | None = None
    inertia: float | None = None

    def __post_init__(self) -> None:
        _tuples(self, "axis", "mass", "center", "inertia")


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
    friction : float
        Coulomb coefficient of kinetic friction (0: frictionless).
    radius : float, optional
        Journal radius of a revolute joint with friction, m: its friction circle's
        radius is ``friction * radius``.
    """

    name: str
    kind: str
    links: tuple[str, str]
    at: PointSpec
    axis: Vec2 | None = None
    friction: float = 0.0
    radius: float | None = None

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

    def __post_init__(self) -> None:
        _tuples(self, "omega", "epsilon")


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
        _tuples(self, "table", "values")


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
        _tuples(self, "at", "force", "torque")


@dataclass(frozen=True, slots=True)
class Point:
    """An extra point of a link to report (a coupler point, say).

    Parameters
    ----------
    name : str
        Identifier, unique among joints and points; the point's columns are
        ``name.x``, ``name.y``, ...
    link : str
        The link the point is fixed in.
    at : PointSpec
        Position in the reference pose: coordinates (m), another point's name or a
        :class:`Toward`.
    """

    name: str
    link: str
    at: PointSpec

    def __post_init__(self) -> None:
        _tuples(self, "at")


@dataclass(frozen=True, slots=True)
class Motor:
    """The motor on the driving crank: its torque against its speed.

    ``M(w) = torque * (1 - w / no_load_speed)``, the linear characteristic of an
    electric motor; without ``no_load_speed`` the torque is constant. The motor
    turns the crank the way its torque points (counter-clockwise positive).

    Parameters
    ----------
    torque : float
        Torque at standstill (the stall torque), N m; not zero.
    no_load_speed : float, optional
        Speed at which the torque falls to zero, rad/s, of the torque's sign.
    """

    torque: float
    no_load_speed: float | None = None

    def __post_init__(self) -> None:
        _tuples(self, "torque", "no_load_speed")

    def at(self, speed: float) -> float:
        """Return the motor's torque (N m) at the crank's ``speed`` (rad/s)."""
        if self.no_load_speed is None:
            return self.torque
        return self.torque * (1.0 - speed / self.no_load_speed)


@dataclass(frozen=True, slots=True)
class Mechanism:
    """A planar mechanism in its reference pose.

    Parameters
    ----------
    links : tuple of Link
        The moving links; the frame ``"ground"`` is implicit.
    joints : tuple of Joint
        The pairs joining the links to each other and to the frame.
    drivers : tuple of Driver
        The driven joints, one per degree of freedom.
    name : str, default ""
        The mechanism's name, shown in reports and kept with exported tables.
    description : str, default ""
        Free text on the mechanism, kept in its file and shown in its HTML report.
    gravity : tuple of float, optional
        Gravitational acceleration vector, m/s^2, e.g. ``(0.0, -9.81)``.
    loads : tuple of Load, default ()
        External forces and torques; weights come from ``gravity`` and inertia loads
        from the masses, neither is a load.
    points : tuple of Point, default ()
        Extra points to report.
    motor : Motor, optional
        The motor on the driving crank, for a start-up in time
        (:func:`assur.startup <assur.dynamics_startup.startup>`); nothing else reads it.

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
    motor: Motor | None = None
    _hash: int | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        for attr, kind in _PARTS.items():
            object.__setattr__(self, attr, _parts(attr, getattr(self, attr), kind))
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
                    self.motor,
                )
            )
            object.__setattr__(self, "_hash", value)
        return self._hash  # type: ignore[return-value]

    def link(self, name: str) -> Link:
        """Return the link called ``name``."""
        for link in self.links:
            if link.name == name:
                return link
        msg = f"unknown link {describe(name)}"
        raise KeyError(msg)

    def joint(self, name: str) -> Joint:
        """Return the joint called ``name``."""
        for joint in self.joints:
            if joint.name == name:
                return joint
        msg = f"unknown joint {describe(name)}"
        raise KeyError(msg)


_PARTS = {
    "links": Link,
    "joints": Joint,
    "drivers": Driver,
    "loads": Load,
    "points": Point,
}


def _parts(entry: str, value: Any, kind: type) -> tuple[Any, ...]:
    """Return a mechanism's collection ``value`` as a tuple of ``kind``."""
    if isinstance(value, str | bytes | dict) or not isinstance(value, Iterable):
        _fail(entry, f"expected a sequence of {kind.__name__}, got {describe(value)}")
    items = tuple(value)
    for index, item in enumerate(items):
        if not isinstance(item, kind):
            _fail(
                f"{entry}[{index}]",
                f"expected a {kind.__name__}, got {describe(item)}",
            )
    return items


_SIMPLE = frozenset({float, int, str})


def mechanism_of(value: Any) -> Mechanism:
    """Return ``value``, checked to be a Mechanism (what every analysis takes).

    Raises
    ------
    UsageError
        For anything else: a file's path, say (read with ``assur.load``).
    """
    if isinstance(value, Mechanism):
        return value
    hint = (
        " (read the file with assur.load)" if isinstance(value, str | PathLike) else ""
    )
    msg = f"mechanism: expected an assur.Mechanism, got {type(value).__name__}{hint}"
    raise UsageError(msg)


def _plain(value: Any) -> Any:
    """Return lists and arrays as tuples, numpy numbers as Python's (hashable)."""
    # the common case, a tuple of plain numbers or names, is kept as it is
    if value.__class__ is tuple and all(v.__class__ in _SIMPLE for v in value):
        return value
    if isinstance(value, np.ndarray) and value.ndim == 0:
        return value.item()  # a number made with np.array(x)
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


def _fail(entry: str, message: str) -> NoReturn:
    msg = f"{entry}: {message}"
    raise ModelError(msg)


def _spec_text(spec: object) -> str:
    """Return a point specification as the file writes it, shortened."""
    if isinstance(spec, Toward):
        return (
            f"{{from = {describe(spec.start)}, toward = {describe(spec.toward)}, "
            f"distance = {describe(spec.distance)}}}"
        )
    return describe(spec)


def _number(value: object) -> bool:
    """Whether ``value`` is a number (not a boolean)."""
    return isinstance(value, int | float) and not isinstance(value, bool)


def _finite(value: object) -> bool:
    """Whether ``value`` is a number of magnitude at most :data:`LARGEST`."""
    if value.__class__ is float:  # the common case, checked first
        return abs(value) <= LARGEST  # type: ignore[arg-type]
    return _number(value) and abs(value) <= LARGEST  # type: ignore[arg-type]


def _number_fault(value: object) -> str:
    """Return what is wrong with a number that is not :func:`_finite`."""
    if not _number(value):
        return f"expected a number, got {describe(value)}"
    if not math.isfinite(value):  # type: ignore[arg-type]
        return f"expected a finite number, got {describe(value)}"
    return f"expected a number of magnitude at most {LARGEST:g}, got {describe(value)}"


def _check_number(entry: str, value: object, minimum: float | None = None) -> None:
    if not _finite(value):
        _fail(entry, _number_fault(value))
    if minimum is not None and value < minimum:  # type: ignore[operator]
        _fail(entry, f"expected a number >= {minimum:g}, got {describe(value)}")


def _sequence_fault(value: object, expected: str, count: int | None = None) -> str:
    """Return what is wrong with a sequence of numbers (``expected``: what it is not).

    Numbers of the right count of which one is too large or not finite are named
    as such, not said to be of the wrong count.
    """
    if (
        isinstance(value, tuple | list)
        and (len(value) == count if count is not None else len(value) >= 2)
        and all(map(_number, value))
    ):
        bad = next((v for v in value if not _finite(v)), None)
        if bad is not None:
            return f"{_number_fault(bad)} in {describe(value)}"
    return f"expected {expected}, got {describe(value)}"


def _check_vec(entry: str, value: object) -> None:
    ok = (
        isinstance(value, tuple | list) and len(value) == 2 and all(map(_finite, value))
    )
    if ok:
        return
    if isinstance(value, tuple | list) and len(value) == 2 and all(map(_number, value)):
        bad = next(v for v in value if not _finite(v))
        _fail(entry, f"{_number_fault(bad)} in {describe(value)}")
    _fail(entry, f"expected two finite numbers [x, y], got {describe(value)}")


def _control(name: str) -> str | None:
    """Return the first control character of ``name`` (or a line separator)."""
    for c in name:
        if unicodedata.category(c) in ("Cc", "Zl", "Zp"):
            return c
    return None


_GOOD_NAMES: set[str] = set()
"""Names found valid already: the variants of a study repeat their names, and the
check reads every character's Unicode category."""


def _check_name(entry: str, name: object) -> None:
    if name.__class__ is str and name in _GOOD_NAMES:
        return
    _check_new_name(entry, name)
    if len(_GOOD_NAMES) >= 4096:
        _GOOD_NAMES.clear()
    _GOOD_NAMES.add(name)  # type: ignore[arg-type]


def _check_new_name(entry: str, name: object) -> None:
    """Check a name not met before: text, no reserved or control character."""
    if not isinstance(name, str) or not name or any(c in name for c in RESERVED):
        _fail(
            entry,
            f"expected a non-empty name without '~', '.' or ',', got {describe(name)}",
        )
    control = _control(name)
    if control is not None:
        _fail(
            entry,
            f"the name {describe(name)} holds the control character "
            f"{control!a}; expected printable characters only",
        )
    if name in RESERVED_NAMES:
        _fail(
            entry,
            f"the name {describe(name)} is taken by the result tables; expected "
            f"another name (not {', '.join(RESERVED_NAMES)})",
        )


def _unknown(kind: str, name: object, known: Iterable[str]) -> str:
    """Return the message of an unknown reference ``name``, with a hint."""
    hint = suggest(name, known) if isinstance(name, str) else ""
    return f"unknown {kind} {describe(name)}{hint}"


def _on_the_frame(why: str, links: list[str]) -> str:
    """Return the message of a point or load on the frame (``why``: what it does)."""
    return f"{GROUND!r} is the frame: {why}; expected a moving link ({listing(links)})"


def _check_point(entry: str, spec: object, points: set[str]) -> None:
    if isinstance(spec, str):
        if spec not in points:
            _fail(entry, _unknown("point", spec, points))
    elif isinstance(spec, Toward):
        for key, ref in (("from", spec.start), ("toward", spec.toward)):
            if not isinstance(ref, str) or ref not in points:
                _fail(f"{entry}.{key}", _unknown("point", ref, points))
        if spec.start == spec.toward:
            _fail(
                entry,
                f"'from' and 'toward' are the same point {describe(spec.start)}; "
                "expected two distinct points",
            )
        if not _finite(spec.distance):
            _fail(f"{entry}.distance", _number_fault(spec.distance))
    else:
        _check_vec(entry, spec)


_VALID: set[Any] = set()
"""Skeletons (:func:`_skeleton`) of mechanisms found valid. The variants of a study
share one: only their numbers need checking (:func:`_validate_numbers`)."""


def _validate(mech: Mechanism) -> None:
    """Check every reference and value of ``mech``; raise on the first fault.

    A mechanism whose skeleton passed before has only its numbers checked, in the
    order of the full check: its first fault, and so the message, is the same.
    """
    key = _skeleton(mech)
    if key is not None and key in _VALID:
        _validate_numbers(mech)
        return
    _validate_all(mech)
    if key is not None:
        if len(_VALID) >= 256:
            _VALID.clear()
        _VALID.add(key)


def _skeleton(mech: Mechanism) -> Any:
    """Return what the checks of references, names and kinds read; None if unusual.

    Names, kinds, which links each joint joins, how each point is given and which
    optional values are present. None (check everything) for anything but the
    common forms: points as coordinates, names or Toward, no tabulated load, no
    motor.
    """
    if mech.motor is not None or not mech.links:
        return None
    if mech.name.__class__ is not str or mech.description.__class__ is not str:
        return None
    try:
        parts: list[Any] = [mech.gravity is None]
        for link in mech.links:
            axis = link.axis
            if axis is not None:
                if axis.__class__ is not tuple or len(axis) != 2:
                    return None
                axis = tuple(map(_spec_key, axis))
            center = _spec_key(link.center)
            parts.append(
                (link.name, axis, link.mass is None, center, link.inertia is None)
            )
        for j in mech.joints:
            at = _spec_key(j.at)
            parts.append(
                (j.name, j.kind, j.links, at, j.axis is None, j.radius is None)
            )
        parts += [(p.name, p.link, _spec_key(p.at)) for p in mech.points]
        parts += [d.joint for d in mech.drivers]
        for load in mech.loads:
            if isinstance(load.force, LoadTable) or isinstance(load.torque, LoadTable):
                return None
            at = _spec_key(load.at)
            parts.append((load.link, at, load.force is None, load.torque is None))
        key = tuple(parts)
        hash(key)
    except (_Odd, TypeError):
        return None
    return key


class _Odd(Exception):  # noqa: N818 (a signal, caught in _skeleton)
    """A point given in none of the common forms."""


def _spec_key(spec: object) -> Any:
    """Return how a point is given: a name, a Toward's two names, or coordinates."""
    if spec is None or spec.__class__ is str:
        return spec
    if spec.__class__ is Toward:
        return ("toward", spec.start, spec.toward)  # type: ignore[attr-defined]
    if spec.__class__ is tuple:
        return ()
    raise _Odd


def _validate_numbers(mech: Mechanism) -> None:
    """Check the numbers of ``mech``, whose skeleton is valid, in the full order.

    Each value is tested quickly; one that fails is checked again by the function
    the full check uses, which raises its message.
    """
    for link in mech.links:
        for key in ("mass", "inertia"):
            value = getattr(link, key)
            if value is not None and not (_finite(value) and value >= 0.0):
                _check_number(f"links.{key_text(link.name)}.{key}", value, 0.0)
    for joint in mech.joints:
        if joint.kind != "revolute" and not (
            _vec_ok(joint.axis) and math.hypot(*joint.axis) >= COINCIDENT  # type: ignore[misc]
        ):
            _check_joint_axis(f"joints.{key_text(joint.name)}", joint)
        friction, radius = joint.friction, joint.radius
        if not (
            _finite(friction)
            and 0.0 <= friction <= MOST_FRICTION
            and (radius is None or (_finite(radius) and radius >= 0.0))
            and not (joint.kind == "revolute" and friction and not radius)
        ):
            _check_friction(f"joints.{key_text(joint.name)}", joint)
    names = {j.name for j in mech.joints} | {p.name for p in mech.points}
    for joint in mech.joints:
        if not _point_ok(joint.at):
            entry = f"joints.{key_text(joint.name)}.at"
            _check_point(entry, joint.at, names - {joint.name})
    for point in mech.points:
        if not _point_ok(point.at):
            entry = f"points.{key_text(point.name)}.at"
            _check_point(entry, point.at, names - {point.name})
    for link in mech.links:
        if link.center is not None and not _point_ok(link.center):
            _check_point(_entry("links", link.name, ".center"), link.center, names)
        if link.axis is not None and not all(map(_point_ok, link.axis)):
            _check_axis(_entry("links", link.name, ".axis"), link.axis, names)
    for index, driver in enumerate(mech.drivers):
        for key in ("omega", "epsilon"):
            if not _finite(getattr(driver, key)):
                _fail(f"drivers[{index}].{key}", _number_fault(getattr(driver, key)))
    if mech.gravity is not None and not _vec_ok(mech.gravity):
        _check_vec("gravity.g", mech.gravity)
    for index, load in enumerate(mech.loads):
        entry = f"loads[{index}]"
        if load.force is not None and not _vec_ok(load.force):
            _check_vec(f"{entry}.force", load.force)
        if load.at is not None and not _point_ok(load.at):
            _check_point(f"{entry}.at", load.at, names)
        if load.torque is not None and not _finite(load.torque):
            _fail(f"{entry}.torque", _number_fault(load.torque))
    resolve = _resolver(mech)
    try:
        _check_resolvable(mech, entries=False, resolve=resolve)
    except ModelError:
        _check_resolvable(mech)  # again, for the message naming the entry
    _check_cranks(mech, resolve)


def _vec_ok(value: object) -> bool:
    """Whether :func:`_check_vec` accepts ``value``."""
    return (
        isinstance(value, tuple | list) and len(value) == 2 and all(map(_finite, value))
    )


def _point_ok(spec: object) -> bool:
    """Whether the numbers of a point in a valid skeleton are acceptable."""
    if spec.__class__ is str:
        return True
    if spec.__class__ is Toward:
        return _finite(spec.distance)  # type: ignore[attr-defined]
    return _vec_ok(spec)


def _validate_all(mech: Mechanism) -> None:
    """Check every reference and value of ``mech``; raise on the first fault."""
    if not mech.links:
        _fail("links", "no moving links; expected at least one [links.NAME] entry")
    for attr in ("name", "description"):
        if not isinstance(getattr(mech, attr), str):
            _fail(attr, f"expected a text, got {describe(getattr(mech, attr))}")
    link_names = _validate_links(mech)
    all_links = [GROUND, *link_names]
    joint_names = _validate_joints(mech, all_links)
    point_names = set(joint_names)
    for point in mech.points:
        entry = f"points.{key_text(point.name)}"
        _check_name(entry, point.name)
        if point.name in point_names:
            _fail(entry, "a point or joint with this name exists already")
        if point.link == GROUND:
            _fail(
                f"{entry}.link", _on_the_frame("a point on it never moves", link_names)
            )
        if not isinstance(point.link, str) or point.link not in link_names:
            _fail(f"{entry}.link", _unknown("link", point.link, link_names))
        point_names.add(point.name)
    for joint in mech.joints:
        _check_point(
            f"joints.{key_text(joint.name)}.at", joint.at, point_names - {joint.name}
        )
    for point in mech.points:
        _check_point(
            f"points.{key_text(point.name)}.at", point.at, point_names - {point.name}
        )
    used = {name for joint in mech.joints for name in joint.links}
    for link in mech.links:
        entry = f"links.{key_text(link.name)}"
        if link.name not in used:
            _fail(entry, "a link with no joints; expected it in some joint's links")
        if link.center is not None:
            _check_point(f"{entry}.center", link.center, point_names)
        if link.axis is not None:
            _check_axis(f"{entry}.axis", link.axis, point_names)
    _validate_drivers(mech)
    if mech.gravity is not None:
        _check_vec("gravity.g", mech.gravity)
    for index, load in enumerate(mech.loads):
        _validate_load(mech, f"loads[{index}]", load, link_names, point_names)
    if mech.motor is not None:
        validate_motor(mech.motor)
    _check_resolvable(mech)
    _check_cranks(mech)


def _validate_links(mech: Mechanism) -> list[str]:
    """Check the links' names and mass properties; return their names."""
    link_names: list[str] = []
    for link in mech.links:
        entry = f"links.{key_text(link.name)}"
        _check_name(entry, link.name)
        if link.name == GROUND:
            _fail(entry, "'ground' is the frame and takes no entry")
        if link.name in link_names:
            _fail(entry, "two links with one name")
        link_names.append(link.name)
        for key in ("mass", "inertia"):
            value = getattr(link, key)
            if value is not None:
                _check_number(f"{entry}.{key}", value, minimum=0.0)
    return link_names


def _validate_joints(mech: Mechanism, all_links: list[str]) -> list[str]:
    """Check the joints' names, kinds, links and axes; return their names."""
    joint_names: list[str] = []
    for joint in mech.joints:
        entry = f"joints.{key_text(joint.name)}"
        _check_name(entry, joint.name)
        if joint.name in joint_names:
            _fail(entry, "two joints with one name")
        joint_names.append(joint.name)
        if not isinstance(joint.kind, str) or joint.kind not in JOINT_KINDS:
            _fail(
                f"{entry}.kind",
                f"unknown kind {describe(joint.kind)}; expected one of "
                + ", ".join(JOINT_KINDS),
            )
        links = joint.links
        if not isinstance(links, tuple) or len(links) != 2:
            _fail(f"{entry}.links", f"expected two links, got {describe(links)}")
        for name in links:
            if not isinstance(name, str) or name not in all_links:
                _fail(f"{entry}.links", _unknown("link", name, all_links))
        if links[0] == links[1]:
            _fail(
                f"{entry}.links",
                f"joins link {describe(links[0])} to itself; "
                "expected two different links",
            )
        _check_joint_axis(entry, joint)
        _check_friction(entry, joint)
    return joint_names


def _check_friction(entry: str, joint: Joint) -> None:
    """Check a joint's friction: a coefficient, and a journal radius on a revolute."""
    _check_number(f"{entry}.friction", joint.friction, 0.0)
    if joint.friction > MOST_FRICTION:  # type: ignore[operator]
        _fail(
            f"{entry}.friction",
            f"expected a Coulomb coefficient from 0 to {MOST_FRICTION:g}, got "
            f"{describe(joint.friction)}",
        )
    if joint.radius is not None:
        if joint.kind != "revolute":
            _fail(
                f"{entry}.radius",
                f"a {joint.kind} joint has no journal, got radius "
                f"{describe(joint.radius)}; expected 'radius' on revolute joints only",
            )
        _check_number(f"{entry}.radius", joint.radius, 0.0)
    if joint.kind == "revolute" and joint.friction and joint.radius is None:
        _fail(
            entry,
            "a revolute joint with friction needs its journal 'radius' (m): the "
            "friction circle's radius is friction * radius",
        )


def _check_joint_axis(entry: str, joint: Joint) -> None:
    """Check a joint's slide line: required on prismatic and slot joints only."""
    if joint.kind == "revolute":
        if joint.axis is not None:
            _fail(
                f"{entry}.axis",
                f"a revolute joint has no slide line, got {describe(joint.axis)}; "
                "expected 'axis' only on prismatic and slot joints",
            )
        return
    if joint.axis is None:
        _fail(entry, f"a {joint.kind} joint needs an 'axis' [x, y]")
    _check_vec(f"{entry}.axis", joint.axis)
    assert joint.axis is not None
    if math.hypot(*joint.axis) < COINCIDENT:
        _fail(
            f"{entry}.axis",
            f"zero axis {describe(joint.axis)}; expected a nonzero direction",
        )


def _check_axis(entry: str, axis: object, points: set[str]) -> None:
    """Check a link's axis: two points, each of any form."""
    if not isinstance(axis, tuple) or len(axis) != 2 or all(map(_number, axis)):
        hint = (
            " (a direction [x, y] is the axis of a prismatic joint)"
            if isinstance(axis, tuple) and len(axis) == 2
            else ""
        )
        _fail(
            entry,
            f"expected two points (each [x, y], a point's name or "
            f"{{from, toward, distance}}), got {describe(axis)}{hint}",
        )
    for index, spec in enumerate(axis):
        _check_point(f"{entry}[{index}]", spec, points)


def _validate_drivers(mech: Mechanism) -> None:
    joints = {joint.name: joint for joint in mech.joints}
    seen = set()
    for index, driver in enumerate(mech.drivers):
        entry = f"drivers[{index}]"
        if not isinstance(driver.joint, str) or driver.joint not in joints:
            _fail(f"{entry}.joint", _unknown("joint", driver.joint, joints))
        if driver.joint in seen:
            _fail(f"{entry}.joint", f"joint {describe(driver.joint)} is driven twice")
        seen.add(driver.joint)
        joint = joints[driver.joint]
        if joint.kind not in ("revolute", "prismatic"):
            _fail(
                f"{entry}.joint",
                f"joint {describe(driver.joint)} is a {joint.kind} joint; "
                "expected a revolute or prismatic joint",
            )
        if GROUND not in joint.links:
            _fail(
                f"{entry}.joint",
                f"joint {describe(driver.joint)} joins {describe(joint.links[0])} "
                f"and {describe(joint.links[1])}; a driver must act between the "
                "frame ('ground') and its input link",
            )
        for key in ("omega", "epsilon"):
            if not _finite(getattr(driver, key)):
                _fail(f"{entry}.{key}", _number_fault(getattr(driver, key)))


def validate_motor(motor: object) -> None:
    """Check the motor: a torque that is not zero, a speed of the same sign."""
    if not isinstance(motor, Motor):
        _fail("motor", f"expected a Motor, got {describe(motor)}")
    if not _finite(motor.torque):
        _fail("motor.torque", _number_fault(motor.torque))
    if motor.torque == 0:
        _fail(
            "motor.torque", "the motor's torque at standstill is 0; expected a torque"
        )
    speed = motor.no_load_speed
    if speed is None:
        return
    if not _finite(speed):
        _fail("motor.no_load_speed", _number_fault(speed))
    if speed * motor.torque <= 0:  # type: ignore[operator]
        _fail(
            "motor.no_load_speed",
            f"{describe(speed)} rad/s against a torque of {describe(motor.torque)} "
            "N m; expected a speed of the torque's sign (the way the motor turns)",
        )


def _validate_table(entry: str, table: LoadTable, ncomp: int, mech: Mechanism) -> None:
    prismatic = [j.name for j in mech.joints if j.kind != "revolute"]
    if table.over != "driver" and table.over not in prismatic:
        hint = (
            suggest(table.over, ["driver", *prismatic])
            if isinstance(table.over, str)
            else ""
        )
        _fail(
            f"{entry}.over",
            f"expected 'driver' or a prismatic joint, got {describe(table.over)}{hint}",
        )
    if (
        not isinstance(table.table, tuple)
        or len(table.table) < 2
        or not all(map(_finite, table.table))
    ):
        _fail(
            f"{entry}.table",
            _sequence_fault(table.table, "at least two finite positions"),
        )
    xs = np.asarray(table.table, dtype=float)
    if np.any(np.diff(xs) <= 0):
        _fail(f"{entry}.table", "expected strictly increasing positions")
    values = table.values
    if not isinstance(values, tuple) or len(values) != ncomp:
        count = len(values) if isinstance(values, tuple) else describe(values)
        _fail(entry, f"expected {ncomp} value sequence(s), got {count}")
    for seq in values:
        if (
            not isinstance(seq, tuple)
            or len(seq) != len(xs)
            or not all(map(_finite, seq))
        ):
            _fail(
                entry,
                _sequence_fault(
                    seq, f"{len(xs)} finite values, one per table position", len(xs)
                ),
            )
    kinds = {j.name: j.kind for j in mech.joints}
    turning = bool(mech.drivers) and kinds.get(mech.drivers[0].joint) == "revolute"
    if table.over != "driver" or not turning:
        return
    for seq in values:
        # a crank's angle is read modulo 360: entries a turn apart are one position
        found = disagreement(xs, np.asarray(seq, dtype=float))
        if found is not None:
            _fail(
                entry,
                f"the value at {found[0]:g} deg is not the one at {found[1]:g} deg, a "
                "whole number of turns before; expected values that repeat from turn "
                "to turn (the crank's angle is read modulo 360)",
            )


def _validate_load(
    mech: Mechanism,
    entry: str,
    load: Load,
    link_names: list[str],
    point_names: set[str],
) -> None:
    if load.link == GROUND:
        why = "a load on it acts on no moving link and changes no reaction"
        _fail(f"{entry}.link", _on_the_frame(why, link_names))
    if not isinstance(load.link, str) or load.link not in link_names:
        _fail(f"{entry}.link", _unknown("link", load.link, link_names))
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
        _fail(f"{entry}.torque", _number_fault(load.torque))


def _resolver(mech: Mechanism) -> Any:
    """Return :func:`resolve_point` for ``mech``, quicker on names of coordinates.

    Validation resolves every point, most of them names of joints given as
    coordinates: those are looked up once. Anything else (a name of a name, a Toward
    of such names, a fault) goes through resolve_point, so results and messages are
    the same.
    """
    plain: dict[str, np.ndarray] = {}
    for name, at in [(j.name, j.at) for j in mech.joints] + [
        (p.name, p.at) for p in mech.points
    ]:
        if at.__class__ is tuple and name not in plain:
            plain[name] = np.asarray(at, dtype=float)

    def resolve(spec: PointSpec, entry: str = "point") -> np.ndarray:
        if spec.__class__ is tuple:
            return np.asarray(spec, dtype=float)  # as resolve_point does
        # names are unique by now: ``plain`` holds the one point of each name
        if spec.__class__ is str and spec in plain:
            return plain[spec]  # type: ignore[index]
        if isinstance(spec, Toward) and spec.start in plain and spec.toward in plain:
            return _toward(spec, plain[spec.start], plain[spec.toward], entry)
        return resolve_point(mech, spec, entry)

    return resolve


def _check_resolvable(
    mech: Mechanism, entries: bool = True, resolve: Any = None
) -> None:
    """Every point must have coordinates (a from/toward pair must not coincide).

    Without ``entries`` the messages name no entry (cheaper when none is expected:
    see :func:`_validate_numbers`). ``resolve`` is the mechanism's
    :func:`_resolver`, made here if not given.
    """
    resolve = resolve or _resolver(mech)
    where = _entry if entries else _no_entry
    for joint in mech.joints:
        resolve(joint.at, where("joints", joint.name, ".at"))
    for point in mech.points:
        resolve(point.at, where("points", point.name, ".at"))
    for link in mech.links:
        if link.center is not None:
            resolve(link.center, where("links", link.name, ".center"))
        if link.axis is not None:
            entry = where("links", link.name, ".axis")
            a, b = (resolve(p, f"{entry}[{i}]") for i, p in enumerate(link.axis))
            if _coincide(a, b):
                _fail(
                    entry,
                    f"its two points {_spec_text(link.axis[0])} and "
                    f"{_spec_text(link.axis[1])} coincide at ({a[0]:.6g}, {a[1]:.6g}) "
                    "in the reference pose; expected two distinct points",
                )
    for index, load in enumerate(mech.loads):
        if load.at is not None:
            resolve(load.at, f"loads[{index}].at" if entries else "")


def _entry(kind: str, name: object, suffix: str) -> str:
    """Return an entry such as ``joints.B.at``."""
    return f"{kind}.{key_text(name)}{suffix}"


def _no_entry(kind: str, name: object, suffix: str) -> str:
    """Return no entry (see :func:`_check_resolvable`)."""
    return ""


def _check_cranks(mech: Mechanism, resolve: Any = None) -> None:
    """Refuse a crank whose joints all sit at its pivot: it would drive nothing."""
    resolve = resolve or _resolver(mech)
    for index, driver in enumerate(mech.drivers):
        joint = mech.joint(driver.joint)
        if joint.kind != "revolute":
            continue
        link = joint.links[1] if joint.links[0] == GROUND else joint.links[0]
        pivot = resolve(joint.at)
        others = [j for j in mech.joints if j is not joint and link in j.links]
        moving = [
            j
            for j in others
            if j.kind != "revolute" or not _coincide(pivot, resolve(j.at))
        ]
        if others and not moving:
            names = ", ".join(describe(j.name) for j in others[:4])
            _fail(
                f"drivers[{index}].joint",
                f"the input link {describe(link)} has its joints {names} at the "
                f"pivot of {describe(joint.name)} (a crank of zero length), so the "
                "driver moves nothing; expected a joint of the input link away from "
                "its pivot",
            )


def _coincide(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two reference-pose points are one (see :data:`COINCIDENT`)."""
    # plain floats: two points cost less so than as numpy reductions
    ax, ay, bx, by = float(a[0]), float(a[1]), float(b[0]), float(b[1])
    size = max(1.0, abs(ax), abs(ay), abs(bx), abs(by))
    return math.hypot(bx - ax, by - ay) <= COINCIDENT * size


def resolve_point(
    mech: Mechanism, spec: PointSpec, entry: str = "point", _depth: int = 0
) -> np.ndarray:
    """Return the reference-pose coordinates (m) of a point specification.

    Parameters
    ----------
    mech : Mechanism
    spec : PointSpec
        Coordinates, a joint's or extra point's name, or a :class:`Toward`. A name
        stands for where that joint or point is in the reference pose, whichever
        link the specification belongs to.
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
        _fail(entry, f"unknown point {describe(spec)}")
    if isinstance(spec, Toward):
        a = resolve_point(mech, spec.start, entry, _depth + 1)
        b = resolve_point(mech, spec.toward, entry, _depth + 1)
        return _toward(spec, a, b, entry)
    return np.asarray(spec, dtype=float)


def _toward(spec: Toward, a: np.ndarray, b: np.ndarray, entry: str) -> np.ndarray:
    """Return the point of ``spec`` from its two points ``a`` and ``b`` resolved."""
    if _coincide(a, b):
        _fail(
            entry,
            f"points {describe(spec.start)} and {describe(spec.toward)} coincide; "
            "expected two distinct points",
        )
    length = float(np.hypot(*(b - a)))
    return a + (b - a) * (spec.distance / length)


def point_links(mech: Mechanism) -> dict[str, tuple[str, ...]]:
    """Return, for every named point, the links it belongs to.

    A joint's point belongs to both of its links, an extra point to its link.
    """
    owners: dict[str, tuple[str, ...]] = {j.name: tuple(j.links) for j in mech.joints}
    owners.update({p.name: (p.link,) for p in mech.points})
    return owners
