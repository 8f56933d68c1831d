"""Load tables: values given at positions, read in between by straight lines.

A table over a crank is periodic: an angle is read modulo 360 within the turn that
starts at the table's first position (docs/file_format.rst: a load table over a
revolute driver is periodic).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._vec import Array

__all__ = [
    "TURN",
    "Reading",
    "disagreement",
    "in_turn",
    "interpolate",
    "periodic",
    "reading",
    "steps",
]

TURN = 360.0
"""A crank's turn, deg."""
SAME_TURN = 1e-12
"""Relative slack by which a table's last position may pass a whole turn from its
first and still close that turn."""
AGREE = 1e-9
"""Difference, relative to a table's largest value, below which two values a turn
apart agree. Relative alone: a watch's torque table of 1e-12 N m steps as a
press's of 1e3 N m does (a floor of 1 N m read its steps as none)."""


def _slack(ys: Any) -> float:
    """Return the difference below which two values of a table agree (see AGREE)."""
    return AGREE * max(float(np.max(np.abs(y))) for y in ys)


def interpolate(at: Array, xs: Array, ys: Array) -> Array:
    """Interpolate ``ys`` over ``xs`` (increasing) linearly at ``at``; ends held.

    As ``np.interp``, but through the fraction of each step, which stays within
    [0, 1]: ``np.interp`` divides the step in the values by the step in the
    positions first, which overflows where a table jumps (1e15 N within 1e-300 deg
    gave inf). Each end of a step is given exactly. A position given twice is a
    jump: there and after it the second value holds, before it the first.
    """
    j, w = _segment(xs, np.asarray(at, dtype=float))
    return (1.0 - w) * ys[j] + w * ys[j + 1]  # type: ignore[no-any-return]


def _segment(xs: Array, at: Array) -> tuple[Any, Array]:
    """Return the entry each of ``at`` is read after, and how far toward the next.

    The last of equal positions (a jump's second value holds from its position
    on), ends held; the fraction stays within [0, 1] (see :func:`interpolate`).
    """
    j = np.clip(np.searchsorted(xs, at, side="right") - 1, 0, len(xs) - 2)
    width = xs[j + 1] - xs[j]
    with np.errstate(invalid="ignore", divide="ignore"):
        w = np.clip((at - xs[j]) / width, 0.0, 1.0)
    # a jump at either end of the table: no width to divide, the side of it tells
    return j, np.where(width == 0.0, (at >= xs[j]).astype(float), w)


def _grids(xs: Array, values: Any, turning: bool) -> list[tuple[Array, Array]]:
    """Return each component's grid as a reading uses it: one closed turn, or all."""
    ys = [np.asarray(v, dtype=float) for v in values]
    if not turning:
        return [(xs, y) for y in ys]
    first = _first_turn(xs)
    return [_closed(xs[first], y[first]) for y in ys]


def periodic(xs: Array, values: Any, at: Array) -> list[Array]:
    """Interpolate a table over a crank's turn at angles ``at`` (deg).

    An angle is read within the turn that starts at the table's first position.
    After its last position the table runs back to its first value, a turn on,
    unless it reaches there itself: a table from 0 to 360 whose ends differ (a load
    that grows over the turn, say) jumps back at 0. The entries of a table that
    goes on past a turn repeat those of its first turn (:func:`disagreement`
    finds any that do not); the first turn's are read.
    """
    first = _first_turn(xs)
    turn = _in_turn(xs[first], np.asarray(at, dtype=float))
    return [
        interpolate(turn, *_closed(xs[first], np.asarray(v, dtype=float)[first]))
        for v in values
    ]


@dataclass(frozen=True, slots=True)
class Reading:
    """Where a table is read at one position: between which two of its entries.

    ``at`` is the position as the table reads it (within its turn, deg, for a
    table over a crank); ``low`` and ``high`` the positions of the entries either
    side, ``below`` and ``above`` their values (one per component), ``fraction``
    how far ``at`` lies from ``low`` toward ``high`` (0 or 1 on an entry).
    """

    at: float
    low: float
    high: float
    below: tuple[float, ...]
    above: tuple[float, ...]
    fraction: float
    held: tuple[float, float, float | None] | None = None
    """Where the table holds the value read here, on a flat stretch: from, to and
    the turn's end it runs through (over a crank, a stretch such as 350 to 190 deg
    through 360), or None for that end; None off a flat stretch."""


