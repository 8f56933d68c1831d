"""Mechanism files (TOML, JSON) and result tables (CSV, JSON).

Reading every form the file contract allows, writing files back (``assur.dumps``,
``assur.save``) so that they read to an equal mechanism, and the CSV and JSON tables.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import math
import tomllib

import numpy as np
import pytest

import assur
from assur import Driver, Joint, Link, Load, LoadTable, Mechanism, Point, Toward
from assur.model import resolve_point

from .conftest import EXAMPLES

SLIDER_CRANK = """\
format = 1
name = "Slider-crank"
description = "every point form, loads, gravity and points"

[links.crank]
axis = ["A", "B"]
mass = 10.0
center = { from = "A", toward = "B", distance = 0.020 }
inertia = 0.0

[links.rod]
axis = ["B", "C"]
mass = 0.5
center = { from = "B", toward = "C", distance = -0.010 }
inertia = 0.0018

[links.slider]
mass = 0.4
center = "C"
inertia = 0.0

[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0, 0]

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
at = "C"
axis = [2.0, 0.0]

[[drivers]]
joint = "A"
omega = 200.0
epsilon = -5

[gravity]
g = [0.0, -9.81]

[[loads]]
link = "slider"
at = "C"
force = { x = [-1000.0, 0.0], y = [0.0, 0.0], over = "guide", table = [-0.2, 0.2] }

[[loads]]
link = "crank"
torque = { values = [1.0, 2.0, 1.0], over = "driver", table = [0, 180, 360] }

[[loads]]
link = "rod"
at = { from = "B", toward = "C", distance = 0.1 }
force = [0.0, -50.0]
torque = 5.0

