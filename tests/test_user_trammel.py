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
STROKE = usercheck.POSITIONS["trammel_slider_driven"]


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
