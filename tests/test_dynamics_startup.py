"""The start-up in time under the motor, and the ``[motor]`` table of the file."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import assur
from assur import Motor

from .test_dynamics import crank, example, steady

MGR = 3.0 * 9.81 * 0.2
"""Peak gravity torque of the test crank's point mass, N m."""


def test_constant_torque_keeps_the_steady_state():
    """Started on the steady state under its constant motor torque, the motion in
    time is that of the energy equation, turn after turn."""
    mech, t = example("whitworth"), steady("whitworth")
    run = assur.startup(
        mech,
        t.flywheel,
        motor=Motor(t.motor),
        omega0=float(t["driver.omega"][0]),
    )
    # periodic from the first turn on, to rounding: a constant torque neither damps
    # nor grows a change of speed (the multiplier is 1), so the changes must be
    # seen to wander either way, as rounding does
    assert run.turns <= 10
    assert run.settle_time == 0.0
    energy = assur.dynamics(mech, run.angle, flywheel=t.flywheel)
    np.testing.assert_allclose(run.omega, energy["driver.omega"], rtol=1e-6)
    assert run.speed_max == pytest.approx(t.speed_max, rel=1e-4)
    assert run.speed_min == pytest.approx(t.speed_min, rel=1e-4)
    assert run.delta == pytest.approx(t.delta, rel=1e-3)
    # the angle is continuous and grows turn after turn
    assert np.all(np.diff(run.angle) > 0)
    assert run.angle[-1] - run.angle[0] == pytest.approx(run.turns * 360.0, abs=5.0)


def test_an_electric_motor_from_rest_settles():
    mech, t = example("whitworth"), steady("whitworth")
    free = 8.0
    motor = Motor(3.0 * t.motor, free)
    run = assur.startup(mech, t.flywheel, motor=motor)
    assert run.omega[0] == 0.0
    assert 0.0 < run.settle_time < run.time[-1]
    # in the periodic state the motor does the work the loads take: its mean torque is
    # the steady state's, up to the speed fluctuation's second order
    assert run.mean_speed == pytest.approx(
        free * (1.0 - t.motor / motor.torque), rel=2e-3
    )
    assert 0.0 < run.delta < 0.1
    # after the time to settle the speed stays near the periodic mean
    late = run.time >= run.settle_time
    assert np.max(np.abs(run.omega[late] - run.mean_speed)) < 0.1 * run.mean_speed


def test_a_balanced_crank_starts_up_exponentially():
    """No load and a constant inertia: J w' = T (1 - w / w0), so the speed rises as
    w0 (1 - exp(-t / tau)) with tau = J w0 / T, and enters the 2 % band around w0 at
    tau ln 50. The motor is the file's."""
    inertia, stall, free = 3.0 * 0.2**2 + 0.01, 2.0, 10.0
    run = assur.startup(crank(motor=Motor(stall, free)))
    assert run.motor == Motor(stall, free)
    tau = inertia * free / stall
    np.testing.assert_allclose(
        run.omega, free * (1.0 - np.exp(-run.time / tau)), rtol=1e-7, atol=1e-9
    )
    assert run.mean_speed == pytest.approx(free, rel=1e-7)
    assert run.delta == pytest.approx(0.0, abs=1e-7)  # periodic to 1e-8 a turn
    # on the continuous motion, not the samples (1/90 turn apart, 0.16 tau here)
    assert run.settle_time == pytest.approx(tau * math.log(50.0), rel=1e-6)


def test_the_crank_stalls_past_its_peak_load():
    """A point mass hanging under the pivot, a constant torque of half its peak load:
    the crank swings up until the motor's work 0.5 m g r (phi + pi/2) equals the rise
    m g r (1 + sin phi), at phi = -26.45 deg, and stalls there."""
    from scipy.optimize import brentq

    mech = crank(gravity=(0.0, -9.81), angle=-90.0, motor=Motor(0.5 * MGR))
    stop = math.degrees(
        brentq(lambda p: 0.5 * (p + math.pi / 2) - 1 - math.sin(p), -1.0, 0.0)
    )
    with pytest.raises(assur.ModelError) as caught:
        assur.startup(mech)
    message = str(caught.value)
    assert message.startswith("startup: the crank stalls at crank angle -26.45")
    assert "cannot carry it past its peak load" in message
    assert float(message.split("crank angle ")[1].split(" deg")[0]) == pytest.approx(
        stop, abs=1e-3
    )


def test_a_motor_too_weak_to_start():
    mech = crank(gravity=(0.0, -9.81), angle=0.0, motor=Motor(0.5 * MGR, 20.0))
    with pytest.raises(assur.ModelError, match="the motor cannot start the crank"):
        assur.startup(mech)