[points]
P = { link = "rod", at = [0.15, 0.08] }
Q = { link = "rod", at = "P" }
R = { link = "rod", at = { from = "B", toward = "P", distance = 0.05 } }
"""


def expected_mechanism() -> Mechanism:
    """What SLIDER_CRANK describes, built in code."""
    return Mechanism(
        links=(
            Link("crank", ("A", "B"), 10.0, Toward("A", "B", 0.020), 0.0),
            Link("rod", ("B", "C"), 0.5, Toward("B", "C", -0.010), 0.0018),
            Link("slider", None, 0.4, "C", 0.0),
        ),
        joints=(
            Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
            Joint("B", "revolute", ("crank", "rod"), (0.052326, 0.052326)),
            Joint("C", "revolute", ("rod", "slider"), (0.245313, 0.0)),
            Joint("guide", "prismatic", ("ground", "slider"), "C", (2.0, 0.0)),
        ),
        drivers=(Driver("A", 200.0, -5.0),),
        name="Slider-crank",
        description="every point form, loads, gravity and points",
        gravity=(0.0, -9.81),
        loads=(
            Load(
                "slider",
                "C",
                LoadTable("guide", (-0.2, 0.2), ((-1000.0, 0.0), (0.0, 0.0))),
            ),
            Load(
                "crank",
                torque=LoadTable("driver", (0.0, 180.0, 360.0), ((1.0, 2.0, 1.0),)),
            ),
            Load("rod", Toward("B", "C", 0.1), (0.0, -50.0), 5.0),
        ),
        points=(
            Point("P", "rod", (0.15, 0.08)),
            Point("Q", "rod", "P"),
            Point("R", "rod", Toward("B", "P", 0.05)),
        ),
    )


# --- reading -----------------------------------------------------------------------


def test_toml_reads_every_form():
    assert assur.loads(SLIDER_CRANK) == expected_mechanism()


def test_load_reads_a_toml_file(tmp_path):
    path = tmp_path / "slider.toml"
    path.write_text(SLIDER_CRANK, encoding="utf-8")
    assert assur.load(path) == expected_mechanism()
    assert assur.load(str(path)) == expected_mechanism()


@pytest.mark.parametrize("suffix", [".json", ".JSON"])
def test_json_reads_like_toml(tmp_path, suffix):
    path = tmp_path / f"slider{suffix}"
    path.write_text(json.dumps(tomllib.loads(SLIDER_CRANK)), encoding="utf-8")
    assert assur.load(path) == expected_mechanism()


def test_loads_json_text():
    text = json.dumps(tomllib.loads(SLIDER_CRANK), indent=1)
    assert assur.loads(text, json_format=True) == expected_mechanism()


def test_point_forms_resolve():
    mech = assur.loads(SLIDER_CRANK)
    b, c = np.array([0.052326, 0.052326]), np.array([0.245313, 0.0])
    unit = (c - b) / np.hypot(*(c - b))
    np.testing.assert_allclose(
        resolve_point(mech, mech.joint("guide").at), c, rtol=0, atol=1e-15
    )
    np.testing.assert_allclose(
        resolve_point(mech, mech.link("rod").center),
        b - 0.010 * unit,
        rtol=0,
        atol=1e-15,
    )
    np.testing.assert_allclose(
        resolve_point(mech, mech.loads[2].at), b + 0.1 * unit, rtol=0, atol=1e-15
    )
    p = np.array([0.15, 0.08])
    np.testing.assert_allclose(resolve_point(mech, "Q"), p, rtol=0, atol=1e-15)
    toward_p = (p - b) / np.hypot(*(p - b))
    np.testing.assert_allclose(
        resolve_point(mech, "R"), b + 0.05 * toward_p, rtol=0, atol=1e-15
    )


def test_optional_keys_take_their_defaults():
    text = SLIDER_CRANK.replace("epsilon = -5\n", "").replace(
        'name = "Slider-crank"\n', ""
    )
    text = text.replace("format = 1\n", "")
    mech = assur.loads(text)
    assert mech.drivers == (Driver("A", 200.0, 0.0),)
    assert mech.name == ""


def test_gravity_table_without_g_is_standard_gravity():
    text = SLIDER_CRANK.replace("g = [0.0, -9.81]\n", "")
    assert assur.loads(text).gravity == (0.0, -9.81)


def test_gravity_is_optional():
    text = SLIDER_CRANK.replace("[gravity]\ng = [0.0, -9.81]\n", "")
    assert assur.loads(text).gravity is None


def test_gravity_vector(tmp_path):
    text = SLIDER_CRANK.replace("g = [0.0, -9.81]", "g = [1.5, -3]")
    assert assur.loads(text).gravity == (1.5, -3.0)


def test_load_table_over_the_driver_in_an_example():
    mech = assur.load(EXAMPLES / "whitworth.toml")
    (load,) = mech.loads
    assert isinstance(load.force, LoadTable)
    assert load.force.over == "driver"
    assert load.force.table[0] == 0.0
    assert load.force.table[-1] == 360.0
    assert len(load.force.values) == 2
    assert all(len(v) == len(load.force.table) for v in load.force.values)


def test_load_table_over_a_slide_is_applied():
    # the guide table says -1000 N at a slide of -0.2 m and 0 N at +0.2 m: linear
    mech = assur.loads(SLIDER_CRANK)
    table = assur.forces(mech, [0.0, 45.0, 90.0])
    s = table["guide.s"]
    assert np.all(np.abs(s) < 0.2)
    without = dataclasses.replace(mech, loads=mech.loads[1:])
    base = assur.forces(without, [0.0, 45.0, 90.0])
    # the table's force acts on the slider along x, so it changes the guide's reaction
    # by nothing along y and the pin C's reaction on the slider by minus the force
    fx = -1000.0 + (s + 0.2) / 0.4 * 1000.0
    np.testing.assert_allclose(table["C.Fx"] - base["C.Fx"], -fx, rtol=1e-9, atol=1e-6)


# --- writing -----------------------------------------------------------------------


def test_round_trip_every_example(example, tmp_path):
    text = assur.dumps(example)
    again = assur.loads(text)
    assert again == example
    assert assur.dumps(again) == text
    path = tmp_path / "again.toml"
    assur.save(example, path)
    assert assur.load(path) == example
    assert path.read_text(encoding="utf-8") == text


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_every_example_reads_the_same_as_json(path, tmp_path):
    target = tmp_path / f"{path.stem}.json"
    target.write_text(
        json.dumps(tomllib.loads(path.read_text(encoding="utf-8"))), encoding="utf-8"
    )
    assert assur.load(target) == assur.load(path)


def test_round_trip_every_example_through_json(example, tmp_path):
    # save() to a .json name wrote TOML, which load() then read as JSON and refused
    path = tmp_path / "again.JSON"
    assur.save(example, path)
    data = json.loads(path.read_text(encoding="utf-8"))
    assert data == tomllib.loads(assur.dumps(example))
    assert assur.load(path) == example
    assert assur.loads(assur.dumps(example, json_format=True), json_format=True) == (
        example
    )


def test_round_trip_a_delete_character():
    # JSON's escapes leave U+007F as it is; TOML forbids it raw in a string
    # (in the description: a name holds no control character)
    mech = dataclasses.replace(assur.catalog.four_bar(), description="a\x7fb\x7f")
    text = assur.dumps(mech)
    assert "\x7f" not in text
    assert assur.loads(text) == mech


def test_json_null_is_a_missing_optional_key():
    # docs/file_format.rst: in JSON, null for an optional key is the same as leaving
    # the key out
    data = tomllib.loads(assur.dumps(expected_mechanism()))
    data["links"]["crank"]["mass"] = None
    nulls = {
        "format": None,
        "name": None,
        "description": None,
        "gravity": None,
        "points": None,
        "motor": None,
    }
    mech = assur.loads(json.dumps({**data, **nulls}), json_format=True)
    without = {k: v for k, v in data.items() if k not in nulls}
    assert mech == assur.loads(json.dumps(without), json_format=True)
    data["drivers"][0]["epsilon"] = None
    data["joints"]["A"]["friction"] = None
    data["gravity"] = {"g": None}
    data["loads"] = None
    mech = assur.loads(json.dumps(data), json_format=True)
    assert mech.drivers[0].epsilon == 0.0
    assert mech.joints[0].friction == 0.0
    assert mech.gravity == (0.0, -9.81)
    assert mech.loads == ()


def test_json_null_for_a_required_key_is_refused():
    data = tomllib.loads(assur.dumps(expected_mechanism()))
    data["drivers"][0]["omega"] = None
    with pytest.raises(
        assur.ModelError, match=r"drivers\[0\]\.omega: expected a number"
    ):
        assur.loads(json.dumps(data), json_format=True)


def test_round_trip_every_form():
    mech = expected_mechanism()
    assert assur.loads(assur.dumps(mech)) == mech


def test_round_trip_catalog():
    for mech in (assur.catalog.four_bar(), assur.catalog.slider_crank(offset=0.01)):
        assert assur.loads(assur.dumps(mech)) == mech


@pytest.mark.parametrize("name", ["my link", "звено", 'a"b', "1", "true", "x\\y"])
def test_round_trip_names_that_need_quotes(name):
    mech = assur.catalog.four_bar()
    links = tuple(
        dataclasses.replace(x, name=name) if x.name == "coupler" else x
        for x in mech.links
    )
    joints = tuple(
        dataclasses.replace(
            j, links=tuple(name if x == "coupler" else x for x in j.links)
        )
        for j in mech.joints
    )
    points = tuple(dataclasses.replace(p, link=name) for p in mech.points)
    renamed = dataclasses.replace(
        mech,
        links=links,
        joints=joints,
        points=points,
        name=f"four-bar {name}",
        description="tab\there\nline",
    )
    assert assur.loads(assur.dumps(renamed)) == renamed


def test_round_trip_characters_outside_the_bmp():
    mech = dataclasses.replace(assur.catalog.four_bar(), name="four-bar \U0001f642")
    assert assur.loads(assur.dumps(mech)) == mech


def test_dumps_is_valid_toml_with_the_contract_keys():
    data = tomllib.loads(assur.dumps(expected_mechanism()))
    assert data["format"] == 1
    assert data["joints"]["guide"] == {
        "kind": "prismatic",
        "links": ["ground", "slider"],
        "at": "C",
        "axis": [2.0, 0.0],
    }
    assert data["links"]["rod"]["center"] == {
        "from": "B",
        "toward": "C",
        "distance": -0.01,
    }
    assert data["drivers"] == [{"joint": "A", "omega": 200.0, "epsilon": -5.0}]
    assert data["gravity"] == {"g": [0.0, -9.81]}
    assert data["loads"][0]["force"]["over"] == "guide"
    assert data["points"]["Q"] == {"link": "rod", "at": "P"}


def test_floats_survive_exactly():
    mech = assur.load(EXAMPLES / "tenbar.toml")
    again = assur.loads(assur.dumps(mech))
    for a, b in zip(mech.joints, again.joints, strict=True):
        assert a.at == b.at  # repr round-trips every float bit for bit


# --- tables ------------------------------------------------------------------------


@pytest.fixture(scope="module")
def table() -> assur.Table:
    return assur.forces(assur.catalog.slider_crank(), [0.0, 33.3, 90.0, 271.0])


def read_csv(text: str) -> tuple[list[str], list[list[str]]]:
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]


def test_csv_header_is_the_columns(table):
    header, rows = read_csv(table.to_csv())
    assert header == list(table.columns)
    assert header[0] == "angle"
    assert len(rows) == len(table) == 4
    assert all(len(row) == len(header) for row in rows)


def test_csv_has_twelve_significant_digits(table):
    header, rows = read_csv(table.to_csv())
    values = np.array(rows, dtype=float)
    for i, column in enumerate(header):
        np.testing.assert_allclose(
            values[:, i], table[column], rtol=1e-11, atol=1e-300, err_msg=column
        )
        for text, value in zip((r[i] for r in rows), table[column], strict=True):
            assert text == f"{value + 0.0:.12g}", column  # -0 written 0


def test_csv_to_a_path_a_file_and_stdout(table, tmp_path, capsys):
    text = table.to_csv()
    path = tmp_path / "out.csv"
    assert table.to_csv(path) is None
    assert path.read_text(encoding="utf-8") == text
    buffer = io.StringIO()
    table.to_csv(buffer)
    assert buffer.getvalue() == text
    table.to_csv("-")
    assert capsys.readouterr().out == text


def test_csv_of_an_empty_table(tmp_path):
    empty = assur.kinematics(assur.catalog.four_bar(), [])
    assert empty.to_csv() == ",".join(empty.columns) + "\n"


def test_table_json(table):
    data = json.loads(json.dumps(table.to_dict(), allow_nan=False))
    assert data["name"] == "Slider-crank exercise"
    assert data["columns"] == list(table.columns)
    assert len(data["rows"]) == len(table)
    for i, row in enumerate(data["rows"]):
        assert list(row) == list(table.columns)
        for column, value in row.items():
            expected = table[column][i]
            if math.isfinite(expected):
                assert value == expected
            else:
                assert value is None


def test_kinematics_columns_follow_the_contract():
    t = assur.kinematics(assur.loads(SLIDER_CRANK), [45.0])
    for link in ("crank", "rod", "slider"):
        for q in ("angle", "omega", "alpha", "jerk"):
            assert f"{link}.{q}" in t.columns
        for q in ("x", "y", "vx", "vy", "ax", "ay", "jx", "jy"):
            assert f"{link}.G.{q}" in t.columns
    for point in ("A", "B", "C", "guide", "P", "Q", "R"):
        for q in ("x", "y", "vx", "vy", "ax", "ay", "jx", "jy"):
            assert f"{point}.{q}" in t.columns
    for q in ("s", "v", "a", "j"):
        assert f"guide.{q}" in t.columns
    assert "B.s" not in t.columns


def test_csv_to_a_binary_stream():
    # a file opened "wb" or a BytesIO took text and raised a bare TypeError
    table = assur.kinematics(assur.catalog.four_bar(), [0.0, 90.0])
    binary = io.BytesIO()
    table.to_csv(binary)
    text = io.StringIO()
    table.to_csv(text)
    assert binary.getvalue().decode("utf-8") == text.getvalue() == table.to_csv()


@pytest.mark.parametrize("thing", [None, {"angle": [0.0]}, 3])
def test_writing_something_that_is_not_a_table_is_refused(thing, tmp_path):
    # an AttributeError ('NoneType' object has no attribute 'columns') before
    from assur.io import write_csv, write_parquet

    for write in (write_csv, write_parquet):
        with pytest.raises(assur.UsageError, match=r"^table: expected a table of"):
            write(thing, tmp_path / "t.out")
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize(
    ("name", "text"), [("e.toml", ""), ("b.toml", "\n \n"), ("e.json", "{}")]
)
def test_an_empty_file_is_said_to_be_empty(tmp_path, capsys, name, text):
    # "links: no moving links" named one of the many things an empty file lacks
    from assur.cli import main

    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    with pytest.raises(assur.ModelError, match="the file has no entries; expected a"):
        assur.load(path)
    assert main(["structure", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert err[0].startswith(f"assur: error: {path}: the file has no entries")


def test_a_mechanism_file_in_utf16_is_named_so(tmp_path):
    # "byte 0 cannot be decoded" left the user to guess that their editor had
    # saved the file as "Unicode"
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    for encoding in ("utf-16", "utf-16-be"):
        path = tmp_path / f"{encoding}.toml"
        data = text.encode(encoding)
        path.write_bytes(data if data[:2] in (b"\xff\xfe", b"\xfe\xff") else
                         b"\xfe\xff" + data)  # fmt: skip
        with pytest.raises(assur.ModelError) as caught:
            assur.load(path)
        assert str(caught.value) == (
            f"{path}: UTF-16 text (it starts with UTF-16's byte-order mark); "
            "expected a TOML or JSON file saved as UTF-8"
        )
    path = tmp_path / "utf32.toml"
    path.write_bytes(text.encode("utf-32"))  # its mark starts as UTF-16's does
    with pytest.raises(assur.ModelError, match=r"UTF-32 text \(it starts with UTF-32"):
        assur.load(path)
    # UTF-8 with its mark is read
    (tmp_path / "bom.toml").write_bytes(text.encode("utf-8-sig"))
    assert (
        assur.load(tmp_path / "bom.toml").name
        == assur.load(EXAMPLES / "four_bar.toml").name
    )
