"""Any Assur group by Newton's method: class III triads and larger groups.

Every link of the group has three unknowns (origin x, y and rotation); every pair
two equations. Positions are found by Newton iterations on the whole batch at once,
started from the previous step of a continuation along the driver's path from the
reference pose (so the branch stays the reference pose's); velocities, accelerations,
jerks and reactions solve stacked dense systems with ``numpy.linalg.solve``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assur._vec import Array
from assur.groups._dyad import Wrench, record
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan, partials, residual, unit_wrenches

__all__ = ["GeneralPlan", "conditioning", "derivative", "jacobian", "positions", "reactions"]

MAX_ITERATIONS = 30
TOLERANCE = 1e-13
"""Newton's stopping tolerance, relative to the mechanism's size."""


@dataclass(frozen=True, slots=True)
class GeneralPlan:
    """Links (body indices), their reference origins and every pair of the group."""

    kind: str
    label: str
    bodies: tuple[int, ...]
    origins: Array
    pairs: tuple[PairPlan, ...]
    scale: float


def _blank(phi: Array, o: Array) -> Motion:
    return Motion([phi, phi, phi, phi], [o, o, o, o])


def jacobian(plan: GeneralPlan, bodies: list[Motion]) -> Array:
    """Return the constraint Jacobian, shape (n, 2p, 3k), in the links' unknowns."""
    n = bodies[plan.bodies[0]].c.shape[0]
    size = 3 * len(plan.bodies)
    jac = np.zeros((n, size, size))
    column = {body: 3 * i for i, body in enumerate(plan.bodies)}
    for j, pair in enumerate(plan.pairs):
        for body in {pair.first, pair.second}:
            if body not in column:
                continue
            rows = partials(pair, bodies, body)
            for r in (0, 1):
                for c in (0, 1, 2):
                    jac[:, 2 * j + r, column[body] + c] += rows[r][c]
    return jac


def conditioning(plan: GeneralPlan, jac: Array) -> Array:
    """Reciprocal condition number of the Jacobian made dimensionless.

    Origins are measured in units of the group's size and a prismatic pair's rotation
    equation multiplied by it, so that the measure does not depend on the units.
    """
    cols = np.ones(jac.shape[-1])
    cols[2::3] = 1.0 / plan.scale
    rows = np.ones(jac.shape[-2])
    for j, pair in enumerate(plan.pairs):
        if pair.kind == "P":
            rows[2 * j] = plan.scale
    return 1.0 / np.linalg.cond(jac * rows[:, None] * cols[None, :])


def _residuals(plan: GeneralPlan, bodies: list[Motion], k: int) -> Array:
    return np.stack([r for pair in plan.pairs for r in residual(pair, bodies, k)], axis=-1)


def positions(plan: GeneralPlan, bodies: list[Motion],
              guess: list[tuple[Array, Array]] | None = None) -> list[tuple[Array, Array]]:
    """Assemble the group by Newton's method; NaN where it does not converge.

    Returns the solved ``(rotation, origin)`` of every link, the next guess of a
    continuation.
    """
    n = next(m for m in bodies if m is not None).o[0].shape[0]
    if guess is None:
        guess = [(np.zeros(n), np.broadcast_to(o, (n, 2)).copy()) for o in plan.origins]
    for body, (phi, o) in zip(plan.bodies, guess, strict=True):
        bodies[body] = _blank(phi, o)
    done = np.zeros(n, dtype=bool)
    for _ in range(MAX_ITERATIONS):
        res = _residuals(plan, bodies, 0)
        done = np.max(np.abs(res), axis=-1) <= TOLERANCE * plan.scale
        if done.all():
            break
        jac = jacobian(plan, bodies)
        bad = ~np.isfinite(jac).all(axis=(1, 2)) | (np.abs(np.linalg.det(jac)) < 1e-300)
        jac[bad] = np.eye(jac.shape[-1])
        step = np.linalg.solve(jac, -res[..., None])[..., 0]
        step[bad | done] = 0.0
        for i, body in enumerate(plan.bodies):
            m = bodies[body]
            m.set_pose(m.phi[0] + step[:, 3 * i + 2], m.o[0] + step[:, 3 * i:3 * i + 2])
    out = []
    for body in plan.bodies:
        m = bodies[body]
        phi = np.where(done, m.phi[0], np.nan)
        o = np.where(done[:, None], m.o[0], np.nan)
        m.set_pose(phi, o)
        out.append((phi, o))
    return out


def derivative(plan: GeneralPlan, bodies: list[Motion], k: int, jac: Array) -> None:
    """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of every link."""
    for body in plan.bodies:
        m = bodies[body]
        m.phi[k] = np.zeros_like(m.phi[0])
        m.o[k] = np.zeros_like(m.o[0])
    x = np.linalg.solve(jac, -_residuals(plan, bodies, k)[..., None])[..., 0]
    for i, body in enumerate(plan.bodies):
        bodies[body].o[k] = x[:, 3 * i:3 * i + 2]
        bodies[body].phi[k] = x[:, 3 * i + 2]


def reactions(plan: GeneralPlan, bodies: list[Motion], wrenches: list[Wrench],
              out: dict[str, tuple[Array, Array]]) -> None:
    """Solve every reaction of the group from the three equilibrium equations per link."""
    row = {body: 3 * i for i, body in enumerate(plan.bodies)}
    n = bodies[plan.bodies[0]].c.shape[0]
    size = 3 * len(plan.bodies)
    mat = np.zeros((n, size, size))
    units = [unit_wrenches(pair, bodies) for pair in plan.pairs]
    for j, pair in enumerate(plan.pairs):
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            if body in row:
                for c in (0, 1):
                    for i in (0, 1, 2):
                        mat[:, row[body] + i, 2 * j + c] += sign * units[j][c][i]
    rhs = np.stack([-wrenches[body][i] for body in plan.bodies for i in (0, 1, 2)], axis=-1)
    lam = np.linalg.solve(mat, rhs[..., None])[..., 0]
    for j, pair in enumerate(plan.pairs):
        wrench = [lam[:, 2 * j] * units[j][0][i] + lam[:, 2 * j + 1] * units[j][1][i]
                  for i in (0, 1, 2)]
        record(pair, bodies, wrench, out)
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            if body not in row:
                known = wrenches[body]
                for i in (0, 1, 2):
                    known[i] = known[i] + sign * wrench[i]
