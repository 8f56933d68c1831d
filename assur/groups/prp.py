"""PRP dyad: two sliders on known guides, pinned to each other.

The pin is where the two slide lines cross; the equations are linear in the slides.
"""

from __future__ import annotations

from typing import Any

from assur.groups._dyad import DyadPlan, linear_step
from assur.groups._motion import Motion

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Any, Any]:
    """Return both sliders' slides (m): the crossing of their lines."""
    return linear_step(plan, bodies, 0.0, 0.0)
