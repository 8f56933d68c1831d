"""Bad input: every fault of a mechanism file gives one message naming the entry.

Each case is a file written to ``tmp_path`` and read with :func:`assur.load`, so the
message also names the file. Faults found when the structure or the forces are asked
for (wrong number of drivers, links left over, loads that cannot be applied) name the
entry; the command line adds the file (tests/test_cli.py runs the same cases).
"""

from __future__ import annotations

import json
import re
import tomllib
from dataclasses import dataclass

import pytest

import assur
from assur import (
    AssurError,
    DecompositionError,
    Driver,
    Joint,
    Link,
    Mechanism,
    ModelError,
    Toward,
)

from .conftest import EXAMPLES

BASE = """\
format = 1
name = "Slider-crank"

[links.crank]
axis = ["A", "B"]
mass = 10.0
center = { from = "A", toward = "B", distance = 0.020 }
inertia = 0.0

[links.rod]
axis = ["B", "C"]
mass = 0.5
center = { from = "B", toward = "C", distance = 0.060 }
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
at = [0.052326, 0.052326]

[joints.C]
kind = "revolute"
links = ["rod", "slider"]
at = [0.245313, 0.0]

[joints.guide]
kind = "prismatic"
links = ["ground", "slider"]
at = [0.245313, 0.0]
axis = [1.0, 0.0]

[[drivers]]
joint = "A"
omega = 200.0
"""

LEFTOVER = """\
# links 2 and 3 make a rigid truss on the frame, links 4 and 5 dangle from the crank
format = 1
[links.1]
[links.2]
[links.3]
[links.4]
[links.5]
[joints.A]
kind = "revolute"
links = ["ground", "1"]
at = [0.0, 0.0]
[joints.g1]
kind = "revolute"
links = ["ground", "2"]
at = [1.0, 1.0]
[joints.g2]
kind = "revolute"
links = ["ground", "2"]
at = [1.0, 2.0]
[joints.j23]
kind = "revolute"
links = ["2", "3"]
at = [2.0, 2.0]
[joints.g3]
kind = "revolute"
links = ["ground", "3"]
at = [3.0, 3.0]
[joints.j14]
kind = "revolute"
links = ["1", "4"]
at = [0.0, 1.0]
[joints.j45]
kind = "revolute"
links = ["4", "5"]
at = [0.0, 2.0]
[[drivers]]
joint = "A"
omega = 1.0
"""


def edit(*pairs: str, text: str = BASE) -> str:
    """BASE with each ``old`` replaced by ``new`` (once; ``old`` must be there)."""
    for old, new in zip(pairs[::2], pairs[1::2], strict=True):
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def load_table(table: str) -> str:
    return BASE + f'\n[[loads]]\nlink = "slider"\nat = "C"\nforce = {table}\n'


@dataclass(frozen=True)
class Bad:
    """A bad mechanism file and the error it must give.

    ``stage`` is where the fault shows: ``"load"`` (reading the file), ``"structure"``
    or ``"forces"`` (at the driver positions ``ANGLES``). ``match`` is searched in
    the message after the file's name.
    """

    text: str
    stage: str
    error: type[AssurError]
    match: str
    suffix: str = ".toml"


ANGLES = [0.0, 10.0]

