"""Solvers of the Assur groups: one module per group family, and their registry.

Every family module has a ``compile_group(context, group)`` function that returns an
object answering the group-solver protocol (:mod:`assur.groups._protocol`): assemble,
linearise, derivatives of any order, equilibrium. The five dyad kinds share their
derivatives and reactions (``_dyad``) and differ in their closed-form assembly;
class III triads and larger groups are solved by Newton's method (``general``).
Adding a group family means one module and one line in :data:`FAMILIES`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from assur.groups import general, prp, rpp, rpr, rrp, rrr
from assur.groups._protocol import CompileContext, GroupSolver

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["FAMILIES", "Compiler", "compile_group"]

Compiler = Callable[[CompileContext, "Group"], GroupSolver]
"""A family's compile function: the solver of one group of a mechanism."""

FAMILIES: dict[str, Compiler] = {
    "RRR": rrr.compile_group,
    "RRP": rrp.compile_group,
    "RPR": rpr.compile_group,
    "PRP": prp.compile_group,
    "RPP": rpp.compile_group,
    "triad": general.compile_group,
    "general": general.compile_group,
}
"""The solver family of each group kind of the decomposition."""


def compile_group(context: CompileContext, group: Group) -> GroupSolver:
    """Return the solver of ``group``, from the family its kind names."""
    return FAMILIES[group.kind](context, group)
