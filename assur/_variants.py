"""Plans of many variants of one mechanism, compiled at once over the variants.

Compiling one variant's plan (:func:`assur.plan.compile_plan`) costs more than solving
its 360 positions, and of that cost little depends on the variant's numbers: the
decomposition, the groups' kinds, the names. So the variants of a study are grouped by
their :func:`form` (the mechanism with its coordinates, masses, inertias and load
values left out); the first of a form that compiles is compiled as any mechanism is
and becomes the :class:`Template`, and every variant is read into one row of numbers
(:func:`numbers`). :func:`compile_many` then computes each numeric field of the
template's plan for all the rows at once with numpy, with the arithmetic of
``compile_plan`` (subtractions of the same coordinates, the same closures of the
dyads), so that a variant gets the numbers its own plan would hold, bit for bit. The
result is the stacked plan of :mod:`assur._stack`, built without a plan per variant
(``assur._variant_plans``).

``compile_plan`` refuses some mechanisms (a reference pose that a dyad does not close
or closes at a dead centre, a link too small beside the mechanism, ...). Those checks
are made on every row, with margins (``assur._variant_checks``): a variant that fails
or nearly fails one, or whose plan could not share the batch (the core's origin moved,
a branch nearly undecided), is marked and compiled on its own by the caller, so that
it fails or warns exactly as a separate call does. Only dyads are compiled so: a
template with a group solved by Newton's method is not stackable
(:func:`assur._stack.signature`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from assur._loads import LoadPlan, compile_loads
from assur._metres import LARGE
from assur._points import PointSpec
from assur._stack import repeat, signature
from assur._variant_checks import MARGIN, _branch, _small_links
from assur._variant_plans import Leaf, _as_is, _dyad, _loads, _pair_plans, _plan
from assur._vec import Array, Mask, diameters
from assur.groups._dyad import DyadSolver
from assur.groups._motion import Motion
from assur.groups._protocol import group_sizes
from assur.model import LoadTable, Mechanism, Toward
from assur.plan import FAR, Plan, compile_plan

__all__ = [
    "Compiled",
    "Many",
    "Template",
    "compile_many",
    "form",
    "numbers",
    "template",
]

Index = NDArray[np.intp]
"""Indices of variants (rows)."""


def form(mech: Mechanism) -> Hashable:
    """Return what variants compiled from one template must share.

    Everything but the numbers that :func:`numbers` reads: names, kinds, which link
    each joint joins, how each point is given (coordinates, a name, a Toward), which
    links have a mass, the drivers, gravity, friction and tabulated loads.
    """
    return (
        tuple(
            (
                link.name,
                None
                if link.axis is None
                else (_spec(link.axis[0]), _spec(link.axis[1])),
                bool(link.mass),
                link.inertia is None,
                _spec(link.center),
            )
            for link in mech.links
        ),
        tuple(
            (j.name, j.kind, j.links, _spec(j.at), j.axis, j.friction, j.radius)
            for j in mech.joints
        ),
        mech.drivers,
        mech.gravity,
        tuple((p.name, p.link, _spec(p.at)) for p in mech.points),
        tuple(
            (ld.link, _spec(ld.at), _value(ld.force), _value(ld.torque))
            for ld in mech.loads
        ),
    )


def _spec(spec: PointSpec | None) -> Hashable:
    """Return how a point is given, without its coordinates or distance."""
    if spec is None or isinstance(spec, str):
        return spec
    if isinstance(spec, Toward):
        return ("toward", spec.start, spec.toward)
    return ""


def _value(value: Any) -> Hashable:
    """Return a load's value as the form sees it: a table, or a number (or None)."""
    return value if value is None or isinstance(value, LoadTable) else ""


