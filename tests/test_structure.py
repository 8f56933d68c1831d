"""Structural analysis: mobility, Assur-group decomposition and the structure report.

Decompositions of the bundled examples (the expected groups are stated in each file's
header comment) and of small mechanisms built here: every dyad kind in both mirror
images, a class III triad, a class IV group of order 2, a two-driver five-bar, a six-bar
whose class depends on its input link, a slot replaced by a block, and the failures
(wrong number of drivers, links left over, two joints between two links, rigid parts
and chains that are no minimal Assur groups).
"""

from __future__ import annotations

import dataclasses
import importlib
import json
import math
import re

import pytest

import assur
from assur import DecompositionError, Driver, Joint, Link, Mechanism, _structure
from assur import _group_search as search

from .conftest import DATA, EXAMPLES

DOCS = EXAMPLES.parent / "docs"

KINDS = {"R": "revolute", "P": "prismatic", "S": "slot"}
STRUCTURE_DATA = DATA / "structure"


def build(joints: list[tuple], drivers: list[str], name: str = "") -> Mechanism:
    """A mechanism from ``(name, kind letter, (link, link), at[, axis])`` tuples.

    The moving links are those the joints name, in order of appearance.
    """
    links = dict.fromkeys(x for joint in joints for x in joint[2] if x != "ground")
    return Mechanism(
        links=tuple(Link(x) for x in links),
        joints=tuple(
            Joint(j[0], KINDS[j[1]], tuple(j[2]), j[3], j[4] if len(j) > 4 else None)
            for j in joints
        ),
        drivers=tuple(Driver(d, 10.0) for d in drivers),
        name=name,
    )


DYADS = ("RRR", "RRP", "RPR", "PRP", "RPP")


def check_group(g: assur.Group) -> None:
    """A group's class, order and kind agree with its links and pairs."""
    k, p = len(g.links), len(g.internal) + len(g.external)
    assert 3 * k == 2 * p
    assert g.order == len(g.external) >= 2
    assert len(set(g.links)) == k
    if g.group_class == 2:
        assert (k, g.kind) in {(2, kind) for kind in DYADS}
    elif g.kind == "triad":
        assert (g.group_class, k, g.order) == (3, 4, 3)
    else:
        assert g.kind == "general"
        assert g.group_class >= 3
        assert k >= 4


def summary(groups: tuple[assur.Group, ...]) -> list[tuple[str, frozenset[str]]]:
    """Each group as (kind, set of links)."""
    return [(g.kind, frozenset(g.links)) for g in groups]


# --- bundled examples --------------------------------------------------------------

# file stem -> (driver joints, [(kind, links) in order of attachment], mechanism class)
EXPECTED = {
    "four_bar": (["O2"], [("RRR", {"coupler", "rocker"})], 2),
    "offset_slider_crank": (["A"], [("RRP", {"rod", "piston"})], 2),
    "slider_crank_exercise": (["A"], [("RRP", {"rod", "slider"})], 2),
    "whitworth": (["O2"], [("RPR", {"block", "lever"}), ("RRP", {"rod", "ram"})], 2),
    "scotch_yoke": (["O2"], [("RPP", {"block", "yoke"})], 2),
    "six_bar_lecture": (["A"], [("RRR", {"3", "4"}), ("RRR", {"5", "6"})], 2),
    "class3": (["O2"], [("triad", {"rod", "plate", "left_rocker", "right_rocker"})], 3),
    "five_bar_two_cranks": (["A", "E"], [("RRR", {"left_rod", "right_rod"})], 2),
    "slot_mechanism": (
        ["O2"],
        [("RPR", {"rocker", "B~block"}), ("RRP", {"rod", "ram"})],
        2,
    ),
    "lever_var9": (["A"], [("RRP", {"2", "3"}), ("PRP", {"4", "5"})], 2),
}


@pytest.mark.parametrize("stem", sorted(EXPECTED))
def test_example_decomposition(stem):
    path = EXAMPLES / f"{stem}.toml"
    if not path.exists():
        pytest.skip(f"{path.name} is not bundled")
    drivers, groups, mechanism_class = EXPECTED[stem]
    s = assur.structure(assur.load(path))
    assert [g.internal[0] for g in s.drivers] == drivers
    assert summary(s.groups) == [(kind, frozenset(links)) for kind, links in groups]
    assert s.mechanism_class == mechanism_class
    assert s.dof == len(drivers)


def test_tenbar_decomposition():
    s = assur.structure(assur.load(EXAMPLES / "tenbar.toml"))
    assert [(g.group_class, g.kind, g.links) for g in s.drivers] == [
        (1, "driver", ("ground", "1"))
    ]
    got = summary(s.groups)
    assert got[0] == ("RRR", {"2", "3"})
    # (4, 5) and (6, 7) both hang on link 2 and the frame: either may come first
    assert sorted(got[1:3], key=lambda g: sorted(g[1])) == [
        ("RRR", {"4", "5"}),
        ("RRP", {"6", "7"}),
    ]
    assert got[3] == ("RRR", {"8", "9"})
    assert s.formula.startswith("I(ground, 1) -> II(2, 3)")
    assert s.mechanism_class == 2


def test_lever_decomposition_details():
    s = assur.structure(assur.load(EXAMPLES / "lever_var9.toml"))
    rrp, prp = s.groups
    assert (rrp.kind, rrp.links, rrp.internal, rrp.external) == (
        "RRP",
        ("2", "3"),
        ("C",),
        ("B", "guide_C"),
    )
    assert (prp.kind, set(prp.links), prp.internal) == ("PRP", {"4", "5"}, ("D",))
    assert set(prp.external) == {"block", "guide_D"}
    assert set(prp.attached_to) == {"2", "ground"}


def test_every_example_decomposes(example):
    s = assur.structure(example)
    assert s.dof == len(example.drivers) == len(s.drivers)
    placed = [link for g in s.groups for link in g.links]
    placed += [g.links[1] for g in s.drivers]
    names = [link.name for link in example.links]
    blocks = [f"{j.name}~block" for j in example.joints if j.kind == "slot"]
    assert sorted(placed) == sorted(names + blocks)
    for g in s.groups:
        check_group(g)
    json.dumps(s.to_dict())


# --- dyads in both mirror images ---------------------------------------------------

SIGNATURES = ["RRR", "RRP", "PRR", "RPR", "PRP", "RPP", "PPR"]


