"""The loads just before a step of a load table, at the positions a sweep lands on one.

A load table that gives a position twice steps there, and at that position the value
after the step holds (the format). A sweep that lands on the step then has only that
value there: a mean over the positions gives the whole position to one side of the
step, which a shaper's cutting force, on for a stroke and off for the return, makes
8 % of the mean power at 1 degree steps. The summary counts such a position half
with the loads after the step and half with the loads before it, the trapezoid rule
across the step; here the reverse pass is solved again at those positions on the same
frozen motion, the tables read just before their steps.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import numpy.typing as npt

from assur import kinetostatics as _kst
from assur._loads import compile_loads
from assur._quiet import quiet
from assur._state import KinematicState, motions
from assur.plan import Plan

__all__ = ["BEFORE", "before_steps"]

BEFORE = 1e-9
"""How far before a step the tables are read, relative to the position (at least 1
deg or 1 m): far above the round-off a reading puts on the step, far below a change
of the motion."""


def before_steps(
    plan: Plan, state: KinematicState, rows: npt.NDArray[np.intp]
) -> _kst.ForceState:
    """Return the forces at ``rows``, positions on load tables' steps, before them.

    ``state`` is a sweep's frozen kinematic state (every body's motion kept). The
    forces are those of the same motion with every load table over the driver read
    just short of the row's position (:func:`assur._loads.step_hits` finds them).
    """
    loads = compile_loads(plan)
    kin = state.rows(rows)
    drive = np.array(kin.drive, dtype=float)
    # at least 1 deg (a crank's positions are in radians) or 1 m
    least = np.radians(1.0) if plan.drivers[0].kind == "R" else 1.0
    size = np.maximum(np.abs(drive[:, 0]), least)
    # the tables read the drive alone: the motion stays the position's own
    drive[:, 0] -= BEFORE * size
    nudged = dataclasses.replace(kin, drive=drive)
    with quiet():
        forces, _ = _kst.solve(plan, loads, motions(plan, kin), nudged)
    return _kst.ForceState(*forces.fields())
