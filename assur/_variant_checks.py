"""The checks of ``compile_plan``, made on many variants' rows at once, with margins.

A variant that fails or nearly fails one (a link too small, a dyad's branch doubtful
or near a dead centre) is marked for :func:`assur._variants.compile_many`, to be
compiled on its own.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from assur._vec import Array, Mask, diameters, wrap
from assur.groups._dyad import (
    APART,
    BRANCH_TOLERANCE,
    DEAD_CENTRE,
    DyadSolver,
    conditioning,
    jacobian,
)
from assur.groups._motion import Motion
from assur.plan import SMALL, Plan

MARGIN = 4.0
"""Factor by which a variant must clear each check of ``compile_plan`` to be compiled
here; one nearer the limit is compiled on its own (and fails there if it must)."""


UNDECIDED = 1e3 * BRANCH_TOLERANCE
"""A variant whose other branch also closes within this is compiled on its own."""


def _small_links(t: Plan, core: dict[str, Array], scale: Array) -> Mask:
    """Mark variants with a link near the smallest size ``compile_plan`` accepts."""
    pins: dict[str, list[Array]] = {}
    for pair in t.topology.pairs:
        if pair.kind == "R":
            for link in pair.links:
                pins.setdefault(link, []).append(core[pair.name])
    near = np.zeros(scale.shape, dtype=bool)
    for link, at in pins.items():
        if link == t.bodies[0] or len(at) < 2:
            continue
        size = diameters(np.stack(at, axis=1))
        near |= (size * MARGIN > 1e-12) & ~(size > MARGIN * SMALL * scale)
    return near


def _branch(
    dyad: DyadSolver, motions: tuple[Motion, ...], scale: Array
) -> tuple[Array, Mask]:
    """Return each variant's branch, as ``compile_dyad`` chooses it, and the doubtful.

    Doubtful: the reference pose does not close (or only loosely) on the branch, the
    other branch closes too, the outer pins nearly meet, or the pose is near a dead
    centre.
    """
    misses = []
    for sign in (1.0, -1.0):
        q = dyad.closure(dyad, list(motions), sign)
        parts = [
            np.abs(wrap(x)) if e.kind == "R" else np.abs(x) / scale
            for x, e in zip(q, dyad.ext, strict=True)
        ]
        misses.append(np.maximum(parts[0], parts[1]))
    plus, minus = misses
    lower = minus < plus
    best, other = np.where(lower, minus, plus), np.where(lower, plus, minus)
    doubtful = ~(best * MARGIN <= BRANCH_TOLERANCE)
    if dyad.gap is not None:  # a kind with two branches
        doubtful |= ~(other > UNDECIDED)
    branch = np.where(lower, -1.0, 1.0)
    chosen = dataclasses.replace(dyad, branch=branch)  # type: ignore[arg-type]
    reference = list(motions)
    chosen.assemble(reference, len(branch))
    with np.errstate(invalid="ignore", divide="ignore"):
        cond = conditioning(chosen, jacobian(chosen, reference))
    doubtful |= ~(cond >= MARGIN * DEAD_CENTRE)
    if dyad.ext[0].kind == "R" and dyad.ext[1].kind == "R":
        (a, b), (da, db) = dyad.known, dyad.d_known
        gap = np.hypot(
            (motions[b].ox[0] + db[0]) - (motions[a].ox[0] + da[0]),
            (motions[b].oy[0] + db[1]) - (motions[a].oy[0] + da[1]),
        )
        doubtful |= ~(gap > MARGIN * APART * scale)
    return branch, doubtful
