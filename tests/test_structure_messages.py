"""What the structural analysis says where a count misleads, or a teacher reads it.

The freedom a chain has at its pose (the rank of its joints' velocity equations),
seen against the count W: a passive constraint (a third parallel crank), a rigid
triangle, three pins in line; drivers put on the wrong part of a chain; the words of
the structure report and of the note's first part.
"""

from __future__ import annotations

import dataclasses

import pytest

import assur
from assur import DecompositionError
from assur._freedom import pose_freedom
from assur._topology import topology
from assur.cli import main

from .conftest import EXAMPLES
from .test_structure import build

PARALLELOGRAM = [
    ("A", "R", ("ground", "2"), (0.0, 0.0)),
    ("B", "R", ("2", "3"), (0.0, 0.1)),
    ("C", "R", ("3", "4"), (0.2, 0.1)),
    ("D", "R", ("ground", "4"), (0.2, 0.0)),
]
THIRD_CRANK = [
    ("E", "R", ("3", "5"), (0.1, 0.1)),
    ("F", "R", ("ground", "5"), (0.1, 0.0)),
]


def test_a_third_parallel_crank_moves_though_the_count_says_rigid() -> None:
    # W = 3*4 - 2*6 = 0, yet the parallelogram still turns: q = 1 repeated constraint
    mech = build(PARALLELOGRAM + THIRD_CRANK, ["A"])
    assert assur.mobility(mech) == 0
    assert pose_freedom(topology(mech)) == 1
    with pytest.raises(DecompositionError) as err:
        assur.structure(mech)
    text = str(err.value)
    assert (
        "W = 3*4 - 2*6 - 0 = 0 degrees of freedom but 1 driver, yet the chain " in text
    )
    assert "moves at its pose (1 degree of freedom): 1 passive constraint (W = " in text
    assert "W = 3n - 2p5 - p4 + q, q = 1), such as a third parallel crank" in text
    assert text.endswith(
        "expected no repeated constraint: remove the redundant link or joint (or "
        "move a joint off the line), then one driver per degree of freedom"
    )
    assert len(text) < 400
    # the same crank off parallel (F moved) locks the chain: rigid, as counted
    skew = build(
        [*PARALLELOGRAM, THIRD_CRANK[0], ("F", "R", ("ground", "5"), (0.13, 0.0))],
        ["A"],
    )
    assert pose_freedom(topology(skew)) == 0
    with pytest.raises(
        DecompositionError,
        match=r"1 driver: the chain is a statically determinate structure \(a truss\), "
        "not a mechanism; exp",
    ):
        assur.structure(skew)


@pytest.mark.parametrize(
    ("joints", "free"),
    [
        # a triangle on the frame: rigid
        (
            [
                ("O", "R", ("ground", "a"), (0, 0)),
                ("P", "R", ("a", "b"), (0.05, 0.05)),
                ("Q", "R", ("b", "ground"), (0.1, 0)),
            ],
            0,
        ),
        # the same with its three pins in line: it moves at that pose (a toggle)
        (
            [
                ("O", "R", ("ground", "a"), (0, 0)),
                ("P", "R", ("a", "b"), (0.05, 0.0)),
                ("Q", "R", ("b", "ground"), (0.1, 0)),
            ],
            1,
        ),
        # a slider-crank: 1, whatever the slide line's slant
        (
            [
                ("A", "R", ("ground", "c"), (0, 0)),
                ("B", "R", ("c", "r"), (0.03, 0.04)),
                ("C", "R", ("r", "s"), (0.15, 0.02)),
                ("G", "P", ("ground", "s"), (0.15, 0.02), (0.98, 0.2)),
            ],
            1,
        ),
        # a block on a guide with two slide lines: one sliding pair counted twice
        (
            [
                ("G", "P", ("ground", "s"), (0, 0), (1.0, 0.0)),
                ("H", "P", ("ground", "s"), (0, 0.1), (1.0, 0.0)),
            ],
            1,
        ),
        # a block whose slide line is the crank pin's tangent: a toggle, it moves
        (
            [
                ("O", "R", ("ground", "c"), (0, 0)),
                ("B", "R", ("c", "s"), (0.6, 0.8)),
                ("G", "P", ("ground", "s"), (0.6, 0.8), (-0.8, 0.6)),
            ],
            1,
        ),
        # the same slide line along the crank: rigid
        (
            [
                ("O", "R", ("ground", "c"), (0, 0)),
                ("B", "R", ("c", "s"), (0.6, 0.8)),
                ("G", "P", ("ground", "s"), (0.6, 0.8), (0.6, 0.8)),
            ],
            0,
        ),
        # a crank and a link hanging on it: two turns
        ([("A", "R", ("ground", "c"), (0, 0)), ("B", "R", ("c", "r"), (1.0, 0))], 2),
    ],
)
def test_the_freedom_at_the_pose_counts_what_moves(joints, free) -> None:
    assert pose_freedom(topology(build(joints, []))) == free


