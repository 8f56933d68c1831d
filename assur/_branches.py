"""Change points: where a dyad's two assembly branches meet, and the branch beyond.

A closed-form dyad (RRR, RRP, RPR) has two assembly branches; its discriminant is
zero where they meet. Where it only touches zero (a change point: a parallelogram
four-bar at 0 and 180 degrees) the mechanism moves on smoothly onto the other branch,
the one whose velocities are continuous: a parallelogram stays a parallelogram. The
driver's range around the reference pose is scanned once per plan for such points;
each position's branch is then the reference pose's, flipped once for every change
point on the driver's straight path from the reference pose.

Scanned: one driver, every dyad; a group solved by Newton's method has no branch to
choose (its continuation follows it), and the dyads attached after it are scanned on
the poses its continuation reaches along the grid, walked on the branches of the
change points found before it. Several drivers: see :mod:`assur._paths`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._follow import BranchOf, drivers
from assur._kinematics import continuation
from assur._quiet import quiet
from assur._vec import Array
from assur._walk import flipped
from assur.plan import Plan

__all__ = [
    "ChangePoints",
    "at_change_point",
    "branch_function",
    "branches",
    "change_points",
    "closed",
    "gaps",
    "lowest",
]

STEP = math.radians(0.5)
"""Grid step of the scan of a crank, rad."""
TURNS = 2
"""A crank is scanned this many turns either side of the reference pose; positions
farther away repeat the window (two turns bring every dyad back to its branch)."""
SIZES = 4.0
"""A slider is scanned this many mechanism sizes either side of the reference pose."""
SLIDER_POINTS = 4001
"""Grid points of the scan of a slider."""
CANDIDATE = 0.05
"""A discriminant at a local minimum of the grid below this is looked at closely."""
TOUCH = 1e-12
"""A discriminant whose minimum is within this of zero touches it: a change point
(the square of the smallest sine a closed form resolves, 1e-6)."""
REFINE = 80
"""Golden-section steps that locate a minimum of the discriminant."""


@dataclass(frozen=True, slots=True)
class ChangePoints:
    """The change points of each solver of a plan, as driver positions (rad or m).

    ``points[g]`` is sorted (empty for a group without change points); ``low`` and
    ``high`` bound the scanned window; ``period`` is the window's width for a crank
    (positions beyond it repeat it), None for a slider.
    """

    points: tuple[Array, ...]
    low: float
    high: float
    period: float | None

    @property
    def any(self) -> bool:
        """Whether some group has a change point."""
        return any(p.size for p in self.points)

    def within(self, x: Any) -> Any:
        """Return driver positions ``x`` (rad or m) moved into the scanned window.

        A crank's position a whole number of turns outside it is the one inside;
        a slider's stays as it is.
        """
        if self.period is None:
            return x
        return self.low + np.remainder(x - self.low, self.period)


def _found_to(plan: Plan) -> float:
    """Return the distance (rad, or m) within which a position is a change point.

    A change point is found to about 1e-8 of a radian, or of the mechanism's size.
    """
    return 1e-6 * (1.0 if plan.drivers[0].kind == "R" else plan.scale)


def change_points(plan: Plan) -> ChangePoints | None:
    """Return the change points of ``plan`` (scanned once and kept), or None.

    None when nothing can change branch: several drivers (their paths are scanned
    by :mod:`assur._paths`), or no change point found.
    """
    if "change-points" not in plan.memo:
        plan.memo["change-points"] = _scan(plan)
    return plan.memo["change-points"]  # type: ignore[no-any-return]


def closed(plan: Plan, upto: int | None = None) -> list[int]:
    """Return the solvers a scan covers: up to the last closed-form one.

    Only those before solver index ``upto`` count (all of them when None).
    """
    last = len(plan.solvers) if upto is None else upto
    found = [g for g, solver in enumerate(plan.solvers[:last]) if not solver.newton]
    return list(range(found[-1] + 1)) if found else []


def _assemble(
    plan: Plan, bodies: list[Any], at: Array, flips: dict[int, Array], g: int
) -> None:
    """Assemble solver ``g`` at driver positions ``at`` (n,) on its branch so far.

    A Newton group takes the poses of its continuation from the reference pose,
    on the branches the change points found so far give the dyads before it; the
    anchors of that continuation are kept for those change points alone.
    """
    solver = plan.solvers[g]
    ref = plan.drivers[0].reference
    drive = at[:, None]
    if solver.newton:
        found = {k: points for k, points in flips.items() if k < g}

        def branch_of(x: Array, upto: int) -> dict[int, Array]:
            return {
                k: _branch(plan.solvers[k], points, x, ref)
                for k, points in found.items()
            }

        # a later Newton group, past more change points, walks anchors of its own:
        # those walked for an earlier one put the dyads between them on their
        # reference branches (the last dyad of two triads with a parallelogram
        # between them lost its change points)
        anchors = plan.memo.setdefault("scan-anchors", {})
        kept = anchors.setdefault(tuple(found), {}) if found else None
        guesses = continuation(plan, drive, branch_of if found else None, kept)
        k = sum(1 for s in plan.solvers[:g] if s.newton)
        solver.assemble(bodies, at.shape[0], guesses[k])
        return
    points = flips.get(g)
    branch = None if points is None else _branch(solver, points, drive, ref)
    solver.assemble(bodies, at.shape[0], branch=branch)


def _scan(plan: Plan) -> ChangePoints | None:
    if len(plan.drivers) != 1:
        return None
    d = plan.drivers[0]
    groups = closed(plan)
    if d.kind == "R":
        half = TURNS * 2.0 * math.pi
        grid = d.reference + np.arange(-half, half + STEP / 2, STEP)
        period: float | None = 2.0 * half
    else:
        half = SIZES * plan.scale
        grid = d.reference + np.linspace(-half, half, SLIDER_POINTS)
        period = None
    flips: dict[int, Array] = {}
    gaps: dict[int, Array] = {}
    # one pass over the grid: each group is assembled on the branches its change
    # points give it before the next group's discriminant is taken
    n = grid.shape[0]
    bodies = drivers(plan, grid[:, None], (0.0,), (0.0,))
    with quiet():
        for g in groups:
            solver = plan.solvers[g]
            values = solver.discriminant(bodies)
            if values is not None:
                values = np.broadcast_to(values, (n,))
                points, dips = _touches(plan, grid, values, flips, g)
                if points.size:
                    flips[g] = points
                if dips.size:
                    gaps[g] = dips
            _assemble(plan, bodies, grid, flips, g)
    # anchors walked on the branches of a part of the change points are not kept
    plan.memo.pop("scan-anchors", None)
    plan.memo["gaps"] = gaps
    if not flips:
        return None
    found = tuple(flips.get(g, np.zeros(0)) for g in range(len(plan.solvers)))
    return ChangePoints(found, float(grid[0]), float(grid[-1]), period)


def _discriminants(
    plan: Plan, at: Array, flips: dict[int, Array], upto: int
) -> Array | None:
    """Group ``upto``'s discriminant at driver positions ``at`` (rad or m).

    The groups before it are assembled on the branches the change points found so far
    give them.
    """
    n = at.shape[0]
    bodies = drivers(plan, at[:, None], (0.0,), (0.0,))
    with quiet():
        for g, solver in enumerate(plan.solvers[: upto + 1]):
            if g == upto:
                values = solver.discriminant(bodies)
                return None if values is None else np.broadcast_to(values, (n,))
            _assemble(plan, bodies, at, flips, g)
    return None


def _touches(
    plan: Plan, grid: Array, values: Array, flips: dict[int, Array], g: int
) -> tuple[Array, Array]:
    """Locate where group ``g``'s discriminant touches zero between grid points.

    Also where it dips below zero there: a gap where the group cannot be assembled,
    narrower than the grid's step (see :func:`gaps`).
    """
    inner = values[1:-1]
    low = (inner <= values[:-2]) & (inner <= values[2:]) & (np.abs(inner) < CANDIDATE)
    index = np.flatnonzero(low) + 1
    if index.size == 0:
        return np.zeros(0), np.zeros(0)

    def discriminant(x: Array) -> Array:
        found = _discriminants(plan, x, flips, g)
        assert found is not None
        return found

    middle, minimum = lowest(discriminant, grid[index - 1], grid[index + 1])
    # a touch, not a dip below zero (where the dyad stops: no branch beyond)
    touch = np.abs(minimum) <= TOUCH
    return np.sort(middle[touch]), np.sort(middle[minimum < -TOUCH])


def gaps(plan: Plan) -> dict[int, Array]:
    """Return where each dyad's discriminant dips below zero between grid points.

    Driver positions (rad or m) by solver index, found by the scan for change points
    (:func:`change_points`, one driver): each lies in a gap where the dyad cannot be
    assembled, which the grid may step over (narrower than 0.5 deg of a crank).
    """
    change_points(plan)
    return plan.memo.get("gaps", {})  # type: ignore[no-any-return]


def lowest(f: Callable[[Array], Array], a: Array, b: Array) -> tuple[Array, Array]:
    """Return where ``f`` is lowest in each interval ``[a, b]``, and its value there.

    Golden-section search, :data:`REFINE` steps, every interval at once; a NaN
    (a pose that does not close) counts as low.
    """
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(REFINE):
        c, d = b - ratio * (b - a), a + ratio * (b - a)
        left = ~(f(c) > f(d))  # the minimum is in [a, d]
        b = np.where(left, d, b)
        a = np.where(left, a, c)
    middle = 0.5 * (a + b)
    return middle, f(middle)


def _branch(solver: Any, points: Array, drive: Array, ref: float) -> Array:
    """Return the branch (+1 or -1) at each driver position.

    The reference pose's branch, flipped at every change point between the reference
    pose and the position.
    """
    x = drive[:, 0]
    count = np.zeros(x.shape[0], dtype=np.int64)
    for c in points:
        if c > ref:
            count += x >= c
        else:
            count += x <= c
    return flipped(solver.branch, count)


def branches(
    plan: Plan, drive: Array
) -> tuple[dict[int, Array], list[tuple[int, float]]]:
    """Return each dyad's branch at driver positions ``drive`` (n, 1), SI units.

    Returns the branch arrays of the dyads that change branch somewhere in the sweep,
    by solver index, and the change points the sweep passes ``(solver index,
    position)``. Empty when nothing changes branch.
    """
    found = change_points(plan)
    if found is None or not found.any:
        return {}, []
    ref = plan.drivers[0].reference
    x = found.within(drive[:, :1])  # positions beyond the window repeat it
    tol = _found_to(plan)
    out, passed = {}, []
    lo, hi = float(np.min(x, initial=ref)), float(np.max(x, initial=ref))
    for g, points in enumerate(found.points):
        if not points.size:
            continue
        branch = _branch(plan.solvers[g], points, x, ref)
        if np.any(branch != plan.solvers[g].branch):
            out[g] = branch
        # passed: a position lies beyond it from the reference pose (a sweep that
        # ends on a change point, or one position there, was told the motion is
        # carried through it, then stopped at its dead centre)
        passed += [
            (g, float(c))
            for c in points
            if (ref - tol <= c < hi - tol) or (lo + tol < c <= ref + tol)
        ]
    return out, passed


def branch_function(plan: Plan) -> BranchOf:
    """Return the groups' branches past change points as a function of position.

    One driver: ``f(drive, upto)`` is :func:`branches`' first item at ``drive`` (n, 1),
    SI units; ``upto`` is not needed, since one scan gives every group's branches.
    """
    return lambda drive, upto: branches(plan, drive)[0]


def at_change_point(plan: Plan, g: int, x: float) -> bool:
    """Return whether driver position ``x`` (rad, or m) is a change point of ``g``.

    ``g`` is a solver's index; a change point is found to within 1e-6 (rad, or of
    the mechanism's size), and a crank's whole turns from one count too.
    """
    found = change_points(plan)
    if found is None or not found.points[g].size:
        return False
    return bool(np.any(np.abs(found.points[g] - found.within(x)) <= _found_to(plan)))