def numbers(mech: Mechanism, keys: dict[Any, int] | None = None) -> list[float]:
    """Return the numbers of ``mech`` that :func:`compile_many` reads, in one row.

    With ``keys``, record where each quantity starts in the row (for the template).
    Coordinates are resolved as :func:`assur.model.resolve_point` resolves them.
    """
    out: list[float] = []
    named = {j.name: j.at for j in mech.joints} | {p.name: p.at for p in mech.points}
    memo: dict[str, tuple[float, float]] = {}

    def at(spec: PointSpec) -> tuple[float, float]:
        if isinstance(spec, str):
            found = memo.get(spec)
            if found is None:
                found = memo[spec] = at(named[spec])
            return found
        if isinstance(spec, Toward):
            # resolve_point's arithmetic (numpy's hypot; the rest is elementwise
            # there, the same operations on floats here)
            (ax, ay), (bx, by) = at(spec.start), at(spec.toward)
            dx, dy = bx - ax, by - ay
            ratio = spec.distance / float(np.hypot(dx, dy))
            return ax + dx * ratio, ay + dy * ratio
        return float(spec[0]), float(spec[1])

    def put(key: Any, *values: float) -> None:
        if keys is not None:
            keys[key] = len(out)
        out.extend(values)

    for joint in mech.joints:
        put(("joint", joint.name), *at(joint.at))
    for point in mech.points:
        put(("point", point.name), *at(point.at))
    for link in mech.links:
        if link.axis is not None:
            a, b = at(link.axis[0]), at(link.axis[1])
            put(("angle", link.name), math.atan2(b[1] - a[1], b[0] - a[0]))
        if link.mass:
            put(("mass", link.name), float(link.mass), float(link.inertia or 0.0))
        if link.center is not None:
            put(("center", link.name), *at(link.center))
    for i, load in enumerate(mech.loads):
        if load.at is not None:
            put(("at", i), *at(load.at))
        if load.force is not None and not isinstance(load.force, LoadTable):
            put(("force", i), float(load.force[0]), float(load.force[1]))
        if load.torque is not None and not isinstance(load.torque, LoadTable):
            put(("torque", i), float(load.torque))
    return out


@dataclass(frozen=True, slots=True)
class Template:
    """A compiled variant whose plan's structure serves every variant of its form.

    ``columns`` says where each quantity starts in a row of :func:`numbers`;
    ``origin_pair`` names, for each body, the pair whose reference point is its
    origin (None for the frame).
    """

    plan: Plan
    loads: LoadPlan
    columns: dict[Any, int]
    origin_pair: tuple[str | None, ...]


def template(mech: Mechanism) -> Template | None:
    """Compile ``mech`` as a template; None when its plans cannot be stacked.

    Raises
    ------
    AssurError
        As :func:`assur.plan.compile_plan` and :func:`assur._loads.compile_loads`.
    """
    plan = compile_plan(mech)
    loads = compile_loads(plan)
    if signature(plan, loads) is None:
        return None
    if any(not isinstance(s, DyadSolver) for s in plan.solvers):
        return None
    columns: dict[Any, int] = {}
    numbers(mech, columns)
    by_name = {p.name: p for p in plan.topology.pairs}
    origin: list[str | None] = [None] * len(plan.bodies)
    for d in plan.drivers:
        origin[d.body] = d.pair.name
    for g in plan.groups:
        for link in g.links:
            origin[plan.index[link]] = next(
                p for p in g.external + g.internal if link in by_name[p].links
            )
    return Template(plan, loads, columns, tuple(origin))


@dataclass(frozen=True, slots=True)
class Many:
    """Variants compiled together: their stacked plan and loads.

    ``plan`` and ``loads`` hold each variant's numbers over ``repeats`` rows in turn;
    ``references`` (k,) is each variant's driver position in the reference pose (rad).
    ``again(count)``, when given, builds the plan with each variant over ``count``
    rows (cheaper than :func:`assur._stack.restack`, which walks the whole plan).
    """

    plan: Plan
    loads: LoadPlan
    references: Array
    again: Callable[[int], Plan] | None = None