def dyad(signature: str) -> Mechanism:
    """A crank, then links x and y: pair 1 crank-x, pair 2 x-y, pair 3 y-frame."""
    pairs = [
        ("B", ("crank", "x"), (0.05, 0.0)),
        ("C", ("x", "y"), (0.15, 0.08)),
        ("D", ("y", "ground"), (0.25, 0.0)),
    ]
    joints: list[tuple] = [("A", "R", ("ground", "crank"), (0.0, 0.0))]
    for letter, (name, links, at) in zip(signature, pairs, strict=True):
        joints.append(
            (name, letter, links, at, (1.0, 0.5))
            if letter == "P"
            else (name, letter, links, at)
        )
    return build(joints, ["A"], name=signature)


@pytest.mark.parametrize("signature", SIGNATURES)
def test_dyad_signature_is_normalised(signature):
    s = assur.structure(dyad(signature))
    (g,) = s.groups
    canonical = {"PRR": "RRP", "PPR": "RPP"}.get(signature, signature)
    assert (g.group_class, g.order, g.kind) == (2, 2, canonical)
    assert set(g.links) == {"x", "y"}
    assert g.internal == ("C",)
    assert set(g.attached_to) == {"crank", "ground"}
    # the signature reads from the external pair of the first link to the other one
    kinds = {j.name: j.kind[0].upper() for j in dyad(signature).joints}
    assert kinds[g.external[0]] + kinds["C"] + kinds[g.external[1]] == canonical
    first = next(j for j in dyad(signature).joints if j.name == g.external[0])
    assert g.links[0] in first.links


@pytest.mark.parametrize("signature", ["RRP", "RPP"])
def test_mirror_images_agree(signature):
    left = assur.structure(dyad(signature)).groups[0]
    right = assur.structure(dyad(signature[::-1])).groups[0]
    assert left.kind == right.kind == signature
    assert (left.links, left.external) == (("x", "y"), ("B", "D"))
    assert (right.links, right.external) == (("y", "x"), ("D", "B"))


def test_only_sliding_pairs_is_no_group():
    # the reason was missing: "they form no Assur group (3k = 2p, every part
    # movable)" read as if the dyad were one
    match = (
        r"^links x and y are left over: .* on the known links crank and ground, "
        r"because joints B, C and D are three sliding pairs, which cannot fix the "
        r"rotation of the dyad x and y \(they tie it twice over, to the known links "
        r"crank and ground, and leave it free to slide\); expected a revolute pair in "
        r"place of one of them$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(dyad("PPP"))


# --- higher classes ----------------------------------------------------------------


def six_bar() -> Mechanism:
    """Crank, rod, ternary plate and two rockers on the frame (class3.toml's chain)."""
    return build(
        [
            ("O2", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "rod"), (0.03, 0.02)),
            ("C", "R", ("rod", "plate"), (0.24, -0.03)),
            ("D", "R", ("plate", "left"), (0.20, 0.02)),
            ("E", "R", ("plate", "right"), (0.30, 0.03)),
            ("F", "R", ("left", "ground"), (0.20, 0.20)),
            ("G", "R", ("right", "ground"), (0.31, 0.21)),
        ],
        ["O2"],
        name="six-bar",
    )


def test_class_three_triad():
    s = assur.structure(six_bar())
    (g,) = s.groups
    assert (g.group_class, g.order, g.kind) == (3, 3, "triad")
    assert set(g.links) == {"rod", "plate", "left", "right"}
    assert set(g.internal) == {"C", "D", "E"}
    assert set(g.external) == {"B", "F", "G"}
    assert set(g.attached_to) == {"crank", "ground"}
    assert s.mechanism_class == 3
    assert s.formula.startswith("I(ground, crank) -> III(")


@pytest.mark.parametrize(("driver", "first"), [("F", "left"), ("G", "right")])
def test_class_depends_on_the_input_link(driver, first):
    s = assur.structure(six_bar(), driver=driver)
    assert [g.links for g in s.drivers] == [("ground", first)]
    assert [(g.group_class, g.kind) for g in s.groups] == [(2, "RRR"), (2, "RRR")]
    assert set(s.groups[-1].links) == {"crank", "rod"}
    assert s.mechanism_class == 2
    assert assur.structure(six_bar(), driver="O2").mechanism_class == 3


def test_driver_option_on_a_file():
    mech = assur.load(EXAMPLES / "class3.toml")
    assert assur.structure(mech).mechanism_class == 3
    assert assur.structure(mech, driver="F").mechanism_class == 2


def test_driver_option_unknown_joint():
    with pytest.raises(DecompositionError, match=r"^driver: unknown joint 'Q'"):
        assur.structure(six_bar(), driver="Q")


def class_four() -> Mechanism:
    """Links a, b, c, d in a closed quadrilateral, hung on the crank and the frame.

    The external pairs are on the opposite links a (to the crank) and c (to the
    frame): no smaller part is an Assur group.
    """
    return build(
        [
            ("A", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "a"), (1.0, 0.0)),
            ("ab", "R", ("a", "b"), (1.5, 1.0)),
            ("bc", "R", ("b", "c"), (3.0, 1.2)),
            ("cd", "R", ("c", "d"), (3.2, -0.5)),
            ("da", "R", ("d", "a"), (1.4, -0.6)),
            ("Oc", "R", ("c", "ground"), (4.0, 0.0)),
        ],
        ["A"],
    )


def test_class_four_order_two_group():
    s = assur.structure(class_four())
    (g,) = s.groups
    check_group(g)
    assert (g.group_class, g.order) == (4, 2)
    assert set(g.links) == {"a", "b", "c", "d"}
    assert set(g.external) == {"B", "Oc"}
    assert s.mechanism_class == 4
    assert "Class IV, order 2" in str(s)


def test_two_driver_five_bar():
    mech = build(
        [
            ("A", "R", ("ground", "left"), (0.0, 0.0)),
            ("B", "R", ("left", "p"), (0.02, 0.035)),
            ("C", "R", ("p", "q"), (0.08, 0.12)),
            ("D", "R", ("q", "right"), (0.13, 0.035)),
            ("E", "R", ("right", "ground"), (0.15, 0.0)),
        ],
        ["A", "E"],
    )
    assert assur.mobility(mech) == 2
    s = assur.structure(mech)
    assert s.dof == 2
    assert [(g.group_class, g.links) for g in s.drivers] == [
        (1, ("ground", "left")),
        (1, ("ground", "right")),
    ]
    (g,) = s.groups
    assert (g.kind, set(g.links), set(g.attached_to)) == (
        "RRR",
        {"p", "q"},
        {"left", "right"},
    )
    assert s.formula == "I(ground, left) -> I(ground, right) -> II(p, q)"
    assert str(s).count("Class I:") == 2


