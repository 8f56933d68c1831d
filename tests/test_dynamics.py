"""The dynamic model reduced to the crank, its steady state and the flywheel.

Checked against the oracle's own computations (tests/oracle.py): the reduced inertia is
twice the kinetic energy at unit crank speed from a forces table's velocities, the
reduced torque the power of gravity and the loads per unit crank speed; the steady
state is checked by a Runge-Kutta time integration of the equation of motion and the
exact flywheel by Wittenbauer's energy-mass diagram with exact tangent slopes.

The textbook case: R. S. Khurmi and J. K. Gupta, *A Textbook of Theory of Machines*,
S. Chand, chapter 16 (Turning moment diagrams and flywheel), Example 16.11 -- an
engine whose turning moment is T = 20000 + 9500 sin 2t - 5700 cos 2t N m (t the crank
angle from the inner dead centre) drives a constant resisting torque at a mean
180 rpm; the total fluctuation of speed is to be 1 % of the mean. The book finds the
maximum fluctuation of energy dE = 11 078 N m (the amplitude sqrt(9500^2 + 5700^2)),
the flywheel I = dE / (w^2 Cs) = 3121 kg m^2 (it rounds w^2 Cs to 3.55; unrounded,
3118.1 kg m^2) and, 45 deg past the inner dead centre, an angular acceleration of the
flywheel of 9500 / I = 3.04 rad/s^2.
"""

from __future__ import annotations

import dataclasses
import functools
import itertools
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur import Driver, Joint, Link, Load, LoadTable, Mechanism, Point

from . import oracle
from .conftest import load_example

DYNAMIC = (
    "four_bar",
    "class3",
    "offset_slider_crank",
    "scotch_yoke",
    "six_bar_lecture",
    "slider_crank_exercise",
    "slot_mechanism",
    "whitworth",
)
"""The bundled examples with masses and one driving crank."""
DELTA = 0.05
"""Coefficient of speed fluctuation given to examples too light to run without a
flywheel at their nominal speed."""


example = functools.cache(load_example)
"""An example mechanism loaded once (a frozen model, shared by the tests)."""


@functools.cache
def flywheel_of(name: str) -> float:
    """No flywheel where the example runs without one, else one for DELTA."""
    try:
        assur.dynamics(example(name), [0.0])
    except assur.ModelError:
        return assur.flywheel(example(name), DELTA)
    return 0.0


@functools.cache
def steady(name: str) -> assur.Dynamics:
    return assur.dynamics(example(name), flywheel=flywheel_of(name))


def crank(
    radius: float = 0.2,
    mass: float = 3.0,
    inertia: float = 0.01,
    omega: float = 10.0,
    gravity=None,
    angle: float = 0.0,
    motor=None,
) -> Mechanism:
    """A crank alone turning about A, with a point mass at B ``radius`` from A."""
    at = (
        radius * math.cos(math.radians(angle)),
        radius * math.sin(math.radians(angle)),
    )
    return Mechanism(
        (Link("crank", axis=("A", "B"), mass=mass, center="B", inertia=inertia),),
        (Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),),
        (Driver("A", omega),),
        points=(Point("B", "crank", at),),
        gravity=gravity,
        motor=motor,
    )


# ----------------------------------------------------------------- reduced quantities


@pytest.mark.parametrize("name", DYNAMIC)
def test_reduced_inertia_and_torque_against_the_forces_table(name):
    mech = example(name)
    t = assur.dynamics(mech, flywheel=flywheel_of(name))
    inertia, torque = oracle.crank_reduction(mech, t["angle"])
    np.testing.assert_allclose(
        t["reduced.inertia"] - t.flywheel, inertia, rtol=1e-9, atol=0
    )
    scale = max(float(np.max(np.abs(torque))), 1e-300)
    np.testing.assert_allclose(
        t["reduced.torque"], torque, rtol=1e-9, atol=1e-9 * scale
    )


@pytest.mark.parametrize("name", DYNAMIC)
def test_inertia_slope_is_the_derivative_of_the_inertia(name):
    mech = example(name)
    angles = np.linspace(3.0, 357.0, 37)
    h = 1e-3  # deg
    ahead = assur.dynamics(mech, angles + h, flywheel=flywheel_of(name))
    behind = assur.dynamics(mech, angles - h, flywheel=flywheel_of(name))
    here = assur.dynamics(mech, angles, flywheel=flywheel_of(name))
    difference = (ahead["reduced.inertia"] - behind["reduced.inertia"]) / (
        2 * math.radians(h)
    )
    size = float(np.max(np.abs(here["reduced.inertia_slope"])))
    np.testing.assert_allclose(
        here["reduced.inertia_slope"], difference, rtol=1e-5, atol=1e-6 * size
    )


