"""Plans of many variants of one mechanism, stacked into one plan over their rows.

Variants of one topology differ only in numbers: their compiled plans are walked
together, and a number equal in every variant stays a number while one that differs
becomes an array with a value per row (each variant's value repeated over its
positions). The kernels then solve every variant's positions in one batch, as they
solve one mechanism's. :func:`signature` says which plans may be stacked together.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Hashable
from typing import Any

import numpy as np

from assur._loads import LoadPlan
from assur.model import LoadTable
from assur.plan import Plan

__all__ = [
    "Rows",
    "Unstackable",
    "repeat",
    "restack",
    "signature",
    "stack_loads",
    "stack_plans",
]

KEPT = frozenset({"mechanism", "topology", "origins", "angle0"})
"""Plan fields the kernels do not read: the first variant's stand for all."""

NAMES = frozenset({"groups", "bodies", "points", "point_body", "index", "group"})
"""Fields of a plan and its solvers that hold names and indices, never numbers:
:func:`restack` keeps them as they are."""


EQUAL_AS_A_WHOLE = (tuple, dict, str, int, bool, type(None))
"""Kinds of field compared whole first: when equal in every variant they are kept."""


class Unstackable(Exception):  # noqa: N818 (a signal, caught where plans are stacked)
    """Plans that differ in more than their numbers."""


class Rows(tuple):  # type: ignore[type-arg]
    """A vector whose components hold one value per row, hashed by identity.

    The kernels keep rotated offsets in dictionaries keyed by the offset (see
    :func:`assur.groups._motion.rotated`); an array is not hashable, so a stacked
    offset is its own key.
    """

    __slots__ = ()

    def __hash__(self) -> int:
        return id(self)

    def __eq__(self, other: object) -> bool:
        return self is other

    def __ne__(self, other: object) -> bool:
        return self is not other


def signature(plan: Plan, loads: LoadPlan) -> Hashable | None:
    """Return what variants stacked together must share; None if ``plan`` cannot be.

    The names and kinds of links, pairs, groups and drivers; the slide lines'
    directions (the kernels take them for constants); the numbers the kernels
    branch on (friction, the drivers' rates, where the core's origin lies, gravity);
    which links carry a mass. Groups solved by Newton's method, friction, tabulated
    loads and drivers other than one crank are analysed one variant at a time.
    """
    if plan.newton or any(p.friction > 0.0 for p in plan.pairs.values()):
        return None
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R":
        return None
    values = [v for *_, v, _ in loads.forces] + [v for _, v, _ in loads.torques]
    if any(isinstance(v, LoadTable) for v in values):
        return None
    return (
        plan.bodies,
        tuple(
            (p.name, p.kind, p.first, p.second, p.virtual, p.axis)
            for p in plan.pairs.values()
        ),
        tuple((s.label, s.bodies, type(s).__name__) for s in plan.solvers),
        tuple((d.pair.name, d.body, d.omega, d.epsilon) for d in plan.drivers),
        plan.points,
        plan.point_body,
        plan.shift,
        loads.gravity,
        tuple(np.flatnonzero(loads.mass).tolist()),
        tuple((b, e) for b, _, _, e in loads.forces),
        tuple((b, e) for b, _, e in loads.torques),
    )


def stack_plans(plans: list[Plan], repeats: int) -> Plan:
    """Return one plan for ``plans``, each variant over ``repeats`` rows in turn.

    Raises
    ------
    Unstackable
        When the plans differ in more than their numbers.
    """
    out = _stack(plans, repeats)
    assert isinstance(out, Plan)
    return out


def repeat(values: Any, count: int) -> Any:
    """Return ``values`` (k,) with each repeated ``count`` times in turn (k * count,).

    As ``numpy.repeat``, which is several times slower at this (it reads a count per
    element): a broadcast copy.
    """
    out = np.empty((len(values), count))
    out[:] = np.asarray(values, dtype=float)[:, None]
    return out.reshape(-1)


