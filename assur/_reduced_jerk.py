"""The crank's jerk in the steady motion: the rate of its equation of motion's epsilon.

With ``J(phi)`` the reduced inertia, ``M(phi)`` the reduced torque with the motor's
and ``w`` the crank's speed, the equation of motion gives
``epsilon = (M - J' w^2 / 2) / J``; its rate in time, ``w d(epsilon)/d(phi)``, is

    jerk = w (M' - J'' w^2 / 2 - 2 J' epsilon) / J,

as ``dw/dphi = epsilon / w``. ``J''`` comes exactly from the jerks at unit crank speed
(the third derivatives of the motion with respect to the crank angle), ``M'`` from
the reduced torque's interpolant.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._vec import Array
from assur.analysis import kinematics
from assur.model import Mechanism

__all__ = ["crank_jerk", "curvature"]


def curvature(mechanism: Mechanism, angles: Any) -> Array:
    r"""Return ``d2J/dphi2`` (kg m^2/rad^2) at the crank angles ``angles`` (deg).

    At unit crank speed and no crank acceleration or jerk, a point's velocity,
    acceleration and jerk are the first three derivatives of its path with respect
    to the crank angle, so that

    .. math::

        \frac{d^2 J}{d\varphi^2} = 2 \sum_L m_L (a_{G_L} \cdot a_{G_L}
        + v_{G_L} \cdot j_{G_L}) + J_{G_L} (\alpha_L^2 + \omega_L \dot\alpha_L).
    """
    links = [link for link in mechanism.links if link.mass]
    wanted = []
    for link in links:
        g = f"{link.name}.G"
        wanted += [f"{g}.{k}{axis}" for k in "vaj" for axis in "xy"]
        wanted += [f"{link.name}.{q}" for q in ("omega", "alpha", "jerk")]
    motion = kinematics(mechanism, angles, omega=1.0, epsilon=0.0, columns=wanted)
    out = np.zeros(len(motion))
    for link in links:
        g, m, jg = f"{link.name}.G", float(link.mass or 0.0), float(link.inertia or 0)
        v, a, j = ((motion[f"{g}.{k}x"], motion[f"{g}.{k}y"]) for k in "vaj")
        w, alpha, jerk = (
            motion[f"{link.name}.{q}"] for q in ("omega", "alpha", "jerk")
        )
        out += 2.0 * (
            m * (a[0] * a[0] + a[1] * a[1] + v[0] * j[0] + v[1] * j[1])
            + jg * (alpha * alpha + w * jerk)
        )
    return out


def crank_jerk(
    omega: Array,
    epsilon: Array,
    inertia: Array,
    slope: Array,
    curve: Array,
    rise: Array,
) -> Array:
    """Return the crank's jerk (rad/s^3) of the motion ``omega``, ``epsilon``.

    ``inertia``, ``slope`` and ``curve`` are ``J`` (the flywheel's in it), ``J'`` and
    ``J''``; ``rise`` is ``M'``, the slope of the reduced torque (N m/rad).
    """
    return (
        omega * (rise - 0.5 * curve * omega * omega - 2.0 * slope * epsilon) / inertia
    )  # type: ignore[no-any-return]
