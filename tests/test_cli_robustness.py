"""The command line under stress: Ctrl-C, closed or failing outputs, odd options.

Every fault is one line on standard error and exit status 2 (130 after Ctrl-C); an
output that cannot be written is named, not the mechanism file; the old file of an
output survives a failed write.
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import assur
from assur import _cli_process, cli
from assur._cli_common import MAX_POSITIONS, parse_angles
from assur.errors import ModelError, UsageError

from .conftest import EXAMPLES
from .conftest import run_cli as run

ROOT = Path(__file__).resolve().parent.parent
FOUR_BAR = EXAMPLES / "four_bar.toml"
SLIDER = EXAMPLES / "slider_crank_exercise.toml"


def one_error(capsys, *argv) -> str:
    """Run ``argv``; check exit 2 and one error line; return the line."""
    status, out, err = run(capsys, *argv)
    assert status == 2, err
    assert out == ""
    assert "Traceback" not in err
    assert err.count("\n") == 1, err
    assert err.startswith("assur: error: ")
    return err.rstrip("\n")


def subprocess_env(**extra: str) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), **extra)
    env.pop("PYTHONIOENCODING", None)
    env.update(extra)
    return env


# --- Ctrl-C ---------------------------------------------------------------------


def test_ctrl_c_anywhere_is_status_130(monkeypatch, capsys):
    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "_cmd_structure", interrupted)
    status, _out, err = run(capsys, "structure", FOUR_BAR)
    assert status == 130
    assert err == "assur: interrupted\n"


@pytest.mark.parametrize(
    ("stop", "status", "said"),
    [
        (signal.SIGINT, 130, "interrupted"),
        (signal.SIGTERM, 143, "terminated"),
        (getattr(signal, "SIGHUP", signal.SIGTERM), None, "terminated"),
    ],
)
def test_a_stop_during_an_animation_keeps_the_old_file(
    tmp_path: Path, stop, status, said
):
    # Ctrl-C, and the signals that end a job (timeout, a CI cancel, a closed
    # terminal), remove the hidden temporary file and keep the old one
    target = tmp_path / "film.gif"
    target.write_bytes(b"the old film")
    process = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "assur",
            "animate",
            str(FOUR_BAR),
            "--angles",
            "0:3600:1",
            "--frames",
            "1000",
            "-o",
            str(target),
        ],
        cwd=tmp_path,
        env=subprocess_env(PYTHONFAULTHANDLER="1"),
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 60
    # wait until the film is being written, in its temporary file
    while len(os.listdir(tmp_path)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    process.send_signal(stop)
    try:
        _out, err = process.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        # the command went on after the stop: where it was, for the report (its
        # faulthandler writes every thread's stack on SIGABRT)
        process.send_signal(signal.SIGABRT)
        _out, err = process.communicate()
        pytest.fail(f"still running 60 s after {stop!r}; its stacks:\n{err[-4000:]}")
    finally:
        # ended and waited for: a process left running failed the next test too
        process.kill()
        process.wait()
    assert process.returncode == (128 + stop if status is None else status), err
    assert err == f"assur: {said}\n"
    assert target.read_bytes() == b"the old film"
    assert os.listdir(tmp_path) == ["film.gif"]


@pytest.mark.parametrize("posix", [True, False], ids=["kill", "interrupt_main"])
@pytest.mark.parametrize(
    ("stop", "raised"),
    [(signal.SIGTERM, _cli_process._Stopped), (signal.SIGINT, KeyboardInterrupt)],
)
def test_a_stop_that_python_ignores_comes_again(
    capsys, monkeypatch, stop, raised, posix
):
    # SIGTERM or Ctrl-C handled inside a __del__ (or a weakref callback of
    # matplotlib's): Python ignores the exception raised there, and the animation
    # went on to its end; the signal is sent again until it unwinds the command,
    # unreported (on Windows, where os.kill would end the process, through the
    # main thread's interruption)
    monkeypatch.setattr(_cli_process, "POSIX", posix)

    class Finalized:
        def __del__(self) -> None:
            os.kill(os.getpid(), stop)
            time.sleep(0.05)  # the handler runs here, its exception ignored

    waited = [0.0]

    def command() -> None:
        with _cli_process._stoppable():
            Finalized()
            started = time.monotonic()
            while waited[0] < 10.0:
                waited[0] = time.monotonic() - started
                time.sleep(0.01)

    with pytest.raises(raised):
        command()
    assert waited[0] < 5.0
    assert "Exception ignored" not in capsys.readouterr().err
    # and once the command is over, no signal comes after it
    time.sleep(2 * _cli_process.RESEND)


@pytest.mark.parametrize("stop", [signal.SIGTERM, signal.SIGINT])
def test_a_stop_whose_exception_is_lost_comes_again(stop):
    # C code calling back into Python may clear the exception a stop raised there,
    # with no report at all: the command ran on; the stop is sent again while it does
    lost = []

    def command() -> None:
        with _cli_process._stoppable():
            try:
                os.kill(os.getpid(), stop)
                time.sleep(1.0)  # the handler runs here
            except BaseException as swallowed:  # as such code does, silently
                lost.append(swallowed)
            started = time.monotonic()
            while time.monotonic() - started < 10.0:
                time.sleep(0.01)

    started = time.monotonic()
    with pytest.raises((_cli_process._Stopped, KeyboardInterrupt)) as caught:
        command()
    assert time.monotonic() - started < 5.0
    assert len(lost) == 1
    assert type(caught.value) is type(lost[0])
    time.sleep(2 * _cli_process.RESEND)


@pytest.mark.parametrize("inner", [False, True], ids=["cleanup", "its-own-error"])
@pytest.mark.parametrize(
    ("stop", "raised"),
    [(signal.SIGTERM, _cli_process._Stopped), (signal.SIGINT, KeyboardInterrupt)],
)
def test_a_stop_during_the_cleanup_of_another_lets_it_end(stop, raised, inner):
    # a second stop (the watchdog's, or the user's) while the first one unwinds the
    # command is passed over: the temporary file's removal is not cut short, nor
    # where that removal handles an error of its own (a file already gone)
    cleaned = []

    def second() -> None:
        os.kill(os.getpid(), stop)
        # longer than RESEND: the first stop's own resend comes here too
        time.sleep(3 * _cli_process.RESEND)

    def command() -> None:
        with _cli_process._stoppable():
            try:
                os.kill(os.getpid(), stop)
                time.sleep(1.0)
            finally:
                if inner:
                    try:
                        raise FileNotFoundError(errno.ENOENT, "gone")
                    except FileNotFoundError:
                        second()
                else:
                    second()
                cleaned.append(True)

    with pytest.raises(raised):
        command()
    assert cleaned == [True]
    time.sleep(2 * _cli_process.RESEND)


class _Timers:
    """Stand-in for ``threading.Timer``: each one made is kept, none runs by itself."""

    def __init__(self) -> None:
        self.made: list[tuple[object, tuple[int, ...]]] = []

    def __call__(self, interval: float, function: object, args: tuple[int, ...]):
        self.made.append((function, args))
        return SimpleNamespace(daemon=False, start=lambda: None, cancel=lambda: None)


@pytest.fixture
def timers(monkeypatch) -> tuple[list[tuple[object, tuple[int, ...]]], list[int]]:
    """The timers armed (function, arguments) and the signals they sent."""
    made = _Timers()
    sent: list[int] = []
    monkeypatch.setattr(threading, "Timer", made)
    monkeypatch.setattr(_cli_process, "_resend", sent.append)
    return made.made, sent


def test_a_command_run_while_its_caller_handles_a_stop_still_stops():
    # the caller's own KeyboardInterrupt, being handled as the command runs, is not
    # one of the command's: a stop then ends the command as always
    def command() -> None:
        with _cli_process._stoppable():
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(2.0)

    try:
        raise KeyboardInterrupt
    except KeyboardInterrupt:
        started = time.monotonic()
        with pytest.raises(_cli_process._Stopped):
            command()
        assert time.monotonic() - started < 1.0
    time.sleep(2 * _cli_process.RESEND)


def test_a_stop_is_sent_again_only_while_the_command_runs(timers):
    # a resend already on its way when the command ends is dropped: the handlers
    # are the caller's again, and SIGTERM's default would end the process
    made, sent = timers
    with _cli_process._stoppable():
        with contextlib.suppress(_cli_process._Stopped):  # the exception lost
            signal.raise_signal(signal.SIGTERM)
        ((send, args),) = made
        send(*args)
        assert sent == [signal.SIGTERM]
    send(*args)
    assert sent == [signal.SIGTERM]


@pytest.mark.parametrize(
    ("stop", "own"), [(signal.SIGTERM, False), (signal.SIGINT, True)]
)
def test_a_stop_python_ignores_is_armed_once(timers, stop, own):
    # ours arms a resend as it raises; one raised by the caller's own SIGINT
    # handler is armed where Python reports it ignored, and that handler is kept
    made, _ = timers

    def theirs(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    class Finalized:
        def __del__(self) -> None:
            signal.raise_signal(stop)  # its exception ignored

    before = signal.signal(signal.SIGINT, theirs if own else signal.default_int_handler)
    try:
        with _cli_process._stoppable():
            if own:
                assert signal.getsignal(signal.SIGINT) is theirs
            Finalized()
    finally:
        signal.signal(signal.SIGINT, before)
    assert [args for _, args in made] == [(stop,)]


def test_a_stop_as_the_command_ends_leaves_no_handler_behind(monkeypatch):
    # a stop coming in the block that puts the handlers back (a resend whose
    # command ended on its own) raised there: ours stayed, and the timers ran on
    real = threading.Lock
    before = signal.getsignal(signal.SIGTERM)

    class Tripping:
        """The lock the block takes: a stop lands as it is taken."""

        def __init__(self) -> None:
            self._lock = real()

        def __enter__(self) -> Tripping:
            self._lock.acquire()
            signal.raise_signal(signal.SIGTERM)  # its handler runs on return
            return self

        def __exit__(self, *exc: object) -> None:
            self._lock.release()

    made = []

    def lock() -> object:
        made.append(True)
        return Tripping() if len(made) == 1 else real()

    monkeypatch.setattr(threading, "Lock", lock)
    try:
        with _cli_process._stoppable():
            pass
        assert signal.getsignal(signal.SIGTERM) is before
    finally:
        signal.signal(signal.SIGTERM, before)


# --- outputs that fail ----------------------------------------------------------


def test_output_error_names_the_output_not_the_input(tmp_path: Path, capsys):
    target = tmp_path / "no" / "such" / "t.csv"
    line = one_error(capsys, "kinematics", FOUR_BAR, "--angles", "0", "--csv", target)
    assert line == (
        f"assur: error: {target}: cannot write the file (No such file or directory)"
    )


def test_a_picture_writer_that_fails_keeps_the_old_picture(
    monkeypatch, tmp_path: Path, capsys
):
    import matplotlib.figure

    target = tmp_path / "m.pdf"
    target.write_bytes(b"the old picture")

    def broken(self, path, **kwargs):
        Path(path).write_bytes(b"half a pict")
        msg = "'Stream' object has no attribute 'pos'"
        raise AttributeError(msg)

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", broken)
    line = one_error(capsys, "plot", FOUR_BAR, "-o", target)
    assert line == (
        f"assur: error: {target}: cannot write the file (AttributeError: 'Stream' "
        "object has no attribute 'pos')"
    )
    assert target.read_bytes() == b"the old picture"
    assert os.listdir(tmp_path) == ["m.pdf"]


def test_diagrams_land_all_or_none(monkeypatch, tmp_path: Path, capsys):
    from assur import plotting

    out = tmp_path / "d"
    out.mkdir()
    (out / "motion.png").write_bytes(b"old motion")

    def broken(table):
        msg = "No space left on device"
        raise OSError(28, msg)

    monkeypatch.setattr(plotting, "draw_decomposition", broken)
    line = one_error(capsys, "diagrams", FOUR_BAR, "--dpi", "20", "-o", out)
    assert (
        line == f"assur: error: {out}: cannot write the file (No space left on device)"
    )
    assert os.listdir(out) == ["motion.png"]
    assert (out / "motion.png").read_bytes() == b"old motion"


def read_fifo(fifo: Path, limit: int | None, into: list[bytes]) -> threading.Thread:
    """Start a reader of ``fifo`` that stops after ``limit`` bytes (None: all)."""

    def reader() -> None:
        with open(fifo, "rb") as stream:
            into.append(stream.read() if limit is None else stream.read(limit))

    thread = threading.Thread(target=reader)
    thread.start()
    return thread


def test_csv_into_a_fifo(tmp_path: Path, capsys):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[bytes] = []
    thread = read_fifo(fifo, None, received)
    status, out, err = run(
        capsys, "kinematics", FOUR_BAR, "--angles", "0:90:10", "--csv", fifo
    )
    thread.join(timeout=30)
    assert status == 0, err
    table = assur.kinematics(assur.load(FOUR_BAR), np.arange(0.0, 91.0, 10.0))
    assert out == f"wrote 10 rows x {len(table.columns)} columns to {fifo}\n"
    assert received == [table.to_csv().encode()]
    assert os.listdir(tmp_path) == ["pipe"]


def test_a_fifo_whose_reader_stops_early_is_one_error(tmp_path: Path, capsys):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[bytes] = []
    thread = read_fifo(fifo, 100, received)
    line = one_error(
        capsys, "kinematics", FOUR_BAR, "--angles", "0:360:0.05", "--csv", fifo
    )
    thread.join(timeout=30)
    assert line == f"assur: error: {fifo}: cannot write the file (Broken pipe)"


def on_ascii(tmp_path: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    """Run ``assur ARGV`` in ``tmp_path`` with standard streams in ASCII."""
    return with_env(tmp_path, {"PYTHONIOENCODING": "ascii"}, *argv)


def with_env(
    tmp_path: Path, extra: dict[str, str], *argv: str
) -> subprocess.CompletedProcess[str]:
    """Run ``assur ARGV`` in ``tmp_path`` with the environment's ``extra`` values."""
    return subprocess.run(
        [sys.executable, "-m", "assur", *argv],
        cwd=tmp_path,
        env=subprocess_env(**extra),
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def shell(tmp_path: Path, command: str) -> subprocess.CompletedProcess[str]:
    """Run ``assur COMMAND`` in a shell (which reads ``| cat``, ``>&-`` and such)."""
    return subprocess.run(
        f"{sys.executable} -m assur {command}",
        shell=True,
        cwd=tmp_path,
        env=subprocess_env(),
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def piped(tmp_path: Path, options: str) -> subprocess.CompletedProcess[str]:
    """Run ``assur kinematics FOUR_BAR --angles 0 OPTIONS | cat`` in a shell."""
    return shell(tmp_path, f"kinematics {FOUR_BAR} --angles 0 {options} | cat")


def test_csv_to_dev_stdout_in_a_pipe(tmp_path: Path):
    result = piped(tmp_path, "--csv /dev/stdout")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("angle,crank.angle,")
    # the table alone: no "wrote ..." line after it in the stream
    table = assur.kinematics(assur.load(FOUR_BAR), [0.0])
    lines = result.stdout.splitlines()
    assert len(lines) == 2
    assert lines[1].count(",") == len(table.columns) - 1
    assert "wrote" not in result.stderr


def test_a_note_or_a_picture_to_dev_stdout_is_as_to_minus(tmp_path: Path):
    # "unknown type of note '(none)'" and "unknown file type '(none)'" they said
    note = shell(tmp_path, f"explain {FOUR_BAR} -o /dev/stdout | cat")
    assert note.stderr == ""
    assert note.stdout == shell(tmp_path, f"explain {FOUR_BAR} -o - | cat").stdout
    assert note.stdout.startswith("# Crank-rocker four-bar at crank angle")
    picture = shell(tmp_path, f"plot {FOUR_BAR} -o /dev/stdout | cat")
    assert picture.stderr == (
        f"assur: error: {FOUR_BAR}: -o /dev/stdout: standard output cannot take a "
        "picture; expected a file name ending in .png, .svg or .pdf\n"
    )
    assert os.listdir(tmp_path) == []


def test_dev_stdout_beside_json_is_refused(tmp_path: Path):
    # /dev/stdout is where --json writes too: the two tables came out mixed
    result = piped(tmp_path, "--json --csv /dev/stdout")
    assert result.returncode == 0  # cat's
    assert result.stdout == ""
    assert result.stderr == (
        f"assur: error: {FOUR_BAR}: --csv /dev/stdout and --json: both write to "
        "standard output; expected one of them (or --csv PATH)\n"
    )


def test_a_file_name_ending_with_a_slash_is_refused(tmp_path: Path, capsys):
    # a Path drops the slash: "--csv out/" wrote a file named out
    target = f"{tmp_path / 'out'}/"
    line = one_error(capsys, "kinematics", FOUR_BAR, "--angles", "0", "--csv", target)
    assert line == (
        f"assur: error: {target}: cannot write the file (the name ends with '/', as "
        "a folder's); expected a file name"
    )
    with pytest.raises(assur.OutputError, match="the name ends with '/'"):
        assur.save(assur.catalog.four_bar(), target)
    assert os.listdir(tmp_path) == []


# --- outputs over the input -----------------------------------------------------


def test_csv_over_the_mechanism_file_is_refused(tmp_path: Path, capsys):
    mech = tmp_path / "m.toml"
    mech.write_bytes(FOUR_BAR.read_bytes())
    os.link(mech, tmp_path / "hard.toml")
    for name in (mech, tmp_path / "sub" / ".." / "m.toml", tmp_path / "hard.toml"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        line = one_error(capsys, "forces", mech, "--angles", "0", "--csv", name)
        assert line == (
            f"assur: error: {mech}: --csv {name}: is the mechanism file being read; "
            "expected another file for the output"
        )
    assert mech.read_bytes() == FOUR_BAR.read_bytes()


@pytest.mark.parametrize(
    ("command", "name"),
    [("plot", "m.png"), ("animate", "m.gif"), ("report", "m.html")],
)
def test_a_picture_over_the_mechanism_file_is_refused(
    command, name, tmp_path: Path, capsys
):
    mech = tmp_path / name
    mech.write_bytes(FOUR_BAR.read_bytes())
    line = one_error(capsys, command, mech, "-o", mech)
    assert line.endswith(
        f"-o {mech}: is the mechanism file being read; expected "
        "another file for the output"
    )
    assert mech.read_bytes() == FOUR_BAR.read_bytes()


def test_diagrams_over_the_mechanism_file_are_refused(tmp_path: Path, capsys):
    mech = tmp_path / "paths.png"
    mech.write_bytes(FOUR_BAR.read_bytes())
    line = one_error(capsys, "diagrams", mech, "-o", tmp_path)
    assert "is the mechanism file being read" in line
    assert os.listdir(tmp_path) == ["paths.png"]


# --- options --------------------------------------------------------------------


def test_a_misspelt_command_gets_a_suggestion(capsys):
    status, out, err = run(capsys, "forcse", FOUR_BAR)
    assert status == 2
    assert out == ""
    assert err.splitlines()[-1] == (
        "assur: error: unknown command 'forcse'; did you mean 'forces'?"
    )
    status, _, err = run(capsys, "zzz", FOUR_BAR)
    assert status == 2
    assert err.splitlines()[-1].startswith(
        "assur: error: unknown command 'zzz' (known: animate, diagrams, dynamics, "
        "explain, forces, "
    )


def test_plot_names_its_own_option(capsys, tmp_path: Path):
    line = one_error(
        capsys, "plot", FOUR_BAR, "--angle", "abc", "-o", tmp_path / "a.png"
    )
    assert line == (
        f"assur: error: {FOUR_BAR}: --angle: cannot read 'abc'; expected a number, "
        "one per driver separated by commas"
    )
    # a number out of range is read, and said to be no position
    line = one_error(capsys, "explain", FOUR_BAR, "--angle", "1e400")
    assert line == (
        f"assur: error: {FOUR_BAR}: --angle: not a finite number: '1e400'; expected "
        "a number, one per driver separated by commas"
    )


@pytest.mark.parametrize(
    "spec",
    ["0:1:1e-320", "-1e308:1e308:1e300", "0:1e308:1e-308", "0:1e9:1e-3", "0:10:1e-300"],
)
def test_absurd_ranges_are_one_usage_error(spec, capsys):
    line = one_error(capsys, "kinematics", FOUR_BAR, f"--angles={spec}")
    assert line.startswith(f"assur: error: {FOUR_BAR}: --angles: '{spec}' gives ")
    assert line.endswith(f"positions; expected at most {MAX_POSITIONS} (a larger step)")
    # a count of 300 digits was printed whole
    assert len(line) < 200
    with pytest.raises(UsageError):
        parse_angles(spec)


def test_option_errors_are_usage_errors_not_model_errors():
    with pytest.raises(UsageError) as info:
        parse_angles("abc")
    assert not isinstance(info.value, ModelError)
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("joint", ["Q", "C"])
def test_the_driver_option_is_a_usage_error(monkeypatch, joint, capsys):
    seen = []
    monkeypatch.setattr(cli, "_error", seen.append)
    path = EXAMPLES / "class3.toml"
    status = cli.main(["structure", str(path), "--driver", joint])
    assert status == 2
    with pytest.raises(UsageError, match=r"^--driver: "):
        cli._cmd_structure(argparse.Namespace(file=path, driver=joint, json=False))
    assert seen[0].startswith(f"{path}: --driver: ")


def test_a_long_option_is_echoed_briefly(capsys):
    line = one_error(capsys, "kinematics", FOUR_BAR, "--angles", "1:" * 5000)
    assert len(line) < 300


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["plot", "--dpi", "inf"],
            "--dpi inf: expected a positive resolution from 10 to 1200 dots per inch",
        ),
        (["plot", "--dpi", "1e6"], "--dpi 1e+06: expected a positive resolution"),
        (["plot", "--dpi", "nan"], "--dpi nan: expected a positive resolution"),
        (["diagrams", "--dpi", "5"], "--dpi 5: expected a positive resolution"),
        (
            ["animate", "--dpi", "600"],
            "--dpi 600: expected a positive resolution from 10 to 300 dots per inch",
        ),
        (
            ["animate", "--fps", "1e-9"],
            "--fps 1e-09: expected a frame rate from 0.1 to 50 frames per second",
        ),
        # a GIF's delays are whole hundredths of a second, and browsers play one of
        # 1 or less as 10: 60 and 100 would play at 10 frames per second
        (
            ["animate", "--fps", "60"],
            "--fps 60: expected a frame rate from 0.1 to 50 frames per second (a "
            "GIF's delays are whole hundredths of a second",
        ),
        (["animate", "--fps", "100"], "--fps 100: expected a frame rate"),
        (["animate", "--fps", "1000"], "--fps 1000: expected a frame rate"),
        (["animate", "--fps", "nan"], "--fps nan: expected a frame rate"),
        (
            ["animate", "--frames", "100000"],
            "--frames 100000: expected at least one frame and at most 1000",
        ),
        (["plot", "--scale", "inf"], "--scale inf: expected a positive number"),
        (["plot", "--scale", "nan"], "--scale nan: expected a positive number"),
    ],
)
def test_bounded_options(argv, message, tmp_path: Path, capsys):
    suffix = {"plot": ".png", "animate": ".gif", "diagrams": ""}[argv[0]]
    target = tmp_path / f"out{suffix}"
    target.write_bytes(b"a good old output") if suffix else None
    line = one_error(capsys, argv[0], FOUR_BAR, *argv[1:], "-o", target)
    assert line.startswith(f"assur: error: {FOUR_BAR}: {message}"), line
    if suffix:
        assert target.read_bytes() == b"a good old output"
    else:
        assert not target.exists()


