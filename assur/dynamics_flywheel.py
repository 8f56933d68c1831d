"""The flywheel for a given coefficient of speed fluctuation, exact and classical.

:func:`flywheel` solves the steady state of :mod:`assur.dynamics_steady` for the
inertia that gives the asked ``delta`` exactly (Brent's method). :func:`flywheel_sizing`
sets it beside three classical estimates: Wittenbauer's energy-mass diagram with its
usual tangent slopes ``w^2 (1 +- delta) / 2``, Mertsalov's method (the links' kinetic
energy at the mean speed taken from the work), and the maximum energy swing
``dE_max / (w^2 delta)`` that neglects the mechanism's own inertia.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._dynamic_checks import check_dynamic
from assur._loads import compile_loads
from assur._text import describe
from assur._vec import real
from assur.dynamics_reduced import Reduced, reduce
from assur.dynamics_steady import steady_state
from assur.errors import ConvergenceError, ModelError, UsageError
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = [
    "FlywheelSizing",
    "delta_in_range",
    "flywheel",
    "flywheel_sizing",
    "mertsalov",
    "wittenbauer",
]

DELTA_RTOL = 1e-12
"""Relative tolerance of the flywheel inertia found by Brent's method."""
WIDENINGS = 60
"""Most times the upper end of the search is multiplied by 4."""
SMALLEST_DELTA = 1e-9
"""Smallest coefficient of speed fluctuation asked for: below it the fluctuation of
the speed is near what rounding leaves of it (about 1e-15)."""
DELTA_CHECK = 1e-6
"""Largest relative gap between the delta of the flywheel found and that asked for."""


@dataclass(frozen=True, slots=True)
class FlywheelSizing:
    """A flywheel for a coefficient of speed fluctuation, four ways.

    Attributes
    ----------
    delta : float
        The coefficient of speed fluctuation asked for.
    omega : float
        The nominal crank speed, rad/s.
    exact : float
        The inertia (kg m^2) whose steady state has exactly ``delta``.
    wittenbauer : float
        The classical estimate from the energy-mass diagram: tangents of slopes
        ``w^2 (1 + delta) / 2`` and ``w^2 (1 - delta) / 2``, kg m^2.
    energy_swing : float
        The estimate ``dE_max / (w^2 delta)`` from the largest swing of the work of
        the loads and the motor, the mechanism's own inertia neglected, kg m^2.
    mertsalov : float
        Mertsalov's estimate: the swing of the work less the links' kinetic energy
        at the nominal speed, over ``w^2 delta``, less the crank's own inertia,
        kg m^2 (see :func:`mertsalov`).
    """

    delta: float
    omega: float
    exact: float
    wittenbauer: float
    energy_swing: float
    mertsalov: float

    def differences(self) -> dict[str, float]:
        """Return how far each estimate is from the exact inertia, relative."""
        return {
            "wittenbauer": (self.wittenbauer - self.exact) / self.exact,
            "energy_swing": (self.energy_swing - self.exact) / self.exact,
            "mertsalov": (self.mertsalov - self.exact) / self.exact,
        }


def flywheel(mechanism: Mechanism, delta: float) -> float:
    """Return the flywheel inertia that gives the coefficient of fluctuation ``delta``.

    Parameters
    ----------
    mechanism : Mechanism
        One revolute driver, masses; its ``omega`` is the nominal speed.
    delta : float
        ``(max w - min w) / omega`` of the steady state, from 1e-9
        (``SMALLEST_DELTA``) to below 2 (at 2 the crank stops).

    Returns
    -------
    float
        The inertia added on the crank, kg m^2, to a relative tolerance of 1e-12
        (``DELTA_RTOL``) on the root of ``delta(J) - delta``.

    Raises
    ------
    UsageError
        For ``delta`` out of its range, or when the mechanism alone already runs
        with a smaller fluctuation (no flywheel can raise it).
    ModelError
        See :func:`assur.dynamics <assur.dynamics_model.dynamics>`; also when the
        inertia found does not give ``delta`` (to 1e-6 of it).
    ConvergenceError
        When the search for the inertia does not converge.
    AssemblyError
        When the crank cannot make a whole turn.

    Examples
    --------
    >>> import assur
    >>> mech = assur.catalog.slider_crank()
    >>> inertia = flywheel(mech, 0.02)
    >>> round(assur.dynamics(mech, [0.0], flywheel=inertia).delta, 6)
    0.02
    """
    return _exact(*_prepared(mechanism, delta), delta)


