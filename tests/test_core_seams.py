"""The core's seams: group protocol and registry, step records, frozen states, driver
speed per position, the column schema and ``columns=``, instant centres.

Each capability is checked against something independent of it: a group family
written separately (tests/groups/dense_rrr.py), the oracle's global equilibrium solve
(tests/oracle.py), separate constant-speed sweeps, and the velocities of a link's own
points.
"""

from __future__ import annotations

import dataclasses
import math
import pickle
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur import _kinematics, kinetostatics
from assur._evaluate import SHORT
from assur._loads import compile_loads
from assur._vec import leaves
from assur.groups import FAMILIES
from assur.plan import cached_plan, compile_plan, plan_of

from . import oracle
from .groups import dense_rrr
from .mechanisms import one_turn
from .test_kinematics import long_crank_four_bar
from .test_kinetostatics import (
    assert_balancing_check,
    assert_links_in_equilibrium,
    assert_matches_global_solve,
    needs_forces,
)

EXAMPLES = Path(__file__).parent.parent / "examples"


def magnitude(values: np.ndarray) -> float:
    """Largest finite magnitude, at least 1."""
    return float(np.max(np.abs(values[np.isfinite(values)]), initial=1.0))


def positions(mech: assur.Mechanism, count: int = 24) -> np.ndarray:
    return one_turn(mech, count, endpoint=False)[0]


def forced(mech: assur.Mechanism) -> bool:
    return needs_forces(mech)


# ------------------------------------------------------------------------------------
# A group family is one module plus one line in the registry


@pytest.mark.parametrize("name", ["four_bar", "six_bar_lecture", "tenbar", "class3"])
def test_a_new_family_from_one_registry_line(monkeypatch, name):
    mech = assur.load(EXAMPLES / f"{name}.toml")
    run = assur.forces if forced(mech) else assur.kinematics
    at = positions(mech)
    expected = run(mech, at)
    monkeypatch.setitem(FAMILIES, "RRR", dense_rrr.compile_group)
    plan = compile_plan(mech)
    assert any(isinstance(s, dense_rrr.DenseRRR) for s in plan.solvers) == (
        name != "class3"
    )
    cached_plan.cache_clear()
    try:
        got = run(mech, at)
    finally:
        cached_plan.cache_clear()
    for column in expected.columns:
        scale = magnitude(expected[column])
        np.testing.assert_allclose(
            got[column], expected[column], rtol=0, atol=1e-9 * scale, err_msg=column
        )


# ------------------------------------------------------------------------------------
# Records of the reverse pass and their equations


def reverse_pass(mech: assur.Mechanism, at: np.ndarray):
    plan = plan_of(mech)
    table = assur.forces(mech, at)
    bodies = _kinematics.motions(plan, table.state)
    applied = kinetostatics.applied_loads(
        plan, compile_loads(plan), bodies, table.state
    )
    return plan, table, bodies, kinetostatics.reverse(plan, bodies, applied)


def test_every_group_returns_a_record_whose_equations_hold(example):
    if not forced(example):
        pytest.skip("no masses and no loads: nothing to analyse")
    plan, table, bodies, result = reverse_pass(example, positions(example))
    assert [r.label for r in result.groups] == [s.label for s in plan.solvers][::-1]
    force, size = oracle.load_scale(example, table)
    for record in result.groups:
        eq = record.equations(bodies, plan.bodies)
        assert eq.unknowns == record.unknowns
        assert len(eq.rows) == len(eq.unknowns) == 3 * len(record.bodies)
        assert np.all(eq.residual <= 1e-9 * force * size), record.label
        # the equations alone, solved densely, give the record's reactions
        dense = np.linalg.solve(eq.matrix, eq.rhs[..., None])[..., 0]
        np.testing.assert_allclose(
            dense, eq.solution, rtol=1e-8, atol=1e-9 * force * size
        )
        for name, reaction in record.reactions.items():
            pair = plan.pairs[name]
            # a prismatic pair's column adds its friction to the normal force
            if not pair.virtual and (pair.kind == "R" or not pair.friction):
                np.testing.assert_array_equal(table[f"{name}.Fx"], reaction.fx)


