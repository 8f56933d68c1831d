"""External loads, gravity and load tables in the force analysis.

Hand-checkable cases: a tabulated load equals the constant load it tabulates, a table
over the driver is periodic, a table over a slide follows the slide, gravity acts like
forces ``m g`` at the centres of mass, and a static slider-crank balances a piston
force by the lever arm of the crank.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import assur
from assur.model import Load, LoadTable

ANGLES = np.arange(0.0, 360.0, 15.0)


def crank_slider(load: Load, omega: float = 0.0, gravity=None) -> assur.Mechanism:
    """The catalog slider-crank without masses, with one load, at rest by default."""
    mech = assur.catalog.slider_crank(omega=omega)
    links = tuple(
        dataclasses.replace(link, mass=None, inertia=None, center=None)
        for link in mech.links
    )
    return dataclasses.replace(mech, links=links, loads=(load,), gravity=gravity)


def test_static_piston_force_matches_lever_arm():
    """At rest, torque = force times the crank's effective arm dx_C/dphi."""
    mech = crank_slider(Load("slider", "C", (-1000.0, 0.0)))
    t = assur.forces(mech, ANGLES)
    kin = assur.kinematics(
        dataclasses.replace(mech, drivers=(assur.Driver("A", 1.0),)), ANGLES
    )
    # virtual work: T * dphi + F * dx_C = 0, and dx_C/dphi is C.vx at omega = 1 rad/s
    np.testing.assert_allclose(t["driver.torque"], 1000.0 * kin["C.vx"], atol=1e-9)


def test_table_over_driver_equals_constant_load():
    table = LoadTable("driver", (0.0, 180.0, 360.0), ((-500.0,) * 3, (20.0,) * 3))
    const = assur.forces(
        crank_slider(Load("slider", "C", (-500.0, 20.0)), 50.0), ANGLES
    )
    tab = assur.forces(crank_slider(Load("slider", "C", table), 50.0), ANGLES)
    np.testing.assert_allclose(tab["driver.torque"], const["driver.torque"], rtol=1e-12)


def test_table_over_driver_is_periodic_and_linear():
    table = LoadTable(
        "driver", (0.0, 90.0, 360.0), ((0.0, -900.0, 0.0), (0.0, 0.0, 0.0))
    )
    at = np.array([45.0, 405.0, 90.0 + 135.0, -315.0])
    t = assur.forces(crank_slider(Load("slider", "C", table)), at)
    unit = assur.forces(crank_slider(Load("slider", "C", (-1.0, 0.0))), at)
    expected_force = np.array([450.0, 450.0, 450.0, 450.0])
    np.testing.assert_allclose(
        t["driver.torque"], expected_force * unit["driver.torque"], rtol=1e-9
    )


def test_table_over_slide_follows_the_piston():
    """A gas force against piston travel: F = k * slide, checked against a constant."""
    table = LoadTable("guide", (-0.2, 0.2), ((-0.2 * 1e4, 0.2 * 1e4), (0.0, 0.0)))
    t = assur.forces(crank_slider(Load("slider", "C", table)), ANGLES)
    unit = assur.forces(crank_slider(Load("slider", "C", (1.0, 0.0))), ANGLES)
    force = 1e4 * t["guide.s"]
    np.testing.assert_allclose(
        t["driver.torque"], force * unit["driver.torque"], rtol=1e-9, atol=1e-9
    )


def test_torque_table_and_constant_torque():
    table = LoadTable("driver", (0.0, 360.0), ((7.0, 7.0),))
    a = assur.forces(crank_slider(Load("rod", torque=table)), ANGLES)
    b = assur.forces(crank_slider(Load("rod", torque=7.0)), ANGLES)
    np.testing.assert_allclose(a["driver.torque"], b["driver.torque"], rtol=1e-12)


