"""Several files of one command land together: each replaces its old file at the end.

A command that writes a set of files (a table as ``--csv`` and ``--parquet``, a
start-up's samples beside the steady state's table) writes each to a temporary
file (:func:`assur._output.output_path`); inside :func:`together` the temporary
files replace their targets only once every one is written, one after the other,
with Ctrl-C, SIGTERM and SIGHUP held back meanwhile: an interrupt that comes while
they are written leaves the old set, one that comes as they land leaves the new.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from collections.abc import Iterator
from contextvars import ContextVar
from pathlib import Path

from assur.errors import OutputError

__all__ = ["defer", "together"]

_PENDING: ContextVar[list[tuple[Path, Path, str]] | None] = ContextVar(
    "assur_pending_files", default=None
)
"""The files written and not landed yet, inside :func:`together` (None outside)."""


def defer(temporary: Path, target: Path, where: str) -> bool:
    """Hold back ``temporary`` replacing ``target`` inside :func:`together`.

    ``where`` names the target in a message. Returns whether it was held back
    (outside :func:`together` the caller replaces it at once).
    """
    pending = _PENDING.get()
    if pending is None:
        return False
    pending.append((temporary, target, where))
    return True


@contextlib.contextmanager
def together() -> Iterator[None]:
    """Land the files written inside the block together, at its end, or none.

    Raises
    ------
    OutputError
        When a file cannot replace its old one: those after it do not land, those
        before it have (a rename refused once the others went through, rare).
    """
    pending: list[tuple[Path, Path, str]] = []
    token = _PENDING.set(pending)
    try:
        yield
        with _held():
            for temporary, target, where in pending:
                try:
                    os.replace(temporary, target)
                except OSError as err:
                    msg = f"{where}: cannot write the file ({err.strerror or err})"
                    raise OutputError(msg) from err
    except BaseException:
        # those landed are gone from their temporary names already
        _remove(pending)
        raise
    finally:
        _PENDING.reset(token)


def _remove(pending: list[tuple[Path, Path, str]]) -> None:
    """Remove the temporary files of ``pending`` that are still there."""
    for temporary, _, _ in pending:
        with contextlib.suppress(OSError):
            os.unlink(temporary)


@contextlib.contextmanager
def _held() -> Iterator[None]:
    """Hold back Ctrl-C, SIGTERM and SIGHUP in the block (from the main thread).

    A signal that comes meanwhile is noted and raised again at the block's end,
    to the handler it would have met a moment later. (Blocking the signals would
    not do: a signal sent to the process goes to any of its threads that does
    not block it, numpy's among them.)
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    came: list[int] = []
    names = ("SIGINT", "SIGTERM", "SIGHUP")
    before = {}
    for number in [getattr(signal, n) for n in names if hasattr(signal, n)]:
        handler = signal.getsignal(number)
        if handler is not None:  # None: set outside Python, which cannot put it back
            before[number] = handler
            signal.signal(number, lambda n, _: came.append(n))
    try:
        yield
    finally:
        for number, handler in before.items():
            signal.signal(number, handler)
        for number in dict.fromkeys(came):
            signal.raise_signal(number)
