"""Kinematic invariants over the bundled examples and random mechanisms.

Over a whole turn of every example (the ``example`` fixture): links stay rigid, points
stay on their slide lines, consecutive rows are linked by the trapezoidal rule (no
jump to another branch), every derivative column equals the central difference in
time of the column below it, and angle columns are continuous. Then: the driver's
angular acceleration (epsilon), a prismatic driver, two drivers, and sweeps that
cannot be assembled.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest
from hypothesis import given
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
    reference_drive,
    slider_cases,
    steady,
    triad_cases,
)

SETTINGS = bounded(12)


def driven_links(mech: assur.Mechanism) -> set[str]:
    out = set()
    for d in mech.drivers:
        a, b = mech.joint(d.joint).links
        out.add(b if a == "ground" else a)
    return out


# ------------------------------------------------------------------------------------
# Every bundled example over a whole turn


def test_example_rigid_links_and_slides(example):
    mech = steady(example)
    positions, dt = one_turn(mech, 361)
    table = assur.kinematics(mech, positions)
    oracle.assert_rigid(mech, table)
    oracle.assert_slides(mech, table)
    oracle.assert_continuous(table, dt)


def test_example_reference_pose(example):
    table = assur.kinematics(example, reference_drive(example)[None, :])
    oracle.assert_reference_pose(example, table, 0)


def test_example_derivatives_are_time_differences(example):
    # as the file gives them: a driver speeding up (epsilon) is followed by the
    # differences too
    positions, _ = one_turn(example, 25)
    oracle.assert_differences(example, oracle.si(example, positions[:-1]))


@pytest.mark.parametrize("start", [0.0, 170.0, 181.0, -540.0, 1000.0])
def test_example_angle_columns_continuous(example, start):
    """Angles of links that are not driven start in (-180, 180] and never jump by a
    turn; a driven crank's angle is the driver position itself."""
    mech = steady(example)
    positions, dt = one_turn(mech, 181)
    positions = np.concatenate(
        [positions, positions[1:] + (positions[-1] - positions[0])]
    )
    positions = positions + start
    table = assur.kinematics(mech, positions)
    driven = driven_links(mech)
    for link in mech.links:
        angle = table[f"{link.name}.angle"]
        if link.name in driven:
            continue
        assert -180.0 < angle[0] <= 180.0, f"{link.name}.angle starts at {angle[0]}"
        step = np.diff(angle)
        # the trapezoidal rule bounds each step; a jump by a turn would break it
        expected = (
            0.5
            * np.degrees(
                table[f"{link.name}.omega"][1:] + table[f"{link.name}.omega"][:-1]
            )
            * dt
        )
        assert np.max(np.abs(step - expected)) < 1.0, f"{link.name}.angle jumps"
    for d in mech.drivers:
        joint = mech.joint(d.joint)
        link = joint.links[1] if joint.links[0] == "ground" else joint.links[0]
        column = "angle" if len(mech.drivers) == 1 else f"{d.joint}.drive"
        np.testing.assert_allclose(
            table[f"{link}.angle"], table[column], rtol=0, atol=1e-9
        )
    oracle.assert_rigid(mech, table)


def test_angle_columns_of_random_mechanisms_start_in_range():
    @SETTINGS
    @given(
        case=st.one_of(*(s() for s in DYAD_STRATEGIES.values())),
        start=st.floats(-1000.0, 1000.0),
    )
    def check(case: Case, start: float):
        positions = case.reference + start + np.linspace(0.0, 30.0, 7)
        if not case.full_turn:
            positions = case.sweep(7)
        table = assur.kinematics(case.mechanism, positions)
        for link in ("link2", "link3"):
            first = table[f"{link}.angle"][0]
            assert -180.0 < first <= 180.0
            assert np.all(np.abs(np.diff(table[f"{link}.angle"])) < 180.0)
        np.testing.assert_array_equal(table["crank.angle"], table["angle"])
        oracle.assert_rigid(case.mechanism, table)

    check()


# ------------------------------------------------------------------------------------
# The driver's acceleration