def test_the_summary_says_what_it_leaves_out(capsys):
    status, out, _ = run(capsys, "kinematics", FOUR_BAR, "--angles", "0:720:1")
    assert status == 0
    lines = out.splitlines()
    assert len(lines) == 2 + 400 + 2
    assert lines[-2] == "... 321 more rows: --csv PATH or --json for all"
    status, out, _ = run(capsys, "kinematics", FOUR_BAR, "--angles", "0:399:1")
    assert "more rows" not in out


def test_non_ascii_names_on_an_ascii_terminal(tmp_path: Path):
    text = FOUR_BAR.read_text(encoding="utf-8").replace('"coupler"', '"coupleur→"')
    text = text.replace("[links.coupler]", '[links."coupleur→"]')
    mech = tmp_path / "u.toml"
    mech.write_text(text, encoding="utf-8")
    # what a person reads shows the name escaped; a CSV table would hold it changed,
    # and is refused (test_a_name_standard_output_cannot_write_is_one_error)
    for argv in (
        ["structure"],
        ["kinematics", "--angles", "0"],
        ["forces", "--angles", "0", "--json"],
    ):
        result = subprocess.run(
            [sys.executable, "-m", "assur", argv[0], str(mech), *argv[1:]],
            env=subprocess_env(PYTHONIOENCODING="ascii"),
            capture_output=True,
            text=True,
            encoding="ascii",
            timeout=60,
            check=False,
        )
        assert result.returncode == 0, (argv, result.stderr)
        assert result.stderr == ""
        assert (
            "coupleur\\u2192" in result.stdout or "coupleur\\\\u2192" in result.stdout
        )


