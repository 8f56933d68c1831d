"""Ready-made mechanisms for examples, doctests and quick experiments.

Each function computes an assembled reference pose from the dimensions it is given.
"""

from __future__ import annotations

import math

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

    Examples
    --------
    >>> four_bar().name
    'Four-bar (crank-rocker)'
    """
    a = math.radians(angle)
    b = (crank * math.cos(a), crank * math.sin(a))
    dx, dy = frame - b[0], -b[1]
    dist = math.hypot(dx, dy)
    along = (coupler**2 - rocker**2 + dist**2) / (2 * dist)
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

    Examples
    --------
    >>> slider_crank().drivers[0].omega
    200.0
    """
    a = math.radians(angle)
    b = (crank * math.cos(a), crank * math.sin(a))
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
