"""Kinetostatic invariants, against an independent global solve (tests/oracle.py).

The oracle writes the three equilibrium equations of every moving link at once (two
unknowns per revolute or prismatic joint, one per slot, one balancing load per
driver) from the mechanism's data and the table's kinematics, and solves them row by
row; the group-by-group reverse pass must give the same reactions and balancing loads.
Then, over every example and random mechanisms (tests/mechanisms.py): each link's
equilibrium under the table's reactions, the balancing torque against the principle
of virtual power, the power balance at every instant and the work over a cycle, and
the loads the frame receives (shaking force and moment).

Tolerances: 1e-9 relative to the largest load (force) or that times the mechanism's
size (moment); the work over a cycle to 1e-6 of the work done by the loads, the
trapezoidal rule over 1440 positions of a turn being exact for a smooth periodic
integrand but only O(h^2) at the kinks of a load table.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import assur

from . import oracle
from .mechanisms import (
    DYAD_STRATEGIES,
    Case,
    any_case,
    bounded,
    five_bar_cases,
    moved,
    one_turn,
    slider_cases,
    slot_cases,
    steady,
    triad_cases,
)

SETTINGS = bounded(25)

RTOL = 1e-9


def crank_cases() -> st.SearchStrategy[Case]:
    """Random mechanisms driven by cranks (every builder but the prismatic driver)."""
    return st.one_of(
        *(s() for s in DYAD_STRATEGIES.values()),
        slot_cases(),
        five_bar_cases(),
        triad_cases(),
    )


def needs_forces(mech: assur.Mechanism) -> bool:
    return bool(mech.loads) or any(link.mass for link in mech.links)


# ------------------------------------------------------------------------------------
# Checks


def assert_matches_global_solve(mech: assur.Mechanism, table: assur.Table) -> None:
    force, size = oracle.load_scale(mech, table)
    expected = oracle.global_solve(mech, table)
    got = oracle.table_reactions(mech, table)
    oracle.assert_same_reactions(mech, got, expected, RTOL, force, size)


def assert_links_in_equilibrium(mech: assur.Mechanism, table: assur.Table) -> None:
    force, size = oracle.load_scale(mech, table)
    residuals = oracle.link_residuals(mech, table, oracle.table_reactions(mech, table))
    for link in mech.links:
        f, m = residuals[link.name]
        assert np.max(np.abs(f)) <= RTOL * force, (
            f"{link.name}: force left {np.max(np.abs(f))}"
        )
        assert np.max(np.abs(m)) <= RTOL * force * size, f"{link.name}: moment left"
    assert np.max(table["residual.force"]) <= RTOL * force
    assert np.max(table["residual.moment"]) <= RTOL * force * size


def assert_balancing_check(mech: assur.Mechanism, table: assur.Table) -> None:
    force, size = oracle.load_scale(mech, table)
    for i in range(len(mech.drivers)):
        main = oracle.balancing_column(mech, table, i)
        check = oracle.balancing_column(mech, table, i, check=True)
        np.testing.assert_allclose(
            main,
            check,
            rtol=RTOL,
            atol=RTOL * force * size,
            err_msg=f"driver {i}: torque != torque_check",
        )


def assert_power_balance(mech: assur.Mechanism, table: assur.Table) -> None:
    """The balancing loads' power plus every applied load's power (inertia loads
    included) is zero at every instant; the powers are the oracle's own."""
    force, size = oracle.load_scale(mech, table)
    loads = oracle.applied_loads(mech, table)
    total = sum(loads.power.values())
    scale = sum(np.abs(p) for p in loads.power.values())
    for i, d in enumerate(mech.drivers):
        power = oracle.balancing_column(mech, table, i) * d.omega
        total = total + power
        scale = scale + np.abs(power)
    speed = max(abs(d.omega) for d in mech.drivers)
    limit = RTOL * (scale + np.max(scale) + force * size * speed)
    assert np.all(np.abs(total) <= limit), (
        f"power left: {np.max(np.abs(total) - limit)}"
    )