# ----------------------------------------------------------------------- steady state


@pytest.mark.parametrize("name", DYNAMIC)
def test_the_steady_state_satisfies_its_energy_equation(name):
    t = steady(name)
    energy = 0.5 * t["reduced.inertia"] * t["driver.omega"] ** 2
    np.testing.assert_allclose(
        energy - t["reduced.work"], t.energy, rtol=1e-12, atol=1e-12 * t.energy
    )
    assert 0.5 * (t.speed_max + t.speed_min) == pytest.approx(abs(t.omega), rel=1e-12)
    assert t.delta == pytest.approx((t.speed_max - t.speed_min) / abs(t.omega))
    speeds = np.abs(t["driver.omega"])
    assert speeds.max() <= t.speed_max * (1 + 1e-12)
    assert speeds.min() >= t.speed_min * (1 - 1e-12)
    assert np.all(np.sign(t["driver.omega"]) == np.sign(t.omega))
    np.testing.assert_allclose(
        t["driver.motor"],
        -np.mean(t["reduced.torque"]),
        atol=1e-3 * max(1.0, float(np.max(np.abs(t["reduced.torque"])))),
    )


@pytest.mark.parametrize("name", DYNAMIC)
def test_balancing_torque_at_the_real_motion(name):
    mech, t = example(name), steady(name)
    table = assur.forces(
        mech, t["angle"], omega=t["driver.omega"], epsilon=t["driver.epsilon"]
    )
    want = t["driver.motor"] - t.flywheel * t["driver.epsilon"]
    # 1e-9 of the largest torque at play: the motor, the flywheel's, the loads'
    scale = max(
        float(np.max(np.abs(want))),
        float(np.max(np.abs(t["reduced.torque"]))),
        float(np.max(np.abs(t["reduced.inertia"] * t["driver.epsilon"]))),
    )
    np.testing.assert_allclose(
        table["driver.torque"], want, rtol=1e-9, atol=1e-9 * scale
    )


@pytest.mark.parametrize("name", DYNAMIC)
def test_time_integration_reproduces_the_steady_state(name):
    """The oracle's Runge-Kutta integration in time, started on the steady state at
    0 deg under the constant motor torque, stays on it for a whole turn."""
    mech = example(name)
    model = oracle.crank_model(mech, flywheel_of(name))
    start = assur.dynamics(mech, [0.0], flywheel=flywheel_of(name))
    _, phi, w = oracle.integrate_turn(
        model, 0.0, float(start["driver.omega"][0]), model.motor
    )
    energy = assur.dynamics(mech, np.degrees(phi), flywheel=flywheel_of(name))
    np.testing.assert_allclose(w, energy["driver.omega"], rtol=1e-7)


@pytest.mark.parametrize("name", [n for n in DYNAMIC if n != "whitworth"])
def test_the_crank_s_jerk_is_the_rate_of_its_acceleration_in_time(name):
    """The oracle's integration in time: the rate of its crank's acceleration along
    the steady motion (differences in time of the equation of motion's phi'') is
    ``driver.jerk``; the forces table at that motion carries it to every link.

    The Whitworth shaper is left out: its cutting force's table has corners, where
    the jerk jumps."""
    mech = example(name)
    model = oracle.crank_model(mech, flywheel_of(name))
    start = assur.dynamics(mech, [0.0], flywheel=flywheel_of(name))
    t, phi, w = oracle.integrate_turn(
        model, 0.0, float(start["driver.omega"][0]), model.motor, steps=6000
    )
    motor = model.motor
    eps = np.array([model.acceleration(*pw, motor) for pw in zip(phi, w, strict=True)])
    rate = np.gradient(eps, t)[5:-5]
    table = assur.dynamics(mech, np.degrees(phi[5:-5]), flywheel=flywheel_of(name))
    scale = float(np.max(np.abs(rate)))
    np.testing.assert_allclose(table["driver.jerk"], rate, atol=2e-4 * scale)
    # every link's jerk at that motion: the time derivative of its acceleration
    rows = slice(0, None, 20)
    at = table["angle"][rows]
    motion = assur.forces(
        mech,
        at,
        omega=table["driver.omega"][rows],
        epsilon=table["driver.epsilon"][rows],
        jerk=table["driver.jerk"][rows],
    )
    pivot = next(j for j in mech.joints if j.name == mech.drivers[0].joint)
    (crank,) = (name for name in pivot.links if name != "ground")
    np.testing.assert_array_equal(motion[f"{crank}.jerk"], table["driver.jerk"][rows])
    for link in (link.name for link in mech.links if link.name != crank):
        alpha = assur.forces(
            mech,
            table["angle"],
            omega=table["driver.omega"],
            epsilon=table["driver.epsilon"],
            columns=[f"{link}.alpha"],
        )[f"{link}.alpha"]
        rate = np.gradient(alpha, t[5:-5])[rows]
        jerk = motion[f"{link}.jerk"]
        size = max(1.0, float(np.max(np.abs(jerk))))
        np.testing.assert_allclose(jerk[1:-1], rate[1:-1], atol=1e-3 * size)