def _closed(tmp_path: Path, command: str) -> subprocess.CompletedProcess[str]:
    """Run ``assur COMMAND`` with standard output closed (``>&-``)."""
    return shell(tmp_path, f"{command} >&-")


def test_a_closed_standard_output(tmp_path: Path):
    # Python leaves sys.stdout None: every command ended in an AttributeError
    result = _closed(tmp_path, f"-q forces {FOUR_BAR} --angles 0:10:5 --csv t.csv")
    assert (result.returncode, result.stderr) == (0, "")
    assert len((tmp_path / "t.csv").read_text(encoding="utf-8").splitlines()) == 1 + 3
    for command in (f"explain {FOUR_BAR}", f"forces {FOUR_BAR} --angles 0"):
        result = _closed(tmp_path, command)
        assert result.returncode == 2
        assert result.stderr == (
            "assur: error: standard output: cannot write (standard output is closed)\n"
        )


@pytest.mark.parametrize("command", ["--help", "forces --help"])
def test_help_to_a_full_disk_is_an_error(tmp_path: Path, command: str):
    # argparse dropped the write's error: no help, exit 0
    result = shell(tmp_path, f"{command} > /dev/full")
    assert result.returncode == 2
    assert result.stderr == (
        "assur: error: standard output: cannot write (No space left on device)\n"
    )


