"""Degrees of freedom a chain has at its reference pose, and what a count of none means.

The count :math:`W = 3n - 2p_5 - p_4` cannot see a constraint that repeats another
(a passive constraint: a third parallel crank of a parallelogram), nor a pose where a
chain's joints line up. The rank of the joints' velocity equations at the pose sees
both: a chain the count calls rigid that still moves there has ``q`` constraints
repeated, and its true mobility is :math:`W = 3n - 2p_5 - p_4 + q`.
"""

from __future__ import annotations

import numpy as np

from assur._text import counted
from assur._topology import Topology

__all__ = ["none_text", "pose_freedom", "structure_text"]


def pose_freedom(topo: Topology) -> int:
    """Return the degrees of freedom of the chain ``topo`` at its reference pose.

    Each link's velocity is that of its point at the origin, (u, v), and its angular
    speed w; a pair equates the velocities of its two links' points at the pair (a
    revolute pair: two equations), or the normal to its slide line and the angular
    speeds (a prismatic pair). The freedom is 3n less the rank of these equations.

    Parameters
    ----------
    topo : Topology
        The chain's links and lower pairs (slots replaced by blocks), the frame not
        among the links.

    Returns
    -------
    int
        3n - rank, at least the count W = 3n - 2 p (no pair repeats another, and
        the pose is not singular, where they are equal).
    """
    column = {name: 3 * i for i, name in enumerate(topo.links)}
    if not topo.pairs:
        return 3 * len(column)
    at = np.array([p.at for p in topo.pairs], dtype=float)
    # positions about the pairs' centre, in units of their spread: the rank's
    # tolerance then reads alike for a watch's linkage and a crane's
    at -= at.mean(axis=0)
    at /= max(float(np.abs(at).max()), 1e-300)
    rows = []
    for pair, (x, y) in zip(topo.pairs, at, strict=True):
        if pair.kind == "R":
            directions = [(1.0, 0.0), (0.0, 1.0)]
        else:
            ax, ay = pair.axis or (1.0, 0.0)
            directions = [(-ay, ax)]
        for dx, dy in directions:
            row = np.zeros(3 * len(column))
            for sign, link in ((1.0, pair.links[0]), (-1.0, pair.links[1])):
                if link in column:  # the frame's velocity is zero
                    k = column[link]
                    row[k : k + 3] += sign * np.array([dx, dy, dy * x - dx * y])
            rows.append(row)
        if pair.kind == "P":
            row = np.zeros(3 * len(column))
            for sign, link in ((1.0, pair.links[0]), (-1.0, pair.links[1])):
                if link in column:
                    row[column[link] + 2] += sign
            rows.append(row)
    return 3 * len(column) - int(np.linalg.matrix_rank(np.array(rows)))


def structure_text(w: int) -> str:
    """Return what a chain rigid at its pose is, by its count ``w`` <= 0."""
    if w == 0:
        return (
            "the chain is a statically determinate structure (a truss), not a mechanism"
        )
    redundant = counted(-w, "redundant constraint")
    return (
        f"the chain is a statically indeterminate structure ({redundant}), not a "
        "mechanism"
    )


def none_text(topo: Topology, w: int) -> tuple[str, str] | None:
    """Return why a chain the count gives ``w`` <= 0 still moves; what was expected.

    None when the chain is rigid at its pose too.
    """
    free = pose_freedom(topo)
    if free <= 0:
        return None
    q = free - w
    # within a line a reader takes in (the error's whole message under 400 characters)
    why = (
        f"yet the chain moves at its pose ({counted(free, 'degree', 'degrees')} of "
        f"freedom): {counted(q, 'passive constraint')} (W = 3n - 2p5 - p4 + q, q = "
        f"{q}), such as a third parallel crank, or joints in line"
    )
    expected = (
        "no repeated constraint: remove the redundant link or joint (or move a joint "
        "off the line)"
    )
    return why, expected
