"""A group family written for the tests: the RRR dyad by complex numbers and dense
linear algebra.

It answers the group-solver protocol of ``assur.groups`` on its own: positions from
the intersection of two circles in complex arithmetic, velocities, accelerations and
jerks from the differentiated loop closure solved with ``numpy.linalg.solve``, and
reactions from all six equilibrium equations of the two links at once. Registered in
place of the closed-form family (one line in ``assur.groups.FAMILIES``), it must give
the same tables: a check of the registry's seam and, independently, of the
closed-form RRR solver.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from assur.groups._motion import Motion, point
from assur.groups._pairs import PairPlan
from assur.groups._protocol import (
    Assembly,
    CompileContext,
    Equilibrium,
    Linearization,
    Reaction,
)


def _perp(x: Any, y: Any) -> tuple[Any, Any]:
    return -y, x


@dataclass(frozen=True)
class DenseRRR:
    group: Any
    bodies: tuple[int, int]
    outer: tuple[PairPlan, PairPlan]
    middle: PairPlan
    known: tuple[int, int]
    d_known: tuple[tuple[float, float], tuple[float, float]]
    d_middle: tuple[tuple[float, float], tuple[float, float]]
    radius: tuple[float, float]
    angle0: tuple[float, float]
    side: float

    newton: ClassVar[bool] = False
    singular: ClassVar[float] = 1e-9
    near: ClassVar[float] = 0.035

    @property
    def label(self) -> str:
        return self.group.label

    def _pins(self, bodies: list[Motion], k: int) -> list[complex | Any]:
        out = []
        for b in (0, 1):
            x, y = point(bodies[self.known[b]], self.d_known[b], k)
            out.append(np.asarray(x) + 1j * np.asarray(y))
        return out

    def assemble(
        self, bodies: list[Motion], n: int, guess: Any = None, branch: Any = None
    ) -> Assembly:
        p1, p2 = (np.broadcast_to(p, (n,)) for p in self._pins(bodies, 0))
        r1, r2 = self.radius
        gap = p2 - p1
        dist = np.abs(gap)
        along = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist)
        with np.errstate(invalid="ignore"):
            height = np.sqrt(r1 * r1 - along * along)
        unit = gap / dist
        side = self.side if branch is None else branch
        c = p1 + unit * (along + 1j * side * height)
        failed = ~np.isfinite(c)
        for b, pin in ((0, p1), (1, p2)):
            rotation = np.angle(c - pin) - self.angle0[b]
            bodies[self.bodies[b]] = Motion(
                [rotation, 0.0, 0.0, 0.0],
                [pin.real, 0.0, 0.0, 0.0],
                [pin.imag, 0.0, 0.0, 0.0],
            )
        return Assembly(failed)

    def _arms(self, bodies: list[Motion]) -> list[tuple[Any, Any]]:
        arms = []
        for b in (0, 1):
            m = bodies[self.bodies[b]]
            d = self.d_middle[b]
            c, s = np.cos(m.phi[0]), np.sin(m.phi[0])
            arms.append((c * d[0] - s * d[1], s * d[0] + c * d[1]))
        return arms

    def linearize(self, bodies: list[Motion]) -> Linearization:
        (u1x, u1y), (u2x, u2y) = self._arms(bodies)
        n = np.size(u1x)
        mat = np.empty((n, 2, 2))
        mat[:, 0, 0], mat[:, 1, 0] = _perp(u1x, u1y)
        px, py = _perp(u2x, u2y)
        mat[:, 0, 1], mat[:, 1, 1] = -px, -py
        cross = u1x * u2y - u1y * u2x
        with np.errstate(invalid="ignore", divide="ignore"):
            cond = np.abs(cross) / (np.hypot(u1x, u1y) * np.hypot(u2x, u2y))
        bad = ~np.isfinite(mat).all(axis=(1, 2)) | ~(cond >= self.singular)
        mat[bad] = np.eye(2)
        return Linearization(mat, cond, ~(cond >= self.singular))

    def derivative(self, bodies: list[Motion], k: int, lin: Linearization) -> None:
        (u1x, u1y), (u2x, u2y) = self._arms(bodies)
        m1, m2 = (bodies[b] for b in self.bodies)
        p1, p2 = self._pins(bodies, k)
        terms = []
        for m, ux, uy in ((m1, u1x, u1y), (m2, u2x, u2y)):
            w = m.phi[1]
            a = m.phi[2]
            if k == 1:
                tx, ty = 0.0, 0.0
            elif k == 2:
                tx, ty = -w * w * ux, -w * w * uy
            else:
                px, py = _perp(ux, uy)
                tx = -(w**3) * px - 3.0 * w * a * ux
                ty = -(w**3) * py - 3.0 * w * a * uy
            terms.append((tx, ty))
        rhs = (p2 - p1) + (terms[1][0] - terms[0][0]) + 1j * (terms[1][1] - terms[0][1])
        n = lin.jacobian.shape[0]
        rhs = np.broadcast_to(rhs, (n,))
        vec = np.stack([rhs.real, rhs.imag], axis=-1)
        x = np.linalg.solve(lin.jacobian, vec[..., None])[..., 0]
        for b, m in ((0, m1), (1, m2)):
            pin = p1 if b == 0 else p2
            m.phi[k] = x[:, b]
            m.ox[k], m.oy[k] = np.real(pin), np.imag(pin)

    def equilibrium(self, bodies: list[Motion], loads: list[Any]) -> Equilibrium:
        pairs = (self.middle, *self.outer)
        n = np.size(bodies[self.bodies[0]].phi[0])
        mat = np.zeros((n, 6, 6))
        rhs = np.zeros((n, 6))
        row = {b: 3 * i for i, b in enumerate(self.bodies)}
        for j, pair in enumerate(pairs):
            qx, qy = point(bodies[pair.second], pair.d_second, 0)
            for c, (fx, fy) in enumerate(((1.0, 0.0), (0.0, 1.0))):
                for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
                    if body in row:
                        r = row[body]
                        mat[:, r, 2 * j + c] += sign * fx
                        mat[:, r + 1, 2 * j + c] += sign * fy
                        mat[:, r + 2, 2 * j + c] += sign * (qx * fy - qy * fx)
        for body, r in row.items():
            for i in range(3):
                rhs[:, r + i] = -np.broadcast_to(loads[body][i], (n,))
        lam = np.linalg.solve(mat, rhs[..., None])[..., 0]
        reactions = {}
        passed = []
        for j, pair in enumerate(pairs):
            fx, fy = lam[:, 2 * j], lam[:, 2 * j + 1]
            reactions[pair.name] = Reaction(fx, fy)
            qx, qy = point(bodies[pair.second], pair.d_second, 0)
            wrench = [fx, fy, qx * fy - qy * fx]
            for body, sign in ((pair.second, 1.0), (pair.first, -1.0)):
                if body not in row:
                    passed.append((body, [sign * w for w in wrench]))
        return Equilibrium(
            self.label,
            self.bodies,
            tuple(loads[b] for b in self.bodies),
            pairs,
            reactions,
            tuple(passed),
            self.d_middle,
        )

    @property
    def branch(self) -> float:
        return self.side

    def discriminant(self, bodies: list[Motion]) -> Any:
        """Squared sine of the angle at the middle pin (negative: cannot close)."""
        p1, p2 = self._pins(bodies, 0)
        r1, r2 = self.radius
        dist = np.abs(p2 - p1)
        along = (r1 * r1 - r2 * r2 + dist * dist) / (2.0 * dist)
        return (r1 * r1 - along * along) * dist * dist / (r1 * r1 * r2 * r2)

    def own_slides(self) -> dict[str, tuple[int, float]]:
        return {}


def compile_group(context: CompileContext, group: Any) -> DenseRRR:
    """Compile an RRR dyad; its branch is the side of the reference pose."""
    bodies = (context.index[group.links[0]], context.index[group.links[1]])
    outer = (context.pairs[group.external[0]], context.pairs[group.external[1]])
    middle = context.pairs[group.internal[0]]
    known = tuple(
        p.first if p.second == b else p.second
        for p, b in zip(outer, bodies, strict=True)
    )
    d_known = tuple(
        p.d_first if p.first == k else p.d_second
        for p, k in zip(outer, known, strict=True)
    )
    d_middle = tuple(
        middle.d_first if middle.first == b else middle.d_second for b in bodies
    )
    pins = [
        context.origins[k] + np.asarray(d) for k, d in zip(known, d_known, strict=True)
    ]
    c = context.origins[bodies[0]] + np.asarray(d_middle[0])
    radius = tuple(float(np.hypot(*(c - p))) for p in pins)
    angle0 = tuple(float(np.arctan2((c - p)[1], (c - p)[0])) for p in pins)
    gap, arm = pins[1] - pins[0], c - pins[0]
    side = 1.0 if gap[0] * arm[1] - gap[1] * arm[0] >= 0 else -1.0
    return DenseRRR(
        group, bodies, outer, middle, known, d_known, d_middle, radius, angle0, side
    )