def test_gravity_equals_weights_as_external_forces():
    mech = assur.catalog.slider_crank()
    g = (0.0, -9.81)
    with_gravity = assur.forces(dataclasses.replace(mech, gravity=g), ANGLES)
    weights = tuple(
        Load(link.name, link.center, (0.0, -9.81 * link.mass)) for link in mech.links
    )
    with_loads = assur.forces(dataclasses.replace(mech, loads=weights), ANGLES)
    for column in ("driver.torque", "A.Fx", "A.Fy", "B.Fy", "guide.Fy", "guide.M"):
        np.testing.assert_allclose(
            with_gravity[column],
            with_loads[column],
            rtol=1e-9,
            atol=1e-9,
            err_msg=column,
        )


def test_table_over_slide_must_cover_the_sweep():
    table = LoadTable("guide", (-0.01, 0.01), ((0.0, 0.0), (0.0, 0.0)))
    with pytest.raises(assur.ModelError, match=r"loads\[0\]\.force\.table: covers"):
        assur.forces(crank_slider(Load("slider", "C", table)), ANGLES)


def test_balancing_torque_of_a_pure_torque_load():
    """A torque on the crank itself is balanced exactly: T = -load."""
    mech = crank_slider(Load("crank", torque=-3.5))
    t = assur.forces(mech, ANGLES)
    np.testing.assert_allclose(t["driver.torque"], 3.5, rtol=1e-12)
    np.testing.assert_allclose(t["A.F"], 0.0, atol=1e-12)
    assert math.isclose(float(t["driver.torque_check"][0]), 3.5, rel_tol=1e-12)


def test_a_table_over_a_turn_whose_ends_differ_jumps_back_at_zero():
    # a torque growing over the turn (0 at 0 deg, 3.6 N m at 360): the ends a turn
    # apart were taken for one position, the table read backwards from 0 to 360
    ramp = LoadTable("driver", (0.0, 360.0), ((0.0, 3.6),))
    at = np.array([0.0, 60.0, 90.0, 180.0, 270.0, 359.0, 360.0, 450.0, -90.0])
    t = assur.forces(crank_slider(Load("crank", torque=ramp)), at)
    load = np.remainder(at, 360.0) / 100.0  # the table read modulo 360, N m
    np.testing.assert_allclose(t["driver.torque"], -load, atol=1e-12)


def test_a_table_short_of_a_turn_runs_back_to_its_first_value():
    # positions from 30 to 210 deg: from 210 on, back to the value at 30, a turn on
    table = LoadTable("driver", (30.0, 120.0, 210.0), ((1.0, 4.0, -2.0),))
    at = np.array([30.0, 75.0, 120.0, 210.0, 300.0, 390.0, 0.0, 15.0, -345.0])
    t = assur.forces(crank_slider(Load("crank", torque=table)), at)
    # by hand: 1 + 3 (a - 30) / 90 up to 120, 4 - 6 (a - 120) / 90 up to 210, then
    # -2 + 3 (a - 210) / 180 up to 390
    expected = [1.0, 2.5, 4.0, -2.0, -0.5, 1.0, 0.5, 0.75, 0.75]
    np.testing.assert_allclose(t["driver.torque"], np.negative(expected), atol=1e-12)


def test_a_table_over_more_turns_is_read_as_its_first_when_they_repeat():
    # the file format sets no limit on the span: a table over two turns that repeats
    # itself reads as its first turn (it was refused for a while)
    two = LoadTable(
        "driver", tuple(np.arange(0.0, 721.0, 90.0)), ((-1e3, 0.0) * 4 + (-1e3,),)
    )
    one = LoadTable("driver", (0.0, 90.0, 180.0, 270.0), ((-1e3, 0.0, -1e3, 0.0),))
    at = np.arange(-90.0, 450.0, 15.0)
    a = assur.forces(crank_slider(Load("crank", torque=two)), at)
    b = assur.forces(crank_slider(Load("crank", torque=one)), at)
    np.testing.assert_array_equal(a["driver.torque"], b["driver.torque"])


def test_a_table_over_more_turns_that_do_not_repeat_is_refused():
    # a load growing over two turns gives the crank's position two values
    table = LoadTable("driver", (0.0, 360.0, 720.0), ((0.0, 1.0, 2.0),))
    with pytest.raises(assur.ModelError) as caught:
        crank_slider(Load("crank", torque=table)).validate()
    assert str(caught.value) == (
        "loads[0].torque: the value at 720 deg is not the one at 0 deg, a whole "
        "number of turns before; expected values that repeat from turn to turn (the "
        "crank's angle is read modulo 360)"
    )


