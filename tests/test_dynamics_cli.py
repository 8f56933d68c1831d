"""``assur dynamics``: figures, tables, the force table at the motion, errors."""

from __future__ import annotations

import dataclasses
import json
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur

from .conftest import EXAMPLES
from .conftest import run_cli as run
from .test_cli_robustness import shell, subprocess_env

WHITWORTH = EXAMPLES / "whitworth.toml"
FOUR_BAR = EXAMPLES / "four_bar.toml"
EPSILON_NOTE = (
    "assur: note: {}: the dynamic model leaves the driver's epsilon = 10 rad/s^2 "
    "out: the crank's acceleration is its equation of motion's (driver.epsilon)\n"
)
"""What ``assur dynamics`` tells of the four-bar's file (its crank accelerates)."""


def one_error(capsys, *args) -> str:
    status, out, err = run(capsys, *args)
    assert status == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    return lines[-1]


def test_figures_and_table(capsys):
    status, out, err = run(capsys, "dynamics", FOUR_BAR, "--angles", "0:90:30")
    assert (status, err) == (0, EPSILON_NOTE.format(FOUR_BAR))
    t = assur.dynamics(assur.load(FOUR_BAR), [0.0, 30.0, 60.0, 90.0])
    assert "dynamic model reduced to the crank" in out
    assert f"delta = {t.delta:.6g}" in out
    assert f"{t.speed_max:.6g} rad/s at {t.angle_max:.6g} deg" in out
    lines = out.splitlines()
    head = next(i for i, line in enumerate(lines) if line.lstrip().startswith("angle"))
    assert lines[head].split() == list(t.columns)
    assert lines[head + 1].split()[:2] == ["[deg]", "[kg"]
    assert len(lines) == head + 2 + 4


def test_flywheel_for_a_delta(capsys):
    status, out, _ = run(
        capsys, "dynamics", WHITWORTH, "--delta", "0.05", "--angles", "0"
    )
    assert status == 0
    sizing = assur.flywheel_sizing(assur.load(WHITWORTH), 0.05)
    assert f"{sizing.exact:.6g} kg m^2 (exact, for delta = 0.05)" in out
    assert f"Wittenbauer {sizing.wittenbauer:.6g}" in out
    assert "delta = 0.05\n" in out


def test_a_delta_near_2_is_not_told_as_2(capsys):
    # 2 (the crank at rest) is refused as --delta: 1.999999 was echoed as "2"
    status, out, _ = run(
        capsys, "dynamics", WHITWORTH, "--delta", "1.999999", "--angles", "0"
    )
    assert status == 0
    assert "(exact, for delta = 1.999999)" in out
    (said,) = (line for line in out.splitlines() if "fluctuation" in line)
    shown = float(said.rpartition("delta = ")[2])
    assert 1.9999 < shown < 2.0


def test_json(capsys):
    status, out, _ = run(
        capsys,
        "dynamics",
        WHITWORTH,
        "--flywheel",
        "20",
        "--angles",
        "0:360:90",
        "--json",
    )
    assert status == 0
    data = json.loads(out)
    t = assur.dynamics(assur.load(WHITWORTH), [0.0, 90.0, 180.0, 270.0, 360.0], 20.0)
    assert data["dynamics"] == t.summary()
    assert data["columns"] == list(t.columns)
    assert data["units"] == {c: t.column(c).unit for c in t.columns}
    assert data["units"]["reduced.inertia"] == "kg m^2"
    assert [r["driver.omega"] for r in data["rows"]] == t["driver.omega"].tolist()


def test_csv_with_the_forces_at_the_motion(capsys, tmp_path: Path):
    target = tmp_path / "d.csv"
    status, out, _ = run(
        capsys,
        "dynamics",
        WHITWORTH,
        "--delta",
        "0.05",
        "--forces",
        "--csv",
        target,
    )
    assert status == 0
    assert out.startswith("wrote 360 rows x ")
    rows = np.genfromtxt(target, delimiter=",", names=True)
    names = rows.dtype.names
    assert names[:8] == (
        "angle",
        "reducedinertia",
        "reducedinertia_slope",
        "reducedtorque",
        "reducedwork",
        "drivermotor",
        "driveromega",
        "driverepsilon",
    )
    assert "drivertorque" in names
    assert "O2F" in names
    inertia = assur.flywheel(assur.load(WHITWORTH), 0.05)
    want = rows["drivermotor"] - inertia * rows["driverepsilon"]
    np.testing.assert_allclose(rows["drivertorque"], want, rtol=1e-9, atol=1e-9)


def test_parquet_and_csv_from_one_pass(capsys, tmp_path: Path, monkeypatch):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    from assur import _dynamics_files

    monkeypatch.setattr(_dynamics_files, "SLICE", 100)  # four slices of the sweep
    csv, parquet = tmp_path / "d.csv", tmp_path / "d.parquet"
    argv = ["dynamics", WHITWORTH, "--delta", "0.05", "--forces"]
    status, out, _ = run(capsys, *argv, "--csv", csv, "--parquet", parquet)
    assert status == 0
    read = pq.read_table(parquet)
    assert pq.ParquetFile(parquet).num_row_groups == 4
    names = csv.read_text(encoding="utf-8").splitlines()[0].split(",")
    assert read.column_names == names
    values = np.loadtxt(csv, delimiter=",", skiprows=1)
    for i, name in enumerate(names):  # the CSV's 12 significant digits
        np.testing.assert_allclose(read.column(name).to_numpy(), values[:, i], 1e-11)
    assert read.schema.field("reduced.inertia").metadata == {b"unit": b"kg m^2"}
    assert read.schema.field("O2.Fx").metadata == {b"unit": b"N"}
    size = f"360 rows x {len(names)} columns"
    assert out == f"wrote {size} to {csv}\nwrote {size} to {parquet}\n"


