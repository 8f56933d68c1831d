"""Ready-made mechanisms for examples, doctests and quick experiments.

Each function computes an assembled reference pose from the dimensions it is given.
"""

from __future__ import annotations

import math
from typing import Any

from assur._checks import LARGEST
from assur._text import describe
from assur._vec import real
from assur.errors import ModelError
from assur.model import Driver, Joint, Link, Mechanism, Point, Toward

__all__ = ["four_bar", "slider_crank"]


def four_bar(
    crank: float = 0.04,
    coupler: float = 0.12,
    rocker: float = 0.08,
    frame: float = 0.10,
    angle: float = 60.0,
    omega: float = 10.0,
) -> Mechanism:
    """Build a crank-rocker four-bar A-B-C-D with pivots A = (0, 0), D = (frame, 0).

    Parameters
    ----------
    crank, coupler, rocker, frame : float
        Link lengths, m.
    angle : float
        Crank angle of the reference pose, deg.
    omega : float
        Crank speed, rad/s.

    Returns
    -------
    Mechanism
        Steel-like bars (mass 2 kg/m, inertia of a slender bar) and a coupler point P.

    Raises
    ------
    ModelError
        For a length that is not a number above 0, or links that cannot close at
        ``angle``.

    Examples
    --------
    >>> four_bar().name
    'Four-bar (crank-rocker)'
    """
    crank, coupler, rocker, frame = (
        _length(name, value)
        for name, value in zip(
            ("crank", "coupler", "rocker", "frame"),
            (crank, coupler, rocker, frame),
            strict=True,
        )
    )
    angle, omega = _number("angle", angle), _number("omega", omega)
    a = math.radians(angle)
    b = (crank * math.cos(a), crank * math.sin(a))
    dx, dy = frame - b[0], -b[1]
    dist = math.hypot(dx, dy)
    along = (coupler**2 - rocker**2 + dist**2) / (2 * dist) if dist > 0 else 0.0
    # h^2 is checked too: near one line, round-off passes the strict test and
    # leaves h^2 just below 0 (frame=1e-20: a math domain error)
    if not abs(coupler - rocker) < dist < coupler + rocker or coupler**2 <= along**2:
        msg = (
            f"four_bar: the coupler ({coupler:g} m) and the rocker ({rocker:g} m) "
            f"cannot join the crank's pin to the pivot D {dist:g} m away at "
            f"{angle:g} deg; expected the two to reach it, and not in one line"
        )
        raise ModelError(msg)
    h = math.sqrt(coupler**2 - along**2)
    c = (b[0] + (along * dx - h * dy) / dist, b[1] + (along * dy + h * dx) / dist)

    def bar(name: str, start: str, end: str, length: float) -> Link:
        mass = 2.0 * length
        return Link(
            name,
            (start, end),
            mass,
            Toward(start, end, length / 2),
            mass * length**2 / 12,
        )

    return Mechanism(
        links=(
            bar("crank", "A", "B", crank),
            bar("coupler", "B", "C", coupler),
            bar("rocker", "D", "C", rocker),
        ),
        joints=(
            Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
            Joint("B", "revolute", ("crank", "coupler"), b),
            Joint("C", "revolute", ("coupler", "rocker"), c),
            Joint("D", "revolute", ("ground", "rocker"), (frame, 0.0)),
        ),
        drivers=(Driver("A", omega),),
        name="Four-bar (crank-rocker)",
        points=(Point("P", "coupler", Toward("B", "C", coupler / 2)),),
    )


def slider_crank(
    crank: float = 0.074,
    rod: float = 0.200,
    offset: float = 0.0,
    angle: float = 45.0,
    omega: float = 200.0,
) -> Mechanism:
    """Build the slider-crank of the kinetostatics lecture's exercise.

    Masses 10, 0.5 and 0.4 kg; crank centre of mass 0.020 m from A, rod's 0.060 m
    from B, rod inertia 0.0018 kg m^2; the slide line is ``y = offset``.

    Parameters
    ----------
    crank, rod : float
        Link lengths, m: the crank A-B from the pivot A = (0, 0), the rod B-C to the
        slider's pin C.
    offset : float
        Height of the slide line above the pivot A, m.
    angle : float
        Crank angle of the reference pose, deg.
    omega : float
        Crank speed, rad/s.

    Returns
    -------
    Mechanism
        Links crank, rod and slider; joints A, B, C and the horizontal guide.

    Raises
    ------
    ModelError
        For a length that is not a number above 0, or a rod that cannot reach the
        slide line at ``angle``.

    Examples
    --------
    >>> slider_crank().drivers[0].omega
    200.0
    """
    crank, rod = _length("crank", crank), _length("rod", rod)
    offset, angle = _number("offset", offset), _number("angle", angle)
    omega = _number("omega", omega)
    a = math.radians(angle)
    b = (crank * math.cos(a), crank * math.sin(a))
    if not rod > abs(offset - b[1]):
        msg = (
            f"slider_crank: the rod ({rod:g} m) cannot reach the slide line "
            f"{abs(offset - b[1]):g} m from the crank's pin at {angle:g} deg; "
            "expected a longer rod"
        )
        raise ModelError(msg)
    c = (b[0] + math.sqrt(rod**2 - (offset - b[1]) ** 2), offset)
    return Mechanism(
        links=(
            Link("crank", ("A", "B"), 10.0, Toward("A", "B", 0.020), 0.0),
            Link("rod", ("B", "C"), 0.5, Toward("B", "C", 0.060), 0.0018),
            Link("slider", None, 0.4, "C", 0.0),
        ),
        joints=(
            Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
            Joint("B", "revolute", ("crank", "rod"), b),
            Joint("C", "revolute", ("rod", "slider"), c),
            Joint("guide", "prismatic", ("ground", "slider"), c, (1.0, 0.0)),
        ),
        drivers=(Driver("A", omega),),
        name="Slider-crank exercise",
    )


def _number(name: str, value: Any) -> float:
    """Return ``value`` as a finite float; a ModelError naming ``name`` if not."""
    number = real(value)
    if number is None or not math.isfinite(number):
        msg = f"{name}: expected a finite number, got {describe(value)}"
        raise ModelError(msg)
    if abs(number) > LARGEST:
        # the model refuses such numbers too; the geometry's squares overflowed first
        msg = (
            f"{name}: expected a number of magnitude at most {LARGEST:g}, got "
            f"{describe(value)}"
        )
        raise ModelError(msg)
    return number


def _length(name: str, value: Any) -> float:
    """Return ``value`` as a length above 0 (m); a ModelError naming ``name`` if not."""
    number = _number(name, value)
    if not number > 0.0:
        msg = f"{name}: expected a length above 0 (m), got {describe(value)}"
        raise ModelError(msg)
    return number
