"""Outputs whole or absent (assur._output): a failed write keeps the old file.

Writers that fail midway are simulated by patching the byte writer, by a file-size
limit in a subprocess (the disk-full case) and by Ctrl-C; FIFOs are written in
place. No test leaves a temporary file behind.
"""

from __future__ import annotations

import errno
import os
import shutil
import stat
import subprocess
import sys
import tempfile
import threading
from pathlib import Path

import pytest

import assur
from assur import _output
from assur._output import (
    output_folder,
    output_path,
    write_all,
    write_bytes,
    write_text,
)
from assur.errors import AssurError, ModelError, OutputError

from .conftest import EXAMPLES
from .conftest import file_names as names

ROOT = Path(__file__).resolve().parent.parent
OLD = "the old contents\n"


@pytest.fixture
def old(tmp_path: Path) -> Path:
    path = tmp_path / "table.csv"
    path.write_text(OLD, encoding="utf-8")
    return path


def fail_midway(monkeypatch: pytest.MonkeyPatch, error: BaseException) -> None:
    """Make every byte write stop halfway through with ``error``."""

    def half_then_fail(stream, data):
        stream.write(data[: len(data) // 2])
        stream.flush()
        raise error

    monkeypatch.setattr(_output, "write_all", half_then_fail)


def test_write_text_new_and_over_an_old_file(old: Path, tmp_path: Path):
    write_text(tmp_path / "new.txt", "é\n")
    assert (tmp_path / "new.txt").read_text(encoding="utf-8") == "é\n"
    write_text(old, "new\n")
    assert old.read_text(encoding="utf-8") == "new\n"
    assert names(tmp_path) == {"table.csv", "new.txt"}


def test_a_new_file_gets_the_usual_permissions(tmp_path: Path):
    mask = os.umask(0o022)
    try:
        write_bytes(tmp_path / "a.bin", b"x")
    finally:
        os.umask(mask)
    assert stat.S_IMODE(os.stat(tmp_path / "a.bin").st_mode) == 0o644


def test_an_old_file_keeps_its_permissions(old: Path):
    old.chmod(0o640)
    write_text(old, "new\n")
    assert stat.S_IMODE(os.stat(old).st_mode) == 0o640


def test_a_write_that_fails_midway_keeps_the_old_file(monkeypatch, old: Path):
    fail_midway(monkeypatch, OSError(errno.ENOSPC, os.strerror(errno.ENOSPC)))
    with pytest.raises(OutputError) as info:
        write_text(old, "x" * 100_000)
    assert str(info.value) == (
        f"{old}: cannot write the file (No space left on device)"
    )
    assert isinstance(info.value, OSError)
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def test_a_new_file_that_fails_midway_is_not_left(monkeypatch, tmp_path: Path):
    fail_midway(monkeypatch, OSError(errno.EIO, "Input/output error"))
    with pytest.raises(OutputError, match=r"new\.csv: cannot write the file"):
        write_text(tmp_path / "new.csv", "x" * 1000)
    assert names(tmp_path) == set()


def test_ctrl_c_midway_keeps_the_old_file(monkeypatch, old: Path):
    fail_midway(monkeypatch, KeyboardInterrupt())
    with pytest.raises(KeyboardInterrupt):
        write_text(old, "x" * 1000)
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def stop_once_made(monkeypatch, call: str) -> None:
    """Make ``os.<call>`` stop (Ctrl-C) right after it made a temporary path.

    As Python runs a signal's handler as soon as the call that made it returns.
    """
    made = getattr(os, call)

    def made_then_stopped(path, *args, **kwargs):
        result = made(path, *args, **kwargs)
        if Path(path).name.startswith("."):  # a temporary name, not the target's
            raise KeyboardInterrupt
        return result

    monkeypatch.setattr(os, call, made_then_stopped)


def test_a_stop_as_the_temporary_file_is_made_leaves_nothing(monkeypatch, old: Path):
    # the stop came before the file was known to be removed (the test of a
    # stopped animation found it left, once in about thirty runs under load)
    stop_once_made(monkeypatch, "open")
    with pytest.raises(KeyboardInterrupt):
        write_text(old, "new")
    monkeypatch.undo()
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def test_a_stop_as_the_temporary_folder_is_made_leaves_nothing(
    monkeypatch, tmp_path: Path
):
    target = tmp_path / "diagrams"
    stop_once_made(monkeypatch, "mkdir")
    with pytest.raises(KeyboardInterrupt), output_folder(target):
        pass
    monkeypatch.undo()
    assert names(tmp_path) == set()


def test_a_name_taken_while_a_stop_comes_is_left_alone(monkeypatch, old: Path):
    # the temporary name drawn first is another's file: should a stop come as
    # the next is drawn, that file is not the one removed
    import secrets

    theirs = old.parent / ".table.csv.00000000.tmp.csv"
    theirs.write_text("theirs", encoding="utf-8")
    drawn = iter(["00000000"])

    def draw(size: int) -> str:
        for token in drawn:
            return token
        raise KeyboardInterrupt

    monkeypatch.setattr(secrets, "token_hex", draw)
    with pytest.raises(KeyboardInterrupt):
        write_text(old, "new")
    monkeypatch.undo()
    assert theirs.read_text(encoding="utf-8") == "theirs"
    assert old.read_text(encoding="utf-8") == OLD


def test_a_set_s_temporary_folder_is_in_its_folder_and_private(tmp_path: Path):
    # in the folder there already, on its file system (a mount point's)
    target = tmp_path / "diagrams"
    target.mkdir()
    with output_folder(target) as folder:
        assert folder.parent == target
        if os.name == "posix":
            assert stat.S_IMODE(folder.stat().st_mode) == 0o700
    with output_folder(tmp_path / "new") as folder:
        assert folder.parent == tmp_path


def test_the_current_folder_takes_a_set_of_files(monkeypatch, tmp_path: Path):
    # "." has no name: its temporary folder is made in it, as for any folder there
    monkeypatch.chdir(tmp_path)
    with output_folder(".") as folder:
        (folder / "a.png").write_text("a", encoding="utf-8")
    assert names(tmp_path) == {"a.png"}


def test_save_and_csv_go_through_the_whole_or_nothing_writer(monkeypatch, old: Path):
    fail_midway(monkeypatch, OSError(errno.ENOSPC, "No space left on device"))
    table = assur.kinematics(assur.catalog.four_bar(), [0.0, 10.0])
    with pytest.raises(OutputError):
        table.to_csv(old)
    with pytest.raises(OutputError):
        assur.save(assur.catalog.four_bar(), old)
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def test_html_report_goes_through_it(monkeypatch, tmp_path: Path):
    from assur.html import write_report

    target = tmp_path / "r.html"
    target.write_text(OLD, encoding="utf-8")
    fail_midway(monkeypatch, OSError(errno.ENOSPC, "No space left on device"))
    with pytest.raises(OutputError, match=r"r\.html: cannot write the file"):
        write_report(assur.catalog.four_bar(), target, angles=[0.0, 90.0])
    assert target.read_text(encoding="utf-8") == OLD
    assert names(tmp_path) == {"r.html"}


def test_output_path_keeps_the_suffix_and_replaces_on_success(old: Path):
    with output_path(old) as temporary:
        assert temporary.parent == old.parent
        assert temporary.suffix == ".csv"
        assert temporary != old
        temporary.write_text("new\n", encoding="utf-8")
        assert old.read_text(encoding="utf-8") == OLD
    assert old.read_text(encoding="utf-8") == "new\n"
    assert names(old.parent) == {"table.csv"}


def write_then_fail(path: Path, error: BaseException, any_error: bool = False):
    """Write half a file through output_path, then fail with ``error``."""
    with output_path(path, any_error=any_error) as temporary:
        temporary.write_text("half", encoding="utf-8")
        raise error


def fail_on_cleaning_up() -> None:
    """Fail like matplotlib's PDF writer on a full disk: again while closing."""
    try:
        raise OSError(errno.ENOSPC, "No space left on device")
    except OSError:
        msg = "'Stream' object has no attribute 'pos'"
        raise AttributeError(msg) from None


def test_output_path_reports_only_os_errors_unless_asked(old: Path):
    with pytest.raises(ValueError, match="a bug"):
        write_then_fail(old, ValueError("a bug"))
    with pytest.raises(OutputError) as info:
        write_then_fail(
            old, AttributeError("'Stream' object has no attribute 'pos'"), True
        )
    assert str(info.value) == (
        f"{old}: cannot write the file (AttributeError: 'Stream' object has no "
        "attribute 'pos')"
    )
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def test_a_writer_that_fails_while_cleaning_up_names_the_disk_fault(old: Path):
    with pytest.raises(OutputError) as info, output_path(old, any_error=True):
        fail_on_cleaning_up()
    assert str(info.value).endswith("cannot write the file (No space left on device)")
    assert old.read_text(encoding="utf-8") == OLD


def test_errors_of_assur_pass_unchanged(old: Path):
    with pytest.raises(ModelError, match=r"^bad$"):
        write_then_fail(old, ModelError("bad"), True)
    assert names(old.parent) == {"table.csv"}


def test_a_folder_or_a_missing_folder_is_an_output_error(tmp_path: Path):
    with pytest.raises(
        OutputError,
        match=r"cannot write the file \(it is a folder\); expected a file$",
    ):
        write_text(tmp_path, "x")
    missing = tmp_path / "no" / "such" / "t.csv"
    with pytest.raises(
        OutputError, match=r"t\.csv: cannot write the file \(No such file or directory"
    ):
        write_text(missing, "x")
    assert issubclass(OutputError, AssurError)


def test_a_link_is_followed_and_kept(old: Path):
    link = old.parent / "link.csv"
    link.symlink_to(old)
    write_text(link, "through the link\n")
    assert link.is_symlink()
    assert old.read_text(encoding="utf-8") == "through the link\n"


def test_a_fifo_is_written_in_place(tmp_path: Path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()))
    reader.start()
    write_bytes(fifo, b"through the pipe" * 10_000)
    reader.join(timeout=30)
    assert received == [b"through the pipe" * 10_000]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert names(tmp_path) == {"pipe"}


@pytest.fixture
def shm_old():
    """An old regular file in /dev/shm (a tmpfs under /dev), removed afterwards."""
    shm = Path("/dev/shm")
    if not shm.is_dir() or not os.access(shm, os.W_OK):
        pytest.skip("no writable /dev/shm")
    folder = Path(tempfile.mkdtemp(prefix="assur-test.", dir=shm))
    path = folder / "table.csv"
    path.write_text(OLD, encoding="utf-8")
    yield path
    shutil.rmtree(folder, ignore_errors=True)


def test_a_regular_file_under_dev_is_replaced_not_written_in_place(
    monkeypatch, shm_old: Path
):
    # /dev/shm holds regular files: a failed write kept nothing of the old one
    fail_midway(monkeypatch, KeyboardInterrupt())
    with pytest.raises(KeyboardInterrupt):
        write_text(shm_old, "x" * 1000)
    assert shm_old.read_text(encoding="utf-8") == OLD
    assert names(shm_old.parent) == {"table.csv"}
    monkeypatch.undo()
    write_text(shm_old, "new\n")
    assert shm_old.read_text(encoding="utf-8") == "new\n"
    assert names(shm_old.parent) == {"table.csv"}


def test_dev_stdout_on_a_shell_file_is_written_in_place(tmp_path: Path):
    # /dev/stdout leads through /proc/self/fd/1 to the file the shell opened: it is
    # the process's stream, written where it is, not a file to replace
    if not Path("/dev/stdout").is_symlink():
        pytest.skip("no /dev/stdout link")
    out = tmp_path / "out.txt"
    out.write_text("before\n", encoding="utf-8")
    inode = out.stat().st_ino
    code = (
        "import sys; from assur._output import write_text; "
        "write_text('/dev/stdout', 'written\\n')"
    )
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    with open(out, "a", encoding="utf-8") as stream:
        subprocess.run(
            [sys.executable, "-c", code],
            stdout=stream,
            env=env,
            check=True,
            timeout=60,
        )
    assert out.read_text(encoding="utf-8") == "written\n"
    assert out.stat().st_ino == inode
    assert names(tmp_path) == {"out.txt"}


def test_write_all_writes_again_what_a_short_write_left():
    class Short:
        def __init__(self, limit: int):
            self.data = b""
            self.limit = limit

        def write(self, view):
            chunk = bytes(view[: self.limit])
            self.data += chunk
            return len(chunk)

        def flush(self):
            pass

    stream = Short(3)
    write_all(stream, b"0123456789")
    assert stream.data == b"0123456789"
    with pytest.raises(OSError, match="took no data"):
        write_all(Short(0), b"x")


def fill_folder(target: Path, error: BaseException | None) -> None:
    """Write a new a.png through output_folder, then fail with ``error``."""
    with output_folder(target) as folder:
        (folder / "a.png").write_bytes(b"new a")
        if error is not None:
            raise error


def test_a_set_of_files_makes_its_folder_only_in_one_that_is_there(tmp_path: Path):
    # a whole tree was made for a misspelt parent, where a file's folder must exist
    with output_folder(tmp_path / "diagrams") as folder:
        (folder / "a.png").write_bytes(b"a")
    assert names(tmp_path / "diagrams") == {"a.png"}
    target = tmp_path / "no" / "such" / "diagrams"
    with (
        pytest.raises(OutputError, match=r"diagrams: cannot write the file \(No such"),
        output_folder(target) as folder,
    ):
        (folder / "a.png").write_bytes(b"a")
    assert not (tmp_path / "no").exists()


def test_a_set_of_files_lands_whole(tmp_path: Path):
    target = tmp_path / "diagrams"
    with output_folder(target) as folder:
        (folder / "a.png").write_bytes(b"a")
        (folder / "b.png").write_bytes(b"b")
        assert not target.exists()
    assert names(target) == {"a.png", "b.png"}
    assert names(tmp_path) == {"diagrams"}


def test_a_set_of_files_that_fails_midway_lands_not_at_all(tmp_path: Path):
    target = tmp_path / "diagrams"
    target.mkdir()
    (target / "a.png").write_bytes(b"old a")
    with pytest.raises(OutputError, match=r"diagrams: cannot write the file"):
        fill_folder(target, OSError(errno.ENOSPC, "No space left on device"))
    assert names(target) == {"a.png"}
    assert (target / "a.png").read_bytes() == b"old a"


def fill_three(target: Path) -> None:
    """Write new a.png, b.png and c.png through output_folder."""
    with output_folder(target) as folder:
        for name in ("a.png", "b.png", "c.png"):
            (folder / name).write_bytes(b"new")


def test_a_folder_in_a_file_s_place_is_named_before_any_file_lands(tmp_path: Path):
    # a.png was replaced, then b.png failed: half a set, and the folder named
    target = tmp_path / "diagrams"
    target.mkdir()
    (target / "a.png").write_bytes(b"old a")
    (target / "b.png").mkdir()
    with pytest.raises(OutputError) as info:
        fill_three(target)
    assert str(info.value) == (
        f"{target / 'b.png'}: cannot write the file (it is a folder); expected a file"
    )
    assert names(target) == {"a.png", "b.png"}
    assert (target / "a.png").read_bytes() == b"old a"
    assert names(tmp_path) == {"diagrams"}


def test_a_move_that_fails_midway_puts_the_old_files_back(monkeypatch, tmp_path: Path):
    target = tmp_path / "diagrams"
    target.mkdir()
    (target / "a.png").write_bytes(b"old a")
    replace = os.replace

    def fail_at_c(source, destination):
        if Path(destination).name == "c.png":
            raise OSError(errno.EACCES, "Permission denied")
        replace(source, destination)

    monkeypatch.setattr(_output.os, "replace", fail_at_c)
    with pytest.raises(OutputError) as info:
        fill_three(target)
    assert str(info.value) == (
        f"{target / 'c.png'}: cannot write the file (Permission denied)"
    )
    assert names(target) == {"a.png"}
    assert (target / "a.png").read_bytes() == b"old a"
    assert names(tmp_path) == {"diagrams"}


def test_without_hard_links_a_set_of_files_still_lands(monkeypatch, tmp_path: Path):
    # os.link raises NotImplementedError where the platform has no linkat: the
    # old files are then not kept, as on a file system without hard links
    target = tmp_path / "diagrams"
    target.mkdir()
    (target / "a.png").write_bytes(b"old a")

    def no_link(*args, **kwargs):
        msg = "link: follow_symlinks unavailable"
        raise NotImplementedError(msg)

    monkeypatch.setattr(_output.os, "link", no_link)
    fill_three(target)
    assert names(target) == {"a.png", "b.png", "c.png"}
    assert names(tmp_path) == {"diagrams"}


@pytest.mark.parametrize(
    ("system", "flags"), [("posix", os.O_RDONLY), ("nt", os.O_RDWR)]
)
def test_a_file_is_flushed_through_a_handle_its_system_can_flush(
    monkeypatch, tmp_path: Path, system: str, flags: int
):
    # Windows flushes a file only through a handle open for writing
    written = tmp_path / "t.csv"
    written.write_bytes(b"a\n")
    opened = []
    real = os.open

    def recording(path, how, *args):
        opened.append(how)
        return real(path, how, *args)

    monkeypatch.setattr(_output.os, "open", recording)
    monkeypatch.setattr(_output.os, "name", system)
    _output._sync(written)
    assert opened == [flags]


def test_a_set_of_files_into_a_new_folder(tmp_path: Path):
    # only the last folder is made (see above): its parent must be there
    target = tmp_path / "x" / "y"
    (tmp_path / "x").mkdir()
    with output_folder(target) as folder:
        (folder / "a.png").write_bytes(b"a")
    assert names(target) == {"a.png"}
    assert names(tmp_path / "x") == {"y"}
    with pytest.raises(OutputError, match=r"is a file; expected a folder"):
        fill_folder(target / "a.png", None)


LIMITED = """\
import resource, signal, sys
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
resource.setrlimit(resource.RLIMIT_FSIZE, (20_000, 20_000))
from assur.cli import main
sys.exit(main(sys.argv[1:]))
"""


def run_limited(*argv: str, cwd: Path, stdout=subprocess.PIPE):
    """Run the command line with files limited to 20 kB: a disk that fills up."""
    resource = pytest.importorskip("resource")
    assert resource
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run(
        [sys.executable, "-c", LIMITED, *argv],
        cwd=cwd,
        env=env,
        stdout=stdout,
        stderr=subprocess.PIPE,
        text=True,
        timeout=120,
        check=False,
    )


def test_csv_on_a_full_disk_keeps_the_old_file(old: Path):
    run = run_limited(
        "kinematics", str(EXAMPLES / "four_bar.toml"), "--csv", old.name, cwd=old.parent
    )
    assert run.returncode == 2
    assert run.stderr == (
        "assur: error: table.csv: cannot write the file (File too large)\n"
    )
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}