@pytest.mark.parametrize("name", ["four_bar", "slider_crank_exercise"])
def test_the_crank_s_jerk_without_loads_in_closed_form(name):
    """No loads, no motor: J w^2 is constant, so w = C / sqrt(J),
    epsilon = -J' w^2 / (2 J) and its rate w (-J'' w^2 / 2 - 2 J' epsilon) / J, with
    J from the oracle's kinetic energy and its slopes by central differences."""
    mech = example(name)
    step = 0.01  # deg
    fine = np.arange(0.0, 360.0, step)
    inertia, _ = oracle.crank_reduction(mech, fine)
    h = math.radians(step)
    slope = (np.roll(inertia, -1) - np.roll(inertia, 1)) / (2.0 * h)
    curve = (np.roll(inertia, -1) - 2.0 * inertia + np.roll(inertia, 1)) / h**2
    omega = mech.drivers[0].omega
    # the mean of the extreme speeds is the file's
    c = 2.0 * omega / (1.0 / math.sqrt(inertia.min()) + 1.0 / math.sqrt(inertia.max()))
    w = c / np.sqrt(inertia)
    eps = -0.5 * slope * w * w / inertia
    jerk = w * (-0.5 * curve * w * w - 2.0 * slope * eps) / inertia
    rows = slice(0, None, 700)
    table = assur.dynamics(mech, fine[rows])
    np.testing.assert_allclose(table["driver.omega"], w[rows], rtol=1e-7)
    scale = float(np.max(np.abs(jerk)))
    np.testing.assert_allclose(table["driver.jerk"], jerk[rows], atol=1e-6 * scale)


@pytest.mark.parametrize("name", ["whitworth", "offset_slider_crank", "four_bar"])
def test_extremes_do_not_depend_on_the_angle_step(name):
    mech = example(name)
    fine = assur.dynamics(mech, np.arange(0.0, 360.0, 0.5), flywheel=flywheel_of(name))
    coarse = assur.dynamics(mech, [10.0, 200.0], flywheel=flywheel_of(name))
    assert coarse.summary() == fine.summary()


def test_delta_decreases_as_the_flywheel_grows():
    mech = example("whitworth")
    deltas = [
        assur.dynamics(mech, [0.0], flywheel=j).delta for j in (2.0, 5.0, 20.0, 100.0)
    ]
    assert all(a > b for a, b in itertools.pairwise(deltas))
    # about inversely proportional once the flywheel dominates
    assert deltas[-1] * 100.0 == pytest.approx(deltas[-2] * 20.0, rel=0.3)


def test_the_table_reads_like_a_table(tmp_path: Path):
    t = steady("four_bar")
    assert t.columns == tuple(c[0] for c in assur.dynamics_model.COLUMNS)
    assert len(t) == 360
    assert "driver.omega" in t
    assert t.column("reduced.inertia").unit == "kg m^2"
    with pytest.raises(KeyError, match=r"did you mean 'driver\.omega'"):
        t["driver.omegaa"]
    with pytest.raises(ValueError, match="read-only"):
        t["driver.omega"][0] = 1.0
    text = t.to_csv()
    assert text.splitlines()[0].startswith("angle,reduced.inertia,")
    assert len(text.splitlines()) == 361
    data = t.to_dict()
    assert data["dynamics"]["delta"] == t.delta
    assert len(data["rows"]) == 360
    t.to_csv(tmp_path / "d.csv")
    assert (tmp_path / "d.csv").read_text(encoding="utf-8") == text


