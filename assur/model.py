"""The mechanism model: links, joints, drivers, loads and extra points.

A :class:`Mechanism` is an immutable value. Every point is given where it lies in the
reference pose, an assembled pose of the mechanism; lengths, body-fixed offsets and
the assembly branch of every group are derived from that pose by later stages.
Validation happens here, once, so the numerical core can trust its input.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from os import PathLike
from typing import Any

from assur import _checks
from assur._checks import _fail, _tuples
from assur._load_checks import LoadTable
from assur._motor import Motor
from assur._points import PointSpec, Toward, Vec2, point_links, resolve_point
from assur._text import describe, suggest
from assur._validation import _validate
from assur.errors import UnknownNameError, UsageError

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

GROUND = _checks.GROUND
"""Name of the frame, the fixed link every mechanism has."""


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
        known = [link.name for link in self.links]
        msg = f"unknown link {describe(name)}{suggest(str(name), known)}"
        raise UnknownNameError(msg)

    def joint(self, name: str) -> Joint:
        """Return the joint called ``name``."""
        for joint in self.joints:
            if joint.name == name:
                return joint
        known = [joint.name for joint in self.joints]
        msg = f"unknown joint {describe(name)}{suggest(str(name), known)}"
        raise UnknownNameError(msg)


_PARTS = {
    "links": Link,
    "joints": Joint,
    "drivers": Driver,
    "loads": Load,
    "points": Point,
}


def _parts(entry: str, value: Any, kind: type) -> tuple[Any, ...]:
    """Return a mechanism's collection ``value`` as a tuple of ``kind``."""
    expected = f"expected a sequence of {kind.__name__}, got {describe(value)}"
    if isinstance(value, str | bytes | dict) or not isinstance(value, Iterable):
        _fail(entry, expected)
    try:
        items = tuple(value)
    except TypeError:  # Iterable, yet no sequence: a 0-d array
        _fail(entry, expected)
    for index, item in enumerate(items):
        if not isinstance(item, kind):
            _fail(
                f"{entry}[{index}]",
                f"expected a {kind.__name__}, got {describe(item)}",
            )
    return items


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
