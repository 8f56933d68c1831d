"""Where an output goes: the path named and the file it leads to.

A path as a message shows it, a file's name written as a folder's refused, and what a
path leads to: a regular file to replace, or a stream to write in place.
"""

from __future__ import annotations

import errno
import os
import stat
import sys
from typing import TYPE_CHECKING, Any

from assur.errors import OutputError

if TYPE_CHECKING:
    from pathlib import Path

__all__ = [
    "a_folder",
    "folder_name",
    "missing_folder",
    "path_text",
    "standard_output",
    "stdout_is",
]

PROCESS_FILES = "/proc/"
"""The folder whose entries name a process's open files (``/dev/stdout`` leads there).

A path through it is written in place: what it leads to is the process's stream, not
a file to replace, whatever that stream is (a pipe, a terminal, a shell's file).
"""
LINKS_FOLLOWED = 40
"""Most symbolic links followed in a path, as the system's own limit (``ELOOP``)."""


def a_folder(path: Any) -> str:
    """Return the message of an output that names a folder."""
    return f"{path_text(path)}: cannot write the file (it is a folder); expected a file"


def path_text(path: Any) -> str:
    """Return a path as a message shows it: as it is, control characters escaped."""
    text = os.fsdecode(path) if isinstance(path, bytes | os.PathLike) else str(path)
    return "".join(c if c.isprintable() else ascii(c)[1:-1] for c in text)


def folder_name(path: str | os.PathLike[str]) -> str | None:
    """Say what is wrong with a file's name written as a folder's; None if nothing.

    A Path drops a name's last slash: ``--csv out/`` would write a file ``out``.
    """
    if isinstance(path, str) and path.endswith(("/", os.sep)):
        return f"the name ends with {path[-1]!r}, as a folder's"
    return None


def missing_folder(path: str | os.PathLike[str]) -> str | None:
    """Say why the folder that ``path`` lies in cannot hold it; None if it can.

    Checked before the work, so that an output whose folder is missing stops the
    command at once, as the write itself would after the analysis.

    Examples
    --------
    >>> missing_folder("/no/such/folder/t.csv")
    'No such file or directory'
    >>> missing_folder("t.csv") is None
    True
    """
    from pathlib import Path

    parent = Path(path).parent
    if parent.is_dir():
        return None
    return os.strerror(errno.ENOTDIR if parent.exists() else errno.ENOENT)


def _not_a_folder(path: str | os.PathLike[str]) -> None:
    """Refuse a file name written as a folder's (see :func:`folder_name`)."""
    fault = folder_name(path)
    if fault is not None:
        msg = (
            f"{path_text(path)}: cannot write the file ({fault}); expected a file name"
        )
        raise OutputError(msg)


def _target(path: Path) -> tuple[Path, bool]:
    """Return the file to replace (links followed) and whether to write in place.

    Only a regular file (or a new one) is replaced; a device, a FIFO or a socket
    is written in place, where it lies (``/dev/shm`` is a folder of regular files),
    and so is a process's open file named through ``/proc`` (``/dev/stdout``).
    """
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        mode = None
    except OSError:
        return path, True  # let the writer meet the fault and name it
    except ValueError as err:  # a NUL character in the name
        msg = f"{path_text(path)}: cannot write the file ({err})"
        raise OutputError(msg) from err
    if mode is not None and stat.S_ISDIR(mode):
        raise OutputError(a_folder(path))
    if mode is not None and not stat.S_ISREG(mode):
        return path, True
    if _through_process_files(path):
        return path, True
    return path.__class__(os.path.realpath(path)), False


def _through_process_files(path: Path) -> bool:
    """Whether ``path``, its links followed one by one, passes through ``/proc``.

    ``os.path.realpath`` cannot tell: ``/dev/stdout`` links to ``/proc/self/fd/1``,
    which reads as the name of the file the shell opened (``> out.csv``).
    """
    pending = os.path.abspath(path)
    for _ in range(LINKS_FOLLOWED):
        if (pending + "/").startswith(PROCESS_FILES):
            return True
        parts = pending.split("/")
        for end in range(2, len(parts) + 1):
            prefix = "/".join(parts[:end])
            try:
                link = os.readlink(prefix)
            except OSError:  # not a link, or not there
                continue
            folder = os.path.dirname(prefix)
            pending = os.path.normpath(os.path.join(folder, link, *parts[end:]))
            break
        else:
            return False
    return False


def stdout_is(path: Any) -> bool:
    """Whether standard output is the regular file ``path`` (the same inode).

    A redirection (``>> m.toml``) to a file the command reads.
    """
    try:
        out = os.fstat(sys.stdout.fileno())
        found = os.stat(path)
    except (AttributeError, OSError, ValueError):
        return False  # no standard output, a stream without a file, no such file
    same = (out.st_dev, out.st_ino) == (found.st_dev, found.st_ino)
    return same and stat.S_ISREG(out.st_mode)


def standard_output(target: str | os.PathLike[str]) -> bool:
    """Whether ``target`` is the file standard output writes to (``/dev/stdout``)."""
    try:
        here, there = os.fstat(sys.stdout.fileno()), os.stat(target)
    except (AttributeError, OSError, ValueError):
        return False
    return (here.st_dev, here.st_ino) == (there.st_dev, there.st_ino)