@pytest.mark.parametrize(
    ("options", "message"),
    [
        (["--parquet", "-"], "--parquet -: a Parquet file is not text"),
        (["--parquet", "d.csv"], "--parquet d.csv: a .csv name for Parquet"),
        (
            ["--csv", "t", "--parquet", "./t"],
            "--parquet ./t: is the file of --csv too",
        ),
        (
            ["--parquet", "s", "--startup-csv", "./s"],
            "--startup-csv ./s: is the file of --parquet too",
        ),
    ],
)
def test_parquet_options_refused(capsys, options, message, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    line = one_error(capsys, "dynamics", FOUR_BAR, *options)
    assert message in line
    assert list(tmp_path.iterdir()) == []


def test_parquet_without_pyarrow_before_any_work(capsys, tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    target = tmp_path / "d.parquet"
    line = one_error(capsys, "dynamics", FOUR_BAR, "--parquet", target)
    assert line.endswith(
        f"--parquet {target}: writing Parquet needs pyarrow, which is not installed; "
        "expected 'pip install pyarrow' (or 'pip install \"assur[parquet]\"')"
    )
    assert not target.exists()


def test_csv_to_standard_output(capsys):
    status, out, _ = run(
        capsys, "dynamics", FOUR_BAR, "--angles", "0:10:5", "--csv", "-"
    )
    assert status == 0
    lines = out.splitlines()
    assert lines[0].startswith("angle,reduced.inertia,")
    assert len(lines) == 4


def with_motor(folder: Path) -> Path:
    """The Whitworth mechanism with an electric motor ten times its mean load."""
    mech = assur.load(WHITWORTH)
    t = assur.dynamics(mech, [0.0], flywheel=20.0)
    path = folder / "w.toml"
    assur.save(dataclasses.replace(mech, motor=assur.Motor(10 * t.motor, 6.0)), path)
    return path


def test_startup_from_the_file_motor(capsys, tmp_path: Path):
    path = with_motor(tmp_path)
    status, out, err = run(
        capsys, "dynamics", path, "--flywheel", "20", "--startup", "--angles", "0"
    )
    assert (status, err) == (0, "")
    run_ = assur.startup(assur.load(path), 20.0)
    # the turns the crank makes until it settles, and those integrated
    turned = np.interp(run_.settle_time, run_.time, run_.angle) - run_.angle[0]
    settles = f"settles in {run_.settle_time:.6g} s ({abs(turned) / 360:.3g} turns; "
    assert settles + f"{run_.turns} turns integrated)" in out
    assert f"time-mean {abs(run_.mean_speed):.6g} rad/s (2 pi / period" in out
    # delta is over the mean of the extremes (the steady state's), which is printed
    middle = (run_.speed_max + run_.speed_min) / 2
    delta = (run_.speed_max - run_.speed_min) / middle
    over = f"(max - min over w_m = (max + min) / 2 = {middle:.6g} rad/s)"
    assert f"delta = {delta:.6g} {over}" in out


def test_startup_samples_to_csv_and_json(capsys, tmp_path: Path):
    path = with_motor(tmp_path)
    target = tmp_path / "start.csv"
    argv = ("dynamics", path, "--flywheel", "20", "--angles", "0")
    status, out, err = run(capsys, *argv, "--startup-csv", target)
    assert (status, err) == (0, "")
    run_ = assur.startup(assur.load(path), 20.0)
    assert f"wrote {len(run_.time)} rows x 3 columns to {target}" in out
    assert "settles in" in out  # --startup-csv implies --startup
    lines = target.read_text(encoding="utf-8").splitlines()
    assert lines[0] == "time,angle,omega"
    got = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    # the file gives back the very samples of the library's start-up
    np.testing.assert_array_equal(got[:, 0], run_.time)
    np.testing.assert_array_equal(got[:, 1], run_.angle)
    np.testing.assert_array_equal(got[:, 2], run_.omega)
    # the speed starts from rest, and time runs forward
    assert got[0, 2] == 0.0
    assert (np.diff(got[:, 0]) > 0).all()
    status, out, err = run(capsys, *argv, "--startup", "--json")
    assert (status, err) == (0, "")
    data = json.loads(out)["startup"]
    np.testing.assert_array_equal(data["omega"], run_.omega)
    assert len(data["time"]) == len(data["angle"]) == len(run_.time)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--startup-csv", "-"], "--startup-csv -: expected a file of its own"),
        (
            ["--csv", "one.csv", "--startup-csv", "./one.csv"],
            "--startup-csv ./one.csv: is the file of --csv too",
        ),
        (["--delta", "0"], "--delta 0: expected a coefficient of speed fluctuation"),
        (["--delta", "nan"], "--delta nan: expected a coefficient"),
        (["--flywheel", "-2"], "--flywheel -2: expected an inertia >= 0"),
        (["--csv", "-", "--json"], "--csv - and --json: both write to standard output"),
        (["--startup"], "startup: the mechanism has no motor"),
        (["--delta", "0.9"], "alone runs with delta"),
        (["--delta", "2"], "--delta 2: expected a coefficient of speed fluctuation"),
        (["--flywheel", "1e300"], "--flywheel 1e+300: expected an inertia >= 0"),
    ],
)
def test_bad_options(capsys, args, message):
    line = one_error(capsys, "dynamics", FOUR_BAR, *args)
    assert line.startswith("assur: error: ")
    assert message in line