def assert_frame_loads(mech: assur.Mechanism, table: assur.Table) -> None:
    """The shaking force and moment are what the moving links exert on the frame
    (through its joints, plus the motor's reaction), and so the resultant of every
    applied load: inertia loads, gravity and external loads."""
    force, size = oracle.load_scale(mech, table)
    frame_force, frame_moment = oracle.link_residuals(
        mech, table, oracle.table_reactions(mech, table)
    )["ground"]
    shaking = np.stack([table["shaking.Fx"], table["shaking.Fy"]], axis=-1)
    np.testing.assert_allclose(
        shaking,
        frame_force,
        rtol=0,
        atol=RTOL * force,
        err_msg="shaking force != loads on the frame",
    )
    np.testing.assert_allclose(
        table["shaking.M"],
        frame_moment,
        rtol=0,
        atol=RTOL * force * size,
        err_msg="shaking moment != moment of loads on the frame",
    )
    loads = oracle.applied_loads(mech, table)
    np.testing.assert_allclose(
        shaking,
        sum(loads.force.values()),
        rtol=0,
        atol=RTOL * force,
        err_msg="shaking force != sum of applied loads",
    )
    np.testing.assert_allclose(
        table["shaking.M"],
        sum(loads.moment.values()),
        rtol=0,
        atol=RTOL * force * size,
        err_msg="shaking moment != moment of applied loads",
    )


def assert_inertia_columns(mech: assur.Mechanism, table: assur.Table) -> None:
    loads = oracle.applied_loads(mech, table)
    for link in mech.links:
        if not link.mass:
            # every moving link has its inertia columns; a massless one's are zero
            for column in ("Fi.x", "Fi.y", "Mi"):
                np.testing.assert_array_equal(table[f"{link.name}.{column}"], 0.0)
            continue
        fi = loads.inertia_force[link.name]
        scale = max(float(np.max(np.abs(fi))), 1e-300)
        np.testing.assert_allclose(
            table[f"{link.name}.Fi.x"], fi[:, 0], rtol=RTOL, atol=RTOL * scale
        )
        np.testing.assert_allclose(
            table[f"{link.name}.Fi.y"], fi[:, 1], rtol=RTOL, atol=RTOL * scale
        )
        np.testing.assert_allclose(
            table[f"{link.name}.Mi"],
            loads.inertia_torque[link.name],
            rtol=RTOL,
            atol=1e-300,
        )


def assert_prismatic_columns(mech: assur.Mechanism, table: assur.Table) -> None:
    """``J.F`` is the reaction's magnitude; ``J.offset`` is where the normal force acts
    along the axis from the joint's point, ``J.M`` over the normal force."""
    force, _ = oracle.load_scale(mech, table)
    for joint in mech.joints:
        fx, fy = table[f"{joint.name}.Fx"], table[f"{joint.name}.Fy"]
        np.testing.assert_allclose(
            table[f"{joint.name}.F"], np.hypot(fx, fy), rtol=1e-12, atol=1e-12 * force
        )
        if joint.kind == "revolute":
            continue
        first = oracle.pose(mech, table, joint.links[0])
        n = oracle.turn(first.rotation, oracle.perp(oracle.unit_axis(joint)))
        normal = fx * n[:, 0] + fy * n[:, 1]
        np.testing.assert_allclose(
            np.hypot(fx, fy),
            np.abs(normal),
            rtol=1e-9,
            atol=RTOL * force,
            err_msg=f"{joint.name}: not normal",
        )
        big = np.abs(normal) > 1e-6 * force
        np.testing.assert_allclose(
            table[f"{joint.name}.offset"][big],
            table[f"{joint.name}.M"][big] / normal[big],
            rtol=1e-9,
        )
        # no normal force beside the largest reaction (round-off: 1e-12 of it), no
        # point it acts at; a normal force clear of that, a point
        largest = np.max([table[f"{j.name}.F"] for j in mech.joints], axis=0)
        offset = table[f"{joint.name}.offset"]
        assert np.isnan(offset[np.abs(normal) < 1e-14 * largest]).all(), joint.name
        assert np.isfinite(offset[np.abs(normal) > 1e-10 * largest]).all(), joint.name
        if joint.kind == "slot":  # a pin: no couple about it
            np.testing.assert_allclose(
                table[f"{joint.name}.M"],
                0.0,
                rtol=0,
                atol=RTOL * force * oracle.mechanism_size(mech),
            )


