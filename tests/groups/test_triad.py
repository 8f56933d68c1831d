"""Invariants of a class III triad (ternary plate and three binary links, six revolute
pairs) driven by a crank.

The mechanisms are the bundled class III example with every frame pivot and plate pin
moved at random by up to 12 mm (tests/mechanisms.py); the sweep covers the range of
crank angles on which the test's own Newton continuation finds the triad assembled and
well conditioned (a whole turn for most). Checks as for the dyads: rigid links, the
reference pose kept as the branch and no jump between rows, derivatives equal to
central differences in time, and the structure's class III group.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given

import assur

from .. import oracle
from ..mechanisms import bounded, triad_cases

SETTINGS = bounded(12)


@SETTINGS
@given(case=triad_cases())
def test_structure_finds_the_triad(case):
    found = assur.structure(case.mechanism)
    assert len(found.groups) == 1
    group = found.groups[0]
    assert (group.kind, group.group_class, group.order) == ("triad", 3, 3)
    assert set(group.links) == case.group
    assert set(group.external) == {"B", "F", "G"}
    assert set(group.internal) == {"C", "D", "E"}
    assert found.mechanism_class == 3


@SETTINGS
@given(case=triad_cases())
def test_rigid_links_on_one_branch(case):
    mech = case.mechanism
    positions, dt = case.path(121)
    table = assur.kinematics(mech, positions)
    oracle.assert_rigid(mech, table)
    oracle.assert_continuous(table, dt)
    oracle.assert_reference_pose(mech, assur.kinematics(mech, case.reference), 0)


@SETTINGS
@given(case=triad_cases())
def test_derivatives_are_time_differences(case):
    positions, _ = case.path(13)
    oracle.assert_differences(
        case.mechanism, oracle.si(case.mechanism, positions[1:-1])
    )


@SETTINGS
@given(case=triad_cases())
def test_sweep_order_does_not_matter(case):
    """A row does not depend on the other rows of the sweep (the continuation runs from
    the reference pose to each position, not from row to row)."""
    positions, _ = case.path(25)
    table = assur.kinematics(case.mechanism, positions)
    shuffled = np.random.default_rng(0).permutation(len(positions))
    other = assur.kinematics(case.mechanism, positions[shuffled])
    for column in ("C.x", "C.y", "D.x", "D.y", "E.vx", "plate.alpha", "left.jerk"):
        np.testing.assert_allclose(
            other[column], table[column][shuffled], rtol=1e-9, atol=1e-9, err_msg=column
        )
