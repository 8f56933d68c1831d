"""PRP dyad: two sliders on known guides, pinned to each other.

The pin is where the two slide lines cross; the equations are linear in the slides.
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
    """Return both sliders' slides (m): the crossing of their lines."""
    return linear_step(plan, bodies, 0.0, 0.0)


def compile_group(context: CompileContext, group: Group) -> DyadSolver:
    """Compile an PRP dyad of a mechanism (its branch from the reference pose)."""
    return compile_dyad(context, group, assemble)