def test_flywheel_and_delta_exclude_each_other(capsys):
    status, _, err = run(
        capsys, "dynamics", FOUR_BAR, "--flywheel", "1", "--delta", "0.1"
    )
    assert status == 2
    assert "not allowed with argument" in err


@pytest.mark.parametrize(
    ("name", "message"),
    [
        ("tenbar", "no link has a mass"),
        ("five_bar_two_cranks", "2 drivers; expected one driving crank"),
        ("offset_slider_crank", "the crank would come to rest at crank angle"),
    ],
)
def test_mechanisms_without_a_dynamic_model(capsys, name, message):
    path = EXAMPLES / f"{name}.toml"
    line = one_error(capsys, "dynamics", path)
    assert line.startswith(f"assur: error: {path}: dynamics: ")
    assert message in line


def test_the_table_is_not_written_over_the_input(capsys, tmp_path: Path):
    copy = tmp_path / "m.toml"
    copy.write_text(FOUR_BAR.read_text(encoding="utf-8"), encoding="utf-8")
    line = one_error(capsys, "dynamics", copy, "--csv", copy)
    assert "is the mechanism file being read" in line
    assert copy.read_text(encoding="utf-8") == FOUR_BAR.read_text(encoding="utf-8")


def test_startup_where_the_file_speed_has_no_steady_state(capsys, tmp_path: Path):
    # the motor carries the crank round; a constant torque at the file's omega
    # would not: the start-up is shown, with a warning, and no table is made up
    path = Path(__file__).parent / "data" / "edge" / "four_bar_motor_slow.toml"
    with pytest.raises(assur.ModelError, match="would come to rest"):
        assur.dynamics(assur.load(path))
    run_ = assur.startup(assur.load(path))
    status, out, err = run(capsys, "dynamics", path, "--startup")
    assert status == 0
    assert err.count("\n") == 1
    assert err.startswith("assur: warning: ")
    assert "would come to rest" in err
    assert err.endswith("shown: the start-up alone\n")
    assert f"mean {abs(run_.mean_speed):.6g} rad/s" in out
    assert "nominal crank speed" not in out
    status, out, _ = run(capsys, "dynamics", path, "--startup", "--json")
    assert status == 0
    data = json.loads(out)
    assert set(data) == {"name", "startup"}
    assert data["startup"]["mean_speed"] == run_.mean_speed
    # a table of the steady state cannot be written: the error stands
    target = tmp_path / "steady.csv"
    status, _, err = run(capsys, "dynamics", path, "--startup", "--csv", target)
    assert status == 2
    assert "would come to rest" in err.splitlines()[-1]
    assert not target.exists()


def test_json_and_a_csv_file_are_both_written(capsys, tmp_path: Path):
    # --json took the place of --csv PATH: no file, exit 0
    target = tmp_path / "d.csv"
    status, out, err = run(
        capsys, "dynamics", FOUR_BAR, "--angles", "0:90:30", "--json", "--csv", target
    )
    assert status == 0, err
    data = json.loads(out)
    t = assur.dynamics(assur.load(FOUR_BAR), [0.0, 30.0, 60.0, 90.0])
    lines = target.read_text(encoding="utf-8").splitlines()
    assert lines[0].split(",") == list(t.columns) == data["columns"]
    assert len(lines) == 1 + 4
    # the line saying so goes to standard error, beside the JSON
    wrote = f"wrote 4 rows x {len(t.columns)} columns to {target}\n"
    assert err == EPSILON_NOTE.format(FOUR_BAR) + wrote


def test_the_files_are_written_as_a_set(capsys, tmp_path: Path):
    # the start-up's file landed, then --csv failed: now neither lands
    path = with_motor(tmp_path)
    start = tmp_path / "start.csv"
    start.write_text("old\n", encoding="utf-8")
    line = one_error(
        capsys, "dynamics", path, "--flywheel", "20", "--angles", "0",
        "--startup-csv", start, "--csv", "/dev/full",
    )  # fmt: skip
    assert "/dev/full" in line
    assert start.read_text(encoding="utf-8") == "old\n"


def _shell(tmp_path: Path, options: str) -> subprocess.CompletedProcess[str]:
    """Run ``assur dynamics FOUR_BAR OPTIONS | cat``: /dev/stdout is the pipe."""
    return shell(tmp_path, f"dynamics {FOUR_BAR} {options} | cat")


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ("--startup-csv /dev/stdout", "--startup-csv /dev/stdout: expected a file"),
        (
            "--csv /dev/stdout --json",
            "--csv /dev/stdout and --json: both write to standard output",
        ),
        (
            "--parquet /dev/stdout --json",
            "--parquet /dev/stdout: is standard output, where --json writes",
        ),
    ],
)
def test_standard_output_by_another_name(tmp_path: Path, options, message):
    result = _shell(tmp_path, options)
    assert result.stdout == ""
    (line,) = result.stderr.splitlines()
    assert message in line