def test_one_turn_does_not_settle_and_says_so():
    # a single turn has one speed at the reference pose: the change is from the
    # start's (it was an IndexError, the last two turns' speeds looked up)
    mech = example("slider_crank_exercise")
    motor = Motor(120.0, 250.0)
    with pytest.raises(assur.ModelError) as caught:
        assur.startup(mech, 0.0, motor=motor, turns=1)
    message = str(caught.value)
    assert message.startswith("startup: the motion does not settle in 1 turn (")
    assert "still changes by 100 % a turn" in message
    with pytest.raises(assur.ModelError, match="does not settle in 2 turns"):
        assur.startup(mech, 0.0, motor=motor, turns=2)


def test_a_constant_torque_above_the_load_does_not_settle():
    mech, t = example("whitworth"), steady("whitworth")
    with pytest.raises(assur.ModelError) as caught:
        assur.startup(mech, t.flywheel, motor=Motor(2.0 * t.motor), turns=20)
    # the torque to give is the steady motion's motor torque, with its sign: it was
    # printed as the load's, the sign turned (a crank turning the other way)
    assert t.motor > 0
    # refused before the turns: the crank gains 2 pi (2 M - M) joules every turn
    gain = 2.0 * math.pi * t.motor
    assert (
        f"a constant torque of {2.0 * t.motor:.6g} N m does {gain:.6g} J more work a "
        "turn than the loads take, so the crank's speed grows every turn without "
        "end" in str(caught.value)
    )
    assert (
        "a constant torque settles only where it balances the mean load, at "
        f"{t.motor:.6g} N m (the steady state's motor torque, as assur "
        "dynamics prints it)" in str(caught.value)
    )


def test_a_constant_torque_that_gains_every_turn_is_refused_after_one_turn():
    # it ran its 2 000 turns first: 40 s, to say the speed still changed
    mech, t = example("whitworth"), steady("whitworth")
    told: list[int] = []
    with pytest.raises(assur.ModelError, match="grows every turn without end"):
        assur.startup(
            mech,
            t.flywheel,
            motor=Motor(1.5 * t.motor),
            progress=lambda done, total: told.append(done),
        )
    assert told == [1]


def test_the_shaper_example_starts_up_near_its_speed():
    # examples/whitworth.toml's motor: 40 N m at standstill, none at 6 rad/s; the
    # load's mean torque of 6.19 N m is met at 6 (1 - 6.19 / 40) = 5.07 rad/s
    mech = example("whitworth")
    assert mech.motor == Motor(40.0, 6.0)
    flywheel = assur.flywheel(mech, 0.05)
    run = assur.startup(mech, flywheel)
    motor = assur.dynamics(mech, [0.0], flywheel=flywheel).motor
    assert run.mean_speed == pytest.approx(6.0 * (1.0 - motor / 40.0), rel=2e-3)
    assert 0.0 < run.settle_time < 20.0


def test_a_mechanism_without_motor():
    with pytest.raises(assur.ModelError, match=r"no motor; expected a \[motor\] table"):
        assur.startup(dataclasses.replace(example("whitworth"), motor=None), 1.0)


def test_a_motor_that_is_not_one():
    with pytest.raises(assur.UsageError, match=r"motor: expected an assur\.Motor"):
        assur.startup(crank(), motor=12.0)


def test_a_start_against_the_motor():
    with pytest.raises(assur.UsageError, match="omega0: -3 rad/s"):
        assur.startup(crank(motor=Motor(1.0)), omega0=-3.0)


def test_startup_needs_a_crank():
    mech = dataclasses.replace(
        assur.catalog.slider_crank(),
        drivers=(assur.Driver("guide", 1.0),),
        motor=Motor(1.0),
    )
    with pytest.raises(assur.ModelError, match="startup: driver joint 'guide'"):
        assur.startup(mech)


# ---------------------------------------------------------------------- [motor] table


def test_the_motor_goes_round_the_file(tmp_path):
    mech = dataclasses.replace(assur.catalog.four_bar(), motor=Motor(12.0, 150.0))
    path = tmp_path / "m.toml"
    assur.save(mech, path)
    assert "[motor]\ntorque = 12.0\nno_load_speed = 150.0\n" in path.read_text(
        encoding="utf-8"
    )
    assert assur.load(path) == mech
    constant = dataclasses.replace(mech, motor=Motor(-4.0))
    assert assur.loads(assur.dumps(constant)).motor == Motor(-4.0)
    assert assur.loads(assur.dumps(assur.catalog.four_bar())).motor is None


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("torque = 0", "motor.torque: the motor's torque at standstill is 0"),
        (
            "torque = 5\nno_load_speed = -3",
            "motor.no_load_speed: -3.0 rad/s against a torque of 5.0 N m; expected "
            "a speed of the torque's sign",
        ),
        ("torque = 5\nspeed = 3", "motor.speed: unknown key 'speed'"),
        ("no_load_speed = 3", "motor: missing key 'torque'"),
        ('torque = "strong"', "motor.torque: expected a number, got 'strong'"),
        ("torque = inf", "motor.torque: expected a finite number, got inf"),
    ],
)
def test_bad_motor_tables(text, message):
    base = assur.dumps(assur.catalog.four_bar())
    with pytest.raises(assur.ModelError, match=message.replace("[", r"\[")):
        assur.loads(base + "\n[motor]\n" + text + "\n")


