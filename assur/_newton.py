"""Newton's method for the sizes of a group's reactions with friction.

Solves the small system ``s = |R(s)|`` of :mod:`assur._friction`, one unknown per pair
with friction, at every position at once; where it fails, raises the friction from
zero in steps and follows the solution that grows from the frictionless one.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any

import numpy as np

from assur._quiet import quiet
from assur._vec import norm

TOLERANCE = 1e-13
"""Newton's step on the sizes, relative to the group's largest reaction, at which it
stops."""
SINGULAR = 1e-12
"""Determinant of the Newton step's matrix below which the step is not taken."""
MAX_ITERATIONS = 30
"""Most Newton steps; a position still moving is locked, or too near it to tell."""

APART = 1e-12
"""Relative difference of two solutions of the sizes below which they are one."""
RAISES = 16
"""Steps in which the friction is raised from zero where the first solve found a
jammed solution or none."""
QUICK = 12
"""Newton steps after which a solve that has a safer one behind it gives up: Newton
settles in a handful where it converges, and where the solution does not exist (a
group that locks) it wanders until the limit."""


def _system(
    start: list[Any],
    response: list[list[Any]],
    here: Any,
    weight: float,
    signed: tuple[bool, ...] = (),
) -> tuple[list[list[Any]], list[Any]]:
    """Return the Jacobian (rows of columns of arrays) and residual of ``s = |R(s)|``.

    Every array is by components (see :func:`_by_components`): ``start[j]`` and
    ``response[k][j]`` (c, n), ``here`` the sizes (m, n). ``weight`` scales every
    pair's friction (1: as given). A pair ``j`` marked in ``signed`` takes its one
    component as it is, not its size (see :func:`_signs`).
    """
    m = len(start)
    # the Jacobian as rows of columns of 1-D arrays: contiguous, unlike the
    # strided entries of an (n, m, m) array, and so several times faster
    jac: list[list[Any]] = []
    left: list[Any] = []
    for j in range(m):
        value = start[j].copy()
        for k in range(m):
            value += (weight * here[k]) * response[k][j]
        if signed and signed[j]:
            size = value[0]
            row = [-weight * response[k][j][0] for k in range(m)]
        else:
            size = _norm(value)
            with quiet():
                along = np.where(size > 0.0, value / size, 0.0)
            row = [-weight * _dot(along, response[k][j]) for k in range(m)]
        left.append(here[j] - size)
        row[j] += 1.0
        jac.append(row)
    return jac, left


def _sizes(
    start: list[Any],
    response: list[list[Any]],
    sizes: Any,
    scale: Any,
    weight: float = 1.0,
    signed: tuple[bool, ...] = (),
    most: int = MAX_ITERATIONS,
    tolerance: float = TOLERANCE,
) -> tuple[Any, Any, Any, int]:
    """Solve ``s = |R(s)|`` by Newton's method from ``sizes`` (changed in place).

    At most ``most`` steps: a position still moving then has not settled.

    Returns the sizes, where they settled, whether they grow from no friction (the
    determinant of the last step's Jacobian, at the solution to rounding, see
    :func:`_growing`) and the number of steps. A step below ``tolerance`` (a
    share, :data:`TOLERANCE` by default) of the larger of ``scale`` and the sizes
    found settles.
    """
    n = sizes.shape[0]
    settled = np.zeros(n, dtype=bool)
    determinant = np.zeros(n)
    count = 0
    # Newton converges quadratically: after a few steps only a handful of positions
    # are still moving, and only those are stepped again
    rows = np.arange(n)
    # the start, responses and sizes of the positions still moving (all of them at
    # first), by components
    now_start = [_by_components(a) for a in start]
    now_response = [[_by_components(a) for a in r] for r in response]
    here = _by_components(sizes)
    while count < most and rows.size:
        count += 1
        jac, left = _system(now_start, now_response, here, weight, signed)
        delta, good, det = _newton_step(jac, left)
        here += delta
        sizes[rows] = here.T
        moved = functools.reduce(np.maximum, np.abs(delta))
        # a finite position whose step could not be taken has not settled
        moved[~good & np.isfinite(sum(left))] = np.inf
        # the tolerance is relative to the frictionless reactions, or to the sizes
        # found where friction makes them far larger
        done = moved <= tolerance * scale[rows]
        if not done.all():
            big = functools.reduce(np.maximum, np.abs(here))
            done |= moved <= tolerance * big
        if done.any():
            settled[rows[done]] = True
            determinant[rows[done]] = det[done]
            stay = ~done
            rows = rows[stay]
            now_start = [a[:, stay] for a in now_start]
            now_response = [[a[:, stay] for a in r] for r in now_response]
            here = here[:, stay]
    return sizes, settled, _growing(determinant), count


