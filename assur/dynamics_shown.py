"""Which steady state the pictures and the HTML report show.

The mechanism alone when it runs at its nominal speed; otherwise (a light linkage
under heavy loads would stop) with the flywheel that holds its speed fluctuation to
:data:`SHOWN_DELTA`, named in the picture's titles and the report's figures (the
motor torque as both print it is :mod:`assur._dynamics_text`'s).
"""

from __future__ import annotations

from typing import Any

from assur._dynamic_checks import check_dynamic
from assur.dynamics_flywheel import flywheel
from assur.dynamics_model import Dynamics, dynamics
from assur.errors import ModelError
from assur.model import Mechanism

__all__ = ["SHOWN_DELTA", "has_dynamics", "shown"]

SHOWN_DELTA = 0.05
"""Coefficient of speed fluctuation of the flywheel shown when one is needed."""


def has_dynamics(mechanism: Mechanism) -> bool:
    """Whether the mechanism has a dynamic model: one crank, masses."""
    try:
        check_dynamic(mechanism)
    except ModelError:
        return False
    return True


def shown(mechanism: Mechanism, angles: Any) -> Dynamics:
    """Return the steady state to show at ``angles`` (deg).

    Raises
    ------
    AssurError
        When the mechanism has no dynamic model or its crank cannot turn round.
    """
    try:
        return dynamics(mechanism, angles)
    except ModelError:
        if not has_dynamics(mechanism):
            raise
        inertia = flywheel(mechanism, SHOWN_DELTA)
    return dynamics(mechanism, angles, flywheel=inertia)