def assert_all(mech: assur.Mechanism, table: assur.Table) -> None:
    assert_matches_global_solve(mech, table)
    assert_links_in_equilibrium(mech, table)
    assert_balancing_check(mech, table)
    assert_power_balance(mech, table)
    assert_frame_loads(mech, table)
    assert_inertia_columns(mech, table)
    assert_prismatic_columns(mech, table)


def cycle_work(mech: assur.Mechanism, count: int = 1440) -> tuple[float, float, float]:
    """Work over one turn at constant speed (periodic trapezoidal rule) of the balancing
    loads and of gravity and external loads; and the work of the loads' magnitudes."""
    positions, dt = one_turn(mech, count, endpoint=False)
    table = assur.forces(mech, positions)
    balancing = sum(
        oracle.balancing_column(mech, table, i) * d.omega
        for i, d in enumerate(mech.drivers)
    )
    loads = oracle.applied_loads(mech, table, inertia=False)
    others = sum(loads.power.values())
    return (
        float(np.sum(balancing) * dt),
        float(np.sum(others) * dt),
        float(np.sum(np.abs(balancing)) * dt),
    )


# ------------------------------------------------------------------------------------
# Every bundled example


def rubbing(mech: assur.Mechanism) -> bool:
    return any(j.friction for j in mech.joints)


def test_example_over_a_turn(example):
    if not needs_forces(example):
        pytest.skip("no masses and no loads: nothing to analyse")
    if rubbing(example):
        pytest.skip("friction: tests/test_friction.py solves it globally with friction")
    positions, _ = one_turn(example, 180, endpoint=False)
    assert_all(example, assur.forces(example, positions))


def test_example_work_over_a_cycle(example):
    """At constant crank speed the motion is periodic: the inertia loads do no work
    over a turn, so the balancing loads' work cancels that of gravity and the loads."""
    if not needs_forces(example):
        pytest.skip("no masses and no loads: nothing to analyse")
    if rubbing(example):
        pytest.skip("friction takes work: tests/test_friction.py counts it")
    mech = steady(example)
    rates = {d.omega for d in mech.drivers}
    assert len(rates) == 1, "periodic only when every crank turns at the same speed"
    balancing, others, scale = cycle_work(mech)
    assert abs(balancing + others) <= 1e-6 * scale + 1e-9, (balancing, others)


def test_flipped_driver_joint_changes_only_the_sign_of_its_reaction():
    """A driver joint listed (crank, ground) instead of (ground, crank): the reaction is
    exerted by the crank on the frame, everything else is unchanged."""
    mech = assur.load(Path(__file__).parent.parent / "examples" / "four_bar.toml")
    flipped = dataclasses.replace(
        mech,
        joints=tuple(
            dataclasses.replace(j, links=j.links[::-1]) if j.name == "O2" else j
            for j in mech.joints
        ),
    )
    positions, _ = one_turn(mech, 24, endpoint=False)
    a = assur.forces(mech, positions)
    b = assur.forces(flipped, positions)
    for column in a.columns:
        sign = -1.0 if column in ("O2.Fx", "O2.Fy") else 1.0
        np.testing.assert_allclose(
            b[column], sign * a[column], rtol=1e-12, atol=1e-12, err_msg=column
        )
    assert_all(flipped, b)


# ------------------------------------------------------------------------------------
# Random mechanisms


