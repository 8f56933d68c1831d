"""A number is right or a message names why not: change points, exact dead centres,
mechanisms far from the origin, huge driver angles, extreme speeds, cost that grows
with the work.

Each check compares with what is known independently: a parallelogram stays a
parallelogram, a mechanism moved or turned gives the same loads, an angle and the same
angle plus whole turns give the same pose.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.groups import general

EXAMPLES = Path(__file__).parent.parent / "examples"

PARALLELOGRAM = """
format = 1
name = "parallelogram"
[links.crank]
axis = ["A", "B"]
mass = 1.0
center = "B"
inertia = 0.001
[links.coupler]
axis = ["B", "C"]
mass = 2.0
center = { from = "B", toward = "C", distance = 0.15 }
inertia = 0.02
[links.rocker]
axis = ["D", "C"]
[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]
[joints.B]
kind = "revolute"
links = ["crank", "coupler"]
at = [0.0707106781186548, 0.0707106781186548]
[joints.C]
kind = "revolute"
links = ["coupler", "rocker"]
at = [0.3707106781186548, 0.0707106781186548]
[joints.D]
kind = "revolute"
links = ["ground", "rocker"]
at = [0.3, 0.0]
[[drivers]]
joint = "A"
omega = 10.0
"""


def parallelogram() -> assur.Mechanism:
    return assur.loads(PARALLELOGRAM)


def record(run, *args, **kwargs):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = run(*args, **kwargs)
    return table, [str(w.message) for w in caught]


# ------------------------------------------------------------------------------------
# Change points


@pytest.mark.parametrize("step", [35.0, 7.0, 1.0])
def test_a_parallelogram_stays_a_parallelogram_through_its_change_points(step):
    mech = parallelogram()
    at = np.arange(45.0, 45.0 + 720.0, step)
    at = at[np.abs(((at % 180.0) + 90.0) % 180.0 - 90.0) > 1e-3]  # not at 0 or 180
    table, said = record(assur.kinematics, mech, at)
    gap = (table["rocker.angle"] - table["crank.angle"] + 180.0) % 360.0 - 180.0
    np.testing.assert_allclose(gap, 0.0, atol=1e-9)
    coupler = (table["coupler.angle"] + 180.0) % 360.0 - 180.0
    np.testing.assert_allclose(coupler, 0.0, atol=1e-9)
    np.testing.assert_allclose(table["rocker.omega"], table["crank.omega"], rtol=1e-9)
    changes = [s for s in said if "change point" in s]
    assert any("180 deg" in s for s in changes), said
    assert any("360 deg" in s for s in changes), said


def test_a_single_position_past_a_change_point_is_on_the_continued_branch():
    table, said = record(assur.kinematics, parallelogram(), [270.0])
    assert table["rocker.angle"][0] % 360.0 == pytest.approx(270.0)
    assert any("meet at driver position 180 deg" in s for s in said), said


def test_positions_in_any_order_give_the_same_rows():
    mech = parallelogram()
    at = np.arange(45.0, 405.0, 10.0)
    rng = np.random.default_rng(3)
    mixed = rng.permutation(at)
    sorted_table, _ = record(assur.forces, mech, at)
    mixed_table, _ = record(assur.forces, mech, mixed)
    order = np.argsort(mixed)
    for column in ("rocker.omega", "C.Fx", "driver.torque"):
        np.testing.assert_allclose(mixed_table[column][order], sorted_table[column])


def test_the_reverse_pass_balances_past_a_change_point():
    mech = parallelogram()
    table, _ = record(assur.forces, mech, np.arange(200.0, 340.0, 10.0))
    np.testing.assert_allclose(
        table["driver.torque"], table["driver.torque_check"], rtol=1e-9, atol=1e-9
    )


# ------------------------------------------------------------------------------------
# Exact dead centres are errors, not huge numbers


def test_a_parallelogram_exactly_at_its_change_point_is_a_dead_centre():
    mech = parallelogram()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        with pytest.raises(assur.SingularConfigurationError, match="180 deg"):
            assur.forces(mech, [170.0, 180.0, 190.0])
    table, _ = record(assur.forces, mech, [170.0, 180.0, 190.0], skip_unassembled=True)
    assert table.skipped.tolist() == [180.0]
    assert np.all(np.abs(table["driver.torque"]) < 1e3)


def non_grashof() -> tuple[assur.Mechanism, float]:
    """A crank that cannot turn: coupler and rocker stretch out at its limit angle."""
    crank, frame, coupler, rocker = 0.3, 0.25, 0.15, 0.2
    limit = math.acos(
        (crank**2 + frame**2 - (coupler + rocker) ** 2) / (2.0 * crank * frame)
    )
    theta = limit / 2.0
    b = np.array([crank * math.cos(theta), crank * math.sin(theta)])
    d = np.array([frame, 0.0])
    gap = np.hypot(*(d - b))
    along = (coupler**2 - rocker**2 + gap**2) / (2.0 * gap)
    height = math.sqrt(coupler**2 - along**2)
    unit = (d - b) / gap
    c = b + along * unit + height * np.array([-unit[1], unit[0]])
    mech = assur.Mechanism(
        (
            assur.Link("crank", ("A", "B"), 1.0, "B", 0.01),
            assur.Link("coupler", ("B", "C"), 1.0, "C", 0.01),
            assur.Link("rocker", ("D", "C"), 1.0, "C", 0.01),
        ),
        (
            assur.Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
            assur.Joint("B", "revolute", ("crank", "coupler"), tuple(b)),
            assur.Joint("C", "revolute", ("coupler", "rocker"), tuple(c)),
            assur.Joint("D", "revolute", ("ground", "rocker"), tuple(d)),
        ),
        (assur.Driver("A", 5.0),),
    )
    return mech, math.degrees(limit)


def test_the_limit_of_a_non_grashof_crank_is_a_dead_centre_and_beyond_it_fails():
    mech, limit = non_grashof()
    table, _ = record(assur.forces, mech, [limit - 1.0])
    assert np.isfinite(table["driver.torque"]).all()
    with pytest.raises(assur.SingularConfigurationError, match="dead centre"):
        assur.forces(mech, [limit])
    with pytest.raises(assur.AssemblyError, match="cannot be assembled"):
        assur.forces(mech, [limit + 1.0])


# ------------------------------------------------------------------------------------
# Far from the origin, huge angles, extreme speeds


def moved(mech: assur.Mechanism, dx: float, dy: float) -> assur.Mechanism:
    """The same mechanism with every coordinate given shifted by (dx, dy)."""
    text = assur.dumps(mech)
    data = __import__("tomllib").loads(text)
    for joint in data["joints"].values():
        if isinstance(joint["at"], list):
            joint["at"] = [joint["at"][0] + dx, joint["at"][1] + dy]
    for section in ("links", "points"):
        for item in data.get(section, {}).values():
            for key in ("center", "at"):
                if isinstance(item.get(key), list) and len(item[key]) == 2:
                    item[key] = [item[key][0] + dx, item[key][1] + dy]
    return assur.io.parse(data)


@pytest.mark.parametrize("name", ["class3", "six_bar_lecture", "whitworth"])
def test_far_from_the_origin_the_loads_are_the_same(name):
    mech = assur.load(EXAMPLES / f"{name}.toml")
    at = np.arange(0.0, 360.0, 30.0) + assur.forces(mech, [0.0])["angle"][0] * 0.0
    near = assur.forces(mech, at, skip_unassembled=True)
    far = assur.forces(moved(mech, 7e4, -3e4), at, skip_unassembled=True)
    assert len(far) == len(near)
    size = max(float(np.max(np.abs(near[f"{j.name}.F"]))) for j in mech.joints)
    for column in near.columns:
        if column.endswith((".x", ".y", ".M")) or "shaking.M" in column:
            continue  # positions move; moments about the origin change with them
        values = far[column]
        assert np.isfinite(values[np.isfinite(near[column])]).all(), column
        if near.column(column).unit == "N":
            np.testing.assert_allclose(values, near[column], atol=1e-7 * size)
    np.testing.assert_allclose(
        far["driver.torque"], near["driver.torque"], rtol=1e-6, atol=1e-7 * size
    )


@pytest.mark.parametrize("angle", [1e15, -3.7e17, 1e20, 123456789.25])
def test_huge_crank_angles_are_reduced_exactly(angle):
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    reduced = math.fmod(angle, 360.0)
    far = assur.forces(mech, [angle])
    near = assur.forces(mech, [reduced])
    for column in far.columns:
        if column in ("angle", "crank.angle"):
            continue
        np.testing.assert_allclose(
            far[column], near[column], rtol=1e-12, atol=1e-12, err_msg=column
        )


def test_a_crank_barely_turning_gives_a_finite_check():
    mech = assur.catalog.four_bar()
    for omega in (5e-324, 1e-200, 0.0):
        slow = dataclasses.replace(
            mech, drivers=(dataclasses.replace(mech.drivers[0], omega=omega),)
        )
        table = assur.forces(slow, [10.0, 100.0])
        assert np.isfinite(table["driver.torque_check"]).all()
        np.testing.assert_allclose(
            table["driver.torque_check"], table["driver.torque"], atol=1e-12
        )


def test_an_offset_is_nan_only_without_normal_force_whatever_the_scale():
    mech = assur.load(EXAMPLES / "whitworth.toml")
    big = assur.forces(mech, np.arange(0.0, 360.0, 15.0))
    small = assur.forces(
        assur.io.parse(scaled(mech, 1e-6)), np.arange(0.0, 360.0, 15.0)
    )
    for joint in mech.joints:
        if joint.kind == "revolute":
            continue
        name = f"{joint.name}.offset"
        assert np.array_equal(np.isnan(big[name]), np.isnan(small[name])), name
        np.testing.assert_allclose(
            small[name] * 1e6, big[name], rtol=1e-6, atol=1e-9, equal_nan=True
        )


def scaled(mech: assur.Mechanism, factor: float) -> dict:
    """The mechanism file's data with every length times ``factor``: masses kept,
    inertias times factor squared, loads' forces times factor and torques times its
    square, so that every force scales with ``factor`` and every moment with its
    square (a similarity)."""
    data = __import__("tomllib").loads(assur.dumps(mech))

    def point(value):
        if isinstance(value, list) and not isinstance(value[0], str):
            return [value[0] * factor, value[1] * factor]
        if isinstance(value, dict):
            return {**value, "distance": value["distance"] * factor}
        return value

    for joint in data["joints"].values():
        joint["at"] = point(joint["at"])
    for link in data["links"].values():
        if "center" in link:
            link["center"] = point(link["center"])
        if "inertia" in link:
            link["inertia"] *= factor**2
        if "axis" in link:
            link["axis"] = [point(p) for p in link["axis"]]
    for item in data.get("points", {}).values():
        item["at"] = point(item["at"])
    for load in data.get("loads", []):
        if "at" in load:
            load["at"] = point(load["at"])
        if isinstance(load.get("force"), list):
            load["force"] = [f * factor for f in load["force"]]
        elif isinstance(load.get("force"), dict):
            for key in ("x", "y"):
                load["force"][key] = [f * factor for f in load["force"][key]]
        if "torque" in load and not isinstance(load["torque"], dict):
            load["torque"] *= factor**2
    return data


# ------------------------------------------------------------------------------------
# The cost grows with the work, not with the angle


def count_assemblies(monkeypatch) -> list[int]:
    """Count the class III groups' assemblies from now on: calls, and positions."""
    calls = [0, 0]
    original = general.GeneralSolver.assemble

    def counted(self, bodies, n, guess=None, branch=None):
        calls[0] += 1
        calls[1] += n
        return original(self, bodies, n, guess, branch)

    monkeypatch.setattr(general.GeneralSolver, "assemble", counted)
    return calls