@dataclass(frozen=True, slots=True)
class Compiled:
    """Variants compiled against a template: their numbers, ready to be batched.

    ``offsets`` are each pair's offsets on its two bodies, ``origins`` (k, B, 2) the
    bodies' origins, ``scale`` (k,) the mechanisms' sizes, ``branches`` each
    dyad's assembly branch (k,) and ``sizes`` each dyad's own size (k,), all in core
    coordinates, one value per variant.
    """

    model: Template
    rows: Array
    offsets: dict[str, tuple[Array, Array]]
    origins: Array
    scale: Array
    branches: list[Array]
    sizes: list[Array]

    def batch(self, chosen: Index, repeats: int) -> Many:
        """Return the stacked plan of the variants ``chosen`` (indices into rows)."""
        leaf = self._leaves(chosen, repeats)
        plan, references = self._plan(leaf, True)
        loads = _loads(self.model, self.rows, leaf, self.origins)

        def again(count: int) -> Plan:
            # for the change-point screen, which reads no reported point
            return self._plan(self._leaves(chosen, count), False)[0]

        return Many(plan, loads, references[chosen], again)

    def screen(self, chosen: Index) -> Many:
        """Return the variants ``chosen`` for the change-point screen alone.

        Only their references and ``again`` are theirs: the screen reads nothing
        else, and it screens the variants of many batches at once.
        """
        _, references = self._plan(self._leaves(chosen[:1], 1), False)

        def again(count: int) -> Plan:
            return self._plan(self._leaves(chosen, count), False)[0]

        return Many(self.model.plan, self.model.loads, references[chosen], again)

    def _leaves(self, chosen: Index, count: int) -> Leaf:
        """Return the leaf of the variants ``chosen``, each over ``count`` rows."""

        def leaf(values: Array) -> Any:
            picked = values[chosen]
            if np.all(picked == picked[0]):
                return float(picked[0])
            return repeat(picked, count)

        return leaf

    def _plan(self, leaf: Leaf, points: bool) -> tuple[Plan, Array]:
        """Return the stacked plan of ``leaf``'s variants and every reference."""
        return _plan(
            self.model,
            self.rows,
            leaf,
            self.offsets,
            self.origins,
            self.scale,
            self.branches,
            self.sizes,
            points,
        )


def compile_many(model: Template, rows: Array) -> tuple[Compiled, Mask]:
    """Compile the variants whose numbers are ``rows`` (k, N) against ``model``.

    Returns the compiled variants (those that pass every check may be batched) and
    a mask (k,) of those that do not, to be compiled on their own.
    """
    t = model.plan
    col = model.columns
    k = rows.shape[0]

    def two(key: Any) -> Array:
        c = col[key]
        return rows[:, c : c + 2]

    shift = np.asarray(t.shift)
    pairs = t.topology.pairs
    file_at = {p.name: two(("joint", p.name.removesuffix("~pin"))) for p in pairs}
    pivot = file_at[t.drivers[0].pair.name]
    doubtful = ~((pivot[:, 0] == shift[0]) & (pivot[:, 1] == shift[1]))
    core = {name: xy - shift for name, xy in file_at.items()}
    origins = np.zeros((k, len(t.bodies), 2))
    for b, name in enumerate(model.origin_pair):
        if name is not None:
            origins[:, b] = core[name]
    scale = np.maximum(1e-12, diameters(np.stack(list(core.values()), axis=1)))
    far = np.max(np.abs(np.stack(list(file_at.values()), axis=1)), axis=(1, 2))
    doubtful |= ~(far * MARGIN <= FAR * scale)
    doubtful |= _small_links(t, core, scale)
    # a variant whose size may be warned of (lengths in millimetres) is compiled on
    # its own, so that the study says so in its row as a separate call does
    # the diagonal of the points' box: never below their diameter, and O(k P) where
    # the diameter's every pair of a long chain's points costs seconds a block
    drawn = np.stack(
        [two(key) for key in col if key[0] in ("joint", "point", "center")], axis=1
    )
    doubtful |= ~(np.hypot(*np.ptp(drawn, axis=1).T) * MARGIN <= LARGE)
    offsets = {
        p.name: (
            core[p.name] - origins[:, t.index[p.links[0]]],
            core[p.name] - origins[:, t.index[p.links[1]]],
        )
        for p in pairs
    }
    branches: list[Array] = []
    sizes: list[Array] = []
    if t.solvers:
        motions = tuple(
            # each variant's origin: the kernels take arrays wherever numbers go
            Motion.fixed(origins[:, b, 0], origins[:, b, 1])  # type: ignore[arg-type]
            for b in range(len(t.bodies))
        )
        plain = _pair_plans(t, offsets, _as_is)
        for solver in t.solvers:
            assert isinstance(solver, DyadSolver)
            names = solver.group.internal + solver.group.external
            # each pair found as compile_plan finds it: the sizes agree to the bit
            at = [origins[:, plain[n].first] + offsets[n][0] for n in names]
            own = group_sizes(np.stack(at, axis=1), scale)
            dyad = _dyad(solver, plain, scale, own)
            branch, bad = _branch(dyad, motions, scale)
            branches.append(branch)
            sizes.append(own)
            doubtful |= bad
    return Compiled(model, rows, offsets, origins, scale, branches, sizes), doubtful
