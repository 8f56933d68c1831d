"""The command line's first moments: Ctrl-C while assur's modules load.

``python -m assur`` and the ``assur`` script import the package and its command line
(numpy, the analysis) before :func:`assur.cli.main` runs and can catch Ctrl-C: a Ctrl-C
there printed a traceback. The package's first lines call :func:`guard`; when the import
starts the command line, Ctrl-C ends it as the command does (one line, status 130) until
:func:`assur.cli.main` takes over and calls :func:`release`. A plain ``import assur`` is
left alone. Only modules that Python has loaded before any script here (``signal``,
``re`` and ``typing`` take milliseconds to load, time for a Ctrl-C to come with a
traceback).
"""

import os
import sys

try:
    import _signal as signal  # signal's own core, loaded with Python itself
except ImportError:  # another Python than CPython
    import signal

INTERRUPTED = 130
"""Exit status after Ctrl-C: 128 plus SIGINT's number, as a shell reports it."""
SCRIPT = "assur"
"""The console script's name."""
SCRIPT_CALL = b"from assur.cli import main"
"""What the console script that pip writes does first."""
FLAGS = frozenset("bBdEiIOPqRsSuvx")
"""Python's one-letter options without a value, which may come joined before ``m``."""
OPTIONS_WITH_VALUE = frozenset({"-X", "-W", "--check-hash-based-pycs"})
"""Python's options before ``-m`` whose value is the next argument."""


def guard() -> None:
    """Make Ctrl-C end the command line quietly while its modules load.

    Does nothing unless this import starts the command line (``python -m assur``
    or the ``assur`` script) in the main thread.
    """
    if not _command_line():
        return
    try:
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
            signal.signal(signal.SIGINT, _interrupted)
    except ValueError:  # not the main thread: signals are not ours to take
        return


def release() -> None:
    """Give Ctrl-C back to Python (a KeyboardInterrupt), if :func:`guard` took it."""
    try:
        if signal.getsignal(signal.SIGINT) is _interrupted:
            signal.signal(signal.SIGINT, signal.default_int_handler)
    except ValueError:
        return


def _interrupted(signum: int, frame: object) -> None:
    """End the command as :func:`assur.cli.main` does after Ctrl-C, at once.

    Nothing is written yet. An exception raised here could land inside a module's
    C code, which turns it into an ImportError of its own (numpy's, a page long).
    """
    try:
        os.write(2, b"assur: interrupted\n")
    finally:
        os._exit(INTERRUPTED)


def _command_line() -> bool:
    """Whether this import starts the command line."""
    first = sys.argv[0] if getattr(sys, "argv", None) else ""
    if first == "-m":  # python -m imports the packages of the module it runs
        return _module_run() in ("assur", "assur.__main__")
    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if not isinstance(path, str) or os.path.basename(path) != SCRIPT:
        return False
    # __main__.__file__ is absolute, sys.argv[0] as typed (bin/assur, ./assur)
    if os.path.abspath(first) != os.path.abspath(path):
        return False
    try:
        with open(path, "rb") as script:
            return SCRIPT_CALL in script.read(4096)
    except OSError:
        return False


def _module_run() -> str:
    """Return the module that ``python -m`` runs, read from Python's own arguments."""
    arguments = iter(getattr(sys, "orig_argv", ())[1:])
    for argument in arguments:
        flags, m, module = argument[1:].partition("m")
        if argument.startswith("-") and m and FLAGS.issuperset(flags):
            return module or next(arguments, "")  # -m assur, -massur, -Im assur
        if argument in OPTIONS_WITH_VALUE:
            next(arguments, None)
        elif argument in ("-", "-c") or not argument.startswith("-"):
            break  # a script, standard input or -c: not -m
    return ""