def test_a_table_s_last_value_is_read_exactly():
    # the step's fraction times the jump cancelled badly next to a jump of 1e15
    from assur._tables import interpolate

    xs, ys = np.array([0.0, 0.05, 0.1]), np.array([0.0, 1e15, 0.3])
    assert interpolate(np.array([0.1, 0.05, 0.0]), xs, ys).tolist() == [0.3, 1e15, 0.0]


def test_a_position_given_twice_is_a_step():
    # a cutting force that acts from 110 to 250 deg only: a step at each end, the
    # second value holding from the step's position on, periodic over the turn
    step = LoadTable("driver", (110.0, 110.0, 250.0, 250.0), ((0.0, -3.0, -3.0, 0.0),))
    at = np.array([0.0, 109.999, 110.0, 180.0, 249.999, 250.0, 300.0, 470.0, -100.0])
    t = assur.forces(crank_slider(Load("crank", torque=step)), at)
    acting = np.array([0, 0, 1, 1, 1, 0, 0, 1, 0], dtype=float)
    np.testing.assert_allclose(t["driver.torque"], 3.0 * acting, atol=1e-12)


ROUND_TRIP_LOW = (15.0, 30.0, 60.0, 120.0, 231.0, 240.0, 249.0)
"""Angles that come back from radians a unit of the last place low:
np.degrees(np.radians(120.0)) is 119.99999999999999."""


@pytest.mark.parametrize("x", [*ROUND_TRIP_LOW, 0.3, 110.0, 359.7])
def test_a_step_holds_its_second_value_at_its_position_as_given(x):
    # read as it came back from radians, a position given as a step's took the
    # value before the step (a load table's cut from 120 to 240 deg did not act
    # at 120 deg and still acted at 240)
    step = LoadTable("driver", (x, x, x + 90.0, x + 90.0), ((0.0, -3.0, -3.0, 0.0),))
    at = x + np.array([0.0, 90.0, 360.0, 450.0, -360.0, -270.0, 720.0, 45.0, -1.0])
    t = assur.forces(crank_slider(Load("crank", torque=step)), at)
    acting = np.array([1, 0, 1, 0, 1, 0, 1, 1, 0], dtype=float)
    np.testing.assert_allclose(t["driver.torque"], 3.0 * acting, atol=1e-12)


@pytest.mark.parametrize(
    ("xs", "at", "turning", "before"),
    [
        ((0.0, 1.0, 1.0, 2.0), 1.0, False, [1.0]),  # a step inside
        ((0.0, 1.0, 1.0, 2.0), 0.5, False, None),  # none between
        ((0.0, 0.0, 2.0, 3.0), 0.0, False, None),  # given twice, one value: no step
        ((0.0, 1.0, 2.0, 3.0), 2.0, False, None),  # a kink is no step
        ((0.0, 90.0, 90.0, 360.0), 450.0, True, [1.0]),  # a turn on
        # a turn from 0 to 360 deg whose ends differ: a step at 0, from the end's
        ((0.0, 90.0, 90.0, 360.0), 0.0, True, [7.0]),
        ((0.0, 90.0, 90.0, 360.0), 360.0, True, [7.0]),
        ((0.0, 90.0, 90.0, 360.0), 89.0, True, None),
    ],
)
def test_the_value_before_a_step(xs, at, turning, before):
    # what the explanatory note says was there just before a step
    from assur._tables import step_before

    ys = [np.array([1.0, 1.0, 5.0, 7.0])]
    assert step_before(np.array(xs), ys, at, turning) == before


def test_the_round_trip_of_those_angles_is_inexact():
    # what the test above stands on: these angles miss their step without care
    for x in ROUND_TRIP_LOW:
        assert np.degrees(np.radians(x)) < x


