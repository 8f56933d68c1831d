"""The time each position of a sweep stands for, when one driver sets the pace.

A summary's means are time averages (:mod:`assur.summary`): with the positions taken
as equally spaced, a position stands for a time inversely as the driver's speed
there. At a constant speed every position weighs the same, and the means are plain
means over the positions, to the last bit.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array, full

__all__ = ["SLOWEST", "Clock", "time_shares"]

SLOWEST = 1e-3
"""A sweep whose slowest speed is below this share of its fastest is not timed: near
a stop the time per position grows without bound, and the means would be those of
the one or two positions nearest it, wherever the grid falls (a crank at 100 (1 +
sin) rad/s gave an RMS reaction of 349, 249 or 118 N by the grid's offset)."""


@dataclass
class Clock:
    """Whether and how a sweep's positions are weighted by time, slice by slice.

    ``one`` says the mechanism has one driver, whose speed (``rate``: "omega" or
    "v") times the positions; ``first`` is each variant's speed at the sweep's first
    position; ``varies``, ``stops`` and ``several`` record what the speeds did.
    """

    one: bool = False
    rate: str = "omega"
    first: Any = None
    slowest: float = float("inf")
    fastest: float = 0.0
    """The one driver's slowest and fastest speeds over the slices added (sizes)."""
    varies: bool = False
    """The one driver's speed varies: the time weights are not all 1."""
    stops: bool = False
    """It reaches zero, turns back or nearly stops: no time to weigh by."""
    several: bool = False
    """Several drivers, a speed among them varying: no one time to weigh by."""

    def record(self, table: Any, shape: tuple[int, int]) -> Array:
        """Record the speeds of ``table``; return the time each position stands for.

        The shares, (variants, m), are ``|speed_0| / |speed|``: 1 at the first
        position's speed, exactly 1 at a constant speed; all 1 where there is no
        one time (see :meth:`over`). Whether the sweep is timed is decided over
        every slice added (:meth:`timed`), not slice by slice.
        """
        n = shape[0] * shape[1]
        if not n:
            return np.ones(shape)
        if not self.one:
            for speed in table.state.speed:
                values = full(speed, n).reshape(shape)
                # each variant's own speed: variants at two constant speeds do not vary
                varies = bool(np.any(values != values[:, :1]))
                self.several = self.several or varies
            return np.ones(shape)
        speed = full(table.state.speed[0], n).reshape(shape)
        if self.first is None:
            self.first = speed[:, :1].copy()
        w, stops = time_shares(speed, self.first)
        sizes = np.abs(speed)
        self.slowest = min(self.slowest, float(np.min(sizes)))
        self.fastest = max(self.fastest, float(np.max(sizes)))
        self.stops = self.stops or stops
        self.varies = self.varies or bool(np.any(w != 1.0))
        return w

    def timed(self) -> bool:
        """Whether the means are weighted by time: one driver, whose speed varies."""
        return self.one and self.varies and not self.stops and not self._slow()

    def _slow(self) -> bool:
        """Whether the slowest speed is too near a stop to time the positions by."""
        return self.slowest < SLOWEST * self.fastest

    def over(self) -> tuple[str, str]:
        """Return what the means and RMS values are over, and why where it matters.

        ``("time", why)`` for one driver whose speed varies, ``("positions", why)``
        where there is no time to weigh by, else ``("positions", "")``.
        """
        if self.timed():
            return (
                "time",
                f"the driver's speed varies; each position weighs 1/|{self.rate}|",
            )
        if self.one and (self.stops or self._slow()):
            return "positions", (
                "the driver's speed reaches 0, turns back or nearly stops (below "
                f"{SLOWEST:g} of its fastest)"
            )
        if self.several:
            return "positions", "several drivers with speeds that vary have no one time"
        return "positions", ""


def time_shares(speed: Array, first: Array) -> tuple[Array, bool]:
    """Return each position's time share and whether the driver stops or turns back.

    ``speed`` (variants, m) is the driver's speed at each position (rad/s or m/s),
    ``first`` (variants, 1) its speed at the sweep's first position: the share is
    ``|first| / |speed|``, the time per unit of the driver's position relative to the
    first position's (exactly 1 at a constant speed). A speed of zero, not finite,
    or turning the other way from the first has no share: the weights are then 1
    there.
    """
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.abs(first) / np.abs(speed)
    usable = np.isfinite(w) & (w > 0.0) & (np.sign(speed) == np.sign(first))
    return np.where(usable, w, 1.0), not bool(np.all(usable))