def test_dev_stdout_is_written_as_standard_output(tmp_path: Path):
    result = _shell(tmp_path, "--angles 0:90:30 --csv /dev/stdout")
    assert result.stderr == EPSILON_NOTE.format(FOUR_BAR)
    # no "wrote ..." line in the stream after the table
    assert len(result.stdout.splitlines()) == 1 + 4
    assert "wrote" not in result.stdout


def test_two_drivers_are_refused_before_their_angles_are_read(capsys):
    # one range was asked for per driver, then a second driver was refused
    path = EXAMPLES / "five_bar_two_cranks.toml"
    line = one_error(capsys, "dynamics", path, "--angles", "0:10:5")
    assert "2 drivers; expected one driving crank" in line


def test_friction_left_out_is_said(capsys):
    # the model drops friction: --forces then showed driver.torque off the model's
    path = EXAMPLES / "slider_crank_friction.toml"
    argv = [
        "dynamics",
        path,
        "--flywheel",
        "0.03",
        "--angles",
        "0:360:90",
        "--csv",
        "-",
    ]
    status, out, err = run(capsys, *argv, "--forces")
    assert status == 0
    assert err == (
        f"assur: note: {path}: the dynamic model leaves the joints' friction out; "
        "the force table's driver.torque overcomes it too (its driver.torque_ideal "
        "is the model's)\n"
    )
    header, *rows = out.splitlines()
    names = header.split(",")
    values = np.array([[float(x) for x in row.split(",")] for row in rows])
    column = dict(zip(names, values.T, strict=True))
    balance = column["driver.motor"] - 0.03 * column["driver.epsilon"]
    np.testing.assert_allclose(column["driver.torque_ideal"], balance, atol=1e-8)
    assert np.all(np.abs(column["driver.torque"] - balance) > 1.0)  # friction's
    status, _, err = run(capsys, *argv, "-q")
    assert (status, err) == (0, "")


def test_turns_of_the_startup(capsys, tmp_path: Path):
    path = with_motor(tmp_path)
    argv = ("dynamics", path, "--flywheel", "20", "--startup", "--turns", "3")
    line = one_error(capsys, *argv)
    assert "the motion does not settle in 3 turns" in line
    line = one_error(capsys, "dynamics", path, "--startup", "--turns", "0")
    assert "--turns 0: expected a whole number of turns from 1 to 100000" in line
    line = one_error(capsys, "dynamics", path, "--startup", "--turns", "99999999999")
    assert "--turns 99999999999: expected a whole number of turns from 1 to" in line
    # without a start-up the option did nothing, without a word
    line = one_error(capsys, "dynamics", path, "--delta", "0.05", "--turns", "5")
    assert line.endswith("--turns 5: expected --startup (or --startup-csv) with it")


def test_one_turn_of_the_startup_is_one_error(capsys, tmp_path: Path):
    # it was an IndexError's traceback and exit status 1
    path = with_motor(tmp_path)
    line = one_error(capsys, "dynamics", path, "--startup", "--turns", "1")
    assert line.startswith(
        f"assur: error: {path}: startup: the motion does not settle in 1 turn ("
    )


def test_an_estimate_below_zero_is_not_printed_as_one(capsys):
    # Wittenbauer's estimate was printed as -0.000133258 (-1.2e+10 %)
    delta = 0.6712204614  # just above the four-bar's own fluctuation
    sizing = assur.flywheel_sizing(assur.load(FOUR_BAR), delta)
    assert sizing.wittenbauer < 0.0 <= sizing.exact
    status, out, _ = run(
        capsys, "dynamics", FOUR_BAR, "--delta", str(delta), "--angles", "0"
    )
    assert status == 0
    (line,) = (x for x in out.splitlines() if "classical estimates" in x)
    assert line.endswith(
        "Wittenbauer none (below zero this close to the mechanism's own delta)"
    )
    assert f"{sizing.wittenbauer:.6g}" not in out


def test_a_mean_torque_of_round_off_is_printed_as_zero(capsys):
    # gravity alone does no work over a turn: the mean was -6.93889e-18 N m
    path = EXAMPLES / "six_bar_lecture.toml"
    result = assur.dynamics(assur.load(path), [0.0], flywheel=1.0)
    assert abs(result.motor) * 2 * np.pi < 1e-12 * result.energy_swing
    status, out, _ = run(capsys, "dynamics", path, "--flywheel", "1", "--angles", "0")
    assert status == 0
    assert "motor torque                          0 N m (constant)" in out


