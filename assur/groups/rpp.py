"""RPP dyad: a pinned link sliding in (or carrying) a slider on a known guide.

The middle prismatic pair makes the pinned link turn with the slider, whose rotation
the external guide fixes; what is left is linear in the slide.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from assur.groups._dyad import DyadSolver, compile_dyad, linear_step
from assur.groups._motion import Motion
from assur.groups._protocol import CompileContext

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["assemble", "compile_group"]


def assemble(plan: DyadSolver, bodies: list[Motion], branch: Any) -> tuple[Any, Any]:
    """Return the pinned link's rotation (rad) and the slider's slide (m)."""
    return linear_step(plan, bodies, bodies[plan.known[1]].phi[0], 0.0)


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an RPP dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble)
