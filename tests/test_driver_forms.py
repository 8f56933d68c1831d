"""Uncommon driver forms against the independent checks of tests/oracle.py.

- A slider and a crank driving one dyad (tests/data/edge/slider_and_crank_one_dyad.toml:
  the first driver prismatic, a load table over it, a load at a point given by
  {from, toward, distance}): rigid links, slides, continuous rows, time differences;
  every reaction and both balancing loads against the oracle's global solve, with
  Coulomb friction in every joint (the drivers' own included) at speeds that vary
  from row to row, stop and turn back; virtual power per driver and the power
  balance with the friction's power.
- Drivers whose acceleration changes (``omega``, ``epsilon`` and ``jerk`` arrays along
  a cubic motion of every driver) on each uncommon form: a prismatic driver, two
  drivers, the RPR, PRP and RPP dyads, a slot, class III triads. Each velocity,
  acceleration and jerk column is the central difference in time of the one below.

Tolerances: the oracle's (1e-9 of the largest load, times the mechanism's size for a
moment; the differences' own truncation error).
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

import assur

from . import oracle
from .mechanisms import any_case, bounded
from .test_friction import assert_matches_friction_solve
from .test_friction import with_friction as rubbing

ROOT = Path(__file__).parent.parent
MIXED = ROOT / "tests" / "data" / "edge" / "slider_and_crank_one_dyad.toml"
RTOL = 1e-9


def mixed_path(count: int, half: float = 0.12) -> tuple[np.ndarray, float]:
    """Positions (slide m, crank deg) of both drivers at their file speeds over
    ``half`` s either side of the reference pose, and the time between rows (s)."""
    t = np.linspace(-half, half, count)
    return np.stack([0.5 * t, 90.0 + np.degrees(5.0 * t)], axis=-1), t[1] - t[0]


def with_friction(mech: assur.Mechanism) -> assur.Mechanism:
    """``mech`` with friction in every joint (a journal of 8 mm in each revolute)."""
    joints = tuple(
        dataclasses.replace(
            j,
            friction=0.12 if j.kind == "revolute" else 0.2,
            radius=0.008 if j.kind == "revolute" else None,
        )
        for j in mech.joints
    )
    return dataclasses.replace(mech, joints=joints)


# ------------------------------------------------------------------------------------
# A slider and a crank


def test_a_slider_and_a_crank_move_rigidly_and_smoothly():
    mech = assur.load(MIXED)
    assert [g.kind for g in assur.structure(mech).groups] == ["RRR"]
    # the file's speeds, at no acceleration: rows along the motion
    steady = dataclasses.replace(
        mech,
        drivers=tuple(dataclasses.replace(d, epsilon=0.0) for d in mech.drivers),
    )
    positions, dt = mixed_path(97)
    table = assur.kinematics(steady, positions)
    np.testing.assert_allclose(table["guide.drive"], positions[:, 0], atol=1e-15)
    np.testing.assert_allclose(table["A.drive"], positions[:, 1], atol=1e-12)
    np.testing.assert_array_equal(table["angle"], table["guide.drive"])
    oracle.assert_rigid(steady, table)
    oracle.assert_slides(steady, table)
    oracle.assert_continuous(table, dt)
    oracle.assert_reference_pose(mech, assur.kinematics(mech, [[0.0, 90.0]]), 0)
    oracle.assert_differences(mech, oracle.si(mech, positions[4:-4:11]))


def test_a_slider_and_a_crank_match_the_global_solve():
    mech = assur.load(MIXED)
    table = assur.forces(mech, mixed_path(41)[0])
    force, size = oracle.load_scale(mech, table)
    expected = oracle.global_solve(mech, table)
    got = oracle.table_reactions(mech, table)
    oracle.assert_same_reactions(mech, got, expected, RTOL, force, size)
    residuals = oracle.link_residuals(mech, table, got)
    for link in (lk.name for lk in mech.links):
        f, m = residuals[link]
        assert np.max(np.abs(f)) <= RTOL * force, link
        assert np.max(np.abs(m)) <= RTOL * force * size, link
    np.testing.assert_array_equal(table["driver.force"], table["guide.force"])


def varying_speeds(count: int) -> tuple[np.ndarray, np.ndarray]:
    """Speeds (m/s, rad/s) and accelerations of the two drivers, row by row: both
    turn back at some rows, one at rest at another, both at rest at the last."""
    k = np.arange(count)
    omega = np.stack([0.5 * np.cos(0.9 * k), 5.0 * np.sin(0.7 * k + 0.3)], axis=-1)
    omega[3, 0] = 0.0
    omega[-1] = 0.0
    epsilon = np.stack([-2.0 + 0.3 * k, 30.0 * np.cos(k)], axis=-1)
    return omega, epsilon


def test_a_slider_and_a_crank_with_friction_match_the_global_solve():
    """Friction in every joint at speeds that change from row to row: reactions,
    friction loads and balancing loads are the oracle's Newton solve's; each
    driver's load balances the virtual power, and all loads' powers, friction's
    included, balance at the real speeds."""
    mech = with_friction(assur.load(MIXED))
    positions = mixed_path(13)[0]
    omega, epsilon = varying_speeds(len(positions))
    table = assur.forces(mech, positions, omega=omega, epsilon=epsilon)
    force, size = oracle.load_scale(mech, table)
    expected, friction = oracle.global_solve_friction(mech, table)
    got = oracle.table_reactions(mech, table)
    oracle.assert_same_reactions(mech, got, expected, RTOL, force, size)
    for joint in mech.joints:
        part = "Mf" if joint.kind == "revolute" else "Ff"
        np.testing.assert_allclose(
            table[f"{joint.name}.{part}"],
            friction[joint.name],
            rtol=0,
            atol=RTOL * force * (size if part == "Mf" else 1.0),
            err_msg=f"{joint.name}.{part}",
        )
    # at rest, no friction; moving, some
    assert not np.any(table["friction.power"][-1])
    assert np.all(table["friction.power"][:-1] < 0.0)
    power = sum(oracle.applied_loads(mech, table).power.values())
    power = power + table["friction.power"]
    for i in range(len(mech.drivers)):
        check = oracle.balancing_column(mech, table, i, check=True)
        main = oracle.balancing_column(mech, table, i)
        np.testing.assert_allclose(check, main, rtol=0, atol=RTOL * force * size)
        power = power + main * omega[:, i]
    speed = float(np.max(np.abs(omega[:, 1])))
    np.testing.assert_allclose(power, 0.0, atol=RTOL * force * size * speed)


@bounded(12)
@given(
    case=any_case(),
    coefficients=st.lists(st.floats(0.0, 0.25), min_size=12, max_size=12),
    data=st.data(),
)
def test_random_friction_at_speeds_that_vary_row_by_row(case, coefficients, data):
    """Random mechanisms of every builder (prismatic driver, two cranks, slots,
    triads) with friction, each row at its own speeds: some drivers stopped, some
    turned back. Friction follows each row's relative speeds, as the global solve
    has it."""
    mech = case.mechanism
    assume(any(link.mass for link in mech.links) or mech.loads)
    friction = dict(zip((j.name for j in mech.joints), coefficients, strict=False))
    mech = rubbing(mech, friction, 0.01)
    positions, _ = case.path(6)
    count = len(mech.drivers)
    factors = st.sampled_from([-1.8, -0.6, 0.0, 0.4, 1.0, 2.5])
    scale = np.array(
        data.draw(st.lists(factors, min_size=6 * count, max_size=6 * count))
    )
    omega = scale.reshape(6, count) * [d.omega for d in mech.drivers]
    epsilon = np.array(
        data.draw(
            st.lists(st.floats(-50.0, 50.0), min_size=6 * count, max_size=6 * count)
        )
    ).reshape(6, count)
    epsilon *= [
        1.0 if mech.joint(d.joint).kind == "revolute" else 0.01 for d in mech.drivers
    ]
    if count == 1:
        omega, epsilon = omega[:, 0], epsilon[:, 0]
    try:
        table = assur.forces(mech, positions, omega=omega, epsilon=epsilon)
    except assur.SelfLockingError:
        assume(False)
    assert_matches_friction_solve(mech, table)


# ------------------------------------------------------------------------------------
# Drivers whose acceleration changes

FORMS = {
    "slider_and_crank": (MIXED, [(-0.04, 80.0), (0.03, 110.0)]),
    "five_bar_two_cranks": (
        ROOT / "examples" / "five_bar_two_cranks.toml",
        [(10.0, 200.0), (250.0, 40.0)],
    ),
    "slider_driven": (
        ROOT / "tests" / "data" / "explain" / "slider_driven.toml",
        [(-0.05,), (0.12,)],
    ),
    "whitworth": (ROOT / "examples" / "whitworth.toml", [(40.0,), (250.0,)]),
    "scotch_yoke": (ROOT / "examples" / "scotch_yoke.toml", [(10.0,), (200.0,)]),
    "slot_mechanism": (ROOT / "examples" / "slot_mechanism.toml", [(0.0,), (130.0,)]),
    "rpp": (ROOT / "tests" / "data" / "friction" / "rpp_steep.toml", [(5.0,), (95.0,)]),
    "prp": (
        ROOT / "tests" / "data" / "explain" / "prp_tangent.toml",
        [(20.0,), (40.0,)],
    ),
    "class3": (ROOT / "examples" / "class3.toml", [(60.0,), (300.0,)]),
    "triad_with_a_slider": (
        ROOT / "tests" / "data" / "edge" / "triadP.toml",
        [(60.0,), (300.0,)],
    ),
}


@pytest.mark.parametrize("form", sorted(FORMS))
def test_a_driver_s_jerk_reaches_every_column(form, monkeypatch):
    """Every driver on ``q + w t + e t^2/2 + j t^3/6``: the rows given their speed,
    acceleration and jerk; the derivative columns are the time differences."""
    path, positions = FORMS[form]
    mech = assur.load(path)
    kinds = oracle.driver_kinds(mech)
    # a jerk of a few omega^3 (a slider's: m/s^3 scaled by the mechanism's size)
    jerk = np.array(
        [
            (3.0 if i % 2 else -2.0)
            * abs(d.omega) ** 3
            / (1.0 if kind == "revolute" else oracle.mechanism_size(mech) ** 2)
            for i, (d, kind) in enumerate(zip(mech.drivers, kinds, strict=True))
        ]
    )
    centres = oracle.si(mech, np.array(positions))
    oracle.assert_differences(mech, centres, jerk=jerk)
    # the comparison sees a jerk left out: the same rows solved without it fail
    solve = assur.kinematics
    monkeypatch.setattr(
        assur, "kinematics", lambda *args, jerk=None, **kw: solve(*args, **kw)
    )
    with pytest.raises(AssertionError, match="finite difference"):
        oracle.assert_differences(mech, centres, jerk=jerk)