def test_the_motor_torque_s_sign_is_told_for_a_clockwise_crank(capsys, tmp_path):
    text = WHITWORTH.read_text(encoding="utf-8")
    assert text.count("omega = 5.0") == 1
    path = tmp_path / "clockwise.toml"
    path.write_text(text.replace("omega = 5.0", "omega = -5.0"), encoding="utf-8")
    t = assur.dynamics(assur.load(path), np.arange(0.0, 360.0, 1.0), flywheel=20.0)
    # the cutting force, a function of the crank angle, helps a crank turned the
    # other way round: the motor's power is negative, it brakes
    power = t["driver.motor"] * t["driver.omega"]
    assert np.all(power < 0.0)
    status, out, _ = run(capsys, "dynamics", path, "--flywheel", "20", "--angles", "0")
    assert status == 0
    lines = {line[:38].strip(): line[38:].strip() for line in out.splitlines()[1:4]}
    # a size and a direction word, as the report and the notebook write it
    assert lines["nominal crank speed"] == "5 rad/s, clockwise"
    assert '<td style="text-align:left">5 rad/s, clockwise</td>' in t._repr_html_()
    # two sentences: the steady state's torque, then the file's motor, which
    # turns the crank counter-clockwise, told in the start-up's warning's words
    from assur._startup_checks import _against_omega

    mech = assur.load(path)
    with pytest.warns(assur.AssurWarning) as said:
        _against_omega(mech, mech.motor)
    warning = str(said[0].message).removeprefix("startup: ").split("; expected")[0]
    assert warning.startswith("the motor turns the crank counter-clockwise")
    assert lines["motor torque"] == (
        f"{t.motor:.6g} N m (constant, counter-clockwise positive; it brakes: the "
        f"loads drive the crank). The file's [motor] drives the start-up alone, but "
        f"{warning}."
    )
    # turning counter-clockwise, the same loads take work: the motor drives
    status, out, _ = run(capsys, "dynamics", WHITWORTH, "--delta", "0.05")
    assert ", clockwise" not in out
    motor = assur.load(WHITWORTH).motor
    assert (
        f"N m (constant). The file's [motor], {motor.at(5.0):.6g} N m at the nominal "
        "5 rad/s, drives the start-up alone.\n"
    ) in out
    assert "brakes" not in out


def test_a_long_sweep_is_written_by_slices(capsys, monkeypatch, tmp_path: Path):
    from assur import dynamics_cli

    # the whole table was built at once: 1.25 GB at 36 000 positions with --json
    monkeypatch.setattr(dynamics_cli, "SLICE", 7)
    target = tmp_path / "d.csv"
    argv = ["dynamics", FOUR_BAR, "--angles", "0:100:5", "--forces"]
    status, out, _ = run(capsys, *argv, "--csv", target, "--json", "-q")
    assert status == 0
    data = json.loads(out)
    mech = assur.load(FOUR_BAR)
    whole = assur.dynamics(mech, np.arange(0.0, 101.0, 5.0))
    motion = assur.forces(
        mech,
        whole["angle"],
        omega=whole["driver.omega"],
        epsilon=whole["driver.epsilon"],
    )
    assert len(data["rows"]) == len(whole) == 21
    header, *lines = target.read_text(encoding="utf-8").splitlines()
    assert header.split(",") == data["columns"]
    for name in ("driver.omega", "reduced.work", "B.F", "driver.torque"):
        table = whole if name in whole.columns else motion
        got = np.array([row[name] for row in data["rows"]])
        np.testing.assert_array_equal(got, table[name])  # to the last bit
        column = header.split(",").index(name)
        from_csv = np.array([float(line.split(",")[column]) for line in lines])
        np.testing.assert_allclose(from_csv, table[name], rtol=1e-11, atol=0)
    assert data["dynamics"] == whole.summary()


@pytest.mark.parametrize("output", [["--csv", "-"], ["--json"], []])
def test_a_lock_in_a_later_slice_writes_nothing(capsys, monkeypatch, tmp_path, output):
    from assur import dynamics_cli

    # the slices before it were on standard output already (a JSON never closed);
    # the readable table showed 400 rows and said nothing of the lock beyond them
    monkeypatch.setattr(dynamics_cli, "SLICE", 7)
    monkeypatch.setattr(dynamics_cli, "ROWS_SHOWN", 5)
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    path = tmp_path / "lock.toml"
    path.write_text(text.replace("friction = 0.8", "friction = 1.3"), encoding="utf-8")
    argv = ["dynamics", path, "--forces", "--flywheel", "1", "--angles", "200:260:2"]
    line = one_error(capsys, *argv, *output, "-q")
    # counted over the whole sweep of 31 positions, not a slice of 7
    assert (
        "its friction locks it at driver position 248 deg (7 of 31 positions)" in line
    )


def test_a_clockwise_start_up_prints_its_speeds_as_magnitudes(capsys) -> None:
    path = Path(__file__).parent / "data" / "edge" / "four_bar_motor_clockwise.toml"
    argv = ("dynamics", path, "--flywheel", "0.01", "--startup", "--angles", "-50")
    status, out, _ = run(capsys, *argv)
    assert status == 0
    run_ = assur.startup(assur.load(path), 0.01)
    assert run_.mean_speed < 0 < run_.speed_min < run_.speed_max
    assert f"mean {-run_.mean_speed:.6g} rad/s (2 pi / period" in out
    # the steady state's nominal speed and the start-up's mean, each said once
    assert "nominal crank speed                   25 rad/s, clockwise\n" in out
    assert out.count(", clockwise\n") == 2