def reading(xs: Array, values: Any, at: float, turning: bool) -> Reading:
    """Return where a table is read at position ``at``, as :func:`interpolate` reads.

    ``turning``: read over a crank's turn (deg), as :func:`periodic` reads it.
    """
    grids = _grids(xs, values, turning)
    t = float(in_turn(xs, np.array([at]))[0]) if turning else at
    grid = grids[0][0]
    # the entries interpolate uses
    found, fraction = _segment(grid, np.array([t]))
    j, w = int(found[0]), float(fraction[0])
    below = tuple(float(g[1][j]) for g in grids)
    above = tuple(float(g[1][j + 1]) for g in grids)
    held = _held(grids, j, turning) if below == above else None
    return Reading(t, float(grid[j]), float(grid[j + 1]), below, above, w, held)


def _held(
    grids: list[tuple[Array, Array]], j: int, turning: bool
) -> tuple[float, float, float | None]:
    """Return the flat stretch of closed ``grids`` around segment ``j`` (see Reading).

    Over a crank the stretch runs on past the turn's end into its start, and back
    past its start into its end: a cut on from 350 deg and off at 190 deg holds
    from 350 through 360 to 190, read at 355 as at 100.
    """
    grid, count = grids[0][0], len(grids[0][0]) - 1
    value = [g[1][j] for g in grids]

    def flat(k: int) -> bool:
        return all(
            g[1][k] == v == g[1][k + 1] for g, v in zip(grids, value, strict=True)
        )

    if all(flat(k) for k in range(count)):
        return float(grid[0]), float(grid[-1]), None
    ends = []
    for step in (-1, 1):
        # round the turn, a stretch ends where the table is not flat, as it is
        # somewhere: not everywhere
        k = j
        while turning or 0 <= k + step < count:
            if not flat((k + step) % count):
                break
            k = (k + step) % count
        ends.append(k)
    low, high = float(grid[ends[0]]), float(grid[ends[1] + 1])
    through = float(grid[-1]) if turning and ends[0] > ends[1] else None
    return low, high, through


def step_before(xs: Array, values: Any, at: float, turning: bool) -> list[float] | None:
    """Return a table's values just before position ``at`` where it steps there.

    None where it does not: its values on either side of ``at`` agree. At a step
    the values read are those after it (:func:`interpolate`, :func:`periodic`).
    ``turning``: read over a crank's turn (deg), as :func:`periodic` reads it.
    """
    ys = [np.asarray(v, dtype=float) for v in values]
    t = np.array([at], dtype=float)
    if turning:
        t = in_turn(xs, t)
    grids = _grids(xs, values, turning)
    before = [_before(float(t[0]), *grid, turning=turning) for grid in grids]
    after = [float(interpolate(t, *grid)[0]) for grid in grids]
    slack = _slack(ys)
    if all(abs(b - a) <= slack for b, a in zip(before, after, strict=True)):
        return None
    return before


def steps(xs: Array, values: Any, turning: bool) -> Array:
    """Return the positions where a table steps: given twice, its values differing.

    ``turning``: a table over a crank's turn (deg), read as :func:`periodic` reads
    it: a step at the turn's end (a table from 0 to 360 whose ends differ) is at
    its start, where a sweep's angle is read. The positions are those a reading
    lands on exactly (:func:`_onto` puts an angle within round-off on them).
    """
    ys = [np.asarray(v, dtype=float) for v in values]
    slack = _slack(ys)
    grids = _grids(xs, values, turning)
    grid = grids[0][0]
    twice = np.flatnonzero(grid[:-1] == grid[1:])
    jumps = [
        float(grid[k])
        for k in twice
        if any(abs(float(g[1][k + 1] - g[1][k])) > slack for g in grids)
    ]
    if turning:
        start = float(grid[0])
        # the turn's end is its start again: a jump there is read at the start
        if grid[-1] >= start + TURN and any(
            abs(float(g[1][-1] - g[1][0])) > slack for g in grids
        ):
            jumps.append(start)
        jumps = [start if x >= start + TURN else x for x in jumps]
    return np.unique(np.array(jumps, dtype=float))


def in_turn(xs: Array, at: Array) -> Array:
    """Return angles ``at`` (deg) as a table over a crank's turn reads them."""
    return _in_turn(xs[_first_turn(xs)], np.asarray(at, dtype=float))