def restack(plan: Plan, repeats: int, again: int) -> Plan:
    """Return a stacked plan with each variant over ``again`` rows, not ``repeats``.

    An array that stands in several places of the plan (a pair's offset that is also
    a group's) is repeated once.
    """
    done: dict[int, Any] = {}

    def change(x: Any) -> Any:
        found = done.get(id(x))
        if found is None:
            found = done[id(x)] = repeat(x[::repeats], again)
        return found

    out = _map(plan, change)
    assert isinstance(out, Plan)
    return out


def _rebuild(
    value: Any, kept: Callable[[str], bool], each: Callable[[str], Any]
) -> Any:
    """Return a dataclass of ``value``'s class, field by field.

    A ``memo`` field is emptied, the fields ``kept`` says are taken as they are, and
    every other field is ``each(name)``.
    """
    fields: dict[str, Any] = {}
    for f in dataclasses.fields(value):
        if not f.init:
            continue
        if f.name == "memo":
            fields[f.name] = {}
        elif kept(f.name):
            fields[f.name] = getattr(value, f.name)
        else:
            fields[f.name] = each(f.name)
    return value.__class__(**fields)


def _map(value: Any, change: Any) -> Any:
    """Return ``value`` with every per-row array replaced by ``change(array)``."""
    kind = value.__class__
    if kind is np.ndarray:
        return change(value)
    if kind is Rows:
        return Rows(_map(x, change) for x in value)
    if kind is tuple:
        return tuple(_map(x, change) for x in value)
    if kind is dict:
        return {k: _map(v, change) for k, v in value.items()}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return _rebuild(
            value,
            lambda n: (kind is Plan and n in KEPT) or n in NAMES,
            lambda n: _map(getattr(value, n), change),
        )
    return value


def stack_loads(loads: list[LoadPlan], repeats: int) -> LoadPlan:
    """Return the loads of stacked variants, each over ``repeats`` rows in turn."""
    first = loads[0]
    bodies = [lp.bodies() for lp in loads]
    stacked = tuple(
        (
            b,
            _stack([x[i][1] for x in bodies], repeats),
            _stack([x[i][2] for x in bodies], repeats),
        )
        for i, (b, _, _) in enumerate(bodies[0])
    )
    return LoadPlan(
        first.mass,
        _stack([lp.center for lp in loads], repeats),
        first.inertia,
        _stack([lp.gravity for lp in loads], repeats),
        _stack([lp.forces for lp in loads], repeats),
        _stack([lp.torques for lp in loads], repeats),
        stacked,
    )


def _stack(values: list[Any], repeats: int) -> Any:
    """Stack one field of every variant (see the module's docstring)."""
    first = values[0]
    kind = first.__class__
    if kind in EQUAL_AS_A_WHOLE and all(v == first for v in values):
        return first  # names, indices, and parts with every number the same
    if kind is float:
        if all(v == first for v in values):
            return first
        if any(v.__class__ is not float for v in values):
            raise Unstackable
        return repeat(values, repeats)
    if kind is tuple or kind is Rows:
        try:
            parts = [_stack(list(p), repeats) for p in zip(*values, strict=True)]
        except ValueError as err:
            raise Unstackable from err
        if any(p.__class__ is np.ndarray for p in parts):
            return Rows(parts)
        return tuple(parts)
    if kind is dict:
        keys = list(first)
        if any(list(v) != keys for v in values):
            raise Unstackable
        return {k: _stack([v[k] for v in values], repeats) for k in keys}
    if dataclasses.is_dataclass(first) and not isinstance(first, type):
        if any(v.__class__ is not kind for v in values):
            raise Unstackable
        return _rebuild(
            first,
            lambda n: kind is Plan and n in KEPT,
            lambda n: _stack([getattr(v, n) for v in values], repeats),
        )
    if kind is np.ndarray:
        if all(np.array_equal(v, first) for v in values):
            return first
        raise Unstackable
    if all(v is first or v == first for v in values):
        return first
    raise Unstackable
