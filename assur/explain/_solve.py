"""Solve a mechanism at one driver position for the note (kinematics or forces)."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from assur._drive import positions
from assur._kinematics import motions
from assur._loads import compile_loads
from assur.analysis import Table, forces, kinematics
from assur.columns import schema
from assur.errors import SelfLockingError, UsageError
from assur.explain._position import Position, from_table
from assur.kinetostatics import solve
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["locked_position", "position", "table_at"]


def table_at(mech: Mechanism, angle: Any, *, motion_only: bool = False) -> Table:
    """Return the forces table at one position (kinematics without masses, loads).

    With ``motion_only``, the kinematics table whatever the loads.

    Raises
    ------
    UsageError
        When ``angle`` is not one driver position (a number per driver).
    """
    plan = plan_of(mech)
    given = positions(plan, angle, "angle")
    if given.shape[0] != 1:
        msg = (
            f"angle: {given.shape[0]} driver positions; expected one (a number per "
            "driver)"
        )
        raise UsageError(msg)
    angles = given if given.shape[1] > 1 else given[:, 0]
    if motion_only or compile_loads(plan).empty:
        return kinematics(mech, angles)
    return forces(mech, angles)


def position(mech: Mechanism, angle: Any) -> Position:
    """Solve ``mech`` at one driver position (deg, or m; one value per driver).

    A mechanism without masses and loads gets its kinematics only.

    Raises
    ------
    AssemblyError
        When the mechanism cannot be assembled there.
    """
    return from_table(table_at(mech, angle))


def locked_position(mech: Mechanism, angle: Any, error: SelfLockingError) -> Position:
    """Solve ``mech`` where friction locks a group, as far as the reverse pass goes.

    The position's forces table holds the kinematics, the inertia loads and the
    reactions of the groups solved before the first one friction locks; the rest
    (that group's reactions and those after it, the balancing loads, the frame's
    shaking load) are NaN: they have no value there. ``locked`` names that group.

    Raises
    ------
    SelfLockingError
        ``error``, when the reverse pass alone finds no group locked.
    """
    kin = table_at(mech, angle, motion_only=True)
    plan = kin.plan
    found, result = solve(
        plan, compile_loads(plan), motions(plan, kin.state), kin.state
    )
    locked = {label for label, mask in result.locked if mask.any()}
    first = next((r.label for r in result.groups if r.label in locked), None)
    if first is None:
        raise error
    # the locked group's reactions, the groups' after it and the drivers'
    labels = [record.label for record in result.groups]
    unknown = {d.pair.name for d in plan.drivers}
    for record in result.groups[labels.index(first) :]:
        unknown.update(record.reactions)
    nan = math.nan
    known = replace(
        found,
        reactions={
            k: (nan, nan, nan) if k in unknown else v
            for k, v in found.reactions.items()
        },
        balancing=tuple(nan for _ in found.balancing),
        shaking=(nan, nan, nan),
        friction={k: nan if k in unknown else v for k, v in found.friction.items()},
    )
    table = Table(plan, schema(plan, True), kin.given, kin.state, known)
    return replace(from_table(table), locked=first)