def test_a_far_crank_position_costs_what_a_near_one_does(monkeypatch):
    mech = assur.load(EXAMPLES / "class3.toml")
    near = assur.forces(mech, [37.0])
    calls = count_assemblies(monkeypatch)
    far = assur.forces(mech, [36000.0 + 37.0])
    assert calls[0] <= 40, calls[0]
    for column in ("driver.torque", "C.Fx", "E.x"):
        np.testing.assert_allclose(far[column], near[column], rtol=1e-9, atol=1e-12)


def test_a_dense_sweep_takes_about_one_step_a_position(monkeypatch):
    # the positions share their paths from the reference pose (a crank's angles are
    # first brought within half a turn of it): walking each alone would take about
    # 18 steps a position
    mech = assur.load(EXAMPLES / "class3.toml")
    calls = count_assemblies(monkeypatch)
    n = 7200
    assur.kinematics(mech, np.linspace(-360.0, 360.0, n))
    # a walk through 71 anchors, one step on, each step checked by a step back to
    # where it started, then the sweep's own assembly
    assert calls[1] <= 3 * n + 2 * 71, calls[1]


def test_anchors_are_walked_to_once_per_mechanism(monkeypatch):
    from assur.plan import plan_of

    mech = assur.load(EXAMPLES / "class3.toml")
    plan_of(mech).memo.pop("anchors", None)
    at = np.linspace(0.0, 359.0, 500)
    first = assur.kinematics(mech, at, columns=["E.x", "plate.omega"])
    calls = count_assemblies(monkeypatch)
    again = assur.kinematics(mech, at[::-1], columns=["E.x", "plate.omega"])
    # one step from the kept anchors (its prediction checks it: no step back),
    # then the sweep's own assembly
    assert calls[1] == 2 * len(at)
    for name in ("E.x", "plate.omega"):
        np.testing.assert_array_equal(again[name][::-1], first[name])