TRUSS = """format = 1
[links.a]
[links.b]
[joints.O]
kind = "revolute"
links = ["ground", "a"]
at = [0.0, 0.0]
[joints.P]
kind = "revolute"
links = ["a", "b"]
at = [0.05, 0.05]
[joints.Q]
kind = "revolute"
links = ["b", "ground"]
at = [0.1, 0.0]
"""


@pytest.mark.parametrize(
    "command",
    [
        ["kinematics"],
        ["forces"],
        ["explain"],
        ["plot", "-o", "{tmp}/p.png"],
        ["plans", "-o", "{tmp}/plans"],
        ["report", "-o", "{tmp}/r.html"],
        # the table's columns were made before any check: an IndexError
        ["kinematics", "--angles", "0"],
        ["forces", "--angles", "0:10:5", "--csv", "-"],
        ["kinematics", "--angles", "0", "--parquet", "{tmp}/k.parquet"],
        # a class III mechanism, said the structure of a truss
        ["structure"],
        ["structure", "--json"],
    ],
)
def test_a_structure_without_drivers_is_one_line(tmp_path, capsys, command):
    # a triangle on the frame (W = 0, no driver) passes the count and decomposes:
    # the default sweep of its drivers was min() of nothing, a traceback
    path = tmp_path / "truss.toml"
    path.write_text(TRUSS, encoding="utf-8")
    argv = [c.format(tmp=tmp_path) for c in command]
    line = one_error(capsys, argv[0], path, *argv[1:])
    assert line == (
        f"assur: error: {path}: drivers: the mechanism has no driver, and W = 3*2 - "
        "2*3 - 0 = 0: "
        "the chain is a statically determinate structure (a truss), not a mechanism; "
        "expected links that can move, "
        "with a [[drivers]] entry for each degree of freedom"
    )
    assert sorted(p.name for p in tmp_path.iterdir()) == ["truss.toml"]


