"""Any Assur group by Newton's method: class III triads and larger groups.

Every link of the group has three unknowns (origin x, y and rotation); every pair
two equations. Positions are found by Newton iterations on the whole batch at once,
started from the previous step of a continuation along the driver's path from the
reference pose (so the branch stays the reference pose's); velocities, accelerations,
jerks and reactions solve stacked dense systems with ``numpy.linalg.solve``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from assur._vec import Array, Mask
from assur.groups._dyad import dead_centre, reaction
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan, partials, residual, unit_wrenches
from assur.groups._protocol import (
    Assembly,
    CompileContext,
    Equilibrium,
    Linearization,
    Reaction,
    Wrench,
)
from assur.groups._rcond import reciprocal_condition

if TYPE_CHECKING:
    from assur._structure import Group

__all__ = ["GeneralSolver", "compile_group"]

MAX_ITERATIONS = 30
SINGULAR_FORCES = 1e-12
"""Reciprocal condition number below which a group's equilibrium equations count as
singular (moments in units of force times the mechanism's size)."""
TOLERANCE = 1e-13
"""Newton's stopping tolerance, relative to the size of the coordinates."""
DEAD_CENTRE = 1e-6
"""Smallest reciprocal condition number accepted in the reference pose (that of
:func:`conditioning`)."""

Pose = tuple[Any, Any, Any]
"""A link's ``(rotation, origin x, origin y)`` over a batch."""


@dataclass(frozen=True, slots=True)
class GeneralSolver:
    """A group solved by Newton's method; answers the group-solver protocol.

    ``bodies`` are the group's links, ``origins`` their reference origins (m),
    ``pairs`` every pair of the group (internal, then external), ``scale`` the
    mechanism's size (m), against which rounding of its coordinates is told, and
    ``size`` the group's own (m, the diameter of its pairs in the reference pose),
    against which its conditioning is measured.
    """

    group: Group
    bodies: tuple[int, ...]
    origins: tuple[tuple[float, float], ...]
    pairs: tuple[PairPlan, ...]
    scale: float
    size: float

    newton: ClassVar[bool] = True
    singular: ClassVar[float] = 1e-9
    """Reciprocal condition number of the Jacobian (see :func:`conditioning`: lengths
    in units of the group's size) below which a pose is a dead centre."""
    near: ClassVar[float] = 1e-3
    """The same, below which a pose is near a dead centre (a warning)."""

    @property
    def kind(self) -> str:
        """``"triad"`` or ``"general"``."""
        return self.group.kind

    @property
    def label(self) -> str:
        """Short label such as ``"triad (2, 3, 4, 5)"``."""
        return self.group.label

    @property
    def branch(self) -> float:
        """Return +1: the branch is the one the continuation follows."""
        return 1.0

    @property
    def reach(self) -> float:
        """Size of the numbers Newton works with, m (it bounds their rounding).

        The mechanism's size or the group's distance from the core's origin,
        whichever is larger.
        """
        far = max(abs(v) for o in self.origins for v in o)
        return max(self.scale, far)

    def assemble(
        self, bodies: list[Motion], n: int, guess: Any = None, branch: Any = None
    ) -> Assembly:
        """Assemble the group by Newton's method; NaN where it does not converge.

        ``guess`` holds every link's ``(rotation, x, y)`` to start from (the reference
        pose without one); the solved poses are the next step's guess.
        """
        return positions(self, bodies, n, guess)

    def linearize(self, bodies: list[Motion]) -> Linearization:
        """Return the Jacobian, with the rows of failed positions made harmless."""
        jac, failed = self._finite_jacobian(bodies)
        # read against ``singular`` and ``near`` only (see assur._kinematics)
        cond = conditioning(self, jac, above=self.near)
        singular = ~failed & ~(cond >= self.singular)
        jac[singular] = np.eye(jac.shape[-1])  # their derivatives are not defined
        return Linearization(jac, cond, singular)

    def _finite_jacobian(self, bodies: list[Motion]) -> tuple[Array, Mask]:
        """Return the Jacobian, the identity where a pose failed, and where it did."""
        jac = jacobian(self, bodies, _count(self, bodies))
        failed = np.logical_not(np.isfinite(jac).all(axis=(1, 2)))
        jac[failed] = np.eye(jac.shape[-1])
        return jac, failed

    def derivative(self, bodies: list[Motion], k: int, lin: Linearization) -> None:
        """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of every link."""
        derivative(self, bodies, k, lin.jacobian)

    def tangent(self, bodies: list[Motion]) -> Array:
        """Solve the links' velocities (level 1) and return the Jacobian's sign.

        The sign of the Jacobian's determinant (n,) keeps along a branch that the
        driver can follow: it changes only where the Jacobian is singular (a dead
        centre, or where two assemblies meet). NaN where the pose failed.
        """
        jac, bad = self._finite_jacobian(bodies)
        sign = np.linalg.slogdet(jac)[0]
        jac[sign == 0.0] = np.eye(jac.shape[-1])  # exactly singular: no velocity
        sign[bad] = np.nan
        derivative(self, bodies, 1, jac)
        return sign

    def equilibrium(self, bodies: list[Motion], loads: list[Wrench]) -> Equilibrium:
        """Solve every reaction of the group from three equations per link."""
        return equilibrium(self, bodies, loads)

    def own_slides(self) -> dict[str, tuple[int, float]]:
        """No slide is a link's own coordinate here (links have x, y, rotation)."""
        return {}

    def discriminant(self, bodies: list[Motion]) -> Any:
        """Return None: the branch is followed by continuation, not chosen."""
        return None


def _count(plan: GeneralSolver, bodies: list[Motion]) -> int:
    """Return the number of positions the group's links are solved at."""
    return int(np.size(bodies[plan.bodies[0]].phi[0]))


def jacobian(plan: GeneralSolver, bodies: list[Motion], n: int) -> Array:
    """Return the constraint Jacobian, shape (n, 2p, 3k), in the links' unknowns."""
    size = 3 * len(plan.bodies)
    jac = np.zeros((n, size, size))
    column = {body: 3 * i for i, body in enumerate(plan.bodies)}
    for j, pair in enumerate(plan.pairs):
        for body in {pair.first, pair.second}:
            if body in column:
                rows = partials(pair, bodies, body)
                for r in (0, 1):
                    for c in (0, 1, 2):
                        jac[:, 2 * j + r, column[body] + c] += rows[r][c]
    return jac


def conditioning(plan: GeneralSolver, jac: Array, above: float | None = None) -> Array:
    """Reciprocal condition number of the Jacobian made dimensionless.

    Origins are measured in units of the group's size and a prismatic pair's rotation
    equation multiplied by it, so that the measure depends neither on the units nor
    on the size of the machine the group is part of. Exact wherever it may lie below
    ``above`` (all of it without), a lower bound at least ``above`` elsewhere (see
    :func:`~assur.groups._rcond.reciprocal_condition`).
    """
    # the group's size, not the machine's: a triad 0.3 m across in a chain 12 m long
    # weighed its rotations 40 times too little and looked near a dead centre
    cols = np.ones(jac.shape[-1])
    cols[2::3] = 1.0 / plan.size
    rows = np.ones(jac.shape[-2])
    for j, pair in enumerate(plan.pairs):
        if pair.kind == "P":
            rows[2 * j] = plan.size
    return reciprocal_condition(jac * rows[:, None] * cols[None, :], above)


def _residuals(plan: GeneralSolver, bodies: list[Motion], k: int, n: int) -> Array:
    out = np.empty((n, 2 * len(plan.pairs)))
    for j, pair in enumerate(plan.pairs):
        out[:, 2 * j], out[:, 2 * j + 1] = residual(pair, bodies, k)
    return out


def positions(
    plan: GeneralSolver, bodies: list[Motion], n: int, guess: list[Pose] | None = None
) -> Assembly:
    """Assemble the group by Newton's method; NaN where it does not converge."""
    if guess is None:
        guess = [
            (np.zeros(n), np.full(n, o[0]), np.full(n, o[1])) for o in plan.origins
        ]
    for body, (phi, x, y) in zip(plan.bodies, guess, strict=True):
        bodies[body] = Motion(
            [phi, 0.0, 0.0, 0.0], [x, 0.0, 0.0, 0.0], [y, 0.0, 0.0, 0.0]
        )
    for _ in range(MAX_ITERATIONS):
        res = _residuals(plan, bodies, 0, n)
        done = np.max(np.abs(res), axis=-1) <= TOLERANCE * plan.reach
        # a residual that is not finite stays so (a failed guess): no step helps
        if (done | ~np.isfinite(res).all(axis=-1)).all():
            break
        jac = jacobian(plan, bodies, n)
        bad = ~np.isfinite(jac).all(axis=(1, 2))
        jac[bad] = 0.0  # replaced below; keeps det from meeting NaN
        bad |= np.abs(np.linalg.det(jac)) < 1e-300
        jac[bad] = np.eye(jac.shape[-1])
        step = np.linalg.solve(jac, -res[..., None])[..., 0]
        step[bad | done] = 0.0
        for i, body in enumerate(plan.bodies):
            m = bodies[body]
            m.set_pose(
                m.phi[0] + step[:, 3 * i + 2],
                m.ox[0] + step[:, 3 * i],
                m.oy[0] + step[:, 3 * i + 1],
            )
    done = (
        np.max(np.abs(_residuals(plan, bodies, 0, n)), axis=-1)
        <= TOLERANCE * plan.reach
    )
    out = []
    for body in plan.bodies:
        m = bodies[body]
        pose = tuple(np.where(done, v, np.nan) for v in (m.phi[0], m.ox[0], m.oy[0]))
        m.set_pose(*pose)
        out.append(pose)
    return Assembly(~done, out)


def derivative(plan: GeneralSolver, bodies: list[Motion], k: int, jac: Array) -> None:
    """Solve level ``k`` (1 velocity, 2 acceleration, 3 jerk) of every link."""
    n = jac.shape[0]
    for body in plan.bodies:
        m = bodies[body]
        m.phi[k] = m.ox[k] = m.oy[k] = 0.0
    x = np.linalg.solve(jac, -_residuals(plan, bodies, k, n)[..., None])[..., 0]
    for i, body in enumerate(plan.bodies):
        m = bodies[body]
        m.ox[k], m.oy[k], m.phi[k] = x[:, 3 * i], x[:, 3 * i + 1], x[:, 3 * i + 2]


def equilibrium(
    plan: GeneralSolver, bodies: list[Motion], loads: list[Wrench]
) -> Equilibrium:
    """Solve every reaction of the group from three equilibrium equations per link.

    Positions where the equations are singular (a dead centre) or the pose failed
    hold NaN; the sweep reports those positions.
    """
    n = _count(plan, bodies)
    row = {body: 3 * i for i, body in enumerate(plan.bodies)}
    size = 3 * len(plan.bodies)
    mat = np.zeros((n, size, size))
    units = [unit_wrenches(pair, bodies) for pair in plan.pairs]
    for j, pair in enumerate(plan.pairs):
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            if body in row:
                for c in (0, 1):
                    for i in (0, 1, 2):
                        mat[:, row[body] + i, 2 * j + c] += sign * units[j][c][i]
    rhs = np.empty((n, size))
    for body, r in row.items():
        for i in (0, 1, 2):
            rhs[:, r + i] = -loads[body][i]
    bad = ~np.isfinite(mat).all(axis=(1, 2))
    mat[bad] = np.eye(size)
    # moments and couples in units of the mechanism's size: a measure free of units;
    # not the group's own (as its conditioning is), which would move the reactions by
    # round-off, and a sound triad a billionth of its machine still measures 5e-11
    rows = np.ones(size)
    rows[2::3] = 1.0 / plan.scale
    cols = np.ones(size)
    for j, pair in enumerate(plan.pairs):
        if pair.kind == "P":
            # a couple in units of force times the mechanism's size, as moments are
            cols[2 * j + 1] = plan.scale
    scaled = mat * rows[:, None] * cols[None, :]
    bad |= reciprocal_condition(scaled, above=SINGULAR_FORCES) < SINGULAR_FORCES
    scaled[bad] = np.eye(size)
    # solved as measured: unscaled, a group 1e13 m across mixed forces of 1 with
    # arms of 1e13 in one elimination and lost three digits of its reactions
    lam = np.linalg.solve(scaled, (rhs * rows)[..., None])[..., 0] * cols
    lam[bad] = np.nan
    reactions: dict[str, Reaction] = {}
    passed = []
    for j, pair in enumerate(plan.pairs):
        wrench = [
            lam[:, 2 * j] * units[j][0][i] + lam[:, 2 * j + 1] * units[j][1][i]
            for i in (0, 1, 2)
        ]
        reactions[pair.name] = reaction(pair, bodies, wrench)
        for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
            if body not in row:
                passed.append((body, [sign * w for w in wrench]))
    return Equilibrium(
        plan.label,
        plan.bodies,
        tuple(loads[b] for b in plan.bodies),
        plan.pairs,
        reactions,
        tuple(passed),
        tuple((0.0, 0.0) for _ in plan.bodies),
    )


def compile_group(context: CompileContext, group: Group) -> GeneralSolver:
    """Compile a group solved by Newton's method; refuse a reference dead centre.

    Raises
    ------
    ModelError
        When the reference pose is at a dead centre of the group.
    """
    bodies = tuple(context.index[x] for x in group.links)
    solver = GeneralSolver(
        group,
        bodies,
        tuple((float(x), float(y)) for x, y in context.origins[list(bodies)]),
        tuple(context.pairs[p] for p in group.internal + group.external),
        context.scale,
        context.size(group),
    )
    jac = jacobian(solver, context.reference(), 1)
    if not conditioning(solver, jac)[0] >= DEAD_CENTRE:
        dead_centre(group)
    return solver