BAD = {
    "unreadable-toml": Bad(
        edit("[links.rod]", "[links.rod"),
        "load",
        ModelError,
        r"^not valid TOML: .*line 10",
    ),
    "unreadable-json": Bad(
        '{"links": {', "load", ModelError, r"^not valid JSON: ", ".json"
    ),
    "unknown-key": Bad(
        edit("inertia = 0.0018", "inertai = 0.0018"),
        "load",
        ModelError,
        r"^links\.rod\.inertai: unknown key 'inertai'; "
        r"did you mean 'inertia'\?$",
    ),
    "unknown-top-key": Bad(
        "nmae = 'x'\n" + BASE,
        "load",
        ModelError,
        r"^nmae: unknown key 'nmae'; did you mean 'name'\?$",
    ),
    "unknown-key-in-point": Bad(
        edit("distance = 0.060", "distanse = 0.060"),
        "load",
        ModelError,
        r"^links\.rod\.center\.distanse: unknown key "
        r"'distanse'; did you mean 'distance'\?$",
    ),
    "unknown-link-in-joint": Bad(
        edit('links = ["crank", "rod"]', 'links = ["crank", "rdo"]'),
        "load",
        ModelError,
        r"^joints\.B\.links: unknown link "
        r"'rdo'; did you mean 'rod'\?$",
    ),
    "link-without-joints": Bad(
        BASE.replace("[links.slider]", "[links.lonely]\n\n[links.slider]"),
        "load",
        ModelError,
        r"^links\.lonely: a link with no joints; expected it in "
        r"some joint's links$",
    ),
    "joint-to-itself": Bad(
        edit('links = ["crank", "rod"]', 'links = ["rod", "rod"]'),
        "load",
        ModelError,
        r"^joints\.B\.links: joins link 'rod' to "
        r"itself; expected two different links$",
    ),
    "duplicate-joint-toml": Bad(
        BASE + '[joints.B]\nkind = "revolute"\nlinks = ["crank", '
        '"rod"]\nat = [0.0, 0.0]\n',
        "load",
        ModelError,
        r"^not valid TOML: Cannot declare \('joints', 'B'\) twice",
    ),
    "prismatic-without-axis": Bad(
        edit("axis = [1.0, 0.0]\n", ""),
        "load",
        ModelError,
        r"^joints\.guide: a prismatic joint needs an 'axis' "
        r"\[x, y\]$",
    ),
    "prismatic-zero-axis": Bad(
        edit("axis = [1.0, 0.0]", "axis = [0.0, 0.0]"),
        "load",
        ModelError,
        r"^joints\.guide\.axis: zero axis \[0\.0, 0\.0\];"
        r" expected a nonzero direction$",
    ),
    "toward-same-point": Bad(
        edit('toward = "C"', 'toward = "B"'),
        "load",
        ModelError,
        r"^links\.rod\.center: 'from' and 'toward' are the same point "
        r"'B'; expected two distinct points$",
    ),
    "toward-coinciding-points": Bad(
        edit(
            "at = [0.245313, 0.0]\n\n[joints.guide]",
            'at = { from = "A", toward = "guide", distance = 0.2 }\n\n[joints.guide]',
            "at = [0.245313, 0.0]\naxis",
            "at = [0.0, 0.0]\naxis",
        ),
        "load",
        ModelError,
        r"^joints\.C\.at: points 'A' and 'guide' coincide; expected "
        r"two distinct points$",
    ),
    "toward-unknown-point": Bad(
        edit('toward = "C"', 'toward = "Z"'),
        "load",
        ModelError,
        r"^links\.rod\.center\.toward: unknown point 'Z'",
    ),
    "negative-mass": Bad(
        edit("mass = 0.5", "mass = -0.5"),
        "load",
        ModelError,
        r"^links\.rod\.mass: expected a number >= 0, got -0\.5$",
    ),
    "negative-inertia": Bad(
        edit("inertia = 0.0018", "inertia = -0.0018"),
        "load",
        ModelError,
        r"^links\.rod\.inertia: expected a number >= 0, "
        r"got -0\.0018$",
    ),
    "mass-not-a-number": Bad(
        edit("mass = 0.5", 'mass = "heavy"'),
        "load",
        ModelError,
        r"^links\.rod\.mass: expected a number, got 'heavy'$",
    ),
    "unknown-joint-kind": Bad(
        edit('kind = "revolute"', 'kind = "revolut"'),
        "load",
        ModelError,
        r"^joints\.A\.kind: unknown kind 'revolut'; "
        r"expected revolute, prismatic or slot$",
    ),
    "missing-joint-key": Bad(
        edit("at = [0.052326, 0.052326]\n", ""),
        "load",
        ModelError,
        r"^joints\.B: missing key 'at'; expected where it is in the reference pose: "
        r"\[x, y\], a joint's name or \{from, toward, distance\}$",
    ),
    "bad-vector": Bad(
        edit("at = [0.052326, 0.052326]", "at = [0.05, 0.05, 0.0]"),
        "load",
        ModelError,
        r"^joints\.B\.at: expected two numbers \[x, y\], got "
        r"\[0\.05, 0\.05, 0\.0\]$",
    ),
    "format-version": Bad(
        edit("format = 1", "format = 2"),
        "load",
        ModelError,
        r"^format: version 2 is not supported; expected 1$",
    ),
    "unknown-driver-joint": Bad(
        edit('joint = "A"', 'joint = "AA"'),
        "load",
        ModelError,
        r"^drivers\[0\]\.joint: unknown joint 'AA'; did you mean "
        r"'A'\?$",
    ),
    "driver-off-the-frame": Bad(
        edit('joint = "A"', 'joint = "B"'),
        "load",
        ModelError,
        r"^drivers\[0\]\.joint: joint 'B' joins 'crank' and 'rod'; "
        r"a driver must act between the frame \('ground'\) and its "
        r"input link$",
    ),
    "driven-twice": Bad(
        BASE + '\n[[drivers]]\njoint = "A"\nomega = 1.0\n',
        "load",
        ModelError,
        r"^drivers\[1\]\.joint: joint 'A' is driven twice; expected each driver on "
        r"a joint of its own$",
    ),
    "no-driver": Bad(
        edit('[[drivers]]\njoint = "A"\nomega = 200.0\n', ""),
        "structure",
        DecompositionError,
        r"^drivers: the mechanism has W = 3\*3 - 2\*4 - 0 "
        r"= 1 degree of freedom but 0 drivers; expected one driver per "
        r"degree of freedom$",
    ),
    "two-drivers-one-dof": Bad(
        BASE + '\n[[drivers]]\njoint = "guide"\nomega = 1.0\n',
        "structure",
        DecompositionError,
        r"^drivers: .* = 1 degree of freedom but 2 drivers",
    ),
    "links-left-over": Bad(
        LEFTOVER,
        "structure",
        DecompositionError,
        r"^links 2, 3, 4 and 5 are left over: they form no Assur group",
    ),
    "load-on-unknown-link": Bad(
        BASE + '\n[[loads]]\nlink = "rdo"\nat = "C"\nforce = [1.0, 0.0]\n',
        "load",
        ModelError,
        r"^loads\[0\]\.link: unknown link 'rdo'; did you mean "
        r"'rod'\?$",
    ),
    "load-at-unknown-point": Bad(
        BASE + '\n[[loads]]\nlink = "rod"\nat = "Q"\nforce = [1.0, 0.0]\n',
        "load",
        ModelError,
        r"^loads\[0\]\.at: unknown point 'Q' \(known: A, B, C, "
        r"guide\)$",
    ),
    "load-table-over-unknown-joint": Bad(
        load_table('{ x = [0, 0], y = [0, 0], over = "giude", table = [0, 1] }'),
        "load",
        ModelError,
        r"^loads\[0\]\.force\.over: expected 'driver' or a prismatic joint, "
        r"got 'giude'; did you mean 'guide'\?$",
    ),
    "load-table-short-of-the-slide": Bad(
        load_table(
            '{ x = [-100, -100], y = [0, 0], over = "guide", table = [-0.01, 0.01] }'
        ),
        "forces",
        ModelError,
        r"^loads\[0\]\.force\.table: covers -0\.01 to 0\.01 m but the "
        r"slide of joint 'guide' runs from 0\.02\d* to 0\.028\d* m; expected a table "
        r"covering every analysed position$",
    ),
    "mass-without-center": Bad(
        edit('center = "C"\n', ""),
        "forces",
        ModelError,
        r"^links\.slider: a link with a mass needs its 'center' "
        r"\(centre of mass\) for the force analysis$",
    ),
    "mass-without-inertia": Bad(
        edit("inertia = 0.0018\n", ""),
        "forces",
        ModelError,
        r"^links\.rod: a link with a mass needs its 'inertia' ",
    ),
    "no-masses-no-loads": Bad(
        edit("mass = 10.0\n", "", "mass = 0.5\n", "", "mass = 0.4\n", ""),
        "forces",
        ModelError,
        r"^forces: no link has a mass and no load is applied; "
        r"expected 'mass', 'center' and 'inertia' on the links or "
        r"\[\[loads\]\] for a force analysis$",
    ),
}