def test_a_truss_without_driver_gives_its_count_worked_out() -> None:
    # W = 3*3 - 2*6 = -3: said as it is, not as 0
    joints = [
        ("A", "R", ("ground", "2"), (0, 0)),
        ("B", "R", ("2", "3"), (0.1, 0.1)),
        ("C", "R", ("ground", "3"), (0.2, 0)),
        ("D", "R", ("ground", "4"), (0.3, 0)),
        ("E", "R", ("4", "3"), (0.25, 0.15)),
        ("F", "R", ("4", "2"), (0.15, 0.2)),
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(joints, []))
    assert str(err.value).startswith(
        "drivers: the mechanism has no driver, and W = 3*3 - 2*6 - 0 = -3: the chain "
        "is a statically indeterminate structure (3 redundant constraints), not a "
        "mechanism"
    )
    # a parallelogram with a third crank and no driver moves: not called rigid
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(PARALLELOGRAM + THIRD_CRANK, []))
    assert "= 0, yet the chain moves at its pose" in str(err.value)
    assert "structure (" not in str(err.value)
    assert str(err.value).endswith(
        "expected no repeated constraint: remove the redundant link or joint (or "
        "move a joint off the line), then a [[drivers]] entry for each degree of "
        "freedom"
    )
    # two cranks more than a parallelogram needs: W = -1, two constraints repeated
    fourth = [
        ("E2", "R", ("3", "6"), (0.05, 0.1)),
        ("F2", "R", ("ground", "6"), (0.05, 0.0)),
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(PARALLELOGRAM + THIRD_CRANK + fourth, []))
    assert (
        "(1 degree of freedom): 2 passive constraints (W = 3n - 2p5 - p4 + q, q = 2)"
        in str(err.value)
    )
    # a slot counted as p4 in the count worked out
    slot = dataclasses.replace(assur.load(EXAMPLES / "slot_mechanism.toml"), drivers=())
    with pytest.raises(DecompositionError) as err:
        assur.structure(slot)
    assert "W = 3*4 - 2*5 - 1 = 1 degree of freedom but 0 drivers" in str(err.value)


def test_two_drivers_on_one_loop_and_none_on_another_are_named() -> None:
    # two four-bars side by side (W = 2), both drivers on the first
    first = [
        *PARALLELOGRAM[:2],
        ("C", "R", ("3", "4"), (0.16, 0.12)),
        ("D", "R", ("ground", "4"), (0.14, 0)),
    ]
    second = [
        (
            j + "2",
            kind,
            tuple(x if x == "ground" else str(int(x) + 3) for x in links),
            (at[0] + 1.0, at[1]),
        )
        for j, kind, links, at in first
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(first + second, ["A", "D"]))
    assert str(err.value).endswith(
        "because links 5, 6 and 7 can move (3k - 2p = 1) with no input, while link 3 "
        "is over-constrained (3k - 2p = -1): the drivers are on the wrong part; "
        "expected a driver moved to joint A2 or D2"
    )
    assert assur.structure(build(first + second, ["A", "D2"])).formula.count("II") == 2
    # a part that moves but has no joint to the frame takes no driver: the link
    # over-constrained is what is named
    between = [
        ("P", "R", ("2", "5"), (0.02, 0.1)),
        ("Q", "R", ("5", "6"), (0.06, 0.2)),
        ("S", "R", ("6", "7"), (0.12, 0.2)),
        ("U", "R", ("7", "4"), (0.15, 0.08)),
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(first + between, ["A", "D"]))
    assert "wrong part" not in str(err.value)
    assert "link 3 is held to the known links by joints B and C" in str(err.value)
    # nor a link that hangs on one joint to the frame: it is named as such
    hanging = [("P", "R", ("ground", "5"), (0.3, 0.3))]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(first + hanging, ["A", "D"]))
    assert "wrong part" not in str(err.value)
    assert "link 5 hangs on joint P alone" in str(err.value)