# --- long chains -------------------------------------------------------------------


def dyad_chain(count: int) -> Mechanism:
    """A crank, then ``count`` RRR dyads on the previous rocker and the frame.

    Dyad i has the coupler ``c{i}`` and the rocker ``r{i}`` (the crank is rocker 0).
    """
    joints: list[tuple] = [("O", "R", ("ground", "crank"), (0.0, 0.0))]
    previous = "crank"
    for i in range(1, count + 1):
        joints += [
            (f"A{i}", "R", (previous, f"c{i}"), (i - 0.9, 0.3)),
            (f"B{i}", "R", (f"c{i}", f"r{i}"), (float(i), 0.8)),
            (f"O{i}", "R", (f"r{i}", "ground"), (i + 0.1, 0.0)),
        ]
        previous = f"r{i}"
    return build(joints, ["O"])


def triad_chain(count: int) -> Mechanism:
    """A crank, then ``count`` triads: a plate ``t{i}`` on three rods.

    Rod ``u{i}`` hangs on the previous triad's rod ``w{i-1}`` (on the crank first),
    rods ``v{i}`` and ``w{i}`` on the frame.
    """
    joints: list[tuple] = [("O", "R", ("ground", "crank"), (0.0, 0.0))]
    previous = "crank"
    for i in range(1, count + 1):
        x = 2.0 * i
        joints += [
            (f"U{i}", "R", (previous, f"u{i}"), (x - 1.0, 0.5)),
            (f"TU{i}", "R", (f"u{i}", f"t{i}"), (x - 0.5, 1.0)),
            (f"TV{i}", "R", (f"t{i}", f"v{i}"), (x, 1.2)),
            (f"TW{i}", "R", (f"t{i}", f"w{i}"), (x + 0.5, 1.0)),
            (f"V{i}", "R", (f"v{i}", "ground"), (x, 0.0)),
            (f"W{i}", "R", (f"w{i}", "ground"), (x + 0.6, 0.0)),
        ]
        previous = f"w{i}"
    return build(joints, ["O"])


def reversed_links(mech: Mechanism) -> Mechanism:
    """The same mechanism with its links listed backwards."""
    return dataclasses.replace(mech, links=mech.links[::-1])


def test_chain_of_500_dyads():
    mech = dyad_chain(500)
    s = assur.structure(mech)
    assert s.dof == 1
    assert len(s.groups) == 500
    assert {(g.group_class, g.order, g.kind) for g in s.groups} == {(2, 2, "RRR")}
    assert [g.links for g in s.groups] == [(f"c{i}", f"r{i}") for i in range(1, 501)]
    assert set(s.groups[0].attached_to) == {"crank", "ground"}
    assert set(s.groups[-1].attached_to) == {"ground", "r499"}
    assert s.mechanism_class == 2
    # listed backwards, the links still attach in the only possible order
    backwards = assur.structure(reversed_links(mech))
    assert [set(g.links) for g in backwards.groups] == [set(g.links) for g in s.groups]