def test_dyad_equations_read_as_the_lecture_writes_them():
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    plan, _, bodies, result = reverse_pass(mech, np.array([45.0]))
    (record,) = result.groups
    eq = record.equations(bodies, plan.bodies)
    assert eq.rows == (
        "moment of rod about C",
        "moment of slider about C",
        "forces on the group along x",
        "forces on the group along y",
        "forces on rod along x",
        "forces on rod along y",
    )
    assert eq.unknowns == ("C.Fx", "C.Fy", "B.Fx", "B.Fy", "guide.N", "guide.M")
    (driver,) = result.drivers
    np.testing.assert_allclose(driver.balancing, 84.625, rtol=1e-6)


# ------------------------------------------------------------------------------------
# The reverse pass reads a frozen state: rebuilt, pickled, in another process


def test_forces_from_a_stored_state_are_the_same(example):
    if not forced(example):
        pytest.skip("no masses and no loads: nothing to analyse")
    at = positions(example, 30)
    table = assur.forces(example, at)
    stored = pickle.loads(pickle.dumps((table.state, table.plan.mechanism)))
    state, mech = stored
    plan = plan_of(mech)
    bodies = _kinematics.motions(plan, state)
    forces, _ = kinetostatics.solve(plan, compile_loads(plan), bodies, state)
    for name, (fx, fy, couple) in table.force_state.reactions.items():
        got = forces.reactions[name]
        np.testing.assert_array_equal(got[0], fx, err_msg=name)
        np.testing.assert_array_equal(got[1], fy, err_msg=name)
        np.testing.assert_array_equal(got[2], couple, err_msg=name)
    np.testing.assert_array_equal(forces.balancing, table.force_state.balancing)