def test_a_driver_added_to_a_structure_is_said_not_to_help(tmp_path, capsys):
    path = tmp_path / "truss.toml"
    path.write_text(TRUSS + '[[drivers]]\njoint = "O"\nomega = 1.0\n', "utf-8")
    line = one_error(capsys, "kinematics", path)
    assert line.endswith(
        "; expected links that can move (W >= 1), one driver per degree of freedom"
    )


# --- empty names ------------------------------------------------------------------

EMPTY_NAMES = [
    ("kinematics", "--csv", "file"),
    ("forces", "--parquet", "file"),
    ("dynamics", "--csv", "file"),
    ("dynamics", "--startup-csv", "file"),
    ("explain", "--output", "file"),
    ("explain", "--answers", "file"),
    ("plot", "--output", "file"),
    ("animate", "--output", "file"),
    ("report", "--output", "file"),
    ("diagrams", "--output", "folder"),
    ("plans", "--output", "folder"),
]


@pytest.mark.parametrize(("command", "option", "what"), EMPTY_NAMES)
@pytest.mark.parametrize("form", ["joined", "apart"])
def test_an_empty_name_is_refused(
    monkeypatch, capsys, tmp_path: Path, command, option, what, form
):
    # --csv= printed the table and wrote nothing; --output= wrote into the current
    # folder and removed its pictures of the set's names; --csv '' was "expected one
    # argument" (empty arguments were dropped)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "torque.png").write_bytes(b"the user's picture")
    given = [f"{option}="] if form == "joined" else [option, ""]
    line = one_error(capsys, command, SLIDER, *given)
    shown = "-o/--output" if option == "--output" else option
    assert line == (
        f"assur: error: {command}: argument {shown}: expected a {what} name, got an "
        f"empty one (see 'assur {command} --help')"
    )
    assert os.listdir(tmp_path) == ["torque.png"]


