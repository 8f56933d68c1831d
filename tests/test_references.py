"""Validation against the reference tables of the three seed documents.

Sources: the ten-bar advance-and-grip mechanism (seed 000, kinematics with jerk), the
kinetostatics lecture's slider-crank exercise (seed 001) and the lever mechanism sheet
(seed 002), rebuilt with reference tables in tests/data (see its README). Tolerance:
1e-6 relative (1e-6 degrees on angles), as the tables carry 12 significant digits.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest

import assur

from .conftest import DATA

CASES = [
    ("tenbar.toml", "tenbar_0p1.csv", False, None),
    ("tenbar.toml", "tenbar_0p01.csv", False, None),
    ("lever_var9.toml", "lever_var9.csv", False, None),
    ("slider_crank_exercise.toml", "slider_crank_exercise.csv", True, None),
    (
        "slider_crank_exercise.toml",
        "slider_crank_exercise_gravity.csv",
        True,
        (0.0, -9.81),
    ),
]


def read_table(name: str) -> dict[str, np.ndarray]:
    with open(DATA / name, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    values = np.array(rows[1:], dtype=float)
    return {column: values[:, i] for i, column in enumerate(rows[0])}


def compare(table: assur.Table, reference: dict[str, np.ndarray]) -> None:
    for column, expected in reference.items():
        got = table[column]
        if column.endswith(".angle") or column == "angle":
            diff = (got - expected + 180.0) % 360.0 - 180.0
            np.testing.assert_allclose(diff, 0.0, atol=1e-6, err_msg=column)
        else:
            scale = np.max(np.abs(expected))
            np.testing.assert_allclose(
                got, expected, rtol=1e-6, atol=1e-6 * max(scale, 1e-3), err_msg=column
            )


@pytest.mark.parametrize(("mechanism", "table", "with_forces", "gravity"), CASES)
def test_reference_table(mechanism, table, with_forces, gravity):
    import dataclasses

    mech = assur.load(DATA / mechanism)
    if gravity is not None:
        mech = dataclasses.replace(mech, gravity=gravity)
    reference = read_table(table)
    run = assur.forces if with_forces else assur.kinematics
    compare(run(mech, reference["angle"]), reference)


def test_slider_crank_lecture_numbers():
    """The exercise's printed results at 45 degrees (seed 001), Fi2 = m2 aG2."""
    t = assur.forces(assur.load(DATA / "slider_crank_exercise.toml"), [45.0])
    a_g1 = np.hypot(t["crank.G.ax"], t["crank.G.ay"])[0]
    a_g2 = np.hypot(t["rod.G.ax"], t["rod.G.ay"])[0]
    a_c = abs(t["C.ax"][0])
    np.testing.assert_allclose(
        [a_g1, a_g2, t["rod.alpha"][0], a_c],
        [800.0, 2565.132, 10046.125, 2134.726],
        rtol=1e-6,
    )
    fi = [
        np.hypot(t[f"{n}.Fi.x"], t[f"{n}.Fi.y"])[0] for n in ("crank", "rod", "slider")
    ]
    np.testing.assert_allclose(fi, [8000.0, 1282.566, 853.890], rtol=1e-6)
    np.testing.assert_allclose(abs(t["rod.Mi"][0]), 18.083, rtol=1e-4)
    np.testing.assert_allclose(t["driver.torque"][0], 84.625, rtol=1e-6)
