"""Summaries of many variants of one topology, solved together in one batch.

The variants' plans are stacked (:mod:`assur._stack`) and their positions solved at
once by the same kernels as :func:`assur.forces`; the force table of the batch is then
reduced to one summary per variant (:class:`assur.summary.Summary`). A variant that
meets any trouble (a group that does not close or comes near a dead centre, values
that are not finite, a change point near its path) is left to be analysed on its own,
so that it fails or warns exactly as a separate call does.
"""

from __future__ import annotations

import math

import numpy as np

from assur import _kinematics as _kin
from assur import kinetostatics as _kst
from assur._branches import CANDIDATE, STEP, TURNS
from assur._loads import compile_loads
from assur._stack import restack, stack_loads, stack_plans
from assur._vec import Array, Mask, is_array, leaves
from assur.analysis import CHUNK, driver_rates, to_si
from assur.columns import selection
from assur.plan import Plan
from assur.summary import Summary
from assur.table import Table

__all__ = ["CHUNK", "summaries"]


def summaries(plans: list[Plan], given: Array) -> list[dict[str, float] | None]:
    """Return each variant's summary over driver positions ``given`` (n, 1), deg.

    ``plans`` are variants of one topology (the same :func:`assur._stack.signature`),
    driven by one crank. None for a variant to be analysed on its own (see the
    module's docstring).

    Raises
    ------
    Unstackable
        When the plans differ in more than their numbers.
    """
    k, m = len(plans), given.shape[0]
    plan = stack_plans(plans, m)
    loads = stack_loads([compile_loads(p) for p in plans], m)
    drive = np.concatenate([to_si(p, given) for p in plans])
    rates = driver_rates(plans[0], None, None, k * m)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        bodies, found = _kin.solve(plan, drive, *rates, top=2)
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
    alone = bad.reshape(k, m).any(axis=1) | _near_change_points(plans, plan, drive)
    chosen = selection(plans[0], True, None)
    table = Table(
        plan, chosen.columns, np.tile(given, (k, 1)), state, forces, _index=chosen.index
    )
    summary = Summary(variants=k)
    with np.errstate(invalid="ignore"):
        summary.add(table)
        values = summary.results()
    return [
        None if alone[i] else {name: float(v[i]) for name, v in values.items()}
        for i in range(k)
    ]


def _near_change_points(plans: list[Plan], stacked: Plan, drive: Array) -> Mask:
    """Mark the variants whose path from the reference pose may meet a change point.

    :func:`assur._branches.change_points` scans a grid for minima of each dyad's
    discriminant below :data:`~assur._branches.CANDIDATE`; a variant whose
    discriminants stay above it on that grid all along its path (and a step beyond)
    has none there, and its sweep keeps the reference pose's branches. Variants
    driven beyond the scanned window are marked too. ``stacked`` is the plans'
    stacked plan, each variant over its ``drive`` positions.
    """
    k = len(plans)
    m = drive.shape[0] // k
    reference = np.array([p.drivers[0].reference for p in plans])
    x = drive[:, 0].reshape(k, m) - reference[:, None]
    low = np.minimum(x.min(axis=1, initial=0.0), 0.0)
    high = np.maximum(x.max(axis=1, initial=0.0), 0.0)
    half = TURNS * 2.0 * math.pi
    outside = (low < -half) | (high > half)
    steps = np.arange(
        math.floor(low.min() / STEP) - 1, math.ceil(high.max() / STEP) + 2
    )
    grid = (reference[:, None] + steps[None, :] * STEP).reshape(-1, 1)
    n = grid.shape[0]
    plan = restack(stacked, m, steps.size)
    bodies = _kin.drivers(plan, grid, (0.0,), (0.0,))
    near = np.zeros(n, dtype=bool)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for solver in plan.solvers:
            values = solver.discriminant(bodies)
            if values is not None:
                near |= ~(np.broadcast_to(values, (n,)) >= CANDIDATE)
            solver.assemble(bodies, n)
    # only the grid's points along each variant's own path count
    along = (steps[None, :] >= np.floor(low / STEP)[:, None] - 1) & (
        steps[None, :] <= np.ceil(high / STEP)[:, None] + 1
    )
    return outside | (near.reshape(k, -1) & along).any(axis=1)
