"""The stacked plan and loads of many variants, built from their rows of numbers.

The template's plan with each numeric field replaced by a leaf: one number when the
variants share it, else the variants' values repeated over their rows (``Rows``).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._loads import LoadPlan
from assur._stack import Rows
from assur._vec import Array
from assur.groups._dyad import DyadSolver, offsets
from assur.groups._pairs import PairPlan
from assur.groups.driver import DriverPlan
from assur.plan import Plan

if TYPE_CHECKING:
    from assur._variants import Template


Leaf = Callable[[Array], Any]


def _as_is(values: Array) -> Array:
    """Return each variant's value once (the leaves of the checks)."""
    return values


def _vector(x: Array, y: Array, leaf: Leaf) -> Any:
    """Return a vector whose components are leaves: Rows when one of them varies."""
    a, b = leaf(x), leaf(y)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return Rows((a, b))
    return (a, b)


def _pair_plans(
    t: Plan, offsets: dict[str, tuple[Array, Array]], leaf: Leaf
) -> dict[str, PairPlan]:
    """Return the template's pair plans with each variant's offsets.

    A slide line's direction is part of the :func:`form`: the kernels take it for a
    constant (a dictionary key, an angle computed once).
    """
    out = {}
    for name, p in t.pairs.items():
        first, second = offsets[name]
        out[name] = dataclasses.replace(
            p,
            d_first=_vector(first[:, 0], first[:, 1], leaf),
            d_second=_vector(second[:, 0], second[:, 1], leaf),
        )
    return out


def _dyad(
    solver: DyadSolver, pairs: dict[str, PairPlan], scale: Any, size: Any
) -> DyadSolver:
    """Return ``solver`` with the pairs ``pairs``, chosen as ``compile_dyad`` does.

    ``scale`` is the mechanisms' size and ``size`` the group's (m).
    """
    ext = (pairs[solver.ext[0].name], pairs[solver.ext[1].name])
    mid = pairs[solver.mid.name]
    bodies, known = solver.bodies, solver.known
    d_known, d_mid = offsets(ext, mid, bodies, known)
    return dataclasses.replace(
        solver,
        ext=ext,
        mid=mid,
        d_known=d_known,
        d_mid=d_mid,
        scale=scale,
        size=size,
        branch=1.0,
    )


def _plan(
    model: Template,
    rows: Array,
    leaf: Leaf,
    offsets: dict[str, tuple[Array, Array]],
    origins: Array,
    scale: Array,
    branches: list[Array],
    sizes: list[Array],
    points: bool = True,
) -> tuple[Plan, Array]:
    """Return the stacked plan, and every variant's reference driver position.

    ``branches`` and ``sizes`` (m) are each dyad's, one value per variant. Without
    ``points``, the reported points' offsets are the template's.
    """
    t = model.plan
    col = model.columns
    shift = np.asarray(t.shift)
    pairs = _pair_plans(t, offsets, leaf)
    size = leaf(scale)
    solvers = []
    for solver, branch, own in zip(t.solvers, branches, sizes, strict=True):
        assert isinstance(solver, DyadSolver)
        dyad = _dyad(solver, pairs, size, leaf(own))
        solvers.append(dataclasses.replace(dyad, branch=leaf(branch)))
    drivers = []
    references = np.zeros(rows.shape[0])
    for d in t.drivers:
        c = col.get(("angle", t.bodies[d.body]))
        angle = np.zeros(rows.shape[0]) if c is None else rows[:, c]
        if d.kind == "R":
            references = angle
        drivers.append(
            DriverPlan(
                pairs[d.pair.name],
                d.body,
                d.omega,
                d.epsilon,
                leaf(angle),
                _vector(origins[:, d.body, 0], origins[:, d.body, 1], leaf),
                leaf(angle) if d.kind == "R" else 0.0,
            )
        )
    offset = [p.d_second for p in pairs.values() if not p.virtual]
    mech = t.mechanism
    located = [(("point", p.name), t.index[p.link]) for p in mech.points] + [
        (("center", link.name), t.index[link.name])
        for link in mech.links
        if link.center is not None
    ]
    if not points:
        offset, located = list(t.point_offset), []
    for key, b in located:
        c = col[key]
        xy = rows[:, c : c + 2] - shift - origins[:, b]
        offset.append(_vector(xy[:, 0], xy[:, 1], leaf))
    plan = Plan(
        mech,
        t.topology,
        t.groups,
        t.bodies,
        t.origins,
        t.shift,
        t.angle0,
        tuple(drivers),
        tuple(solvers),
        pairs,
        t.points,
        t.point_body,
        tuple(offset),
        size,
        t.index,
    )
    return plan, references


def _loads(model: Template, rows: Array, leaf: Leaf, origins: Array) -> LoadPlan:
    """Return the stacked loads: the template's, with each variant's numbers."""
    t, first = model.plan, model.loads
    col = model.columns
    shift = np.asarray(t.shift)

    def offset(key: Any, b: int) -> Any:
        c = col[key]
        xy = rows[:, c : c + 2] - shift - origins[:, b]
        return _vector(xy[:, 0], xy[:, 1], leaf)

    mech = t.mechanism
    center: list[Any] = [(0.0, 0.0)] * len(t.bodies)
    stacked = []
    for link in mech.links:
        if link.mass:
            b = t.index[link.name]
            center[b] = offset(("center", link.name), b)
            c = col[("mass", link.name)]
            stacked.append((b, leaf(rows[:, c]), leaf(rows[:, c + 1])))
    forces, torques = [], []
    for i, load in enumerate(mech.loads):
        b = t.index[load.link]
        if load.force is not None:
            c = col[("force", i)]
            value = _vector(rows[:, c], rows[:, c + 1], leaf)
            forces.append((b, offset(("at", i), b), value, f"loads[{i}].force"))
        if load.torque is not None:
            torque = leaf(rows[:, col[("torque", i)]])
            torques.append((b, torque, f"loads[{i}].torque"))
    return LoadPlan(
        first.mass,
        tuple(center),
        first.inertia,
        first.gravity,
        tuple(forces),
        tuple(torques),
        tuple(sorted(stacked, key=lambda x: x[0])),
    )
