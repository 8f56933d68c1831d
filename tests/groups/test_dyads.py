"""Invariants of every dyad kind driven by a crank, in both mirror images.

The mechanisms come from tests/mechanisms.py: a crank and one dyad of each kind, with
closed-form reference poses and random dimensions for which the dyad assembles over
the whole sweep. Mirror images: RRR in both assembly branches; RRP with the rod on the
crank and the slider on the frame or the rod on the frame and the slider on the crank;
RPR with the slide line fixed in the link pinned to the frame or to the crank; PRP and
RPP with every prismatic joint listed both ways (the slide line in either of its
links); RPR and RPP with a pin sliding directly in a slot (``slot``). Every joint may
also be listed the other way round (``flip``).

For each: (a) links stay rigid and points stay on their slide lines; (b) velocities,
accelerations and jerks equal central differences in time of the level below, within
the difference's own O(h^2) error; (c) the assembly branch of the reference pose is
kept and consecutive rows are linked smoothly; (d) the structure finds the kind.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import assur

from .. import oracle
from ..mechanisms import DYAD_STRATEGIES, bounded

SETTINGS = bounded(8)

VARIANTS = [
    ("RRR", {"flip": False, "branch": 1.0}),
    ("RRR", {"flip": False, "branch": -1.0}),
    ("RRR", {"flip": True, "branch": 1.0}),
    ("RRR", {"flip": True, "branch": -1.0}),
    ("RRP", {"attach": "crank", "flip": False}),
    ("RRP", {"attach": "crank", "flip": True}),
    ("RRP", {"attach": "frame", "flip": False}),
    ("RRP", {"attach": "frame", "flip": True}),
    ("RPR", {"guide": "link3", "flip": False}),
    ("RPR", {"guide": "link3", "flip": True}),
    ("RPR", {"guide": "link2", "flip": False}),
    ("RPR", {"guide": "link2", "flip": True}),
    ("PRP", {"flips": (False, False, False)}),
    ("PRP", {"flips": (True, False, True)}),
    ("PRP", {"flips": (False, True, False)}),
    ("PRP", {"flips": (True, True, True)}),
    ("RPP", {"attach": "crank", "flips": (False, False, False)}),
    ("RPP", {"attach": "crank", "flips": (True, True, True)}),
    ("RPP", {"attach": "crank", "flips": (True, False, False)}),
    ("RPP", {"attach": "frame", "flips": (False, False, False)}),
    ("RPP", {"attach": "frame", "flips": (True, True, True)}),
    ("RPP", {"attach": "frame", "flips": (False, True, True)}),
    ("RPR", {"slot": True, "flip": False}),
    ("RPR", {"slot": True, "flip": True}),
    ("RPP", {"attach": "crank", "slot": True, "flips": (False, False, False)}),
    ("RPP", {"attach": "crank", "slot": True, "flips": (False, True, False)}),
    ("RPP", {"attach": "frame", "slot": True, "flips": (False, False, False)}),
    ("RPP", {"attach": "frame", "slot": True, "flips": (False, True, False)}),
]


def _id(variant: tuple[str, dict]) -> str:
    kind, options = variant
    parts = [kind]
    for key, value in options.items():
        if isinstance(value, tuple):
            value = "".join("1" if v else "0" for v in value)
        parts.append(f"{key}={value}")
    return "-".join(parts)


parametrize = pytest.mark.parametrize(
    ("kind", "options"), VARIANTS, ids=[_id(v) for v in VARIANTS]
)


@parametrize
@SETTINGS
@given(data=st.data())
def test_structure_finds_the_kind(kind, options, data):
    case = data.draw(DYAD_STRATEGIES[kind](**options))
    found = assur.structure(case.mechanism)
    assert [g.kind for g in found.groups] == [kind]
    group = found.groups[0]
    assert (group.group_class, group.order) == (2, 2)
    assert set(group.links) == case.group
    assert [g.links for g in found.drivers] == [("ground", "crank")]
    assert found.dof == 1


@parametrize
@SETTINGS
@given(data=st.data())
def test_rigid_links_and_slides_on_one_branch(kind, options, data):
    case = data.draw(DYAD_STRATEGIES[kind](**options))
    mech = case.mechanism
    positions, dt = case.path(145)
    table = assur.kinematics(mech, positions)
    oracle.assert_rigid(mech, table)
    oracle.assert_slides(mech, table)
    oracle.assert_continuous(table, dt)
    if case.branch is not None:
        indicator = case.branch(table)
        assert (indicator > 0).all(), (
            f"branch left at rows {(indicator <= 0).nonzero()[0]}"
        )
    at_reference = assur.kinematics(mech, case.reference)
    oracle.assert_reference_pose(mech, at_reference, 0)


@parametrize
@SETTINGS
@given(data=st.data())
def test_derivatives_are_time_differences(kind, options, data):
    case = data.draw(DYAD_STRATEGIES[kind](**options))
    positions, _ = case.path(13)
    oracle.assert_differences(
        case.mechanism, oracle.si(case.mechanism, positions[1:-1])
    )