def two_triads(radius: float) -> assur.Mechanism:
    """The class III example with a copy of its triad (names ending in 2), 0.5 m
    lower and moved to hang on a second crank pin at ``radius`` (m) on the crank."""
    import tomllib

    data = tomllib.loads((EXAMPLES / "class3.toml").read_text(encoding="utf-8"))
    turn = math.radians(30.0)
    pin = np.array([radius * math.cos(turn), radius * math.sin(turn)])
    move = pin - np.array(data["joints"]["B"]["at"])
    for name in ("rod", "plate", "left_rocker", "right_rocker"):
        link = dict(
            data["links"][name], axis=[a + "2" for a in data["links"][name]["axis"]]
        )
        center = link["center"]
        if isinstance(center, dict):
            link["center"] = dict(
                center,
                **{"from": center["from"] + "2", "toward": center["toward"] + "2"},
            )
        else:
            link["center"] = list(np.array(center) + move)
        data["links"][name + "2"] = link
    for name in ("B", "C", "D", "E", "F", "G"):
        joint = data["joints"][name]
        data["joints"][name + "2"] = dict(
            joint,
            links=[x if x in ("ground", "crank") else x + "2" for x in joint["links"]],
            at=list(np.array(joint["at"]) + move),
        )
    return assur.io.parse(data)


