"""The mechanism reduced to its crank: reduced inertia, its slope, reduced torque.

A one-degree-of-freedom mechanism driven by a crank moves as one body on the crank's
shaft whose inertia ``J(phi)`` varies with the crank angle and on which one torque
``M(phi)`` does the work of all the loads. Both come from sweeps of the core: the
kinematics at unit crank speed give the velocity ratios, the static balancing torque
gives the loads' torque by the principle of virtual work. :func:`reduce` samples them
on a fine periodic grid over one turn and builds the interpolants that the steady
state (:mod:`assur.dynamics_model`) and the start-up in time
(:mod:`assur.dynamics_startup`) use.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from assur._change_limits import across_change_points
from assur._dynamic_checks import check_dynamic
from assur._grid_warnings import noise_message, pass_on, unresolved_message
from assur._vec import Array
from assur._warn import held
from assur.analysis import forces, kinematics
from assur.errors import (
    AssemblyError,
    AssurWarning,
    SingularConfigurationError,
)
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["GRID_RTOL", "Reduced", "reduce", "reduced_at"]

GRID_START = 1024
"""Positions of the first internal grid over one turn; it is doubled until converged."""
GRID_MOST = 65536
"""Most positions of the internal grid over one turn."""
GRID_RTOL = 1e-10
"""Tolerance of the internal grid: successive grids must agree on the loads' work
over the turn to this fraction of the work done in the turn (the integral of
``|M|``), and the interpolants of ``J`` and ``M`` must match the computed values
between grid points to 1e-8 of their largest magnitude."""
BETWEEN_RTOL = 1e-8
"""Tolerance of the interpolants of ``J`` and ``M`` between grid points (relative to
their largest magnitude)."""


def reduced_at(
    mechanism: Mechanism, angles: Any, curvature: bool = False
) -> tuple[Array, ...]:
    r"""Return ``J``, ``dJ/dphi`` and ``M`` at the crank angles ``angles`` (deg).

    With ``curvature``, ``d2J/dphi2`` (kg m^2/rad^2) too, last: from the jerks at
    unit crank speed, in the same sweep.

    Returns
    -------
    angle : ndarray (n,)
        The crank angles, deg, as the sweep read them.
    inertia : ndarray (n,)
        Reduced inertia of the mechanism, kg m^2 (no flywheel).
    slope : ndarray (n,)
        Its derivative with respect to the crank angle, kg m^2/rad.
    torque : ndarray (n,)
        Reduced torque of gravity and the external loads, N m.

    Notes
    -----
    At unit crank speed and zero crank acceleration and jerk, the velocities are the
    velocity ratios and the accelerations and jerks their derivatives with respect
    to the crank angle:

    .. math::

        J = \sum_L m_L |v_{G_L}|^2 + J_{G_L} \omega_L^2, \qquad
        \frac{dJ}{d\varphi} = 2 \sum_L \left(m_L\, v_{G_L} \cdot a_{G_L}
        + J_{G_L} \omega_L \alpha_L\right),

        \frac{d^2J}{d\varphi^2} = 2 \sum_L \left(m_L (a_{G_L} \cdot a_{G_L}
        + v_{G_L} \cdot j_{G_L}) + J_{G_L} (\alpha_L^2 + \omega_L \eta_L)\right),

    with :math:`j` a point's jerk and :math:`\eta` a link's angular jerk.

    The reduced torque is minus the balancing torque at rest (zero speed and
    acceleration): by virtual work, the power of the loads per unit crank speed.
    """
    mech = mechanism
    links = [link for link in mech.links if link.mass]
    wanted = []
    levels = "vaj" if curvature else "va"
    for link in links:
        g = f"{link.name}.G"
        wanted += [f"{g}.{k}{axis}" for k in levels for axis in "xy"]
        wanted += [f"{link.name}.omega", f"{link.name}.alpha"]
        wanted += [f"{link.name}.jerk"] if curvature else []
    motion = kinematics(mech, angles, omega=1.0, epsilon=0.0, columns=wanted)
    inertia = np.zeros(len(motion))
    slope = np.zeros(len(motion))
    curve = np.zeros(len(motion))
    for link in links:
        g, m, jg = f"{link.name}.G", float(link.mass or 0.0), float(link.inertia or 0)
        vx, vy = motion[f"{g}.vx"], motion[f"{g}.vy"]
        ax, ay = motion[f"{g}.ax"], motion[f"{g}.ay"]
        w, alpha = motion[f"{link.name}.omega"], motion[f"{link.name}.alpha"]
        inertia += m * (vx * vx + vy * vy) + jg * w * w
        slope += 2.0 * (m * (vx * ax + vy * ay) + jg * w * alpha)
        if curvature:
            jx, jy = motion[f"{g}.jx"], motion[f"{g}.jy"]
            spin = motion[f"{link.name}.jerk"]
            square = ax * ax + ay * ay + vx * jx + vy * jy
            curve += 2.0 * (m * square + jg * (alpha * alpha + w * spin))
    static = forces(mech, angles, omega=0.0, epsilon=0.0, columns=["driver.torque"])
    torque = -np.asarray(static["driver.torque"])
    found = (np.asarray(motion["angle"]), inertia, slope, torque)
    return (*found, curve) if curvature else found


@dataclass(frozen=True, eq=False)
class Reduced:
    """The reduced model sampled on a fine grid over one turn, with interpolants.

    Attributes
    ----------
    start : float
        Crank angle of the first grid point (the reference pose), rad.
    angle : ndarray (N,)
        The grid, rad: ``start + 2 pi k / N``.
    inertia, slope, torque : ndarray (N,)
        ``J`` (kg m^2), ``dJ/dphi`` (kg m^2/rad), ``M`` (N m) on the grid.
    motor : float
        The constant torque that does the loads' work back over a turn, N m: minus
        the mean of ``M``.
    work : ndarray (N,)
        Work of ``M`` and the motor from the start, J.
    error : float
        Estimated relative error of the work (see :data:`GRID_RTOL`).
    """

    start: float
    angle: Array
    inertia: Array
    slope: Array
    torque: Array
    motor: float
    work: Array
    error: float
    splines: tuple[Any, Any, Any]

    @property
    def step(self) -> float:
        """Spacing of the grid, rad."""
        return 2.0 * math.pi / self.angle.shape[0]

    def inertia_at(self, phi: Any) -> Any:
        """Interpolate ``J`` (kg m^2) at crank angles ``phi`` (rad), any turn."""
        return self.splines[0](phi)

    def slope_at(self, phi: Any) -> Any:
        """Interpolate ``dJ/dphi`` (kg m^2/rad) at crank angles ``phi`` (rad)."""
        return self.splines[0](phi, 1)

    def torque_slope_at(self, phi: Any) -> Any:
        """Interpolate ``dM/dphi`` (N m/rad) at crank angles ``phi`` (rad)."""
        return self.splines[1](phi, 1)

    def torque_at(self, phi: Any) -> Any:
        """Interpolate the reduced torque ``M`` (N m) at crank angles ``phi`` (rad)."""
        return self.splines[1](phi)

    def work_at(self, phi: Any) -> Any:
        """Return the work of ``M`` and the motor from the start to ``phi`` (rad), J.

        Periodic: the work over a whole turn is zero.
        """
        return self.splines[2](phi)

    @property
    def scale(self) -> float:
        """The work that the loads do in a turn, both ways counted (J)."""
        return float(np.sum(np.abs(self.torque)) * self.step)


def reduce(mechanism: Mechanism) -> Reduced:
    """Sample the reduced model on a grid over one turn, fine enough to integrate.

    The grid starts at the reference pose with ``GRID_START`` positions and is
    doubled (up to ``GRID_MOST``) until the work over the turn and the
    interpolants of ``J`` and ``M`` between grid points agree to :data:`GRID_RTOL`
    and ``BETWEEN_RTOL``, or until ``M`` proves to be noise (its typical miss
    between grid points not halved by two doublings in a row: the rounding of a
    huge load, say), which a warning names with the work's estimated error.

    Raises
    ------
    ModelError
        See :func:`check_dynamic`.
    AssemblyError, SingularConfigurationError
        When the crank cannot make a full turn.
    """
    check_dynamic(mechanism)
    plan = plan_of(mechanism)
    # kept with the plan: dynamics, flywheel and startup of one mechanism share it
    found = plan.memo.get("dynamics-reduced")
    if found is None:
        try:
            found = _reduce(mechanism)
        except (AssemblyError, SingularConfigurationError) as err:
            grid = getattr(err, "grid", None)
            where = (
                ""
                if grid is None
                else f" (on the model's grid of {grid} positions a turn)"
            )
            msg = f"dynamics: the crank cannot make a full turn{where}: {err}"
            raise type(err)(msg) from err
        plan.memo["dynamics-reduced"] = found
    model, messages = found
    pass_on(messages, model.angle.shape[0])
    return model  # type: ignore[no-any-return]


def _reduce(mechanism: Mechanism) -> tuple[Reduced, list[str]]:
    """Body of :func:`reduce`: the model and the warnings met on the grid."""
    start = float(plan_of(mechanism).drivers[0].angle0)
    count = GRID_START
    values, caught = _sample(mechanism, start, count, 0, 1)
    model = _model(start, values)
    misses = [math.inf]
    worst = ("J", 0.0, 0.0)
    while count < GRID_MOST:
        middle, more = _sample(mechanism, start, 2 * count, 1, 2)
        values = tuple(
            np.ravel(np.column_stack(p)) for p in zip(values, middle, strict=True)
        )
        finer = _model(start, values)
        done, error, miss, worst = _converged(model, finer, middle)
        misses.append(miss)
        model, count, caught = replace(finer, error=error), 2 * count, caught + more
        if done:
            break
        if _noisy(misses):
            caught.append(noise_message(misses[-1], error))
            break
    else:
        if worst[1] > BETWEEN_RTOL:
            # the finest grid still misses J: the speeds are known only so far (a
            # sharp turn of J near a change point, say), which is said, not hidden
            caught.append(unresolved_message(count, worst))
    return model, caught


def _noisy(misses: list[float]) -> bool:
    """Whether ``M`` is noise on the grid.

    Its typical miss is above the tolerance and was not halved by either of the last
    two refinements: a smooth ``M`` is missed about sixteen times less each time the
    grid is doubled.
    """
    if len(misses) < 3 or not misses[-1] > BETWEEN_RTOL:
        return False
    return misses[-1] > 0.5 * misses[-2] and misses[-2] > 0.5 * misses[-3]


def _sample(
    mech: Mechanism, start: float, count: int, first: int, every: int
) -> tuple[tuple[Array, ...], list[str]]:
    """Return ``J``, ``dJ/dphi``, ``M`` at grid points ``first::every`` of ``count``.

    Also the messages of the warnings the sweeps gave.
    """
    k = np.arange(first, count, every)
    angles = math.degrees(start) + 360.0 * k / count
    with held() as caught:
        try:
            # at a change point the sweep is singular: J, J' and M are its limits
            values = tuple(
                across_change_points(
                    plan_of(mech), angles, lambda a: reduced_at(mech, a)[1:]
                )
            )
        except (AssemblyError, SingularConfigurationError) as err:
            # its counts ("512 of 1024 positions") are of the model's own grid,
            # which the user never asked for: reduce() says what they count
            setattr(err, "grid", k.size)  # noqa: B010 (an attribute of our own)
            raise
    return values, [str(w.message) for w in caught if w.category is AssurWarning]


def _model(start: float, values: Sequence[Array]) -> Reduced:
    """Build the interpolants of the sampled ``J``, ``dJ/dphi`` and ``M``."""
    from scipy.interpolate import CubicHermiteSpline, CubicSpline

    inertia, slope, torque = (np.asarray(v) for v in values)
    n = inertia.shape[0]
    angle = start + 2.0 * math.pi * np.arange(n) / n
    knots = np.append(angle, start + 2.0 * math.pi)
    closed = [np.append(v, v[0]) for v in (inertia, slope, torque)]
    j = CubicHermiteSpline(knots, closed[0], closed[1], extrapolate="periodic")
    m = CubicSpline(knots, closed[2], bc_type="periodic", extrapolate="periodic")
    # a periodic cubic spline integrates over its period as the trapezoid rule does,
    # so the mean taken here leaves a work that is periodic to rounding
    motor = 0.0 - float(np.mean(torque))  # no load: +0, not -0
    if abs(motor) <= 1e-13 * float(np.max(np.abs(torque), initial=0.0)):
        # loads that do no work over a turn (gravity alone): their mean is
        # round-off, shown as -6.9e-18 N m in the table beside a figure of 0
        motor = 0.0
    net = CubicSpline(
        knots, closed[2] + motor, bc_type="periodic", extrapolate="periodic"
    )
    w = net.antiderivative()
    w.extrapolate = "periodic"
    work = w(angle) - w(start)
    shifted = _Shifted(w, float(w(start)))
    return Reduced(
        start, angle, inertia, slope, torque, motor, work, 0.0, (j, m, shifted)
    )


@dataclass(frozen=True)
class _Shifted:
    """A periodic antiderivative less its value at the start."""

    ppoly: Any
    offset: float

    def __call__(self, phi: Any) -> Any:
        return self.ppoly(phi) - self.offset


def _converged(
    coarse: Reduced, fine: Reduced, middle: tuple[Array, ...]
) -> tuple[bool, float, float, tuple[str, float, float]]:
    """Whether the finer grid adds nothing (same work, interpolants that held).

    Also the estimate of the work's relative error, the typical miss of ``M``'s
    interpolant at the new points: the median, relative to ``M``'s largest
    magnitude (a step or a kink of a load misses at a few points only, noise at
    every one), and the worst miss of ``J``'s interpolant: its name, the miss
    relative to ``J``'s largest value, and where (deg). ``M`` is judged by its
    work, which a load table's corners leave converged; ``J`` enters the speed
    pointwise.
    """
    scale = fine.scale
    gap = float(np.max(np.abs(fine.work[::2] - coarse.work)))
    ok = gap <= GRID_RTOL * scale
    mids = fine.angle[1::2]
    misses = []
    worst = ("J", 0.0, 0.0)
    for what, got, want in (
        ("J", coarse.inertia_at(mids), middle[0]),
        ("M", coarse.torque_at(mids), middle[2]),
    ):
        size = float(np.max(np.abs(want)))
        miss = np.abs(got - want)
        ok = ok and float(np.max(miss)) <= BETWEEN_RTOL * size
        misses.append(float(np.median(miss)) / size if size > 0.0 else 0.0)
        i = int(np.argmax(miss))
        relative = float(miss[i]) / size if size > 0.0 else 0.0
        if what == "J":
            worst = (what, relative, math.degrees(float(mids[i])) % 360.0)
    return bool(ok), (gap / scale if scale > 0 else 0.0), misses[1], worst
