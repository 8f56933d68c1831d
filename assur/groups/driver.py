"""The input link: a crank on a revolute pair or a slider on a prismatic pair.

Its motion is prescribed (position, speed and acceleration at every analysed position,
zero jerk); in the force analysis it takes the balancing load.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from assur._vec import Array
from assur.groups._dyad import Wrench, record
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan

__all__ = ["DriverPlan", "balance", "motion"]


@dataclass(frozen=True, slots=True)
class DriverPlan:
    """Input link ``body`` driven through ``pair`` at ``omega`` and ``epsilon``.

    ``angle0`` is the link's angle in the reference pose (rad): the driver position
    of a revolute driver is the link's absolute angle. ``origin`` is the pair's point
    (m). ``reference`` is the driver position of the reference pose (rad or m).
    """

    pair: PairPlan
    body: int
    omega: float
    epsilon: float
    angle0: float
    origin: tuple[float, float]
    reference: float

    @property
    def kind(self) -> str:
        """``"R"`` for a crank, ``"P"`` for a slider."""
        return self.pair.kind

    @property
    def sign(self) -> float:
        """+1 when the input link is the pair's second link, else -1."""
        return 1.0 if self.pair.second == self.body else -1.0


def motion(plan: DriverPlan, position: Array, rate: float | None = None) -> Motion:
    """Return the input link's motion at driver positions ``position`` (rad or m).

    ``rate`` replaces the speed (used for velocity coefficients).
    """
    omega = plan.omega if rate is None else rate
    x0, y0 = plan.origin
    if plan.kind == "R":
        return Motion(
            [position - plan.angle0, omega, plan.epsilon, 0.0],
            [x0, 0.0, 0.0, 0.0],
            [y0, 0.0, 0.0, 0.0],
        )
    assert plan.pair.axis is not None
    ex, ey = plan.pair.axis
    s = position - plan.reference
    eps = plan.epsilon
    return Motion(
        [0.0, 0.0, 0.0, 0.0],
        [x0 + s * ex, omega * ex, eps * ex, 0.0],
        [y0 + s * ey, omega * ey, eps * ey, 0.0],
    )


def balance(
    plan: DriverPlan,
    bodies: list[Motion],
    wrenches: list[Wrench],
    out: dict[str, tuple[Any, Any, Any]],
) -> Any:
    """Return the balancing torque (N m) or force (N) and store the frame's reaction.

    The frame applies the reaction and the balancing load that hold the input link in
    (kinetostatic) equilibrium; the frame itself receives the sum of the input link's
    loads.
    """
    fx, fy, tau = wrenches[plan.body]
    m = bodies[plan.body]
    px, py = m.ox[0], m.oy[0]
    couple = px * fy - py * fx - tau  # about the joint's point, to balance the link
    if plan.kind == "R":
        balancing = couple
        on_link = [-fx, -fy, -tau - couple]
    else:
        ex, ey = plan.pair.axis  # type: ignore[misc]
        balancing = -(fx * ex + fy * ey)
        nx, ny = -fx - balancing * ex, -fy - balancing * ey
        on_link = [nx, ny, px * ny - py * nx + couple]
    ground = wrenches[0]
    for i, value in enumerate((fx, fy, tau)):
        ground[i] = ground[i] + value
    record(plan.pair, bodies, on_link if plan.sign > 0 else [-w for w in on_link], out)
    return balancing
