"""Reach: the driver positions a one-driver mechanism reaches from its reference pose.

A closed-form dyad is assembled at each position on its reference branch: it does not
follow the motion. A position the mechanism cannot reach without being taken apart
(another circuit of a four-bar whose input only rocks, or the far side of a PRP
dyad's dead centre, where its pin goes off to infinity) is then assembled all the
same. The driver's range around the reference pose is scanned once per plan for
barriers (a closed-form group that fails or is singular, or whose Jacobian's
determinant changes sign between two grid points); :func:`unreached` marks the
positions beyond them for the forward pass, a trouble of kind "unreached".
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._branches import (
    SIZES,
    SLIDER_POINTS,
    STEP,
    branch_function,
    change_points,
    gaps,
)
from assur._follow import BranchOf
from assur._kinematics import Trouble, solve
from assur._quiet import quiet
from assur._vec import Array, Mask
from assur.groups._motion import Motion
from assur.plan import Plan

__all__ = ["Barrier", "Reach", "beyond", "reach", "unreached"]

TURN = 2.0 * math.pi
"""A crank's turn, rad; it is scanned one turn either side of the reference pose."""
BARRIERS = frozenset({"assembly", "singular"})
"""The troubles of a closed-form group at a grid point that stop the mechanism."""


@dataclass(frozen=True, slots=True)
class Barrier:
    """Where a group stops the mechanism on one side of the reference pose.

    ``group`` is the solver's index; ``kind`` is "assembly" (the group cannot be
    assembled from ``start`` to ``end``) or "singular" (a dead centre at ``start``,
    ``end`` the same), driver positions in rad (m for a slider).
    """

    group: int
    kind: str
    start: float
    end: float


@dataclass(frozen=True, slots=True)
class Reach:
    """The driver positions reached from the reference pose: ``low`` to ``high``.

    In rad (m for a slider), infinite on a side without a barrier; ``below`` and
    ``above`` are the barriers that bound it; ``period`` is a turn for a crank
    (positions a whole number of turns from the range are reached too), None for a
    slider. ``first`` and ``last`` are the outermost grid positions reached.
    """

    low: float
    high: float
    period: float | None
    below: Barrier | None
    above: Barrier | None
    first: float
    last: float

    def reached(self, x: Array) -> Mask:
        """Return where driver positions ``x`` (rad or m) are reached."""
        if self.period is None:
            return (x >= self.low) & (x <= self.high)  # type: ignore[no-any-return]
        y = self.low + np.remainder(x - self.low, self.period)
        return y <= self.high  # type: ignore[no-any-return]


def reach(plan: Plan) -> Reach | None:
    """Return the driver positions ``plan`` reaches (scanned once and kept), or None.

    None when every position is: several drivers (out of scope), a crank without a
    barrier within a turn of the reference pose (it turns fully) or whose barriers
    leave it a turn or more, a slider without a barrier in the scanned window.
    """
    if "reach" not in plan.memo:
        plan.memo["reach"] = _scan(plan)
    return plan.memo["reach"]  # type: ignore[no-any-return]


def unreached(plan: Plan, drive: Array, found: list[Trouble]) -> list[Trouble]:
    """Return the troubles of the driver positions ``drive`` (n, 1) not reached.

    One per barrier's group, of kind "unreached"; the positions where ``found`` (the
    forward pass's troubles) already has a group fail are left to that trouble.
    """
    span = reach(plan)
    if span is None or drive.shape[1] != 1:
        return []
    x = drive[:, 0]
    out = ~span.reached(x)
    if not out.any():
        return []
    for trouble in found:
        if trouble.what in BARRIERS:
            out &= ~trouble.mask
    ahead = x > plan.drivers[0].reference
    troubles = []
    for barrier, side in ((span.above, ahead), (span.below, ~ahead)):
        # a position beyond the range is named with the barrier on its way
        barrier = barrier or span.above or span.below
        mask = out & side
        if barrier is not None and mask.any():
            label = plan.solvers[barrier.group].label
            troubles.append(Trouble(label, "unreached", mask))
    return troubles


def beyond(plan: Plan, drive: Array) -> Mask:
    """Return where driver positions ``drive`` (n, 1) are marked "unreached".

    Those beyond a barrier where every group assembles, away from dead centres: the
    positions :func:`unreached` gives a trouble of their own (rad or m).
    """
    span = reach(plan)
    if span is None or drive.shape[1] != 1:
        return np.zeros(drive.shape[0], dtype=bool)
    out = ~span.reached(drive[:, 0])
    if out.any():
        branch_of = branch_function(plan) if change_points(plan) is not None else None
        with quiet():
            found = solve(plan, drive[out], (0.0,), (0.0,), 0, branch_of)[1]
        far = np.ones(int(out.sum()), dtype=bool)
        for trouble in found:
            if trouble.what in BARRIERS:
                far &= ~trouble.mask
        out[out] = far
    return out  # type: ignore[no-any-return]


def _grid(plan: Plan) -> tuple[Array, float | None]:
    """Return the scan's driver positions (rad or m) and a crank's period."""
    d = plan.drivers[0]
    if d.kind == "R":
        return d.reference + np.arange(-TURN, TURN + STEP / 2, STEP), TURN
    half = SIZES * plan.scale
    return d.reference + np.linspace(-half, half, SLIDER_POINTS), None


