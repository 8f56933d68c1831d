"""Force arrows: the loads a picture shows and their scale.

An :class:`_Arrow` is a force at a point or a couple; forces are drawn to a scale in
N per cm of drawing (the drawing is in metres), couples as arcs
(:mod:`assur.plotting._arrows`).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._style import REACTION_COLOUR
from assur._vec import full
from assur.plotting._context import _unit
from assur.plotting._friction import shown_point
from assur.plotting._geometry import _anchor, _nice, _public
from assur.plotting._mathtext import couple_symbol, reaction_symbol
from assur.plotting._numbers import quantity
from assur.plotting._style import (
    ARROW_LENGTH,
    BALANCING_COLOR,
    INERTIA_COLOR,
    LOAD_COLOR,
    math_name,
)

if TYPE_CHECKING:
    from assur.analysis import Table
    from assur.plotting._context import _Context, _Pose


@dataclass(frozen=True)
class _Arrow:
    """One load of a picture: a force at a point or a couple (N, N m).

    ``units`` are those of the force and of the couple, as the schema gives them for
    the columns of such loads ("" for a part the load has not); ``kind`` is one of
    "inertia", "gravity", "load", "reaction" (on the body or group drawn),
    "internal" (between two links of a group, on the pair's second link),
    "opposite" (the same on its first link, drawn without a name) and "balancing".
    """

    label: str
    point: np.ndarray
    force: np.ndarray | None
    couple: float | None
    color: str
    units: tuple[str, str]
    kind: str
    shown: np.ndarray | None = None
    """Where the force is drawn, when not at ``point``: a reaction tangent to its
    enlarged friction circle (:mod:`assur.plotting._friction`)."""
    couple_label: str | None = None
    """The couple's own name when it has one beside the force's (a sliding pair's
    reaction); ``label`` otherwise."""

    @property
    def at(self) -> np.ndarray:
        """Return the point the arrow is drawn from, m."""
        return self.point if self.shown is None else self.shown


def _units(table: Table, force: str = "", couple: str = "") -> tuple[str, str]:
    """Return the units of the columns ``force`` and ``couple`` ("" for none)."""
    return (
        _unit(table, force) if force else "",
        _unit(table, couple) if couple else "",
    )


def _tex(name: str) -> str:
    """Return ``name`` for a mathtext label (inside a subscript), drawn as written."""
    return math_name(name)


def _reaction(
    ctx: _Context, pose: _Pose, row: int, name: str, sign: float = 1.0
) -> tuple[np.ndarray, np.ndarray, float | None]:
    """Reaction of pair ``name`` on its second link (``sign`` -1: on its first).

    A prismatic pair's normal force is placed where it balances the pair's couple;
    the couple is returned separately when that point lies too far away. A revolute
    pair with friction has its force on the line tangent to its friction circle where
    the force's moment about the pin is the friction couple, as the books draw it.
    """
    pair = ctx.plan.pairs[name]
    force, couple = ctx.forces.reaction(name, len(ctx.table))
    f = sign * np.asarray(force[row], dtype=float)
    q = pose.at(pair.second, pair.d_second)
    if pair.kind == "R":
        size = float(np.dot(f, f))
        if name in ctx.forces.friction and size > 0.0:
            # the same line for the force on either link: sign enters twice
            mf = sign * float(full(ctx.forces.friction[name], len(ctx.table))[row])
            q = q + (mf / size) * np.array([f[1], -f[0]])
        return q, f, None
    e = pose.turn(pair.first, pair.axis)
    normal = float(np.dot(f, np.array([-e[1], e[0]])))
    m = sign * float(couple[row])
    # a normal force of round-off is that of the reaction, not 1e-9 N: a watch's
    # slot pressed by 1e-10 N is drawn where it acts, not as a couple beside it
    if abs(normal) > 1e-9 * float(np.hypot(*f)) and abs(m / normal) < 0.5 * ctx.size:
        return q + (m / normal) * e, f, None
    return q, f, m


def _centre(table: Table, link: str, row: int) -> np.ndarray:
    """Centre of mass of ``link`` at ``row``, m."""
    return np.array([table[f"{link}.G.x"][row], table[f"{link}.G.y"][row]])


def _inertia_arrows(ctx: _Context, row: int, links: Iterable[str]) -> list[_Arrow]:
    """Inertia force at the centre of mass and inertia torque of each massive link."""
    fs = ctx.forces
    arrows = []
    for link in links:
        if not ctx.table.mechanism.link(link).mass:
            continue
        b, g, name = ctx.plan.body(link), _centre(ctx.table, link, row), _tex(link)
        forces, torques = fs.inertia_load(b, len(ctx.table))
        force, torque = forces[row], float(torques[row])
        units = _link_units(ctx.table, link)
        arrows += [
            _Arrow(
                f"$F_{{i,{name}}}$", g, force, None, INERTIA_COLOR, units, "inertia"
            ),
            _Arrow(
                f"$M_{{i,{name}}}$", g, None, torque, INERTIA_COLOR, units, "inertia"
            ),
        ]
    return arrows


def _applied_arrows(
    ctx: _Context, pose: _Pose, row: int, links: list[str], bodies: set[int]
) -> list[_Arrow]:
    """Return the weights of ``links`` and the external loads on ``bodies`` at ``row``.

    The loads applied to a free body (:func:`draw_free_body`) or to every link
    (:func:`draw`), drawn alike.
    """
    return _gravity_arrows(ctx.table, links, row) + _load_arrows(ctx, pose, row, bodies)


def _gravity_arrows(table: Table, links: list[str], row: int) -> list[_Arrow]:
    """Return the weight of each massive link of ``links``, at its centre of mass."""
    mech = table.mechanism
    if mech.gravity is None or not any(mech.gravity):
        return []
    g = np.asarray(mech.gravity, dtype=float)
    return [
        _Arrow(
            f"$m_{{{_tex(x)}}} g$",
            _centre(table, x, row),
            mech.link(x).mass * g,
            None,
            LOAD_COLOR,
            _link_units(table, x),
            "gravity",
        )
        for x in links
        if mech.link(x).mass
    ]


def _load_arrows(
    ctx: _Context, pose: _Pose, row: int, bodies: set[int]
) -> list[_Arrow]:
    """Return the external forces and torques on ``bodies`` at ``row``."""
    from assur.model import resolve_point

    plan, mech = ctx.plan, ctx.table.mechanism
    arrows = []
    number = _load_numbers(mech.loads)
    for i, load in enumerate(mech.loads):
        b = plan.body(load.link)
        if b not in bodies:
            continue
        name, units = _tex(load.link), _link_units(ctx.table, load.link)
        if load.force is not None:
            assert load.at is not None  # the model requires a force's point
            at = pose.at(b, plan.offset(b, resolve_point(mech, load.at)))
            force = _load_value(ctx, row, load.force, f"loads[{i}].force")
            arrows.append(
                # Q, as the note writes it: F_{i,j} is the force of link i on link j
                _Arrow(
                    f"$Q_{{{name},{number[i, 'force']}}}$",
                    at,
                    force,
                    None,
                    LOAD_COLOR,
                    units,
                    "load",
                )
            )
        if load.torque is not None:
            at = _anchor(ctx, pose, b)
            torque = _load_value(ctx, row, load.torque, f"loads[{i}].torque")
            arrows.append(
                _Arrow(
                    f"$T_{{{name},{number[i, 'torque']}}}$",
                    at,
                    None,
                    float(torque[0]),
                    LOAD_COLOR,
                    units,
                    "load",
                )
            )
    return arrows


def _load_numbers(loads: Sequence[Any]) -> dict[tuple[int, str], int]:
    """Return the number of each external force and torque on its link (the note's).

    A link's forces come first, 1, 2, ... in the file's order, then its torques:
    Q_{ram,1} here is the note's and the polygons' Q_{ram,1}. Keys are the load's
    index and ``"force"`` or ``"torque"``.
    """
    count: dict[str, int] = {}
    number = {}
    for part in ("force", "torque"):
        for i, load in enumerate(loads):
            if getattr(load, part) is not None:
                count[load.link] = number[i, part] = count.get(load.link, 0) + 1
    return number


def _load_value(ctx: _Context, row: int, value: Any, entry: str) -> np.ndarray:
    """Return a load's value at ``row``: constant, or from its load table (N, N m)."""
    from assur._loads import table_values
    from assur.model import LoadTable

    if not isinstance(value, LoadTable):
        return np.atleast_1d(np.asarray(value, dtype=float))
    state = ctx.table.state
    drive = state.drive[row : row + 1]
    slides = {
        k: full(s[0], len(ctx.table))[row : row + 1] for k, s in state.slide.items()
    }
    values = table_values(value, ctx.plan, drive, slides, entry)
    return np.array([c[0] for c in values])


def _link_units(table: Table, link: str) -> tuple[str, str]:
    """Units of a force and a torque on ``link``: of its inertia loads' columns."""
    return _units(table, f"{link}.Fi.x", f"{link}.Mi")


def _reaction_units(table: Table, name: str) -> tuple[str, str]:
    """Units of the reaction at pair ``name``, a slot's pin's those of its slot."""
    joint = _public(name)
    couple = f"{joint}.M" if table.plan.pairs[joint].kind == "P" else ""
    return _units(table, f"{joint}.Fx", couple)


def _overview_arrows(ctx: _Context, pose: _Pose, row: int) -> list[_Arrow]:
    """Inertia loads, applied loads, reactions and balancing loads at ``row``.

    The loads of :func:`draw`: with the reactions, those on each link balance.
    """
    links = [link.name for link in ctx.table.mechanism.links]
    bodies = set(range(len(ctx.plan.bodies)))
    arrows = _inertia_arrows(ctx, row, links)
    arrows += _applied_arrows(ctx, pose, row, links, bodies)
    for name, pair in ctx.plan.pairs.items():
        if not pair.virtual:
            arrows.append(_reaction_arrow(ctx, pose, row, name, 1.0, "reaction"))
    return arrows + _balancing_arrows(ctx, pose, row)


def _reaction_arrow(
    ctx: _Context, pose: _Pose, row: int, name: str, sign: float, kind: str
) -> _Arrow:
    """Return the reaction of pair ``name`` on its second link (``sign`` -1: first).

    Named the force of the other link on the one it acts on; a journal's drawn
    tangent to its friction circle as that circle is drawn, enlarged.
    """
    pair = ctx.plan.pairs[name]
    q, f, m = _reaction(ctx, pose, row, name, sign)
    by, on = (ctx.plan.bodies[b] for b in (pair.first, pair.second))
    ends = (by, on) if sign > 0 else (on, by)
    units = _reaction_units(ctx.table, name)
    shown = None
    if pair.kind == "R" and name in ctx.forces.friction:
        shown = shown_point(ctx, pose.at(pair.second, pair.d_second), q)
    # a couple drawn apart is named as one: "F = -200 N m" read as a force
    couple = couple_symbol(*ends) if m is not None else None
    return _Arrow(
        reaction_symbol(*ends), q, f, m, REACTION_COLOUR, units, kind, shown, couple
    )


def _balancing_arrows(ctx: _Context, pose: _Pose, row: int) -> list[_Arrow]:
    """Return the balancing torque (force, for a prismatic driver) of each driver."""
    drivers = ctx.plan.drivers
    arrows = []
    for i, d in enumerate(drivers):
        p = pose.at(d.pair.second, d.pair.d_second)
        value = float(full(ctx.forces.balancing[i], len(ctx.table))[row])
        # the note's symbols: M_b for a torque, F_b for a force
        letter = "M" if d.kind == "R" else "F"
        many = len(drivers) > 1
        label = f"${letter}_{{b,{_tex(d.pair.name)}}}$" if many else f"${letter}_b$"
        owner = "driver" if len(drivers) == 1 else d.pair.name
        if d.kind == "R":
            units = _units(ctx.table, couple=f"{owner}.torque")
            arrow = _Arrow(label, p, None, value, BALANCING_COLOR, units, "balancing")
        else:
            e = pose.turn(d.pair.first, d.pair.axis)
            units = _units(ctx.table, force=f"{owner}.force")
            arrow = _Arrow(
                label, p, value * e, None, BALANCING_COLOR, units, "balancing"
            )
        arrows.append(arrow)
    return arrows


def _scale_text(arrows: Iterable[_Arrow], scale: float) -> str:
    """Return the legend's note of the force scale, in the forces' unit."""
    units = dict.fromkeys(a.units[0] for a in arrows if a.force is not None)
    # the drawing is in the mechanism's metres: a centimetre read on its axes,
    # not on the page (whose size the viewer chooses)
    return f"force scale: 1 cm on the axes = {quantity(scale, ' or '.join(units), 6)}"


def _scale(arrows: Iterable[_Arrow], size: float) -> float:
    """Return the default force scale, N per cm: the largest arrow 28 % of ``size``."""
    big = max(
        (float(np.hypot(*a.force)) for a in arrows if a.force is not None), default=0.0
    )
    return _nice(big / (ARROW_LENGTH * size * 100.0))
