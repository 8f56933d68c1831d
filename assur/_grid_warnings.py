"""The warnings of the dynamic model's internal grid (:mod:`assur.dynamics_reduced`).

The troubles its sweeps met (a group near a dead centre), each named once from the
finest grid, and the grid's own: a reduced torque that is noise, or a reduced
inertia that the finest grid does not resolve.
"""

from __future__ import annotations

from assur._text import fitting
from assur._warn import warn
from assur.errors import AssurWarning

__all__ = ["OWN", "TROUBLE_TEXT", "noise_message", "pass_on", "unresolved_message"]

TROUBLE_TEXT = 300
"""Most characters of the troubles the internal grid met, as one warning names them
(the first always whole)."""


OWN = ("the reduced torque is not smooth", "the reduced inertia is not resolved")
"""How the grid's own warnings begin (see :func:`pass_on`)."""


def unresolved_message(count: int, worst: tuple[str, float, float]) -> str:
    """Return the warning of a grid that reached its finest, ``count``, unresolved.

    ``worst`` is the interpolant that misses most: its name, the miss relative to
    its largest value, and where (deg).
    """
    _, miss, at = worst
    return (
        f"the reduced inertia is not resolved on the model's finest grid ({count} "
        f"positions a turn): between grid points its interpolant misses it by up "
        f"to {miss:.2g} of its largest value (near {at:.6g} deg: a sharp turn, as "
        "near a change point?); the steady state's figures can be off, by up to "
        "about that much"
    )


def noise_message(miss: float, error: float) -> str:
    """Return the warning of a reduced torque that refining the grid does not settle."""
    return (
        f"the reduced torque is not smooth: between grid points it misses its "
        f"interpolant by {miss:.2g} of its largest value however fine the grid "
        "(the rounding of a load much larger than the work it does?); the work over "
        f"the turn is known to about {error:.1g} of the work done in the turn"
    )


def pass_on(messages: list[str], count: int) -> None:
    """Warn once of each distinct trouble the internal grid met.

    The grid's own troubles (a reduced model that is noise, or not resolved) are
    warned of apart: they say how far the figures can be trusted.
    """
    own = [m for m in messages if m.startswith(OWN)]
    for message in own:
        warn(f"dynamics: {message}", AssurWarning, stacklevel=3)
    messages = [m for m in messages if not m.startswith(OWN)]
    if not messages:
        return
    # each finer grid meets a trouble again at positions a little closer to its
    # edges: the last (finest) message of each trouble stands for it
    latest: dict[str, str] = {}
    for message in messages:
        latest[message.split(" at driver position")[0]] = message
    troubles = list(latest.values())
    fit = max(1, fitting(troubles, TROUBLE_TEXT))
    shown = "; ".join(troubles[:fit])
    if fit < len(troubles):
        shown += f"; and {len(troubles) - fit} more"
    warn(
        f"dynamics, on its internal grid of up to {count} positions a turn: {shown}",
        AssurWarning,
        stacklevel=3,
    )
