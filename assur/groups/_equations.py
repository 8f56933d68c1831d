"""A group's equilibrium equations with their numbers, as a textbook writes them.

Every link of a group is in equilibrium under its known loads and the reactions of its
pairs: two force sums and one moment equation per link. For a dyad the textbook takes
the moment of each link about the middle joint (which leaves the outer reactions'
tangential parts), then the force sum of the whole group, then that of its first
link; for larger groups each link's equations in turn. The equations are evaluated
from a solved :class:`~assur.groups._protocol.Equilibrium`, so that a note can print
them and a test can check that the solved unknowns satisfy them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._vec import Array
from assur.groups._motion import Motion, point, rotated
from assur.groups._pairs import unit_wrenches

if TYPE_CHECKING:
    from assur.groups._protocol import Equilibrium

__all__ = ["Equations", "equations"]


@dataclass(frozen=True, slots=True)
class Equations:
    """A group's equilibrium equations, written as a textbook writes them.

    ``matrix @ unknowns = rhs`` at every position: ``matrix`` (n, m, m), ``rhs``
    (n, m). Row ``i`` is the equation named ``rows[i]`` (for example "moment of rod
    about C"); column ``j`` is the unknown named ``unknowns[j]`` (for example
    "B.Fx"). ``solution`` (n, m) holds the unknowns the group's step found.
    """

    rows: tuple[str, ...]
    unknowns: tuple[str, ...]
    matrix: Array
    rhs: Array
    solution: Array

    @property
    def residual(self) -> Array:
        """Largest equation residual at each position (N or N m)."""
        left = np.einsum("nij,nj->ni", self.matrix, self.solution)
        return np.max(np.abs(left - self.rhs), axis=-1)


def _link_rows(
    rec: Equilibrium, bodies: list[Motion], b: int, n: int
) -> tuple[Array, Array]:
    """Rows (3, n, m) and right-hand sides (3, n) of link ``b``'s equations.

    Row 0 and 1: forces along x and y; row 2: moments about the link's moment point.
    """
    body = rec.bodies[b]
    m = 2 * len(rec.pairs)
    rows = np.zeros((3, n, m))
    qx, qy = point(bodies[body], rec.moment_points[b], 0)
    for j, pair in enumerate(rec.pairs):
        sign = 1.0 if pair.second == body else -1.0 if pair.first == body else 0.0
        if not sign:
            continue
        for c, (fx, fy, tau) in enumerate(unit_wrenches(pair, bodies)):
            rows[0, :, 2 * j + c] = sign * fx
            rows[1, :, 2 * j + c] = sign * fy
            rows[2, :, 2 * j + c] = sign * (tau - (qx * fy - qy * fx))
    fx, fy, tau = rec.loads[b]
    rhs = np.empty((3, n))
    rhs[0], rhs[1] = -np.broadcast_to(fx, n), -np.broadcast_to(fy, n)
    rhs[2] = -np.broadcast_to(tau - (qx * fy - qy * fx), n)
    return rows, rhs


def _solution(rec: Equilibrium, bodies: list[Motion], n: int) -> Array:
    """Return the solved unknowns (n, m): forces, or normal forces and couples."""
    out = np.empty((n, 2 * len(rec.pairs)))
    for j, pair in enumerate(rec.pairs):
        r = rec.reactions[pair.name]
        if pair.kind == "R":
            out[:, 2 * j], out[:, 2 * j + 1] = r.fx, r.fy
        else:
            nx, ny = rotated(bodies[pair.first], pair.normal)
            out[:, 2 * j] = r.fx * nx + r.fy * ny
            out[:, 2 * j + 1] = r.couple
    return out


def _size(rec: Equilibrium) -> int:
    """Return the number of positions the record holds."""
    values: list[Any] = [*rec.loads[0]]
    for r in rec.reactions.values():
        values += [r.fx, r.fy]
    return max((int(np.size(v)) for v in values), default=1)


def equations(
    rec: Equilibrium, bodies: list[Motion], names: tuple[str, ...]
) -> Equations:
    """Return the equations of the group of ``rec``, numbers substituted.

    Parameters
    ----------
    rec : Equilibrium
    bodies : list of Motion
        The motions the group was solved on.
    names : tuple of str
        Link names by body index.
    """
    n = _size(rec)
    link = [_link_rows(rec, bodies, b, n) for b in range(len(rec.bodies))]
    label = [names[body] for body in rec.bodies]
    where = [_where(rec, b) for b in range(len(rec.bodies))]
    if len(rec.bodies) == 2:
        # moments about the middle joint first, then the group's and the first link's
        # force sums: the order of the lecture notes
        (r0, b0), (r1, b1) = link
        rows = [r0[2], r1[2], r0[0] + r1[0], r0[1] + r1[1], r0[0], r0[1]]
        rhs = [b0[2], b1[2], b0[0] + b1[0], b0[1] + b1[1], b0[0], b0[1]]
        titles = [
            f"moment of {label[0]} about {where[0]}",
            f"moment of {label[1]} about {where[1]}",
            "forces on the group along x",
            "forces on the group along y",
            f"forces on {label[0]} along x",
            f"forces on {label[0]} along y",
        ]
    else:
        rows, rhs, titles = [], [], []
        for (r, b), name, at in zip(link, label, where, strict=True):
            rows += [r[0], r[1], r[2]]
            rhs += [b[0], b[1], b[2]]
            titles += [
                f"forces on {name} along x",
                f"forces on {name} along y",
                f"moment of {name} about {at}",
            ]
    return Equations(
        tuple(titles),
        rec.unknowns,
        np.stack(rows, axis=1),
        np.stack(rhs, axis=1),
        _solution(rec, bodies, n),
    )


def _where(rec: Equilibrium, b: int) -> str:
    """Name the point a link's moment equation is taken about."""
    body = rec.bodies[b]
    offset = rec.moment_points[b]
    for pair in rec.pairs:
        if (pair.second == body and pair.d_second == offset) or (
            pair.first == body and pair.kind == "R" and pair.d_first == offset
        ):
            return pair.name.split("~")[0]
    return "its origin" if offset == (0.0, 0.0) else f"the point {offset}"
