"""Solve a mechanism at one driver position for the note (kinematics or forces)."""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._loads import compile_loads
from assur.analysis import Table, forces, kinematics
from assur.explain._position import Position, from_table
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["position", "table_at"]


def table_at(mech: Mechanism, angle: Any) -> Table:
    """Return the forces table at one position (kinematics without masses, loads)."""
    given = np.asarray(angle, dtype=float).reshape(1, -1)
    angles = given if given.shape[1] > 1 else given[:, 0]
    if compile_loads(plan_of(mech)).empty:
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
