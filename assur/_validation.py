"""The check of a whole mechanism: every reference and value, on the first fault.

:class:`~assur.model.Mechanism` runs :func:`_validate` when it is made. The variants
of a study share a skeleton (names, kinds, references), checked once; only their
numbers are checked again, in the same order, so the message is the same.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from assur._checks import (
    COINCIDENT,
    GROUND,
    JOINT_KINDS,
    MOST_FRICTION,
    _check_name,
    _check_number,
    _check_title,
    _check_unique,
    _check_vec,
    _coincide,
    _entry,
    _fail,
    _finite,
    _number_fault,
    _on_the_frame,
    _unknown,
    _vec_ok,
)
from assur._load_checks import LoadTable, _validate_load
from assur._motor import validate_motor
from assur._points import (
    Toward,
    _check_axis,
    _check_point,
    _check_resolvable,
    _resolver,
)
from assur._text import describe, key_text, listing, noun_for, spoken
from assur.errors import ModelError

if TYPE_CHECKING:
    from assur.model import Joint, Mechanism


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
        # the name is checked too (no control character in it)
        parts: list[Any] = [mech.name, mech.gravity is None]
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
            _check_point(entry, joint.at, names - {joint.name}, joint.name)
    for point in mech.points:
        if not _point_ok(point.at):
            entry = f"points.{key_text(point.name)}.at"
            _check_point(entry, point.at, names - {point.name}, point.name)
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
    _check_title(mech.name)
    link_names = _validate_links(mech)
    all_links = [GROUND, *link_names]
    joint_names = _validate_joints(mech, all_links)
    point_names = set(joint_names)
    for point in mech.points:
        entry = f"points.{key_text(point.name)}"
        _check_name(entry, point.name)
        _check_unique(entry, point.name, point_names, "a joint or point has the name")
        if point.link == GROUND:
            _fail(
                f"{entry}.link", _on_the_frame("a point on it never moves", link_names)
            )
        if not isinstance(point.link, str) or point.link not in link_names:
            _fail(f"{entry}.link", _unknown("link", point.link, link_names))
        point_names.add(point.name)
    for joint in mech.joints:
        entry = f"joints.{key_text(joint.name)}.at"
        _check_point(entry, joint.at, point_names - {joint.name}, joint.name)
    for point in mech.points:
        entry = f"points.{key_text(point.name)}.at"
        _check_point(entry, point.at, point_names - {point.name}, point.name)
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
            msg = f"{GROUND!r} is the frame and takes no entry; expected another name"
            _fail(entry, msg)
        _check_unique(entry, link.name, link_names, "two links with one name")
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
        _check_unique(entry, joint.name, joint_names, "two joints with one name")
        joint_names.append(joint.name)
        if not isinstance(joint.kind, str) or joint.kind not in JOINT_KINDS:
            _fail(
                f"{entry}.kind",
                f"unknown kind {describe(joint.kind)}; expected "
                + spoken(JOINT_KINDS, "or"),
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


def _validate_drivers(mech: Mechanism) -> None:
    joints = {joint.name: joint for joint in mech.joints}
    seen = set()
    for index, driver in enumerate(mech.drivers):
        entry = f"drivers[{index}]"
        if not isinstance(driver.joint, str) or driver.joint not in joints:
            _fail(f"{entry}.joint", _unknown("joint", driver.joint, joints))
        if driver.joint in seen:
            _fail(
                f"{entry}.joint",
                f"joint {describe(driver.joint)} is driven twice; expected each "
                "driver on a joint of its own",
            )
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
            names = listing([describe(j.name) for j in others], 4)
            _fail(
                f"drivers[{index}].joint",
                f"the input link {describe(link)} has its "
                f"{noun_for(len(others), 'joint')} {names} at the "
                f"pivot of {describe(joint.name)} (a crank of zero length), so the "
                "driver moves nothing; expected a joint of the input link away from "
                "its pivot",
            )
