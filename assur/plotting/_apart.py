"""Arrows that lie on one another drawn a little apart, each to be seen.

At a dead centre a force polygon's sides, a plan's terms or the forces at one joint
lie on one line, each drawn over the one before. :func:`moved` finds, for a new
arrow, the nearest place sideways where it lies on none of those drawn: by a step
to one side, then the other, then farther.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["lies_on", "moved", "slid"]

Ends = tuple[np.ndarray, np.ndarray]
"""An arrow's tail and tip."""
TRIES = (0, 1, -1, 2, -2, 3, -3)
"""The steps sideways tried, in turn."""


def lies_on(arrow: Ends, other: Ends, near: float) -> bool:
    """Whether ``other`` lies on ``arrow``, within ``near`` of its line.

    It does when they share a span of ``arrow``'s line longer than ``near`` and
    ``other`` is within ``near`` of that line all along it (measured at both ends
    of the span): a short arrow that runs back over a long one at a slight angle
    lies on it.
    """
    a0, a1 = arrow
    b0, b1 = other
    length = float(np.hypot(*(a1 - a0)))
    if length <= near:
        return False
    u = (a1 - a0) / length
    t0, t1 = float(np.dot(u, b0 - a0)), float(np.dot(u, b1 - a0))
    low, high = max(0.0, min(t0, t1)), min(length, max(t0, t1))
    if high - low <= near:  # side by side for no more than a point
        return False
    for t in (low, high):
        p = b0 + (t - t0) / (t1 - t0) * (b1 - b0)
        q = p - a0
        if abs(float(u[0] * q[1] - u[1] * q[0])) > near:
            return False
    return True


def moved(drawn: list[Ends], start: np.ndarray, end: np.ndarray, step: float,
          near: float) -> Ends:  # fmt: skip
    """Return an arrow's ends, moved sideways by steps of ``step`` off those drawn.

    ``drawn`` holds the arrows drawn before (their ends, as moved); an arrow no
    longer than ``near`` stays where it is, as does one that lies on some arrow
    at every place tried (:data:`TRIES` steps).
    """
    return _clear(drawn, start, end, near, np.array([[0.0, -1.0], [1.0, 0.0]]),
                  step, TRIES)  # fmt: skip


def slid(drawn: list[Ends], start: np.ndarray, end: np.ndarray, step: float,
         near: float, most: int = 60) -> Ends:  # fmt: skip
    """Return an arrow's ends, slid along its own line by steps of ``step``.

    As :func:`moved`, but along the arrow's line of action: on Zhukovsky's lever a
    load's moment about the pole stays what it is wherever on that line it is
    drawn, where a step sideways would show an arm it does not have. Forward, then
    back, farther each time, up to ``most`` steps each way.
    """
    tries = [0] + [sign * k for k in range(1, most + 1) for sign in (1, -1)]
    return _clear(drawn, start, end, near, np.eye(2), step, tries)


def _clear(drawn: list[Ends], start: np.ndarray, end: np.ndarray, near: float,
           turn: np.ndarray, step: float, tries: Sequence[int]) -> Ends:  # fmt: skip
    """Return the arrow's ends at the first of ``tries`` clear of those ``drawn``.

    Each try shifts it by that many steps of ``step`` along its direction turned
    by ``turn`` (the identity: along its line; a quarter turn: sideways).
    """
    length = float(np.hypot(*(end - start)))
    if length <= near:
        return start, end
    shift = step * (turn @ (end - start)) / length
    for k in tries:
        ends = (start + k * shift, end + k * shift)
        if not any(
            lies_on(ends, other, near) or lies_on(other, ends, near) for other in drawn
        ):
            return ends
    return start, end
