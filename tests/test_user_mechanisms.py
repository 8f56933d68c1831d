"""The checks every user's mechanism (tests/data/users) is held to, one test each.

Each file there was written from the file format alone; each mechanism's own
physics (a slide's law of cosines, a trammel's ellipse, a wedge's slope) is tested
in its own file, tests/test_user_<name>.py.
"""

from __future__ import annotations

import pytest

from . import usercheck

NAMES = sorted(usercheck.POSITIONS)


@pytest.mark.parametrize("name", NAMES)
def test_matches_the_global_solve_with_and_without_friction(name):
    usercheck.assert_global_solve(usercheck.load(name), usercheck.POSITIONS[name])


@pytest.mark.parametrize("name", NAMES)
def test_driver_power_balances_the_loads(name):
    usercheck.assert_virtual_power(usercheck.load(name), usercheck.POSITIONS[name])


@pytest.mark.parametrize("name", NAMES)
def test_kinematics_are_rigid_and_differentiate(name):
    usercheck.assert_kinematics(usercheck.load(name), usercheck.POSITIONS[name])


@pytest.mark.parametrize("name", NAMES)
def test_note_holds_at_two_positions(name):
    mech = usercheck.load(name)
    for position in usercheck.NOTED[name]:
        usercheck.assert_note(mech, position)