def families_at(
    mech: assur.Mechanism, positions: np.ndarray
) -> dict[str, list[np.ndarray]]:
    return oracle.families(assur.kinematics(mech, positions))


def assert_superposition(mech: assur.Mechanism, positions: np.ndarray) -> None:
    """With driver speed w and acceleration e, v = w v1, a = w^2 a1 + e v1 and
    j = w^3 j1 + 3 w e a1, where v1, a1, j1 are the motion at w = 1, e = 0."""
    (driver,) = mech.drivers
    w, e = driver.omega, driver.epsilon
    got = families_at(mech, positions)
    unit = families_at(steady(mech, omega=1.0), positions)
    expected = {}
    for name, (x1, v1, a1, j1) in unit.items():
        expected[name] = [x1, w * v1, w * w * a1 + e * v1, w**3 * j1 + 3.0 * w * e * a1]
    for angles in (True, False):  # one scale per level, for angles and for points
        names = [n for n in got if n.endswith(".angle") == angles]
        for k in range(4):
            scale = max(
                [float(np.max(np.abs(expected[n][k]))) for n in names] + [1e-300]
            )
            for name in names:
                np.testing.assert_allclose(
                    got[name][k],
                    expected[name][k],
                    rtol=1e-9,
                    atol=1e-10 * scale,
                    err_msg=f"{name} level {k}",
                )


def test_example_epsilon_superposition(example):
    if len(example.drivers) != 1:
        pytest.skip("one driver")
    mech = example
    if example.drivers[0].epsilon == 0.0:
        mech = steady(example, omega=-7.0, epsilon=13.0)
    positions, _ = one_turn(mech, 37)
    assert_superposition(mech, positions)


@SETTINGS
@given(
    case=st.one_of(
        *(s() for s in DYAD_STRATEGIES.values()), triad_cases(), slider_cases()
    ),
    epsilon=st.floats(-50.0, 50.0),
)
def test_epsilon_superposition(case, epsilon):
    mech = steady(
        case.mechanism, omega=case.mechanism.drivers[0].omega, epsilon=epsilon
    )
    assert_superposition(mech, case.sweep(13))


@pytest.mark.parametrize("name", ["four_bar", "lever_var9", "whitworth", "class3"])
def test_epsilon_along_an_accelerating_motion(name):
    """Along theta(t) = theta0 + w0 t + e t^2/2 with w(t) = w0 + e t (each instant
    analysed with its own w and the constant e), velocity, acceleration and jerk are
    the time derivatives of position, velocity and acceleration.

    The derivatives are central differences with steps tau and tau/2 combined by
    Richardson extrapolation (error O(tau^4)).
    """
    from .conftest import EXAMPLES

    base = assur.load(EXAMPLES / f"{name}.toml")
    w0, e, tau = 12.0, 30.0, 4e-4
    theta0 = math.radians(float(reference_drive(base)[0]))
    size = oracle.mechanism_size(base)

    def state(now: float) -> dict[str, list[np.ndarray]]:
        mech = steady(base, omega=w0 + e * now, epsilon=e)
        theta = theta0 + w0 * now + 0.5 * e * now * now
        return oracle.families(assur.kinematics(mech, [math.degrees(theta)]))

    def central(rows: dict, h: float, key: str, k: int) -> float:
        step = float(rows[h][key][k][0] - rows[-h][key][k][0])
        if k == 0 and key.endswith(".angle"):
            step = math.remainder(step, 2 * math.pi)
        return step / (2 * h)

    for t in (0.0, 0.05, 0.13, 0.3):
        rows = {dt: state(t + dt) for dt in (-tau, -tau / 2, 0.0, tau / 2, tau)}
        w = w0 + e * t
        for key, levels in rows[0.0].items():
            length = 1.0 if key.endswith(".angle") else size
            for k in range(3):
                fd = (
                    4.0 * central(rows, tau / 2, key, k) - central(rows, tau, key, k)
                ) / 3
                exact = float(levels[k + 1][0])
                scale = max(
                    abs(exact), abs(float(levels[k][0])) * w, length * w ** (k + 1)
                )
                assert abs(fd - exact) <= 1e-7 * scale, (key, k, t, fd, exact)


