"""A wedge lifter (a PRP group on a prismatic driver), written from the file format.

A ram driven along the x axis, slowing down, carries a 20 degree wedge face; a shoe
slides on it, pinned to a follower on a vertical guide that lifts a 2 kN load. Held
to the oracle's global solve (with and without friction), virtual power, finite
differences and the note's arithmetic; by hand, the follower moves at the ram's
speed times tan 20 deg, and the face's normal force carries the follower's load.
"""

from __future__ import annotations

import math

import numpy as np

import assur

from . import usercheck

MECH = usercheck.load("wedge_lifter")
STROKE = usercheck.POSITIONS["wedge_lifter"]


def _slope() -> float:
    face = next(j for j in MECH.joints if j.name == "face")
    return math.atan2(face.axis[1], face.axis[0])


def test_follower_moves_by_the_wedge_slope():
    table = assur.kinematics(MECH, STROKE)
    drive = MECH.drivers[0]
    rise = -math.tan(_slope())
    np.testing.assert_allclose(table["guide2.v"], rise * drive.omega, rtol=1e-12)
    np.testing.assert_allclose(table["guide2.a"], rise * drive.epsilon, rtol=1e-12)


def test_face_normal_force_carries_the_follower():
    table = assur.forces(MECH, STROKE)
    lifted = [lk for lk in MECH.links if lk.name in ("shoe", "follower")]
    mass = sum(lk.mass for lk in lifted)
    g = -MECH.gravity[1]
    load = -sum(ld.force[1] for ld in MECH.loads)
    # vertical balance of shoe and follower: the guide pushes only sideways
    weight = mass * (g + table["guide2.a"]) + load
    normal = np.hypot(table["face.Fx"], table["face.Fy"])
    np.testing.assert_allclose(normal * math.cos(_slope()), weight, rtol=1e-12)