def test_an_empty_mechanism_file_name_is_refused(capsys):
    line = one_error(capsys, "kinematics", "")
    assert line.startswith(
        "assur: error: kinematics: argument file: expected a file name, got an empty "
        "one"
    )


def _table_in(
    tmp_path: Path, encoding: str, option: str
) -> subprocess.CompletedProcess[bytes]:
    """Run ``assur forces`` with its table (``--csv -`` or ``--json``) on standard
    output in ``encoding``; return what came out, as bytes."""
    argv = ["forces", str(EXAMPLES / "four_bar.toml"), "--angles", "0:10:5"]
    argv += [option] if option else []
    return subprocess.run(
        [sys.executable, "-m", "assur", *argv, *(["-"] if option == "--csv" else [])],
        cwd=tmp_path,
        env=subprocess_env(PYTHONIOENCODING=encoding),
        capture_output=True,
        timeout=120,
        check=False,
    )


@pytest.mark.parametrize("option", ["--csv", "--json"])
def test_standard_output_in_utf16_is_refused(tmp_path: Path, option: str) -> None:
    # the header came out in UTF-16 (with its mark), the rows' numbers in ASCII:
    # a stream that reads as neither
    result = _table_in(tmp_path, "utf-16", option)
    assert (result.returncode, result.stdout) == (2, b"")
    assert result.stderr.decode("utf-16") == (
        "assur: error: standard output: its encoding (utf-16) does not write numbers "
        "as ASCII; expected a file (written in UTF-8) or standard output in UTF-8 "
        "(PYTHONIOENCODING=utf-8)\n"
    )


