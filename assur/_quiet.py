"""Numpy's floating-point warnings switched off once for a block and what it calls.

A sweep's kernels divide by determinants that are zero at a dead centre and carry
NaN through positions that do not assemble: numpy's warnings there say nothing the
sweep does not report itself, so each kernel switches them off. ``np.errstate``
builds its settings anew at every entry, which cost as much as the 2x2 solve it
guarded (some twenty thousand instructions; a 360-position sweep entered it eight
times). :class:`quiet` enters it once: a block already quiet runs inner blocks as
they are.
"""

from __future__ import annotations

from contextvars import ContextVar, Token
from typing import Any

import numpy as np

__all__ = ["quiet"]

_QUIET: ContextVar[bool] = ContextVar("assur_quiet", default=False)
"""Whether a :func:`quiet` block encloses the running code (per thread and task, as
numpy's own settings are)."""


class _Inside:
    """What an inner block enters: nothing to change."""

    __slots__ = ()

    def __enter__(self) -> None:
        return None

    def __exit__(self, *exc: object) -> None:
        return None


_INSIDE = _Inside()


class _Quiet:
    """The outermost block: numpy's settings, and the mark for inner blocks."""

    __slots__ = ("_state", "_token")

    def __enter__(self) -> None:
        self._state = np.errstate(all="ignore")
        self._state.__enter__()
        self._token: Token[bool] = _QUIET.set(True)

    def __exit__(self, *exc: Any) -> None:
        _QUIET.reset(self._token)
        self._state.__exit__(*exc)


def quiet() -> _Quiet | _Inside:
    """Ignore division by zero, invalid operations and overflow in a ``with`` block.

    As ``np.errstate(divide="ignore", invalid="ignore", over="ignore")``; within a
    block that is already quiet, an inner one changes nothing and costs a lookup.
    Code in a quiet block must not set numpy's settings back (none here does): an
    inner block would then run under those.
    """
    return _INSIDE if _QUIET.get() else _Quiet()
