"""The inertia loads of every link: Fi = m aG against aG, Mi = JG eps against eps.

The single equivalent force is the inertia force moved off the centre of mass by
h = Mi / Fi, so that its moment about G is the inertia torque.
"""

from __future__ import annotations

import math

import numpy as np

from assur.explain._loads_text import inertia_load
from assur.explain._note import Block, Display, Heading, Para
from assur.explain._position import Position
from assur.explain._tex import deg, kept, name, par, plain, point_name, vec

__all__ = ["inertia_blocks"]


def _link(pos: Position, body: int) -> list[str]:
    """Return the inertia loads of one link with their numbers."""
    found = inertia_load(pos, body)
    assert found is not None
    force, torque = found
    link = name(pos.link(body))
    g = point_name(f"{pos.link(body)}.G")
    mass = float(pos.loads.mass[body])
    inertia = float(pos.loads.inertia[body])
    a = pos.point(body, pos.loads.center[body], 2)
    size = math.hypot(*a)
    eps = pos.epsilon(body)
    # every value here is a datum or cleaned of its round-off relative to the
    # mechanism's motion: a small link's are shown however small
    lines = [
        f"\\vec a_{{{g}}} = {vec(a)}\\ \\mathrm{{m/s^2}},\\quad a_{{{g}}} = "
        f"{kept(size)}\\ \\mathrm{{m/s^2}}",
        f"F_{{i,{link}}} = m_{{{link}}} a_{{{g}}} = {kept(mass)} \\cdot {kept(size)} = "
        f"{kept(mass * size)}\\ \\mathrm{{N}}",
    ]
    if size > 0:
        lines.append(
            f"\\vec F_{{i,{link}}} = -m_{{{link}}} \\vec a_{{{g}}} = {vec(force)}\\ "
            f"\\mathrm{{N}},\\quad \\text{{at }} {deg(math.atan2(force[1], force[0]))}"
            " \\text{ (against } \\vec a_G\\text{)}"
        )
    lines.append(
        f"M_{{i,{link}}} = -J_{{{g}}} \\varepsilon_{{{link}}} = -{kept(inertia)} "
        f"\\cdot {par(eps, abs(eps))} = {kept(torque)}\\ \\mathrm{{N\\,m}}"
    )
    if mass * size > 0 and torque:
        lines.append(
            f"h_{{{link}}} = \\frac{{|M_{{i,{link}}}|}}{{F_{{i,{link}}}}} = "
            f"\\frac{{{kept(abs(torque))}}}{{{kept(mass * size)}}} = "
            f"{kept(abs(torque) / (mass * size))}\\ \\mathrm{{m}}"
        )
    return lines


def inertia_blocks(pos: Position) -> list[Block]:
    """Return the inertia loads of every link with a mass."""
    bodies = [b for b in range(1, len(pos.plan.bodies)) if pos.loads.mass[b]]
    blocks: list[Block] = [
        Heading(2, "3. Inertia loads"),
        Para(
            "Each link with a mass carries d'Alembert's inertia force $\\vec F_i = "
            "-m \\vec a_G$ at its centre of mass and the inertia torque $M_i = -J_G "
            "\\varepsilon$ (counter-clockwise positive). Together they are one force "
            "$\\vec F_i$ moved off $G$ by $h = |M_i| / F_i$, to the side where its "
            "moment about $G$ turns like $M_i$."
        ),
    ]
    if not bodies:
        return [*blocks, Para("No link has a mass: there are no inertia loads.")]
    for b in bodies:
        blocks += [
            Heading(3, f"Link {plain(pos.link(b))}"),
            Display(tuple(_link(pos, b))),
        ]
    gravity = np.asarray(pos.loads.gravity, dtype=float)
    if gravity.any():
        blocks.append(
            Para(
                f"Gravity $\\vec g = {vec(gravity)}\\ \\mathrm{{m/s^2}}$ adds the "
                "weight $m \\vec g$ of each link at its centre of mass."
            )
        )
    return blocks
