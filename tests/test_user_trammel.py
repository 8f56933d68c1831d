"""An elliptical trammel driven by a slider, written from the file format.

Block 1 is driven along the x axis (a prismatic driver), block 2 slides on the y
axis, the rod AB joins them (an RRP group); a tool point P on the rod beyond B
carries a load. Held to the oracle's global solve (with and without friction),
virtual power, finite differences and the note's arithmetic; by hand, P draws the
ellipse of semi-axes |AP - AB| along x and |AP| along y, and the dead centre (the
rod along the x guide) is refused.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import assur

from . import oracle, usercheck

MECH = usercheck.load("trammel_slider_driven")
STROKE = np.linspace(-0.06, 0.06, 13)


def test_matches_the_global_solve_with_and_without_friction():
    usercheck.assert_global_solve(MECH, STROKE)


def test_driver_power_balances_the_loads():
    usercheck.assert_virtual_power(MECH, STROKE)


def test_kinematics_are_rigid_and_differentiate():
    usercheck.assert_kinematics(MECH, STROKE)


def test_tool_point_draws_the_ellipse():
    a, b, p = (np.asarray(oracle.resolve(MECH, n)) for n in ("A", "B", "P"))
    rod, reach = math.dist(a, b), math.dist(a, p)
    table = assur.kinematics(MECH, STROKE)
    x, y = table["P.x"], table["P.y"]
    np.testing.assert_allclose(
        (x / (reach - rod)) ** 2 + (y / reach) ** 2, 1.0, rtol=1e-12
    )


def test_dead_centre_is_refused():
    a, b = (np.asarray(oracle.resolve(MECH, n)) for n in ("A", "B"))
    # block 1 where the rod lies along the x guide
    flat = math.dist(a, b) - a[0]
    with pytest.raises(assur.SingularConfigurationError, match="dead centre"):
        assur.forces(MECH, [flat])


def test_note_holds_at_two_positions():
    usercheck.assert_note(MECH, -0.05)
    usercheck.assert_note(MECH, 0.04)
