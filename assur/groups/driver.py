"""The input link: a crank on a revolute pair or a slider on a prismatic pair.

Its motion is prescribed (position, speed and acceleration at every analysed position,
zero jerk); in the force analysis it takes the balancing load.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assur._vec import Array
from assur.groups._dyad import Wrench, record
from assur.groups._motion import Motion
from assur.groups._pairs import PairPlan

__all__ = ["DriverPlan", "balance", "motion"]


@dataclass(frozen=True, slots=True)
class DriverPlan:
    """Input link ``body`` driven through ``pair`` at speed ``omega``, acceleration ``epsilon``.

    ``angle0`` is the link's angle in the reference pose (rad): the driver position
    of a revolute driver is the link's absolute angle. ``origin`` is the pair's point.
    """

    pair: PairPlan
    body: int
    omega: float
    epsilon: float
    angle0: float
    origin: Array
    reference: float

    @property
    def kind(self) -> str:
        """``"R"`` for a crank, ``"P"`` for a slider."""
        return self.pair.kind


def motion(plan: DriverPlan, position: Array, rate: float | None = None) -> Motion:
    """Return the input link's motion at driver positions ``position`` (rad or m).

    ``rate`` replaces the speed (used for velocity coefficients).
    """
    n = position.shape[0]
    omega = np.full(n, plan.omega if rate is None else rate)
    epsilon = np.full(n, plan.epsilon)
    zero = np.zeros(n)
    zero2 = np.zeros((n, 2))
    if plan.kind == "R":
        origin = np.broadcast_to(plan.origin, (n, 2))
        return Motion([position - plan.angle0, omega, epsilon, zero],
                      [origin, zero2, zero2, zero2])
    assert plan.pair.axis is not None
    e = plan.pair.axis
    s = position - plan.reference
    return Motion([zero, zero, zero, zero],
                  [plan.origin + s[:, None] * e, omega[:, None] * e, epsilon[:, None] * e,
                   zero2])


def balance(plan: DriverPlan, bodies: list[Motion], wrenches: list[Wrench],
            out: dict[str, tuple[Array, Array]]) -> Array:
    """Return the balancing torque (N m) or force (N) and the frame's reaction.

    The frame applies the reaction (stored in ``out``) and the balancing load that hold
    the input link in (kinetostatic) equilibrium; the frame itself receives the sum
    of the input link's loads.
    """
    load = wrenches[plan.body]
    m = bodies[plan.body]
    pivot = m.o[0]
    force = [-load[0], -load[1]]
    couple = -(load[2] - (pivot[:, 0] * load[1] - pivot[:, 1] * load[0]))
    if plan.kind == "R":
        balancing = couple
        wrench_on_link = [force[0], force[1], pivot[:, 0] * force[1] - pivot[:, 1] * force[0]]
    else:
        e = plan.pair.axis
        assert e is not None
        balancing = force[0] * e[0] + force[1] * e[1]
        normal = [force[0] - balancing * e[0], force[1] - balancing * e[1]]
        wrench_on_link = [normal[0], normal[1],
                          pivot[:, 0] * normal[1] - pivot[:, 1] * normal[0] + couple]
    ground = wrenches[0]
    for i in (0, 1, 2):
        ground[i] = ground[i] + load[i]
    on_second = wrench_on_link if plan.pair.second == plan.body else [
        -w for w in wrench_on_link]
    record(plan.pair, bodies, on_second, out)
    return balancing
