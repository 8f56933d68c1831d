"""A larger group's equilibrium: its linear system with the numbers, solved.

A triad (or any group without a textbook sequence) is written as the equations
:meth:`~assur.groups._protocol.Equilibrium.equations` gives: each link's two force
sums and its moment equation, the known loads on the right, then the solution.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from assur.explain._note import Block, Display, Para
from assur.explain._position import Position
from assur.explain._tex import name, num, par, plain, text
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
        Para(_meaning(pos, eq.unknowns)),
        Para(
            "Each link's two force sums and its moment equation, with the known loads "
            "on the right ($\\mathrm{N}$, $\\mathrm{N\\,m}$):"
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


def _meaning(pos: Position, unknowns: Sequence[str]) -> str:
    """Say what the unknowns are: each joint's load of its first link on its second.

    The table's columns of the same joint (``J.Fx``, ``J.Fy``, ``J.M``) hold the
    same loads.
    """
    joints = list(dict.fromkeys(u.rpartition(".")[0] for u in unknowns))
    pairs = []
    for joint in joints:
        pair = pos.plan.pairs[joint]
        first, second = plain(pos.link(pair.first)), plain(pos.link(pair.second))
        pairs.append(f"{plain(joint)}: {first} on {second}")
    # a sliding pair's unknowns are its normal force and its couple
    sliding = any(u.endswith((".N", ".M")) for u in unknowns)
    extra = (
        " (a sliding pair's normal force $N^{J}$ along its normal, and its couple "
        "$M^{J}$, the table's J.M)"
        if sliding
        else ""
    )
    return (
        "The unknowns are the loads in the joints, each of the joint's first link "
        f"on its second: $F_{{x}}^{{J}}, F_{{y}}^{{J}}$ as the table's J.Fx, J.Fy"
        f"{extra}. {'; '.join(pairs)}."
    )