def test_the_table_has_every_column_method_of_a_sweep_s_table(tmp_path: Path):
    """The format: ``assur.dynamics(...) -> Table``; what a Table's columns give."""
    t = steady("four_bar")
    sweep = assur.kinematics(example("four_bar"), [0.0, 1.0])
    for name in dir(sweep):
        if name.startswith(("to_", "arrays")):
            assert callable(getattr(t, name)), name
    assert isinstance(t, assur.table.Columns)
    assert isinstance(sweep, assur.table.Columns)
    block = t.to_array()
    assert block.shape == (360, len(t.columns))
    for i, name in enumerate(t.columns):
        np.testing.assert_array_equal(block[:, i], t[name])
        np.testing.assert_array_equal(t.arrays()[i], t[name])
    frame = t.to_pandas()
    assert list(frame.columns) == list(t.columns)
    np.testing.assert_array_equal(frame["driver.omega"].to_numpy(), t["driver.omega"])
    assert t.skipped.shape == (0,)
    with pytest.raises(TypeError, match="a Dynamics is not iterable"):
        iter(t)
    pq = pytest.importorskip("pyarrow.parquet")
    t.to_parquet(tmp_path / "d.parquet")
    read = pq.read_table(tmp_path / "d.parquet")
    assert read.column_names == list(t.columns)
    assert read.schema.field("driver.epsilon").metadata[b"unit"] == b"rad/s^2"
    np.testing.assert_array_equal(
        read.column("driver.omega").to_numpy(), t["driver.omega"]
    )


# ---------------------------------------------------------------------------- flywheel


@pytest.mark.parametrize("name", DYNAMIC)
def test_flywheel_gives_the_asked_delta(name):
    mech = example(name)
    inertia = assur.flywheel(mech, 0.02)
    got = assur.dynamics(mech, [0.0], flywheel=inertia).delta
    assert got == pytest.approx(0.02, rel=1e-6)


@pytest.mark.parametrize("name", ["whitworth", "scotch_yoke", "offset_slider_crank"])
def test_flywheel_against_the_energy_mass_diagram(name):
    """Wittenbauer's tangents with the exact slopes give the exact flywheel."""
    mech = example(name)
    want = oracle.wittenbauer_flywheel(mech, 0.02)
    assert assur.flywheel(mech, 0.02) == pytest.approx(want, rel=1e-6)


def test_flywheel_sizing_sets_the_classical_estimates_beside_it():
    mech = example("whitworth")
    sizing = assur.flywheel_sizing(mech, 0.02)
    assert sizing.exact == pytest.approx(assur.flywheel(mech, 0.02), rel=1e-12)
    gaps = sizing.differences()
    # the usual slopes w^2 (1 +- delta) / 2 miss only terms of order delta^2
    assert abs(gaps["wittenbauer"]) < 0.02**2
    # the energy swing alone leaves out the mechanism's own inertia
    assert gaps["energy_swing"] > 0


@pytest.mark.parametrize(
    ("name", "delta", "within"),
    [
        ("whitworth", 0.02, 1e-3),
        ("six_bar_lecture", 0.05, 0.02),
        ("offset_slider_crank", 0.05, 5e-3),
        ("four_bar", 0.05, 0.1),
    ],
)
def test_mertsalov_s_estimate_against_the_textbook_s_working(name, delta, within):
    mech = example(name)
    sizing = assur.flywheel_sizing(mech, delta)
    want = oracle.mertsalov_flywheel(mech, delta)
    # the oracle's trapezoidal work on 7200 positions against the model's grid
    assert sizing.mertsalov == pytest.approx(want, rel=1e-5, abs=1e-9 * sizing.exact)
    # it keeps the links' varying energy the swing leaves out, off by the speed's
    # fluctuation in it: a few per cent where the energy swing missed by 17 to 100
    assert abs(sizing.differences()["mertsalov"]) < within
    assert abs(sizing.differences()["mertsalov"]) < abs(
        sizing.differences()["energy_swing"]
    )
    gaps = sizing.differences()
    assert gaps["mertsalov"] == (sizing.mertsalov - sizing.exact) / sizing.exact
    # a crank of constant inertia: no varying energy, the exact flywheel
    alone = assur.flywheel_sizing(crank(gravity=(0.0, -9.81)), 0.05)
    assert alone.mertsalov == pytest.approx(alone.exact, rel=1e-6)


def test_the_energy_swing_neglects_the_mechanism_s_own_inertia():
    # a crank of constant inertia J: the estimate is the whole inertia needed, the
    # flywheel J more than it (docs/dynamics.rst)
    mech = crank(gravity=(0.0, -9.81))
    sizing = assur.flywheel_sizing(mech, 0.05)
    own = 3.0 * 0.2**2 + 0.01
    assert sizing.energy_swing - sizing.exact == pytest.approx(own, rel=1e-6)
    whitworth = assur.flywheel_sizing(example("whitworth"), 0.02)
    assert whitworth.exact == pytest.approx(33.48, abs=5e-3)
    assert whitworth.differences()["energy_swing"] == pytest.approx(2.7e-4, abs=5e-6)


