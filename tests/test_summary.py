"""Summaries of a forces table: ``table.summary()`` and ``assur forces --summary``.

Every value is checked against plain numpy reductions of the table's own columns
(maximum, where it occurs, RMS, mean), the friction losses against the friction
columns and the links' rates, and the efficiency against the energy balance of a
steady cycle; a summary gathered slice by slice equals the summary of the whole.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

import assur
from assur._running import Running
from assur.analysis import default_positions
from assur.cli import main
from assur.summary import Summary, efficiency

from . import oracle
from .mechanisms import steady
from .test_kinetostatics import needs_forces

EXAMPLES = Path(__file__).parent.parent / "examples"
DATA = Path(__file__).parent / "data"


def forces_over_a_turn(mech: assur.Mechanism) -> assur.Table:
    return assur.forces(mech, default_positions(mech, 2.0))


def balancing_names(mech: assur.Mechanism) -> list[str]:
    """Every balancing column: the first driver's, and each driver's with several."""
    out = []
    for i, d in enumerate(mech.drivers):
        what = "torque" if mech.joint(d.joint).kind == "revolute" else "force"
        out += [f"driver.{what}"] if i == 0 else []
        out += [f"{d.joint}.{what}"] if len(mech.drivers) > 1 else []
    return out


def first_largest(values) -> int:
    """The first index of the largest of ``values``, ties but for round-off alike."""
    values = np.asarray(values)
    top = values.max()
    return int(np.argmax(values >= top - 1e-12 * abs(top)))


def _magnitude(table, name: str):
    """Return the size summarised as ``name.max`` (``B.F``, ``guide.M``, ...)."""
    if name == "shaking.F":
        return np.hypot(table["shaking.Fx"], table["shaking.Fy"])
    return np.abs(table[name])


def test_summary_is_numpy_reductions_of_the_table(example):
    if not needs_forces(example):
        pytest.skip("no masses and no loads: nothing to analyse")
    table = forces_over_a_turn(example)
    got = table.summary()
    n = len(table)
    where = table.given[:, 0]
    expected: dict[str, float] = {}
    force = max(float(np.max(table[f"{j.name}.F"])) for j in example.joints)

    def largest(name: str, size: np.ndarray, scale: float) -> None:
        # round-off (below 1e-12 of the largest reaction, times the mechanism's
        # size for a moment) is 0, at the first position
        noise = size.max() <= 1e-12 * force * scale
        expected[f"{name}.max"] = 0.0 if noise else float(size.max())
        expected[f"{name}.at"] = float(where[0 if noise else first_largest(size)])

    for joint in example.joints:
        f = table[f"{joint.name}.F"]
        expected[f"{joint.name}.F.max"] = float(f.max())
        expected[f"{joint.name}.F.at"] = float(where[first_largest(f)])
        expected[f"{joint.name}.F.rms"] = float(np.sqrt(np.mean(f**2)))
        if joint.kind == "prismatic":
            size = np.abs(table[f"{joint.name}.M"])
            largest(f"{joint.name}.M", size, table.plan.scale)
    for part in ("F", "M"):
        size = _magnitude(table, f"shaking.{part}")
        largest(f"shaking.{part}", size, table.plan.scale if part == "M" else 1.0)
    power = 0.0
    powers = np.zeros(n)
    for name in balancing_names(example):
        t = table[name]
        expected[f"{name}.max"] = float(t.max())
        expected[f"{name}.min"] = float(t.min())
        expected[f"{name}.mean"] = float(t.mean())
        expected[f"{name}.rms"] = float(np.sqrt(np.mean(t**2)))
    for i, d in enumerate(example.drivers):
        what = "torque" if example.joint(d.joint).kind == "revolute" else "force"
        name = f"driver.{what}" if i == 0 else f"{d.joint}.{what}"
        power += float(np.mean(table[name] * d.omega))
        powers += table[name] * d.omega
    expected["driver.power.mean"] = power
    expected["driver.power.max"] = float(powers.max())
    expected["driver.power.min"] = float(powers.min())
    rubbing = any(j.friction for j in example.joints)
    assert set(got) >= set(expected)
    assert ("efficiency" in got) == rubbing
    for key, value in expected.items():
        assert got[key] == pytest.approx(value, rel=1e-12, abs=1e-12 * n), key


def test_largest_values_that_tie_but_for_round_off_are_at_the_first():
    # the centred slider-crank's guide force is alike at 41 and 319 deg by
    # symmetry: the two values tie, or differ in their last bit by the machine's
    # arithmetic, and "guide.F.at" was either position by the machine
    from assur._running import Running

    tie = 448.1618614655428
    later = np.nextafter(tie, np.inf)  # the later one larger by an ulp
    running = Running.start(2)
    where = np.array([[319.0, 360.0, 401.0], [319.0, 360.0, 401.0]])
    values = np.array([[tie, 1.0, later], [tie - 1e-6, 1.0, tie]])
    running.add(values, where, None, np.array([2]))
    assert running.at.tolist() == [319.0, 401.0]  # a clear winner stays one
    assert running.top.tolist() == [later, tie]
    # and from one slice to the next: an ulp more later on is no larger
    more = np.array([[np.nextafter(later, np.inf)], [2 * tie]])
    running.add(more, np.array([[500.0], [500.0]]), None, np.array([0]))
    assert running.at.tolist() == [319.0, 500.0]
    # the summary of the whole turn: the first of the two
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    table = assur.forces(mech, np.arange(45.0, 405.0, 1.0))
    guide = np.asarray(table["guide.F"])
    top = guide.max()
    tied = np.flatnonzero(guide >= top - 1e-12 * top)
    assert table["angle"][tied].tolist() == [319.0, 401.0]
    assert table.summary()["guide.F.at"] == 319.0


def test_a_value_that_is_not_a_number_is_neither_largest_nor_smallest():
    from assur._running import Running

    running = Running.start(2)
    where = np.array([[0.0, 10.0, 20.0], [0.0, 10.0, 20.0]])
    values = np.array([[1.0, np.nan, 5.0], [np.nan, np.nan, np.nan]])
    running.add(values, where, np.ones((2, 2, 3)), np.array([2]))
    # argmax took the NaN for the largest and lost 5 at 20 deg; min gave NaN
    assert running.top[0] == 5.0
    assert running.at[0] == 20.0
    assert running.bottom[0] == 1.0
    assert np.isnan(running.total[:, 0]).all()  # the mean says there was one
    assert (running.top[1], running.bottom[1]) == (-np.inf, np.inf)  # none yet
    seven = np.array([[7.0], [2.0]])
    running.add(seven, np.array([[30.0], [30.0]]), np.ones((2, 2, 1)), np.array([0]))
    assert running.top.tolist() == [7.0, 2.0]
    assert running.at.tolist() == [30.0, 30.0]


def test_a_summary_by_slices_is_the_summary_of_the_whole():
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    positions = default_positions(mech, 1.0)
    whole = assur.forces(mech, positions).summary()
    parts = Summary()
    for chunk in np.array_split(positions, [70, 71, 200]):
        parts.add(assur.forces(mech, chunk))
    assert parts.count == len(positions)
    by_slices = parts.result()
    assert list(by_slices) == list(whole)
    for key, value in whole.items():
        assert by_slices[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


@pytest.mark.parametrize(
    "name",
    ["slider_crank_friction", "four_bar_bearings", "slider_crank_locking"],
)
def test_friction_losses_and_efficiency(name):
    mech = steady(assur.load(EXAMPLES / f"{name}.toml"))
    table = forces_over_a_turn(mech)
    got = table.summary()
    total = 0.0
    for joint in mech.joints:
        if not joint.friction:
            assert f"{joint.name}.friction.loss" not in got
            continue
        part = "Mf" if joint.kind == "revolute" else "Ff"
        power = table[f"{joint.name}.{part}"] * oracle.relative_speed(table, joint)
        assert (power <= 1e-12 * np.abs(power).max()).all()
        loss = -float(np.mean(power))
        assert got[f"{joint.name}.friction.loss"] == pytest.approx(loss, rel=1e-12)
        total += loss
    assert got["friction.loss"] == pytest.approx(total, rel=1e-12)
    assert got["friction.loss"] == pytest.approx(
        -float(np.mean(table["friction.power"])), rel=1e-12
    )
    omega = mech.drivers[0].omega
    ideal = float(np.mean(table["driver.torque_ideal"] * omega))
    assert got["driver.power_ideal.mean"] == pytest.approx(ideal, rel=1e-12, abs=1e-9)
    # a steady cycle: inertia does no work, so the motor's work is what the loads
    # take plus what friction loses
    power = got["driver.power.mean"]
    assert power == pytest.approx(ideal + total, rel=1e-9)
    eta = got["efficiency"]
    assert 0.0 <= eta < 1.0
    if abs(ideal) > 1e-6 * power:
        assert eta == pytest.approx(ideal / power, rel=1e-12)
    else:
        assert eta == 0.0


def test_efficiency_by_hand():
    assert efficiency(100.0, 80.0, 20.0) == 0.8
    assert efficiency(20.0, 1e-14, 20.0) == 0.0  # friction is all the driver feeds
    assert math.isnan(efficiency(-5.0, -10.0, 5.0))  # the loads drive the mechanism
    assert math.isnan(efficiency(0.0, 0.0, 0.0))
    assert math.isnan(efficiency(5.0, -10.0, 15.0))  # loads give work back


def test_a_table_of_few_columns_summarises_the_loads_among_them():
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    at = np.arange(0.0, 360.0, 5.0)
    whole = assur.forces(mech, at).summary()
    power = ["driver.power.mean", "driver.power.max", "driver.power.min"]
    for columns, named in [
        (["guide.M"], ["guide.M.max", "guide.M.at", *power]),
        (["shaking.M"], [*power, "shaking.M.max", "shaking.M.at"]),
        (["shaking.Fx"], power),  # the force's size needs both components
        (["shaking.Fx", "shaking.Fy"], [*power, "shaking.F.max", "shaking.F.at"]),
    ]:
        few = assur.forces(mech, at, columns=columns).summary()
        assert list(few) == named, columns
        for key in few:
            assert few[key] == pytest.approx(whole[key], rel=1e-12, abs=1e-12), key


def test_a_couple_of_round_off_is_none():
    # an in-line slider's guide carries no couple: its largest was the round-off's
    # largest, 7e-15 N m, at whichever position that peaked
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    at = np.arange(0.0, 360.0, 1.0)
    table = assur.forces(mech, at)
    couple = np.abs(table["guide.M"])
    assert couple.max() <= 1e-12 * np.max(table["A.F"]) * table.plan.scale
    found = table.summary()
    assert (found["guide.M.max"], found["guide.M.at"]) == (0.0, 0.0)
    # a couple that is there is given as it is, small too (the shaper's slot)
    for name, joint in (("scotch_yoke", "guide"), ("whitworth", "slot")):
        t = assur.forces(assur.load(EXAMPLES / f"{name}.toml"), at)
        largest = np.abs(t[f"{joint}.M"]).max()
        assert largest > 1e-3
        assert t.summary()[f"{joint}.M.max"] == pytest.approx(largest, rel=1e-12)


def test_a_clockwise_crank_s_summary_says_which_sign_drives(capsys, tmp_path):
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    path = tmp_path / "clockwise.toml"
    path.write_text(text.replace("omega = 200.0", "omega = -200.0"), encoding="utf-8")
    table = assur.forces(assur.load(path), np.arange(0.0, 360.0, 1.0))
    # the crank is driven where the balancing torque times its speed is positive
    power = table["driver.torque"] * table["crank.omega"]
    assert np.all(table["crank.omega"] < 0.0)
    assert table.summary()["driver.power.max"] == pytest.approx(power.max())
    assert main(["forces", str(path), "--summary"]) == 0
    said = capsys.readouterr().out.splitlines()[-3:]
    assert said[0] == (
        "  (the crank turns clockwise and torques are counter-clockwise positive:"
    )
    assert main(["forces", str(path), "--summary", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["clockwise"] == ["A"]
    # turning counter-clockwise, the summary needs no word on signs
    assert (
        main(["forces", str(EXAMPLES / "slider_crank_exercise.toml"), "--summary"]) == 0
    )
    assert "clockwise" not in capsys.readouterr().out
    # two cranks, one of them clockwise: that one is named ("the crank" was said)
    text = (EXAMPLES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    first = text.index("omega = 10.0")
    five = tmp_path / "five.toml"
    five.write_text(text[:first] + "omega = -10.0" + text[first + 12 :], "utf-8")
    assert main(["forces", str(five), "--summary"]) == 0
    said = capsys.readouterr().out.splitlines()[-3:]
    assert said[0] == (
        "  (the crank at A turns clockwise and torques are counter-clockwise positive:"
    )
    assert said[1] == (
        "   a torque that drives it is negative; a positive power is work the"
    )


def test_kinematics_and_empty_tables_have_no_summary():
    mech = assur.load(EXAMPLES / "four_bar.toml")
    with pytest.raises(assur.UsageError, match="kinematics table has no forces"):
        assur.kinematics(mech, [0.0, 10.0]).summary()
    with pytest.raises(assur.UsageError, match="no positions"):
        assur.forces(mech, np.zeros(0)).summary()


def test_cli_summary_text_and_json(capsys, tmp_path):
    path = EXAMPLES / "slider_crank_friction.toml"
    assert main(["forces", str(path), "--summary", "--angles", "45:404:1"]) == 0
    text = capsys.readouterr().out
    table = assur.forces(assur.load(path), np.arange(45.0, 405.0, 1.0))
    summary = table.summary()
    lines = text.splitlines()
    assert lines[0].startswith("Summary over 360 positions")
    shown = {line.split()[0]: line.split()[1:] for line in lines[1:]}
    # the values, then what is said of them (no load takes work: efficiency 0; a
    # peak past 360 deg)
    assert shown.pop("(efficiency")[0] == "0:"
    assert "is the crank at" in " ".join(shown.pop("(positions"))
    assert list(shown) == list(summary)
    for key, (value, *_) in shown.items():
        assert float(value) == pytest.approx(summary[key], rel=1e-5, abs=1e-9), key
    assert shown["A.F.max"][1:] == ["N"]
    assert shown["driver.torque.max"][1:] == ["N", "m"]
    assert shown["driver.power.mean"][1:] == ["W"]

    assert (
        main(["forces", str(path), "--summary", "--json", "--angles", "45:404:1"]) == 0
    )
    data = json.loads(capsys.readouterr().out)
    assert data["positions"] == 360
    assert data["summary"] == pytest.approx(summary, rel=1e-15)
    assert data["units"]["A.F.at"] == "deg"
    assert data["notes"][0].startswith("efficiency 0: the loads take no work")

    csv = tmp_path / "t.csv"
    assert main(["forces", str(path), "--summary", "--csv", str(csv)]) == 0
    out = capsys.readouterr().out
    assert "Summary over 360 positions" in out
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 361

    # --json with a file: the summary alone on standard output (the table was
    # printed before it as a second JSON document)
    csv.unlink()
    argv = ["forces", str(path), "--summary", "--json", "--csv", str(csv)]
    assert main(argv) == 0
    captured = capsys.readouterr()
    assert json.loads(captured.out)["summary"] == pytest.approx(summary, rel=1e-15)
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 361
    assert captured.err == f"wrote 360 rows x {len(table.columns)} columns to {csv}\n"


def test_cli_summary_refuses_two_outputs_on_stdout(capsys):
    path = EXAMPLES / "four_bar.toml"
    assert main(["forces", str(path), "--summary", "--csv", "-"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "--csv - and --summary" in err[0]


def test_an_undefined_efficiency_says_why(capsys):
    # "efficiency  nan" with no reason: at 90 deg the load drives the crank
    path = str(EXAMPLES / "slider_crank_friction.toml")
    table = assur.forces(assur.load(path), [90.0])
    summary = table.summary()
    assert summary["driver.power.mean"] < 0.0
    assert math.isnan(summary["efficiency"])
    assert main(["forces", path, "--summary", "--angles", "90"]) == 0
    line = capsys.readouterr().out.splitlines()[-1]
    assert line.split()[:2] == ["efficiency", "undefined"]
    assert line.endswith(
        "(the driver does no net work (mean power <= 0): the loads drive)"
    )
    assert main(["forces", path, "--summary", "--angles", "90", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["efficiency"] is None
    assert data["undefined"] == {"efficiency": line.split("(", 1)[1][:-1]}
    # a defined one has no reason
    assert main(["forces", path, "--summary", "--json"]) == 0
    assert "undefined" not in json.loads(capsys.readouterr().out)


@pytest.mark.parametrize("stop", [360.0, 720.0, -360.0])
def test_a_sweep_ending_a_whole_turn_on_counts_that_pose_once(stop):
    """0:360:10 ends on its first pose again: counted twice, it tipped a shaper's
    mean driver power to -1.50 W (+1.264 W over the cycle, its friction loss) and
    its efficiency to "the loads drive"."""
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    step = 10.0 if stop > 0 else -10.0
    table = assur.forces(mech, np.arange(0.0, stop + step / 2, step))
    closed = table.summary()
    cycle = assur.forces(mech, np.arange(0.0, 360.0 * np.sign(stop), step)).summary()
    assert closed.keys() == cycle.keys()
    for name, value in cycle.items():
        if name.endswith(".at"):
            # equal largest values a half turn apart (the shaking moment's) are
            # told apart by round-off: where it is, the value is the largest
            largest = cycle[name.replace(".at", ".max")]
            row = np.flatnonzero(table["angle"] == closed[name])
            assert _magnitude(table, name[: -len(".at")])[row] == pytest.approx(
                largest, rel=1e-12
            ), name
            continue
        assert closed[name] == pytest.approx(value, rel=1e-12, abs=1e-9), name
    # a sweep that ends short of a whole turn counts every position
    short = assur.forces(mech, np.arange(0.0, 350.0, 10.0))
    powers = short["driver.torque"] * short["crank.omega"]
    assert short.summary()["driver.power.mean"] == pytest.approx(np.mean(powers))


@pytest.mark.parametrize(("stop", "closes"), [(360, True), (350, False)])
def test_the_summary_says_a_closing_pose_is_counted_once(capsys, stop, closes):
    # "Summary over 37 positions" stood over means of 36
    path = EXAMPLES / "slider_crank_friction.toml"
    argv = ["forces", str(path), "--summary", "--angles", f"0:{stop}:10"]
    assert main(argv) == 0
    head = capsys.readouterr().out.splitlines()[0]
    once = ", the closing pose counted once" if closes else ""
    name = assur.load(path).name
    assert head == f"Summary over {stop // 10 + 1} positions{once} ({name})"
    assert main([*argv, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert (data["positions"], data["closes_a_turn"]) == (stop // 10 + 1, closes)


def test_an_ideal_power_of_round_off_is_zero():
    # no load takes work (inertia alone): -1.6e-13 W stood beside a driver's 2564 W
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    summary = assur.forces(mech, np.arange(0.0, 360.0, 1.0)).summary()
    assert summary["driver.power_ideal.mean"] == 0.0
    assert summary["driver.power.mean"] == pytest.approx(summary["friction.loss"])
    assert summary["efficiency"] == 0.0


@pytest.mark.parametrize("friction", [1e-6, 1e-12, 1e-300])
def test_an_efficiency_of_round_off_is_zero_however_small_the_friction(friction):
    # beside a friction of 1e-12 every mean was small, and the round-off of the
    # power without friction (3e-13 W) made an efficiency of 1.2e-5; at 1e-320, 1
    import dataclasses

    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    joints = tuple(
        dataclasses.replace(j, friction=friction) if j.friction else j
        for j in mech.joints
    )
    rubbed = dataclasses.replace(mech, joints=joints)
    summary = assur.forces(rubbed, np.arange(0.0, 360.0, 1.0)).summary()
    assert summary["driver.power_ideal.mean"] == 0.0
    assert summary["friction.loss"] > 0.0
    assert summary["efficiency"] == 0.0


def _speeding(mech: assur.Mechanism, positions, swing: float, mean: float = 200.0):
    """Forces with the crank's speed ``mean + swing sin(phi)`` rad/s (phi, deg)."""
    phi = np.radians(positions)
    omega = mean + swing * np.sin(phi)
    # d omega / dt = d omega / d phi * omega
    epsilon = swing * np.cos(phi) * omega
    return assur.forces(mech, positions, omega=omega, epsilon=epsilon)


