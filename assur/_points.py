"""Points of the reference pose: how they are given, checked and resolved.

A point is given as coordinates, a joint's or extra point's name, or a
:class:`Toward`; :func:`resolve_point` turns any of them into coordinates (m), and the
model's validation checks every point of a mechanism resolves.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._checks import (
    _check_vec,
    _coincide,
    _entry,
    _fail,
    _finite,
    _no_entry,
    _number,
    _number_fault,
    _tuples,
    _unknown,
)
from assur._text import describe

if TYPE_CHECKING:
    from assur.model import Mechanism


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


def _spec_text(spec: object) -> str:
    """Return a point specification as the file writes it, shortened."""
    if isinstance(spec, Toward):
        return (
            f"{{from = {describe(spec.start)}, toward = {describe(spec.toward)}, "
            f"distance = {describe(spec.distance)}}}"
        )
    return describe(spec)


def _check_point(
    entry: str, spec: object, points: set[str], itself: str | None = None
) -> None:
    """Check a point's specification; ``itself``: the point it places, if named."""

    def known(where: str, ref: object) -> None:
        if itself is not None and ref == itself:
            _fail(
                where,
                f"the point {describe(itself)} is placed at itself; expected "
                "coordinates [x, y] or another point",
            )
        if not isinstance(ref, str) or ref not in points:
            _fail(where, _unknown("point", ref, points))

    if isinstance(spec, str):
        known(entry, spec)
    elif isinstance(spec, Toward):
        for key, ref in (("from", spec.start), ("toward", spec.toward)):
            known(f"{entry}.{key}", ref)
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


DEEPEST = 64
"""Most names a point's specification may lead through before its coordinates."""


def resolve_point(
    mech: Mechanism,
    spec: PointSpec,
    entry: str = "point",
    _path: tuple[str, ...] = (),
    _known: dict[str, np.ndarray] | None = None,
    _own: str = "",
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
    # each name resolved once: points toward the two before them each would
    # resolve those twice, and a chain of forty such 10^8 times
    known = {} if _known is None else _known
    if isinstance(spec, str) and spec in known:
        return known[spec]
    if isinstance(spec, str):
        if spec in _path:
            # the names met on the way, from the first of the circle back to it;
            # told from the entry's own point where the circle passes it
            ring = list(_path[_path.index(spec) :])
            start = ring.index(_own) if _own in ring else 0
            circle = (*ring[start:], *ring[:start], ring[start])
            _fail(
                entry,
                f"points refer to each other in a circle ({' -> '.join(circle)}); "
                "expected names that lead to coordinates [x, y]",
            )
        if len(_path) >= DEEPEST:
            msg = f"points refer to each other more than {DEEPEST} deep"
            _fail(entry, f"{msg}; expected a shorter chain of names")
        named = [j.at for j in mech.joints if j.name == spec] or [
            p.at for p in mech.points if p.name == spec
        ]
        if not named:
            _fail(entry, f"unknown point {describe(spec)}")
        path = (*_path, spec)
        known[spec] = resolve_point(mech, named[0], entry, path, known, _own)
        return known[spec]
    if isinstance(spec, Toward):
        a = resolve_point(mech, spec.start, entry, _path, known, _own)
        b = resolve_point(mech, spec.toward, entry, _path, known, _own)
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

    def resolve(spec: PointSpec, entry: str = "point", own: str = "") -> np.ndarray:
        if spec.__class__ is tuple:
            return np.asarray(spec, dtype=float)  # as resolve_point does
        # names are unique by now: ``plain`` holds the one point of each name
        if spec.__class__ is str and spec in plain:
            return plain[spec]  # type: ignore[index]
        if isinstance(spec, Toward) and spec.start in plain and spec.toward in plain:
            return _toward(spec, plain[spec.start], plain[spec.toward], entry)
        return resolve_point(mech, spec, entry, _own=own)

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
        resolve(joint.at, where("joints", joint.name, ".at"), joint.name)
    for point in mech.points:
        resolve(point.at, where("points", point.name, ".at"), point.name)
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


def point_links(mech: Mechanism) -> dict[str, tuple[str, ...]]:
    """Return, for every named point, the links it belongs to.

    A joint's point belongs to both of its links, an extra point to its link.
    """
    owners: dict[str, tuple[str, ...]] = {j.name: tuple(j.links) for j in mech.joints}
    owners.update({p.name: (p.link,) for p in mech.points})
    return owners


def moves_with(mech: Mechanism, point: str, link: str) -> bool:
    """Return whether the named point is one point of ``link`` at every position.

    A revolute joint's point moves with both its links, a prismatic or slot joint's
    with its second link only (it slides along the first), an extra point with its
    link. Elsewhere the name stands for where the point is in the reference pose.
    """
    for joint in mech.joints:
        if joint.name == point:
            return link == joint.links[1] or (
                joint.kind == "revolute" and link == joint.links[0]
            )
    return any(p.name == point and p.link == link for p in mech.points)
