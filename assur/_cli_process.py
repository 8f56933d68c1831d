"""How the command line meets its process: the signals that stop it, its streams.

SIGTERM and SIGHUP unwind a command as Ctrl-C does (:func:`_stoppable`); standard
output or error that started closed get a stand-in (:func:`_closed_streams`); what a
terminal's encoding cannot show is written as backslash escapes
(:func:`_lenient_streams`). :func:`assur.cli.main` wraps every command in them.
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import signal
import sys
import threading
from collections.abc import Iterator
from typing import Any

from assur._stdout import unmarked

__all__ = [
    "RESEND",
    "_Stopped",
    "_closed_streams",
    "_lenient_streams",
    "_quiet_stdout",
    "_stoppable",
]


RESEND = 0.5
"""Seconds after which Ctrl-C, SIGTERM or SIGHUP is sent again while the command it
stopped still runs: the exception it raised was lost."""
POSIX = os.name == "posix"


def _resend(signum: int) -> None:
    """Send the signal ``signum`` to this process again, from another thread."""
    if POSIX:
        os.kill(os.getpid(), signum)  # a real signal: it cuts a blocking call short
    else:
        import _thread

        # os.kill on Windows ends the process at once, its exit status the
        # signal's number: the main thread is interrupted as a signal would
        _thread.interrupt_main(signal.Signals(signum))


class _Stopped(BaseException):
    """SIGTERM or SIGHUP, raised where the command is: it unwinds like Ctrl-C."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


def _unwinding(before: BaseException | None = None) -> bool:
    """Whether a stop raised before is being handled where this runs.

    Called in a signal handler: the exception being handled by the code the signal
    cut into (an ``except`` or ``finally`` block, a context manager's exit), or one
    that exception arose from, is a stop. ``before`` is the exception the caller of
    the command was handling when it started (the command runs in its ``except``
    block): it and those it arose from are the caller's, not the command's.
    """
    seen = sys.exc_info()[1]
    chain: set[int] = set()
    while seen is not None and seen is not before and id(seen) not in chain:
        if isinstance(seen, _Stopped | KeyboardInterrupt):
            return True
        chain.add(id(seen))
        seen = seen.__context__
    return False


