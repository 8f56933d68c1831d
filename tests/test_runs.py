"""Runs of driver positions in messages (assur._runs): a whole turn is one range."""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest

import assur
from assur._runs import _turn, digits_apart, runs_text, telling_apart
from assur.plan import compile_plan

from .conftest import EXAMPLES

EDGE = Path(__file__).parent / "data" / "edge"


def _crank() -> assur.Mechanism:
    return assur.load(EXAMPLES / "four_bar.toml")


def _text(mech: assur.Mechanism, x: np.ndarray, mask: np.ndarray) -> str:
    return runs_text(compile_plan(mech), x.reshape(-1, 1), mask, join=True)


def _between(x: np.ndarray, low: float, high: float) -> np.ndarray:
    """Positions whose angle, modulo a turn, is from ``low`` to ``high`` (deg)."""
    return np.remainder(x - low, 360.0) <= high - low


@pytest.mark.parametrize(
    ("start", "stop", "step", "want"),
    [
        # one turn from 40 deg: the first run goes on into the last
        (40.0, 400.0, 1.0, "-11 deg to 41 deg"),
        # ending on the first pose again
        (40.0, 401.0, 1.0, "-11 deg to 41 deg"),
        # the other way round: told in the sweep's order
        (40.0, -320.0, -1.0, "41 deg to -11 deg"),
        # from 355 down to 0 deg: not "555 deg to 345 deg"
        (355.0, -1.0, -5.0, "40 deg to -10 deg"),
        # from 360 down to 0: the mirror of the sweep up, not "401 deg to 349 deg"
        (360.0, -1.0, -1.0, "41 deg to -11 deg"),
        # less than a turn: two runs
        (40.0, 390.0, 1.0, "40 deg to 41 deg; 349 deg to 389 deg"),
    ],
)
def test_a_whole_turn_joins_its_ends(start, stop, step, want) -> None:
    x = np.arange(start, stop, step)
    assert _text(_crank(), x, _between(x, -11.0, 41.0)) == want


def test_runs_inside_a_turn_are_told_apart() -> None:
    x = np.arange(0.0, 360.0, 1.0)
    mask = _between(x, 10.0, 20.0) | _between(x, 100.0, 120.0)
    assert _text(_crank(), x, mask) == "10 deg to 20 deg; 100 deg to 120 deg"
    # every position: one run, nothing to join
    assert _text(_crank(), x, np.ones_like(mask)) == "0 deg to 359 deg"


def test_only_one_crank_s_sweep_wraps() -> None:
    x = np.arange(0.0, 360.0, 1.0)
    assert _turn(compile_plan(_crank()), x.reshape(-1, 1)) == 360.0
    # a prismatic driver's 360 mm of travel is no turn
    exercise = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    pushed = dataclasses.replace(exercise, drivers=(assur.Driver("guide", 1.0),))
    slider = compile_plan(pushed)
    assert [d.kind for d in slider.drivers] == ["P"]
    assert _turn(slider, x.reshape(-1, 1)) == 0.0
    # nor are two cranks' positions
    two = compile_plan(assur.load(EXAMPLES / "five_bar_two_cranks.toml"))
    assert _turn(two, np.stack([x, x], axis=1)) == 0.0


def test_a_failure_s_count_tells_the_other_groups_failures_too() -> None:
    # "(4 of 121 positions fail)" where 85 fail: the count was the first group's;
    # the others are counted by name ("85 in all" did not say what it counted)
    mech = assur.load(EDGE / "tenbar_two_groups_fail.json")
    angles = np.arange(-180.0, 181.0, 3.0)
    with pytest.raises(assur.AssemblyError) as raised:
        assur.kinematics(mech, angles)
    left = assur.kinematics(mech, angles, skip_unassembled=True)
    assert len(angles) - len(left) == 85
    # the sweep's first failing position, -180 deg, is the second group's
    assert str(raised.value).startswith(
        "group RRR (4, 5): cannot be assembled at driver position -180 deg "
        "(68 of 121 positions fail, 17 more where other groups cannot be "
        "assembled);"
    )


@pytest.mark.parametrize(
    ("angles", "where"),
    [
        (np.arange(0.0, 360.0, 5.0), "200 deg"),
        (np.arange(355.0, -1.0, -5.0), "340 deg"),
        (np.array([270.0, 200.0]), "270 deg"),
        (np.array([200.0, 270.0]), "200 deg"),
    ],
)
def test_the_error_names_the_sweep_s_first_failing_position(angles, where) -> None:
    # the lever's dyad (the first group) fails at 270 deg alone, the ram's from 200
    # deg: the error named the lever's at 270 deg, where the sweep stops at 200 deg
    mech = assur.load(EDGE / "shaper_two_groups_fail.toml")
    with pytest.raises(assur.AssemblyError) as raised:
        assur.kinematics(mech, angles)
    text = str(raised.value)
    group = "RPR (block, lever)" if where == "270 deg" else "RRP (rod, ram)"
    assert text.startswith(
        f"group {group}: cannot be assembled at driver position {where} ("
    ), text
    if len(angles) > 2:
        assert text.endswith(
            "it assembles for -15 deg to 195 deg"
            if angles[0] < angles[-1]
            else "it assembles for 195 deg to -15 deg"
        )