def test_the_energy_swing_misses_where_the_links_own_inertia_varies():
    # the figures of docs/dynamics.rst: heavy links, and loads that do no work
    six_bar = assur.flywheel_sizing(example("six_bar_lecture"), 0.05)
    assert six_bar.exact == pytest.approx(0.1460, abs=5e-5)
    assert six_bar.energy_swing == pytest.approx(0.1214, abs=5e-5)
    assert six_bar.differences()["energy_swing"] == pytest.approx(-0.17, abs=5e-3)
    four_bar = assur.flywheel_sizing(example("four_bar"), 0.05)
    assert four_bar.energy_swing == 0.0
    assert four_bar.exact == pytest.approx(0.01458, abs=5e-6)


# --------------------------------------------------------------- cases checked by hand


def test_extremes_that_tie_but_for_round_off_are_the_first():
    # the centred slider-crank is slowest at 73.056 and 286.944 deg alike: the
    # grid's two values differ in their last bit by the machine's arithmetic,
    # and "smallest speed ... at" named either angle
    from assur.dynamics_steady import _first

    tie = 30380.25
    grid = np.array([40000.0, tie, 50000.0, np.nextafter(tie, 0.0), 45000.0])
    assert _first(grid, -1.0) == 1  # not 3, an ulp smaller
    assert _first(-grid, 1.0) == 1
    assert _first(np.array([1.0, 3.0, 3.0 - 1e-6, 2.0]), 1.0) == 1
    # a work of 0 at the turn's start and its round-off at the end tie too
    assert _first(np.array([0.0, 5.0, 3.0, -1e-17]), -1.0) == 0
    t = assur.dynamics(example("slider_crank_exercise"))
    assert t.angle_min == pytest.approx(73.056, abs=1e-3)


def test_a_crank_with_a_point_mass_turns_evenly():
    """No load: J = m r^2 + J_G at every angle, the speed is the file's, delta 0."""
    t = assur.dynamics(crank(), [0.0, 45.0, 90.0, 300.0])
    np.testing.assert_allclose(t["reduced.inertia"], 3.0 * 0.2**2 + 0.01, rtol=1e-14)
    np.testing.assert_allclose(t["reduced.inertia_slope"], 0.0, atol=1e-14)
    np.testing.assert_allclose(t["driver.omega"], 10.0, rtol=1e-12)
    np.testing.assert_allclose(t["driver.epsilon"], 0.0, atol=1e-12)
    assert t.delta == pytest.approx(0.0, abs=1e-12)
    assert t.motor == 0.0
    assert t.energy == pytest.approx(0.5 * 0.13 * 100.0, rel=1e-12)


def test_a_crank_with_a_point_mass_under_gravity():
    """J constant, M = -m g r cos(phi): w^2 = c - (2 m g r / J) sin(phi), with c such
    that the mean of the extremes sqrt(c + a) and sqrt(c - a) is the file's speed."""
    from scipy.optimize import brentq

    m, r, g, jg, w = 3.0, 0.2, 9.81, 0.01, 10.0
    inertia = m * r * r + jg
    a = 2 * m * g * r / inertia
    c = brentq(lambda c: 0.5 * (math.sqrt(c + a) + math.sqrt(c - a)) - w, a, 1e4)
    angles = np.arange(0.0, 360.0, 15.0)
    t = assur.dynamics(crank(gravity=(0.0, -g)), angles)
    phi = np.radians(angles)
    np.testing.assert_allclose(
        t["reduced.torque"], -m * g * r * np.cos(phi), atol=1e-12
    )
    np.testing.assert_allclose(
        t["driver.omega"], np.sqrt(c - a * np.sin(phi)), rtol=1e-10
    )
    np.testing.assert_allclose(
        t["driver.epsilon"], -m * g * r * np.cos(phi) / inertia, rtol=1e-10, atol=1e-12
    )
    assert t.speed_max == pytest.approx(math.sqrt(c + a), rel=1e-10)
    assert t.speed_min == pytest.approx(math.sqrt(c - a), rel=1e-10)
    assert t.angle_max == pytest.approx(270.0, abs=1e-6)
    assert t.angle_min == pytest.approx(90.0, abs=1e-6)
    assert t.delta == pytest.approx((math.sqrt(c + a) - math.sqrt(c - a)) / w)


