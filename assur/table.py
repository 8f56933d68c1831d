"""The result of a sweep: a table of columns over driver positions.

A :class:`Table` carries the plan it was computed from, the frozen kinematic and force
states and the column schema; each column is computed from the states when it is first
asked for and kept, read-only.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._evaluate import CHUNKED, SHORT, evaluate, grouped, materialize
from assur._exports import Columns, column_name
from assur._keep import keep
from assur._kinematics import KinematicState
from assur._loads import compile_loads
from assur._quiet import quiet
from assur._text import counted, describe, suggest
from assur._vec import Array, ArrayLike, freeze
from assur.columns import Column, families, schema
from assur.errors import UnknownNameError, UsageError
from assur.kinetostatics import ForceState
from assur.model import Mechanism
from assur.plan import Plan

if TYPE_CHECKING:  # matplotlib is imported only when a picture is drawn
    from matplotlib.axes import Axes

__all__ = ["Columns", "Table"]


@dataclass(frozen=True, eq=False)
class Table(Columns):
    """Results per driver position, by column name.

    ``table["rod.omega"]`` is a read-only array with one value per position;
    ``columns`` lists the names in order and ``schema`` describes each column (its
    owner, quantity and unit).

    Attributes
    ----------
    plan : Plan
        The compiled mechanism the table was computed from.
    schema : tuple of Column
        The table's columns.
    given : ndarray (n, d)
        The driver positions as given (deg, or m for a prismatic driver).
    state : KinematicState
        The links' motions (a property).
    force_state : ForceState or None
        Inertia loads, reactions and balancing loads (a force analysis only; a
        property).
    skipped : ndarray
        Driver positions left out (deg, or m), with ``skip_unassembled``.

    Notes
    -----
    A table is equal only to itself (its hash is its identity); it is not iterable
    (``columns`` names its columns, ``arrays()`` gives them).

    A table of the drivers' columns alone (``columns=["driver.torque"]``, say) keeps
    no links' motions or reactions: ``state`` and ``force_state`` are solved again,
    once, when first asked for, with the same numbers. A picture reads the columns
    it draws: a table made with ``columns=`` serves the pictures whose columns it
    holds (the mechanism's drawing needs its points' ``.x`` and ``.y``).
    """

    plan: Plan
    schema: tuple[Column, ...]
    given: Array
    _kept: KinematicState
    _kept_forces: ForceState | None = None
    skipped: Array = field(default_factory=lambda: np.zeros(0))
    _cache: dict[str, Array] = field(default_factory=dict, repr=False, compare=False)
    _index: dict[str, Column] = field(default_factory=dict, repr=False, compare=False)
    _families: dict[str, tuple[Column, ...]] = field(
        default_factory=dict, repr=False, compare=False
    )
    _states: dict[int, KinematicState] = field(
        default_factory=dict, repr=False, compare=False
    )
    _again: Any = field(default=None, repr=False, compare=False)
    """Solves the states the table did not keep: ``_again.solve()`` returns the
    kinematic and the force state (see :func:`assur.analysis.forces`)."""
    _whole: list[tuple[KinematicState, ForceState | None]] = field(
        default_factory=list, repr=False, compare=False
    )
    _frozen: list[bool] = field(default_factory=list, repr=False, compare=False)
    """Not empty once the states' arrays are read-only."""

    def __post_init__(self) -> None:
        for values in (self.given, self.skipped):
            if values.flags.owndata:  # the table's own: read-only as its columns
                values.flags.writeable = False
        if not self._index:
            self._index.update((c.name, c) for c in self.schema)
        if not self._families:
            self._families.update(families(self.schema))

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Take ``state`` unpickled or deep-copied: its arrays read-only again."""
        super().__setstate__(state)
        if self._frozen:  # states already handed out: read-only as they were
            # a list of its own (a shallow copy shares the original's)
            object.__setattr__(self, "_frozen", [])
            self._freeze()

    @property
    def state(self) -> KinematicState:
        """The links' motions (see :class:`~assur._kinematics.KinematicState`).

        Read-only arrays: the table's columns are computed from them.
        """
        found = self._kept if self._again is None else self._complete()[0]
        if not self._frozen:
            self._freeze()
        return found

    @property
    def force_state(self) -> ForceState | None:
        """Inertia loads, reactions and balancing loads (a force analysis only)."""
        found = self._kept_forces if self._again is None else self._complete()[1]
        if not self._frozen:
            self._freeze()
        return found

    def _freeze(self) -> None:
        """Make the states' arrays read-only, once (when first handed out)."""
        whole = (s for pair in self._whole for s in pair)
        for state in (self._kept, self._kept_forces, *whole):
            if isinstance(state, KinematicState):
                motion = (state.drive, state.speed, state.acceleration, state.motion)
                freeze((*motion, state.slide, state.jerk))
            elif state is not None:
                freeze(state.fields())
        self._frozen.append(True)

    def _complete(self) -> tuple[KinematicState, ForceState | None]:
        """Return the states the table did not keep, solved again on first use."""
        if not self._whole:
            self._whole.append(self._again.solve())
        return self._whole[0]

    @property
    def partial(self) -> bool:
        """Whether the table holds some of its analysis's columns only (``columns=``).

        A picture that reads a column such a table lacks says so (a KeyError).
        """
        if self._again is not None:
            return True
        return len(self.schema) < len(schema(self.plan, self._kept_forces is not None))

    @property
    def mechanism(self) -> Mechanism:
        """The mechanism the table was computed for."""
        return self.plan.mechanism

    @property
    def columns(self) -> tuple[str, ...]:
        """The column names, in order."""
        return tuple(self._index)

    def motion(self, level: int = 2) -> KinematicState:
        """Return the kinematic state solved up to time derivative ``level`` at least.

        A long sweep solves up to accelerations, its jerks when first asked for; a
        short one (up to 2048 positions, with no ``columns=``) solves them in the call.

        Parameters
        ----------
        level : int
            0 positions, 1 velocities, 2 accelerations, 3 jerks.

        Raises
        ------
        UsageError
            For a level that is not 0, 1, 2 or 3.
        """
        if isinstance(level, bool) or level not in (0, 1, 2, 3):
            got = describe(level)
            msg = f"level: expected 0, 1, 2 or 3 (positions to jerks), got {got}"
            raise UsageError(msg)
        if self.state.top >= level:
            return self.state
        found = self._states.get(level)
        if found is None:
            from assur._kinematics import extend

            with quiet():  # the sweep's own troubles were told
                found = extend(self.plan, self.state)
            # read-only before it is kept: another thread may read it at once
            freeze((found.motion, found.slide))
            self._states[level] = found
        return found

    def column(self, name: str) -> Column:
        """Return the description of column ``name`` (owner, quantity, unit).

        Parameters
        ----------
        name : str
            A column's name, e.g. ``"rod.omega"`` or ``"B.Fx"``.

        Returns
        -------
        Column
            Its ``name``, ``owner``, ``quantity`` and ``unit`` (SI in plain text,
            angles in degrees).

        Raises
        ------
        UnknownNameError
            For a name the table has no column of, with the nearest names (a
            KeyError too).
        """
        name = column_name(name)
        try:
            return self._index[name]
        except KeyError:
            pass
        forces = self._kept_forces is not None
        if self.partial and any(c.name == name for c in schema(self.plan, forces)):
            msg = (
                f"no column {name!r}: the table was made with columns= "
                f"({len(self.schema)} columns); expected {name!r} among them, or "
                "no columns="
            )
        elif (
            not forces
            and not compile_loads(self.plan).empty
            and any(c.name == name for c in schema(self.plan, True))
        ):
            msg = f"no column {name!r} in a kinematics table (a force column: use "
            msg += "assur.forces)"
        else:
            msg = f"no column {name!r}{suggest(name, self._index, listing=False)}"
        raise UnknownNameError(msg) from None

    def __getitem__(self, name: str) -> Array:
        try:
            found = self._cache.get(name)
        except TypeError:  # a slice, a list: not a name (told by column())
            found = self.column(name)  # type: ignore[assignment]
        if found is not None:
            return found
        column = self.column(name)
        if len(self) <= SHORT and column.family not in CHUNKED:
            # in a short table a family's columns (every link's instant centre, say)
            # cost little more together than one alone: they are computed at once
            cache = self._cache
            self._compute(
                c for c in self._families[column.family] if c.name not in cache
            )
        else:
            # values that are not finite were named by the sweep (a warning):
            # the columns built from them say nothing more
            with quiet():
                self._store(evaluate(self, column))
        return self._cache[name]

    def __repr__(self) -> str:
        # the dataclass's repr spelt out every state array (20 000 characters)
        name = self.plan.mechanism.name or "mechanism"
        # "1 column", as the notebook's caption counts it
        size = f"{counted(len(self), 'row')} x {counted(len(self.columns), 'column')}"
        return f"<assur.Table: {self._kind} of {name!r}, {size}>"

    def _repr_html_(self) -> str:
        """Return the table as a notebook shows it: some rows and columns (HTML)."""
        from assur._table_display import table_html

        return table_html(self, self._kind)

    @property
    def _kind(self) -> str:
        """What the table holds, "forces" or "kinematics", told without solving."""
        again = self._again  # what force_state would be solved with
        forces = again.with_forces if again else self._kept_forces is not None
        return "forces" if forces else "kinematics"

    def __len__(self) -> int:
        return int(self.given.shape[0])

    def __contains__(self, name: object) -> bool:
        # a list is in no table, where as a dict's key it raised TypeError
        return isinstance(name, str) and name in self._index

    def arrays(self) -> list[Array]:
        """Return every column, in order; those not read yet are computed together.

        One pass serves them all: cheaper than reading each by name.
        """
        cache = self._cache
        if not cache:
            # the table's own grouping by family: no pass over its columns
            with quiet():  # as in __getitem__
                self._store(grouped(self, self._families))
        elif len(cache) < len(self._index):
            self._compute(c for c in self.schema if c.name not in cache)
        return [cache[name] for name in self._index]

    def _compute(self, columns: Iterable[Column]) -> None:
        """Compute ``columns`` (and those computed along with them) into the cache."""
        with quiet():  # as in __getitem__
            self._store(materialize(self, columns))

    def _store(self, found: dict[str, Array]) -> None:
        """Keep the columns ``found``, read-only for good (see :func:`keep`)."""
        keep(found, self._index, self._cache)

    def summary(self) -> dict[str, float]:
        """Return the few numbers joints and motors are sized on, by name.

        For every joint ``J`` (a forces table only): ``J.F.max``, the largest reaction
        over the positions (N), ``J.F.at``, the driver position where it occurs (deg,
        or m for a prismatic driver) and ``J.F.rms``; for the balancing load
        ``driver.torque.max``, ``.min``, ``.mean`` and ``.rms`` (``driver.force.*``
        for a prismatic driver; with several drivers these are the first driver's,
        as the column ``driver.torque`` is, and every driver's own ``J.torque.*``
        is given too: size each motor on its own);
        ``driver.power.mean``, the mean of the balancing loads times the drivers'
        speeds (W), all drivers' together, and ``driver.power.max`` and
        ``driver.power.min``, its largest and smallest values (the most the drivers
        supply, and, negative, the most they take back; with several, each one's
        own too: ``J.power.mean``, ``J.power.max``, ``J.power.min``, J its
        joint); for every sliding pair J also ``J.M.max``, the largest couple of
        its reaction (N m), and ``J.M.at``; the largest shaking force
        ``shaking.F.max`` (N, the size of ``shaking.Fx``, ``shaking.Fy``) and
        moment ``shaking.M.max`` (N m, its size), with ``shaking.F.at`` and
        ``shaking.M.at`` (a couple or shaking load that is zero but for round-off
        is 0, at the first position). With friction also ``J.friction.loss``, the
        mean power lost in joint J (W), ``friction.loss`` in all,
        ``driver.power_ideal.mean`` without friction and ``efficiency``,
        ``driver.power_ideal.mean`` over ``driver.power.mean``: the share of the
        driver's work that reaches the loads (NaN where the driver does no net
        work, or the loads give back work it still supplies).

        A table made with ``columns=`` summarises the joints and drivers among its
        columns only (``columns=["driver.torque"]`` gives the driver's figures,
        but counts a load table's step on the side after it: see below).

        Means and RMS values are time averages, the positions taken as equally
        spaced: at a constant driver speed, plain means over the positions; where
        one driver's speed varies (``omega=`` arrays, the dynamic model's real
        speed), each position weighs ``1 / |speed|``. Several drivers, or a speed
        that reaches zero, turns back or falls below 1/1000 of its fastest: means
        over the positions. A position on a step of a load table over the driver
        counts half with the loads before the step, half after it, and the peaks
        are sought on both sides (the forces before it are solved on the same
        motion: with the dynamic model's speed, whose acceleration steps there
        too, the half before keeps the acceleration after, a first-order error);
        a step between two positions is counted by the positions around it. A
        crank's sweep that ends a whole number of turns on from its first
        position (``0:360:10``) ends on its first pose again, and that pose counts
        once. :func:`assur._summary_notes.notes` says which of these apply.

        Returns
        -------
        dict of str to float
            The values by name, in SI units; the positions (``J.F.at``) in degrees,
            or metres for a prismatic driver.

        Raises
        ------
        UsageError
            For a kinematics table, or a table with no positions.
        """
        from assur.summary import summarize

        return summarize(self)

    def plot(self, angle: ArrayLike | None = None, **kwargs: Any) -> Axes:
        """Draw the mechanism at a driver position (see :func:`assur.plotting.draw`).

        Parameters
        ----------
        angle : float or sequence of float, optional
            Driver position, deg (m for a prismatic driver; one value per driver);
            the nearest row is drawn. Default: the first row.
        **kwargs
            Passed to :func:`assur.plotting.draw` (``forces``, ``ax``, ...).

        Returns
        -------
        matplotlib.axes.Axes
            The axes drawn on.
        """
        from assur.plotting import draw

        return draw(self, angle=angle, **kwargs)
