"""Solve a mechanism at one driver position for the note (kinematics or forces)."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from assur._drive import positions
from assur._loads import compile_loads
from assur.analysis import Table, forces, kinematics
from assur.errors import SelfLockingError, UsageError
from assur.explain._position import Position, from_table
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
    """Solve ``mech`` where friction locks a group: the kinematics, the reverse pass.

    The reverse pass runs on the kinematics as far as it goes; ``locked`` names the
    first group it solves that friction locks (the records from it on hold sizes
    that did not settle).

    Raises
    ------
    SelfLockingError
        ``error``, when the reverse pass alone finds no group locked.
    """
    pos = from_table(table_at(mech, angle, motion_only=True), reverse_pass=True)
    assert pos.result is not None
    locked = {label for label, mask in pos.result.locked if mask.any()}
    first = next((r.label for r in pos.result.groups if r.label in locked), None)
    if first is None:
        raise error
    return replace(pos, locked=first)