def test_a_group_spoiled_by_the_group_before_it():
    # x, y is a dyad on the crank and the frame until p becomes known: the pair H
    # between x and p then makes it over-constrained (w, v dangle, keeping W = 1)
    mech = build(
        [
            ("A", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "p"), (0.1, 0.0)),
            ("C", "R", ("p", "q"), (0.2, 0.1)),
            ("D", "R", ("q", "ground"), (0.3, 0.0)),
            ("E", "R", ("crank", "x"), (-0.1, 0.0)),
            ("F", "R", ("x", "y"), (-0.2, 0.1)),
            ("G", "R", ("y", "ground"), (-0.3, 0.0)),
            ("H", "R", ("x", "p"), (0.0, 0.2)),
            ("K", "R", ("crank", "w"), (0.0, -0.1)),
            ("L", "R", ("w", "v"), (0.0, -0.2)),
        ],
        ["A"],
    )
    assert assur.mobility(mech) == 1
    match = (
        r"^links x, y, w and v are left over: .* on the known links crank, ground, p "
        r"and q, because link x is held to the known links by joints E and H, which "
        r"fix it, and link v hangs on joint L alone;"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(mech)


def test_chain_of_triads():
    s = assur.structure(reversed_links(triad_chain(40)))
    assert len(s.groups) == 40
    assert {(g.group_class, g.order, g.kind) for g in s.groups} == {(3, 3, "triad")}
    assert [set(g.links) for g in s.groups] == [
        {f"t{i}", f"u{i}", f"v{i}", f"w{i}"} for i in range(1, 41)
    ]
    for g in s.groups:
        check_group(g)


# --- slots -------------------------------------------------------------------------


def slotted_lever() -> Mechanism:
    """A crank whose pin B slides in the straight slot of a rocker (a higher pair)."""
    return build(
        [
            ("O2", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "S", ("rocker", "crank"), (0.03, 0.02), (0.03, 0.14)),
            ("O4", "R", ("ground", "rocker"), (0.0, -0.12)),
        ],
        ["O2"],
    )


def test_slot_is_replaced_by_a_block():
    mech = slotted_lever()
    assert assur.mobility(mech) == 3 * 2 - 2 * 2 - 1 == 1
    s = assur.structure(mech)
    assert (s.links, s.lower_pairs, s.higher_pairs, s.dof) == (2, 2, 1, 1)
    assert s.slots == ("B",)
    (g,) = s.groups
    assert g.kind == "RPR"
    assert set(g.links) == {"rocker", "B~block"}
    assert set(g.external) == {"O4", "B~pin"}
    report = str(s)
    assert "Slot B" in report
    assert "block" in report
    assert "p4 = 1" in report
    assert "= 1" in report.splitlines()[2]
    assert "B (block)" in s.formula
    assert s.to_dict()["slots"] == ["B"]


def test_slot_example_keeps_its_mobility():
    mech = assur.load(EXAMPLES / "slot_mechanism.toml")
    s = assur.structure(mech)
    assert s.dof == assur.mobility(mech) == 1
    assert s.higher_pairs == 1
    assert "replaced by an equivalent block" in str(s)


# --- mobility and failures ---------------------------------------------------------


def test_mobility_chebyshev_gruebler():
    assert assur.mobility(assur.catalog.four_bar()) == 3 * 3 - 2 * 4
    assert assur.mobility(assur.catalog.slider_crank()) == 1
    assert assur.mobility(six_bar()) == 3 * 5 - 2 * 7
    truss = build(
        [
            ("A", "R", ("ground", "p"), (0.0, 0.0)),
            ("B", "R", ("p", "q"), (1.0, 1.0)),
            ("C", "R", ("q", "ground"), (2.0, 0.0)),
        ],
        [],
    )
    assert assur.mobility(truss) == 0


def test_mobility_differs_from_drivers():
    four_bar = assur.catalog.four_bar()
    two = Mechanism(
        four_bar.links, four_bar.joints, (Driver("A", 1.0), Driver("D", 1.0))
    )
    match = (
        r"drivers: the mechanism has W = 3\*3 - 2\*4 - 0 = 1 degree of "
        r"freedom but 2 drivers; expected one driver per degree of freedom"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(two)
    none = Mechanism(four_bar.links, four_bar.joints, ())
    with pytest.raises(DecompositionError, match=r"= 1 degree of freedom but 0 "):
        assur.structure(none)


def with_links(mech: Mechanism, links: list[str], joints: list[tuple]) -> Mechanism:
    """``mech`` with more links and joints ``(name, kind letter, (link, link), at)``."""
    added = tuple(
        Joint(j[0], KINDS[j[1]], j[2], j[3], (1.0, 0.0) if j[1] == "P" else None)
        for j in joints
    )
    return dataclasses.replace(
        mech,
        links=(*mech.links, *(Link(x) for x in links)),
        joints=(*mech.joints, *added),
    )


@pytest.mark.parametrize(
    ("kind", "moves"), [("R", "turns about"), ("P", "slides along")]
)
def test_a_link_on_one_joint_is_named_when_the_count_goes_wrong(kind, moves):
    # W = 2 with one driver: "expected one driver per degree of freedom" could not be
    # followed, since a driver acts between the frame and its input link
    mech = with_links(
        assur.catalog.four_bar(),
        ["flag"],
        [("E", kind, ("coupler", "flag"), (0.1, 0.1))],
    )
    with pytest.raises(DecompositionError) as caught:
        assur.structure(mech)
    assert str(caught.value) == (
        "drivers: the mechanism has W = 3*4 - 2*5 - 0 = 2 degrees of freedom but 1 "
        f"driver, as link flag hangs on joint E alone and {moves} it freely; "
        "expected every link held by two joints at least (an input link by its "
        "driver)"
    )


def test_a_link_held_by_two_joints_at_one_point_is_named_as_it_spins():
    # a four-bar with a link put between coupler and rocker in place of their pin,
    # both its pins where that pin was: it spins about them, a passive freedom
    joints = [
        ("A", ("ground", "crank"), (0.0, 0.0)),
        ("B", ("crank", "coupler"), (0.0, 0.1)),
        ("D", ("ground", "rocker"), (0.35, 0.0)),
        ("X", ("coupler", "idler"), (0.3, 0.2)),
        ("Y", ("idler", "rocker"), (0.3, 0.2)),
    ]
    mech = Mechanism(
        links=tuple(Link(x) for x in ("crank", "coupler", "rocker", "idler")),
        joints=tuple(Joint(n, "revolute", links, at) for n, links, at in joints),
        drivers=(Driver("A", 10.0),),
    )
    with pytest.raises(DecompositionError) as caught:
        assur.structure(mech)
    assert str(caught.value) == (
        "drivers: the mechanism has W = 3*4 - 2*5 - 0 = 2 degrees of freedom but 1 "
        "driver, as link idler is held by joints X and Y at one point and spins "
        "about it freely, a freedom no driver can take; expected the two joints of a "
        "link apart (or the link left out, its joints one)"
    )


def test_a_part_not_joined_to_the_frame_is_named_when_the_count_goes_wrong():
    # a triangle p, q, r joined to nothing: W = 1 + 3 with one driver
    triangle = [
        ("pq", "R", ("p", "q"), (1.0, 0.0)),
        ("qr", "R", ("q", "r"), (1.0, 1.0)),
        ("rp", "R", ("r", "p"), (0.0, 1.0)),
    ]
    mech = with_links(assur.catalog.four_bar(), ["p", "q", "r"], triangle)
    with pytest.raises(DecompositionError) as caught:
        assur.structure(mech)
    assert str(caught.value) == (
        "drivers: the mechanism has W = 3*6 - 2*7 - 0 = 4 degrees of freedom but 1 "
        "driver, as links p, q and r are joined to the frame by no chain of joints; "
        "expected every link joined to the frame through joints"
    )


def test_leftover_links_are_named():
    # link 2 is pinned to the frame and to the crank, link 3 to 2 and to the frame
    # (over-constrained), links 4 and 5 dangle from the crank: W = 3*5 - 2*7 = 1 but
    # no Assur group attaches.
    mech = build(
        [
            ("A", "R", ("ground", "1"), (0.0, 0.0)),
            ("g1", "R", ("ground", "2"), (1.0, 1.0)),
            ("j12", "R", ("1", "2"), (1.0, 2.0)),
            ("j23", "R", ("2", "3"), (2.0, 2.0)),
            ("g3", "R", ("ground", "3"), (3.0, 3.0)),
            ("j14", "R", ("1", "4"), (0.0, 1.0)),
            ("j45", "R", ("4", "5"), (0.0, 2.0)),
        ],
        ["A"],
    )
    assert assur.mobility(mech) == 1
    match = (
        # "(3k = 2p, no smaller group)" read as if these links had 3k = 2p
        r"^links 2, 3, 4 and 5 are left over: they form no Assur group \(one "
        r"needs 3k = 2p, no smaller group\) on the known links 1 and "
        r"ground, because link 2 is held to "
        r"the known links by joints g1 and j12, which fix it, and link 5 hangs on "
        r"joint j45 alone; expected every link of a group held by two joints at least, "
        r"at most one of them to a known link$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(mech)


def test_leftover_names_two_joints_between_two_links():
    # link 2 is pinned twice to the frame: a rigid truss with link 3
    mech = build(
        [
            ("A", "R", ("ground", "1"), (0.0, 0.0)),
            ("g1", "R", ("ground", "2"), (1.0, 1.0)),
            ("g2", "R", ("ground", "2"), (1.0, 2.0)),
            ("j23", "R", ("2", "3"), (2.0, 2.0)),
            ("g3", "R", ("ground", "3"), (3.0, 3.0)),
            ("j14", "R", ("1", "4"), (0.0, 1.0)),
            ("j45", "R", ("4", "5"), (0.0, 2.0)),
        ],
        ["A"],
    )
    match = (
        r"^links 2, 3, 4 and 5 are left over: they form no Assur group .* on the known "
        r"links 1 and ground, because joints g1 and g2 both join ground and 2: two "
        r"revolute pairs at two points weld the links into one rigid body; expected "
        r"one joint between two links \(or one link in place of two welded ones\)$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(mech)


# --- robustness: chains that are no Assur groups -----------------------------------

# the kinds of D and E, where E is and its axis, what the two do to links x and y
PARALLEL = [
    ("RR", (0.15, 0.08), None, "two revolute pairs at two points weld the links"),
    ("RR", (0.25, 0.0), None, "two revolute pairs at one point are one pair counted"),
    ("RP", (0.15, 0.08), (1.0, 0.5), "a revolute and a prismatic pair together weld"),
    ("PP", (0.15, 0.08), (-2.0, -1.0), "two prismatic pairs along parallel lines are"),
    ("PP", (0.15, 0.08), (0.0, 1.0), "two prismatic pairs along different lines weld"),
]


@pytest.mark.parametrize(("kinds", "at", "axis", "reason"), PARALLEL)
def test_two_joints_between_two_links(kinds, at, axis, reason):
    # a crank, then x and y: B crank-x, D y-x and a second joint E between x and y
    d = ("D", kinds[0], ("y", "x"), (0.25, 0.0), (1.0, 0.5))
    e = ("E", kinds[1], ("x", "y"), at, axis)
    mech = build(
        [
            ("A", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "x"), (0.05, 0.0)),
            d if kinds[0] == "P" else d[:4],
            e if kinds[1] == "P" else e[:4],
        ],
        ["A"],
    )
    assert assur.mobility(mech) == 1
    match = (
        r"^links x and y are left over: .* on the known links crank and ground, "
        rf"because joints D and E both join y and x: {reason}"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(mech)


def relinked(path: str, joint: str, links: tuple[str, str]) -> Mechanism:
    """The example ``path`` with the links of ``joint`` replaced."""
    mech = assur.load(EXAMPLES / path)
    joints = tuple(
        dataclasses.replace(j, links=links) if j.name == joint else j
        for j in mech.joints
    )
    return dataclasses.replace(mech, joints=joints)


@pytest.mark.parametrize(
    ("links", "match"),
    [
        (("coupler", "rocker"), r"joints B and O4 both join coupler and rocker"),
        (("rocker", "coupler"), r"joints B and O4 both join coupler and rocker"),
    ],
)
def test_four_bar_with_its_ground_pivot_relinked(links, match):
    with pytest.raises(DecompositionError, match=match):
        assur.structure(relinked("four_bar.toml", "O4", links))


def test_four_bar_with_its_rocker_s_pivot_on_the_crank():
    # O4 typed as ["ground", "crank"]: the frame and the crank, both known, were
    # not looked at, and the rocker was left over without a reason
    match = (
        r"^links coupler and rocker are left over: .* on the known links crank and "
        r"ground, because joints O2 and O4 both join ground and crank: two revolute "
        r"pairs at two points weld the links into one rigid body; expected one joint "
        r"between two links \(or one link in place of two welded ones\)$"
    )
    for links in [("ground", "crank"), ("crank", "ground")]:
        with pytest.raises(DecompositionError, match=match):
            assur.structure(relinked("four_bar.toml", "O4", links))


def test_four_bar_with_its_rocker_pinned_to_the_crank():
    # coupler and rocker hang on the crank alone: still a dyad, rigid with the crank
    s = assur.structure(relinked("four_bar.toml", "O4", ("crank", "rocker")))
    (g,) = s.groups
    assert (g.group_class, g.kind, g.attached_to) == (2, "RRR", ("crank",))


def test_whitworth_with_a_rigid_triangle():
    # lever, rod and ram pinned to one another in a triangle: a truss, not links
    # of an Assur group (the chain was reported as a class III group before)
    match = (
        r"^links block, lever, rod and ram are left over: .* because joints O4, E and "
        r"F make links lever, rod and ram rigid \(k = 3, p = 3: 2p >= 3\(k - 1\)\); "
        r"expected one link in their place, or fewer joints between them$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(relinked("whitworth.toml", "O4", ("lever", "ram")))


def test_whitworth_with_two_joints_between_lever_and_rod():
    # the chain block-lever-rod-ram was reported as a class II "general" group
    with pytest.raises(
        DecompositionError, match=r"joints O4 and E both join lever and rod"
    ):
        assur.structure(relinked("whitworth.toml", "O4", ("lever", "rod")))


def test_group_of_order_one_is_refused():
    # links 6..9 hang on one external pair H (this was a class IV group of order 1):
    # the guide between 6 and 9 closes the rigid triangle 6, 7, 9
    match = r"because joints L, S and guide make links 6, 7 and 9 rigid"
    with pytest.raises(DecompositionError, match=match):
        assur.structure(relinked("tenbar.toml", "guide", ("6", "9")))


def test_open_chain_with_a_sliding_dyad_is_no_group():
    # a-b-c-d in a row; c and d slide on the frame and on each other (a dyad of
    # sliding pairs only, which cannot fix its rotation); the whole row has 3k = 2p
    # but is no minimal Assur group (it was reported as a class II "general" group)
    mech = build(
        [
            ("A", "R", ("ground", "crank"), (0.0, 0.0)),
            ("B", "R", ("crank", "a"), (0.05, 0.0)),
            ("C", "R", ("a", "b"), (0.1, 0.05)),
            ("D", "R", ("b", "c"), (0.2, 0.05)),
            ("E", "P", ("c", "d"), (0.3, 0.05), (1.0, 1.0)),
            ("F", "P", ("ground", "c"), (0.2, 0.0), (1.0, 0.0)),
            ("G", "P", ("ground", "d"), (0.3, 0.0), (0.0, 1.0)),
        ],
        ["A"],
    )
    assert assur.mobility(mech) == 1
    with pytest.raises(DecompositionError, match=r"^links a, b, c and d are left over"):
        assur.structure(mech)


COUNTED = r"4 links are left over, in no Assur group on the 2 known links"
"""The same counted, where the names would run the message past 400 characters."""


@pytest.mark.parametrize(
    ("name", "through", "head"),
    [
        # the names would run past 400 characters by 5: counted
        ("sliding_loop", "link ground", COUNTED),
        ("sliding_lock", "links crank and ground", COUNTED),
    ],
)
def test_a_loop_of_sliding_pairs_alone_is_no_group(name, through, head):
    # yg, xy, xz, zg slide in a loop through the frame (or from the frame to the
    # crank): one rotation is tied twice, and d, x, y, z were a class III triad
    match = (
        rf"^{head}, "
        r"because joints yg, xy, xz and zg close a loop of sliding pairs alone through "
        rf"the known {through}: each ties its two links' rotations; those of links "
        r"y, x and z are tied once too often, which W = 3n - 2p5 - p4 miscounts; "
        r"expected a revolute pair in place of one of them$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(assur.load(STRUCTURE_DATA / f"{name}.toml"))


@pytest.mark.parametrize("sliding", ["F", "FG", "BFG", "DFG", "CDE", "BCDEFG"])
def test_a_triad_with_sliding_pairs_and_no_loop_of_them_is_a_group(sliding):
    # the sliding pairs of these triads close no loop: each is still a triad
    joints = [
        (j.name, "P", j.links, j.at, (1.0, 0.3))
        if j.name in sliding
        else (j.name, "R", j.links, j.at)
        for j in six_bar().joints
    ]
    if sliding != "BCDEFG":
        (g,) = assur.structure(build(joints, ["O2"])).groups
        assert (g.kind, set(g.links)) == ("triad", {"rod", "plate", "left", "right"})
    else:  # all six slide: the loops rod-plate-left-frame-crank and the like
        with pytest.raises(DecompositionError, match=r"loop of sliding pairs alone"):
            assur.structure(build(joints, ["O2"]))


def test_open_path_of_four_links_is_never_described_as_a_group():
    from assur._structure import Pair, _describe

    def pair(name: str, a: str, b: str) -> Pair:
        return Pair(name, "R", (a, b), (0.0, 0.0))

    chain = [
        pair("B", "crank", "a"),
        pair("C", "a", "b"),
        pair("D", "b", "c"),
        pair("E", "c", "d"),
        pair("F", "c", "ground"),
        pair("G", "d", "ground"),
    ]
    match = (
        r"^links a, b, c and d: a chain of 4 links whose joints among them form an "
        r"open path is no minimal Assur group"
    )
    with pytest.raises(DecompositionError, match=match):
        _describe(["a", "b", "c", "d"], chain, {"crank", "ground"})


# --- report and serialisation ------------------------------------------------------


def test_report_names_every_step():
    s = assur.structure(assur.load(EXAMPLES / "tenbar.toml"))
    report = str(s)
    assert "W = 3n - 2p5 - p4 = 3*9 - 2*13 - 0 = 1" in report
    assert (
        "1. Class I: the frame and the input link 1 (driven through pair A)" in report
    )
    for step, g in enumerate(s.groups, start=2):
        first, second = g.links
        line = f"{step}. Class II, order 2, dyad {g.kind}: links {first} and {second}"
        assert line in report
    assert f"Structure formula: {s.formula}" in report
    assert "Class of the mechanism: II" in report


WHY = (
    "Why an Assur group: k = {k} links, p = {p} lower pairs; with its external pairs "
    "on the known links, W = 3k - 2p = {n} - {n} = 0, and every smaller part of it "
    "keeps W > 0 (it cannot be split into simpler groups)."
)


def test_report_of_a_triad():
    report = str(assur.structure(six_bar()))
    assert "Structure of six-bar" in report
    assert "2. Class III, order 3, triad: links" in report
    assert (
        "internal pairs C, D and E; external pairs B, F and G on the known links"
        in report
    )
    # three pairs on two links do not pair off in order: each link's are named
    assert "on the known links crank (B) and ground (F and G)." in report
    assert WHY.format(k=4, p=6, n=12) in report
    assert "Class of the mechanism: III" in report
    # what makes it class III: the base link with its three internal pairs
    (group,) = assur.structure(six_bar()).groups
    assert group.base == "plate"
    assert sorted(group.basis) == ["C", "D", "E"]
    why = [line.strip() for line in report.splitlines() if "Why class" in line]
    assert why == [
        "Why class III: its base link plate carries three internal pairs, "
        "C, D and E (above class II, the class is the number of "
        "internal pairs of the most complex closed contour they form; a base link "
        "carrying three internal pairs counts as a contour of three)."
    ]


def test_report_of_a_dyad_counts_its_pairs_and_links():
    report = str(assur.structure(assur.catalog.four_bar()))
    assert (
        "internal pair C; external pairs B and D on the known links crank and ground."
        in (report)
    )
    assert WHY.format(k=2, p=3, n=6) in report
    pinned = str(assur.structure(relinked("four_bar.toml", "O4", ("crank", "rocker"))))
    assert "external pairs A and O4 on the known link crank." in pinned


def test_report_of_a_general_group():
    report = str(assur.structure(class_four()))
    assert "2. Class IV, order 2, group: links a, b, c and d" in report
    assert (
        "internal pairs ab, bc, cd and da; external pairs B and Oc on the known links"
        in (report)
    )
    assert WHY.format(k=4, p=6, n=12) in report
    # what makes it class IV: no link carries more than two internal pairs, and
    # the four close a contour
    (group,) = assur.structure(class_four()).groups
    assert group.base == ""
    assert sorted(group.basis) == ["ab", "bc", "cd", "da"]
    assert (
        "Why class IV: its internal pairs ab, bc, cd and da close a contour of four "
        "links" in report
    )
    # a dyad's class needs no reason: two links and one internal pair
    assert "Why class" not in str(assur.structure(assur.catalog.four_bar()))


def test_report_of_a_mechanism_without_groups():
    # a crank alone was said to be of class I as "the highest class of its groups"
    s = assur.structure(build([("A", "R", ("ground", "crank"), (0.0, 0.0))], ["A"]))
    assert (s.groups, s.mechanism_class) == ((), 1)
    line = (
        "Class of the mechanism: I (the frame and its input link alone, no Assur group)"
    )
    assert line in str(s)


def test_to_dict_is_json():
    s = assur.structure(assur.load(EXAMPLES / "whitworth.toml"))
    data = json.loads(json.dumps(s.to_dict()))
    assert data["dof"] == 1
    assert data["formula"] == s.formula
    assert data["mechanism_class"] == 2
    assert [g["kind"] for g in data["groups"]] == ["RPR", "RRP"]
    assert data["groups"][0]["class"] == 2
    assert data["groups"][0]["class_roman"] == "II"
    assert data["groups"][0]["order"] == 2
    assert data["drivers"][0]["internal_pairs"] == ["O2"]
    assert set(data["groups"][1]["attached_to"]) == {"lever", "ground"}
    assert "base" not in data["groups"][0]  # a dyad's class needs no reason
    # a triad's base link and its internal pairs, as the report gives them
    (triad,) = assur.structure(six_bar()).to_dict()["groups"]
    assert triad["base"] == "plate"
    assert sorted(triad["basis"]) == ["C", "D", "E"]


def test_the_docs_state_the_search_as_the_code_does():
    # cli.rst left out "general" (class IV and six- to eight-link groups in the
    # JSON); concepts.rst pointed at assur.structure.structure, which no module
    # holds, and stated the test of a group as 2p_s <= 3s for every subset
    cli = (DOCS / "cli.rst").read_text("utf-8")
    for kind in (*DYADS, "triad", "general"):
        assert f"``{kind}``" in cli, kind
    concepts = (DOCS / "concepts.rst").read_text("utf-8")
    targets = re.findall(r":func:`[^`<]*<([^>]+)>`", concepts)
    assert targets
    for target in targets:
        module, _, name = target.rpartition(".")
        assert hasattr(importlib.import_module(module), name), target
    criterion = " ".join(concepts.split())
    for rule in ("2p_s < 3s", "2q_s < 3(s - 1)", "prismatic pairs close no loop"):
        assert rule in criterion, rule


def test_structure_does_not_change_the_mechanism():
    mech = six_bar()
    assur.structure(mech, driver="F")
    assert mech.drivers == (Driver("O2", 10.0),)


@pytest.mark.parametrize("name", ["slot_mechanism", "whitworth", "class3", "tenbar"])
def test_known_links_come_in_the_order_of_the_external_pairs(name):
    # the note says "on X, Y through P, Q": P joins X and Q joins Y (the known links
    # were listed alphabetically, so O4 read as on the crank)
    mech = assur.load(EXAMPLES / f"{name}.toml")
    joints = {j.name: j for j in mech.joints}
    known = {"ground"}
    for g in assur.structure(mech).drivers:
        known.update(g.links)
    for g in assur.structure(mech).groups:
        joined = []
        for pair in g.external:
            name_ = pair.split("~")[0]
            links = set(joints[name_].links) & known
            joined += [x for x in sorted(links) if x not in joined]
        assert g.attached_to == tuple(joined), g
        known.update(g.links)


def _ring(groups_on_frame: tuple[int, ...], count: int) -> assur.Mechanism:
    """A crank driving a closed ring of ``count`` links, some pinned to the frame."""
    lines = ["format = 1", 'name = "ring"', "[links.crank]"]
    lines += [f"[links.d{i}]" for i in range(count)]

    def joint(name: str, a: str, b: str, x: float, y: float) -> None:
        lines.extend(
            [f"[joints.{name}]", 'kind = "revolute"', f'links = ["{a}", "{b}"]',
             f"at = [{x:.4f}, {y:.4f}]"]
        )  # fmt: skip

    joint("A", "ground", "crank", 0.0, 0.0)
    joint("B", "crank", "d0", 0.2, 1.0)
    for i in range(count):
        t = 2 * math.pi * i / count
        joint(f"Q{i}", f"d{i}", f"d{(i + 1) % count}", 5 + 3 * math.cos(t),
              5 + 3 * math.sin(t))  # fmt: skip
    for i in groups_on_frame:
        t = 2 * math.pi * (i + 0.5) / count
        joint(f"G{i}", "ground", f"d{i}", 5 + 4.5 * math.cos(t), 5 + 4.5 * math.sin(t))
    lines += ["[[drivers]]", 'joint = "A"', "omega = 1.0"]
    return assur.loads("\n".join(lines) + "\n")


def test_a_group_larger_than_the_search_is_named_so():
    # a ring of ten links held at every other one is one class X group (k = 10,
    # p = 15); it was said to form "no Assur group"
    with pytest.raises(DecompositionError) as caught:
        assur.structure(_ring((2, 4, 6, 8), 10))
    message = str(caught.value)
    assert "no Assur group of at most 8 links attaches" in message
    assert "(k = 10, p = 15: 3k = 2p) they may form one larger group" in message
    # the same ring of eight links (class VIII, k = 8, p = 12) is found
    found = assur.structure(_ring((2, 4, 6), 8))
    (group,) = found.groups
    assert (group.group_class, len(group.links)) == (8, 8)
    assert group.label == "class VIII (d0, d1, d2, d3, d4, d5, d6, d7)"


def test_links_held_twice_or_on_one_joint_are_no_larger_group():
    # ten links left over with 3k = 2p were said to "may form one larger group"; u0
    # is held to the crank and the frame (B0, X) and v4 hangs on C4: no group at all
    match = (
        r"^links u0, v0, u1, v1, u2, v2, \.\.\. \(10 in all\) are left over: .* on the "
        r"known links c0 and ground, because link u0 is held to the known links by "
        r"joints B0 and X, which fix it, and link v4 hangs on joint C4 alone; expected "
        r"every link of a group held by two joints at least, at most one of them to "
        r"a known link$"
    )
    with pytest.raises(DecompositionError, match=match):
        assur.structure(assur.load(STRUCTURE_DATA / "overfixed_chain.toml"))


def test_a_pin_entered_twice_is_named_when_the_count_goes_wrong():
    # W = -1 with one driver: the count was given with no reason, as if a driver
    # were missing
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    start = text.index("[joints.B]")
    block = text[start : text.index("[joints.", start + 1)]
    mech = assur.loads(text + "\n" + block.replace("[joints.B]", "[joints.B2]"))
    with pytest.raises(DecompositionError) as caught:
        assur.structure(mech)
    assert str(caught.value) == (
        "drivers: the mechanism has W = 3*3 - 2*5 - 0 = -1 degrees of freedom but "
        "1 driver, as joints B and B2 both join coupler and rocker: two revolute "
        "pairs at one point are one pair counted twice; expected one driver per "
        "degree of freedom"
    )


def test_a_slot_s_block_and_pin_read_as_such():
    # "external pairs O4, B~pin": the internal names, in the report students read
    s = assur.structure(assur.load(EXAMPLES / "slot_mechanism.toml"))
    text = str(s)
    assert "~" not in text.replace("B~block and B~pin", "")
    assert "links rocker and B (block)" in text
    assert "external pairs O4 and B (pin)" in text
    data = s.to_dict()  # the names the JSON gives: those of the columns
    assert data["groups"][0]["links"] == ["rocker", "B~block"]


def _radial(rods: int) -> assur.Mechanism:
    """A radial engine of ``rods`` articulated rods whose master rod is pinned twice
    to the crank, one piston's cylinder left out so that the count still gives W = 1.
    """
    lines = ["format = 1", 'name = "radial"', "[links.crank]", "[links.master]"]
    lines += ["[links.pm]"] + [f"[links.r{i}]\n[links.p{i}]" for i in range(rods)]

    def joint(name: str, kind: str, a: str, b: str, at: tuple[float, float]) -> None:
        lines.extend(
            [f"[joints.{name}]", f'kind = "{kind}"', f'links = ["{a}", "{b}"]',
             f"at = [{at[0]:.6f}, {at[1]:.6f}]"]
        )  # fmt: skip
        if kind == "prismatic":
            size = math.hypot(*at)
            lines.append(f"axis = [{at[0] / size:.6f}, {at[1] / size:.6f}]")

    joint("O", "revolute", "ground", "crank", (0.0, 0.0))
    joint("B", "revolute", "crank", "master", (0.0, 0.05))
    joint("B2", "revolute", "crank", "master", (0.0, 0.05))
    joint("Cm", "revolute", "master", "pm", (0.0, 0.25))
    joint("Gm", "prismatic", "ground", "pm", (0.0, 0.25))
    for i in range(rods):
        t = math.pi / 2 + 2 * math.pi * (i + 1) / (rods + 1)
        pin = (0.03 * math.cos(t), 0.05 + 0.03 * math.sin(t))
        end = (0.2 * math.cos(t), 0.2 * math.sin(t))
        joint(f"A{i}", "revolute", "master", f"r{i}", pin)
        joint(f"C{i}", "revolute", f"r{i}", f"p{i}", end)
        if i:
            joint(f"G{i}", "prismatic", "ground", f"p{i}", end)
    lines += ["[[drivers]]", 'joint = "O"', "omega = 1.0"]
    return assur.loads("\n".join(lines) + "\n")


def _sets_tested(monkeypatch, mech: assur.Mechanism) -> tuple[list, str]:  # type: ignore[type-arg]
    """Return the sets of links the search tested, and the error its failure gave."""
    tested = []
    is_group = search._is_group

    def counting(index, subset, known):  # type: ignore[no-untyped-def]
        tested.append(subset)
        return is_group(index, subset, known)

    monkeypatch.setattr(search, "_is_group", counting)
    _structure._DECOMPOSED.clear()
    with pytest.raises(DecompositionError) as caught:
        assur.structure(mech)
    return tested, str(caught.value)


def test_a_failing_search_does_not_grow_sets_past_a_part_held_too_often(monkeypatch):
    # the master rod pinned twice can be in no group; every set of up to eight
    # links around it was grown and tested: 44 s to the error with 20 rods
    tested, error = _sets_tested(monkeypatch, _radial(20))
    assert "joints B and B2 both join crank and master" in error
    # sets holding the master rod are tested as pairs with a neighbour, not grown
    assert max((len(s) for s in tested if "master" in s), default=0) <= 2
    assert len(tested) < 200


def _hub(spokes: int) -> assur.Mechanism:
    """A crank driving a hub H with an arm r and ``spokes`` dyads u, v to the frame,
    the arm's pivot D typed on v0 instead (v0 pinned twice to the frame, W = 1).
    """
    lines = ["format = 1", 'name = "hub"', "[links.c]", "[links.H]", "[links.r]"]
    lines += [f"[links.u{i}]\n[links.v{i}]" for i in range(spokes)]
    joints = [("A", "ground", "c"), ("B", "c", "H"), ("C", "H", "r")]
    joints += [("D", "v0", "ground")]
    for i in range(spokes):
        joints += [(f"E{i}", "H", f"u{i}"), (f"F{i}", f"u{i}", f"v{i}")]
        joints += [(f"G{i}", f"v{i}", "ground")]
    for n, (name, a, b) in enumerate(joints):
        lines += [f"[joints.{name}]", 'kind = "revolute"', f'links = ["{a}", "{b}"]']
        lines.append(f"at = [{math.cos(n):.4f}, {math.sin(n):.4f}]")
    lines += ["[[drivers]]", 'joint = "A"', "omega = 1.0"]
    return assur.loads("\n".join(lines) + "\n")


def test_a_failing_search_does_not_grow_sets_that_cannot_close(monkeypatch):
    # every connected set of up to eight links around the hub was grown and tested
    # (170,000 sets, 6 s of CPU with 16 spokes): none can reach 3k = 2p, for no link
    # it could take brings more constraints than freedoms
    tested, error = _sets_tested(monkeypatch, _hub(16))
    assert "joints D and G0 both join v0 and ground" in error
    assert len(tested) < 100


def test_the_json_formula_names_links_as_the_json_does():
    # "II(lever, B (block))" stood beside links ["lever", "B~block"]
    data = assur.structure(assur.load(EXAMPLES / "slot_mechanism.toml")).to_dict()
    steps = [
        f"{g['class_roman']}({', '.join(g['links'])})"
        for g in (*data["drivers"], *data["groups"])
    ]
    assert data["formula"] == " -> ".join(steps)
    assert "~block" in data["formula"]


def test_a_group_counted_as_one_before_refers_to_it():
    # a ten-bar's four dyads said the whole reason four times over
    report = str(assur.structure(assur.load(EXAMPLES / "tenbar.toml")))
    why = [line.strip() for line in report.splitlines() if "Why an Assur" in line]
    assert why[0] == WHY.format(k=2, p=3, n=6)
    assert why[1:] == 3 * [
        "Why an Assur group: the same counts as for links 2 and 3 above: k = 2, p = 3, "
        "W = 3k - 2p = 6 - 6 = 0, and every smaller part keeps W > 0."
    ]


def test_the_getting_started_page_shows_the_structure_command_s_own_output(capsys):
    # the page had kept the words of an older report ("3k = 2p = 6, so ...")
    from assur.cli import main

    page = (DOCS / "getting_started.rst").read_text(encoding="utf-8")
    command = "   $ assur structure docs/files/first_four_bar.toml\n"
    start = page.index(command) + len(command)
    shown = []
    for line in page[start:].splitlines():
        if line and not line.startswith("   "):  # the block's end
            break
        shown.append(line)
    assert main(["structure", str(DOCS / "files" / "first_four_bar.toml")]) == 0
    printed = capsys.readouterr().out.rstrip("\n")
    assert [line.strip() for line in shown[:-1]] == [
        line.strip() for line in printed.splitlines()
    ]


def test_report_of_a_group_made_without_its_carriers():
    # Group is public and its carriers default to (): the report's naming of each
    # known link's external pairs raised "zip() argument 2 is shorter than argument 1"
    from assur.report import _pairs_text

    g = assur.Group(
        3, 6, "RRR", ("a", "b", "c", "d"), ("C", "D", "E"), ("B", "F", "G"),
        ("crank", "ground"),
    )  # fmt: skip
    assert _pairs_text(g).endswith(
        "external pairs B, F and G on the known links crank and ground"
    )
