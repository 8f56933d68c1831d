"""The work of a pass over slices, worked out once per plan and set of columns."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import assur
from assur._recipe import KEPT, recipe
from assur.columns import schema
from assur.plan import plan_of

from .conftest import EXAMPLES


def test_a_recipe_is_worked_out_once_per_plan_and_columns():
    plan = plan_of(assur.catalog.slider_crank())
    columns = [c for c in schema(plan, True) if c.family in ("point", "check")]
    first = recipe(plan, columns, 3, True)
    assert recipe(plan, list(columns), 3, True) is first
    assert recipe(plan, columns, 2, False) is not first
    assert first.checks == (("driver.torque_check", 0),)
    assert not first.residual


def test_a_plan_keeps_a_bounded_number_of_recipes():
    plan = plan_of(assur.catalog.four_bar())
    points = [c for c in schema(plan, False) if c.family == "point"]
    for i in range(KEPT + 10):
        recipe(plan, points[: 1 + i % len(points)], i % 4, i % 2 == 0)
    assert len(plan.memo["recipes"]) <= KEPT


def test_a_point_at_the_place_of_another_has_its_columns(tmp_path: Path):
    # the coupler's centre of mass put at the coupler point P: computed once
    text = (EXAMPLES / "four_bar.toml").read_text()
    old = "center = [0.07026634527443965, 0.0705401769645083]"
    assert old in text
    text = text.replace(old, "center = [0.05715659849033345, 0.10333881224869168]")
    path = tmp_path / "same_place.toml"
    path.write_text(text)
    mech = assur.load(path)
    plan = plan_of(mech)
    how = recipe(plan, list(schema(plan, True)), 3, True)
    assert ("coupler.G.jy", "P.jy") in how.aliases
    angles = np.arange(0.0, 360.0, 10.0)
    table = assur.forces(mech, angles)
    by_name = assur.forces(mech, angles)
    for name, values in zip(table.columns, table.arrays(), strict=True):
        assert np.array_equal(values, by_name[name], equal_nan=True), name
    for part in ("x", "vy", "ax", "jy"):
        assert np.array_equal(table[f"coupler.G.{part}"], table[f"P.{part}"])