def run(case: Bad, path) -> None:
    """Do what ``case.stage`` says with the file at ``path``."""
    mech = assur.load(path)
    if case.stage == "structure":
        assur.structure(mech)
    elif case.stage == "forces":
        assur.forces(mech, ANGLES)


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_file(name, tmp_path):
    case = BAD[name]
    path = tmp_path / f"{name}{case.suffix}"
    path.write_text(case.text, encoding="utf-8")
    if case.stage != "load":
        assur.load(path)  # reads fine; the fault shows later
    with pytest.raises(case.error) as info:
        run(case, path)
    message = str(info.value)
    assert "\n" not in message
    if case.stage == "load":
        assert message.startswith(f"{path}: ")
        message = message[len(f"{path}: ") :]
    assert re.search(case.match, message), message


def test_every_error_is_an_assur_error_and_model_errors_are_value_errors():
    assert issubclass(ModelError, ValueError)
    for error in (
        ModelError,
        DecompositionError,
        assur.AssemblyError,
        assur.SingularConfigurationError,
    ):
        assert issubclass(error, AssurError)


def test_unreadable_file(tmp_path):
    path = tmp_path / "missing.toml"
    with pytest.raises(
        ModelError,
        match=r"missing\.toml: cannot read the file "
        r"\(No such file or directory\)$",
    ):
        assur.load(path)
    with pytest.raises(ModelError, match=r"cannot read the file"):
        assur.load(tmp_path)


