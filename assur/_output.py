"""Outputs written whole or not at all: files and sets of files.

Every file that assur writes (mechanism files, CSV tables, pictures, animations, HTML
reports) is first written to a temporary file in the target's folder and then moved
over the target with :func:`os.replace`, so that a write that fails midway (a full
disk, Ctrl-C, a killed process) leaves the old file as it was and no partial file.
Targets that are not regular files (standard output, a FIFO, a device) are written in
place. A failed write raises :class:`~assur.errors.OutputError` naming the output.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

from assur._landing import defer
from assur._stdout import StdoutError, stdout_writer, write_all, write_stdout
from assur._targets import (
    _not_a_folder,
    _target,
    a_folder,
    path_text,
    standard_output,
)
from assur.errors import AssurError, OutputError

if TYPE_CHECKING:
    from pathlib import Path

__all__ = [
    "StdoutError",
    "finishing",
    "output_folder",
    "output_path",
    "path_text",
    "standard_output",
    "stdout_writer",
    "write_all",
    "write_bytes",
    "write_stdout",
    "write_text",
]

NAME_KEPT = 80
"""Most characters of the target's name kept in a temporary name (names are short)."""


def write_text(path: str | os.PathLike[str], text: str) -> None:
    r"""Write ``text`` to the file ``path`` as UTF-8, whole or not at all.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "note.txt"
    >>> write_text(target, "one line\n")
    >>> target.read_text()
    'one line\n'
    """
    write_bytes(path, text.encode("utf-8"))


