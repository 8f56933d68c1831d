"""What a mechanism needs to have a dynamic model: one crank, and some mass to move.

Checked first by every part of the dynamic model (the steady state, the flywheel,
the start-up) and by the pictures that draw it, each naming itself in the message.
"""

from __future__ import annotations

from assur._loads import compile_loads
from assur._text import describe
from assur.errors import ModelError
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["check_dynamic"]


def check_dynamic(mechanism: Mechanism, what: str = "dynamics") -> float:
    """Check that ``mechanism`` has a dynamic model; return its crank's speed (rad/s).

    One revolute driver and at least one link with a mass are needed.

    Raises
    ------
    ModelError
        For a prismatic driver, several drivers, or no mass at all.
    """
    plan = plan_of(mechanism)
    if len(plan.drivers) != 1:
        msg = (
            f"{what}: the mechanism has {len(plan.drivers)} drivers; expected one "
            "driving crank (a revolute driver) for a model reduced to the crank"
        )
        raise ModelError(msg)
    driver = plan.drivers[0]
    if driver.kind != "R":
        msg = (
            f"{what}: driver joint {describe(driver.pair.name)} is prismatic; "
            "expected a revolute driver (a crank): the reduced model turns through "
            "a revolution"
        )
        raise ModelError(msg)
    if not compile_loads(plan).mass.any():
        msg = (
            f"{what}: no link has a mass, so the reduced inertia is zero; expected "
            "'mass', 'center' and 'inertia' on the moving links"
        )
        raise ModelError(msg)
    return float(mechanism.drivers[0].omega)