# ------------------------------------------------------------------------------------
# A prismatic driver, two drivers


@SETTINGS
@given(case=slider_cases())
def test_prismatic_driver(case):
    mech = case.mechanism
    found = assur.structure(mech)
    assert [g.kind for g in found.groups] == ["RRR"]
    assert [g.links for g in found.drivers] == [("ground", "slider")]
    positions, dt = case.path(61)
    table = assur.kinematics(mech, positions)
    np.testing.assert_allclose(table["angle"], positions, rtol=0, atol=1e-15)
    np.testing.assert_allclose(table["S.s"], positions, rtol=0, atol=1e-12)
    np.testing.assert_allclose(table["S.v"], mech.drivers[0].omega, rtol=1e-12)
    np.testing.assert_allclose(table["slider.omega"], 0.0, atol=0)
    oracle.assert_rigid(mech, table)
    oracle.assert_slides(mech, table)
    oracle.assert_continuous(table, dt)
    assert (case.branch(table) > 0).all()
    oracle.assert_reference_pose(mech, assur.kinematics(mech, [0.0]), 0)
    oracle.assert_differences(mech, oracle.si(mech, positions[1:-1:6]))


@SETTINGS
@given(case=five_bar_cases())
def test_two_drivers(case):
    mech = case.mechanism
    found = assur.structure(mech)
    assert found.dof == 2
    assert [g.links[1] for g in found.drivers] == ["crank", "crank2"]
    assert [g.kind for g in found.groups] == ["RRR"]
    positions, dt = case.path(91)
    table = assur.kinematics(mech, positions)
    np.testing.assert_allclose(table["A.drive"], positions[:, 0], rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["E.drive"], positions[:, 1], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(table["angle"], table["A.drive"])
    oracle.assert_rigid(mech, table)
    oracle.assert_continuous(table, dt)
    assert (case.branch(table) > 0).all()
    oracle.assert_reference_pose(
        mech, assur.kinematics(mech, case.reference[None, :]), 0
    )
    oracle.assert_differences(mech, oracle.si(mech, positions[1:-1:8]))
    # velocities are linear in the two drivers' speeds
    w1, w2 = (d.omega for d in mech.drivers)
    only = [
        dataclasses.replace(
            mech,
            drivers=(
                dataclasses.replace(mech.drivers[0], omega=a),
                dataclasses.replace(mech.drivers[1], omega=b),
            ),
        )
        for a, b in ((1.0, 0.0), (0.0, 1.0))
    ]
    parts = [assur.kinematics(m, positions) for m in only]
    for column in ("C.vx", "C.vy", "link2.omega", "link3.omega", "link2_p.vx"):
        expect = w1 * parts[0][column] + w2 * parts[1][column]
        np.testing.assert_allclose(
            table[column],
            expect,
            rtol=1e-9,
            atol=1e-9 * float(np.max(np.abs(expect))),
            err_msg=column,
        )
    # accelerations are linear in the drivers' accelerations
    e1, e2 = 3.0, -5.0
    accelerating = dataclasses.replace(
        mech,
        drivers=(
            dataclasses.replace(mech.drivers[0], epsilon=e1),
            dataclasses.replace(mech.drivers[1], epsilon=e2),
        ),
    )
    fast = assur.kinematics(accelerating, positions)
    for column in ("C.ax", "C.ay", "link2.alpha", "link3.alpha", "link3_q.ay"):
        v = (
            column.replace(".alpha", ".omega")
            .replace(".ax", ".vx")
            .replace(".ay", ".vy")
        )
        expect = table[column] + e1 * parts[0][v] + e2 * parts[1][v]
        np.testing.assert_allclose(
            fast[column],
            expect,
            rtol=1e-9,
            atol=1e-9 * float(np.max(np.abs(expect))),
            err_msg=column,
        )


# ------------------------------------------------------------------------------------
# Sweeps that cannot be assembled


def long_crank_four_bar() -> tuple[assur.Mechanism, np.ndarray, np.ndarray]:
    """A four-bar whose crank (0.12 m) is too long to turn fully, the positions of one
    turn in steps of 1 degree from 60, and which of them it reaches: the closed form
    closes there, on the reference pose's circuit (the run of closing positions
    around 60 degrees; its dyad closes on another circuit too)."""
    crank, coupler, rocker, frame = 0.12, 0.12, 0.08, 0.10
    mech = assur.catalog.four_bar(
        crank=crank, coupler=coupler, rocker=rocker, frame=frame, angle=60.0
    )
    angles = 60.0 + np.arange(0.0, 360.0, 1.0)
    diagonal = np.sqrt(
        crank**2 + frame**2 - 2 * crank * frame * np.cos(np.radians(angles))
    )
    closes = (diagonal <= coupler + rocker) & (diagonal >= abs(coupler - rocker))
    # the run from the first position up, and the one that comes back to it from
    # the end of the turn
    ok = np.cumprod(closes).astype(bool) | np.cumprod(closes[::-1])[::-1].astype(bool)
    assert ok.sum() < closes.sum()  # the other circuit is left out
    return mech, angles, ok


def test_assembly_error_names_the_group_and_first_angle():
    mech, angles, ok = long_crank_four_bar()
    assert ok[0]
    assert not ok.all()
    first = angles[np.argmin(ok)]
    with pytest.raises(assur.AssemblyError) as info:
        assur.kinematics(mech, angles)
    message = str(info.value)
    assert "RRR (coupler, rocker)" in message
    assert f"{first:g} deg" in message
    assert f"cannot be assembled at driver position {first:g} deg" in message


def test_assembly_error_in_a_force_sweep():
    mech, angles, _ = long_crank_four_bar()
    with pytest.raises(assur.AssemblyError, match=r"RRR \(coupler, rocker\)"):
        assur.forces(mech, angles)


def test_skip_unassembled_keeps_the_good_rows():
    mech, angles, ok = long_crank_four_bar()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)  # near the assembly limits
        table = assur.kinematics(mech, angles, skip_unassembled=True)
        full = assur.kinematics(mech, angles[ok][:40])
    np.testing.assert_array_equal(table["angle"], angles[ok])
    np.testing.assert_allclose(np.ravel(table.skipped), angles[~ok], rtol=0, atol=1e-12)
    assert len(table) == int(ok.sum())
    for column in ("C.x", "C.vy", "rocker.alpha", "P.jx"):
        np.testing.assert_allclose(
            table[column][:40], full[column], rtol=1e-12, atol=1e-15
        )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        oracle.assert_rigid(mech, table)