@pytest.mark.parametrize(
    ("xs", "ys", "at", "want"),
    [
        # a step inside, and at the start and the end of a table held at its ends
        (
            (0.0, 1.0, 1.0, 2.0),
            (0.0, 1.0, 5.0, 6.0),
            (0.5, 1.0, 1.5, 3.0),
            (0.5, 5, 5.5, 6),
        ),
        ((0.0, 0.0, 2.0), (7.0, 1.0, 3.0), (-1.0, 0.0, 1.0, 2.0), (7.0, 1.0, 2.0, 3.0)),
        ((0.0, 2.0, 2.0), (1.0, 3.0, 9.0), (1.0, 2.0, 5.0, -1.0), (2.0, 9.0, 9.0, 1.0)),
    ],
)
def test_a_step_is_read_on_its_side(xs, ys, at, want):
    from assur._tables import interpolate

    got = interpolate(np.array(at), np.array(xs), np.array(ys))
    assert got.tolist() == list(want)


@pytest.mark.parametrize(
    ("table", "values", "refused"),
    [
        # two turns of a stepped load: each step's values side by side
        ((0.0, 90.0, 90.0, 360.0, 450.0, 450.0, 720.0), (0, 0, 10, 0, 0, 10, 0), None),
        (
            (0.0, 90.0, 90.0, 360.0, 450.0, 450.0, 720.0),
            (0, 0, 10, 0, 0, 9, 0),
            "at 450 deg is not the one at 90 deg, a whole number of turns before",
        ),
        (
            (0.0, 90.0, 90.0, 360.0, 450.0, 450.0, 720.0),
            (0, 0, 10, 0, 1, 10, 0),
            "before the step at 450 deg is not the one at 90 deg",
        ),
        # a step a turn from the start is a step at the start: its values too
        (
            (0.0, 180.0, 360.0, 360.0),
            (1, 2, 3, 4),  # 4 was never used
            "after the step at 360 deg is not the one at 0 deg",
        ),
        ((0.0, 180.0, 360.0, 360.0), (1, 2, 3, 1), None),
        (
            (0.0, 0.0, 180.0, 360.0),
            (1, 2, 3, 4),  # 1 was never used
            "before the step at 0 deg is not the one at 360 deg, a whole number of "
            "turns after",
        ),
        ((0.0, 0.0, 180.0, 360.0), (4, 2, 3, 4), None),
        ((0.0, 0.0, 360.0, 360.0), (2, 1, 2, 1), None),
    ],
)
@pytest.mark.parametrize("scale", [1.0, 1e-12, 1e12])
def test_a_step_a_whole_turn_on_agrees_with_the_first(table, values, refused, scale):
    # at every scale: a watch's torque table of 1e-12 N m was read against 1 N m,
    # and its second turn's values were taken for the first's
    load = LoadTable("driver", table, (tuple(scale * float(v) for v in values),))
    if refused is None:
        crank_slider(Load("crank", torque=load))  # checked as it is made
        return
    with pytest.raises(assur.ModelError) as caught:
        crank_slider(Load("crank", torque=load))
    assert str(caught.value).startswith(f"loads[0].torque: the value {refused}")


def test_a_position_given_three_times_is_refused():
    table = LoadTable("driver", (0.0, 90.0, 90.0, 90.0), ((0.0, 1.0, 2.0, 3.0),))
    with pytest.raises(assur.ModelError) as caught:
        crank_slider(Load("crank", torque=table)).validate()
    assert str(caught.value) == (
        "loads[0].torque.table: expected increasing positions, each at most twice "
        "(twice: a step, the value jumps there)"
    )


@pytest.mark.parametrize("scale", [1.0, 1e-12, 1e12])
def test_a_table_s_steps_are_found_at_every_scale(scale):
    # a step of 1e-12 N m was under a slack of 1e-9 N m: read as no step
    from assur._tables import step_before, steps

    xs = np.array([0.0, 90.0, 90.0, 360.0])
    values = [scale * np.array([0.0, 1.0, 2.0, 0.0])]
    assert steps(xs, values, True).tolist() == [90.0]
    assert step_before(xs, values, 90.0, True) == [scale * 1.0]
    assert step_before(xs, values, 45.0, True) is None
