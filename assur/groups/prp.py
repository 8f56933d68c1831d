"""PRP dyad: two sliders on known guides, pinned to each other.

The pin is where the two slide lines cross; the equations are linear in the slides.
"""

from __future__ import annotations

import numpy as np

from assur._vec import Array
from assur.groups._dyad import DyadPlan, linear_step
from assur.groups._motion import Motion

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Array, Array]:
    """Return both sliders' slides (m): the crossing of their lines."""
    zero = np.zeros(bodies[plan.known[0]].o[0].shape[0])
    return linear_step(plan, bodies, zero, zero)
