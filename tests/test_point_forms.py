"""Point forms: ``[x, y]``, a point's name or ``{from, toward, distance}`` anywhere.

Every place that asks for a point (a joint's ``at``, a link's ``center`` and
``axis``, a load's ``at``, an extra point's ``at``) takes all three forms; the same
point given in any form gives the same analysis, and writing the mechanism back
keeps the form the user chose.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import assur
from assur import ModelError, Toward
from assur.model import resolve_point

from .conftest import EXAMPLES

A = (0.0, 0.0)
B = (0.05232590180780452, 0.05232590180780451)
C = (0.2453595776263, 0.0)
AB = math.hypot(B[0] - A[0], B[1] - A[1])
AC = math.hypot(C[0] - A[0], C[1] - A[1])

TEMPLATE = """\
format = 1
name = "Slider-crank, points in every form"

[links.crank]
axis = {axis}
mass = 10.0
center = {center}
inertia = 0.0

[links.rod]
axis = ["B", "C"]
mass = 0.5
center = {{ from = "B", toward = "C", distance = 0.060 }}
inertia = 0.0018

[links.slider]
mass = 0.4
center = "C"
inertia = 0.0

[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]

[joints.B]
kind = "revolute"
links = ["crank", "rod"]
at = [{B[0]!r}, {B[1]!r}]

[joints.C]
kind = "revolute"
links = ["rod", "slider"]
at = [{C[0]!r}, {C[1]!r}]

[joints.guide]
kind = "prismatic"
links = ["ground", "slider"]
at = {guide}
axis = [1.0, 0.0]

[[drivers]]
joint = "A"
omega = 200.0

[[loads]]
link = "slider"
at = {load}
force = [-1000.0, 0.0]

[points]
P = {{ link = "rod", at = {point} }}
"""


def toward(start: str, end: str, distance: float) -> str:
    return f'{{ from = "{start}", toward = "{end}", distance = {distance!r} }}'


def coords(p: tuple[float, float]) -> str:
    return f"[{p[0]!r}, {p[1]!r}]"


# place -> form -> the text of that form; every form of a place is the same point
FORMS = {
    "guide": {
        "coordinates": coords(C),
        "name": '"C"',
        "toward": toward("A", "C", AC),
    },
    "center": {
        "coordinates": coords(B),
        "name": '"B"',
        "toward": toward("A", "B", AB),
    },
    "axis": {
        "coordinates": f"[{coords(A)}, {coords(B)}]",
        "name": '["A", "B"]',
        "toward": f"[{toward('B', 'A', AB)}, {toward('A', 'B', AB)}]",
    },
    "load": {
        "coordinates": coords(C),
        "name": '"C"',
        "toward": toward("A", "C", AC),
    },
    "point": {
        "coordinates": coords(B),
        "name": '"B"',
        "toward": toward("A", "B", AB),
    },
}
PLACES = sorted(FORMS)
KINDS = ("coordinates", "name", "toward")
ANGLES = np.arange(0.0, 360.0, 15.0)


def text(place: str = "", form: str = "name") -> str:
    """The file with every place in the name form but ``place`` in ``form``."""
    chosen = {p: FORMS[p]["name"] for p in PLACES}
    if place:
        chosen[place] = FORMS[place][form]
    return TEMPLATE.format(B=B, C=C, **chosen)


def spec(mech: assur.Mechanism, place: str) -> object:
    """The point specification of ``place`` in ``mech``."""
    return {
        "guide": lambda: mech.joint("guide").at,
        "center": lambda: mech.link("crank").center,
        "axis": lambda: mech.link("crank").axis,
        "load": lambda: mech.loads[0].at,
        "point": lambda: mech.points[0].at,
    }[place]()


def form_of(value: object) -> str:
    if isinstance(value, str):
        return "name"
    if isinstance(value, Toward):
        return "toward"
    assert isinstance(value, tuple)
    assert all(isinstance(v, float) for v in value)
    return "coordinates"


@pytest.fixture(scope="module")
def reference() -> assur.Table:
    return assur.forces(assur.loads(text()), ANGLES)


@pytest.mark.parametrize("form", KINDS)
@pytest.mark.parametrize("place", PLACES)
def test_every_form_in_every_place(place, form, reference):
    mech = assur.loads(text(place, form))
    value = spec(mech, place)
    points = value if place == "axis" else (value,)
    assert [form_of(p) for p in points] == [form] * len(points)
    expected = [A, B] if place == "axis" else [C if place in ("guide", "load") else B]
    for p, where in zip(points, expected, strict=True):
        np.testing.assert_allclose(resolve_point(mech, p), where, rtol=0, atol=1e-15)
    table = assur.forces(mech, ANGLES)
    assert table.columns == reference.columns
    for column in table.columns:
        np.testing.assert_allclose(
            table[column], reference[column], rtol=1e-9, atol=1e-9, err_msg=column
        )


@pytest.mark.parametrize("form", KINDS)
@pytest.mark.parametrize("place", PLACES)
def test_round_trip_keeps_the_form(place, form):
    mech = assur.loads(text(place, form))
    written = assur.dumps(mech)
    again = assur.loads(written)
    assert again == mech
    assert assur.dumps(again) == written
    value = spec(again, place)
    points = value if place == "axis" else (value,)
    assert {form_of(p) for p in points} == {form}


def test_dumps_writes_the_axis_as_given():
    names = assur.dumps(assur.loads(text("axis", "name")))
    assert 'axis = ["A", "B"]' in names
    numbers = assur.dumps(assur.loads(text("axis", "coordinates")))
    assert f"axis = [[0.0, 0.0], [{B[0]!r}, {B[1]!r}]]" in numbers
    towards = assur.dumps(assur.loads(text("axis", "toward")))
    assert re.search(
        r'axis = \[\{ from = "B", toward = "A", distance = [0-9.e-]+ \}, ', towards
    )


def test_axis_of_mixed_forms():
    mech = assur.loads(
        text("axis", "name").replace('["A", "B"]', f'["A", {coords(B)}]')
    )
    assert mech.link("crank").axis == ("A", B)
    assert assur.loads(assur.dumps(mech)) == mech


WHITWORTH = (EXAMPLES / "whitworth.toml").read_text(encoding="utf-8")


def test_axis_through_the_pin_of_a_block_sliding_on_the_link():
    """B is the pin of the block in the lever's slot, not a point of the lever."""
    through_pin = WHITWORTH.replace('axis = ["E", "O4"]', 'axis = ["O4", "B"]')
    mech = assur.loads(through_pin)
    angles = np.arange(45.0, 405.0, 30.0)
    got = assur.kinematics(mech, angles)
    base = assur.kinematics(assur.loads(WHITWORTH), angles)
    # the lever's angle is measured from another line of the lever: a constant shift
    o4 = np.array([0.0, 0.03])
    b = np.array([0.042426406871192854, 0.04242640687119285])
    e = np.array([-0.04798414911303337, 0.01594576811425899])
    shift = math.degrees(math.atan2(*(b - o4)[::-1]) - math.atan2(*(o4 - e)[::-1]))
    np.testing.assert_allclose(
        (got["lever.angle"] - base["lever.angle"] - shift + 180.0) % 360.0 - 180.0,
        0.0,
        atol=1e-9,
    )
    for column in base.columns:
        if column != "lever.angle":
            np.testing.assert_allclose(got[column], base[column], atol=1e-12)


