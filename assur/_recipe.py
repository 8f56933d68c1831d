"""What one pass over slices computes for a set of columns, worked out once.

The points, offsets, checks and residuals asked for, and the names of their columns,
depend on the plan and the columns alone: they are kept in ``plan.memo``, so a short
table's pass does no work per column beyond writing it.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from assur.columns import POINT_PARTS, Column, schema

__all__ = ["Recipe", "recipe"]

KEPT = 64
"""Recipes kept per plan: a program asking for ever other columns keeps no more."""

Parts = tuple[tuple[int, str, str], ...]
"""A point's levels and the names of their two columns."""


@dataclass(frozen=True, slots=True)
class Recipe:
    """The work of one pass over slices (see :func:`assur._chunks._chunked`).

    Attributes
    ----------
    deeper : bool
        Whether a column needs a level above the table's state (jerks).
    origins : tuple
        ``(body, level, x, y)``: a column pair of a point at its link's origin.
    rebuilt : tuple
        ``(point, parts)``: each point off its link's origin at a place of its own,
        with its levels and column names.
    aliases : tuple
        ``(name, same)``: a column of a point at the place of another, and that
        point's column of the same quantity.
    offsets : tuple of str
        The prismatic pairs whose offset is asked for.
    checks : tuple
        ``(name, driver)``: the virtual-power checks, every driver's (empty if none
        is asked for).
    residual : bool
        Whether the equilibrium residuals are asked for.
    jerks : tuple of int
        The points whose jerks are asked for beyond the state's levels.
    """

    deeper: bool
    origins: tuple[tuple[int, int, str, str], ...]
    rebuilt: tuple[tuple[int, Parts], ...]
    aliases: tuple[tuple[str, str], ...]
    offsets: tuple[str, ...]
    checks: tuple[tuple[str, int], ...]
    residual: bool
    jerks: tuple[int, ...]


def recipe(plan: Any, columns: list[Column], top: int, short: bool) -> Recipe:
    """Return the recipe of ``columns`` on a state solved up to level ``top``.

    ``short`` is whether the table fits in one slice (its state is then extended to
    jerks when a column needs them). Kept in ``plan.memo``.
    """
    kept = plan.memo.setdefault("recipes", {})
    key = (tuple([c.name for c in columns]), top, short)
    found = kept.get(key)
    if found is None:
        found = _recipe(plan, columns, top, short)
        if len(kept) < KEPT:
            kept[key] = found
    return found  # type: ignore[no-any-return]


def _recipe(plan: Any, columns: list[Column], top: int, short: bool) -> Recipe:
    deeper = short and any(c.level > top for c in columns)
    if deeper:
        top = 3  # one slice: the state extended to jerks serves every level
    levels = range(top + 1)
    wanted = {c.key[0] for c in columns if c.family == "point" and c.level <= top}
    at_origin, rebuilt = split(plan, wanted)
    rebuilt, same = distinct(plan, rebuilt)
    jerks = {c.key[0] for c in columns if c.family == "point" and c.level > top}
    families = {c.family for c in columns}
    checks: tuple[tuple[str, int], ...] = ()
    if "check" in families:
        checks = tuple(
            (c.name, c.key[0]) for c in schema(plan, True) if c.family == "check"
        )
    return Recipe(
        deeper,
        origins(plan, at_origin, levels),
        tuple((p, parts(plan, p, levels)) for p in rebuilt),
        aliases(plan, same, levels),
        tuple(sorted({c.owner for c in columns if c.family == "offset"})),
        checks,
        "residual" in families,
        tuple(sorted(jerks)),
    )


def split(plan: Any, points: Iterable[int]) -> tuple[list[int], list[int]]:
    """Split ``points`` into those at their link's origin and the others, in order."""
    at_origin: list[int] = []
    rebuilt: list[int] = []
    for p in sorted(points):
        (at_origin if plan.point_offset[p] == (0.0, 0.0) else rebuilt).append(p)
    return at_origin, rebuilt


def distinct(plan: Any, points: list[int]) -> tuple[list[int], dict[int, int]]:
    """Split ``points`` into those at distinct places and the others.

    Returns the first point at each place (a link and an offset on it) and, for
    each other point, the first at its place: a centre of mass at a joint, say, is
    computed once.
    """
    first: dict[tuple[int, tuple[float, float]], int] = {}
    same = {}
    for p in points:
        place = (plan.point_body[p], plan.point_offset[p])
        if place in first:
            same[p] = first[place]
        else:
            first[place] = p
    return list(first.values()), same


def parts(plan: Any, p: int, levels: Iterable[int]) -> Parts:
    """Return the ``levels`` of point ``p`` with the names of their columns."""
    name = plan.points[p]
    return tuple(
        (k, f"{name}.{x}", f"{name}.{y}") for k in levels for x, y in (POINT_PARTS[k],)
    )


def origins(
    plan: Any, points: list[int], levels: Iterable[int]
) -> tuple[tuple[int, int, str, str], ...]:
    """Return ``(body, level, x, y)`` for the ``levels`` of points at an origin."""
    return tuple(
        (plan.point_body[p], k, x, y)
        for k in levels
        for p in points
        for _, x, y in parts(plan, p, (k,))
    )


def aliases(
    plan: Any, same: dict[int, int], levels: Iterable[int]
) -> tuple[tuple[str, str], ...]:
    """Return ``(name, same)`` for the columns of the points of ``same``."""
    out = []
    for p, q in same.items():
        for (_, x, y), (_, qx, qy) in zip(
            parts(plan, p, levels), parts(plan, q, levels), strict=True
        ):
            out += [(x, qx), (y, qy)]
    return tuple(out)
