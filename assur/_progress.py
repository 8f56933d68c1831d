"""Progress of long work: a bar on standard error, only when asked for.

The library shows none unless a caller passes ``progress=True`` (or a callable that
receives the work done so far); the command line asks for one when standard error is
a terminal. The bar is tqdm's, imported only when a bar is shown.
"""

from __future__ import annotations

import inspect
import sys
import time
from collections.abc import Callable
from types import TracebackType
from typing import Any

from assur._text import python_value
from assur._vec import is_flag
from assur.errors import UsageError

__all__ = ["BAR_DELAY", "Progress", "progress"]

BAR_DELAY = 1.0
"""Seconds the command line's work runs before its progress bar appears (on a
terminal): whatever makes it long, its positions or its mechanism's columns."""
SCALED = 10_000
"""Totals from which a bar writes its counts with SI prefixes (100k)."""
Callback = Callable[[int, int], None]
"""A caller's own report: ``callback(done, total)``."""


class Progress:
    """Report ``done`` out of ``total`` units of work; a no-op when not enabled."""

    def __init__(
        self,
        what: str,
        total: int,
        show: bool | Callback = False,
        delay: float = 0.0,
        unit: str = "it",
    ) -> None:
        if not callable(show):
            # "yes" showed nothing, where skip_unassembled="no" is refused
            if not is_flag(show):
                msg = (
                    "progress: expected True, False or a callable (done, total), got "
                    f"{python_value(show)}"
                )
                raise UsageError(msg)
            show = bool(show)
        else:
            _two_arguments(show)
        self.total = total
        self.done = 0
        self._callback: Callback | None = show if callable(show) else None
        self._bar: Any = None
        # a bar appears only once the work has run ``delay`` seconds
        self._shown_from = time.monotonic() + delay
        if show is True and total > 0:
            from tqdm import tqdm

            self._bar = tqdm(
                total=total,
                desc=what,
                file=sys.stderr,
                leave=False,
                unit=unit,
                # "100k/1.00M positions", but "1/8 figures", not "1.00/8.00"
                unit_scale=total >= SCALED,
                delay=delay,
            )

    def advance(self, count: int) -> None:
        """Record ``count`` more units done."""
        self.done += count
        if self._bar is not None:
            self._bar.update(count)
            if self.done >= self.total and time.monotonic() >= self._shown_from:
                # tqdm skips updates that come fast; the last one is always shown
                self._bar.refresh()
        if self._callback is not None:
            self._callback(self.done, self.total)

    def close(self) -> None:
        """Remove the bar."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self) -> Progress:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        trace: TracebackType | None,
    ) -> None:
        self.close()


def _two_arguments(callback: Callable[..., Any]) -> None:
    """Refuse a callback that cannot be called as ``callback(done, total)``.

    Else its TypeError came from the first report, deep in a sweep. A callable
    whose signature cannot be read (some built-ins) is taken as it is.
    """
    try:
        signature = inspect.signature(callback)
    except (TypeError, ValueError):
        return
    try:
        signature.bind(0, 0)
    except TypeError as err:
        name = getattr(callback, "__name__", type(callback).__name__)
        msg = (
            f"progress: expected a callable of two arguments (done, total), got "
            f"{name}{signature} ({err})"
        )
        raise UsageError(msg) from None


def progress(
    what: str,
    total: int,
    show: bool | Callback = False,
    delay: float = 0.0,
    unit: str = "it",
) -> Progress:
    """Return a :class:`Progress` of ``total`` units named ``what``.

    ``show``: True for a bar on standard error, a callable ``(done, total)`` to be
    told, False for nothing. ``delay``: seconds before a bar appears (none for work
    done sooner). ``unit``: what is counted, as the bar writes it ("position").
    """
    return Progress(what, total, show, delay, unit)
