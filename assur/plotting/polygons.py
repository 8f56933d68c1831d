"""The force polygon of every Assur group, drawn as a student draws it.

Each polygon runs through the known loads on the group's links and their outer
reactions, tip to tail, to its own scale (so many N per mm); each side's name is
put beside it, outside the polygon, clear of the other sides and names.
matplotlib is imported inside the functions only.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._digits import ROUND_OFF
from assur._style import REACTION_COLOUR
from assur.errors import ModelError
from assur.explain._loads_text import link_loads
from assur.explain._position import Position
from assur.explain._tex import name as tex_name
from assur.plotting._drawing import _arrow_apart, _legend
from assur.plotting._key import keys_clear
from assur.plotting._mathtext import _symbol, reaction_symbol
from assur.plotting._numbers import quantity
from assur.plotting._placing import Name, place_names
from assur.plotting._style import (
    INERTIA_COLOR,
    LOAD_COLOR,
    REACTION_LEGEND,
    literal,
    load_colour,
)
from assur.plotting.plans import _pos, _scale, _title

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from assur.table import Table

__all__ = ["force_polygons"]

TINY_SIDE = 1e-9
"""A side shorter than this times the polygon's longest is round-off: not drawn."""


def force_polygons(table: Table, angle: Any = None) -> Figure:
    """Draw the force polygon of every Assur group (reverse order), closed.

    Each polygon runs through the known loads on the group's first link and its
    outer reaction (with its friction force), then those of the next link: the
    group is in equilibrium, so the polygon closes at its start (the title says
    so, or gives the gap where it is more than round-off, see :func:`_closing`).

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib.pyplot as plt

    from assur.plotting._context import _need_forces

    _need_forces(table, "force_polygons")
    pos = _pos(table, angle)
    assert pos.result is not None
    records = pos.result.groups
    if not records:
        msg = (
            "force_polygons: the mechanism has no Assur group, so no polygon; "
            "expected a mechanism whose input links move a group"
        )
        raise ModelError(msg)
    fig, axes = plt.subplots(1, len(records), figsize=(5.5 * len(records), 5.2),
                             layout="constrained", squeeze=False)  # fmt: skip
    solved: set[int] = set()
    names = []
    for ax, rec in zip(axes.flat, records, strict=True):
        names.append(_polygon(ax, pos, rec, solved))
        solved |= set(rec.bodies)
    fig.suptitle(_title(pos, "force polygons"), fontsize=10)
    # the sides meet at the polygon's corners: each name beside its own side,
    # outside the polygon, clear of the other sides and names; one layout for
    # every polygon (laying the whole figure out again for each polygon made the
    # time grow as the square of the number of groups)
    # a key over the sides goes beside its polygon
    texts = [n.text for own in names for n in own]
    renderer = keys_clear(list(axes.flat), texts, widen=True)
    for ax, own in zip(axes.flat, names, strict=True):
        place_names(ax, own, renderer=renderer)
    return fig


def _polygon(ax: Any, pos: Position, rec: Any, solved: set[int]) -> list[Name]:
    """Draw one group's force polygon on ``ax``; return its sides' names to place."""
    sequence: list[tuple[str, np.ndarray, str]] = []
    for body in rec.bodies:
        pair = _outer(pos, rec, body)
        # a sliding pair's reaction is its normal part: its friction force is listed
        for load in link_loads(pos, body, solved, [p.name for p in pair]):
            if math.hypot(*load.force) > 0:  # a couple is no side of the polygon
                sequence.append((_symbol(load.tex), load.force, load_colour(load.tex)))
        for p in pair:
            r = rec.reactions[p.name]
            sign = 1.0 if p.second == body else -1.0
            f = sign * np.array([float(np.ravel(r.fx)[0]), float(np.ravel(r.fy)[0])])
            other = p.first if p.second == body else p.second
            symbol = reaction_symbol(pos.link(other), pos.link(body))
            if p.kind == "P" and p.friction > 0.0:
                # its normal part only, as the note names it: F_f is its own side
                normal = f"\\vec N_{{{tex_name(p.name)}}}"
                symbol = _symbol(normal if sign > 0 else "-" + normal)
            sequence.append((symbol, f, REACTION_COLOUR))
    mu = _scale([f for _, f, _ in sequence])
    tips = np.cumsum([np.zeros(2)] + [f / mu for _, f, _ in sequence], axis=0)
    longest = max(float(np.hypot(*f)) for _, f, _ in sequence) / mu
    # the names go outside the polygon, away from its middle
    middle = tips[:-1].mean(axis=0)
    names = []
    drawn: list[tuple[np.ndarray, np.ndarray]] = []
    for (label, _, color), tip, end in zip(sequence, tips[:-1], tips[1:], strict=True):
        # a side of round-off (a slider's inertia force at mid-stroke) is nothing:
        # neither drawn nor named, though the next side starts at its tip
        if float(np.hypot(*(end - tip))) <= TINY_SIDE * longest:
            continue
        # at a dead centre the sides lie on one line, each over the one before:
        # moved aside, each can be seen and named
        ends = _arrow_apart(ax, drawn, tip, end, color)
        if ends is None:
            continue
        text = ax.annotate(label, tuple(0.5 * (ends[0] + ends[1])), color=color,
                           fontsize=7)  # fmt: skip
        names.append(Name(text, *ends, middle))
    tip = tips[-1]
    ax.plot([0], [0], "ko", ms=4)
    # room round the polygon for the names outside it
    ax.margins(0.12)
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, lw=0.4, alpha=0.4)
    ax.set_xlabel("mm of the polygon")
    ax.set_title(
        f"group {literal(rec.label)}: {_closing(float(np.hypot(*tip)), longest)}",
        fontsize=9,
    )
    # the colours of the mechanism drawings, so a reaction reads alike in both
    kinds = {
        REACTION_COLOUR: REACTION_LEGEND,
        INERTIA_COLOR: "inertia force",
        LOAD_COLOR: "gravity, external load",
    }
    shown = {c for _, _, c in sequence}
    entries = [(text, c) for c, text in kinds.items() if c in shown]
    # the scale once, in the key beside the drawing, as a textbook writes μF by its
    # polygon and as the velocity and acceleration plans write theirs: the title
    # says what the drawing shows (its group, whether it closes)
    _legend(ax, entries, f"scale: μF = {quantity(mu, 'N/mm', 6)}")
    return names


def _closing(gap: float, longest: float) -> str:
    """Return how a polygon closes: its ``gap`` (mm), told from round-off.

    A gap below :data:`assur._digits.ROUND_OFF` of the ``longest`` side (mm) is
    round-off, 7.1e-15 mm on one machine and 0 on another by the order of the
    sums: the polygon closes. A larger one is a polygon left open, written out.

    Examples
    --------
    >>> _closing(7.1e-15, 60.0), _closing(0.0, 60.0), _closing(0.25, 60.0)
    ('the polygon closes', 'the polygon closes', 'the polygon is open by 0.25 mm')
    """
    # "group RRP (rod, slider): closes" read as if the group closed
    if gap <= ROUND_OFF * longest:
        return "the polygon closes"
    return f"the polygon is open by {gap:.2g} mm"


def _outer(pos: Position, rec: Any, body: int) -> list[Any]:
    """Return the pairs of ``rec`` that join ``body`` to a link outside the group."""
    inside = set(rec.bodies)
    return [
        p
        for p in rec.pairs
        if body in (p.first, p.second) and not {p.first, p.second} <= inside
    ]