def test_runs_of_a_slice_are_not_joined() -> None:
    # a warning's runs are of one slice of a long sweep: a slice that spans a turn
    # joined its ends, and the merged warning claimed 178 to 362 deg near a dead centre
    x = np.arange(0.0, 360.0, 1.0)
    mask = _between(x, -2.0, 2.0) | _between(x, 178.0, 182.0)
    plan = compile_plan(_crank())
    assert runs_text(plan, x.reshape(-1, 1), mask) == (
        "0 deg to 2 deg; 178 deg to 182 deg; 358 deg to 359 deg"
    )
    assert _text(_crank(), x, mask) == "-2 deg to 2 deg; 178 deg to 182 deg"


def test_a_joined_run_of_one_pose_is_told_once() -> None:
    # the first pose and the closing one alone: "0 deg to 0 deg"
    x = np.arange(0.0, 361.0, 1.0)
    mask = np.zeros(len(x), dtype=bool)
    mask[[0, -1, 100]] = True
    assert _text(_crank(), x, mask) == "0 deg; 100 deg"


def test_a_turn_is_no_wider_than_the_rounding_of_far_angles() -> None:
    # a tolerance of 1e-9 of the angles passed a whole turn beyond 3.6e11 deg
    far = np.array([1e12, 1e12 + 10.0, 1e12 + 20.0]).reshape(-1, 1)
    assert _turn(compile_plan(_crank()), far) == 0.0


def test_a_fine_step_s_neighbours_are_written_apart() -> None:
    # at a step of 1e-4 deg: "cannot be assembled at 149.528 deg ... it assembles
    # for 60 deg to 149.528 deg"
    mech = assur.catalog.four_bar(
        crank=0.1, coupler=0.05, rocker=0.08, frame=0.1, angle=60.0
    )
    with pytest.raises(assur.AssemblyError) as raised:
        assur.kinematics(mech, np.arange(80.0, 82.0, 1e-4))
    found = re.search(
        r"driver position (\S+) deg .* it assembles for \S+ deg to (\S+) deg",
        str(raised.value),
    )
    assert found is not None
    failing, last_good = (float(v) for v in found.groups())
    assert failing - last_good == pytest.approx(1e-4, rel=1e-6)
    # and a coarse sweep keeps six digits
    assert telling_apart([(np.array([30.0]), np.array([31.0]))]) == 6


def test_a_failing_position_is_written_apart_from_its_nearest_neighbours() -> None:
    # given out of order: 137.8736 fails, 137.87355 (given after it) assembles; both
    # were "137.874 deg"
    mech = assur.catalog.four_bar(0.06, 0.07, 0.08, 0.1)
    angles = [100.0, 137.8736, 137.8735, 137.87355, 120.0]
    with pytest.raises(assur.AssemblyError) as raised:
        assur.kinematics(mech, angles)
    found = re.search(r"driver position (\S+) deg", str(raised.value))
    assert found is not None
    assert float(found.group(1)) == pytest.approx(137.8736, abs=1e-9)
    given = np.array(angles).reshape(-1, 1)
    digits = digits_apart(given, 1)
    assert f"{137.8736:.{digits}g}" != f"{137.87355:.{digits}g}"
    assert f"{137.8736:.6g}" == f"{137.87355:.6g}"  # as they were


def test_a_joined_run_s_start_is_written_apart_too() -> None:
    # the joined run's start, a turn back, was not among the ends told apart: it
    # began "-355 deg" where the position before it, failing, is -355 deg too
    x = np.r_[np.arange(-350.0, 5.0, 1.0), 5.0, 5.00001, np.arange(6.0, 10.5, 1.0)]
    mask = (x <= -9.0) | (x >= 5.00001)
    assert _text(_crank(), x, mask).startswith("-354.99999 deg to -9 deg")


def test_a_triad_near_a_dead_centre_is_not_told_of_a_transmission_angle() -> None:
    # a triad has no one transmission angle: its warning is its equations' conditioning
    from assur._kinematics import Trouble
    from assur._troubles import _report

    plan = compile_plan(assur.load(EXAMPLES / "class3.toml"))
    given = np.array([[10.0], [11.0], [12.0]])
    near = np.array([False, True, False])
    for label, how in (
        ("triad (rod, plate, left, right)", "its position equations nearly singular"),
        ("RRR (coupler, rocker)", "within about 2 degrees of transmission angle 0"),
    ):
        with pytest.warns(assur.AssurWarning) as caught:
            _report(plan, given, [(Trouble(label, "near", near), 0)], False)
        assert str(caught[0].message) == (
            f"group {label}: near a dead centre ({how}"
            + (" or 180 deg" if label.startswith("RRR") else "")
            + ") at driver position 11 deg"
        )