def test_the_driver_option_takes_a_list_with_spaces(capsys) -> None:
    path = EXAMPLES / "five_bar_two_cranks.toml"
    drivers = [d.joint for d in assur.load(path).drivers]
    assert main(["structure", "--driver", ", ".join(drivers), str(path)]) == 0
    assert "Structure of" in capsys.readouterr().out
    # a trailing comma or a space around one name: the name alone
    four_bar = str(EXAMPLES / "four_bar.toml")
    for given in ("O2,", " O2 "):
        assert main(["structure", "--driver", given, four_bar]) == 0
        assert "driven through pair O2" in capsys.readouterr().out


@pytest.mark.parametrize("given", ["", " ", ","])
def test_a_driver_option_naming_no_joint_says_so(capsys, given: str) -> None:
    # it was taken for no driver at all: "the mechanism has ... 0 drivers"
    path = str(EXAMPLES / "four_bar.toml")
    assert main(["structure", "--driver", given, path]) == 2
    assert capsys.readouterr().err == (
        f"assur: error: structure: argument --driver: no joint named in {given!r}; "
        "expected a joint name (see 'assur structure --help')\n"
    )


def test_an_unknown_driver_lists_the_joints_with_the_frame(capsys) -> None:
    path = EXAMPLES / "four_bar.toml"
    assert main(["structure", "--driver", "Zq9", str(path)]) == 2
    err = capsys.readouterr().err
    frame = sorted(j.name for j in assur.load(path).joints if "ground" in j.links)
    assert f"unknown joint 'Zq9' (joints with the frame: {', '.join(frame)})" in err


def test_the_note_says_why_a_group_is_of_its_class() -> None:
    note = str(assur.explain(assur.load(EXAMPLES / "class3.toml"), 30.0))
    assert (
        "triad (rod, plate, left_rocker, right_rocker): internal pairs C, D and E; "
        "external pairs B, F and G on the known links crank (B) and ground (F and G). "
        "Why an Assur "
        "group: $k = 4$ links, $p = 6$ lower pairs" in note
    )
    # the counts typeset as the note's other formulas, minus signs and all
    assert (
        "$W = 3k - 2p = 12 - 12 = 0$, and every smaller part of it keeps $W > 0$"
        in (note)
    )
    assert "Why class III: its base link plate carries three internal pairs" in note
    assert (
        "the force analysis in the reverse order, ending with the input link." in note
    )


def test_a_crank_alone_is_said_to_have_no_group() -> None:
    crank = build([("A", "R", ("ground", "c"), (0, 0))], ["A"])
    s = assur.structure(crank)
    assert str(s).splitlines()[-1] == (
        "Kinematics and the force analysis take the input link alone."
    )
    assert "groups in this order" not in str(s)
    note = str(assur.explain(crank, 30.0))
    assert (
        "With no Assur group, the kinematic and the force analysis take the input "
        "link alone." in note
    )
    assert "the groups in this order" not in note


def test_groups_that_do_not_hang_on_each_other_are_said_to() -> None:
    # the ten-bar's RRP dyad (6, 7) hangs on link 2 and the frame, not on the dyad
    # (4, 5) the arrow of the formula puts before it
    text = str(assur.structure(assur.load(EXAMPLES / "tenbar.toml")))
    said = [line.strip() for line in text.splitlines() if "either order" in line]
    assert said == [
        "II(6, 7) is attached to links 2 and ground, not to II(4, 5): the two "
        "groups could be attached in either order."
    ]
    note = str(assur.explain(assur.load(EXAMPLES / "tenbar.toml"), 30.0))
    assert "mechanism. II(6, 7) is attached to links 2 and ground, not to" in note
    # a chain where each group hangs on the one before: nothing to say
    assert "either order" not in str(
        assur.structure(assur.load(EXAMPLES / "class3.toml"))
    )


def test_a_triad_names_its_prismatic_pairs() -> None:
    # a dyad's kind (RRP, ...) names its sliding pairs; a triad said nothing of its
    triad = build(
        [
            ("A", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "rod"), (0.035, 0.02)),
            ("C", "P", ("rod", "plate"), (0.24, -0.03), (1.0, -0.2)),
            ("D", "R", ("plate", "lr"), (0.2, 0.02)),
            ("E", "R", ("plate", "rr"), (0.3, 0.03)),
            ("F", "R", ("ground", "lr"), (0.2, 0.2)),
            ("G", "R", ("ground", "rr"), (0.31, 0.21)),
        ],
        ["A"],
    )
    s = assur.structure(triad)
    (group,) = s.groups
    assert (group.kind, group.sliding) == ("triad", ("C",))
    assert "; prismatic pair C, the others revolute." in str(s)
    assert s.to_dict()["groups"][0]["sliding_pairs"] == ["C"]
    note = str(assur.explain(triad, 0.0))
    assert "on the known links crank (B) and ground (F and G); prismatic pair C" in note
    # an all-revolute triad and a dyad: no such words
    assert "prismatic pair" not in str(
        assur.structure(assur.load(EXAMPLES / "class3.toml"))
    )
    assert "sliding_pairs" not in str(
        assur.structure(assur.catalog.slider_crank()).to_dict()
    )