def test_a_tiny_motor_of_one_sense_is_accepted():
    # the check multiplied speed and torque: 1e-300 * 1e-300 underflows to 0 and
    # was refused as "expected a speed of the torque's sign"
    base = assur.dumps(assur.catalog.four_bar())
    tiny = assur.loads(base + "\n[motor]\ntorque = 1e-300\nno_load_speed = 1e-300\n")
    assert tiny.motor == Motor(1e-300, 1e-300)
    with pytest.raises(assur.ModelError, match=r"motor\.no_load_speed: 0\.0 rad/s"):
        assur.loads(base + "\n[motor]\ntorque = 1e-300\nno_load_speed = 0.0\n")


def test_a_motor_built_in_code_is_checked():
    with pytest.raises(assur.ModelError, match="motor: expected a Motor"):
        dataclasses.replace(assur.catalog.four_bar(), motor=5.0)
    assert Motor(10.0, 100.0).at(50.0) == 5.0
    assert Motor(10.0).at(50.0) == 10.0


def test_a_slow_start_is_told_how_many_turns_it_needs():
    """J w' = T (1 - w / w0) with a time constant of many turns: periodic to 1e-8
    a turn takes more than the turns allowed. The message says about how many more
    (the geometric shrink of the last turns), and that many settle."""
    mech = crank(inertia=2.0, motor=Motor(2.0, 10.0))
    with pytest.raises(assur.ModelError) as caught:
        assur.startup(mech, turns=60)
    message = str(caught.value)
    assert message.startswith("startup: the motion does not settle in 60 turns")
    needed = int(message.split("settles in about ")[1].split(" turns")[0])
    run = assur.startup(mech, turns=needed + 100)
    assert run.turns == pytest.approx(needed, rel=0.2)
    tau = (2.0 + 3.0 * 0.2**2) * 10.0 / 2.0
    assert run.settle_time == pytest.approx(tau * math.log(50.0), rel=1e-2)


def test_a_heavy_flywheel_turns_slowly_and_does_not_stall():
    """The first turn of a flywheel of 1e6 kg m^2 under 2 N m takes about
    sqrt(4 pi J / T) = 2507 s, more than 10^4 turns at the motor's no-load speed:
    that time limit was reported as a stall "past its peak load" (there is none)."""
    mech = crank(motor=Motor(2.0, 10.0))
    with pytest.raises(assur.ModelError) as caught:
        assur.startup(mech, 1e6, turns=2)
    assert "stall" not in str(caught.value)
    assert str(caught.value).startswith("startup: the motion does not settle in 2")


def test_a_crank_that_creeps_is_not_said_to_stall(monkeypatch):
    from assur import _startup_steps

    # a time limit far too short for the first turn: the crank still moves there
    monkeypatch.setattr(_startup_steps, "_time_limit", lambda *args: 0.01)
    with pytest.raises(assur.ModelError, match=r"startup: the crank creeps: 0\.01 s"):
        assur.startup(crank(motor=Motor(2.0, 10.0)))


def test_a_stiff_motor_is_integrated_implicitly(monkeypatch):
    """A motor whose speed relaxes thousands of times a turn: the explicit method
    took minutes (torque 1e8 N m); the implicit one gives the same motion."""
    from assur import _startup_steps

    from .test_dynamics import example

    mech = dataclasses.replace(example("whitworth"), motor=Motor(3e5, 6.0))
    stiff = assur.startup(mech, 13.0)
    monkeypatch.setattr(_startup_steps, "_stiff", lambda *args: False)
    explicit = assur.startup(mech, 13.0)
    # periodic to 1e-8 a turn either way (the implicit steps repeat sooner)
    for name in ("settle_time", "mean_speed", "speed_max", "speed_min", "period"):
        assert getattr(stiff, name) == pytest.approx(getattr(explicit, name), rel=1e-7)
    # the motor holds its speed to within the load's share of its droop
    assert 5.99 < stiff.speed_min <= stiff.speed_max < 6.01