def test_a_motor_against_omega_is_told(capsys, tmp_path: Path) -> None:
    # the four-bar turns clockwise (omega -25); this motor turns it the other way
    path = Path(__file__).parent / "data" / "edge" / "four_bar_motor_clockwise.toml"
    text = path.read_text(encoding="utf-8").replace("torque = -8.0", "torque = 8.0")
    target = tmp_path / "against.toml"
    target.write_text(
        text.replace("no_load_speed = -30.0", "no_load_speed = 30.0"), encoding="utf-8"
    )
    with pytest.warns(assur.AssurWarning, match="against the driver's omega = -25"):
        run_ = assur.startup(assur.load(target), 0.01)
    assert run_.mean_speed > 0
    status, _, err = run(capsys, "dynamics", target, "--flywheel", "0.01", "--startup")
    assert status == 0
    assert err.count("the motor turns the crank counter-clockwise (torque 8 N m)") == 1
    # a motor of omega's sign: no word
    with warnings.catch_warnings():
        warnings.simplefilter("error", assur.AssurWarning)
        assur.startup(assur.load(path), 0.01)


def test_the_file_s_epsilon_is_said_to_be_left_out(capsys, tmp_path: Path) -> None:
    text = WHITWORTH.read_text(encoding="utf-8")
    assert "epsilon = 0.0" in text
    path = tmp_path / "accelerating.toml"
    path.write_text(text.replace("epsilon = 0.0", "epsilon = 5.0"), encoding="utf-8")
    status, out, err = run(capsys, "dynamics", path, "--flywheel", "20")
    assert status == 0
    assert err == (
        f"assur: note: {path}: the dynamic model leaves the driver's epsilon = 5 "
        "rad/s^2 out: the crank's acceleration is its equation of motion's "
        "(driver.epsilon)\n"
    )
    # the same model as without it
    _, same, _ = run(capsys, "dynamics", WHITWORTH, "--flywheel", "20")
    assert out == same.replace(WHITWORTH.name, path.name)


def test_a_name_standard_output_cannot_write_stops_before_any_file(tmp_path: Path):
    # the start-up's CSV was written, and "wrote ..." said, before the error
    from .test_cli_robustness import on_ascii

    path = Path(__file__).parent / "data" / "edge" / "four_bar_motor_clockwise.toml"
    text = path.read_text(encoding="utf-8").replace("[links.rocker]", '[links."ракер"]')
    (tmp_path / "m.toml").write_text(
        text.replace('"rocker"', '"ракер"'), encoding="utf-8"
    )
    argv = ["dynamics", "m.toml", "--flywheel", "0.01", "--startup-csv", "s.csv"]
    result = on_ascii(tmp_path, *argv, "--forces", "--csv", "-")
    assert (result.returncode, result.stdout) == (2, "")
    assert result.stderr.startswith("assur: error: standard output: its encoding")
    assert result.stderr.count("\n") == 1
    assert not (tmp_path / "s.csv").exists()


def test_loads_that_do_no_work_need_no_motor() -> None:
    # gravity alone: the motor's torque was -6.9e-18 N m in the table, 0 above it
    mech = assur.load(EXAMPLES / "six_bar_lecture.toml")
    table = assur.dynamics(mech, [0.0, 45.0], flywheel=0.4)
    assert table.motor == 0.0
    assert np.all(table["driver.motor"] == 0.0)
    # the model's own mean: round-off against the largest reduced torque
    from assur.dynamics_reduced import reduce

    model = reduce(mech)
    assert abs(np.mean(model.torque)) < 1e-13 * np.max(np.abs(model.torque))


def test_parquet_on_standard_output_keeps_the_lines_off_it(tmp_path: Path):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    # "wrote ... to /dev/stdout" was written after the file's footer: no Parquet
    result = _shell(tmp_path, "--angles 0:10:5 --parquet /dev/stdout > out.parquet")
    assert result.returncode == 0, result.stderr
    assert pq.read_table(tmp_path / "out.parquet").num_rows == 3
    assert "wrote 3 rows x" in result.stderr


def test_standard_output_that_cannot_take_the_json_lands_no_file(tmp_path: Path):
    pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    # the refusal of UTF-16 came after the Parquet file had landed
    result = subprocess.run(
        [sys.executable, "-m", "assur", "dynamics", str(FOUR_BAR), "--angles",
         "0:10:5", "--json", "--parquet", "u.parquet", "--csv", "u.csv"],
        cwd=tmp_path,
        env=subprocess_env(PYTHONIOENCODING="utf-16"),
        capture_output=True,
        timeout=120,
        check=False,
    )  # fmt: skip
    assert (result.returncode, result.stdout) == (2, b"")
    assert "its encoding (utf-16)" in result.stderr.decode("utf-16")
    assert list(tmp_path.iterdir()) == []


CRANK_ALONE = """format = 1
name = "crank alone"
[links.crank]
mass = 2.0
center = "A"
inertia = 0.01
[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]
[[drivers]]
joint = "A"
omega = 50.0
[[loads]]
link = "crank"
torque = -2.0
[motor]
torque = 10.0
no_load_speed = 60.0
"""


def figures(out: str) -> dict[str, str]:
    """The summary's lines by label (continuation lines under the label before)."""
    found: dict[str, str] = {}
    label = ""
    for line in out.split("\n\n")[0].splitlines()[1:]:
        label = line[:38].strip() or label
        found[label] = (found.get(label, "") + " " + line[38:].strip()).strip()
    return found