def test_file_not_in_utf8(tmp_path):
    path = tmp_path / "latin1.toml"
    path.write_bytes(
        BASE.replace("Slider-crank", "Manivelle \xe0 coulisse").encode("latin-1")
    )
    with pytest.raises(ModelError, match=r"latin1\.toml: "):
        assur.load(path)


def test_file_with_a_byte_order_mark(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_text("\ufeff" + BASE, encoding="utf-8")
    assert assur.load(path).name == "Slider-crank"


def json_with_duplicate_joint() -> str:
    data = tomllib.loads(BASE)
    text = json.dumps(data)
    joint_b = json.dumps(data["joints"]["B"])
    # a second "B" entry inside "joints": json.loads keeps only the last one
    return text.replace(f'"B": {joint_b}', f'"B": {joint_b}, "B": {joint_b}')


def test_duplicate_joint_in_code():
    mech = assur.loads(BASE)
    twice = (*mech.joints, Joint("B", "revolute", ("crank", "rod"), (0.0, 0.0)))
    with pytest.raises(
        ModelError,
        match=r"^joints\.B: two joints with one name; expected a name for each$",
    ):
        Mechanism(mech.links, twice, mech.drivers)


def test_duplicate_link_in_code():
    with pytest.raises(
        ModelError,
        match=r"^links\.a: two links with one name; expected a name for each$",
    ):
        Mechanism(
            (Link("a"), Link("a")),
            (Joint("A", "revolute", ("ground", "a"), (0.0, 0.0)),),
            (Driver("A", 1.0),),
        )


def test_duplicate_joint_in_json(tmp_path):
    path = tmp_path / "twice.json"
    text = json_with_duplicate_joint()
    assert text.count('"B": {') == 2
    path.write_text(text, encoding="utf-8")
    with pytest.raises(ModelError, match=r"joints\.B"):
        assur.load(path)


def test_center_toward_coinciding_points(tmp_path):
    # C moved onto B: the rod's centre {from = B, toward = C} has no direction
    path = tmp_path / "zero_rod.toml"
    path.write_text(
        edit(
            "at = [0.245313, 0.0]",
            "at = [0.052326, 0.052326]",
            "at = [0.245313, 0.0]",
            "at = [0.052326, 0.052326]",
        ),
        encoding="utf-8",
    )
    with pytest.raises(
        ModelError,
        match=r"links\.rod\.center: points 'B' and 'C' "
        r"coincide",
    ):
        assur.load(path)


def test_model_validates_built_mechanisms():
    crank = Link("crank", ("A", "B"), 1.0, Toward("A", "A", 0.1), 0.1)
    joints = (
        Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
        Joint("B", "revolute", ("crank", "ground"), (1.0, 0.0)),
    )
    with pytest.raises(
        ModelError,
        match=r"^links\.crank\.center: 'from' and 'toward' "
        r"are the same point 'A'",
    ):
        Mechanism((crank,), joints, (Driver("A", 1.0),))
    with pytest.raises(ModelError, match=r"^links\.ground: 'ground' is the frame"):
        Mechanism((Link("ground"),), joints, ())
    with pytest.raises(
        ModelError,
        match=r"^drivers\[0\]\.omega: expected a finite "
        r"number, got nan$",
    ):
        Mechanism((Link("crank"),), joints, (Driver("A", float("nan")),))
    with pytest.raises(
        ModelError,
        match=r"^joints\.B\.links: unknown link 'crnak'; "
        r"did you mean 'crank'\?$",
    ):
        Mechanism(
            (Link("crank"),),
            (joints[0], Joint("B", "revolute", ("crnak", "ground"), (1.0, 0.0))),
            (),
        )


def test_lookup_by_name():
    mech = assur.loads(BASE)
    assert mech.link("rod").mass == 0.5
    assert mech.joint("guide").axis == (1.0, 0.0)
    with pytest.raises(KeyError, match="unknown link 'piston'"):
        mech.link("piston")
    with pytest.raises(KeyError, match="unknown joint 'D'"):
        mech.joint("D")
    # a near miss is named, or the names there are, as the file reader does
    with pytest.raises(KeyError, match=r"unknown link 'rdo'; did you mean 'rod'\?"):
        mech.link("rdo")
    with pytest.raises(KeyError, match=r"unknown joint 'zz' \(known: "):
        mech.joint("zz")


def test_mechanism_is_frozen_and_hashable():
    mech = assur.loads(BASE)
    with pytest.raises(AttributeError):
        mech.name = "other"  # type: ignore[misc]
    assert hash(mech) == hash(assur.loads(BASE))


def _parts(mech, **changes):
    """The mechanism's fields with some of its parts changed (a list per part)."""
    fields = {
        "links": list(mech.links),
        "joints": list(mech.joints),
        "drivers": list(mech.drivers),
        "loads": list(mech.loads),
        "points": list(mech.points),
        "gravity": mech.gravity,
    }
    for name, change in changes.items():
        fields[name] = change(fields[name])
    return fields


def _replace(items, index, **values):
    import dataclasses

    items[index] = dataclasses.replace(items[index], **values)
    return items


NAN = float("nan")
NUMERIC_FAULTS = {
    "mass": {"links": lambda x: _replace(x, 0, mass=NAN)},
    "inertia": {"links": lambda x: _replace(x, 1, inertia=-1.0)},
    "distance": {"links": lambda x: _replace(x, 0, center=Toward("A", "B", 1e300))},
    "coordinates": {"joints": lambda x: _replace(x, 1, at=(NAN, 0.1))},
    "axis": {"joints": lambda x: _replace(x, 3, axis=(0.0, 0.0))},
    "friction": {"joints": lambda x: _replace(x, 0, friction=0.1)},
    "radius": {"joints": lambda x: _replace(x, 0, friction=0.1, radius=-1.0)},
    "omega": {"drivers": lambda x: _replace(x, 0, omega=float("inf"))},
    "gravity": {"gravity": lambda g: (0.0, NAN)},
    "two": {
        "links": lambda x: _replace(x, 0, mass=-2.0),
        "drivers": lambda x: _replace(x, 0, epsilon=NAN),
    },
    "coincide": {
        "joints": lambda x: _replace(_replace(x, 1, at=(0.0, 0.0)), 2, at=(0.0, 0.0))
    },
}


@pytest.mark.parametrize("fault", sorted(NUMERIC_FAULTS))
def test_a_known_skeleton_gives_the_full_checks_message(fault, monkeypatch):
    # a mechanism whose skeleton passed before has only its numbers checked; its
    # message must be the one every check gives
    from assur import _validation, catalog

    base = catalog.slider_crank()
    assert _validation._skeleton(base) in _validation._VALID
    fields = _parts(base, **NUMERIC_FAULTS[fault])
    with pytest.raises(ModelError) as quick:
        Mechanism(**fields)
    every = _validation._validate_all
    ran = []
    monkeypatch.setattr(_validation, "_VALID", set())
    monkeypatch.setattr(
        _validation, "_validate_all", lambda m: ran.append(1) or every(m)
    )
    with pytest.raises(ModelError) as full:
        Mechanism(**fields)
    assert ran
    assert str(quick.value) == str(full.value)


@pytest.mark.parametrize(
    ("block", "entry", "why"),
    [
        (
            '[[loads]]\nlink = "ground"\ntorque = 1.0\n',
            "loads[0].link",
            "a load on it acts on no moving link and changes no reaction",
        ),
        (
            '[points.Q]\nlink = "ground"\nat = [0.0, 0.0]\n',
            "points.Q.link",
            "a point on it never moves",
        ),
    ],
)
def test_a_load_or_point_on_the_frame_says_it_is_the_frame(block, entry, why):
    # it was "unknown link 'ground'", of the name the file format gives the frame
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    with pytest.raises(assur.ModelError) as caught:
        assur.loads(text + "\n" + block)
    assert str(caught.value) == (
        f"{entry}: 'ground' is the frame: {why}; expected a moving link (crank, "
        "coupler or rocker)"
    )


def _huge(field: str) -> assur.Mechanism:
    """The catalog's four-bar with ``field`` given an integer of 401 digits."""
    import dataclasses

    from assur.model import Load, LoadTable, Motor, Toward

    m, big, swap = assur.catalog.four_bar(), 10**400, dataclasses.replace
    crank, pivot = m.links[0], m.joints[0]
    made = {
        "mass": lambda: swap(m, links=(swap(crank, mass=big), *m.links[1:])),
        "distance": lambda: swap(
            m, links=(swap(crank, center=Toward("A", "B", big)), *m.links[1:])
        ),
        "at": lambda: swap(m, joints=(swap(pivot, at=(big, 0)), *m.joints[1:])),
        "friction": lambda: swap(m, joints=(swap(pivot, friction=big), *m.joints[1:])),
        "omega": lambda: swap(m, drivers=(swap(m.drivers[0], omega=big),)),
        "torque": lambda: swap(m, loads=(Load("crank", None, None, big),)),
        "table": lambda: swap(
            m, loads=(Load("crank", "A", LoadTable("driver", (0, big), ((0, 1),) * 2)),)
        ),
        "no_load_speed": lambda: swap(m, motor=Motor(5.0, big)),
    }
    return made[field]()  # type: ignore[no-any-return]


@pytest.mark.parametrize(
    "field",
    ["mass", "distance", "at", "friction", "omega", "torque", "table", "no_load_speed"],
)
def test_an_integer_too_large_for_a_float_is_named_in_code_as_in_a_file(field):
    # an OverflowError from math.isfinite, where a file's gets one line
    with pytest.raises(assur.ModelError, match=rf"{field}: .*an integer of 401 digits"):
        _huge(field)
