"""Summaries of many variants of one topology, solved together in one batch.

The variants' plan comes stacked (compiled at once by :mod:`assur._variants`, or one
plan per variant stacked by :mod:`assur._stack`) and their positions are solved at
once by the same kernels as :func:`assur.forces <assur.analysis.forces>`; the force
table of the batch is then reduced to one summary per variant
(:class:`assur.summary.Summary`). A variant that meets any trouble (a group that does
not close or comes near a dead centre, values that are not finite, a change point
near its path) is left to be analysed on its own, so that it fails or warns exactly
as a separate call does.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from assur import _kinematics as _kin
from assur import kinetostatics as _kst
from assur._branches import CANDIDATE, STEP, TURNS
from assur._drive import EXACT_DEGREES, driver_rates, to_si
from assur._loads import compile_loads
from assur._quiet import quiet
from assur._stack import restack, stack_loads, stack_plans
from assur._variants import Many
from assur._vec import Array, Mask, is_array, leaves
from assur.columns import selection
from assur.plan import Plan
from assur.table import Table

__all__ = ["CHUNK", "near_change_points", "stacked", "summaries"]

CHUNK = 8192
"""Rows solved at once in a batch of variants, or a part of a change-point grid: a
row's temporaries stay below the allocator's mmap threshold (64 kB each)."""


def stacked(plans: list[Plan], repeats: int) -> Many:
    """Return the plans of variants of one topology stacked, each over ``repeats`` rows.

    Raises
    ------
    Unstackable
        When the plans differ in more than their numbers.
    """
    return Many(
        stack_plans(plans, repeats),
        stack_loads([compile_loads(p) for p in plans], repeats),
        np.array([p.drivers[0].reference for p in plans]),
    )


def summaries(
    batch: Many, first: Plan, given: Array, near: Mask | None = None
) -> list[dict[str, float] | None]:
    """Return each variant's summary over driver positions ``given`` (n, 1), deg.

    ``batch`` holds variants of one topology, driven by one crank, each over the
    ``n`` rows of ``given`` in turn; ``first`` is one of their plans (the one whose
    structure they share). ``near`` marks the variants that may meet a change point
    (:func:`near_change_points`; found here when not given). None for a variant to
    be analysed on its own (see the module's docstring).
    """
    k, m = batch.references.shape[0], given.shape[0]
    plan, loads = batch.plan, batch.loads
    drive = _drive(first, batch.references, given)
    rates = driver_rates(first, None, None, k * m)
    with quiet():
        bodies, found = _kin.solve(plan, drive, rates[0], rates[1], top=2)
        state = _kin.state_of(plan, bodies, drive, rates, 2)
        forces, result = _kst.solve(plan, loads, bodies, state)
    bad = np.zeros(k * m, dtype=bool)
    for trouble in found:
        bad |= trouble.mask
    for _, mask in result.locked:
        bad |= mask
    for leaf in leaves((forces.reactions, forces.balancing, forces.shaking)):
        if is_array(leaf):
            bad |= ~np.isfinite(leaf)
    if near is None:
        near = _near(batch, drive)
    alone = bad.reshape(k, m).any(axis=1) | near
    chosen = selection(first, True, None)
    table = Table(
        plan,
        chosen.columns,
        np.tile(given, (k, 1)),
        state,
        forces,
        _index=chosen.index,
        _families=chosen.families,
    )
    # the summary's modules load with the first study, not with ``import assur``
    from assur.summary import Summary

    summary = Summary(variants=k)
    with quiet():
        summary.add(table)
        values = summary.results()
    names = list(values)
    each = np.column_stack([values[name] for name in names]).tolist()
    return [
        None if alone[i] else dict(zip(names, each[i], strict=True)) for i in range(k)
    ]


def _drive(first: Plan, references: Array, given: Array) -> Array:
    """Return the driver positions of every variant in turn, rad (see ``to_si``).

    Angles below :data:`~assur._drive.EXACT_DEGREES` are converted as they are, the
    same for every variant; larger ones are reduced about each variant's reference.
    """
    if not first.newton and np.all(np.abs(given) < EXACT_DEGREES):
        return np.tile(to_si(first, given), (references.shape[0], 1))
    out = []
    for reference in references.tolist():
        driver = dataclasses.replace(first.drivers[0], reference=reference)
        # a plan of its own: what the first plan keeps belongs to its own reference
        plan = dataclasses.replace(first, drivers=(driver,), memo={})
        out.append(to_si(plan, given))
    return np.concatenate(out)


def near_change_points(batch: Many, first: Plan, given: Array) -> Mask:
    """Mark the variants of ``batch`` whose path may meet a change point.

    The variants are those of any number of batches: only their references and
    ``batch.again`` are read (see :func:`_near`). ``given`` are the driver positions
    (n, 1), deg, and ``first`` one of the variants' plans.
    """
    return _near(batch, _drive(first, batch.references, given))


def _near(batch: Many, drive: Array) -> Mask:
    """Mark the variants whose path from the reference pose may meet a change point.

    :func:`assur._branches.change_points` scans a grid for minima of each dyad's
    discriminant below :data:`~assur._branches.CANDIDATE`; a variant whose
    discriminants stay above it on that grid all along its path (and a step beyond)
    has none there, and its sweep keeps the reference pose's branches. A PRP or RPP
    dyad has no discriminant: a variant whose dyad's determinant changes sign along
    its path (a dead centre it cannot pass, its positions beyond it out of reach,
    see :mod:`assur._reach`) is marked too, and so are variants driven beyond the
    scanned window. ``batch`` holds the variants,
    each over its ``drive`` positions.
    """
    reference = batch.references
    k = reference.shape[0]
    m = drive.shape[0] // k
    x = drive[:, 0].reshape(k, m) - reference[:, None]
    low = np.minimum(x.min(axis=1, initial=0.0), 0.0)
    high = np.maximum(x.max(axis=1, initial=0.0), 0.0)
    half = TURNS * 2.0 * math.pi
    outside = (low < -half) | (high > half)
    steps = np.arange(
        math.floor(low.min() / STEP) - 1, math.ceil(high.max() / STEP) + 2
    )
    # the grid in parts of equal length, each at most CHUNK rows (its temporaries
    # stay below the allocator's mmap threshold); one plan serves every part
    parts = max(1, math.ceil(k * steps.size / CHUNK))
    length = math.ceil(steps.size / parts)
    steps = np.arange(steps[0], steps[0] + parts * length)
    if batch.again is not None:
        plan = batch.again(length)
    else:
        plan = restack(batch.plan, m, length)
    found = [
        _below(plan, reference, steps[p * length : (p + 1) * length])
        for p in range(parts)
    ]
    near = np.concatenate([f[0] for f in found], axis=1)
    # a dyad's determinant of the other sign than at the reference pose: a dead
    # centre lies between (a PRP dyad's pin at infinity has no discriminant)
    zero = int(np.flatnonzero(steps == 0)[0])
    for g in range(len(found[0][1])):
        sign = np.concatenate([f[1][g] for f in found], axis=1)
        near |= sign * sign[:, zero : zero + 1] < 0.0
    # only the grid's points along each variant's own path count
    along = (steps[None, :] >= np.floor(low / STEP)[:, None] - 1) & (
        steps[None, :] <= np.ceil(high / STEP)[:, None] + 1
    )
    return outside | (near & along).any(axis=1)


def _below(plan: Plan, reference: Array, steps: Array) -> tuple[Mask, list[Array]]:
    """Mark the grid's points (k, steps) where a discriminant is below CANDIDATE.

    Also return the sign of the Jacobian's determinant there (k, steps) of each
    closed-form dyad that has no discriminant, one array per dyad.
    """
    k = reference.shape[0]
    grid = (reference[:, None] + steps[None, :] * STEP).reshape(-1, 1)
    n = grid.shape[0]
    bodies = _kin.drivers(plan, grid, (0.0,), (0.0,))
    near = np.zeros(n, dtype=bool)
    signs = []
    with quiet():
        last = len(plan.solvers) - 1
        for i, solver in enumerate(plan.solvers):
            values = solver.discriminant(bodies)
            if values is not None:
                near |= ~(np.broadcast_to(values, (n,)) >= CANDIDATE)
            # the determinant of a closed-form dyad without a discriminant (PRP,
            # RPP): one with a discriminant meets its dead centres where that is 0
            signed = getattr(solver, "signed_conditioning", None)
            if solver.newton or values is not None:
                signed = None
            # a group is assembled for the discriminants of those after it, and a
            # dyad for its own determinant
            if signed is not None or i < last:
                solver.assemble(bodies, n)
            if signed is not None:
                det = np.broadcast_to(signed(bodies), (n,))
                signs.append(np.sign(det).reshape(k, -1))
    return near.reshape(k, -1), signs
