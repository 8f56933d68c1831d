"""A mechanism's size read as a sign of its lengths' unit: metres, not millimetres."""

from __future__ import annotations

import os
import sys
from typing import Any

from assur._warn import warn
from assur.errors import AssurWarning

__all__ = ["LARGE", "metres", "metres_text"]

LARGE = 50.0
"""Size of a mechanism (m) above which its lengths are likely millimetres: a drawing's
figures copied into the file as they are."""


def metres(size: float) -> None:
    """Warn of a mechanism whose size suggests lengths in millimetres, not metres.

    Every length of a file is in metres (the file format): a slider-crank drawn with a
    74 mm crank and written with a crank of 74 has speeds in km/s at 200 rad/s, and
    inertia forces a thousand times too large, without a word otherwise.
    """
    msg = metres_text(size)
    if msg is not None:
        warn(msg, AssurWarning, stacklevel=_outside())


def metres_text(size: float) -> str | None:
    """Return the warning :func:`metres` gives of a size (m), or None."""
    if not size > LARGE:
        return None
    return (
        f"joints: the mechanism is {size:.4g} m across; lengths are in metres "
        "(SI units): if they are millimetres, divide them by 1000"
    )


def _outside() -> int:
    """Return the stack level of the first caller outside the package (a warning's).

    A plan is compiled on many paths (a sweep, a study, the pictures): the warning
    points at the user's line, whichever.
    """
    package = os.path.dirname(__file__)
    frame: Any = sys._getframe(1)
    level = 1
    while frame is not None and frame.f_code.co_filename.startswith(package):
        frame, level = frame.f_back, level + 1
    return level