def test_jerks_solved_later_equal_jerks_solved_at_once(example):
    # a long table solves its jerks when first read; a short one, or one asked for
    # jerks by name, with the rest
    at = positions(example, 20)
    run = assur.forces if forced(example) else assur.kinematics
    reps = (SHORT // len(at) + 1,) + (1,) * (at.ndim - 1)
    lazy = run(example, np.tile(at, reps))
    assert lazy.state.top == 2
    jerks = [c for c in lazy.columns if c.endswith((".jerk", ".jx", ".jy", ".j"))]
    for eager in (run(example, at), run(example, at, columns=jerks)):
        assert eager.state.top == 3
        for column in jerks:
            np.testing.assert_allclose(
                lazy[column][: len(at)],
                eager[column],
                rtol=1e-12,
                atol=1e-12,
                err_msg=column,
            )


def test_the_motion_of_a_table_of_few_columns_is_solved_to_the_level_asked(example):
    # a table of one position column keeps positions only; its motion at a higher
    # level solves the derivatives it lacks, the drivers moving at the sweep's rates
    at = positions(example, 12)
    drivers = len(example.drivers)
    omega = np.linspace(2.0, 5.0, len(at) * drivers).reshape(drivers, -1).T.squeeze()
    epsilon = np.linspace(-30.0, 40.0, len(at) * drivers).reshape(drivers, -1).T
    epsilon = epsilon.squeeze()
    whole = assur.kinematics(example, at, omega=omega, epsilon=epsilon)
    point = next(c.name for c in whole.schema if c.family == "point")
    few = assur.kinematics(example, at, columns=[point], omega=omega, epsilon=epsilon)
    assert few.state.top == 0
    for level in (1, 2, 3):
        state = few.motion(level)
        assert state.top >= level
        got = leaves((state.motion, state.slide))
        want = leaves((whole.state.motion, whole.state.slide))
        for a, b in zip(got, want, strict=True):
            np.testing.assert_allclose(
                np.broadcast_to(a, len(at)),
                np.broadcast_to(b, len(at)),
                rtol=1e-11,
                atol=1e-11 * magnitude(np.asarray(b, dtype=float)),
            )


# ------------------------------------------------------------------------------------
# Driver speed and acceleration per position


def speeds(n: int, omega: float) -> tuple[np.ndarray, np.ndarray]:
    t = np.linspace(0.0, 1.0, n)
    return omega * (0.5 + t), omega * 40.0 * np.cos(5.0 * t)


@pytest.mark.parametrize(
    "name", ["slider_crank_exercise", "four_bar", "whitworth", "class3", "lever_var9"]
)
def test_constant_arrays_give_the_file_constants(name):
    mech = assur.load(EXAMPLES / f"{name}.toml")
    at = positions(mech, 16)
    d = mech.drivers[0]
    run = assur.forces if forced(mech) else assur.kinematics
    same = run(
        mech,
        at,
        omega=np.full(len(at), d.omega),
        epsilon=np.full(len(at), d.epsilon),
    )
    plain = run(mech, at)
    for column in plain.columns:
        np.testing.assert_allclose(
            same[column], plain[column], rtol=1e-13, atol=1e-13, err_msg=column
        )


@pytest.mark.parametrize(
    "name",
    ["slider_crank_exercise", "four_bar", "whitworth", "class3", "six_bar_lecture"],
)
def test_speed_per_position_matches_separate_sweeps_and_the_global_solve(name):
    mech = assur.load(EXAMPLES / f"{name}.toml")
    at = positions(mech, 12)
    omega, epsilon = speeds(len(at), mech.drivers[0].omega)
    table = assur.forces(mech, at, omega=omega, epsilon=epsilon)
    # each row is the sweep at that row's constant speed and acceleration
    for i in range(len(at)):
        row = assur.forces(mech, at[i : i + 1], omega=omega[i], epsilon=epsilon[i])
        for column in row.columns:
            scale = magnitude(row[column])
            gap = table[column][i] - row[column][0]
            if row.column(column).unit == "deg":  # angles agree modulo a turn
                gap = (gap + 180.0) % 360.0 - 180.0
            assert abs(gap) <= 1e-10 * scale or np.isnan(gap), (column, gap)
    # and the reactions are those of the whole mechanism's equilibrium
    assert_matches_global_solve(mech, table)
    assert_links_in_equilibrium(mech, table)
    assert_balancing_check(mech, table)


def test_velocities_scale_with_the_speed_and_accelerations_split():
    """At unit speed the velocities are the velocity coefficients; the acceleration at
    speed w and acceleration e is e times them plus w^2 times those at unit speed."""
    mech = assur.load(EXAMPLES / "tenbar.toml")
    at = positions(mech, 36)
    omega, epsilon = speeds(len(at), 3.0)
    table = assur.kinematics(mech, at, omega=omega, epsilon=epsilon)
    unit = assur.kinematics(mech, at, omega=1.0, epsilon=0.0)
    for point in ("C", "E", "S"):
        for axis in ("x", "y"):
            v1 = unit[f"{point}.v{axis}"]
            a1 = unit[f"{point}.a{axis}"]
            np.testing.assert_allclose(
                table[f"{point}.v{axis}"], omega * v1, atol=1e-12
            )
            np.testing.assert_allclose(
                table[f"{point}.a{axis}"], epsilon * v1 + omega**2 * a1, atol=1e-9
            )


@pytest.mark.parametrize("count", [36, SHORT + 500])  # jerks at once, jerks later
def test_jerks_split_with_the_driver_s_jerk(count):
    """r(phi(t)): the jerk is w^3 d3r + 3 w e d2r + j dr, the derivatives with
    respect to the crank angle being the motion at unit speed (``jerk=`` the driver's
    own jerk j; zero before it could be given, wrong for a driver whose acceleration
    changes, the dynamic model's steady motion say)."""
    mech = assur.load(EXAMPLES / "tenbar.toml")
    at = np.linspace(0.0, 360.0, count, endpoint=False)
    omega, epsilon = speeds(count, 3.0)
    jerk = np.linspace(-400.0, 250.0, count)
    table = assur.kinematics(mech, at, omega=omega, epsilon=epsilon, jerk=jerk)
    unit = assur.kinematics(mech, at, omega=1.0, epsilon=0.0)
    np.testing.assert_array_equal(table["1.jerk"], jerk)
    for point in ("C", "E", "S"):
        for axis in ("x", "y"):
            v1, a1, j1 = (unit[f"{point}.{k}{axis}"] for k in "vaj")
            want = omega**3 * j1 + 3.0 * omega * epsilon * a1 + jerk * v1
            got = table[f"{point}.j{axis}"]
            tol = 1e-9 * np.abs(want).max()
            np.testing.assert_allclose(got, want, rtol=1e-9, atol=tol)
    # a table of the jerk alone solves it so too, and a number is every position's
    few = assur.kinematics(
        mech, at, omega=omega, epsilon=epsilon, jerk=jerk, columns=["S.jx"]
    )
    np.testing.assert_allclose(few["S.jx"], table["S.jx"], rtol=1e-12, atol=1e-9)
    same = assur.kinematics(mech, at, jerk=7.0)
    np.testing.assert_array_equal(same["1.jerk"], 7.0)
    # the file's constants: a jerk of zero, every number as before
    plain = assur.kinematics(mech, at)
    zero = assur.kinematics(mech, at, jerk=0.0)
    for name in plain.columns:
        np.testing.assert_array_equal(zero[name], plain[name])


def test_a_bad_jerk_is_refused():
    mech = assur.catalog.slider_crank()
    with pytest.raises(assur.UsageError, match="jerk: expected a number or one value"):
        assur.kinematics(mech, [0.0, 10.0, 20.0], jerk=[1.0, 2.0])
    with pytest.raises(
        assur.UsageError, match=r"jerk: expected real numbers \(rad/s\^3"
    ):
        assur.forces(mech, [0.0], jerk="fast")
    with pytest.raises(assur.UsageError, match="jerk: expected finite numbers"):
        assur.kinematics(mech, [0.0], jerk=[np.inf])
    refused = r"^jerk: expected real numbers .*got True or False$"
    with pytest.raises(assur.UsageError, match=refused):
        assur.kinematics(mech, [0.0], jerk=True)
    # a jerk grows as the speed cubed: the steady motion of a crank at 1e5 rad/s
    # has some 1.5e15 rad/s^3, beyond the file's numbers' 1e15
    fast = dataclasses.replace(mech, drivers=(assur.Driver("A", 1e5),))
    steady = assur.dynamics(fast, [0.0, 90.0])
    assert np.max(np.abs(steady["driver.jerk"])) > 1e15
    table = assur.forces(
        fast,
        steady["angle"],
        omega=steady["driver.omega"],
        epsilon=steady["driver.epsilon"],
        jerk=steady["driver.jerk"],
    )
    np.testing.assert_array_equal(table["crank.jerk"], steady["driver.jerk"])
    with pytest.raises(assur.UsageError, match=r"expected magnitudes up to 1e\+30"):
        assur.kinematics(mech, [0.0], jerk=2e30)


def test_speeds_are_the_third_and_fourth_arguments_as_format_md_writes_them():
    """``assur.kinematics(mechanism, angles, omega=None, epsilon=None)``: by position
    as by name, the same table; the skipping of unassembled positions goes by name."""
    mech = assur.catalog.slider_crank()
    at = positions(mech, 12)
    omega, epsilon = speeds(len(at), 2.0)
    for analyse in (assur.kinematics, assur.forces):
        by_name = analyse(mech, at, omega=omega, epsilon=epsilon)
        by_place = analyse(mech, at, omega, epsilon)
        assert by_place.columns == by_name.columns
        for name in ("rod.alpha", "C.ay"):
            np.testing.assert_array_equal(by_place[name], by_name[name])
        assert not np.array_equal(by_place["rod.alpha"], analyse(mech, at)["rod.alpha"])
    table = assur.forces(mech, at, omega, skip_unassembled=True)
    np.testing.assert_array_equal(table["crank.omega"], omega)
    np.testing.assert_array_equal(table["crank.alpha"], 0.0)


def test_bad_speed_arrays_are_refused():
    mech = assur.catalog.slider_crank()
    with pytest.raises(assur.UsageError, match="omega: expected a number or one value"):
        assur.forces(mech, [0.0, 10.0, 20.0], omega=[1.0, 2.0])
    with pytest.raises(assur.UsageError, match="epsilon: expected real numbers"):
        assur.forces(mech, [0.0], epsilon=[1j])
    with pytest.raises(assur.UsageError, match="omega: expected finite numbers"):
        assur.forces(mech, [0.0], omega=[np.nan])


# ------------------------------------------------------------------------------------
# The column schema and columns=


def test_the_schema_describes_every_column(example):
    run = assur.forces if forced(example) else assur.kinematics
    table = run(example, positions(example, 4))
    assert [c.name for c in table.schema] == list(table.columns)
    units = {
        "angle": {"deg", "m"},
        "omega": {"rad/s"},
        "alpha": {"rad/s^2"},
        "jerk": {"rad/s^3"},
        "x": {"m"},
        "vx": {"m/s"},
        "ax": {"m/s^2"},
        "jy": {"m/s^3"},
        "Fx": {"N"},
        "Mi": {"N m"},
        "torque": {"N m"},
    }
    for column in table.schema:
        if column.quantity in units:
            assert column.unit in units[column.quantity], column
        assert table.column(column.name) == column
        values = table[column.name]
        assert values.shape == (len(table),)
        assert not values.flags.writeable, column.name


def test_columns_computes_only_what_is_asked():
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    at = np.arange(45.0, 405.0, 5.0)
    full = assur.forces(mech, at)
    few = assur.forces(mech, at, columns=["driver.torque", "C.vx"])
    assert few.columns == ("angle", "C.vx", "driver.torque")
    assert few.state.top == 2
    np.testing.assert_array_equal(few["driver.torque"], full["driver.torque"])
    np.testing.assert_array_equal(few["C.vx"], full["C.vx"])
    with pytest.raises(KeyError, match=r"no column 'B\.Fx'"):
        few["B.Fx"]
    # a KeyError and one of assur's own (the pictures drawn from such a table
    # raised it from deep inside), the message as written, not quoted
    with pytest.raises(assur.UnknownNameError) as caught:
        few["B.Fx"]
    assert isinstance(caught.value, assur.AssurError)
    assert str(caught.value).startswith("no column 'B.Fx': the table was made with")
    motion = assur.kinematics(mech, at[:2])
    with pytest.raises(assur.UnknownNameError, match=r"a force column: use assur.f"):
        motion["driver.torque"]
    with pytest.raises(assur.UnknownNameError, match=r"expected a column's name, a"):
        motion[0:2]  # type: ignore[index]
    with pytest.raises(assur.UnknownNameError, match="unknown link 'piston'"):
        mech.link("piston")
    # a mechanism without masses or loads has no force table to point to
    four = assur.catalog.four_bar()
    links = tuple(
        dataclasses.replace(link, mass=None, inertia=None, center=None)
        for link in four.links
    )
    bare = assur.kinematics(dataclasses.replace(four, links=links), [0.0])
    with pytest.raises(assur.UnknownNameError) as caught:
        bare["driver.torque"]
    assert "assur.forces" not in str(caught.value)
    # text for the positions, an array of it or bytes, told as the text it is
    for text, shown in (
        (np.array(["30", "40"]), "['30', '40']"),
        (b"30", "'30'"),
        ("30", "'30'"),
    ):
        with pytest.raises(assur.UsageError, match=rf"got text {re.escape(shown)}$"):
            assur.kinematics(mech, text)
    only = assur.forces(mech, at, columns=["C.x"])
    assert only.force_state is None
    assert only.state.top == 0
    with pytest.raises(assur.UsageError, match=r"a force column: use assur\.forces"):
        assur.kinematics(mech, at, columns=["driver.torque"])
    with pytest.raises(assur.UsageError, match=r"did you mean 'driver\.torque'"):
        assur.forces(mech, at, columns=["driver.torqe"])


def test_positions_alone_are_given_at_a_dead_centre():
    # a parallelogram four-bar at 180 deg: every link on one line, the RRR
    # group's velocity equations singular; its pose is sound
    mech = assur.load(
        EXAMPLES.parent / "docs" / "files" / "errors" / "parallelogram.toml"
    )
    at = [170.0, 180.0, 190.0]
    with warnings.catch_warnings(record=True) as told:
        warnings.simplefilter("always")
        poses = assur.kinematics(mech, at, columns=["coupler.angle", "B.x", "B.y"])
        ok = assur.kinematics(mech, [170.0, 190.0])
    said = [str(w.message) for w in told]
    assert any("near a dead centre" in s and "180 deg" in s for s in said), said
    # a parallelogram's coupler stays parallel to the frame
    np.testing.assert_allclose(poses["coupler.angle"], 0.0, atol=1e-6)
    np.testing.assert_array_equal(poses["B.x"][[0, 2]], ok["B.x"])
    # at a double root the pose holds to the square root of the round-off
    np.testing.assert_allclose(poses["B.y"][1], 0.0, atol=1e-8)
    # a speed there is what the singular equations cannot give
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        with pytest.raises(assur.SingularConfigurationError, match="180 deg"):
            assur.kinematics(mech, at, columns=["coupler.omega"])


def test_a_short_table_gives_the_numbers_of_a_long_one(example):
    # a short table computes a column's family (or every column needing the links'
    # motions) at once; a long one each column alone, slice by slice
    at = positions(example, 20)
    run = assur.forces if forced(example) else assur.kinematics
    short = run(example, at)
    long = run(example, np.tile(at, (SHORT // len(at) + 1,) + (1,) * (at.ndim - 1)))
    assert len(short) <= SHORT < len(long)
    for name in short.columns:
        np.testing.assert_array_equal(
            long[name][: len(short)], short[name], err_msg=name
        )
    arrays = run(example, at).arrays()
    for name, values in zip(short.columns, arrays, strict=True):
        np.testing.assert_array_equal(values, short[name], err_msg=name)


@pytest.mark.parametrize("n", [30, SHORT + 1])
def test_the_order_columns_are_read_in_changes_no_number(n):
    # reading points first keeps their values in the rebuilt motions, which the
    # checks and residuals then use: far from the origin (a plan with a shift) the
    # positions kept must be the core's, not the shifted columns
    from .mechanisms import moved

    mech = moved(assur.catalog.slider_crank(), 0.3, (40.0, -25.0))
    assert any(plan_of(mech).shift)
    at = np.linspace(0.0, 360.0, n)
    first = assur.forces(mech, at)
    points = [c.name for c in first.schema if c.family == "point"]
    rest = [c.name for c in first.schema if c.family != "point"]
    for name in points + rest:
        first[name]
    second = assur.forces(mech, at)
    for name in rest + points:
        np.testing.assert_array_equal(first[name], second[name], err_msg=name)
    assert np.all(first["residual.force"] < 1e-9 * magnitude(first["A.F"]))


def assert_same_states(table, reference):
    """The states of ``table`` are those of ``reference``, to the last bit."""
    for got, want in (
        (
            (table.state.motion, table.state.slide),
            (reference.state.motion, reference.state.slide),
        ),
        (table.force_state.fields(), reference.force_state.fields()),
    ):
        got, want = leaves(got), leaves(want)
        assert len(got) == len(want)
        for a, b in zip(got, want, strict=True):
            np.testing.assert_array_equal(a, b)


def test_a_table_of_the_drivers_columns_keeps_no_motions_and_solves_them_again():
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    at = np.arange(0.0, 360.0, 7.5)
    omega = np.linspace(10.0, 20.0, at.shape[0])
    full = assur.forces(mech, at, omega=omega)
    torque = assur.forces(mech, at, omega=omega, columns=["driver.torque"])
    # nothing of the links is kept: the torque is all the table holds
    assert torque._kept.motion == ()
    assert torque._kept.slide == {}
    assert torque._kept_forces.reactions == {}
    assert torque._kept_forces.inertia == ()
    np.testing.assert_array_equal(torque["driver.torque"], full["driver.torque"])
    omega[:] = 0.0  # the caller's array changes after the call: the table's may not
    assert_same_states(torque, full)
    whole = full.summary()
    assert {k: whole[k] for k in torque.summary()} == torque.summary()
    assert "driver.torque.max" in torque.summary()
    assert torque.state is torque.state  # solved again once


def test_a_table_of_the_drivers_columns_with_skipped_positions():
    mech, angles, ok = long_crank_four_bar()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        full = assur.forces(mech, angles, skip_unassembled=True)
        torque = assur.forces(
            mech, angles, skip_unassembled=True, columns=["driver.torque"]
        )
    np.testing.assert_array_equal(torque.skipped, full.skipped)
    np.testing.assert_array_equal(torque["driver.torque"], full["driver.torque"])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # solving again repeats no warning
        assert_same_states(torque, full)
    angle = assur.kinematics(mech, angles[ok], columns=["angle"])
    assert angle._kept.motion == ()
    np.testing.assert_array_equal(angle.state.motion[2][0], full.state.motion[2][0])


# ------------------------------------------------------------------------------------
# Instant centres


def test_instant_centres_are_where_the_link_does_not_move(example):
    table = assur.kinematics(example, positions(example, 30))
    size = oracle.mechanism_size(example)
    for link in example.links:
        name = link.name
        icx, icy = table[f"{name}.ic.x"], table[f"{name}.ic.y"]
        omega = table[f"{name}.omega"]
        points = oracle.reported_points(example, name)
        translating = np.isnan(icx)
        assert np.array_equal(translating, np.isnan(icy))
        for point, _ in points:
            vx, vy = table[f"{point}.vx"], table[f"{point}.vy"]
            x, y = table[f"{point}.x"], table[f"{point}.y"]
            speed = np.max(np.hypot(vx, vy)) + 1e-300
            # v_P = omega z x (P - IC): the IC's own velocity on the link is zero
            ok = ~translating
            np.testing.assert_allclose(
                vx[ok], -omega[ok] * (y[ok] - icy[ok]), atol=1e-9 * speed + 1e-12
            )
            np.testing.assert_allclose(
                vy[ok], omega[ok] * (x[ok] - icx[ok]), atol=1e-9 * speed + 1e-12
            )
            # a translating link: every point has the same velocity
            if translating.any():
                assert np.allclose(np.abs(omega[translating]) * size, 0.0, atol=1e-9)


def test_the_instant_centre_of_numbers_is_that_of_arrays():
    """A link whose motion is a constant (a crank's, with its origin on its pivot)
    takes the arithmetic on numbers; a moving origin checks its terms by hand:
    omega = 2 rad/s, the origin at (0.1, 0) moving at (1, 0.4) m/s has its centre
    at (0.1 - 0.4 / 2, 0 + 1 / 2) = (-0.1, 0.5) m. (On the crank's pivot the
    origin's velocity is zero: a sign in those terms went unseen.)"""
    from types import SimpleNamespace

    from assur._evaluate import _centre, _fixed_centre

    plan = SimpleNamespace(scale=0.1, shift=(0.0, 0.0))
    assert _fixed_centre(plan, [2.0, 0.1, 0.0, 1.0, 0.4]) == pytest.approx((-0.1, 0.5))
    x, y = np.empty(2), np.empty(2)
    rows = [np.array([2.0, -3.0]), np.array([0.1, 0.2]), np.zeros(2)]
    rows += [np.array([1.0, 0.3]), np.array([0.4, -0.6])]
    _centre(plan, rows, x, y)
    for k in range(2):
        leaves = [float(r[k]) for r in rows]
        assert (x[k], y[k]) == pytest.approx(_fixed_centre(plan, leaves), rel=1e-15)
    # translating: no centre
    assert np.isnan(_fixed_centre(plan, [0.0, 0.1, 0.0, 1.0, 0.4])).all()


def test_instant_centre_of_a_crank_is_its_pivot_and_a_slider_has_none():
    table = assur.kinematics(assur.catalog.slider_crank(), [10.0, 70.0])
    np.testing.assert_allclose(table["crank.ic.x"], table["A.x"])
    np.testing.assert_allclose(table["crank.ic.y"], table["A.y"])
    assert np.isnan(table["slider.ic.x"]).all()
    assert np.isnan(table["slider.ic.y"]).all()


@pytest.mark.parametrize("first", [0.0, -0.0])
def test_shared_constant_columns_keep_the_sign_of_zero(first):
    # constant columns are made once per value and shared: -0.0 == 0.0, yet a
    # zero's sign changes results (atan2, 1/x), whichever was asked for first
    from assur._vec import full

    n = 7 + int(first == 0.0)  # a length no other test asks for first
    for value in (first, -first, first):
        got = full(value, n)
        negative = math.copysign(1.0, value) < 0
        assert np.all(np.signbit(got) == negative), value
        assert not got.flags.writeable