@contextlib.contextmanager
def _stoppable() -> Iterator[None]:
    """Let SIGTERM and SIGHUP end the command as Ctrl-C does, while it runs.

    By default they end the process at once, leaving an output's temporary file
    behind; raised as an exception, they remove it and keep the old file. A stop
    (Ctrl-C too) is sent again every :data:`RESEND` seconds while the command runs
    on: its exception can be lost (Python ignores one raised in a ``__del__``; C
    code calling back into Python may clear one). One that comes while a stop
    unwinds the command is passed over, so that its cleanup runs to the end.
    (Only the main thread can take signals; SIGKILL cannot be taken at all.)
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    caller = sys.exc_info()[1]  # what the caller is handling, if anything
    again: list[threading.Timer] = []
    over = threading.Lock()  # held while a stop is sent
    ended = [False]  # the command is over: nothing is sent, no stop raised

    def send(signum: int) -> None:
        with over:
            if not ended[0]:
                _resend(signum)

    def arm(signum: int) -> None:
        timer = threading.Timer(RESEND, send, (signum,))
        timer.daemon = True
        again.append(timer)
        timer.start()

    def stop(signum: int, frame: Any) -> None:
        if ended[0] or _unwinding(caller):
            return
        # should this exception be lost, the stop comes again while the command runs
        arm(signum)
        if signum == signal.SIGINT:
            raise KeyboardInterrupt
        raise _Stopped(signum)

    previous = sys.unraisablehook

    def unraised(unraisable: Any) -> None:
        stopped = unraisable.exc_value
        if isinstance(stopped, _Stopped):
            signum = stopped.signum
        elif isinstance(stopped, KeyboardInterrupt):
            signum = signal.SIGINT
        else:
            previous(unraisable)
            return
        # raised where Python ignores an exception (a __del__, a weakref callback
        # of matplotlib's), the stop left the command running (an animation of
        # a thousand frames went on to its end after Ctrl-C): unreported, it comes
        # again shortly, until one lands where it unwinds the command
        if signum not in saved:  # raised by a handler not ours: it is not armed
            arm(signum)

    saved: dict[int, Any] = {}
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        saved[signal.SIGINT] = signal.default_int_handler  # another's is left alone
        signal.signal(signal.SIGINT, stop)
    for name in ("SIGTERM", "SIGHUP"):
        number = getattr(signal, name, None)
        if number is not None:
            saved[number] = signal.signal(number, stop)
    sys.unraisablehook = unraised
    try:
        yield
    finally:
        # the command is over: a stop coming in this block (a resend, a late
        # Ctrl-C) is passed over, or the handlers would stay ours and the timers run
        ended[0] = True
        with over:  # a stop being sent is sent whole, and none after
            pass
        for timer in again:
            timer.cancel()
        for number, handler in saved.items():
            signal.signal(number, handler)
        sys.unraisablehook = previous


class _Closed:
    """Standard output started closed (``>&-``): every write is an OSError.

    Python leaves ``sys.stdout`` None then; a command writing only files, with
    ``--quiet``, still runs, one that writes to standard output says it cannot.
    """

    encoding = "utf-8"
    errors = "strict"

    @property
    def buffer(self) -> _Closed:
        return self

    def write(self, data: Any) -> int:
        raise OSError(errno.EBADF, "standard output is closed")

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        raise OSError(errno.EBADF, "standard output is closed")


class _Sturdy:
    """Standard error that passes over its own failures to write (a full disk).

    Nowhere to say anything: the exit status speaks, 2 for an error, not the 1 of
    the OSError that printing the error line raised.
    """

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        try:
            return int(self._stream.write(text))
        except OSError:
            return len(text)

    def flush(self) -> None:
        with contextlib.suppress(OSError):
            self._stream.flush()

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


@contextlib.contextmanager
def _closed_streams() -> Iterator[None]:
    """Stand in for standard output or error when they started closed or fail."""
    saved = sys.stdout, sys.stderr
    with contextlib.ExitStack() as stack:
        if sys.stdout is None:
            sys.stdout = _Closed()  # type: ignore[assignment]
        if sys.stderr is None:  # nowhere to say anything: the exit status speaks
            sys.stderr = stack.enter_context(open(os.devnull, "w"))
        else:
            sys.stderr = _Sturdy(sys.stderr)  # type: ignore[assignment]
        try:
            yield
        finally:
            sys.stdout, sys.stderr = saved


@contextlib.contextmanager
def _lenient_streams() -> Iterator[None]:
    """Write what a terminal's encoding cannot show as backslash escapes.

    Standard output in UTF-8 with a byte-order mark is written as UTF-8: the
    table's bytes and print()'s text would each put a mark of their own in it.
    """
    saved = []
    marked = getattr(sys.stdout, "encoding", None) or ""
    if unmarked(marked) == marked:
        marked = ""
    if marked and hasattr(sys.stdout, "reconfigure"):
        with contextlib.suppress(OSError, ValueError):
            sys.stdout.reconfigure(encoding="utf-8")
    for stream in (sys.stdout, sys.stderr):
        errors = getattr(stream, "errors", None)
        if errors in (None, "backslashreplace") or not hasattr(stream, "reconfigure"):
            continue
        with contextlib.suppress(OSError, ValueError):
            stream.reconfigure(errors="backslashreplace")
            saved.append((stream, errors))
    try:
        yield
    finally:
        for stream, errors in saved:
            with contextlib.suppress(OSError, ValueError):
                stream.reconfigure(errors=errors)
        if marked and hasattr(sys.stdout, "reconfigure"):
            with contextlib.suppress(OSError, ValueError):
                sys.stdout.reconfigure(encoding=marked)


def _quiet_stdout() -> None:
    """Point standard output at nothing, so the exit does not flush it again."""
    try:
        descriptor = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):
        return  # not a file: nothing flushes at exit
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, descriptor)
    finally:
        os.close(devnull)


def _plain_matplotlib() -> None:
    """Set matplotlib up for the command line, before it is imported.

    The command line draws on Agg whatever the environment names: a backend
    matplotlib does not know stopped its very import with a traceback. And
    matplotlib says nothing of its own (an unwritable cache folder was told in its
    words, even with -q).
    """
    if "matplotlib" in sys.modules:  # imported by the caller: its settings stand
        return
    os.environ["MPLBACKEND"] = "agg"
    logging.getLogger("matplotlib").setLevel(logging.ERROR)