def test_axis_through_coordinates_reads_like_names():
    names = WHITWORTH.replace('axis = ["E", "O4"]', 'axis = ["O4", "B"]')
    numbers = WHITWORTH.replace(
        'axis = ["E", "O4"]',
        "axis = [[0.0, 0.03], [0.042426406871192854, 0.04242640687119285]]",
    )
    angles = np.arange(0.0, 360.0, 20.0)
    a = assur.kinematics(assur.loads(names), angles)
    b = assur.kinematics(assur.loads(numbers), angles)
    np.testing.assert_array_equal(a.to_array(), b.to_array())


def test_a_joint_name_on_a_link_it_does_not_touch():
    """A name stands for where the joint is in the reference pose, on any link."""
    by_name = text().replace('[[loads]]\nlink = "slider"', '[[loads]]\nlink = "crank"')
    by_coordinates = by_name.replace('at = "C"\nforce', f"at = {coords(C)}\nforce")
    assert by_coordinates != by_name
    a = assur.forces(assur.loads(by_name), ANGLES)
    b = assur.forces(assur.loads(by_coordinates), ANGLES)
    np.testing.assert_array_equal(a.to_array(), b.to_array())


@pytest.mark.parametrize(
    ("axis", "message"),
    [
        (
            '["A", [0.0, 0.0]]',
            r"^links\.crank\.axis: its two points 'A' and \[0\.0, 0\.0\] coincide "
            r"at \(0, 0\) in the reference pose; expected two distinct points$",
        ),
        (
            f'["B", {toward("A", "B", AB)}]',
            r"^links\.crank\.axis: its two points 'B' and \{from = 'A', toward = 'B', "
            r"distance = 0\.074\d*\} coincide",
        ),
        (
            '["A", "A"]',
            r"^links\.crank\.axis: its two points 'A' and 'A' coincide",
        ),
        (
            "[0.0, 1.0]",
            r"^links\.crank\.axis: expected two points, got the direction "
            r"\[0\.0, 1\.0\]; a direction \[x, y\] is the axis of a prismatic joint",
        ),
        (
            '["A", "B", "C"]',
            r"^links\.crank\.axis: expected two points \(each \[x, y\], a point's "
            r"name or \{from, toward, distance\}\), got \['A', 'B', 'C'\]$",
        ),
        (
            '"A"',
            r"^links\.crank\.axis: expected two points .*, got 'A'$",
        ),
        (
            '["A", "Q"]',
            r"^links\.crank\.axis\[1\]: unknown point 'Q' \(known: A, B, C, P, "
            r"guide\)$",
        ),
        (
            '["A", [0.0, 1.0, 2.0]]',
            r"^links\.crank\.axis\[1\]: expected two numbers \[x, y\], got "
            r"\[0\.0, 1\.0, 2\.0\]$",
        ),
        (
            '["A", { from = "A", toward = "B" }]',
            r"^links\.crank\.axis\[1\]: missing key 'distance' of a point",
        ),
        (
            # from and toward name points: coordinates are a point of their own
            '["A", { from = "A", toward = [0.1, 0.3], distance = 0.01 }]',
            r"^links\.crank\.axis\[1\]\.toward: expected a point's name in quotes, "
            r"got \[0\.1, 0\.3\]$",
        ),
    ],
)
def test_bad_axis(axis, message):
    with pytest.raises(ModelError, match=message):
        assur.loads(text("axis", "name").replace('["A", "B"]', axis, 1))


