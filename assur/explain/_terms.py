"""The vectors of a velocity or acceleration equation, and a slider's terms.

A :class:`Term` is one vector of an equation the note writes (``v_C = v_B + v_CB``):
known, with its value and how it follows, or unknown, a magnitude times a known
direction. A slider's point adds the guide's point under it (worked out from the
guide's pin), the Coriolis term of a turning guide and the relative motion.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assur._vec import Array
from assur.explain._position import Position, perp
from assur.explain._tex import (
    LENGTH,
    ROTATION,
    name,
    num,
    par,
    point_name,
    text,
    unit,
    vec,
)

__all__ = ["LEVEL", "SPEED", "TURN", "Term", "sliding"]

LEVEL = {1: ("v", "velocities"), 2: ("a", "accelerations")}
SPEED = {k: unit(LENGTH[k]) for k in (1, 2)}
"""The unit of a point's velocity (k = 1) or acceleration (k = 2)."""
TURN = {k: unit(ROTATION[k]) for k in (1, 2)}
"""The unit of a link's angular velocity (k = 1) or acceleration (k = 2)."""


@dataclass(frozen=True, slots=True)
class Term:
    """One vector of a velocity or acceleration equation.

    ``tex`` names it, ``value`` is its vector now (m/s or m/s^2), ``note`` tells its
    direction and size; an unknown term is ``unknown`` times ``column``.
    """

    tex: str
    value: Array
    note: str = ""
    unknown: str | None = None
    column: Array | None = None
    size: str = ""
    working: str = ""
    """How a known term follows from a point shown before, ending before its value
    (``\\vec v_O + ... = (0,\\ 0) + 4 \\cdot ...``); empty when it is given."""
    own_line: bool = False
    """Whether ``note`` goes on a line of its own under the value (a long one)."""


def sliding(
    pos: Position,
    guide: int,
    slider: int,
    m: Array,
    e: Array,
    j: str,
    base: str,
    k: int,
) -> list[Term]:
    """Terms of a slider's point at ``m``: the guide's point there, relative motion."""
    letter = LEVEL[k][0]
    rel = float(np.dot(pos.coincident(slider, m, 1) - pos.coincident(guide, m, 1), e))
    terms = [
        Term(
            f"\\vec {letter}_{{{base}}}",
            pos.coincident(guide, m, k),
            f"\\text{{the point of {text(pos.link(guide))} at }} {j}",
            working=_from_pin(pos, guide, m, base, k),
        )
    ]
    if k == 1:
        return [
            *terms,
            Term(
                f"\\vec v^{{r}}_{{{j}}}",
                rel * e,
                f"\\parallel \\vec e_{{{j}}} = {vec(e)}",
                f"\\dot s_{{{j}}}",
                e,
            ),
        ]
    wg = pos.omega(guide)
    acc = float(
        np.dot(
            pos.coincident(slider, m, 2)
            - pos.coincident(guide, m, 2)
            - 2 * wg * rel * perp(e),
            e,
        )
    )
    # the frame never turns: no Coriolis term to write (2 * 0 * v_r = 0 was noise)
    coriolis = (
        []
        if guide == 0
        else [
            Term(
                f"\\vec a^{{k}}_{{{j}}}",
                2 * wg * rel * perp(e),
                _coriolis(pos, guide, j, wg, rel),
                own_line=True,
            )
        ]
    )
    return [
        *terms,
        *coriolis,
        Term(
            f"\\vec a^{{r}}_{{{j}}}",
            acc * e,
            f"\\parallel \\vec e_{{{j}}}",
            f"\\ddot s_{{{j}}}",
            e,
        ),
    ]


def _coriolis(pos: Position, guide: int, j: str, wg: float, rel: float) -> str:
    """Return what the Coriolis term of slide ``j`` is: its rule, direction, size.

    Its size is ``2 |omega| |v_r|``; its direction the relative velocity turned by
    a quarter turn the way the guide turns (no direction when either is zero).
    """
    link = name(pos.link(guide))
    rule = f"2\\,\\omega_{{{link}}}\\,\\vec k \\times \\vec v^{{r}}_{{{j}}}"
    size = (
        f"a^k = 2\\,|\\omega_{{{link}}}|\\,v^{{r}}_{{{j}}} = 2 \\cdot {num(abs(wg))} "
        f"\\cdot {num(abs(rel))} = {num(2 * abs(wg * rel))}{SPEED[2]}"
    )
    if num(2 * abs(wg * rel)) == "0":
        return f"{rule},\\ {size}"
    sense = "counter-clockwise" if wg > 0 else "clockwise"
    return (
        f"{rule}:\\ \\vec v^{{r}}_{{{j}}} \\text{{ turned }} 90^\\circ\\ "
        f"\\text{{{sense}, as link {text(pos.link(guide))} turns}},\\ {size}"
    )


def _from_pin(pos: Position, guide: int, m: Array, label: str, k: int) -> str:
    """Return how the guide's point at ``m`` moves, from a pin of the guide.

    The note showed the motion of the guide link's pins before (the crank's pivot,
    the joint of an earlier group); the point of the guide under the slider is
    found from one of them like any other point of the link. Empty for the frame
    (its points stand still) and for a guide without a pin.
    """
    if guide == 0:
        return ""
    pins = [p for p in pos.pairs_of(guide) if p.kind == "R"]
    if not pins:
        return ""
    pin = pins[0]
    offset = pin.d_first if pin.first == guide else pin.d_second
    r = m - pos.point(guide, offset)
    x = point_name(pin.name.split("~")[0])
    base = pos.point(guide, offset, k)
    if math.hypot(*r) <= 1e-12 * pos.size():
        return f"\\vec {LEVEL[k][0]}_{{{x}}}"
    link = name(pos.link(guide))
    w = pos.omega(guide)
    if k == 1:
        return (
            f"\\vec v_{{{x}}} + \\omega_{{{link}}}\\,\\vec k \\times \\vec "
            f"r_{{{x}{label}}} = {vec(base)} + {par(w)} \\cdot \\vec k \\times {vec(r)}"
        )
    return (
        f"\\vec a_{{{x}}} + \\varepsilon_{{{link}}}\\,\\vec k \\times \\vec "
        f"r_{{{x}{label}}} - \\omega_{{{link}}}^2 \\vec r_{{{x}{label}}} = "
        f"{vec(base)} + {par(pos.epsilon(guide))} \\cdot \\vec k \\times {vec(r)} - "
        f"{par(w)}^2 \\cdot {vec(r)}"
    )