def engine() -> Mechanism:
    """Khurmi and Gupta, Example 16.11: the engine's turning moment as a torque table
    on the crank (every 0.1 deg), the crank's own inertia nil, 180 rpm."""
    deg = np.round(np.arange(0.0, 360.05, 0.1), 10)
    t = np.radians(deg)
    turning = 20000.0 + 9500.0 * np.sin(2 * t) - 5700.0 * np.cos(2 * t)
    return Mechanism(
        (Link("crank", axis=("A", "B"), mass=1.0, center="A", inertia=0.0),),
        (Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),),
        (Driver("A", 2 * math.pi * 180 / 60),),
        points=(Point("B", "crank", (0.3, 0.0)),),
        loads=(
            Load(
                "crank",
                torque=LoadTable("driver", tuple(deg.tolist()), (tuple(turning),)),
            ),
        ),
        name="Khurmi and Gupta, Example 16.11",
    )


def test_textbook_flywheel_of_an_engine():
    mech = engine()
    w = 2 * math.pi * 180 / 60
    inertia = assur.flywheel(mech, 0.01)
    # the book: I = 3121 kg m^2 with w^2 Cs rounded to 3.55; unrounded, 3118.1
    assert inertia == pytest.approx(3121.0, rel=2e-3)
    assert inertia == pytest.approx(math.hypot(9500, 5700) / (w * w * 0.01), rel=1e-5)
    t = assur.dynamics(mech, [45.0], flywheel=inertia)
    # the resisting torque is the mean turning moment: power 20000 w = 377 kW
    assert -t.motor * w / 1000 == pytest.approx(377.0, abs=0.5)
    assert t.energy_swing == pytest.approx(11078.0, rel=1e-4)
    # 45 deg past the inner dead centre the excess torque is 9500 N m
    assert t["driver.epsilon"][0] == pytest.approx(3.044, abs=0.005)
    assert t["driver.epsilon"][0] == pytest.approx(9500.0 / inertia, rel=1e-6)


# -------------------------------------------------------------------------- bad input


def test_a_prismatic_driver_is_refused():
    mech = assur.catalog.slider_crank()
    slid = dataclasses.replace(mech, drivers=(Driver("guide", 1.0),))
    with pytest.raises(assur.ModelError, match="driver joint 'guide' is prismatic"):
        assur.dynamics(slid)
    with pytest.raises(assur.ModelError, match="prismatic"):
        assur.flywheel(slid, 0.1)


def test_several_drivers_are_refused():
    with pytest.raises(assur.ModelError, match="2 drivers; expected one driving crank"):
        assur.dynamics(load_example("five_bar_two_cranks"))


def test_a_mechanism_without_mass_is_refused():
    with pytest.raises(assur.ModelError, match="no link has a mass"):
        assur.dynamics(load_example("tenbar"))


@pytest.mark.parametrize("delta", [1e-9, 1.99])
def test_flywheel_gives_the_asked_delta_at_its_ends(delta):
    # a small delta needs a huge flywheel; near 2 the crank nearly stops
    mech = example("whitworth")
    inertia = assur.flywheel(mech, delta)
    got = assur.dynamics(mech, [0.0], flywheel=inertia).delta
    assert got == pytest.approx(delta, rel=1e-6)


@pytest.mark.parametrize(
    "delta", [0.0, -0.1, math.nan, math.inf, 2.0, 2.5, 100.0, 1e-12, 1e-300]
)
def test_delta_must_be_positive(delta):
    # at delta = 2 the smallest speed is zero (above, a steady state would need a
    # negative one); below 1e-9 the fluctuation is near what rounding leaves of it
    # (the search had returned an inertia with another delta, or scipy's error)
    with pytest.raises(assur.UsageError, match="expected a coefficient of speed"):
        assur.flywheel(example("four_bar"), delta)


def test_a_search_that_finds_no_flywheel(monkeypatch):
    from assur import dynamics_flywheel

    monkeypatch.setattr(dynamics_flywheel, "WIDENINGS", 0)
    with pytest.raises(assur.ModelError, match=r"no inertia up to .* brings the"):
        assur.flywheel(example("whitworth"), 1e-6)


def test_delta_that_needs_no_flywheel():
    with pytest.raises(assur.UsageError, match=r"alone runs with delta = 0\.67"):
        assur.flywheel(example("four_bar"), 0.9)


@pytest.mark.parametrize("value", [-1.0, math.nan, "heavy", 1e16, 1e308])
def test_flywheel_must_be_an_inertia(value):
    with pytest.raises(assur.UsageError, match="flywheel"):
        assur.dynamics(example("four_bar"), [0.0], flywheel=value)