def _raised(
    start: list[Any], response: list[list[Any]], first: Any, scale: Any
) -> tuple[Any, Any, int]:
    """Follow the solution from no friction to the friction given, in steps.

    Returns the sizes, where the solution held all the way (a fold on the way, the
    determinant through zero, is where the group locks) and the Newton steps. The
    positions it leaves in :data:`RAISES` steps are followed again in steps eight
    times shorter, from the last friction at which they held: a step too long may
    land on the jammed solution, or cycle where a normal force turns over.
    """
    n = first.shape[0]
    sizes, held, count = first.copy(), np.zeros(n, dtype=bool), 0
    reached = np.zeros(n, dtype=int)
    left = np.arange(n)
    # the first pass gives up on a step quickly: the second takes it again
    for raises, most in ((RAISES, QUICK), (8 * RAISES, MAX_ITERATIONS)):
        part = [[a[left] for a in r] for r in response]
        found, kept, last, more = _followed(
            [a[left] for a in start], part, sizes[left], scale[left], raises,
            reached[left], most,
        )  # fmt: skip
        sizes[left], held[left] = found, kept
        count += more
        left = left[~kept]
        reached[left] = 8 * last[~kept]
        if not left.size:
            break
    return sizes, held, count


def _followed(
    start: list[Any],
    response: list[list[Any]],
    sizes: Any,
    scale: Any,
    raises: int,
    begin: Any,
    most: int,
) -> tuple[Any, Any, Any, int]:
    """Raise the friction in ``raises`` steps (see :func:`_raised`).

    Each position starts at step ``begin`` (0: no friction), from its ``sizes``
    there, with at most ``most`` Newton steps each. A position the solution leaves
    is dropped from the later steps: it locks, or is followed again in shorter
    steps. Returns the sizes at the last step each position held, whether it held
    to the end, that step, and the Newton steps taken.
    """
    sizes = sizes.copy()
    held = np.ones(sizes.shape[0], dtype=bool)
    last = begin.copy()
    rows = np.zeros(0, dtype=int)
    count = 0
    for step in range(1, raises + 1):
        # the positions that held up to the step before join here
        rows = np.concatenate((rows, np.flatnonzero(begin == step - 1)))
        if not rows.size:
            continue
        found, settled, growing, steps = _sizes(
            [a[rows] for a in start],
            [[a[rows] for a in r] for r in response],
            sizes[rows],
            scale[rows],
            step / raises,
            most=most,
        )
        count += steps
        on = settled & growing
        sizes[rows[on]] = found[on]
        last[rows[on]] = step
        held[rows[~on]] = False
        rows = rows[on]
    return sizes, held, last, count


def _signs(
    start: Sequence[Any],
    response: Sequence[Sequence[Any]],
    held: Sequence[Any] | None = None,
) -> tuple[tuple[bool, ...], list[Any], list[list[Any]]]:
    """Return which pairs' normal forces are held on their frictionless side.

    A sliding pair's reaction is its normal force ``N``, one component: with ``N``
    turned to the sign it has without friction, its size ``|N|`` is ``N`` itself
    while the motion keeps it there. ``held``, if given, holds each pair's normal
    force of the side to keep instead (None for a revolute pair). Returns the
    pairs so marked and the start and responses so turned.
    """
    signed = tuple(a.shape[-1] == 1 for a in start)
    held = start if held is None else held
    sides = [np.where(a[:, :1] < 0.0, -1.0, 1.0) if one else None
             for a, one in zip(held, signed, strict=True)]  # fmt: skip
    turned_start = [
        a if side is None else side * a for a, side in zip(start, sides, strict=True)
    ]
    turned = [
        [a if side is None else side * a for a, side in zip(row, sides, strict=True)]
        for row in response
    ]
    return signed, turned_start, turned


def _growing(det: Any) -> Any:
    """Whether solutions with these Jacobian determinants grow from no friction.

    Such a solution keeps the frictionless determinant's sign (+1). Under a huge
    friction coefficient (a slider whose normal force friction has all but
    cancelled, say) the jammed solution beside it differs from it by about
    ``2 / |det|`` of the sizes: below :data:`APART` the two are one to rounding.
    """
    return (det > 0.0) | (det < -2.0 / APART)


