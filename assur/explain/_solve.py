"""Solve a mechanism at one driver position for the note (kinematics or forces)."""

from __future__ import annotations

from typing import Any

from assur._drive import positions
from assur._loads import compile_loads
from assur.analysis import Table, forces, kinematics
from assur.errors import UsageError
from assur.explain._position import Position, from_table
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["position", "table_at"]


def table_at(mech: Mechanism, angle: Any) -> Table:
    """Return the forces table at one position (kinematics without masses, loads).

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
    if compile_loads(plan).empty:
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
