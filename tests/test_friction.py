"""Coulomb friction in the joints: checked against an independent solve and by hand.

- The group-by-group solution (each group by Newton's method on its reactions' sizes)
  equals tests/oracle.py's global solve with friction (every link's equations at once,
  one nonlinear system per position) for the bundled examples with friction, a slot
  joint with friction and random mechanisms with random friction.
- Virtual power with the friction power counted balances the balancing load; friction
  only takes power; each revolute reaction is tangent to its friction circle and each
  friction load opposes its joint's relative motion; zero friction is the frictionless
  table exactly.
- By hand: a block pushed up and down an incline (the worked example of Khurmi and
  Gupta's chapter on friction), a collar on a loose shaft (a friction-circle problem
  of Hibbeler's Statics with its printed answer), a crank whose bearing alone rubs,
  and the friction-circle construction of a crank, rod and crosshead.
- Self-locking is refused with one line naming the group and the position.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from scipy.optimize import brentq

import assur
from assur.cli import main

from . import oracle
from .conftest import load_example as example
from .mechanisms import any_case, bounded, steady
from .test_kinetostatics import needs_forces

EXAMPLES = Path(__file__).parent.parent / "examples"
RUBBING = ["slider_crank_friction", "four_bar_bearings", "slider_crank_locking"]
RTOL = 1e-9


def with_friction(
    mech: assur.Mechanism, friction: dict[str, float], radius: float | None = None
) -> assur.Mechanism:
    """``mech`` with the friction coefficients ``friction`` by joint (and one journal
    radius, m, for every revolute joint that has none)."""
    joints = []
    for j in mech.joints:
        if j.name in friction:
            r = j.radius if j.radius or j.kind != "revolute" else radius
            j = dataclasses.replace(j, friction=friction[j.name], radius=r)
        joints.append(j)
    return dataclasses.replace(mech, joints=tuple(joints))


# ------------------------------------------------------------------------------------
# The independent solve


def assert_matches_friction_solve(
    mech: assur.Mechanism, table: assur.Table, raises: int = oracle.RAISES
) -> None:
    force, size = oracle.load_scale(mech, table)
    expected, friction = oracle.global_solve_friction(mech, table, raises)
    got = oracle.table_reactions(mech, table)
    oracle.assert_same_reactions(mech, got, expected, RTOL, force, size)
    for joint in mech.joints:
        if joint.friction:
            part = "Mf" if joint.kind == "revolute" else "Ff"
            scale = force * (size if part == "Mf" else 1.0)
            np.testing.assert_allclose(
                table[f"{joint.name}.{part}"],
                friction[joint.name],
                rtol=0,
                atol=RTOL * scale,
                err_msg=f"{joint.name}.{part}",
            )


@pytest.mark.parametrize("name", RUBBING)
def test_examples_match_the_global_solve_with_friction(name):
    mech = example(name)
    table = assur.forces(mech, np.arange(0.0, 360.0, 10.0), skip_unassembled=True)
    assert len(table) == 36
    assert_matches_friction_solve(mech, table)


def test_slot_friction_matches_the_global_solve():
    mech = example("slot_mechanism")
    rubbing = {j.name: 0.15 for j in mech.joints}
    mech = with_friction(mech, rubbing, radius=0.01)
    assert {j.kind for j in mech.joints} >= {"slot"}
    table = assur.forces(mech, np.arange(0.0, 360.0, 15.0))
    slots = [j.name for j in mech.joints if j.kind == "slot"]
    assert all(np.abs(table[f"{s}.Ff"]).max() > 0 for s in slots)
    assert_matches_friction_solve(mech, table)


@bounded(12)
@given(
    case=any_case(),
    coefficients=st.lists(st.floats(0.0, 0.25), min_size=12, max_size=12),
    radius=st.floats(0.002, 0.03),
)
def test_random_mechanisms_match_the_global_solve(case, coefficients, radius):
    mech = case.mechanism
    assume(needs_forces(mech))
    mech = with_friction(
        mech,
        {j.name: f for j, f in zip(mech.joints, coefficients, strict=False)},
        radius,
    )
    positions, _ = case.path(7)
    try:
        table = assur.forces(mech, positions)
    except assur.SelfLockingError:
        assume(False)
    assert_matches_friction_solve(mech, table)


# ------------------------------------------------------------------------------------
# Invariants


@pytest.mark.parametrize("name", RUBBING)
def test_virtual_power_balances_with_the_friction_power(name):
    mech = example(name)
    table = assur.forces(mech, np.arange(0.0, 360.0, 2.0))
    force, size = oracle.load_scale(mech, table)
    np.testing.assert_allclose(
        table["driver.torque_check"],
        table["driver.torque"],
        rtol=0,
        atol=RTOL * force * size,
    )
    # friction changes the balancing load: the check is not the frictionless one
    assert np.abs(table["driver.torque"] - table["driver.torque_ideal"]).max() > 1e-3


@pytest.mark.parametrize("name", RUBBING)
def test_friction_takes_power_and_sits_on_its_circle(name):
    mech = example(name)
    table = assur.forces(mech, np.arange(0.0, 360.0, 2.0))
    total = np.zeros(len(table))
    for joint in mech.joints:
        if not joint.friction:
            continue
        f = joint.friction
        speed = oracle.relative_speed(table, joint)
        # a pair at rest (its relative speed rounding) has no friction: kinetic only
        moving = np.abs(speed) > 1e-9 * np.abs(speed).max()
        assert (~moving).sum() <= 4, joint.name
        if joint.kind == "revolute":
            couple = table[f"{joint.name}.Mf"]
            # the reaction is tangent to the friction circle of radius f r
            size = f * joint.radius * table[f"{joint.name}.F"]
            np.testing.assert_allclose(
                np.abs(couple[moving]), size[moving], rtol=0, atol=1e-10 * size.max()
            )
            power = couple * speed
        else:
            ff = table[f"{joint.name}.Ff"]
            # |R|^2 = N^2 + Ff^2 and |Ff| = f |N|
            size = f * table[f"{joint.name}.F"] / math.hypot(1.0, f)
            np.testing.assert_allclose(
                np.abs(ff[moving]), size[moving], rtol=0, atol=1e-10 * size.max()
            )
            power = ff * speed
        assert (power[moving] < 0.0).all(), joint.name
        assert (np.abs(power[~moving]) <= 1e-9 * np.abs(power).max()).all()
        total += power
    assert (table["friction.power"] <= 0.0).all()
    np.testing.assert_allclose(
        table["friction.power"], total, rtol=1e-12, atol=1e-12 * np.abs(total).max()
    )


def test_zero_friction_is_the_frictionless_table_exactly():
    plain = example("slider_crank_exercise")
    zero = with_friction(plain, {j.name: 0.0 for j in plain.joints}, radius=0.01)
    angles = np.arange(0.0, 360.0, 5.0)
    a, b = assur.forces(plain, angles), assur.forces(zero, angles)
    assert a.columns == b.columns
    for name in a.columns:
        assert np.array_equal(a[name], b[name], equal_nan=True), name


def test_friction_tends_to_the_frictionless_table():
    mech = example("slider_crank_friction")
    plain = with_friction(mech, {j.name: 0.0 for j in mech.joints})
    angles = np.arange(0.0, 360.0, 5.0)
    ideal = assur.forces(plain, angles)
    for scale in (1e-3, 1e-6):
        tiny = with_friction(
            mech, {j.name: j.friction * scale for j in mech.joints if j.friction}
        )
        table = assur.forces(tiny, angles)
        np.testing.assert_allclose(
            table["driver.torque_ideal"], ideal["driver.torque"], rtol=1e-12, atol=1e-9
        )
        gap = np.abs(table["driver.torque"] - ideal["driver.torque"]).max()
        # friction loads are first order in f
        assert gap <= 20.0 * scale * np.abs(ideal["driver.torque"]).max()
        assert gap > 0.0


# ------------------------------------------------------------------------------------
# By hand


def incline(weight: float, mu: float, degrees: float, speed: float) -> assur.Mechanism:
    """A block of ``weight`` (N) driven along an incline by a force along it."""
    a = math.radians(degrees)
    return assur.loads(
        f"""
        name = "block on an incline"
        [gravity]
        g = [0.0, -9.81]
        [links.block]
        mass = {weight / 9.81!r}
        center = [0.0, 0.0]
        inertia = 0.0
        [joints.slope]
        kind = "prismatic"
        links = ["ground", "block"]
        at = [0.0, 0.0]
        axis = [{math.cos(a)!r}, {math.sin(a)!r}]
        friction = {mu!r}
        [[drivers]]
        joint = "slope"
        omega = {speed!r}
        """
    )


def test_a_block_pushed_up_an_incline_as_in_the_textbook():
    """Khurmi and Gupta, Theory of Machines, chapter Friction: an effort of 1500 N
    along a 12 deg incline moves a body up it, 1720 N at 15 deg; the printed answers
    are W = 4462 N and mu = 0.131. Back: P = W (sin a + mu cos a)."""
    for degrees, printed in ((12.0, 1500.0), (15.0, 1720.0)):
        table = assur.forces(incline(4462.0, 0.131, degrees, 0.5), [0.0, 0.3])
        # the book's W and mu are rounded to four and three digits
        assert table["driver.force"] == pytest.approx(printed, rel=1e-3)
    for degrees in (0.0, 12.0, 30.0):
        a = math.radians(degrees)
        for speed in (0.5, -0.5):
            table = assur.forces(incline(4462.0, 0.131, degrees, speed), [0.0])
            push = 4462.0 * (
                math.sin(a) + 0.131 * math.cos(a) * math.copysign(1, speed)
            )
            assert table["driver.force"][0] == pytest.approx(push, rel=1e-12)
            assert table["slope.Ff"][0] == pytest.approx(
                -math.copysign(0.131 * 4462.0 * math.cos(a), speed), rel=1e-12
            )
            assert table["driver.force_ideal"][0] == pytest.approx(
                4462.0 * math.sin(a), rel=1e-12, abs=1e-9
            )


def test_a_block_lifted_off_its_guide_rubs_on_the_guide_s_other_face():
    """An upward pull P above the block's weight W: the guide holds it down with
    N = W - P < 0, and the friction is f |W - P| against the motion all the same
    (a mutation that dropped the size's absolute value went unseen)."""
    weight, pull, mu = 100.0, 250.0, 0.2
    text = (
        assur.dumps(incline(weight, mu, 0.0, 0.5))
        + f'\n[[loads]]\nlink = "block"\nat = [0.0, 0.0]\nforce = [0.0, {pull!r}]\n'
    )
    for speed in (0.5, -0.5):
        mech = assur.loads(text.replace("omega = 0.5", f"omega = {speed!r}"))
        table = assur.forces(mech, [0.0, 0.1])
        drag = mu * abs(weight - pull) * math.copysign(1.0, speed)
        np.testing.assert_allclose(table["slope.Ff"], -drag, rtol=1e-12)
        np.testing.assert_allclose(table["driver.force"], drag, rtol=1e-12)
        # the guide's reaction: the friction along it and N = W - P across it
        np.testing.assert_allclose(table["slope.Fy"], weight - pull, rtol=1e-12)


def crank_alone(mass: float, offset: float, omega: float, f: float, r: float, g: float):
    return assur.loads(
        f"""
        name = "a crank in its bearing"
        [gravity]
        g = [0.0, {-g!r}]
        [links.crank]
        mass = {mass!r}
        center = [{offset!r}, 0.0]
        inertia = 0.01
        [joints.A]
        kind = "revolute"
        links = ["ground", "crank"]
        at = [0.0, 0.0]
        friction = {f!r}
        radius = {r!r}
        [[drivers]]
        joint = "A"
        omega = {omega!r}
        """
    )


def test_a_crank_bearing_alone():
    """A balanced crank under its weight: the bearing carries m g and the motor
    overcomes f r m g; an unbalanced one at speed without weight: m w^2 e."""
    angles = np.arange(0.0, 360.0, 30.0)
    for omega in (10.0, -10.0):
        table = assur.forces(crank_alone(3.0, 0.0, omega, 0.1, 0.02, 9.81), angles)
        torque = 0.1 * 0.02 * 3.0 * 9.81 * math.copysign(1.0, omega)
        np.testing.assert_allclose(table["driver.torque"], torque, rtol=1e-12)
        np.testing.assert_allclose(table["A.Mf"], -torque, rtol=1e-12)
        np.testing.assert_allclose(table["A.F"], 3.0 * 9.81, rtol=1e-12)
        np.testing.assert_allclose(table["driver.torque_ideal"], 0.0, atol=1e-12)
    table = assur.forces(crank_alone(2.0, 0.05, 20.0, 0.2, 0.015, 0.0), angles)
    pull = 2.0 * 20.0**2 * 0.05
    np.testing.assert_allclose(table["A.F"], pull, rtol=1e-12)
    np.testing.assert_allclose(table["driver.torque"], 0.2 * 0.015 * pull, rtol=1e-12)
    power = table["driver.torque"] * 20.0
    np.testing.assert_allclose(table["friction.power"], -power, rtol=1e-12)


def collar(push: float, mu: float) -> assur.Mechanism:
    """A collar loose on a fixed shaft of radius 2, turned by a belt wrapped on it at
    radius 2.25: 20 down on the left, ``push`` to the right on top (lb and in; the
    equations are homogeneous in the units). A loose journal of coefficient ``mu``
    has its friction circle at r sin(atan mu), so its ``friction`` is that sine."""
    return assur.loads(
        f"""
        [links.collar]
        [joints.O]
        kind = "revolute"
        links = ["ground", "collar"]
        at = [0.0, 0.0]
        friction = {mu / math.sqrt(1.0 + mu * mu)!r}
        radius = 2.0
        [[drivers]]
        joint = "O"
        omega = 1.0
        [[loads]]
        link = "collar"
        at = [-2.25, 0.0]
        force = [0.0, -20.0]
        [[loads]]
        link = "collar"
        at = [0.0, 2.25]
        force = [{push!r}, 0.0]
        """
    )


def test_a_collar_on_a_loose_shaft_as_in_the_textbook():
    """Hibbeler, Engineering Mechanics: Statics and Dynamics, 14th ed., problem 8-116:
    the belt force P that turns the collar counterclockwise at constant speed,
    mu_k = 0.3 (friction circle r_f = 2 sin 16.699 deg = 0.5747 in); printed answer
    P = 13.8 lb.

    No motor drives the collar: P is where the balancing torque vanishes.
    """
    mu = 0.3

    def torque(push: float) -> float:
        return float(assur.forces(collar(push, mu), [0.0])["driver.torque"][0])

    push = brentq(torque, 0.0, 40.0, xtol=1e-13)
    assert push == pytest.approx(13.8, abs=0.05)
    # the book's moment equation about the shaft: the reaction on the friction circle
    circle = 2.0 * math.sin(math.atan(mu))
    assert circle == pytest.approx(0.5747, abs=5e-5)
    assert 20.0 * 2.25 - push * 2.25 == pytest.approx(
        circle * math.hypot(push, 20.0), rel=1e-10
    )
    table = assur.forces(collar(push, mu), [0.0])
    assert table["O.F"][0] == pytest.approx(math.hypot(push, 20.0), rel=1e-12)
    assert table["O.Mf"][0] == pytest.approx(-circle * table["O.F"][0], rel=1e-12)
    # without friction the belt's two ends pull alike
    ideal = assur.forces(collar(20.0, mu), [0.0])["driver.torque_ideal"][0]
    assert ideal == pytest.approx(0.0, abs=1e-12)


def eccentric(f: float, omega: float) -> assur.Mechanism:
    """Crank OC = 8, rod CP = 80 at crank angle 60 deg, a load of 6 along the stroke
    pulling the crosshead away, journal radii 7 at O, 15 at C (an eccentric sheave) and
    4.4 at P, frictionless guide (a friction-circle exercise in inch-tons)."""
    c = (8.0 * math.cos(math.radians(60.0)), 8.0 * math.sin(math.radians(60.0)))
    p = c[0] + math.sqrt(80.0**2 - c[1] ** 2)
    return assur.loads(
        f"""
        [links.crank]
        axis = ["O", "C"]
        [links.rod]
        [links.crosshead]
        [joints.O]
        kind = "revolute"
        links = ["ground", "crank"]
        at = [0.0, 0.0]
        friction = {f!r}
        radius = 7.0
        [joints.C]
        kind = "revolute"
        links = ["crank", "rod"]
        at = [{c[0]!r}, {c[1]!r}]
        friction = {f!r}
        radius = 15.0
        [joints.P]
        kind = "revolute"
        links = ["rod", "crosshead"]
        at = [{p!r}, 0.0]
        friction = {f!r}
        radius = 4.4
        [joints.guide]
        kind = "prismatic"
        links = ["ground", "crosshead"]
        at = [{p!r}, 0.0]
        axis = [1.0, 0.0]
        [[drivers]]
        joint = "O"
        omega = {omega!r}
        [[loads]]
        link = "crosshead"
        at = "P"
        force = [6.0, 0.0]
        """
    )


# the textbook's figures are without units (crank 8, rod 80): 83.7 "m" across
@pytest.mark.filterwarnings("ignore:joints. the mechanism is .* m across")
def test_the_friction_circle_construction():
    """The rod, a two-force member, carries its force along the line tangent to the
    friction circles (radii f r) of its two pins, crossing between them: inclined by
    asin(f (rC + rP) / CP) to the rod's centre line. The crank's torque is that force
    times its distance from O, shifted by the friction circles at C and O.

    With the load driving the crank (crank turning clockwise) friction lowers the
    torque the crank can give: 36.744 against 43.656 (efficiency 0.842); with the
    crank driving against the load it raises it to 50.581.
    """
    f, theta, crank, rod, load = 0.05, math.radians(60.0), 8.0, 80.0, 6.0
    phi = math.asin(crank * math.sin(theta) / rod)
    alpha = math.asin(f * (15.0 + 4.4) / rod)
    ideal = load / math.cos(phi) * crank * math.sin(theta + phi)
    driven = (
        load
        / math.cos(phi - alpha)
        * (crank * math.sin(theta + phi - alpha) - f * (15.0 + 7.0))
    )
    driving = (
        load
        / math.cos(phi + alpha)
        * (crank * math.sin(theta + phi + alpha) + f * (15.0 + 7.0))
    )
    assert driven / ideal == pytest.approx(0.842, abs=5e-4)
    for omega, expected in ((-1.0, driven), (1.0, driving)):
        table = assur.forces(eccentric(f, omega), [60.0])
        assert table["driver.torque"][0] == pytest.approx(expected, rel=1e-12)
        assert table["driver.torque_ideal"][0] == pytest.approx(ideal, rel=1e-12)


# ------------------------------------------------------------------------------------
# Self-locking


def locking(f: float) -> assur.Mechanism:
    mech = example("slider_crank_locking")
    pins = {j.name: 0.0 for j in mech.joints if j.kind == "revolute"}
    return with_friction(mech, {**pins, "guide": f})


def lean(table: assur.Table) -> np.ndarray:
    """The rod's angle to the guide (rad)."""
    dx = table["C.x"] - table["B.x"]
    dy = table["C.y"] - table["B.y"]
    return np.arctan2(np.abs(dy), np.abs(dx))


def test_self_locking_is_refused_by_name():
    angles = np.arange(0.0, 360.0, 5.0)
    with pytest.raises(assur.SelfLockingError) as caught:
        assur.forces(locking(1.3), angles)
    text = str(caught.value)
    assert "\n" not in text
    assert "group RRP (rod, slider)" in text
    assert "driver position 250 deg" in text
    # where the mechanism locks, the guide's friction outgrows the rod's push along it
    table = assur.forces(locking(1.3), angles, skip_unassembled=True)
    kept = set(table.given[:, 0].tolist())
    locked = np.array([a for a in angles if a not in kept])
    # the return stroke's steepest leans; at the dead centres the slider is at rest,
    # which friction does not lock
    assert locked.tolist() == list(range(250, 295, 5))
    everything = assur.kinematics(locking(1.3), angles)
    leans = dict(zip(angles.tolist(), lean(everything), strict=True))
    assert all(1.3 * math.tan(leans[a]) >= 1.0 for a in locked)
    # and it does not lock where friction cannot hold the push
    assert all(1.3 * math.tan(leans[a]) < 1.0 for a in kept if leans[a] < 0.6)
    # less friction than 1 / tan(largest lean) runs the whole turn
    assert len(assur.forces(locking(1.0), angles)) == len(angles)


def test_self_locking_on_the_command_line(tmp_path, capsys):
    path = tmp_path / "locked.toml"
    path.write_text(assur.dumps(steady(locking(1.3))), encoding="utf-8")
    assert main(["forces", str(path), "--angles", "0:355:5"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1
    assert "locks it at driver position 250 deg" in err[0]
    status = main(["forces", str(path), "--angles", "0:355:5", "--skip-unassembled"])
    assert status == 0
    assert "left out 9 positions" in capsys.readouterr().err


def test_a_joint_at_rest_has_a_friction_of_plus_zero():
    # the law's sign of a speed of 0 made "-0.0" in JSON for a crank at rest
    m = assur.load(EXAMPLES / "slider_crank_friction.toml")
    t = assur.forces(m, [60.0, 0.0], omega=[0.0, 5.0], epsilon=[10.0, 0.0])
    names = [c for c in t.columns if c.endswith((".Mf", ".Ff"))]
    assert len(names) == 4
    at_rest = np.array([t[name][0] for name in names])
    assert (at_rest == 0.0).all()
    assert not np.signbit(at_rest).any()
    assert t["guide.Ff"][1] == 0.0  # at the dead centre the slider is at rest
    assert not np.signbit(t["guide.Ff"][1])
    written = t.to_dict()["rows"][0]
    assert all(repr(written[name]) == "0.0" for name in names)


def test_a_journal_of_radius_zero_has_no_friction_couple():
    # the file format allows radius >= 0: a pin of radius 0 has a friction circle of
    # radius 0, so the joint carries no couple, as if it had no friction (a radius
    # of 0 was refused as missing)
    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")

    def joint_a(**change):
        return dataclasses.replace(
            mech,
            joints=tuple(
                dataclasses.replace(j, **change) if j.name == "A" else j
                for j in mech.joints
            ),
        )

    at = np.arange(0.0, 360.0, 30.0)
    pin = assur.forces(joint_a(radius=0.0), at)
    smooth = assur.forces(joint_a(friction=0.0, radius=None), at)
    np.testing.assert_array_equal(pin["A.Mf"], 0.0)
    np.testing.assert_allclose(
        pin["driver.torque"], smooth["driver.torque"], atol=1e-12
    )
    with pytest.raises(assur.ModelError, match="needs its journal 'radius'"):
        joint_a(radius=None)


def test_a_lock_is_counted_over_every_slice(monkeypatch):
    # the message counted the positions of the first slice the group locked in
    import re

    from assur import _state

    monkeypatch.setattr(_state, "CHUNK", 8192)
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    mech = assur.loads(text.replace("friction = 0.8", "friction = 1.3"))
    # 36000 positions: slices of 8192 (81.92 deg), one of them ending at 270 deg
    angles = 24.24 + np.arange(36000) * 0.01
    kept = assur.forces(mech, angles, skip_unassembled=True)
    with pytest.raises(assur.SelfLockingError) as raised:
        assur.forces(mech, angles)
    count = re.search(r"\((\d+) of 36000 positions\)", str(raised.value))
    assert count is not None
    assert int(count.group(1)) == len(kept.skipped)
    # the return stroke locks from 246.15 to 295.6 deg: in two slices
    assert kept.skipped.min() < 270.0 < kept.skipped.max()


FRICTION_DATA = Path(__file__).parent / "data" / "friction"


def _locking(coefficient: float) -> assur.Mechanism:
    """The example near self-locking, its guide's friction set to ``coefficient``."""
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    return assur.loads(text.replace("friction = 0.8", f"friction = {coefficient}"))


@pytest.mark.parametrize(
    ("coefficient", "angles"),
    [
        # f tan(beta) > 1 with the load helping the motion: Coulomb's law holds
        # twice, and a solve from the frictionless sizes found the jammed one (a
        # torque of 856 N m for -17.75 at 76 deg, with no warning)
        (1.2, [72.0, 76.0, 80.0, 90.0, 100.0, 104.0]),
        (1.3, [68.0, 90.0, 112.0]),
        # where the step's tolerance, relative to the frictionless reactions, was
        # below the rounding of the reactions found (100 times larger): "locked"
        (1.2, [253.4, 253.59999999999994]),
        (1.3, [297.4]),
    ],
)
def test_the_motion_that_grows_from_no_friction(coefficient, angles):
    mech = _locking(coefficient)
    table = assur.forces(mech, angles)
    assert_matches_friction_solve(mech, table)
    # the torque is continuous over the forward stroke (it jumped by 870 N m)
    if angles[0] < 200.0:
        steps = np.diff(
            assur.forces(mech, np.arange(60.0, 121.0, 1.0))["driver.torque"]
        )
        assert np.max(np.abs(steps)) < 1.0


def test_a_prismatic_driver_near_its_jam():
    # the ram's guide (friction 3) wedged: driver.force -45.04 N for 7.464
    mech = assur.load(FRICTION_DATA / "ram_up_a_steep_guide.toml")
    table = assur.forces(mech, [-0.05, 0.0, 0.04])
    assert_matches_friction_solve(mech, table)
    assert table["driver.force"][0] == pytest.approx(7.464, abs=1e-3)


def test_a_huge_coefficient_locks_only_where_the_global_solve_finds_no_motion():
    """A guide's friction of 1e6: where the motion goes on, friction all but
    cancels the guide's normal force, and the jammed solution beside it differs
    by about 1e-6. Newton's method from the frictionless sizes landed on the
    latter, and every position was said to lock; the global solve, raising the
    friction from zero, finds the motion at the positions kept and none where the
    group is said to lock."""
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    start = text.index("[joints.guide]")
    end = text.index("\n\n", start)
    mech = assur.loads(text[:end] + "\nfriction = 1e6" + text[end:])
    angles = np.arange(0.0, 360.0, 20.0)
    table = assur.forces(mech, angles, skip_unassembled=True)
    assert 0 < len(table.skipped) < len(angles)
    assert_matches_friction_solve(mech, table)
    frictionless = assur.forces(example("slider_crank_exercise"), table.skipped)
    for row in range(len(frictionless)):
        with pytest.raises(ValueError, match="did not converge"):
            oracle.global_solve_friction(mech, _rows(frictionless, row))
    with pytest.raises(
        assur.ModelError, match=r"friction: expected a Coulomb .* 1e\+06"
    ):
        assur.loads(text[:end] + "\nfriction = 1.5e6" + text[end:])


def _rows(table: assur.Table, row: int) -> assur.Table:
    """Return the one-position table of ``table``'s mechanism at its row ``row``."""
    return assur.forces(table.mechanism, table.given[row : row + 1, 0])


def test_a_motion_followed_in_finer_steps_is_no_lock():
    # 16 steps of friction left the motion (Newton landed on the jammed solution):
    # "locks at 132 deg", where the motion goes on, as the global solve finds
    mech = assur.load(FRICTION_DATA / "rpp_steep.toml")
    table = assur.forces(mech, [131.0, 132.0, 134.5])
    assert table["driver.torque"][1] == pytest.approx(-16.988, abs=1e-3)
    # the oracle too needs finer steps to stay on the motion here
    assert_matches_friction_solve(mech, table, raises=96)


def test_a_motion_followed_on_from_where_it_held_is_no_lock():
    # at much friction (the slot of rpp_steep x23.7) the second, finer raising
    # started from no friction again and was said to lock at -51.4 deg; followed on
    # from the last friction the first raising held at, it moves, as the global
    # solve finds
    base = assur.load(FRICTION_DATA / "rpp_steep.toml")
    mech = dataclasses.replace(
        base,
        joints=tuple(
            dataclasses.replace(j, friction=j.friction * 23.737027856943964)
            if j.friction
            else j
            for j in base.joints
        ),
    )
    table = assur.forces(mech, [-51.4])
    assert table["driver.torque"][0] == pytest.approx(-80.618, abs=1e-3)
    assert_matches_friction_solve(mech, table, raises=96)


def test_an_assembly_error_names_where_it_assembles_and_where_it_locks():
    """Where a group does not assemble and friction locks it elsewhere, the message
    says where it assembles (locked positions too) and where it locks."""
    mech = assur.load(FRICTION_DATA / "triad_assembles_and_locks.toml")
    at = np.arange(0.0, 361.0, 10.0)
    with pytest.raises(assur.AssemblyError) as raised:
        assur.forces(mech, at)
    message = str(raised.value)
    assert "(12 of 37 positions fail)" in message
    # the sweep is a whole turn: its last run goes on into its first
    assert "it assembles for -120 deg to 110 deg (" in message
    assert message.endswith(
        "(where friction locks it at 0 deg to 110 deg; 260 deg to 310 deg)"
    )
    # the same positions as the kinematics and the skipped force sweep find
    assembles = assur.kinematics(mech, at, skip_unassembled=True)
    assert len(assembles) == 25
    moving = assur.forces(mech, at, skip_unassembled=True)
    locked = np.setdiff1d(assembles["angle"], moving["angle"])
    np.testing.assert_array_equal(
        locked, [*range(0, 111, 10), 260, 270, 280, 290, 300, 310, 360]
    )