def accelerated(mech: assur.Mechanism, epsilon: float) -> assur.Mechanism:
    drivers = tuple(
        dataclasses.replace(d, epsilon=epsilon * (-1) ** i)
        for i, d in enumerate(mech.drivers)
    )
    return dataclasses.replace(mech, drivers=drivers)


@SETTINGS
@given(case=crank_cases(), epsilon=st.sampled_from([0.0, 0.0, 25.0, -400.0]))
def test_random_mechanism(case, epsilon):
    mech = accelerated(case.mechanism, epsilon)
    positions, _ = case.path(19)
    assert_all(mech, assur.forces(mech, positions))


@SETTINGS
@given(
    case=st.one_of(
        *(s() for k, s in DYAD_STRATEGIES.items() if k != "PRP"),
        slot_cases(),
        triad_cases(min_span=360.0),
    )
)
def test_random_work_over_a_cycle(case):
    mech = steady(case.mechanism)
    balancing, others, scale = cycle_work(mech, 720)
    assert abs(balancing + others) <= 1e-6 * scale + 1e-9 * abs(others) + 1e-12, (
        balancing,
        others,
    )


@SETTINGS
@given(case=crank_cases(), omega=st.floats(-5.0, 5.0))
def test_random_mechanism_slow_or_at_rest(case, omega):
    """The same checks with the crank slow or at rest (omega = 0: statics)."""
    mech = case.mechanism
    drivers = tuple(
        dataclasses.replace(d, omega=omega * (i + 1), epsilon=0.0)
        for i, d in enumerate(mech.drivers)
    )
    mech = dataclasses.replace(mech, drivers=drivers)
    positions = case.sweep(9)
    assert_all(mech, assur.forces(mech, positions))


@settings(SETTINGS, max_examples=15)
@given(case=slider_cases(), epsilon=st.sampled_from([0.0, 2.0, -30.0]))
def test_prismatic_driver(case, epsilon):
    mech = accelerated(case.mechanism, epsilon)
    positions, _ = case.path(19)
    assert_all(mech, assur.forces(mech, positions))


def with_tables(
    mech: assur.Mechanism, over: str, low: float, high: float, values: list[float]
) -> assur.Mechanism:
    """``mech`` with a force on its last link and a torque on its first tabulated
    against ``over`` from ``low`` to ``high``."""
    grid = tuple(float(x) for x in np.linspace(low, high, len(values)))
    force = assur.LoadTable(over, grid, (tuple(values), tuple(v / 3 for v in values)))
    torque = assur.LoadTable(over, grid, (tuple(v / 100 for v in values[::-1]),))
    last = mech.links[-1].name
    loads = (
        *mech.loads,
        assur.Load(last, at=f"{last}_p", force=force),
        assur.Load(mech.links[0].name, torque=torque),
    )
    return dataclasses.replace(mech, loads=loads)


@SETTINGS
@given(
    case=st.one_of(DYAD_STRATEGIES["RRP"](), slot_cases(), DYAD_STRATEGIES["PRP"]()),
    values=st.lists(st.floats(-500.0, 500.0), min_size=3, max_size=6),
)
def test_load_tables_over_a_slide(case, values):
    """A force and a torque tabulated against a prismatic or slot joint's slide,
    linearly interpolated (the table covers the slide's range over the sweep)."""
    mech = case.mechanism
    joint = next(j.name for j in mech.joints if j.kind != "revolute")
    positions, _ = case.path(37)
    slide = assur.kinematics(mech, positions)[f"{joint}.s"]
    mech = with_tables(mech, joint, slide.min() - 1e-3, slide.max() + 1e-3, values)
    assert_all(mech, assur.forces(mech, positions))


