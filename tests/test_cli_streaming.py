"""Long sweeps on the command line: slice by slice, the same output as one table.

The slices are made small here (8192 positions, and the library's own slice as
many) so that a sweep of a few tens of thousands of positions crosses several of
them.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur import _cli_summary, _cli_sweep, _sliced, _state, cli
from assur._cli_common import parse_angles

from .conftest import run_cli as run

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
SLIDER_CRANK = EXAMPLES / "slider_crank_exercise.toml"
SKIP_HINT = " (--skip-unassembled leaves such positions out)"
"""What the command line adds to a position it cannot solve (the library does not)."""
WHITWORTH = EXAMPLES / "whitworth.toml"  # its block and lever turn round and round


@pytest.fixture
def small_slices(monkeypatch):
    monkeypatch.setattr(_state, "CHUNK", 8192)
    monkeypatch.setattr(_sliced, "CHUNK", 8192)


def whole(command: str, path: Path, spec: str, skip: bool = False):
    """The table of the whole sweep at once, and its warnings."""
    mech = assur.load(path)
    given = parse_angles(spec, max(1, len(mech.drivers)))
    analyse = assur.forces if command == "forces" else assur.kinematics
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = analyse(mech, given, skip_unassembled=skip)
    return table, [str(w.message) for w in caught]


@pytest.mark.parametrize(
    ("command", "path", "spec"),
    [
        ("kinematics", WHITWORTH, "-170:40000:1.7"),  # 94 turns, 3 slices
        ("forces", WHITWORTH, "400:-20000:-0.9"),  # backwards
        ("forces", SLIDER_CRANK, "0:16384:1"),  # exactly two slices and a row
        ("kinematics", EXAMPLES / "five_bar_two_cranks.toml", "0:9000:0.5,90:9090:0.5"),
    ],
)
def test_csv_slice_by_slice_is_the_whole_table(
    small_slices, tmp_path, capsys, command, path, spec
):
    target = tmp_path / "t.csv"
    status, out, err = run(capsys, command, path, "--angles", spec, "--csv", target)
    assert status == 0, err
    table, _ = whole(command, path, spec)
    assert len(table) > 8192 * 2
    assert target.read_text(encoding="utf-8") == table.to_csv()
    assert (
        out == f"wrote {len(table)} rows x {len(table.columns)} columns to {target}\n"
    )
    assert err == ""


def test_angles_run_on_across_slices(small_slices, tmp_path, capsys):
    spec = "-170:40000:1.7"
    run(capsys, "kinematics", WHITWORTH, "--angles", spec, "--csv", tmp_path / "t.csv")
    values = np.loadtxt(tmp_path / "t.csv", delimiter=",", skiprows=1)
    header = (tmp_path / "t.csv").read_text(encoding="utf-8").split("\n", 1)[0]
    lever = values[:, header.split(",").index("lever.angle")]
    assert np.abs(np.diff(lever)).max() < 180.0  # no jump of a turn anywhere
    assert lever[-1] - lever[0] > 360.0 * 90


def test_json_slice_by_slice_is_the_whole_table(small_slices, capsys):
    spec = "0:20000:1.1"
    status, out, _ = run(capsys, "forces", SLIDER_CRANK, "--angles", spec, "--json")
    assert status == 0
    table, _ = whole("forces", SLIDER_CRANK, spec)
    assert out == json.dumps(table.to_dict()) + "\n"


def test_parquet_slice_by_slice(small_slices, tmp_path, capsys):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    spec = "-170:30000:1.3"
    target = tmp_path / "t.parquet"
    status, out, _ = run(
        capsys, "forces", WHITWORTH, "--angles", spec, "--parquet", target
    )
    assert status == 0
    table, _ = whole("forces", WHITWORTH, spec)
    read = pq.read_table(target)
    assert pq.ParquetFile(target).num_row_groups == 3  # one per slice
    assert read.column_names == list(table.columns)
    for name in table.columns:
        np.testing.assert_array_equal(read.column(name).to_numpy(), table[name])
        assert read.schema.field(name).metadata == {
            b"unit": table.column(name).unit.encode()
        }
    assert (
        out == f"wrote {len(table)} rows x {len(table.columns)} columns to {target}\n"
    )


def test_csv_and_parquet_from_one_sweep(tmp_path, capsys):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    csv, parquet = tmp_path / "t.csv", tmp_path / "t.parquet"
    status, out, _ = run(
        capsys, "kinematics", SLIDER_CRANK, "--csv", csv, "--parquet", parquet
    )
    assert status == 0
    table = assur.kinematics(assur.load(SLIDER_CRANK), parse_angles("45:404:1"))
    assert csv.read_text(encoding="utf-8") == table.to_csv()
    assert pq.read_table(parquet).num_rows == len(table) == 360
    assert out.splitlines() == [
        f"wrote 360 rows x {len(table.columns)} columns to {csv}",
        f"wrote 360 rows x {len(table.columns)} columns to {parquet}",
    ]


def test_near_dead_centre_warned_once_across_slices(
    small_slices, double_rocker, capsys
):
    # a run of positions near a dead centre (about 17.26 to 17.30 deg, where the
    # group starts to assemble) that the boundary between the first two slices cuts
    spec = f"{17.28 - 8192 * 0.001}:30:0.001"
    status, _, err = run(
        capsys, "kinematics", double_rocker, "--angles", spec, "--skip-unassembled"
    )
    assert status == 0
    _, messages = whole("kinematics", double_rocker, spec, skip=True)
    assert len(messages) == 1
    assert " to " in messages[0].rpartition("positions ")[2]
    note, warning = err.splitlines()  # the note as the command goes, then warnings
    assert note.startswith(f"assur: note: {double_rocker}: left out ")
    assert warning == f"assur: warning: {double_rocker}: {messages[0]}"


def test_many_runs_near_dead_centres_are_cut_as_one_table_cuts_them(
    small_slices, double_rocker, capsys
):
    # twenty runs over ten turns, in 44 slices (the other circuit's twenty, about
    # 278.9 and 342.7 deg, are left out: the mechanism cannot reach them)
    spec = "0:3600:0.01"
    status, _, err = run(
        capsys, "kinematics", double_rocker, "--angles", spec, "--skip-unassembled"
    )
    assert status == 0
    _, messages = whole("kinematics", double_rocker, spec, skip=True)
    assert messages[0].endswith("; ...")
    lines = err.splitlines()
    assert lines[1] == f"assur: warning: {double_rocker}: {messages[0]}"
    table, _ = whole("kinematics", double_rocker, spec, skip=True)
    # the runs of positions left out: broken where a kept position lies between
    left = np.ravel(table.skipped)
    breaks = np.flatnonzero(np.diff(left) > 0.015) + 1
    runs = [(run[0], run[-1]) for run in np.split(left, breaks)]
    assert len(runs) > 6  # some left unnamed
    shown = "; ".join(f"{a:g} deg to {b:g} deg" for a, b in runs[:6]) + "; ..."
    assert lines[0] == (
        f"assur: note: {double_rocker}: left out {len(table.skipped)} positions "
        "where a group cannot be assembled, stands at a dead centre or a change "
        "point, or is locked by friction, or that the mechanism cannot reach from "
        "its reference pose: "
        f"{shown}"
    )
    assert len(lines) == 2


def test_a_failure_in_a_later_slice_is_reported_for_the_whole_sweep(
    small_slices, double_rocker, tmp_path, capsys
):
    spec = "20:100:0.004"  # assembles up to about 96 deg: the third slice fails
    target = tmp_path / "t.csv"
    target.write_text("old", encoding="utf-8")
    status, out, err = run(
        capsys, "kinematics", double_rocker, "--angles", spec, "--csv", target
    )
    assert status == 2
    mech = assur.load(double_rocker)
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(mech, parse_angles(spec))
    assert err == f"assur: error: {double_rocker}: {caught.value}{SKIP_HINT}\n"
    assert "of 20001 positions fail" in err
    assert target.read_text(encoding="utf-8") == "old"
    assert sorted(os.listdir(tmp_path)) == ["double_rocker.toml", "t.csv"]
    assert out == ""
    # the positions are solved first: not one row reaches standard output
    for output in (["--csv", "-"], ["--json"]):
        status, out, err = run(
            capsys, "forces", double_rocker, "--angles", spec, *output
        )
        assert (status, out) == (2, "")
        assert "of 20001 positions fail" in err


@pytest.mark.parametrize(
    ("command", "spec", "friction"),
    [
        ("kinematics", "0:720:0.02", None),  # two runs fail, in three slices
        ("forces", "150:359:0.005", 1.5),  # locked in two slices
    ],
)
def test_a_failure_over_several_slices_is_counted_as_the_whole_sweep(
    small_slices, tmp_path, capsys, command, spec, friction
):
    # the sweep is solved again slice by slice for its message, keeping only where
    # each slice fails: the counts and ranges are the whole sweep's all the same
    if friction is None:
        # cannot be assembled from about 112 to 248 deg
        mech = assur.catalog.four_bar(
            crank=0.06, coupler=0.07, rocker=0.0645, frame=0.1, angle=30.0
        )
        path = tmp_path / "four_bar.toml"
        assur.save(mech, path)
    else:
        text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
        path = tmp_path / "locks.toml"
        path.write_text(
            text.replace("friction = 0.8", f"friction = {friction}"), encoding="utf-8"
        )
    mech = assur.load(path)
    given = parse_angles(spec)
    analyse = assur.forces if command == "forces" else assur.kinematics
    with pytest.raises(assur.AssurError) as whole:
        analyse(mech, given)
    failing = re.search(r"\((\d+) of \d+ positions", str(whole.value))
    assert failing is not None
    assert int(failing[1]) > 8192  # more than one of the library's slices
    status, out, err = run(
        capsys, command, path, "--angles", spec, "--csv", tmp_path / "t.csv"
    )
    assert (status, out) == (2, "")
    assert err == f"assur: error: {path}: {whole.value}{SKIP_HINT}\n"
    assert f"of {len(given)} positions" in err


def test_the_readable_table_of_a_long_sweep(small_slices, capsys):
    status, out, _ = run(capsys, "kinematics", WHITWORTH, "--angles", "0:20000:1")
    assert status == 0
    table, _ = whole("kinematics", WHITWORTH, "0:20000:1")
    lines = out.splitlines()
    assert lines[-2] == f"... {20001 - 400} more rows: --csv PATH or --json for all"
    last = lines[-3].split()
    picked = _cli_summary.summary_columns(table, forces=False)
    assert last == [f"{table[c][399]:.6g}" for c in picked]


# --- options ------------------------------------------------------------------------


def test_two_tables_on_standard_output_are_refused(capsys):
    status, _, err = run(capsys, "forces", SLIDER_CRANK, "--csv", "-", "--json")
    assert status == 2
    assert err == (
        f"assur: error: {SLIDER_CRANK}: --csv - and --json: both write to standard "
        "output; expected one of them (or --csv PATH)\n"
    )


def test_parquet_to_standard_output_is_refused(capsys):
    status, _, err = run(capsys, "forces", SLIDER_CRANK, "--parquet", "-")
    assert status == 2
    assert "--parquet -: a Parquet file is not text; expected a file name" in err


def test_parquet_without_pyarrow_is_one_error(tmp_path, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    target = tmp_path / "t.parquet"
    status, _, err = run(capsys, "kinematics", SLIDER_CRANK, "--parquet", target)
    assert status == 2
    assert err == (
        f"assur: error: {SLIDER_CRANK}: --parquet {target}: writing Parquet needs "
        "pyarrow, which is not installed; expected 'pip install pyarrow' (or 'pip "
        'install "assur[parquet]"\')\n'
    )
    assert not target.exists()


def test_csv_path_and_json_write_the_lines_to_standard_error(tmp_path, capsys):
    target = tmp_path / "t.csv"
    status, out, err = run(
        capsys,
        "kinematics",
        SLIDER_CRANK,
        "--angles",
        "0:10:5",
        "--csv",
        target,
        "--json",
    )
    assert status == 0
    assert json.loads(out)["columns"][0] == "angle"
    assert err.startswith("wrote 3 rows x ")


# --- progress and --quiet ---------------------------------------------------------


@pytest.fixture
def long_is_short(monkeypatch):
    monkeypatch.setattr(_cli_sweep, "BAR_DELAY", 0.0)


@pytest.mark.parametrize("output", [[], ["--csv", "t.csv"]])
def test_a_bar_on_a_terminal(long_is_short, capsys, monkeypatch, tmp_path, output):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, _, err = run(
        capsys, "forces", SLIDER_CRANK, "--angles", "0:5000:1", *output
    )
    assert status == 0
    assert "forces:" in err
    assert "%|" in err


@pytest.mark.parametrize("stdout_tty", [True, False])
@pytest.mark.parametrize(
    "output", [["--csv", "-"], ["--json"], ["--summary", "--json"], ["--summary"]]
)
def test_no_bar_over_a_table_streamed_to_the_terminal(
    long_is_short, capsys, monkeypatch, output, stdout_tty
):
    # the bar's redrawn line ran into the CSV's rows on the screen
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    monkeypatch.setattr(sys.stdout, "isatty", lambda: stdout_tty)
    status, out, err = run(
        capsys, "forces", SLIDER_CRANK, "--angles", "0:5000:1", *output
    )
    assert status == 0
    assert out
    # a table piped on (standard output not a terminal) keeps the bar, and so
    # does a summary, printed once the sweep is done
    streams = "--summary" not in output
    assert ("%|" in err) is not (stdout_tty and streams)


def test_no_bar_when_standard_error_is_not_a_terminal(long_is_short, capsys):
    status, _, err = run(capsys, "forces", SLIDER_CRANK, "--angles", "0:5000:1")
    assert status == 0
    assert err == ""


def test_no_bar_for_a_short_sweep(capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, _, err = run(capsys, "forces", SLIDER_CRANK, "--angles", "0:5000:1")
    assert status == 0
    assert err == ""


@pytest.mark.parametrize("where", ["before", "after"])
def test_quiet(long_is_short, capsys, monkeypatch, tmp_path, double_rocker, where):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    target = tmp_path / "t.csv"
    args = [
        "kinematics",
        double_rocker,
        "--angles",
        "0:360:0.1",
        "--skip-unassembled",
        "--csv",
        target,
    ]
    args = ["--quiet", *args] if where == "before" else [*args, "-q"]
    status, out, err = run(capsys, *args)
    assert status == 0
    assert out == ""
    # no bar, no note, no "wrote" line; the warning stays
    assert err.count("\n") == 1
    assert err.startswith(f"assur: warning: {double_rocker}: group RRR")
    assert target.read_text(encoding="utf-8").startswith("angle,")


def test_quiet_readable_table_keeps_the_table(capsys):
    status, out, _ = run(capsys, "-q", "kinematics", SLIDER_CRANK, "--angles", "0")
    assert status == 0
    assert out.splitlines()[0].split()[0] == "angle"
    assert "columns in all" not in out


# --- the readable table's columns come from the schema ------------------------------


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_summary_columns_as_the_names_picked_them(path):
    mech = assur.load(path)
    given = assur.analysis.default_positions(mech)[:3]
    kinematics = assur.kinematics(mech, given, skip_unassembled=True)
    by_name = [
        "angle",
        *(c for c in kinematics.columns if c.endswith((".angle", ".omega", ".alpha"))),
    ]
    assert _cli_summary.summary_columns(kinematics, forces=False) == by_name
    try:
        forces = assur.forces(mech, given, skip_unassembled=True)
    except assur.ModelError:
        return  # no masses, no loads
    drivers = {
        f"{d.joint}.{what}"
        for d in mech.drivers
        for what in ("torque", "force", "torque_check", "force_check")
    }
    by_name = [
        "angle",
        *(
            c
            for c in forces.columns
            if c.endswith(".F") or c.startswith("driver.") or c in drivers
        ),
    ]
    assert _cli_summary.summary_columns(forces, forces=True) == by_name


def test_units_of_the_readable_table(capsys):
    status, out, _ = run(capsys, "kinematics", SLIDER_CRANK, "--angles", "45")
    assert status == 0
    heads, units = out.splitlines()[:2]
    table = assur.kinematics(assur.load(SLIDER_CRANK), [45.0])
    assert units.split() == [f"[{table.column(h).unit}]" for h in heads.split()]
    assert "[rad/s^2]" in units.split()
    status, out, _ = run(capsys, "forces", SLIDER_CRANK, "--angles", "45")
    units = out.splitlines()[1]
    assert "[N m]" in units
    assert units.isascii()


# --- memory -----------------------------------------------------------------------


PEAK = """
import resource, sys
import assur.analysis, assur.cli
from assur import _sliced
_sliced.CHUNK = int(sys.argv[1])
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
status = assur.cli.main(sys.argv[2:])
after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print((after - before) // 1024)  # kB on Linux
sys.exit(status)
"""


def test_memory_stays_that_of_one_slice(tmp_path):
    # 200,000 positions of 79 columns: the whole table takes 126 MB of numbers (and
    # its states as much again); slices of 8192 positions take a few MB each
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            PEAK,
            "8192",
            "kinematics",
            str(SLIDER_CRANK),
            "--angles",
            "0:199999:1",
            "--csv",
            str(tmp_path / "t.csv"),
        ],
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert result.returncode == 0, result.stderr
    grown = int(result.stdout.splitlines()[-1])
    assert grown < 90, f"{grown} MB more than after the imports"


def test_parquet_into_a_fifo(tmp_path, capsys):
    pq = pytest.importorskip("pyarrow.parquet", reason="pyarrow is not installed")
    import io
    import threading

    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[bytes] = []

    def reader() -> None:
        with open(fifo, "rb") as stream:
            received.append(stream.read())

    thread = threading.Thread(target=reader)
    thread.start()
    status, _, err = run(capsys, "kinematics", SLIDER_CRANK, "--parquet", fifo)
    thread.join(timeout=30)
    assert status == 0, err
    assert pq.read_table(io.BytesIO(received[0])).num_rows == 360
    assert os.listdir(tmp_path) == ["pipe"]


@pytest.mark.parametrize("command", ["kinematics", "forces"])
def test_two_outputs_to_one_file_are_refused(tmp_path, capsys, command):
    # written in turn, the second would replace the first: refused before any work,
    # whatever the spelling of the path
    target = tmp_path / "same.out"
    other = f"{tmp_path}/./same.out"
    status, out, err = run(
        capsys, command, SLIDER_CRANK, "--csv", target, "--parquet", other
    )
    assert (status, out) == (2, "")
    assert err == (
        f"assur: error: {SLIDER_CRANK}: --parquet {other}: is the file of --csv too; "
        "expected a file of its own for each output\n"
    )
    assert not target.exists()


@pytest.mark.parametrize(
    ("stdout", "files"),
    [("--json", ["--csv", "out.csv"]), ("--csv", ["-", "--parquet", "out.parquet"])],
)
def test_a_reader_that_goes_away_leaves_the_files_whole(tmp_path: Path, stdout, files):
    # ``assur ... --json --csv t.csv | head``: standard output stops, the file asked
    # for is still written to the end (it kept an old file and said status 0)
    if "--parquet" in files:
        pytest.importorskip("pyarrow")
    target = tmp_path / files[-1]
    target.write_text("old\n", encoding="utf-8")
    command = [
        sys.executable, "-m", "assur", "kinematics", str(SLIDER_CRANK),
        "--angles", "0:36000:1", stdout, *files[:-1], str(target),
    ]  # fmt: skip
    with subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, cwd=tmp_path
    ) as run:
        assert run.stdout is not None
        assert run.stderr is not None
        assert len(run.stdout.read(100)) == 100
        run.stdout.close()  # the reader goes
        errors = run.stderr.read().decode()
        status = run.wait()
    assert status == 0, errors
    assert "error" not in errors
    assert "Traceback" not in errors
    rows = len(parse_angles("0:36000:1"))
    if target.suffix == ".csv":
        lines = target.read_text(encoding="utf-8").splitlines()
        assert lines[0].startswith("angle,")
        assert len(lines) == rows + 1
    else:
        import pyarrow.parquet as pq

        assert pq.read_table(target).num_rows == rows
    assert sorted(p.name for p in tmp_path.iterdir()) == [target.name]


def test_friction_that_locks_is_counted_over_the_whole_sweep(
    small_slices, tmp_path: Path, capsys
):
    # the slice where the group locked gave its own counts ("of 8192 positions")
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    path = tmp_path / "locks.toml"
    path.write_text(text.replace("friction = 0.8", "friction = 1.5"), encoding="utf-8")
    mech = assur.load(path)
    given = parse_angles("150:240:0.005")
    with pytest.raises(assur.SelfLockingError) as whole:
        assur.forces(mech, given)
    assert f"of {len(given)} positions" in str(whole.value)
    status = cli.main(
        ["forces", str(path), "--angles", "150:240:0.005", "--csv", str(tmp_path / "t")]
    )
    assert status == 2
    err = capsys.readouterr().err
    assert err == f"assur: error: {path}: {whole.value}{SKIP_HINT}\n"


@pytest.mark.parametrize("output", [["--json"], ["--csv", "-"]])
def test_friction_locking_in_a_later_slice_writes_nothing(
    capsys, monkeypatch, tmp_path, output
):
    from assur import _sliced

    # the check of the whole sweep solved positions only: the slices before the
    # lock went to standard output (206 MB of a JSON never closed), then the error
    monkeypatch.setattr(_sliced, "CHUNK", 8)  # 31 positions: four slices
    text = (EXAMPLES / "slider_crank_locking.toml").read_text(encoding="utf-8")
    path = tmp_path / "lock.toml"
    path.write_text(text.replace("friction = 0.8", "friction = 1.3"), encoding="utf-8")
    status = cli.main(["forces", str(path), "--angles", "200:260:2", *output])
    out, err = capsys.readouterr()
    assert (status, out) == (2, "")
    assert "its friction locks it at driver position 248 deg (7 of 31 positions)" in err


def test_friction_of_a_prismatic_driver_is_checked_slice_by_slice(capsys, monkeypatch):
    # the check of a long sweep with friction asked for driver.torque, which a
    # prismatic driver has not (its balancing load is driver.force)
    monkeypatch.setattr(_sliced, "CHUNK", 8)  # 21 positions: three slices
    path = Path(__file__).parent / "data" / "friction" / "ram_up_a_steep_guide.toml"
    status = cli.main(["forces", str(path), "--angles", "0:0.02:0.001", "--csv", "-"])
    out, err = capsys.readouterr()
    assert status == 0, err
    header, *rows = out.splitlines()
    assert "driver.force" in header.split(",")
    assert len(rows) == 21


@pytest.mark.parametrize(
    ("values", "chunk"),
    [
        (1 << 24, 65536),
        (109 * _state.CHUNK * 3, 3 * _state.CHUNK),  # a whole number of the library's
        (109 * 5000, 4096),
        (10, 64),
    ],
)
def test_a_slice_holds_a_bounded_number_of_values(monkeypatch, values, chunk):
    # a chain of 300 dyads (17 736 columns) took 65 536 positions a slice: 9 GB
    mech = assur.load(SLIDER_CRANK)
    assert len(assur.forces(mech, [0.0]).columns) == 109
    monkeypatch.setattr(_sliced, "SLICE_VALUES", values)
    assert _sliced._chunk(mech, True) == chunk


@pytest.mark.parametrize(
    ("library", "rows"), [(4096, 5 * 4096 + 7), (_state.CHUNK, 3 * _state.CHUNK + 5)]
)
def test_a_slice_is_a_whole_number_of_the_library_s(monkeypatch, library, rows):
    # the library's slice as it is when called (a test's smaller one too), and
    # whole ones of it: every number is then the one table's
    mech = assur.load(SLIDER_CRANK)
    monkeypatch.setattr(_state, "CHUNK", library)
    monkeypatch.setattr(_sliced, "SLICE_VALUES", 109 * rows)
    assert _sliced._chunk(mech, True) == rows // library * library


def test_slices_smaller_than_the_library_s_give_its_numbers(
    capsys, monkeypatch, tmp_path
):
    monkeypatch.setattr(_sliced, "SLICE_VALUES", 109 * 100)  # 64 positions a slice
    target = tmp_path / "t.csv"
    angles = "0:1000:0.7"
    status, _, _ = run(
        capsys, "forces", SLIDER_CRANK, "--angles", angles, "--csv", target
    )
    assert status == 0
    written = np.loadtxt(target, delimiter=",", skiprows=1)
    table = assur.forces(assur.load(SLIDER_CRANK), parse_angles(angles))
    assert written.shape == (len(table), 109)
    # the same numbers, to the CSV's 12 digits (another grouping: the last bit)
    np.testing.assert_allclose(written, table.to_array(), rtol=1e-11, atol=1e-9)


@pytest.mark.parametrize(
    ("command", "option", "name", "kind"),
    [
        ("forces", "--csv", "t.parquet", "CSV"),
        ("forces", "--csv", "t.json", "CSV"),
        ("kinematics", "--parquet", "t.csv", "Parquet"),
        ("dynamics", "--csv", "t.png", "CSV"),
        ("dynamics", "--startup-csv", "t.parquet", "CSV"),
    ],
)
def test_a_table_named_for_another_format_is_refused(
    capsys, monkeypatch, tmp_path, command, option, name, kind
):
    # --csv x.parquet wrote CSV text into x.parquet, without a word
    monkeypatch.chdir(tmp_path)
    status, out, err = run(capsys, command, SLIDER_CRANK, option, name)
    assert (status, out) == (2, "")
    suffix = name.rpartition(".")[2]
    assert err.rstrip("\n").endswith(
        f"{option} {name}: a .{suffix} name for {kind}; expected a name ending in "
        + (".csv or .txt" if kind == "CSV" else ".parquet or .pq")
    )
    assert err.count("\n") == 1
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("name", ["t.csv", "t.txt", "t"])
def test_a_csv_file_of_any_other_name_is_written(capsys, monkeypatch, tmp_path, name):
    monkeypatch.chdir(tmp_path)
    status, _, _ = run(
        capsys, "forces", SLIDER_CRANK, "--angles", "0:10:5", "--csv", name
    )
    assert status == 0
    assert (tmp_path / name).read_text(encoding="utf-8").startswith("angle,")


def test_the_note_of_positions_left_out_tells_each_driver_s_with_its_unit():
    # a crank and a slider: "129, 0.0647823, 130, 0.0666876" read as four
    # positions; one driver's positions took no unit
    from types import SimpleNamespace

    from assur._skipped import Skipped
    from assur.plan import compile_plan

    two = SimpleNamespace(
        drivers=[SimpleNamespace(kind="R"), SimpleNamespace(kind="P")]
    )
    found = Skipped()
    found.add(np.array([[129.0, 0.0647823], [130.0, 0.0666876]]), two)
    assert found.note("m.toml").endswith(
        ": (129 deg, 0.0647823 m); (130 deg, 0.0666876 m)"
    )
    assert "left out 2 positions " in found.note("m.toml")
    one = Skipped()
    crank = compile_plan(assur.catalog.four_bar())
    one.add(np.arange(100.0, 130.0).reshape(-1, 1), crank)
    assert one.note("m.toml").endswith(
        ": 100, 101, 102, 103, 104, 105, 106, 107, "
        "108, 109, 110, 111, 112, 113, 114, 115, 116, "
        "117, 118, 119, ... deg"
    )
    # neighbours a step of 1e-5 deg apart: "197.555" twenty times, before
    close = Skipped()
    close.add(197.55453 + 1e-5 * np.arange(3.0), crank)
    assert close.note("m.toml").endswith(": 197.55453, 197.55454, 197.55455 deg")
    single = Skipped()
    single.add(np.array([[200.0]]), crank)
    assert ": left out 1 position " in single.note("m.toml")
    assert single.note("m.toml").endswith(": 200 deg")
    # each slice with its positions: the runs of the sweep, one across the slices'
    # boundary (103 to 107 deg), and a lone position
    sweep = np.arange(100.0, 112.0)
    runs = Skipped()
    for part in (sweep[:6], sweep[6:]):
        runs.add(part[(part >= 103) & (part <= 107) | (part == 110)], crank, part)
    assert runs.note("m.toml", sweep).endswith(": 103 deg to 107 deg; 110 deg")
    assert ": left out 6 positions " in runs.note("m.toml", sweep)
    # two drivers: a row is left out whole, not where one driver's value matches
    rows = np.array([[129.0, 0.1], [130.0, 0.2], [131.0, 0.1], [132.0, 0.3]])
    pairs = Skipped()
    pairs.add(rows[[1, 3]], two, rows)
    assert pairs.marks is not None
    np.testing.assert_array_equal(pairs.marks[0], [False, True, False, True])
    # a slice given without its positions: the first positions, one by one
    runs.add(np.array([111.0]), crank)
    one_by_one = ": 103, 104, 105, 106, 107, 110, 111 deg"
    assert runs.note("m.toml", sweep).endswith(one_by_one)
