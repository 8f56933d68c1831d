"""The reduced model's curves as fast scalar functions of the crank angle.

A start-up integrates thousands of turns, each of hundreds of steps: the splines of
:class:`~assur.dynamics_reduced.Reduced` are evaluated here with plain floats, not
through scipy's array machinery.
"""

from __future__ import annotations

import math

from assur.dynamics_reduced import Reduced

__all__ = ["Curves"]


class Curves:
    """Fast scalar interpolants of ``J + J_f``, ``dJ/dphi`` and ``M`` (periodic)."""

    def __init__(self, model: Reduced, flywheel: float) -> None:
        self.start = model.start
        self.step = model.step
        self.count = model.angle.shape[0]
        j, m, _ = model.splines
        self.j = [list(map(float, row)) for row in j.c[:, : self.count]]
        self.m = [list(map(float, row)) for row in m.c[:, : self.count]]
        self.flywheel = flywheel

    def __call__(self, phi: float) -> tuple[float, float, float]:
        """Return ``J + J_f``, ``dJ/dphi`` and ``M`` at ``phi`` (rad)."""
        u = (phi - self.start) % (2.0 * math.pi)
        if not math.isfinite(u):
            # a trial step of the integrator past every float (a motor of 1e10 N m):
            # nothing to interpolate, and the step is refused
            return math.nan, math.nan, math.nan
        i = min(int(u / self.step), self.count - 1)
        x = u - i * self.step
        a, b, c, d = (row[i] for row in self.j)
        e, f, g, h = (row[i] for row in self.m)
        inertia = ((a * x + b) * x + c) * x + d + self.flywheel
        slope = (3.0 * a * x + 2.0 * b) * x + c
        return inertia, slope, ((e * x + f) * x + g) * x + h
