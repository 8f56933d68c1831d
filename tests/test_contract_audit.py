"""Gaps between the format and the package, found by an audit of the file format.

The format is docs/file_format.rst.

Each test holds one: the reference pose's angle in (-180, 180] whatever the sign of
a zero, the dynamic model's table a Table, every driver's power with several, a
JSON format version written 1.0, a point placed at itself named so, and driver
positions beyond the file's own limit refused.
"""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

import assur
from assur import cli
from assur.analysis import default_positions

from .conftest import EXAMPLES

SLIDER_CRANK = EXAMPLES / "slider_crank_exercise.toml"


def slider_crank_text() -> str:
    return SLIDER_CRANK.read_text(encoding="utf-8")


def test_a_reference_angle_of_minus_zero_y_is_180_not_minus_180():
    """atan2(-0.0, x < 0) is -180 deg: the crank's angle started there."""
    mech = assur.load(SLIDER_CRANK)
    joint = mech.joint("B")
    x = -float(np.hypot(*joint.at))
    tables = []
    for y in (-0.0, 0.0):
        joints = tuple(
            dataclasses.replace(j, at=(x, y)) if j.name == "B" else j
            for j in mech.joints
        )
        moved = dataclasses.replace(mech, joints=joints)
        tables.append(assur.kinematics(moved, default_positions(moved)))
    for table in tables:
        assert table["crank.angle"][0] == 180.0
        assert table["angle"][0] == 180.0
    for name in tables[0].columns:
        np.testing.assert_array_equal(tables[0][name], tables[1][name], err_msg=name)


def test_the_dynamic_model_is_a_table():
    result = assur.dynamics(assur.load(EXAMPLES / "four_bar.toml"))
    assert isinstance(result, assur.Table)
    assert result.to_csv().startswith("angle,")


def test_with_several_drivers_each_one_s_power_is_summed_too():
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    angles = np.column_stack([np.arange(60, 420, 1.0), np.arange(120, 480, 1.0)])
    table = assur.forces(mech, angles)
    found = table.summary()
    own = {}
    for name, link in (("A", "left_crank"), ("E", "right_crank")):
        power = table[f"{name}.torque"] * table[f"{link}.omega"]
        own[name] = float(np.mean(power))
        assert found[f"{name}.power.mean"] == pytest.approx(own[name], rel=1e-12)
        assert found[f"{name}.power.max"] == pytest.approx(power.max(), rel=1e-12)
        assert found[f"{name}.power.min"] == pytest.approx(power.min(), rel=1e-12)
        both = table["A.torque"] * table["left_crank.omega"]
        both = both + table["E.torque"] * table["right_crank.omega"]
        assert found["driver.power.max"] == pytest.approx(both.max(), rel=1e-12)
    assert abs(own["A"]) > 1.0  # each crank works; together they do no net work
    assert found["driver.power.mean"] == pytest.approx(
        own["A"] + own["E"], abs=1e-9 * abs(own["A"])
    )


def test_a_json_format_version_of_1_0_is_1(tmp_path):
    data = json.loads(assur.dumps(assur.load(SLIDER_CRANK), json_format=True))
    data["format"] = 1.0
    path = tmp_path / "m.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    assert assur.load(path).name == assur.load(SLIDER_CRANK).name
    data["format"] = 1.5
    path.write_text(json.dumps(data), encoding="utf-8")
    with pytest.raises(
        assur.ModelError, match=r"format: version 1\.5 is not supported"
    ):
        assur.load(path)


@pytest.mark.parametrize(
    ("old", "new", "entry"),
    [
        ("at = [0.05232590180780452, 0.05232590180780451]", 'at = "B"', "joints.B.at"),
        (
            "at = [0.05232590180780452, 0.05232590180780451]",
            'at = { from = "B", toward = "A", distance = 0.1 }',
            "joints.B.at.from",
        ),
    ],
)
def test_a_point_placed_at_itself_is_told_so(old, new, entry):
    """It was called unknown, the list of known points beside it."""
    text = slider_crank_text()
    assert old in text
    with pytest.raises(assur.ModelError) as caught:
        assur.loads(text.replace(old, new, 1))
    assert str(caught.value) == (
        f"{entry}: the point 'B' is placed at itself; expected coordinates [x, y] or "
        "another point"
    )


def test_a_step_below_the_resolution_of_the_positions_is_refused(capsys):
    """1e17:1.0000000000000002e17:1 gave two equal rows: the step of 1 deg is
    below the spacing of floats there (16). A crank angle of 1e300 deg is still an
    angle (taken modulo 360 exactly)."""
    for spec in ("1e17:1.0000000000000002e17:1", "1e14:100000000000000.1:0.001"):
        status = cli.main(["kinematics", str(SLIDER_CRANK), f"--angles={spec}"])
        err = capsys.readouterr().err
        assert status == 2
        assert "the step is below the resolution of the positions" in err
        assert err.count("\n") == 1
    huge = assur.kinematics(assur.load(SLIDER_CRANK), [1e300, np.remainder(1e300, 360)])
    assert huge["slider.G.x"][0] == huge["slider.G.x"][1]