def _in_turn(xs: Array, at: Array) -> Array:
    """Return angles ``at`` (deg) within the turn of a table's first turn ``xs``."""
    turn = _onto(xs, at, xs[0] + np.remainder(at - xs[0], TURN))
    # a remainder rounded up to a whole turn is the turn's start
    turn[turn >= xs[0] + TURN] = xs[0]
    return turn


def _onto(xs: Array, at: Array, turn: Array) -> Array:
    """Return the angles ``turn`` (``at`` within the table's turn) on the table's grid.

    An angle within round-off of a table's position (or of the turn's end) is put
    on it. A position given as a step's, 120 deg, comes here through radians and
    back, np.degrees(np.radians(120.0)) = 119.99999999999999: read as it came, the
    value before the step, where the step's second value holds at the position.
    Degrees to radians and back are each rounded once, within an ulp of ``at``.
    """
    grid = np.append(xs, xs[0] + TURN)
    j = np.clip(np.searchsorted(grid, turn), 1, len(grid) - 1)
    below, above = grid[j - 1], grid[j]
    near = np.where(turn - below <= above - turn, below, above)
    tiny = 4.0 * np.spacing(np.maximum(np.abs(at), np.abs(near)))
    return np.where(np.abs(turn - near) <= tiny, near, turn)  # type: ignore[no-any-return]


def disagreement(xs: Array, ys: Array) -> tuple[float, float, str] | None:
    """Return the first entry past the first turn whose value is not the first turn's.

    As ``(position, the position whole turns away, which value)``, deg, the last
    "" or, for a step, "before the step " or "after the step "; None when every
    entry past the first turn repeats it (or there are none). A step (a position
    given twice) is compared side by side: the value before it with the value
    before the first turn's, the value after with the value after. A step where
    the first turn ends, a turn from its start, must agree so with the start.
    """
    first = _first_turn(xs)
    head, values = _closed(xs[first], ys[first])
    slack = _slack([ys])
    start, end = head[0], head[0] + TURN
    if head[-1] >= end and len(head) > 2:
        # the turn's end is its start again: the value arriving there, and the
        # value after a step there, are the start's, before and after its step
        if head[0] == head[1] and abs(_before(end, head, values) - values[0]) > slack:
            return float(start), float(head[-1]), "before the step "
        stepped = head[-2] == head[-1]
        after = interpolate(np.array([start]), head, values)[0]
        if stepped and abs(values[-1] - after) > slack:
            return float(head[-1]), float(start), "after the step "
    if first.all():
        return None
    later = np.flatnonzero(np.logical_not(first))
    back = start + np.remainder(xs[later] - start, TURN)
    expected = interpolate(back, head, values)
    # the first of two equal positions is a step's value before it
    steps = later[:-1][xs[later[:-1]] == xs[later[:-1] + 1]]
    for step in np.flatnonzero(np.isin(later, steps)):
        expected[step] = _before(float(back[step]), head, values)
    bad = np.flatnonzero(np.abs(expected - ys[later]) > slack)
    if not bad.size:
        return None
    k = int(bad[0])
    which = "before the step " if later[k] in steps else ""
    return float(xs[later[k]]), float(back[k]), which


def _before(at: float, xs: Array, ys: Array, turning: bool = True) -> float:
    """Return a closed turn's value just before position ``at`` (a step's first).

    Just before the turn's start is just before its end, a turn on. Not
    ``turning`` (a table over a slide), the table is held before its start.
    """
    if at <= xs[0]:
        if not turning:
            return float(ys[0])
        at += TURN
    j = int(np.clip(np.searchsorted(xs, at, side="left") - 1, 0, len(xs) - 2))
    width = xs[j + 1] - xs[j]
    w = 1.0 if width == 0.0 else min(1.0, max(0.0, (at - xs[j]) / width))
    return float((1.0 - w) * ys[j] + w * ys[j + 1])


def _first_turn(xs: Array) -> Array:
    """Return the mask of a table's positions within its first turn (the end in)."""
    return xs <= xs[0] + TURN * (1.0 + SAME_TURN)  # type: ignore[no-any-return]


def _closed(xs: Array, ys: Array) -> tuple[Array, Array]:
    """Return the grid of one turn: back to the first value a turn on, if open."""
    if xs[-1] >= xs[0] + TURN:
        return xs, ys
    return np.append(xs, xs[0] + TURN), np.append(ys, ys[0])