def test_a_constant_speed_and_a_motor_s_own_speed_are_said(capsys, tmp_path):
    # a crank of constant inertia under a constant load: "largest speed 50 rad/s at
    # 0.175781 deg" and the same smallest, a delta of integration noise, and no word
    # that the motor (10 N m falling to 0 at 60 rad/s) runs it at 48, not 50
    path = tmp_path / "crank.toml"
    path.write_text(CRANK_ALONE, encoding="utf-8")
    status, out, _ = run(
        capsys, "dynamics", path, "--flywheel", "0.04", "--startup", "--angles", "0"
    )
    assert status == 0
    lines = figures(out)
    assert lines["crank speed"] == "constant, 50 rad/s"
    assert "largest speed" not in lines
    assert "smallest speed" not in lines
    # the file's motor: 10 (1 - 50 / 60) N m at the nominal speed
    assert lines["motor torque"].endswith(
        "(constant). The file's [motor], 1.66667 N m at the nominal 50 rad/s, "
        "drives the start-up alone."
    )
    periodic = lines["periodic motion"]
    assert re.search(r"delta = [0-9.e-]+, none within the periodic speed's", periodic)
    # M (1 - w / 60) = 2 at w = 48: 4 % below the nominal speed
    assert periodic.endswith(
        "the time-mean speed is -4 % from the nominal 50 rad/s, at which the steady "
        "state above and its delta hold"
    )


def test_a_constant_speed_turning_clockwise_is_its_size(capsys, tmp_path):
    clockwise = (
        CRANK_ALONE.replace("omega = 50.0", "omega = -50.0")
        .replace("torque = 10.0", "torque = -10.0")
        .replace("no_load_speed = 60.0", "no_load_speed = -60.0")
        .replace("torque = -2.0", "torque = 2.0")
    )
    path = tmp_path / "clockwise.toml"
    path.write_text(clockwise, encoding="utf-8")
    status, out, _ = run(
        capsys, "dynamics", path, "--flywheel", "0.04", "--angles", "0"
    )
    assert status == 0
    assert figures(out)["crank speed"] == "constant, 50 rad/s"
    # a motor of constant torque: nothing to set the steady state's torque apart
    constant = CRANK_ALONE.replace("no_load_speed = 60.0\n", "")
    path.write_text(constant, encoding="utf-8")
    status, out, _ = run(
        capsys, "dynamics", path, "--flywheel", "0.04", "--angles", "0"
    )
    assert status == 0
    assert figures(out)["motor torque"] == "2 N m (constant)"


def test_a_periodic_delta_is_none_only_below_ten_times_the_tolerance():
    from assur._dynamics_text import _run_delta
    from assur._startup_turns import PERIODIC_RTOL

    assert _run_delta(5.0 * PERIODIC_RTOL).endswith(
        ", none within the periodic speed's tolerance"
    )
    assert _run_delta(20.0 * PERIODIC_RTOL) == f"{20.0 * PERIODIC_RTOL:.6g}"


def test_a_crank_angle_is_said_on_the_dial_where_it_is_past_a_turn():
    from assur._text import crank_angle_text as dial

    assert dial(0.0) == "0 deg"
    assert dial(359.5) == "359.5 deg"
    assert dial(360.0) == "360 deg (that is, 0 deg)"
    assert dial(float("nan")) == "nan deg"
    assert dial(-30.0, "°") == "-30° (that is, 330°)"
    # a millionth below a turn, written with an exponent: the turn, 0 on the dial
    assert dial(-6e-7) == "-6e-07 deg (that is, 0 deg)"


def test_an_angle_past_a_turn_is_said_on_the_dial_too(capsys):
    # angles count on from the reference pose (60 deg): 364.72 deg is 4.72 deg
    status, _, err = run(capsys, "dynamics", EXAMPLES / "offset_slider_crank.toml")
    assert status == 2
    found = re.search(
        r"come to rest at crank angle ([0-9.]+) deg \(that is, ([0-9.]+) deg\)", err
    )
    assert found is not None
    assert float(found[1]) - 360.0 == pytest.approx(float(found[2]), abs=1e-3)
    status, out, _ = run(
        capsys, "dynamics", EXAMPLES / "whitworth.toml", "--delta", "0.05"
    )
    estimates = figures(out)["classical estimates"]
    sizing = assur.flywheel_sizing(assur.load(EXAMPLES / "whitworth.toml"), 0.05)
    assert f"Mertsalov {sizing.mertsalov:.6g} (+0.0167 %)" in estimates
    status, out, _ = run(
        capsys, "dynamics", EXAMPLES / "whitworth.toml", "--delta", "0.05", "--json"
    )
    assert json.loads(out)["flywheel"]["mertsalov"] == sizing.mertsalov
    # the smallest speed at the end of the scotch yoke's turn: 360 deg, not 4e-09
    status, out, _ = run(
        capsys, "dynamics", EXAMPLES / "scotch_yoke.toml", "--delta", "0.05"
    )
    assert figures(out)["smallest speed"].endswith("at 360 deg (that is, 0 deg)")


@pytest.mark.parametrize("option", ["--csv", "--startup-csv", "--parquet"])
def test_a_table_named_as_a_folder_is_refused_before_the_model(
    capsys, monkeypatch, tmp_path: Path, option: str
):
    # the model, then the start-up, were computed before the folder was found
    def unread(*_args):
        msg = "the mechanism was read"
        raise AssertionError(msg)

    monkeypatch.setattr("assur.dynamics_cli.load_mechanism", unread)
    line = one_error(capsys, "dynamics", WHITWORTH, "--delta", "0.05", option, tmp_path)
    fault = "cannot write the file (it is a folder); expected a file"
    assert line == f"assur: error: {tmp_path}: {fault}"