def write_bytes(path: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to the file ``path``, whole or not at all.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept.
    """
    with output_path(path) as temporary, open(temporary, "wb") as stream:
        write_all(stream, data)


@contextlib.contextmanager
def finishing(writer: Any) -> Iterator[Any]:
    """Close ``writer`` when the block succeeds; abort it (if it can) when not."""
    try:
        yield writer
    except BaseException:
        abort = getattr(writer, "abort", None)
        if abort is not None:
            with contextlib.suppress(Exception):
                abort()
        raise
    writer.close()


@contextlib.contextmanager
def output_path(
    path: str | os.PathLike[str], any_error: bool = False
) -> Iterator[Path]:
    """Yield the path a writer should write to; it replaces ``path`` on success.

    For a regular file (or a new one) the path is a temporary file beside ``path``
    with the same suffix, so writers that choose the format by the suffix
    (matplotlib's ``savefig``, GIF writers) still do; when the block ends without
    an exception the temporary file replaces ``path`` (inside
    :func:`assur._landing.together`, with the other files of its set), otherwise it
    is removed and ``path`` is left as it was. A FIFO, a device or another target
    that is not a regular file is yielded as it is and written in place.

    Parameters
    ----------
    path : str or path-like
        The output file.
    any_error : bool
        Report any exception of the writer (not only an :class:`OSError`) as an
        :class:`OutputError`: picture writers fail in many ways on a full disk.
        Errors of assur itself pass unchanged.

    Raises
    ------
    OutputError
        When the file cannot be written.
    """
    from pathlib import Path

    _not_a_folder(path)
    target, in_place = _target(Path(path))
    where = path_text(path)
    if in_place:
        with _reported(where, any_error, standard_output(target)):
            yield target
        return
    reserved: list[Path] = []
    try:
        with _reported(where, any_error):
            temporary = _reserve(target, reserved)
        with _reported(where, any_error):
            yield temporary
            _sync(temporary)
            if not defer(temporary, target, where):  # else it lands with its set
                os.replace(temporary, target)
    except BaseException:
        for made in reserved:
            _remove(made)
        raise


@contextlib.contextmanager
def output_folder(
    path: str | os.PathLike[str], any_error: bool = False
) -> Iterator[Path]:
    """Yield an empty temporary folder; on success its files move into ``path``.

    The writer puts a set of files (the diagrams of a sweep, say) in the yielded
    folder, which lies in ``path`` when that folder is there already (on its file
    system, should it be a mount point), else beside it, only its owner may enter
    it. When the block ends without an exception the
    folder ``path`` is created if need be (in its parent, which must be there) and
    every file replaces its namesake
    there; otherwise none of them lands. The temporary folder is removed either way.

    Raises
    ------
    OutputError
        When ``path`` is a file or the files cannot be written.
    """
    import shutil
    from pathlib import Path

    target = Path(path)
    where = path_text(path)
    if target.exists() and not target.is_dir():
        msg = f"{where}: is a file; expected a folder"
        raise OutputError(msg)
    # only the last folder is made, as a file's folder must be there already
    base = target if target.is_dir() else target.parent
    reserved: list[Path] = []
    try:
        with _reported(where, any_error):
            temporary = _reserve(base / target.name, reserved, folder=True)
        with _reported(where, any_error):
            yield temporary
            target.mkdir(exist_ok=True)
            _move_all(sorted(temporary.iterdir()), target, temporary)
    finally:
        for made in reserved:
            shutil.rmtree(made, ignore_errors=True)


def _move_all(items: list[Path], target: Path, temporary: Path) -> None:
    """Move every file of ``items`` into the folder ``target``, or none of them.

    Every place is checked before the first file moves: a folder in a file's place
    is refused by name. Should a move still fail, those done are undone: each old
    file was kept (a hard link in ``temporary``) and is put back.
    """
    for item in items:
        place = target / item.name
        if place.is_dir() and not place.is_symlink():
            raise OutputError(a_folder(place))
    moved: list[tuple[Path, bool, Path | None]] = []
    try:
        for item in items:
            place = target / item.name
            _sync(item)
            existed, kept = _keep_old(place, temporary)
            try:
                os.replace(item, place)
            except OSError as err:
                reason = err.strerror or err
                msg = f"{path_text(place)}: cannot write the file ({reason})"
                raise OutputError(msg) from err
            moved.append((place, existed, kept))
    except BaseException:
        for place, existed, kept in reversed(moved):
            with contextlib.suppress(OSError):
                if kept is not None:
                    os.replace(kept, place)
                elif not existed:
                    os.unlink(place)
        raise


def _keep_old(place: Path, temporary: Path) -> tuple[bool, Path | None]:
    """Return whether ``place`` holds a file, and that file kept in ``temporary``.

    The old file is kept as a hard link; on a file system without them it is not
    (None), and cannot be put back.
    """
    kept = temporary / f".old.{place.name}"
    try:
        os.link(place, kept, follow_symlinks=False)
    except FileNotFoundError:
        return os.path.lexists(place), None
    except (OSError, NotImplementedError):  # no hard links here (or no linkat)
        return True, None
    return True, kept


def _reserve(target: Path, reserved: list[Path], folder: bool = False) -> Path:
    """Create an empty temporary file beside ``target``, with its permissions.

    With ``folder``, an empty temporary folder (only its owner may enter it). Its
    path is put in ``reserved`` before it is made, so that a stop (Ctrl-C, SIGTERM)
    coming as it is made still finds it to remove.
    """
    import secrets

    try:
        mode = None if folder else stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        mode = None
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    while True:
        tail = "" if folder else f".tmp{target.suffix}"
        name = f".{target.name[:NAME_KEPT]}.{secrets.token_hex(4)}{tail}"
        # in target's parent, not by ``with_name``: the folder "." (or "/") has no
        # name, and output_folder reserves beside "./." to write into "." itself
        temporary = target.parent / name
        # told before it exists: Python runs a signal's handler as soon as the
        # call that makes it returns, before its result is kept anywhere
        reserved[:] = [temporary]
        try:
            if folder:
                os.mkdir(temporary, 0o700)
                return temporary
            # 0o666 less the umask, as a new file gets; an old file's own mode
            descriptor = os.open(temporary, flags, 0o666)
        except FileExistsError:
            reserved.clear()  # another's: not to be removed
            continue
        os.close(descriptor)
        if mode is not None:
            with contextlib.suppress(OSError):
                os.chmod(temporary, mode)
        return temporary


def _sync(path: Path) -> None:
    """Flush ``path`` to the disk, so a crash after the rename finds it whole."""
    # Windows flushes a file only through a handle open for writing (a read-only
    # one fails, "Bad file descriptor"); elsewhere reading is enough, and works for
    # a file given a read-only mode (the old file's it replaces)
    flags = os.O_RDWR if os.name == "nt" else os.O_RDONLY
    descriptor = os.open(path, flags)
    try:
        os.fsync(descriptor)
    finally:
        os.close(descriptor)


def _remove(path: Path) -> None:
    """Remove a temporary file, if it is still there."""
    with contextlib.suppress(OSError):
        os.unlink(path)


@contextlib.contextmanager
def _reported(where: str, any_error: bool, stdout: bool = False) -> Iterator[None]:
    """Turn the failure of a write into an :class:`OutputError` naming ``where``.

    On standard output (``stdout``), a reader that has gone (``| head``) raises
    BrokenPipeError, which the command line ends on quietly, as for ``-``.
    """
    try:
        yield
    except AssurError:
        raise
    except OSError as err:
        if stdout and err.errno == errno.EPIPE:
            raise BrokenPipeError(errno.EPIPE, os.strerror(errno.EPIPE)) from err
        msg = f"{where}: cannot write the file ({err.strerror or err})"
        raise OutputError(msg) from err
    except Exception as err:
        # a writer that failed as Ctrl-C or SIGHUP unwound it (matplotlib's
        # "Invalid bounding box" from a drawing cut short): the stop, not a fault
        stop = _behind(err, lambda e: not isinstance(e, Exception))
        if stop is not None:
            raise stop from None
        if not any_error:
            raise
        cause = _os_error(err)
        if stdout and cause is not None and cause.errno == errno.EPIPE:
            raise BrokenPipeError(errno.EPIPE, os.strerror(errno.EPIPE)) from err
        if cause is not None:  # a writer that fails again on cleaning up
            msg = f"{where}: cannot write the file ({cause.strerror or cause})"
            raise OutputError(msg) from err
        reason = " ".join(f"{type(err).__name__}: {err}".split())
        if len(reason) > 120:
            reason = reason[:117] + "..."
        msg = f"{where}: cannot write the file ({reason})"
        raise OutputError(msg) from err


def _os_error(err: BaseException) -> OSError | None:
    """Return the OSError behind ``err`` (its cause or context), if any."""
    found = _behind(err, lambda e: isinstance(e, OSError))
    return found if isinstance(found, OSError) else None


def _behind(
    err: BaseException, wanted: Callable[[BaseException], bool]
) -> BaseException | None:
    """Return the first of ``err``, its cause or context, ... that is ``wanted``."""
    seen: set[int] = set()
    cause: BaseException | None = err
    while cause is not None and id(cause) not in seen:
        if wanted(cause):
            return cause
        seen.add(id(cause))
        cause = cause.__cause__ or cause.__context__
    return None