def test_skip_unassembled_in_a_force_sweep():
    mech, angles, ok = long_crank_four_bar()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        table = assur.forces(mech, angles, skip_unassembled=True)
    np.testing.assert_array_equal(table["angle"], angles[ok])
    np.testing.assert_allclose(
        table["driver.torque"],
        table["driver.torque_check"],
        rtol=1e-9,
        atol=1e-9 * float(np.max(np.abs(table["driver.torque"]))),
    )


# ------------------------------------------------------------------------------------
# Where the mechanism is and how large it is


def moved_positions(case: Case, expected: dict[str, np.ndarray]) -> np.ndarray:
    if len(case.mechanism.drivers) == 1:
        return expected["angle"]
    return np.stack([expected[f"{d.joint}.drive"] for d in case.mechanism.drivers], -1)


@SETTINGS
@given(
    case=any_case(),
    angle=st.floats(-math.pi, math.pi),
    shift=st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)),
    scale=st.sampled_from([0.05, 1.0, 20.0]),
)
def test_rigid_motion_and_similarity(case, angle, shift, scale):
    """Turning, shifting and scaling the whole mechanism turns, shifts and scales its
    motion (angular speeds unchanged; a prismatic driver's speed scaled)."""
    mech = case.mechanism
    positions, _ = case.path(13)
    table = assur.kinematics(mech, positions)
    expected = oracle.moved_columns(mech, table, angle, shift, scale)
    other = moved(mech, angle, shift, scale)
    oracle.assert_columns(
        other, assur.kinematics(other, moved_positions(case, expected)), expected
    )