def _scan(plan: Plan) -> Reach | None:
    """Scan the driver's range for barriers either side of the reference pose."""
    if len(plan.drivers) != 1 or all(s.newton for s in plan.solvers):
        return None
    grid, period = _grid(plan)
    points = change_points(plan)
    cps = np.zeros(0) if points is None else np.concatenate(points.points)
    # the sweeps' own branches past change points (see assur._passes)
    branch_of = branch_function(plan) if cps.size else None
    with quiet():
        bodies, found = solve(plan, grid[:, None], (0.0,), (0.0,), 0, branch_of)
    barriers = _failed(plan, grid, found, cps)
    # gaps narrower than the grid's step, found where a discriminant dips below zero
    for g, where in gaps(plan).items():
        barriers += [Barrier(g, "assembly", float(x), float(x)) for x in where]
    for g, solver in enumerate(plan.solvers):
        # a family without a signed conditioning: only its failures are barriers
        if solver.newton or not hasattr(solver, "signed_conditioning"):
            continue
        with quiet():
            det = _determinant(solver, bodies)
        for a, b in _sign_changes(grid, np.broadcast_to(det, grid.shape), cps):
            x = _refine(plan, g, a, b, branch_of)
            barriers.append(Barrier(g, "singular", x, x))
    return _bounded(plan, grid, period, barriers)


def _failed(plan: Plan, grid: Array, found: list[Trouble], cps: Array) -> list[Barrier]:
    """Return the barriers of grid points where a closed-form group fails.

    A group fails at the grid point where a group before it does (its links' poses
    are NaN): the first owns the point. A point at a change point is passed there
    (a parallelogram is singular at it), and a Newton group's failures are left to
    its continuation, which follows it (or turns the other way round).
    """
    index = {s.label: g for g, s in enumerate(plan.solvers)}
    owner = np.full(grid.shape[0], -1)
    for trouble in found:
        if trouble.what in BARRIERS:
            owner[(owner < 0) & trouble.mask] = index[trouble.group]
    if cps.size:
        spacing = float(grid[1] - grid[0])
        gap = np.min(np.abs(grid[:, None] - cps[None, :]), axis=1)
        owner[gap <= spacing] = -1
    newton = np.array([s.newton for s in plan.solvers] + [True])
    bad = ~newton[owner]
    if not bad.any():
        return []
    # the runs of consecutive grid points that fail, each of its first group
    steps = np.diff(np.r_[False, bad, False].astype(np.int8))
    starts, ends = np.flatnonzero(steps == 1), np.flatnonzero(steps == -1) - 1
    out = []
    for i, j in zip(starts.tolist(), ends.tolist(), strict=True):
        g = int(owner[i])
        kind = "singular" if i == j and _singular(found, plan, g, i) else "assembly"
        out.append(Barrier(g, kind, float(grid[i]), float(grid[j])))
    return out


def _singular(found: list[Trouble], plan: Plan, g: int, i: int) -> bool:
    """Whether group ``g``'s trouble at grid point ``i`` is a dead centre."""
    label = plan.solvers[g].label
    return any(t.group == label and t.what == "singular" and t.mask[i] for t in found)


def _determinant(solver: Any, bodies: list[Motion]) -> Any:
    """Return a closed-form group's signed conditioning (its determinant's sign)."""
    return solver.signed_conditioning(bodies)


def _sign_changes(grid: Array, det: Array, cps: Array) -> list[tuple[float, float]]:
    """Return the grid intervals where ``det`` changes sign with no change point."""
    with quiet():
        flip = np.sign(det[:-1]) * np.sign(det[1:]) < 0.0
    out = []
    for i in np.flatnonzero(flip).tolist():
        a, b = float(grid[i]), float(grid[i + 1])
        if not np.any((cps >= a) & (cps <= b)):
            out.append((a, b))
    return out


def _refine(
    plan: Plan, g: int, a: float, b: float, branch_of: BranchOf | None
) -> float:
    """Return where group ``g``'s determinant changes sign between ``a`` and ``b``."""
    from scipy.optimize import brentq

    solver = plan.solvers[g]

    def det(x: float) -> float:
        with quiet():
            bodies = solve(plan, np.array([[x]]), (0.0,), (0.0,), 0, branch_of)[0]
            value = float(np.ravel(_determinant(solver, bodies))[0])
        # a pose that does not close is itself the dead centre
        return value if math.isfinite(value) else 0.0

    return float(brentq(det, a, b, xtol=1e-12))


def _bounded(
    plan: Plan, grid: Array, period: float | None, barriers: list[Barrier]
) -> Reach | None:
    """Return the reach between the nearest barriers either side of the reference."""
    ref = plan.drivers[0].reference
    above = min(
        (b for b in barriers if b.start > ref), key=lambda b: b.start, default=None
    )
    below = max((b for b in barriers if b.end < ref), key=lambda b: b.end, default=None)
    high = math.inf if above is None else above.start
    low = -math.inf if below is None else below.end
    if period is not None and not high - low < period:
        return None  # a whole turn or more: every angle is reached on some turn
    if above is None and below is None:
        return None
    # the outermost grid positions reached, for the messages
    inside = grid[(grid > low) & (grid < high)]
    first = low if below is not None and below.kind == "singular" else inside[0]
    last = high if above is not None and above.kind == "singular" else inside[-1]
    return Reach(low, high, period, below, above, float(first), float(last))