def test_zero_speed_is_refused():
    mech = dataclasses.replace(crank(), drivers=(Driver("A", 0.0),))
    with pytest.raises(assur.ModelError, match=r"drivers\[0\]\.omega: 0 rad/s"):
        assur.dynamics(mech)


def test_too_slow_for_its_loads():
    with pytest.raises(
        assur.ModelError,
        match="at a mean speed of 100 rad/s the crank would come to rest at crank "
        "angle",
    ):
        assur.dynamics(example("offset_slider_crank"))


def test_too_slow_names_what_makes_it_faster_whichever_way_it_turns():
    # "a larger 'omega'" for a crank at -25 rad/s, which needs a more negative one;
    # the command line's user was sent to the library's arguments
    mech = example("offset_slider_crank")
    for sense, faster in ((1.0, "a larger 'omega'"), (-1.0, "more negative")):
        driver = dataclasses.replace(mech.drivers[0], omega=sense * 100.0)
        turning = dataclasses.replace(mech, drivers=(driver,))
        with pytest.raises(assur.ModelError) as raised:
            assur.dynamics(turning)
        assert faster in str(raised.value)
        assert str(raised.value).endswith(
            "or a flywheel (--flywheel or --delta on the command line)"
        )


def test_no_mass_in_motion():
    with pytest.raises(assur.ModelError, match="reduced inertia is zero"):
        assur.dynamics(engine(), [0.0])


def test_no_mass_in_motion_between_grid_points():
    # a Scotch yoke whose yoke alone has a mass: J = m (r sin(phi))^2 touches zero
    # at the crank's dead centres, 0 and 180 deg, which no grid point hits
    yoke = example("scotch_yoke")
    links = tuple(
        link
        if link.name == "yoke"
        else dataclasses.replace(link, mass=0.0, inertia=0.0)
        for link in yoke.links
    )
    still = dataclasses.replace(yoke, links=links, loads=())
    with pytest.raises(
        assur.ModelError,
        match=r"reduced inertia is zero at crank angle (180|360|0) deg",
    ):
        assur.dynamics(still, [0.0, 90.0])
    # a flywheel keeps it turning: finite speeds everywhere, at 0 and 180 deg too
    table = assur.dynamics(still, [0.0, 90.0, 180.0], flywheel=1e-3)
    assert np.isfinite(table["driver.omega"]).all()
    assert np.isfinite(table["driver.epsilon"]).all()


def test_a_crank_that_cannot_turn_round():
    rocker = assur.catalog.four_bar(crank=0.09, coupler=0.06, rocker=0.08)
    with pytest.raises(
        assur.AssemblyError,
        match=r"^dynamics: the crank cannot make a full turn \(on the model's grid "
        r"of 1024 positions a turn\): group RRR "
        r"\(coupler, rocker\): cannot be assembled",
    ):
        assur.dynamics(rocker, [60.0])


def test_the_grid_names_each_trouble_once_from_its_finest_grid():
    from assur._grid_warnings import TROUBLE_TEXT
    from assur._grid_warnings import pass_on as _pass_on

    near = "group RRP (rod, ram): near a dead centre at driver positions "
    grids = [near + f"89.{k} deg to 90.{9 - k} deg" for k in range(5)]
    with pytest.warns(assur.AssurWarning) as caught:
        _pass_on(grids, 65536)
    (message,) = (str(w.message) for w in caught)
    assert message == (
        "dynamics, on its internal grid of up to 65536 positions a turn: " + grids[-1]
    )
    many = [
        f"group RRR (l{k}, r{k}): {'x' * 80} at driver positions 1 deg"
        for k in range(9)
    ]
    with pytest.warns(assur.AssurWarning) as caught:
        _pass_on(many, 2048)
    (message,) = (str(w.message) for w in caught)
    assert "group RRR (l0, r0)" in message
    assert message.endswith(" more")
    assert len(message) < TROUBLE_TEXT + 120


def test_a_torque_that_is_rounding_noise_stops_the_grid():
    # 1e15 N at the rocker's fixed pivot F does no work, but the rounding of F's
    # speed (1e-17 m/s) leaves a reduced torque of noise about 1e-2 N m: refining the
    # grid cannot settle it, and stops with a warning instead of at 65536 positions
    from assur.dynamics_reduced import GRID_MOST, reduce

    mech = example("class3")
    loud = dataclasses.replace(
        mech, loads=(*mech.loads, Load("left_rocker", at="F", force=(0.0, 1e15)))
    )
    with pytest.warns(assur.AssurWarning, match="reduced torque is not smooth"):
        model = reduce(loud)
    assert model.angle.shape[0] < GRID_MOST
    assert 1e-5 < model.error < 1e-2  # the noise, as the model estimates it
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the quiet mechanism settles as before
        assert reduce(mech).angle.shape[0] == 2048


