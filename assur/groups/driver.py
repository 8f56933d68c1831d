"""The input link: a crank on a revolute pair or a slider on a prismatic pair.

Its motion is prescribed (position, speed and acceleration at every analysed position,
zero jerk); in the force analysis it takes the balancing load.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from assur._vec import Array, add, cross, dot, mul, sub
from assur.groups._dyad import reaction
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan
from assur.groups._protocol import Reaction, Wrench

__all__ = ["Balance", "DriverPlan", "balance", "motion"]


@dataclass(frozen=True, slots=True)
class DriverPlan:
    """Input link ``body`` driven through ``pair``.

    ``angle0`` is the link's angle in the reference pose (rad): the driver position
    of a revolute driver is the link's absolute angle. ``origin`` is the pair's point
    (m, core coordinates). ``reference`` is the driver position of the reference pose
    (rad or m). ``omega`` and ``epsilon`` are the file's speed and acceleration
    (rad/s, rad/s^2; m/s, m/s^2), used when a sweep is not given its own.
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


@dataclass(frozen=True, slots=True)
class Balance:
    """The input link's equilibrium: the frame's reaction and the balancing load.

    ``load`` is the known wrench on the input link (its applied loads and the
    reactions of the groups on it); ``reaction`` the frame's reaction in the driving
    pair; ``balancing`` the torque (N m) or force (N) that holds the link.
    """

    label: str
    body: int
    load: Wrench
    reaction: Reaction
    balancing: Any


def motion(
    plan: DriverPlan, position: Array, omega: Any, epsilon: Any, jerk: Any = 0.0
) -> Motion:
    """Return the input link's motion at driver positions ``position`` (rad or m).

    ``omega``, ``epsilon`` and ``jerk`` are the speed, acceleration and jerk (rad/s,
    rad/s^2, rad/s^3, or m/s... for a slider), a float or one value per position.
    """
    x0, y0 = plan.origin
    if plan.kind == "R":
        return Motion(
            [position - plan.angle0, omega, epsilon, jerk],
            [x0, 0.0, 0.0, 0.0],
            [y0, 0.0, 0.0, 0.0],
        )
    assert plan.pair.axis is not None
    ex, ey = plan.pair.axis
    s = position - plan.reference
    return Motion(
        [0.0, 0.0, 0.0, 0.0],
        [x0 + s * ex, omega * ex, epsilon * ex, jerk * ex],
        [y0 + s * ey, omega * ey, epsilon * ey, jerk * ey],
    )


def balance(plan: DriverPlan, bodies: list[Motion], loads: list[Wrench]) -> Balance:
    """Return the balancing torque (N m) or force (N) and the frame's reaction.

    The frame applies the reaction and the balancing load that hold the input link in
    (kinetostatic) equilibrium; the frame itself receives the sum of the input link's
    loads.
    """
    fx, fy, tau = loads[plan.body]
    m = bodies[plan.body]
    px, py = m.ox[0], m.oy[0]
    couple = sub(cross(px, py, fx, fy), tau)  # about the joint's point
    if plan.kind == "R":
        balancing = couple
        on_link = [mul(-1.0, fx), mul(-1.0, fy), mul(-1.0, add(tau, couple))]
    else:
        assert plan.pair.axis is not None
        ex, ey = plan.pair.axis
        balancing = mul(-1.0, dot((fx, fy), (ex, ey)))
        nx = mul(-1.0, add(fx, mul(balancing, ex)))
        ny = mul(-1.0, add(fy, mul(balancing, ey)))
        on_link = [nx, ny, add(cross(px, py, nx, ny), couple)]
    on_second = on_link if plan.sign > 0 else [mul(-1.0, w) for w in on_link]
    label = f"driver ({plan.pair.name})"
    return Balance(
        label,
        plan.body,
        loads[plan.body],
        reaction(plan.pair, bodies, on_second),
        balancing,
    )