@pytest.mark.parametrize("option", ["--csv", "--json", ""])
def test_standard_output_in_utf8_with_its_mark_is_written_as_utf8(
    tmp_path: Path, option: str
) -> None:
    # a spreadsheet's UTF-8 (with a byte-order mark) is ASCII's numbers too: the
    # table was refused; its JSON, and the readable table's last line written by
    # print(), each had a mark of their own inside the text
    result = _table_in(tmp_path, "utf-8-sig", option)
    assert result.returncode == 0, result.stderr
    assert b"\xef\xbb\xbf" not in result.stdout
    text = result.stdout.decode("utf-8")
    if option == "--json":
        assert len(json.loads(text)["rows"]) == 3
    elif option == "--csv":
        assert text.splitlines()[0].startswith("angle,crank.angle,")
    else:
        assert "columns in all" in text.splitlines()[-1]


def test_a_name_standard_output_cannot_write_is_one_error(tmp_path: Path) -> None:
    # on an ASCII output the CSV's names came out as \u0448..., changed silently
    text = (EXAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace("[links.rocker]", '[links."шатун"]')
    (tmp_path / "cyr.toml").write_text(
        text.replace('"rocker"', '"шатун"'), encoding="utf-8"
    )

    def ascii_run(*options: str) -> subprocess.CompletedProcess[str]:
        return on_ascii(tmp_path, "forces", "cyr.toml", *options, "--angles", "0:10:5")

    result = ascii_run("--csv", "-")
    assert (result.returncode, result.stdout) == (2, "")
    # standard error is ASCII too: the name is escaped in the message alone
    assert result.stderr == (
        "assur: error: standard output: its encoding (ascii) cannot write "
        "'\\u0448\\u0430\\u0442\\u0443\\u043d' of the table; expected a file "
        "(written in UTF-8) or standard output in UTF-8 (PYTHONIOENCODING=utf-8)\n"
    )
    # JSON escapes them as JSON does: the names read back unchanged
    result = ascii_run("--json")
    assert "шатун.angle" in json.loads(result.stdout)["columns"]


def test_a_note_over_its_answers_file_is_refused(tmp_path: Path, capsys):
    # the note replaced the answers it was to be checked against
    answers = tmp_path / "answers.md"
    text = '[answers]\n"rod.omega" = -54.2\n'
    answers.write_text(text, encoding="utf-8")
    line = one_error(
        capsys, "explain", SLIDER, "--angle", "45", "--answers", answers, "-o", answers
    )
    assert line.endswith(
        f"-o {answers}: is the answers file being read; expected another file for "
        "the output"
    )
    assert answers.read_text(encoding="utf-8") == text


def test_standard_output_into_the_mechanism_file_is_refused(tmp_path: Path) -> None:
    # the table (or a "wrote" line) was added to the very file being read
    source = tmp_path / "m.toml"
    source.write_text(FOUR_BAR.read_text(encoding="utf-8"), encoding="utf-8")
    before = source.read_bytes()
    for options in ("--csv -", "--csv out.csv", "--json"):
        done = shell(tmp_path, f"kinematics m.toml --angles 0:3:1 {options} >> m.toml")
        assert done.returncode == 2, options
        assert done.stderr == (
            "assur: error: m.toml: standard output is the mechanism file being read "
            "(a redirection to it); expected another file for the output\n"
        )
        assert source.read_bytes() == before
    # another file, or a pipe, is as before
    elsewhere = shell(tmp_path, "kinematics m.toml --angles 0 --csv - > t.csv")
    assert elsewhere.returncode == 0


def test_an_unknown_matplotlib_backend_in_the_environment_is_passed_over(
    tmp_path: Path,
) -> None:
    # MPLBACKEND=nonsense stopped matplotlib's import with a traceback
    argv = ("plot", str(FOUR_BAR), "-o", "p.png", "-q")
    done = with_env(tmp_path, {"MPLBACKEND": "nonsense"}, *argv)
    assert (done.returncode, done.stderr) == (0, "")
    assert (tmp_path / "p.png").stat().st_size > 1000


def test_an_error_standard_error_cannot_take_is_still_status_2(tmp_path: Path) -> None:
    # printing the error line to a full disk raised OSError: status 1
    done = shell(tmp_path, "structure none.toml 2>/dev/full")
    assert done.returncode == 2


def test_matplotlib_s_layout_advice_is_not_passed_on(capsys, monkeypatch):
    # a picture of 80 links' panels: "constrained_layout not applied because axes
    # sizes collapsed to zero. Try making figure larger", a traceback-like line
    import argparse
    import warnings

    from assur import cli

    def drawing(args: argparse.Namespace) -> int:
        warnings.warn("constrained_layout not applied: ...", UserWarning, stacklevel=1)
        warnings.warn("another of matplotlib's", UserWarning, stacklevel=1)
        return 0

    shown: list[str] = []
    with warnings.catch_warnings():
        warnings.simplefilter("default")  # as a command line's process has them
        monkeypatch.setattr(warnings, "showwarning", lambda m, *a: shown.append(str(m)))
        assert cli._run(drawing, argparse.Namespace(file="m.toml")) == 0
    assert shown == ["another of matplotlib's"]


def test_off_posix_a_stop_is_sent_again_without_os_kill(monkeypatch):
    # os.kill on Windows ends the process at once (its status the signal's number)
    import _thread

    killed, interrupted = [], []
    monkeypatch.setattr(_cli_process, "POSIX", False)
    monkeypatch.setattr(_cli_process.os, "kill", lambda *a: killed.append(a))
    monkeypatch.setattr(_thread, "interrupt_main", interrupted.append)
    _cli_process._resend(signal.SIGTERM)
    assert killed == []
    assert interrupted == [signal.SIGTERM]