@pytest.mark.parametrize("loaded", [False, True])
def test_a_varying_crank_speed_gives_means_over_time(loaded):
    # the means were over the angle: inertia alone took -116 W on average, where
    # over a cycle its work is zero; a motor is rated on the time average
    import dataclasses

    from scipy.integrate import quad

    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    if loaded:
        # a resisting couple on the crank: a load that takes work over a cycle
        brake = assur.Load(link="crank", torque=-50.0)
        mech = dataclasses.replace(mech, loads=(brake,))
    positions = np.arange(0.0, 361.0, 1.0)
    summary = _speeding(mech, positions, 20.0).summary()
    # by hand: the work of a turn over the time it takes, the work on a fine grid
    fine = np.linspace(0.0, 360.0, 14401)
    dense = _speeding(mech, fine, 20.0)
    torque = np.asarray(dense["driver.torque"])
    work = np.trapezoid(torque, np.radians(fine))
    period = quad(lambda p: 1.0 / (200.0 + 20.0 * np.sin(p)), 0.0, 2 * np.pi)[0]
    speed = 200.0 + 20.0 * np.sin(np.radians(fine))
    squares = np.trapezoid(torque**2 / speed, np.radians(fine)) / period
    peak = max(abs(summary["driver.power.max"]), abs(summary["driver.power.min"]))
    assert summary["driver.power.mean"] == pytest.approx(
        work / period, rel=1e-6, abs=1e-9 * peak
    )
    assert abs(work) > 1.0 if loaded else abs(work) < 1e-6 * peak * period
    assert summary["driver.torque.rms"] == pytest.approx(np.sqrt(squares), rel=1e-6)
    # over the positions instead: another number, so the test tells them apart
    torque_1 = np.asarray(_speeding(mech, positions[:-1], 20.0)["driver.torque"])
    assert abs(np.sqrt(np.mean(torque_1**2)) - np.sqrt(squares)) > 1e-4 * np.sqrt(
        squares
    )