def test_bad_axis_in_code():
    mech = assur.loads(text())
    crank = mech.link("crank")
    for axis, message in (
        (("A", (0.0, 0.0)), r"coincide"),
        ((1.0, 0.0), r"expected two points"),
        (("A", None), r"^links\.crank\.axis\[1\]: expected two finite numbers"),
        (("A", Toward("A", "Z", 1.0)), r"^links\.crank\.axis\[1\]\.toward: unknown"),
    ):
        links = (crank.__class__(crank.name, axis), *mech.links[1:])
        with pytest.raises(ModelError, match=message):
            assur.Mechanism(links, mech.joints, mech.drivers)


def _with_points(entries: list[str]) -> str:
    """Return the four-bar's file with ``entries`` as points of its coupler."""
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    return text + "".join(
        f'\n[points.{name}]\nlink = "coupler"\nat = {at}\n'
        for name, at in (e.split(" = ", 1) for e in entries)
    )


def test_points_in_a_circle_are_named_in_its_order():
    # "points refer to each other in a circle" named neither the points nor what
    # was expected
    text = _with_points(['X = "Y"', 'Y = { from = "Z", toward = "B", distance = 0.01 }',
                         'Z = "X"'])  # fmt: skip
    with pytest.raises(ModelError) as caught:
        assur.loads(text)
    assert str(caught.value) == (
        "points.X.at: points refer to each other in a circle (X -> Y -> Z -> X); "
        "expected names that lead to coordinates [x, y]"
    )


def test_a_long_chain_of_points_is_no_circle_and_is_read_at_once():
    # each point toward the two before it: read as "in a circle" past 16 of them
    # (the depth counted both ways of each point), and each name was read again
    # on every way to it (2^40 reads for 40 points)
    entries = ["P0 = [0.0, 0.0]", "P1 = [0.01, 0.0]"] + [
        f'P{i} = {{ from = "P{i - 1}", toward = "P{i - 2}", distance = 0.001 }}'
        for i in range(2, 41)
    ]
    mech = assur.loads(_with_points(entries))
    at = {p.name: resolve_point(mech, p.at) for p in mech.points}
    for i in range(2, 41):
        # 1 mm from the point before toward the one before that
        step = at[f"P{i - 2}"] - at[f"P{i - 1}"]
        expected = at[f"P{i - 1}"] + step / np.hypot(*step) * 0.001
        np.testing.assert_allclose(at[f"P{i}"], expected, atol=1e-15)
    chain = ["P0 = [0.0, 0.0]"] + [f'P{i} = "P{i - 1}"' for i in range(1, 70)]
    with pytest.raises(ModelError, match=r"more than 64 deep; expected a shorter"):
        assur.loads(_with_points(chain))


def test_a_circle_met_at_the_end_of_a_chain_is_named_from_its_first_point():
    # V and W lead into the circle and are no part of it: the names before the
    # circle are left out of it
    text = _with_points(['V = "W"', 'W = "X"', 'X = "Y"', 'Y = "Z"', 'Z = "X"'])
    with pytest.raises(ModelError) as caught:
        assur.loads(text)
    assert "in a circle (X -> Y -> Z -> X);" in str(caught.value)


def test_a_chain_of_as_many_names_as_allowed_is_read_and_one_more_refused():
    # DEEPEST names: P64's "P63" leads through P63, ..., P0; one more was let by
    # while the message said "more than 64 deep"
    chain = ["P0 = [0.0, 0.0]"] + [f'P{i} = "P{i - 1}"' for i in range(1, 65)]
    mech = assur.loads(_with_points(chain))
    assert resolve_point(mech, mech.points[-1].at).tolist() == [0.0, 0.0]
    with pytest.raises(ModelError, match=r"^points\.P65\.at: .* more than 64 deep"):
        assur.loads(_with_points([*chain, 'P65 = "P64"']))