def test_the_periodic_extremes_against_a_runge_kutta_turn():
    """The largest and smallest speeds of the settled turn, against the oracle's own
    reduction integrated over that turn (RK4, 8000 steps) from where the package's
    last turn starts. Sampled at 2048 points they were off by 4e-6."""
    from .test_dynamics import example

    mech = example("four_bar")
    motor = Motor(0.5, 25.0)
    run = assur.startup(mech, motor=motor)
    fastest, slowest = oracle_extremes(mech, motor, run)
    assert run.speed_max == pytest.approx(fastest, rel=2e-7)
    assert run.speed_min == pytest.approx(slowest, rel=2e-7)


def oracle_extremes(
    mech: assur.Mechanism, motor: Motor, run: assur.Startup
) -> tuple[float, float]:
    """The largest and smallest speeds of the oracle's RK4 turn (8000 steps, its own
    reduction) from where the start-up's last turn starts."""
    from . import oracle

    last = np.flatnonzero(run.time >= run.time[-1] - run.period * (1 - 1e-9))[0]
    phi0, w0 = math.radians(run.angle[last]), run.omega[last]
    _, _, w = oracle.integrate_turn(
        oracle.crank_model(mech), phi0, w0, motor.torque, 8000, motor.no_load_speed
    )
    return float(np.max(np.abs(w))), float(np.min(np.abs(w)))


def test_a_vanishing_motor_torque_stalls_where_the_loads_work_runs_out():
    """Under 1e-300 N m the crank moves by its loads alone and stops where their
    work from the start is back at zero (kinetic energy from rest). The speed's
    tolerance was scaled by the motor's 1e-150 rad/s: scipy's error norms
    overflowed ("overflow encountered in dot", warnings here are errors)."""
    from scipy.optimize import brentq

    from . import oracle
    from .test_startup_settle import loaded_slider_crank

    mech = loaded_slider_crank()
    torque = oracle.crank_model(mech).torque
    start = math.radians(45.0)  # the reference pose
    grid = start + np.radians(np.arange(1.0, 360.0))
    work = [torque.integrate(start, phi) for phi in grid]
    i = int(np.flatnonzero(np.array(work) < 0)[0])
    stop = brentq(lambda p: torque.integrate(start, p), grid[i - 1], grid[i])
    for motor in (Motor(1e-300), Motor(1e-300, 180.0)):
        with pytest.raises(assur.ModelError) as caught:
            assur.startup(mech, motor=motor)
        message = str(caught.value)
        assert message.startswith("startup: the crank stalls at crank angle 282.5")
        angle = float(message.split("crank angle ")[1].split(" deg")[0])
        assert angle == pytest.approx(math.degrees(stop), abs=1e-3)


def test_a_start_up_tells_its_turns_when_asked():
    """A start-up of hundreds of turns took 18 s without a word (a loaded press):
    a callable is told each turn, out of the turns allowed."""
    told = []
    run = assur.startup(
        example("four_bar"),
        motor=Motor(0.5, 25.0),
        turns=500,
        progress=lambda done, total: told.append((done, total)),
    )
    assert told == [(k, 500) for k in range(1, run.turns + 1)]
    assert assur.startup(example("four_bar"), motor=Motor(0.5, 25.0)).turns == (
        run.turns
    )


def test_the_command_line_shows_the_start_up_s_bar_on_a_terminal(
    tmp_path, capsys, monkeypatch
):
    import sys

    from assur import cli

    path = tmp_path / "m.toml"
    mech = dataclasses.replace(example("four_bar"), motor=Motor(0.5, 25.0))
    assur.save(mech, path)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    # shown from the start here (a start-up of a second or more, else), counting
    # the turns toward their limit
    monkeypatch.setattr(assur.dynamics_startup, "BAR_DELAY", 0.0)
    assert cli.main(["dynamics", str(path), "--startup"]) == 0
    err = capsys.readouterr().err
    assert "startup:" in err
    assert "turns at most" in err
    assert cli.main(["dynamics", str(path), "--startup", "--quiet"]) == 0
    assert "startup:" not in capsys.readouterr().err


def test_a_start_up_whose_turns_scatter_settles():
    """The six-bar under a motor: the integration's steps span many knots of the
    model's splines, and the speed at the reference pose scatters by 2e-8 to 9e-8
    of itself from turn to turn, either way. It ran to 2000 turns and was said
    "still gathering speed"; its periodic motion is reached in a few turns (the
    multiplier 0.145). The extremes of its settled turn agree with the oracle's RK4
    turn from the same start."""

    mech = example("six_bar_lecture")
    motor = Motor(1.0, 40.0)
    run = assur.startup(mech, motor=motor, turns=60)
    assert run.turns < 40
    fastest, slowest = oracle_extremes(mech, motor, run)
    assert run.speed_max == pytest.approx(fastest, rel=1e-6)
    assert run.speed_min == pytest.approx(slowest, rel=1e-6)
