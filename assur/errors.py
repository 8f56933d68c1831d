"""Exceptions and warnings raised by assur.

Every error carries one line that names the object, what is wrong, the value received
and what was expected; the command line prints that line and exits with status 2.
Each error also derives from the built-in exception that fits it, so code that knows
nothing of assur can still catch a ``ValueError`` or an ``OSError``.
"""

from __future__ import annotations

__all__ = [
    "AssemblyError",
    "AssurError",
    "AssurWarning",
    "ConvergenceError",
    "DecompositionError",
    "ModelError",
    "OutputError",
    "SelfLockingError",
    "SingularConfigurationError",
    "UnknownNameError",
    "UsageError",
]


class AssurError(Exception):
    """Base class of every error raised by assur."""


class ModelError(AssurError, ValueError):
    """An invalid mechanism, load or mechanism file."""


class DecompositionError(AssurError, ValueError):
    """The mechanism does not split into supported Assur groups."""


class AssemblyError(AssurError, ValueError):
    """A group cannot be closed at some driver position."""


class SingularConfigurationError(AssurError, ValueError):
    """A dead centre: the velocity or force system of a group is singular."""


class SelfLockingError(AssurError, ValueError):
    """Friction locks a group: no driving load can move it at some position."""


class ConvergenceError(AssurError, RuntimeError):
    """An iteration (Newton's method, a continuation) did not reach its tolerance."""


class UsageError(AssurError, ValueError):
    """A command-line option or a library argument that cannot be used as given."""


class UnknownNameError(UsageError, KeyError):
    """A name a table or a mechanism has no column, link or joint of.

    A KeyError too, as a lookup by a name that is not there is in Python.
    """

    # the message as written: a KeyError's own str() quotes it
    __str__ = Exception.__str__


class OutputError(AssurError, OSError):
    """An output file that cannot be written (the old file, if any, is kept)."""


class AssurWarning(UserWarning):
    """A near-singular pose or another result that deserves a second look."""
