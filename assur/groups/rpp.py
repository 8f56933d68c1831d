"""RPP dyad: a pinned link sliding in (or carrying) a slider on a known guide.

The middle prismatic pair makes the pinned link turn with the slider, whose rotation
the external guide fixes; what is left is linear in the slide.
"""

from __future__ import annotations

from typing import Any

from assur.groups._dyad import DyadPlan, linear_step
from assur.groups._motion import Motion

__all__ = ["assemble"]


def assemble(plan: DyadPlan, bodies: list[Motion]) -> tuple[Any, Any]:
    """Return the pinned link's rotation (rad) and the slider's slide (m)."""
    return linear_step(plan, bodies, bodies[plan.known[1]].phi[0], 0.0)