def test_a_grid_that_reaches_its_finest_unresolved_says_so():
    # a four-bar a hair from a change point: J turns sharply near 0 and 180 deg, the
    # grid stopped at 65536 positions with J's interpolant missing by 10 %, and the
    # steady state's delta came out 3e-4 off with no word of it (a review's own
    # solver)
    from assur.dynamics_reduced import GRID_MOST, reduce

    mech = assur.catalog.four_bar(
        crank=0.04, coupler=0.12, rocker=0.0400000001, frame=0.12
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", assur.AssurWarning)
        model = reduce(mech)
    assert model.angle.shape[0] == GRID_MOST
    said = [str(w.message) for w in caught if "not resolved" in str(w.message)]
    assert len(said) == 1
    assert said[0].startswith(
        "dynamics: the reduced inertia is not resolved on the model's finest grid "
        "(65536 positions a turn): between grid points its interpolant misses it by "
        "up to "
    )


@pytest.mark.parametrize("omega", [0.0, 1e-170])
def test_a_crank_at_rest_has_no_steady_state_nor_flywheel(omega, tmp_path, capsys):
    from assur.cli import main

    # a ZeroDivisionError came out of the flywheel's first guess (omega squared),
    # in the report and the diagrams too, which fall back to a flywheel
    mech = dataclasses.replace(
        assur.catalog.slider_crank(),
        drivers=(
            dataclasses.replace(assur.catalog.slider_crank().drivers[0], omega=omega),
        ),
    )
    # the message says what is wrong with the speed, and what would do
    what = "is zero" if omega == 0.0 else "is too small: its square underflows"
    with pytest.raises(
        assur.ModelError,
        match=rf"drivers\[0\].omega: .* rad/s {what}; expected .* at least 1e-160",
    ):
        assur.dynamics(mech)
    with pytest.raises(assur.ModelError, match=r"flywheel: drivers\[0\].omega"):
        assur.flywheel(mech, 0.05)
    # the forces at rest are a static analysis: the pictures and the report stand
    path = tmp_path / "rest.toml"
    assur.save(mech, path)
    report = tmp_path / "r.html"
    assert main(["report", str(path), "-o", str(report), "-q"]) == 0
    assert report.exists()
    assert main(["dynamics", str(path), "--delta", "0.05"]) == 2
    (line,) = capsys.readouterr().err.splitlines()
    assert "flywheel: drivers[0].omega" in line


def test_a_huge_crank_angle_is_its_angle_within_a_turn():
    # the work was read at radians(1e300): 8.32 J for -3.84 (the kinematics exact)
    mech = example("whitworth")
    huge = [1e300, 1e15, 3.6e14 + 30.0]
    within = np.remainder(huge, 360.0)  # exact
    a = assur.dynamics(mech, huge, flywheel=1.0)
    b = assur.dynamics(mech, within, flywheel=1.0)
    for name in ("reduced.work", "driver.omega", "driver.epsilon", "reduced.inertia"):
        np.testing.assert_allclose(a[name], b[name], rtol=1e-12, atol=1e-12)


def test_the_extreme_between_grid_points_is_the_parabola_s_vertex():
    """By hand: y = (x - 0.3)^2 + 2 at x = -1, 0, 1 is 3.69, 2.09, 2.49; its
    vertex is 2 at x = 0.3. The grid closes on itself: the neighbours of the first
    point are the last and the second. (A vertex off by its curvature's factor of
    two went unseen: the grid is fine, so the refinement is small.)"""
    from assur.dynamics_steady import _vertex

    values = np.array([3.69, 2.09, 2.49])
    assert _vertex(values, 1) == pytest.approx((2.0, 0.3), rel=1e-12)
    assert _vertex(np.roll(values, -1), 0) == pytest.approx((2.0, 0.3), rel=1e-12)
    # a maximum alike: y = 5 - 2 (x + 0.25)^2
    top = np.array([5.0 - 2.0 * (x + 0.25) ** 2 for x in (-1.0, 0.0, 1.0)])
    assert _vertex(top, 1) == pytest.approx((5.0, -0.25), rel=1e-12)
    assert _vertex(np.array([1.0, 2.0, 3.0]), 1) == (2.0, 0.0)  # a straight line