def flywheel_sizing(mechanism: Mechanism, delta: float) -> FlywheelSizing:
    r"""Return the exact flywheel and the three classical estimates beside it.

    Parameters
    ----------
    mechanism : Mechanism
        One revolute driver, masses; its ``omega`` is the nominal speed.
    delta : float
        ``(max w - min w) / omega`` of the steady state, from 1e-9 to below 2, as
        :func:`flywheel` takes it.

    Returns
    -------
    FlywheelSizing
        The inertia :func:`flywheel` returns (``exact``), Wittenbauer's estimate,
        the energy-swing estimate and Mertsalov's, kg m^2 each.

    Raises
    ------
    UsageError, ModelError, ConvergenceError
        As :func:`flywheel` raises them.

    Notes
    -----
    In Wittenbauer's energy-mass diagram the change of kinetic energy
    :math:`W(\varphi)` is plotted against the mechanism's reduced inertia
    :math:`J(\varphi)`; a ray from the pole :math:`(-J_f, -E_0)` to a point of the
    curve has the slope :math:`w^2/2`. The tangents to the curve of slopes
    :math:`w_{max}^2/2` and :math:`w_{min}^2/2` meet the energy axis at
    :math:`b_{max}` and :math:`b_{min}`, and
    :math:`J_f = (b_{max} - b_{min}) / (w_{max}^2/2 - w_{min}^2/2)`. The classical
    construction takes the slopes :math:`w^2 (1 \pm \delta) / 2`, which drops terms
    of order :math:`\delta^2`.

    References
    ----------
    F. Wittenbauer, *Graphische Dynamik*, Springer, Berlin, 1923.
    """
    model, omega = _prepared(mechanism, delta)
    exact = _exact(model, omega, delta)
    w2 = omega * omega
    swing = float(np.max(model.work) - np.min(model.work))
    return FlywheelSizing(
        delta,
        omega,
        exact,
        wittenbauer(model, w2 * (1.0 + delta) / 2.0, w2 * (1.0 - delta) / 2.0),
        swing / (w2 * delta),
        mertsalov(model, omega, delta, crank_inertia(mechanism)),
    )


def mertsalov(model: Reduced, omega: float, delta: float, own: float) -> float:
    r"""Return Mertsalov's flywheel (kg m^2): the links' energy at the mean speed.

    The kinetic energy of the links whose reduced inertia varies is taken at the
    nominal speed, :math:`T_{II} = (J - J_c)\,\omega^2/2`, and the rest of the work
    goes to the parts of constant inertia :math:`J_I`, the flywheel and the crank's
    own ``own`` = :math:`J_c`:
    :math:`J_I = \max(W - T_{II}) - \min(W - T_{II})` over :math:`\omega^2\delta`,
    and the flywheel is :math:`J_I - J_c`. The speed in :math:`T_{II}` is the
    nominal one, not the real: the estimate is off by terms of order
    :math:`\delta` times the links' share of the energy's swing.
    """
    w2 = omega * omega
    # the constant part's own energy shifts every value alike: the swing keeps it out
    kept = model.work - 0.5 * w2 * model.inertia
    return float(np.max(kept) - np.min(kept)) / (w2 * delta) - own


def crank_inertia(mechanism: Mechanism) -> float:
    """Return the driving link's own inertia about its pivot, kg m^2.

    ``J_G + m |OG|^2`` of the crank, constant over the turn: the part of the
    reduced inertia that a flywheel on the crank adds to.
    """
    plan = plan_of(mechanism)
    loads = compile_loads(plan)
    b = plan.drivers[0].body
    # the crank's origin is its pivot (the driver's pair)
    ox, oy = loads.center[b]
    return float(loads.inertia[b] + loads.mass[b] * (ox * ox + oy * oy))