def test_triad_far_from_the_origin():
    from .conftest import EXAMPLES

    mech = assur.load(EXAMPLES / "class3.toml")
    positions = 30.0 + np.arange(0.0, 360.0, 5.0)
    table = assur.kinematics(mech, positions)
    far = moved(mech, 0.0, (300.0, 0.0))
    expected = oracle.moved_columns(mech, table, 0.0, (300.0, 0.0))
    oracle.assert_columns(far, assur.kinematics(far, positions), expected)


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_a_triad_s_dead_centre_warnings_do_not_depend_on_its_units(scale):
    """Its conditioning is measured with the origins in units of the group's size,
    and its reactions solved with moments so (a measure left in metres warned of
    a dead centre in millimetres' and kilometres' copies only)."""
    from .conftest import DATA

    mech = assur.load(DATA / "edge" / "triad_locks_ahead.toml")
    angles = np.arange(0.0, 360.0, 2.0)

    def said(m: assur.Mechanism) -> tuple[int, list[str]]:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            table = assur.forces(m, angles, skip_unassembled=True)
        told = [str(w.message) for w in caught if "across" not in str(w.message)]
        return len(table), told

    assert said(moved(mech, 0.0, (0.0, 0.0), scale)) == said(mech)


@pytest.mark.parametrize("scale", [1e-3, 0.1, 10.0, 1e3])
@pytest.mark.filterwarnings("ignore:joints. the mechanism is .* m across")
def test_a_triad_scaled_moves_alike(scale):
    """The triad's continuation weighs its unknowns by the group's reach, so that
    its steps do not depend on the units: scaled by up to a thousand either way it
    follows the same motion, its lengths and speeds scaled."""
    from .conftest import EXAMPLES

    mech = assur.load(EXAMPLES / "class3.toml")
    positions = 30.0 + np.arange(0.0, 360.0, 5.0)
    table = assur.kinematics(mech, positions)
    other = moved(mech, 0.0, (0.0, 0.0), scale)
    expected = oracle.moved_columns(mech, table, 0.0, (0.0, 0.0), scale)
    oracle.assert_columns(other, assur.kinematics(other, positions), expected)


def test_angles_stay_continuous_beside_a_prismatic_driver_s_body():
    """A drag-link four-bar beside a ram, two drivers: the ram's body is among the
    links whose angle is not given, and only the others are made continuous
    (unwrapping the ram's instead left the follower's whole turns jumping back by
    360 deg), read together or alone."""
    from .conftest import DATA

    mech = assur.load(DATA / "edge" / "drag_link_beside_a_ram.toml")
    crank = np.linspace(0.0, 720.0, 361)
    given = np.column_stack([crank, np.zeros_like(crank)])
    table = assur.kinematics(mech, given)
    follower = table["follower.angle"]
    assert follower[0] == pytest.approx(79.7534, abs=1e-4)
    assert follower[-1] == pytest.approx(follower[0] + 720.0, abs=1e-9)
    assert np.abs(np.diff(follower)).max() < 4.0
    alone = assur.kinematics(mech, given, columns=["follower.angle"])
    np.testing.assert_array_equal(alone["follower.angle"], follower)
    np.testing.assert_array_equal(table["ram.angle"], 0.0)


def test_sub_millimetre_mechanism():
    from .conftest import EXAMPLES

    mech = assur.load(EXAMPLES / "whitworth.toml")
    positions = 45.0 + np.arange(0.0, 360.0, 5.0)
    table = assur.kinematics(mech, positions)
    small = moved(mech, 0.0, (0.0, 0.0), 1e-3)
    expected = oracle.moved_columns(mech, table, 0.0, (0.0, 0.0), 1e-3)
    oracle.assert_columns(small, assur.kinematics(small, positions), expected)