@settings(SETTINGS, max_examples=10)
@given(
    case=slider_cases(),
    values=st.lists(st.floats(-500.0, 500.0), min_size=3, max_size=6),
)
def test_load_tables_over_a_prismatic_driver(case, values):
    """Tables over a slider driver's position (m), not periodic."""
    lo, hi = float(case.span[0, 0]), float(case.span[1, 0])
    mech = with_tables(case.mechanism, "driver", lo, hi, values)
    positions, _ = case.path(19)
    assert_all(mech, assur.forces(mech, positions))


@SETTINGS
@given(
    case=any_case(),
    angle=st.floats(-math.pi, math.pi),
    shift=st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)),
    scale=st.sampled_from([0.05, 1.0, 20.0]),
)
def test_rigid_motion_and_similarity(case, angle, shift, scale):
    """Turning, shifting and scaling the whole mechanism (inertias with the square of
    the scale, forces and gravity with it, torques with its square) turns and scales
    every force and scales every torque by the square; the shaking moment about the
    origin picks up the moment of the shaking force about the shifted origin."""
    mech = case.mechanism
    positions, _ = case.path(13)
    table = assur.forces(mech, positions)
    expected = oracle.moved_columns(mech, table, angle, shift, scale)
    other = moved(mech, angle, shift, scale)
    if len(mech.drivers) == 1:
        at = expected["angle"]
    else:
        at = np.stack([expected[f"{d.joint}.drive"] for d in mech.drivers], -1)
    oracle.assert_columns(other, assur.forces(other, at), expected)


def test_a_slider_on_the_frame_needs_no_inertia():
    # the file format's own sample gives its slider a mass and a centre, no inertia: a
    # link that slides on the frame never turns, so its inertia never enters
    mech = assur.catalog.slider_crank()
    links = tuple(
        dataclasses.replace(x, inertia=None) if x.name == "slider" else x
        for x in mech.links
    )
    without = dataclasses.replace(mech, links=links)
    angles = np.arange(0.0, 360.0, 15.0)
    want, got = assur.forces(mech, angles), assur.forces(without, angles)
    for name in want.columns:
        np.testing.assert_array_equal(got[name], want[name])
    # a link that turns still needs one
    rod = tuple(
        dataclasses.replace(x, inertia=None) if x.name == "rod" else x
        for x in mech.links
    )
    with pytest.raises(assur.ModelError, match=r"links\.rod: a link with a mass needs"):
        assur.forces(dataclasses.replace(mech, links=rod), angles)
    note = assur.explain(without, 45.0)
    assert "that the slider runs along" in str(note)


def test_a_load_varying_only_along_y_does_work():
    # a slider on a vertical guide through the origin: its inertia force's x part
    # and its moment about the origin are the number 0.0, its y part varies; the
    # virtual-power check took the varying part for a number (ValueError)
    path = Path(__file__).parent / "data" / "fuzz" / "vertical_slider_on_the_axis.toml"
    table = assur.forces(assur.load(path), np.arange(0.0, 100.0, 10.0))
    # torques against the reactions' size times the mechanism's (about 0.25 m)
    largest = max(float(np.max(table[c])) for c in table.columns if c.endswith(".F"))
    assert largest > 0.0
    np.testing.assert_allclose(
        table["driver.torque_check"], table["driver.torque"], atol=1e-9 * largest
    )


def test_a_stepped_cutting_force_matches_the_global_solve():
    # a crank shaper whose 2000 N cut steps on at 350 deg and off at 190 deg, a
    # periodic table with twin positions at its steps (the oracle read it with
    # np.interp's period=, which sorts the twins apart and merges 0 with 360: it
    # disagreed by 3500 N) and a ram that slides on the frame with no inertia given
    path = Path(__file__).parent / "data" / "explain" / "crank_shaper.toml"
    mech = assur.load(path)
    positions = np.arange(0.25, 720.0, 2.5)  # two turns, off the steps themselves
    table = assur.forces(mech, positions)
    cut = np.abs(table["driver.torque"])
    assert np.max(cut) > 100.0  # the cut is on somewhere, as the file says
    assert_all(mech, table)
