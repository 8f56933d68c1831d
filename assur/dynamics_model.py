"""The dynamic model of a crank-driven mechanism and its steady motion.

:func:`dynamics` reduces the mechanism to its crank (:mod:`assur.dynamics_reduced`),
finds the steady state under the constant motor torque that balances the loads over a
turn (:mod:`assur.dynamics_steady`) and returns the reduced quantities and the real
motion of the crank at the asked crank angles as a :class:`Dynamics` table, with the
coefficient of speed fluctuation and the other figures of the steady state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from assur._change_limits import across_change_points
from assur._checks import LARGEST
from assur._drive import positions
from assur._dynamic_checks import check_dynamic
from assur._exports import column_name
from assur._text import describe, suggest
from assur._vec import Array, real
from assur.analysis import default_positions
from assur.columns import Column
from assur.dynamics_reduced import Reduced, reduce, reduced_at
from assur.dynamics_steady import Steady, steady_state
from assur.errors import UnknownNameError, UsageError
from assur.model import Mechanism
from assur.plan import plan_of
from assur.table import Columns, Table

__all__ = [
    "COLUMNS",
    "Dynamics",
    "checked_flywheel",
    "dynamics",
    "flywheel_in_range",
    "result",
    "solved",
]

COLUMNS = (
    ("angle", "angle", "angle", "deg"),
    ("reduced.inertia", "reduced", "inertia", "kg m^2"),
    ("reduced.inertia_slope", "reduced", "inertia_slope", "kg m^2/rad"),
    ("reduced.torque", "reduced", "torque", "N m"),
    ("reduced.work", "reduced", "work", "J"),
    ("driver.motor", "driver", "motor", "N m"),
    ("driver.omega", "driver", "omega", "rad/s"),
    ("driver.epsilon", "driver", "epsilon", "rad/s^2"),
    ("driver.jerk", "driver", "jerk", "rad/s^3"),
)
"""The columns of a :class:`Dynamics` table: name, owner, quantity, unit."""
NONE_SKIPPED = np.zeros(0)
NONE_SKIPPED.flags.writeable = False


@dataclass(frozen=True, eq=False)
class Dynamics(Columns):
    """The dynamic model and the steady motion of a crank, per crank angle.

    A table with the columns of :class:`~assur.analysis.Table`:
    ``result["driver.omega"]`` is a read-only array with one value per crank angle,
    ``columns`` lists the names, ``schema`` their units; ``arrays``, ``to_array``,
    ``to_csv``, ``to_dict``, ``to_pandas`` and ``to_parquet`` give them as a sweep's
    table does. The figures of the steady state over the whole turn are attributes
    (and :meth:`summary`). Registered as a :class:`~assur.analysis.Table`:
    ``isinstance(result, assur.Table)`` holds, as the format says ``dynamics``
    returns one.

    Attributes
    ----------
    mechanism : Mechanism
    schema : tuple of Column
    omega : float
        Nominal crank speed, rad/s (the file's): the mean of the largest and the
        smallest speed; its sign is the sense of rotation.
    delta : float
        Coefficient of speed fluctuation, ``(max w - min w) / |omega|``.
    flywheel : float
        Inertia added on the crank, kg m^2 (included in ``reduced.inertia``).
    motor : float
        The constant motor torque of the steady state, N m.
    energy : float
        Kinetic energy at the reference pose, J.
    speed_max, speed_min : float
        Largest and smallest crank speed over a turn, rad/s (magnitudes).
    angle_max, angle_min : float
        Crank angles where they occur, deg, within the turn from the reference pose
        counter-clockwise (the default sweep's, whichever way the crank turns).
    energy_swing : float
        Largest minus smallest ``reduced.work`` over the turn, J.
    grid : int
        Crank positions of the internal grid over a turn.
    tolerance : float
        Estimated relative error of the work integral on that grid.
    """

    mechanism: Mechanism = field(repr=False)
    schema: tuple[Column, ...] = field(repr=False)
    omega: float
    delta: float
    flywheel: float
    motor: float
    energy: float
    speed_max: float
    speed_min: float
    angle_max: float
    angle_min: float
    energy_swing: float
    grid: int
    tolerance: float
    values: dict[str, Array] = field(repr=False)

    @property
    def columns(self) -> tuple[str, ...]:
        """The column names, in order."""
        return tuple(c.name for c in self.schema)

    def column(self, name: str) -> Column:
        """Return the description of column ``name`` (owner, quantity, unit)."""
        name = column_name(name)
        for c in self.schema:
            if c.name == name:
                return c
        msg = f"no column {name!r}{suggest(name, self.columns, listing=False)}"
        raise UnknownNameError(msg)

    def __getitem__(self, name: str) -> Array:
        if name not in self:
            self.column(name)  # raises with a hint
        return self.values[name]

    def __len__(self) -> int:
        return int(self.values["angle"].shape[0])

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and name in self.values

    def summary(self) -> dict[str, float]:
        """Return the figures of the steady state by name (SI units, angles in deg)."""
        names = (
            "omega",
            "delta",
            "flywheel",
            "motor",
            "energy",
            "speed_max",
            "speed_min",
            "angle_max",
            "angle_min",
            "energy_swing",
            "grid",
            "tolerance",
        )
        return {name: float(getattr(self, name)) for name in names}

    @property
    def skipped(self) -> Array:
        """Crank angles left out: none, every angle has its steady motion (deg)."""
        return NONE_SKIPPED

    def _repr_html_(self) -> str:
        """Return the result as a notebook shows it: its figures, some rows (HTML)."""
        from assur._dynamics_text import dynamics_html
        from assur._table_display import table_html

        return dynamics_html(self) + table_html(self, "dynamic model")

    def to_dict(self) -> dict[str, Any]:
        """Return JSON-ready data: name, the steady state's figures, columns, rows."""
        data = super().to_dict()
        return {"name": data["name"], "dynamics": self.summary(), **data}

    def plot(self, **kwargs: Any) -> Any:
        """Draw the dynamic model (see :func:`assur.plotting.plot_dynamics`).

        Parameters
        ----------
        **kwargs
            Passed to :func:`assur.plotting.plot_dynamics`.
        """
        from assur.plotting import plot_dynamics

        return plot_dynamics(self, **kwargs)


Table.register(Dynamics)


def dynamics(
    mechanism: Mechanism,
    angles: ArrayLike | None = None,
    flywheel: float = 0.0,
) -> Dynamics:
    r"""Reduce the mechanism to its crank and find its steady motion.

    Parameters
    ----------
    mechanism : Mechanism
        One revolute driver; at least one link with a mass.
    angles : array_like, optional
        Crank angles (deg) of the table's rows. Default: one turn from the reference
        pose in steps of 1 deg.
    flywheel : float
        Inertia added on the crank, kg m^2.

    Returns
    -------
    Dynamics
        Columns ``angle`` (deg), ``reduced.inertia`` ``J`` (kg m^2, flywheel
        included), ``reduced.inertia_slope`` ``dJ/dphi`` (kg m^2/rad),
        ``reduced.torque`` ``M`` of gravity and the external loads (N m),
        ``reduced.work`` the work of ``M`` and the motor from the reference pose
        (J), ``driver.motor`` (N m), ``driver.omega`` (rad/s), ``driver.epsilon``
        (rad/s^2) and ``driver.jerk`` (rad/s^3) of the steady state.

    Raises
    ------
    ModelError
        For a prismatic driver, several drivers, no mass, a zero ``omega``, a reduced
        inertia that vanishes, or a mean speed too low to carry the crank round.
    UsageError
        For a flywheel that is negative or not a number.
    AssemblyError
        When the crank cannot make a whole turn (the mechanism does not assemble
        at every crank angle), naming the group and the angles it reaches.

    Notes
    -----
    The motor torque is :math:`M_d = -\overline{M}`, the mean over a turn. The
    kinetic energy :math:`\tfrac12 J w^2 = E_0 + W(\varphi)`, with
    :math:`W = \int (M + M_d)\,d\varphi` from the reference pose, gives the speed;
    :math:`E_0` makes the mean of its extremes the file's ``omega``. The crank's
    acceleration is the equation of motion's,

    .. math::

        \varepsilon = \frac{dw}{dt} = \frac{M + M_d - \tfrac12 J' w^2}{J},

    so that the balancing torque of the kinetostatics at that motion is
    :math:`M_d - J_f \varepsilon`. Its derivative in time is the crank's jerk,

    .. math::

        \frac{d\varepsilon}{dt} = w\,\frac{M' - \tfrac12 J'' w^2
        - 2 J' \varepsilon}{J},

    with :math:`J''` from the jerks at unit crank speed and :math:`M'` the slope of
    :math:`M`'s interpolant (a corner of a load table makes it jump, a step
    infinite in theory).
    ``assur.forces(..., jerk=t["driver.jerk"])`` then gives the links' jerks at
    that motion too. The work is integrated on an internal grid of
    ``GRID_START`` to
    ``GRID_MOST`` positions a turn, refined until it
    changes by less than :data:`~assur.dynamics_reduced.GRID_RTOL`; the extremes of
    the speed are found on that grid and its interpolants, whatever ``angles`` is.

    References
    ----------
    I. I. Artobolevsky, *Theory of Mechanisms and Machines*, ch. on the motion of
    machines under given forces (the reduced inertia and the energy equation).

    Examples
    --------
    >>> import assur
    >>> t = dynamics(assur.catalog.slider_crank(), angles=[0.0, 90.0])
    >>> t.columns[:3]
    ('angle', 'reduced.inertia', 'reduced.inertia_slope')
    >>> bool(0.0 < t.delta < 1.0)
    True
    """
    model, steady = solved(mechanism, flywheel)
    if angles is None:
        angles = default_positions(mechanism)
    return result(mechanism, model, steady, angles)


def solved(mechanism: Mechanism, flywheel: float = 0.0) -> tuple[Reduced, Steady]:
    """Return the reduced model and its steady state, whatever the table's angles.

    What :func:`dynamics` finds before its rows: :func:`result` gives the rows at
    any angles from them (a long sweep slice by slice). Raises as :func:`dynamics`.
    """
    flywheel = checked_flywheel(flywheel)
    omega = check_dynamic(mechanism)
    model = reduce(mechanism)
    return model, steady_state(model, omega, flywheel)


def result(mech: Mechanism, model: Reduced, steady: Steady, angles: Any) -> Dynamics:
    """Return the table of ``steady`` at the crank angles ``angles`` (deg)."""
    plan = plan_of(mech)
    angle = positions(plan, angles)[:, 0]
    # at a change point the sweep is singular: J, J' and M are its limits there
    inertia, slope, torque, curve = across_change_points(
        plan, angle, lambda a: reduced_at(mech, a, curvature=True)[1:]
    )
    inertia = inertia + steady.flywheel
    # the work is periodic: a turn taken off in degrees is exact, in radians of a
    # huge angle (1e15 deg, say) it is not
    phi = np.radians(np.remainder(angle, 360.0))
    work = model.work_at(phi)
    square = np.maximum(2.0 * (steady.energy + work) / inertia, 0.0)
    omega = math.copysign(1.0, steady.omega) * np.sqrt(square)
    epsilon = (torque + model.motor - 0.5 * slope * omega * omega) / inertia
    # d(epsilon)/dt = w d(epsilon)/d(phi): J, J' and J'' exact, the slope of M
    # from its interpolant (dw/dphi = epsilon / w)
    rise = model.torque_slope_at(phi)
    jerk = omega * (rise - 0.5 * curve * omega * omega - 2.0 * slope * epsilon)
    jerk /= inertia
    n = angle.shape[0]
    arrays = (angle, inertia, slope, torque, work, np.full(n, model.motor), omega)
    values = dict(zip((c[0] for c in COLUMNS), (*arrays, epsilon, jerk), strict=True))
    for v in values.values():
        v.flags.writeable = False
    schema = tuple(Column(*c, "dynamics", (), 0) for c in COLUMNS)
    return Dynamics(
        mech,
        schema,
        steady.omega,
        steady.delta,
        steady.flywheel,
        model.motor,
        steady.energy,
        steady.speed_max,
        steady.speed_min,
        math.degrees(steady.angle_max),
        math.degrees(steady.angle_min),
        float(np.max(model.work) - np.min(model.work)),
        int(model.angle.shape[0]),
        model.error,
        values,
    )


def checked_flywheel(value: Any) -> float:
    """Return the flywheel inertia, checked: a finite number >= 0 (kg m^2)."""
    number = real(value)
    if number is None:
        msg = f"flywheel: expected an inertia in kg m^2, got {describe(value)}"
        raise UsageError(msg)
    if not flywheel_in_range(number):
        msg = (
            f"flywheel: {number:g} kg m^2; expected an inertia from 0 to {LARGEST:g} "
            "(as the file's numbers)"
        )
        raise UsageError(msg)
    return number


def flywheel_in_range(inertia: float) -> bool:
    """Whether a flywheel inertia (kg m^2) is from 0 to the file's largest number."""
    return math.isfinite(inertia) and 0.0 <= inertia <= LARGEST