def test_pictures_on_a_full_disk_are_one_error(tmp_path: Path):
    (tmp_path / "m.pdf").write_text(OLD, encoding="utf-8")
    for argv in (["plot", "-o", "m.pdf"], ["diagrams", "--dpi", "60", "-o", "d"]):
        run = run_limited(
            argv[0],
            str(EXAMPLES / "slider_crank_exercise.toml"),
            *argv[1:],
            cwd=tmp_path,
        )
        assert run.returncode == 2
        assert run.stderr.count("\n") == 1
        assert run.stderr.startswith(f"assur: error: {argv[-1]}: cannot write the file")
        assert "Traceback" not in run.stderr
    assert (tmp_path / "m.pdf").read_text(encoding="utf-8") == OLD
    assert names(tmp_path) == {"m.pdf"}


def test_standard_output_on_a_full_disk_is_one_error(tmp_path: Path):
    with open(tmp_path / "out.csv", "w", encoding="utf-8") as out:
        run = run_limited(
            "kinematics",
            str(EXAMPLES / "four_bar.toml"),
            "--csv",
            "-",
            cwd=tmp_path,
            stdout=out,
        )
    assert run.returncode == 2
    assert run.stderr == (
        "assur: error: standard output: cannot write (File too large)\n"
    )


@pytest.mark.parametrize("any_error", [True, False])
def test_a_fault_raised_as_a_stop_unwinds_is_the_stop(old: Path, any_error: bool):
    # SIGHUP in the middle of a GIF's drawing: matplotlib, cleaning up, raised
    # "Invalid bounding box", which was told as the file's fault (exit 2, not 129)
    from assur._output import output_path

    def writing() -> None:
        with output_path(old, any_error=any_error) as temporary:
            temporary.write_text("half", encoding="utf-8")
            try:
                raise KeyboardInterrupt
            finally:
                msg = "Invalid bounding box"
                raise ValueError(msg)  # a cleanup that fails, on purpose

    with pytest.raises(KeyboardInterrupt):
        writing()
    assert old.read_text(encoding="utf-8") == OLD
    assert names(old.parent) == {"table.csv"}
