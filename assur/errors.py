"""Exceptions and warnings raised by assur.

Every error carries one line that names the object, what is wrong, the value received
and what was expected; the command line prints that line and exits with status 2.
"""

from __future__ import annotations

__all__ = [
    "AssemblyError",
    "AssurError",
    "AssurWarning",
    "DecompositionError",
    "ModelError",
    "SingularConfigurationError",
]


class AssurError(Exception):
    """Base class of every error raised by assur."""


class ModelError(AssurError, ValueError):
    """An invalid mechanism, load or file contents."""


class DecompositionError(AssurError):
    """The mechanism does not split into supported Assur groups."""


class AssemblyError(AssurError):
    """A group cannot be closed at some driver position."""


class SingularConfigurationError(AssurError):
    """A dead centre: the velocity or force system of a group is singular."""


class AssurWarning(UserWarning):
    """A near-singular pose or another result that deserves a second look."""
