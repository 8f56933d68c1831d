"""A larger group's equilibrium: its linear system with the numbers, solved.

A triad (or any group without a textbook sequence) is written as the equations
:meth:`~assur.groups._protocol.Equilibrium.equations` gives: each link's two force
sums and its moment equation, the known loads on the right, then the solution.
"""

from __future__ import annotations

import numpy as np

from assur.explain._note import Block, Display, Para
from assur.explain._position import Position
from assur.explain._tex import name, num, par, text
from assur.groups._protocol import Equilibrium

__all__ = ["system_blocks"]


def system_blocks(pos: Position, rec: Equilibrium) -> list[Block]:
    """Return a larger group's equilibrium equations as a linear system, solved."""
    eq = rec.equations(pos.bodies, pos.plan.bodies)
    a, rhs, x = eq.matrix[0], eq.rhs[0], eq.solution[0]
    symbols = [_unknown(u) for u in eq.unknowns]
    ref = float(np.abs(a).max())
    lines = []
    for i, row in enumerate(eq.rows):
        terms = [
            f"{par(a[i, k], ref)}\\,{symbols[k]}"
            for k in range(len(symbols))
            if abs(a[i, k]) > 1e-12 * ref
        ]
        lines.append(
            f"\\text{{{text(row)}}}:\\ " + " + ".join(terms) + f" = {num(rhs[i])}"
        )
    values = [f"{sym} = {num(v)}" for sym, v in zip(symbols, x, strict=True)]
    return [
        Para(
            "Each link's two force sums and its moment equation, with the known loads "
            "on the right (N, N m):"
        ),
        Display(tuple(lines)),
        Para("Solved together:"),
        Display(tuple(values)),
    ]


def _unknown(key: str) -> str:
    """Return the TeX of an unknown such as ``B.Fx`` or ``guide.N``."""
    joint, _, part = key.rpartition(".")
    what = {"Fx": "F_{x}", "Fy": "F_{y}", "N": "N", "M": "M"}[part]
    return f"{what}^{{{name(joint)}}}"