def wittenbauer(model: Reduced, upper: float, lower: float) -> float:
    """Return the flywheel (kg m^2) of the energy-mass diagram's two tangents.

    ``upper`` and ``lower`` are the tangents' slopes, J per kg m^2; the tangent
    points are found on the grid of ``model``.
    """
    top = float(np.max(model.work - upper * model.inertia))
    bottom = float(np.min(model.work - lower * model.inertia))
    return (top - bottom) / (upper - lower)


def _prepared(mechanism: Mechanism, delta: Any) -> tuple[Reduced, float]:
    """Check ``delta`` and the mechanism; return its reduced model and its speed."""
    value = real(delta)
    if value is None:
        msg = (
            f"delta: expected a coefficient of speed fluctuation, got {describe(delta)}"
        )
        raise UsageError(msg)
    if not delta_in_range(value):
        msg = (
            f"delta: {value:g}; expected a coefficient of speed fluctuation, "
            f"(max w - min w) / omega, from {SMALLEST_DELTA:g} to below 2 (where the "
            "crank would stop), such as 0.02"
        )
        raise UsageError(msg)
    omega = check_dynamic(mechanism, "flywheel")
    if not omega * omega > 0.0:  # a speed whose square underflows is zero too
        msg = (
            f"flywheel: drivers[0].omega: {omega:g} rad/s; expected the crank's "
            "nominal speed: the flywheel holds the fluctuation about it"
        )
        raise ModelError(msg)
    return reduce(mechanism), omega


def delta_in_range(delta: float) -> bool:
    """Whether a coefficient of speed fluctuation can be asked for.

    From ``SMALLEST_DELTA`` to below 2, where the smallest speed would be zero.
    """
    return math.isfinite(delta) and SMALLEST_DELTA <= delta < 2.0


def _exact(model: Reduced, omega: float, delta: float) -> float:
    """Solve ``delta(J_f) = delta`` for the flywheel ``J_f`` by Brent's method."""
    from scipy.optimize import brentq

    def excess(inertia: float) -> float:
        try:
            return steady_state(model, omega, inertia).delta - delta
        except ModelError:
            return math.inf  # the crank would stop: far too little inertia

    guess = _guess(model, omega, delta)
    # without a mass in motion somewhere, the search starts just above zero
    low = 0.0 if float(np.min(model.inertia)) > 0 else 1e-9 * guess
    at_low = excess(low)
    if at_low <= 0:
        # the value as given: "delta: 2" was said of 1.9999999, which is below 2
        msg = (
            f"delta: {float(delta)!r}; the mechanism alone runs with delta = "
            f"{at_low + delta:.6g}, so it needs no flywheel; expected a smaller delta"
        )
        raise UsageError(msg)
    high = max(guess, low, 1e-300)
    for _ in range(WIDENINGS):
        if excess(high) < 0:
            break
        low, high = high, 4.0 * high
    else:
        msg = (
            f"flywheel: no inertia up to {high:.3g} kg m^2 brings the fluctuation "
            f"down to delta = {delta:g}"
        )
        raise ModelError(msg)
    try:
        found = float(brentq(excess, low, high, xtol=1e-300, rtol=DELTA_RTOL))
    except RuntimeError as err:  # no convergence within brentq's iterations
        msg = f"flywheel: the inertia for delta = {delta:g} was not found ({err})"
        raise ConvergenceError(msg) from None
    # the promise is the delta asked for: a root rounding has blurred is refused
    got = excess(found) + delta
    if not abs(got - delta) <= DELTA_CHECK * delta:
        msg = (
            f"flywheel: {found:.6g} kg m^2 gives delta = {got:.6g}, not the {delta:g} "
            "asked for (the fluctuation is lost in rounding); expected a larger delta"
        )
        raise ModelError(msg)
    return found


def _guess(model: Reduced, omega: float, delta: float) -> float:
    """Return an inertia that gives at most about ``delta`` (the swing estimate)."""
    swing = float(np.max(model.work) - np.min(model.work))
    spread = float(np.max(model.inertia) - np.min(model.inertia))
    return 2.0 * swing / (omega * omega * delta) + spread / delta