def test_a_constant_speed_s_means_are_the_plain_means_to_the_bit():
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    positions = np.arange(0.0, 360.0, 1.0)
    table = assur.forces(mech, positions)
    summary = Summary()
    summary.add(table)
    assert summary.means_over() == ("positions", "")
    values = summary.result()
    power = np.asarray(table["driver.torque"]) * np.asarray(table["crank.omega"])
    assert values["driver.power.mean"] == np.sum(power) / 360


def test_a_crank_that_stops_is_summarised_over_its_positions(capsys, tmp_path):
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    positions = np.arange(0.0, 360.0, 1.0)
    # the speed 20 + 20 sin(phi) reaches 0 at 270 deg: no time share there
    table = _speeding(mech, positions, 20.0, mean=20.0)
    summary = Summary()
    summary.add(table)
    over, why = summary.means_over()
    assert over == "positions"
    assert why.startswith("the driver's speed reaches 0, turns back or nearly stops")
    power = np.asarray(table["driver.torque"]) * np.asarray(table["crank.omega"])
    assert summary.result()["driver.power.mean"] == pytest.approx(np.mean(power))


@pytest.mark.parametrize(
    ("angles", "part"), [("0:90:1", True), ("0:360:1", False), ("0:359:1", False)]
)
def test_the_summary_says_what_its_numbers_are_of(capsys, angles, part):
    # over part of a turn it printed an efficiency and a mean power as a cycle's;
    # the shaking moment's point was said only in the documentation
    path = EXAMPLES / "four_bar_bearings.toml"
    assert main(["forces", str(path), "--summary", "--angles", angles]) == 0
    out = capsys.readouterr().out
    assert ("not whole turns: means, RMS and efficiency are of these" in out) == part
    moment = next(line for line in out.splitlines() if "shaking.M.max" in line)
    assert moment.endswith("N m (about the origin of the file's coordinates)")
    assert main(["forces", str(path), "--summary", "--angles", angles, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["means_over"] == "positions"
    assert any("not whole turns" in line for line in data.get("notes", [])) == part


CUTTING = Path(__file__).parent / "data" / "edge" / "cutting_steps.toml"


def _slider_x(phi_deg: float) -> float:
    """The cutting file's slider x (m) by hand: crank 0.05, rod 0.2, C at y -0.02."""
    phi = math.radians(phi_deg)
    r, rod, c = 0.05, 0.2, -0.02
    return r * math.cos(phi) + math.sqrt(rod**2 - (c - r * math.sin(phi)) ** 2)


@pytest.mark.parametrize("stop", [359.0, 360.0])
def test_a_load_table_s_step_counts_half_on_each_side(stop):
    # each step counted whole with the value after it: 428.53 W of a turn's 464.2
    mech = assur.load(CUTTING)
    summary = assur.forces(mech, np.arange(0.0, stop + 0.5, 1.0)).summary()
    # the cut alone takes work over a turn (inertia, gravity and the rod's couple
    # give theirs back): 3000 N against the slider's travel from 110 to 250 deg,
    # along +x (the force is along -x)
    work = 3000.0 * (_slider_x(250.0) - _slider_x(110.0))
    mean = work * 100.0 / (2.0 * math.pi)
    assert mean == pytest.approx(464.2, abs=0.05)
    assert summary["driver.power.mean"] == pytest.approx(mean, rel=1e-4)
    assert summary["driver.torque.mean"] == pytest.approx(mean / 100.0, rel=1e-4)


def test_a_peak_just_before_a_step_is_the_summary_s():
    mech = assur.load(CUTTING)
    positions = np.arange(0.0, 360.0, 1.0)
    table = assur.forces(mech, positions)
    summary = table.summary()
    # just before 110 deg the cut is off, just before 250 still on: solved apart
    before = assur.forces(mech, [110.0 - 1e-6, 250.0 - 1e-6])
    for joint in ("A", "B", "C", "guide"):
        largest = max(np.max(table[f"{joint}.F"]), np.max(before[f"{joint}.F"]))
        assert summary[f"{joint}.F.max"] == pytest.approx(largest, rel=1e-6), joint
    torque = np.concatenate([table["driver.torque"], before["driver.torque"]])
    assert summary["driver.torque.max"] == pytest.approx(torque.max(), rel=1e-6)
    assert summary["driver.torque.min"] == pytest.approx(torque.min(), rel=1e-6)
    # the cut's last position before the step back is the largest torque
    assert summary["driver.torque.max"] > np.max(table["driver.torque"])


def test_a_summary_by_slices_across_a_step_is_the_summary_of_the_whole():
    mech = assur.load(CUTTING)
    positions = np.arange(0.0, 360.0, 1.0)
    whole = assur.forces(mech, positions).summary()
    parts = Summary()
    # a slice ends on the step at 110 deg, another starts on the one at 250
    for chunk in np.array_split(positions, [111, 250]):
        parts.add(assur.forces(mech, chunk))
    for key, value in whole.items():
        assert parts.result()[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


@pytest.mark.parametrize(
    ("angles", "coarse"), [("60:420:30", True), ("0:360:1", False)]
)
def test_a_coarse_sweep_says_its_peaks_may_be_missed(capsys, angles, coarse):
    # at 30 deg steps the shaking force's largest read 19.54 N of 21.83 N
    path = EXAMPLES / "four_bar_bearings.toml"
    assert main(["forces", str(path), "--summary", "--angles", angles]) == 0
    out = capsys.readouterr().out
    said = "(positions 30 deg apart: the largest values are those at these positions"
    assert (said in out) == coarse


def test_a_sliding_driver_s_varying_speed_gives_means_over_time():
    # the means were over the positions: 27 % above the time average for a slider
    # pushed from 0.5 to 2.5 m/s
    mech = assur.load(Path(__file__).parent / "data" / "explain" / "slider_driven.toml")
    lo, hi = -0.06, 0.02

    def speeding(s):
        v = 0.5 + 2.0 * (s - lo) / (hi - lo)
        # a = dv/dt = dv/ds * v
        return assur.forces(mech, s, omega=v, epsilon=2.0 / (hi - lo) * v)

    summary = speeding(np.linspace(lo, hi, 2001)).summary()
    fine = np.linspace(lo, hi, 40001)
    table = speeding(fine)
    force = np.asarray(table["driver.force"])
    speed = 0.5 + 2.0 * (fine - lo) / (hi - lo)
    # by hand: the work over the stroke, over the time it takes
    time = np.trapezoid(1.0 / speed, fine)
    assert summary["driver.power.mean"] == pytest.approx(
        np.trapezoid(force, fine) / time, rel=2e-3
    )
    assert summary["driver.force.rms"] == pytest.approx(
        np.sqrt(np.trapezoid(force**2 / speed, fine) / time), rel=2e-3
    )
    plain = np.mean(force * speed)
    assert abs(summary["driver.power.mean"] - plain) > 0.05 * abs(plain)


def test_two_drivers_whose_speeds_vary_say_their_means_are_over_positions(capsys):
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    first = np.arange(0.0, 360.0, 10.0)
    given = np.stack([first, np.full(36, 120.0)], axis=1)
    omega = np.stack([10.0 + np.sin(np.radians(first)), np.full(36, 1.0)], axis=1)
    summary = Summary()
    summary.add(assur.forces(mech, given, omega=omega, epsilon=np.zeros((36, 2))))
    over, why = summary.means_over()
    assert over == "positions"
    assert "several drivers" in why


@pytest.mark.parametrize("offset", [0.5, 0.1])
def test_a_crank_that_nearly_stops_is_summarised_over_its_positions(offset):
    # 100 (1 + sin) rad/s stops at 270 deg: a grid missing it by 0.5 or 0.1 deg gave
    # RMS reactions set by the one position nearest the stop
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    positions = np.arange(offset, 360.0, 1.0)
    table = _speeding(mech, positions, 100.0, mean=100.0)
    summary = Summary()
    summary.add(table)
    assert summary.means_over()[0] == "positions"
    force = np.asarray(table["B.F"])
    assert summary.result()["B.F.rms"] == pytest.approx(np.sqrt(np.mean(force**2)))


def test_a_step_between_positions_is_said_to_be(capsys):
    # steps at 110 and 250 deg between positions (0.25, 1.25, ...) are counted by
    # the positions around them: said, not silent
    path = CUTTING
    assert main(["forces", str(path), "--summary", "--angles", "0.25:360:1"]) == 0
    out = capsys.readouterr().out
    said = "(loads[0].force steps at 110 and 250 deg, between the positions analysed:"
    assert said in out
    assert main(["forces", str(path), "--summary", "--angles", "0:360:1"]) == 0
    assert "between the positions analysed" not in capsys.readouterr().out


def test_a_table_of_few_columns_says_it_counts_a_step_on_one_side():
    mech = assur.load(CUTTING)
    positions = np.arange(0.0, 360.0, 1.0)
    summary = Summary()
    summary.add(assur.forces(mech, positions, columns=["driver.torque"]))
    from assur._summary_notes import notes

    assert any(
        "counts a load table's step on the side after it" in n for n in notes(summary)
    )


def test_a_sweep_near_a_stop_is_summarised_alike_whole_or_by_slices():
    # the "near a stop" cut-off was each slice's: one table was over positions,
    # the same sweep in 6 slices over time (B.F.rms 1145 N against 211 N)
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    positions = np.arange(0.0, 360.0, 1.0)
    table = _speeding(mech, positions, 100.0, mean=100.15)
    whole = table.summary()
    parts = Summary()
    for chunk in np.array_split(positions, 6):
        parts.add(_speeding(mech, chunk, 100.0, mean=100.15))
    assert parts.means_over()[0] == "positions"
    for key, value in whole.items():
        assert parts.result()[key] == pytest.approx(value, rel=1e-12, abs=1e-9), key


def test_positions_left_out_do_not_make_a_turn_look_short(capsys):
    # 340 positions of a turn with 100 to 119 deg left out were said to "cover
    # 360.059 deg, not whole turns"
    mech = assur.load(EXAMPLES / "four_bar_bearings.toml")
    kept = [a for a in np.arange(0.0, 360.0, 1.0) if not 100.0 <= a < 120.0]
    summary = Summary()
    summary.add(assur.forces(mech, kept))
    from assur._summary_notes import notes

    assert summary.covered() == pytest.approx(360.0)
    assert summary.spacing == pytest.approx(1.0)
    assert not any("not whole turns" in n for n in notes(summary))


def test_a_sliding_driver_a_hair_before_a_step_is_not_on_it(tmp_path):
    # a slider's position within 4 ulps of a step was taken as on it, while the
    # table reads it before the step: both halves before, and no word
    text = (
        Path(__file__).parent / "data" / "explain" / "slider_driven.toml"
    ).read_text(encoding="utf-8")
    step = "force = { x = [0.0, 0.0, -50.0, -50.0], y = [0.0, 0.0, 0.0, 0.0], "
    step += 'over = "driver", table = [-0.07, -0.02, -0.02, 0.03] }'
    path = tmp_path / "stepped.toml"
    path.write_text(
        text + f'\n[[loads]]\nlink = "slider"\nat = "guide"\n{step}\n', encoding="utf-8"
    )
    mech = assur.load(path)
    on, hair = -0.02, float(np.nextafter(-0.02, -1.0))
    for given, landed in (([on], True), ([hair], False)):
        summary = Summary()
        summary.add(assur.forces(mech, given))
        assert bool(summary.landed) == landed, given


def test_a_sweep_out_and_back_is_no_closed_turn():
    """0, 90, 0 deg starts and ends at one pose but makes no turn: its means are the
    rows' plain means (taken for a turn, the last row was dropped: -2298.69 W for
    -548.74)."""
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    table = assur.forces(mech, [0.0, 90.0, 0.0])
    power = table["driver.torque"] * table["crank.omega"]
    summary = table.summary()
    assert summary["driver.power.mean"] == pytest.approx(np.mean(power), rel=1e-12)
    assert summary["driver.power.mean"] == pytest.approx(-548.738, abs=1e-3)


@pytest.mark.parametrize("start", [110.0, 250.0])
def test_a_turn_started_anywhere_has_the_same_means(start):
    """A turn of the cutting-load example started where its load steps (110 deg,
    250 deg) has the means of 0:360: 464.18518 W. A step's row counts half on each
    side; off by one column, the start's half was lost (456.92 W, 486.96 W)."""
    mech = assur.load(DATA / "edge" / "cutting_steps.toml")
    whole = assur.forces(mech, np.arange(0.0, 360.5, 1.0)).summary()
    moved = assur.forces(mech, np.arange(start, start + 360.5, 1.0)).summary()
    assert whole["driver.power.mean"] == pytest.approx(464.18518, abs=1e-5)
    for key in ("driver.power.mean", "driver.torque.mean", "driver.torque.rms"):
        assert moved[key] == pytest.approx(whole[key], rel=1e-12), key


def test_an_efficiency_of_0_says_the_loads_take_no_work(capsys):
    # the slider-crank with friction and no working load: all the driver's work
    # goes to friction, and a bare "efficiency 0" read as a fault
    path = str(EXAMPLES / "slider_crank_friction.toml")
    assert main(["forces", path, "--summary", "--angles", "0:360:2"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"efficiency\s+0\n", out)
    assert "(efficiency 0: the loads take no work over the cycle" in out
    # a working load takes work: an efficiency below 1 and nothing said
    path = str(EXAMPLES / "four_bar_bearings.toml")
    assert main(["forces", path, "--summary", "--angles", "0:360:2"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"efficiency\s+0\.\d+", out)
    assert "the loads take no work" not in out


def test_the_cranks_turning_clockwise_are_listed_as_a_sentence():
    from types import SimpleNamespace

    from assur._summary_notes import turning

    three = SimpleNamespace(clockwise=("A", "E", "F"), drivers=3)
    assert turning(three)[0].startswith("the cranks at A, E and F turn clockwise")


def test_a_mean_that_is_round_off_is_plus_zero(capsys):
    # inertia alone does no work over a turn: the means of the driving torque
    # and power were -1.5e-16 N m and -1.5e-15 W here, of the sign and digits of
    # the machine's summation order, printed so by "assur forces --summary"
    path = EXAMPLES / "class3.toml"
    table = assur.forces(assur.load(path), default_positions(assur.load(path), 1.0))
    torque = np.asarray(table["driver.torque"])
    peak = float(np.max(np.abs(torque)))
    assert peak > 0.1
    assert abs(float(np.mean(torque))) < 1e-12 * peak  # round-off only
    got = table.summary()
    for name in ("driver.torque.mean", "driver.power.mean"):
        assert got[name] == 0.0, name
        assert not math.copysign(1.0, got[name]) < 0.0, name
    assert main(["forces", str(path), "--summary"]) == 0
    shown = {
        line.split()[0]: line.split()[1]
        for line in capsys.readouterr().out.splitlines()[1:]
    }
    assert shown["driver.torque.mean"] == shown["driver.power.mean"] == "0"


def test_a_mean_is_kept_where_it_is_more_than_round_off():
    from assur._running import settled_mean

    low, high = np.array([-0.1, -0.1, -0.1]), np.array([0.2, 0.2, 0.2])
    mean = np.array([-1.5e-16, 3e-12, np.nan])
    got = settled_mean(mean, low, high, 1e-12)
    assert got[0] == 0.0
    assert not np.signbit(got[0])
    assert got[1] == 3e-12  # above 1e-12 of 0.2: the mechanism's own
    assert np.isnan(got[2])


def test_a_constant_mean_is_not_past_its_largest_by_round_off():
    # a constant torque over 72 positions: its sum divided by 72 came out one
    # rounding step above the constant, a mean power above the largest
    mech = assur.catalog.slider_crank()
    massless = tuple(
        dataclasses.replace(link, mass=None, center=None, inertia=0.0)
        for link in mech.links
    )
    load = assur.model.Load(link="crank", torque=-3.9655172413793105)
    mech = dataclasses.replace(mech, links=massless, loads=(load,))
    table = assur.forces(mech, np.arange(0.0, 720.0, 10.0))
    got = table.summary()
    for name in ("driver.power", "driver.torque"):
        assert got[f"{name}.min"] <= got[f"{name}.mean"] <= got[f"{name}.max"], name


def test_a_mean_between_its_bounds_is_kept_and_one_past_them_is_clipped():
    from assur._running import settled_mean

    low, high = np.array([1.0, 1.0, 1.0]), np.array([2.0, 2.0, 2.0])
    got = settled_mean(np.array([1.5, np.nextafter(2.0, 3.0), 0.5]), low, high, 1e-12)
    assert list(got) == [1.5, 2.0, 1.0]


def test_a_largest_of_exactly_zero_is_found_where_it_is() -> None:
    # a value that peaks at 0 (a driver's power, no floor): the tie with it is 0
    # itself, and its first position is where the values reach it, not the first
    running = Running.start(1)
    where = np.array([[10.0, 20.0, 30.0]])
    running.add(np.array([[-1.0, 0.0, -2.0]]), where, None, np.array([2]))
    assert running.at[0] == where[0, 1]
    assert running.top[0] == 0.0


def test_a_peak_s_position_past_a_turn_is_read_on_the_crank(capsys):
    # a turn from the four-bar's reference pose runs from 60 to 419 deg, and its
    # peaks were printed "375 deg" with nothing to say that is 15 deg on the crank
    path = str(EXAMPLES / "four_bar.toml")
    assert main(["forces", path, "--summary"]) == 0
    out = capsys.readouterr().out
    at = float(re.search(r"O2\.F\.at\s+(\S+)\s+deg", out).group(1))
    assert not 0.0 <= at < 360.0
    said = f"{at:g} deg is the crank at {at - 360.0:g} deg"
    assert said in out
    # the same peaks found within one turn of 0 deg need no word
    assert main(["forces", path, "--summary", "--angles", "0:359:1"]) == 0
    out = capsys.readouterr().out
    assert float(re.search(r"O2\.F\.at\s+(\S+)\s+deg", out).group(1)) == at - 360.0
    assert "is the crank at" not in out
