"""The library's own warnings, given at once or held for its caller to tell.

Some calls keep the warnings of the work they do on the side (the sweeps about a
change point, a study's variants, the model's grid): those are held in a list
instead of given. A context variable holds them, not a warnings filter: a filter
(``warnings.catch_warnings``) is the whole process's, and from two threads at once
it lost the other thread's warnings, filed them under the wrong call, or stayed
behind for good, every later warning silenced.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

from assur.errors import AssurWarning

__all__ = ["held", "warn"]

_HELD: ContextVar[list[warnings.WarningMessage] | None] = ContextVar(
    "assur_held_warnings", default=None
)
"""The list this thread's (or task's) warnings go to while :func:`held` runs."""


def warn(
    message: str, category: type[Warning] = AssurWarning, stacklevel: int = 1
) -> None:
    """Give a warning, as :func:`warnings.warn` does, or hold it (see :func:`held`).

    Parameters
    ----------
    message : str
        What the warning says.
    category : type of Warning
        Its class.
    stacklevel : int
        As for :func:`warnings.warn`, counted from the caller of this function.
    """
    found = _HELD.get()
    if found is None:
        warnings.warn(message, category, stacklevel=stacklevel + 1)
    else:
        found.append(warnings.WarningMessage(category(message), category, "", 0))


@contextmanager
def held() -> Iterator[list[warnings.WarningMessage]]:
    """Hold the warnings :func:`warn` gives in this context, in the list yielded.

    Every one is held, in the order given (as the filter ``"always"`` would keep
    them); a caller that wants none drops the list. Other warnings (numpy's, the
    user's own) pass as they would, and so do those of a thread started inside
    (a new thread begins with no context of its own: the library starts none that
    warns).

    Examples
    --------
    >>> with held() as found:
    ...     warn("near a dead centre")
    >>> [str(w.message) for w in found]
    ['near a dead centre']
    """
    found: list[warnings.WarningMessage] = []
    token = _HELD.set(found)
    try:
        yield found
    finally:
        _HELD.reset(token)