def test_a_speed_that_varies_without_work_is_explained(capsys):
    # no loads: "energy swing 0 J" stood beside "delta = 0.254" with no word why
    path = EXAMPLES / "slider_crank_exercise.toml"
    t = assur.dynamics(assur.load(path), [0.0])
    assert t.energy_swing == 0.0 < t.delta
    status, out, _ = run(capsys, "dynamics", path, "--angles", "0")
    assert status == 0
    why = "No load does work: the speed varies with the links' reduced inertia alone."
    assert figures(out)["energy swing"] == f"0 J. {why}"
    # the notebook's figures say it too
    assert f"0 J. {why}</td>" in t._repr_html_().replace("&#x27;", "'")
    # loads that do work over the turn: the swing needs no word
    status, out, _ = run(capsys, "dynamics", WHITWORTH, "--delta", "0.05")
    assert figures(out)["energy swing"].endswith(" J")
    assert "No load does work" not in out


def test_a_clockwise_crank_s_file_motor_is_read_at_its_speed(capsys) -> None:
    # the falling motor's torque at the crank's own speed (-25 rad/s), the speed
    # itself written as a size beside "nominal"
    from assur._text import number_text

    path = Path(__file__).parent / "data" / "edge" / "four_bar_motor_clockwise.toml"
    motor = assur.load(path).motor
    assert motor is not None
    assert motor.at(-25.0) != motor.at(25.0)
    status, out, _ = run(capsys, "dynamics", path, "--flywheel", "0.01")
    assert status == 0
    torque = number_text(motor.at(-25.0))
    assert f"The file's [motor], {torque} N m at the nominal 25 rad/s, drives" in out


@pytest.mark.parametrize(
    ("speeds", "swing", "energy", "said"),
    [
        ((11.0, 9.0), 0.0, 50.0, True),  # no work: the reduced inertia alone
        ((10.0, 10.0), 0.0, 50.0, False),  # nothing varies: nothing to explain
        ((11.0, 9.0), 1e-9 * 50.0, 50.0, False),  # a little work is work
        ((11.0, 9.0), 1e-14 * 5e6, 5e6, True),  # round-off of a large energy
    ],
)
def test_an_energy_swing_of_none_says_why_the_speed_varies(
    speeds, swing, energy, said
) -> None:
    from types import SimpleNamespace

    from assur._dynamics_text import swing_text
    from assur._text import number_text

    result = SimpleNamespace(
        speed_max=speeds[0], speed_min=speeds[1], energy_swing=swing, energy=energy
    )
    text = swing_text(result)
    assert text.startswith(f"{number_text(swing)} J")
    assert ("No load does work" in text) is said


@pytest.mark.parametrize("size", [1.0, 1e-200])
def test_a_motor_against_omega_is_told_at_any_size(size) -> None:
    # the signs compared: the product of two small numbers underflowed to -0.0
    from assur._motor import against_omega

    assert against_omega(assur.Motor(-size), size) is not None
    assert against_omega(assur.Motor(size), -size) is not None
    assert against_omega(assur.Motor(size), size) is None
    assert against_omega(assur.Motor(-size), -size) is None


@pytest.mark.parametrize("size", [1.0, 1e-200])
def test_a_braking_motor_torque_is_told_at_any_size(size) -> None:
    # the signs compared: the product of two small numbers underflowed to -0.0
    from types import SimpleNamespace

    from assur._dynamics_text import _motor_note

    def brakes(motor: float, omega: float) -> bool:
        return "it brakes" in _motor_note(motor, SimpleNamespace(omega=omega))

    assert brakes(-size, size)
    assert brakes(size, -size)
    assert not brakes(size, size)
    assert not brakes(-size, -size)
    assert not brakes(0.0, size)
    assert not brakes(0.0, -size)


def test_a_mean_torque_of_none_points_to_what_sizes_the_motor(capsys):
    from assur._dynamics_text import NO_MEAN_TORQUE
    from assur.html import render_report

    # masses only: inertia gives back its work, the mean torque is 0
    mech = assur.load(FOUR_BAR)
    t = assur.dynamics(mech, [0.0])
    assert t.motor == 0.0
    status, out, _ = run(capsys, "dynamics", FOUR_BAR, "--angles", "0")
    assert status == 0
    assert (
        f"motor torque                          0 N m (constant). {NO_MEAN_TORQUE}"
        in out
    )
    assert NO_MEAN_TORQUE in t._repr_html_()
    report = render_report(mech, np.arange(0.0, 360.0, 30.0))
    assert NO_MEAN_TORQUE in report
    # the figures it names are the forces' summary's
    summary = assur.forces(mech, np.arange(0.0, 360.0, 30.0)).summary()
    named = re.findall(r"driver\.torque\.\w+", NO_MEAN_TORQUE)
    assert named
    assert set(named) <= set(summary)
    # a cutting force takes work over a turn: the mean torque sizes the motor
    status, out, _ = run(capsys, "dynamics", WHITWORTH, "--delta", "0.05")
    assert status == 0
    assert "No load does net work" not in out
    whitworth = assur.load(WHITWORTH)
    assert "No load does net work" not in render_report(
        whitworth, np.arange(0.0, 360.0, 30.0)
    )