def _newton_step(jac: list[list[Any]], left: list[Any]) -> tuple[Any, Any, Any]:
    """Return Newton's step ``-jac^-1 left``, where it was taken, its determinant.

    ``jac[j][k]`` and ``left[j]`` are arrays over the positions; the step is (m, n), a
    row per unknown. Up to three pairs with friction (every dyad) are solved by Cramer's
    rule, several times faster than a batch of LAPACK calls on small matrices; more, by
    ``numpy.linalg.solve``. A step is not taken (zero) where the matrix or the residual
    is not finite, or the matrix is nearly singular: a reaction through zero, a group on
    the edge of locking.
    """
    m = len(left)
    with quiet():
        if m <= 3:
            adj, det = _adjugate(jac)
        else:
            square = np.stack([np.stack(r, axis=-1) for r in jac], axis=-2)
            det = np.linalg.det(np.where(np.isfinite(square), square, 0.0))
        # a matrix that is not finite has a determinant that is not finite
        good = np.isfinite(det) & np.isfinite(sum(left)) & (np.abs(det) > SINGULAR)
        safe = np.where(good, det, 1.0)
        if m <= 3:
            columns = [
                -sum(adj[i][j] * left[j] for j in range(m)) / safe for i in range(m)
            ]
            delta = np.stack(columns)
        else:
            square[~good] = np.eye(m)
            rhs = -np.stack(left, axis=-1)[..., None]
            delta = np.linalg.solve(square, np.where(np.isfinite(rhs), rhs, 0.0))[
                ..., 0
            ].T
    delta[:, ~good] = 0.0
    return delta, good, det


def _adjugate(a: list[list[Any]]) -> tuple[list[list[Any]], Any]:
    """Return the adjugate and the determinant of a batch of 1 x 1 to 3 x 3 matrices."""
    m = len(a)
    if m == 1:
        return [[1.0]], a[0][0]
    if m == 2:
        adj = [[a[1][1], -a[0][1]], [-a[1][0], a[0][0]]]
        return adj, a[0][0] * a[1][1] - a[0][1] * a[1][0]
    adj = [[0.0] * 3 for _ in range(3)]
    for i in range(3):
        for j in range(3):
            r = [x for x in range(3) if x != j]
            c = [x for x in range(3) if x != i]
            minor = a[r[0]][c[0]] * a[r[1]][c[1]] - a[r[0]][c[1]] * a[r[1]][c[0]]
            adj[i][j] = minor if (i + j) % 2 == 0 else -minor
    det = a[0][0] * adj[0][0] + a[0][1] * adj[1][0] + a[0][2] * adj[2][0]
    return adj, det


def across(ufunc: np.ufunc, a: Any) -> Any:
    """Return ``ufunc`` reduced across the few columns of an (n, m) array.

    The same as ``ufunc.reduce(a, axis=-1)`` (a maximum, an and, an or: exact), but
    ``m - 1`` calls over whole columns: numpy reduces a short last axis position by
    position, 80 times slower for an (n, 2) array's maximum.

    Examples
    --------
    >>> a = np.array([[1.0, 3.0, 2.0], [np.nan, 0.0, 5.0]])
    >>> across(np.maximum, a), np.max(a, axis=-1)
    (array([ 3., nan]), array([ 3., nan]))
    """
    return functools.reduce(ufunc, [a[:, j] for j in range(a.shape[-1])])


def _norm(a: Any) -> Any:
    """Return the lengths of a (2, n) or (1, n) array's columns: a reaction's sizes.

    A (n, c) array is read through its transpose, ``_norm(a.T)``.
    """
    return norm(a[0], a[1]) if len(a) == 2 else np.abs(a[0])


def _dot(a: Any, b: Any) -> Any:
    """Return the dot products of two (2, n) or (1, n) arrays' columns."""
    out = a[0] * b[0]
    return out + a[1] * b[1] if len(a) == 2 else out


def _by_components(a: Any) -> Any:
    """Return an (n, c) array as a contiguous (c, n) one: a row per component.

    The solve reads each component of a reaction whole: a column of an (n, c)
    array is strided, and numpy's operations on it markedly slower.
    """
    return np.ascontiguousarray(a.T)