LOOP_WITH_SLOT = [
    ("G5", "R", ("ground", "5"), (1.0, 0.0)),
    ("H", "R", ("5", "6"), (1.0, 0.1)),
    ("S", "S", ("ground", "6"), (1.2, 0.1), (1.0, 0.0)),
]


def test_drivers_on_the_wrong_part_name_no_slot_as_a_driver() -> None:
    # a slot (or its pin) to the frame cannot take a driver: the pin joint G5 can
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(PARALLELOGRAM + LOOP_WITH_SLOT, ["A", "D"]))
    assert str(err.value).endswith("expected a driver moved to joint G5")
    # names of 60 characters: the parts are counted, and the line stays short
    long = "x" * 60

    def named(joints):
        return [
            (
                j + long,
                kind,
                tuple(x if x == "ground" else x + long for x in links),
                *rest,
            )
            for j, kind, links, *rest in joints
        ]

    with pytest.raises(DecompositionError) as err:
        assur.structure(
            build(named(PARALLELOGRAM + LOOP_WITH_SLOT), ["A" + long, "D" + long])
        )
    text = str(err.value)
    assert len(text) < 400
    assert text.startswith("4 links are left over, in no Assur group on the 3 known")
    assert "3 of them can move (3k - 2p = 1) with no input, while 1 is over-" in text


def test_a_part_apart_from_the_frame_is_named_before_a_passive_constraint() -> None:
    # a triangle on the frame and four links braced to each other but to nothing
    # else: W = 0 by the count; it was "3 passive constraints, remove a link"
    apart = [
        ("A", "R", ("ground", "2"), (0.0, 0.0)),
        ("B", "R", ("2", "3"), (0.1, 0.1)),
        ("C", "R", ("ground", "3"), (0.2, 0.0)),
        ("P", "R", ("4", "5"), (1.0, 0.0)),
        ("Q", "R", ("5", "6"), (1.1, 0.1)),
        ("U", "R", ("6", "7"), (1.2, 0.0)),
        ("V", "R", ("7", "4"), (1.1, -0.1)),
        ("X", "R", ("4", "6"), (1.05, 0.05)),
        ("Y", "R", ("5", "7"), (1.15, 0.05)),
    ]
    assert assur.mobility(build(apart, [])) == 0
    for drivers in ([], ["A"]):
        with pytest.raises(DecompositionError) as err:
            assur.structure(build(apart, drivers))
        assert str(err.value).endswith(
            ", as links 4, 5, 6 and 7 are joined to the frame by no chain of joints; "
            "expected every link joined to the frame through joints"
        )
    # three pins in line: moving a joint off the line is said as the remedy too
    in_line = [
        ("A", "R", ("ground", "2"), (0.0, 0.0)),
        ("B", "R", ("2", "3"), (0.1, 0.0)),
        ("C", "R", ("ground", "3"), (0.2, 0.0)),
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(in_line, []))
    assert "or joints in line; expected no repeated constraint" in str(err.value)
    assert "(or move a joint off the line)" in str(err.value)


def test_drivers_on_the_wrong_part_of_five_links_name_three_and_a_choice() -> None:
    # the four-bar of two drivers beside the lecture's six-bar of none: the five
    # links that can move are named three and counted, and the joints a driver
    # may take read as a choice, where "A2 or D2 or G2" was written
    from assur.model import resolve_point

    six = assur.load(EXAMPLES / "six_bar_lecture.toml")
    second = [
        (
            j.name + "2",
            "R",
            tuple(x if x == "ground" else "s" + x for x in j.links),
            (at[0] + 1.0, at[1]),
        )
        for j in six.joints
        for at in [resolve_point(six, j.at)]
    ]
    first = [
        *PARALLELOGRAM[:2],
        ("C", "R", ("3", "4"), (0.16, 0.12)),
        ("D", "R", ("ground", "4"), (0.14, 0)),
    ]
    with pytest.raises(DecompositionError) as err:
        assur.structure(build(first + second, ["A", "D"]))
    assert str(err.value).endswith(
        "because links s2, s3, s4, ... (5 in all) can move (3k - 2p = 1) with no "
        "input, while link 3 is over-constrained (3k - 2p = -1): the drivers are on "
        "the wrong part; expected a driver moved to joint A2, D2 or G2"
    )