def test_a_group_that_fails_leaves_the_others_be():
    # the copy on the farther pin locks over part of the turn; the first triad
    # turns all round, and the error names the one that fails
    mech = two_triads(0.1)
    at = np.linspace(-180.0, 179.0, 360)
    with pytest.raises(assur.AssemblyError, match=r"rod2, plate2") as caught:
        assur.kinematics(mech, at)
    assert "(rod, plate" not in str(caught.value)
    both = assur.kinematics(mech, at, skip_unassembled=True)
    assert len(both.skipped) == 163
    alone = assur.kinematics(assur.load(EXAMPLES / "class3.toml"), both["angle"])
    for name in ("E.x", "E.y", "plate.omega"):
        np.testing.assert_allclose(both[name], alone[name], rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("driver", ["crank", "slider"])
def test_shared_paths_reach_the_poses_of_separate_walks(monkeypatch, driver):
    from assur import _kinematics

    if driver == "crank":
        mech = assur.load(EXAMPLES / "class3.toml")
        at = np.concatenate((np.linspace(-725.0, 725.0, 1001), [37.0, 37.0 + 1e-9]))
    else:  # it assembles from -0.136 m to 0.162 m
        mech = slider_triad()
        at = np.linspace(-0.3, 0.3, 601)
    names = ["E.x", "E.y", "plate.angle"]
    shared = assur.kinematics(mech, at, columns=names, skip_unassembled=True)

    monkeypatch.setattr(_kinematics, "_walk", _kinematics._separate)
    alone = assur.kinematics(mech, at, columns=names, skip_unassembled=True)
    np.testing.assert_array_equal(shared.skipped, alone.skipped)
    assert len(shared) > 250
    for name in names:
        np.testing.assert_allclose(shared[name], alone[name], rtol=0, atol=1e-9)


def slider_triad() -> assur.Mechanism:
    """The class III example with its crank replaced by a slider on a level guide."""
    import tomllib

    data = tomllib.loads((EXAMPLES / "class3.toml").read_text(encoding="utf-8"))
    data["links"]["crank"] = {"mass": 0.1, "center": "B", "inertia": 0.0}
    data["joints"]["O2"] = {
        "kind": "prismatic",
        "links": ["ground", "crank"],
        "at": "B",
        "axis": [1.0, 0.0],
    }
    data["drivers"] = [{"joint": "O2", "omega": 0.5}]
    return assur.io.parse(data)


def test_a_slider_driven_class_III_group_stops_at_its_reach(monkeypatch):
    mech = slider_triad()
    near = assur.forces(mech, [0.0, 0.01])
    assert np.isfinite(near["driver.force"]).all()
    calls = count_assemblies(monkeypatch)
    with pytest.raises(assur.AssemblyError, match="50 m"):
        assur.kinematics(mech, [0.0, 50.0])
    # the continuation stops where the group stops closing, not 50 m away
    assert calls[0] < 200, calls[0]


def test_a_position_too_far_to_walk_to_is_named():
    mech = slider_triad()
    with pytest.raises(assur.ConvergenceError, match="continuation steps"):
        assur.kinematics(mech, [1e6])


# ------------------------------------------------------------------------------------
# No silent NaN


def test_values_that_are_not_finite_without_a_failure_are_named(monkeypatch):
    from assur.groups import _dyad

    original = _dyad.equilibrium

    def broken(plan, bodies, loads):
        record = original(plan, bodies, loads)
        middle = record.reactions[plan.mid.name]
        fx, fy, couple = middle.fx, middle.fy, middle.couple
        fx = np.where(np.arange(np.size(fx)) == 1, np.nan, fx)
        reactions = dict(record.reactions)
        reactions[plan.mid.name] = _dyad.Reaction(fx, fy, couple)
        return dataclasses.replace(record, reactions=reactions)

    monkeypatch.setattr(_dyad, "equilibrium", broken)
    with pytest.warns(
        assur.AssurWarning, match=r"joint C .*not finite at driver position 20 deg"
    ) as caught:
        assur.forces(assur.catalog.slider_crank(), [10.0, 20.0, 30.0])
    assert caught[0].filename == __file__


def test_speeds_out_of_range_are_refused():
    mech = assur.catalog.slider_crank()
    with pytest.raises(assur.UsageError, match=r"omega: .* out of range"):
        assur.forces(mech, [10.0, 20.0], omega=[1e200, 1.0])


def test_warnings_point_at_the_caller():
    with pytest.warns(assur.AssurWarning, match="change point") as caught:
        assur.kinematics(parallelogram(), [270.0])
    assert caught[0].filename == __file__


@pytest.mark.parametrize("scale", [1.0, 1e-200, 1e-160, 1e-300, 1e160, 1e200, 1e300])
def test_the_fast_norm_is_hypot_at_every_scale(scale):
    """assur._vec.norm sums squares where they keep their precision and falls back to
    np.hypot where they would underflow or overflow: within an ulp of np.hypot."""
    from assur._vec import norm

    rng = np.random.default_rng(7)
    x, y = rng.normal(size=(2, 2000)) * scale
    x[::5] = 0.0
    y[::7] = 0.0
    x[1] = np.inf
    y[2] = np.nan
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = norm(x, y)
    want = np.hypot(x, y)
    np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
    finite = np.isfinite(want)
    infinite = ~finite & ~np.isnan(want)
    assert np.array_equal(got[infinite], want[infinite])
    np.testing.assert_allclose(got[finite], want[finite], rtol=4.5e-16, atol=0.0)
    assert norm(3.0, 4.0) == 5.0
    np.testing.assert_allclose(norm(np.array([3.0, 6.0]), 4.0), [5.0, np.hypot(6, 4)])


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_random_triads_follow_one_branch_whatever_the_step(monkeypatch, seed, request):
    # the continuation in steps of 5 degrees assembles the positions that steps of
    # half a degree do, in the same poses: past a rocking crank's limit it neither
    # jumps to another assembly nor gives up early (before the step back checked
    # each step, about one random triad in thirty jumped)
    if "slow" not in (request.config.getoption("markexpr") or ""):
        pytest.skip("sixty random triads: run with -m slow")
    from assur import _kinematics
    from assur.plan import cached_plan

    from .mechanisms import LinkDecor, triad

    rng = np.random.default_rng(seed)
    names = ["C.x", "C.y", "D.x", "D.y", "E.x", "E.y"]
    for _ in range(20):
        moves = {k: tuple(rng.uniform(-0.02, 0.02, 2)) for k in "CDEFG"}
        crank, theta0 = rng.uniform(0.03, 0.09), rng.uniform(0.0, 2.0 * math.pi)
        case = triad(crank, theta0, 10.0, moves, [LinkDecor()] * 5, None, check=False)
        at = float(case.reference[0]) + np.arange(-360.0, 360.01, 0.5)
        tables = []
        for step in (5.0, 0.5):
            monkeypatch.setattr(_kinematics, "CONTINUATION_STEP", math.radians(step))
            cached_plan.cache_clear()  # the anchors belong to the step
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", assur.AssurWarning)
                tables.append(
                    assur.kinematics(
                        case.mechanism, at, columns=names, skip_unassembled=True
                    )
                )
        coarse, fine = tables
        np.testing.assert_array_equal(coarse.skipped, fine.skipped)
        for name in names:
            np.testing.assert_allclose(coarse[name], fine[name], rtol=0, atol=1e-9)


def test_a_mechanism_drawn_in_millimetres_is_warned_of():
    # the exercise's figures copied from the drawing as they are (crank 74, rod 200):
    # every speed would be in mm/s labelled m/s, every inertia force 1000 times too big
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    with pytest.warns(
        assur.AssurWarning, match=r"245\.4 m across.*millimetres"
    ) as caught:
        assur.forces(assur.io.parse(scaled(mech, 1000.0)), [30.0])
    assert caught[0].filename == __file__  # the user's line, not the package's
    # the same mechanism in metres, and one 39 m across (a crane's), are not
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assur.forces(mech, [30.0])
        assur.kinematics(assur.io.parse(scaled(mech, 160.0)), [30.0])


def test_a_mechanism_s_own_warning_is_given_when_it_is_compiled():
    # as docs/conventions.rst says: once per mechanism (its compiled form is kept),
    # again for a mechanism changed in any value
    from assur.plan import cached_plan

    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    cached_plan.cache_clear()
    big = assur.io.parse(scaled(mech, 1000.0))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assur.forces(big, [30.0])
        assur.forces(big, [60.0])
        assur.kinematics(big, [30.0])
        assur.forces(assur.io.parse(scaled(mech, 1001.0)), [30.0])
    said = [str(w.message) for w in caught if "millimetres" in str(w.message)]
    assert len(said) == 2
    assert "245.4 m across" in said[0]
    assert "245.6 m across" in said[1]


@pytest.mark.parametrize(
    ("tie", "digits"), [(3.3075, "3.308"), (364.0575, "364.058"), (0.15625, "0.1562")]
)
def test_a_decimal_tie_is_written_alike_an_ulp_either_side(tie, digits):
    # 0.147 kg * 22.5 m/s^2 = 3.3075 N, the Scotch yoke's crank: an ulp either
    # side of it by the machine's arithmetic, and the note wrote 3.307 on one
    # machine and 3.308 on another (364.057 N and 364.058 N in the tables): now
    # as the tie's own double rounds, on every machine
    from assur._text import number_text
    from assur.explain._tex import num

    spec = f".{len(digits.replace('.', '').lstrip('0'))}g"  # the tie's digits less one
    near = [float(np.nextafter(tie, -np.inf)), tie, float(np.nextafter(tie, np.inf))]
    assert [number_text(v, spec) for v in near] == [digits] * 3
    assert len({num(v) for v in near}) == 1


@pytest.mark.parametrize(("tie", "digits"), [(3.3075, "3.308"), (0.15625, "0.1562")])
def test_the_report_and_the_pictures_write_a_decimal_tie_alike(tie, digits):
    from assur.html._sections import number as html_number
    from assur.plotting._numbers import number as picture_number

    near = [float(np.nextafter(tie, -np.inf)), tie, float(np.nextafter(tie, np.inf))]
    assert [picture_number(v, 4) for v in near] == [digits] * 3
    # the report's 5 digits: a tie of the sixth
    fine = float(f"{tie:.5g}") + 5e-5 * 10.0 ** math.floor(math.log10(tie))
    near = [float(np.nextafter(fine, -np.inf)), fine, float(np.nextafter(fine, np.inf))]
    assert len({html_number(v) for v in near}) == 1
