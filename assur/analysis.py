"""Sweeps over driver positions: the library's main entry points.

:func:`kinematics` and :func:`forces` check their arguments, run the forward and
reverse passes over the whole sweep in slices (so temporaries stay in cache), report
the positions where a group failed, and return a :class:`~assur.table.Table` whose
columns are the mechanism file contract's.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from assur import _state
from assur._drive import _at, _no_driver, driver_rates, positions, to_si
from assur._loads import compile_loads
from assur._passes import (
    Again,
    _branch_of,
    _kept_rows,
    _passes,
    _solve_slice,
    _states,
    _up_front,
)
from assur._progress import Callback, progress
from assur._text import describe
from assur._troubles import NOTICES, _change_points, _report
from assur._vec import Array, is_flag
from assur._warn import held
from assur.columns import balancing_columns, selection
from assur.errors import ModelError, UsageError
from assur.model import Mechanism, mechanism_of
from assur.plan import SIZELESS, drawn_size, plan_of
from assur.table import Columns, Table

__all__ = ["Columns", "Table", "default_positions", "forces", "kinematics"]


def default_positions(mech: Mechanism, step: float = 1.0) -> Array:
    """Return one full turn from the reference pose in steps of ``step`` degrees.

    For a prismatic driver: 101 positions over a round stroke (1, 2 or 5 times a
    power of ten, m), the largest within +-20 % of the mechanism's size (that of
    its joints, or of every point the file places where the joints all meet at
    one: a ram alone). With several drivers, each its own, as many as the shortest
    has (a crank beside a prismatic driver turns 100 steps of its turn).
    """
    plan = plan_of(mech)
    if not plan.drivers:
        raise _no_driver(plan)
    size = plan.scale
    if size <= SIZELESS:
        # one place for every joint: a stroke of 4e-13 m stood for "no size"
        size = max(size, drawn_size(mechanism_of(mech)))
    starts = []
    for d in plan.drivers:
        if d.kind == "R":
            starts.append(math.degrees(d.angle0) + np.arange(0.0, 360.0, step))
        else:
            starts.append(np.linspace(-1.0, 1.0, 101) * round_stroke(0.2 * size))
    count = min(len(s) for s in starts)
    out = np.stack([s[:count] for s in starts], axis=-1)
    return out[:, 0] if out.shape[1] == 1 else out


def reference_position(mech: Mechanism) -> Array:
    """Return the driver positions of the reference pose, as :func:`default_positions`.

    A crank's angle in the file (deg); 0 m for a prismatic driver, whose position
    is its displacement from that pose. One value (0-d) for one driver, one per
    driver (drivers,) for several.

    Examples
    --------
    >>> from assur import catalog
    >>> round(float(reference_position(catalog.four_bar())), 9)
    60.0
    """
    plan = plan_of(mech)
    if not plan.drivers:
        raise _no_driver(plan)
    values = [math.degrees(d.angle0) if d.kind == "R" else 0.0 for d in plan.drivers]
    return np.array(values[0] if len(values) == 1 else values)


def round_stroke(bound: float) -> float:
    """Return the largest of 1, 2 or 5 times a power of ten not above ``bound`` (m).

    The default positions of a prismatic driver then read as typed ones: +-0.02 m
    in steps of 0.0004 m, not +-0.0223607 m in steps of 0.000447214 m.

    Examples
    --------
    >>> round_stroke(0.0223607), round_stroke(0.2), round_stroke(0.0499)
    (0.02, 0.2, 0.02)
    """
    power = 10.0 ** math.floor(math.log10(bound))
    # log10 rounds: 0.3 / 0.1 is 2.9999999999999996, which is still 2 of 0.1
    first = bound / power * (1.0 + 1e-12)
    factor = max((f for f in (1.0, 2.0, 5.0, 10.0) if f <= first), default=1.0)
    return float(f"{factor * power:.1g}")


def kinematics(
    mechanism: Mechanism,
    angles: ArrayLike,
    omega: ArrayLike | None = None,
    epsilon: ArrayLike | None = None,
    *,
    skip_unassembled: bool = False,
    columns: Sequence[str] | None = None,
    progress: bool | Callback = False,
    jerk: ArrayLike | None = None,
) -> Table:
    """Positions, velocities, accelerations and jerks over driver positions.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism, as :func:`assur.load <assur.io.load>` or
        :mod:`assur.catalog` give it.
    angles : array_like
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers): there a flat sequence of one value per driver is one
        position (``[90, 100]`` of two cranks), not two.
    omega, epsilon : float or array_like, optional
        The driver's speed (rad/s; m/s for a prismatic driver) and acceleration
        (rad/s^2; m/s^2) at every position, replacing the file's constants: a number
        (every driver's), or one value per position (shape (n,); (n, drivers) with
        several drivers).
    skip_unassembled : bool
        Leave out the positions where a group cannot be assembled, stands at a dead
        centre or a change point, or is locked by friction, or that the mechanism
        cannot reach from its reference pose (one driver: see :mod:`assur._reach`),
        instead of raising; ``Table.skipped`` lists them.
    columns : sequence of str, optional
        Compute only these columns (and ``angle``). A table of the drivers' columns
        alone (``["driver.torque"]``, say) keeps none of the links' motions or
        reactions; they are solved again if asked for (see :class:`Table`).
        Positions alone (``["B.x", "rocker.angle"]``) solve no velocities: a dead
        centre is then a warning, not an error. Every group is still assembled,
        since the mechanism must reach the position.
    progress : bool or callable, optional
        Show a progress bar on standard error (True), or call ``progress(done,
        total)`` as slices of positions are solved.
    jerk : float or array_like, optional
        The driver's jerk (rad/s^3; m/s^3), as ``omega``: zero by default, a driver
        whose acceleration holds (the file's constants). A driver whose ``epsilon``
        changes along the sweep has a jerk of its own, ``d epsilon / dt``, which
        every jerk column carries (the steady motion's ``driver.jerk`` of
        :func:`assur.dynamics <assur.dynamics_model.dynamics>`).

    Returns
    -------
    Table

    Raises
    ------
    AssemblyError, SingularConfigurationError
        At the first driver position where a group cannot close or is at a dead
        centre, naming the group; an AssemblyError too at a position the mechanism
        cannot reach from its reference pose (another circuit, or past a dead
        centre), naming the group that stops it and the positions it reaches.
    UsageError
        When an argument cannot be used (shape, values, unknown column).

    Examples
    --------
    >>> from assur import catalog
    >>> t = kinematics(catalog.four_bar(), [0.0, 90.0])
    >>> t["crank.omega"].tolist()
    [10.0, 10.0]
    """
    speeds = (omega, epsilon, jerk)
    return _sweep(mechanism, angles, False, skip_unassembled, speeds, columns, progress)


def forces(
    mechanism: Mechanism,
    angles: ArrayLike,
    omega: ArrayLike | None = None,
    epsilon: ArrayLike | None = None,
    *,
    skip_unassembled: bool = False,
    columns: Sequence[str] | None = None,
    progress: bool | Callback = False,
    jerk: ArrayLike | None = None,
) -> Table:
    """Kinematics plus inertia loads, joint reactions and balancing loads.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism, as :func:`assur.load <assur.io.load>` or
        :mod:`assur.catalog` give it.
        With masses (and centres of mass and inertias) or loads.
    angles : array_like
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers) (a flat sequence of one value per driver is one
        position).
    omega, epsilon : float or array_like, optional
        The drivers' speeds (rad/s; m/s) and accelerations (rad/s^2; m/s^2) at every
        position, replacing the file's constants, as in :func:`kinematics`.
    skip_unassembled : bool
        Leave out the positions where a group cannot be assembled, stands at a dead
        centre or a change point, or is locked by friction, or that the mechanism
        cannot reach from its reference pose, instead of raising.
    columns : sequence of str, optional
        Compute only these columns (and ``angle``), as in :func:`kinematics`.
    progress : bool or callable, optional
        A progress bar on standard error, or a callback ``progress(done, total)``.
    jerk : float or array_like, optional
        The drivers' jerks (rad/s^3; m/s^3), as in :func:`kinematics`: the jerk
        columns' alone (no force depends on it).

    Returns
    -------
    Table
        Every kinematics column, then inertia loads (N, N m), joint reactions (N, N
        m), the balancing loads (N m, or N for a prismatic driver) and their checks
        by virtual power.

    Raises
    ------
    ModelError
        When no link has a mass and no load is applied, when a link with a mass lacks
        its centre of mass or inertia, or a load table over a slide or a prismatic
        driver does not cover the sweep (one over a crank is periodic).
    AssemblyError, SingularConfigurationError, SelfLockingError
        At the first driver position where a group cannot close, is at a dead centre
        or is locked by friction, naming the group; an AssemblyError too at a
        position the mechanism cannot reach from its reference pose.
    UsageError
        When an argument cannot be used (shape, values, unknown column).

    Examples
    --------
    >>> from assur import catalog
    >>> t = forces(catalog.slider_crank(), [45.0])
    >>> bool(abs(t["driver.torque"][0] - t["driver.torque_check"][0]) < 1e-9)
    True
    """
    plan = plan_of(mechanism)
    if not plan.drivers:  # what is wrong first: nothing moves
        raise _no_driver(plan)
    if compile_loads(plan).empty:
        msg = (
            "forces: no link has a mass and no load is applied; expected 'mass', "
            "'center' and 'inertia' on the links or [[loads]] for a force analysis"
        )
        raise ModelError(msg)
    speeds = (omega, epsilon, jerk)
    return _sweep(mechanism, angles, True, skip_unassembled, speeds, columns, progress)


def _sweep(
    mech: Mechanism,
    angles: Any,
    with_forces: bool,
    skip: bool,
    speeds: tuple[Any, Any, Any],
    names: Sequence[str] | None,
    show: bool | Callback = False,
) -> Table:
    plan = plan_of(mech)
    if not is_flag(skip):
        # a speed given third, say, would else switch skipping on without a word
        msg = f"skip_unassembled: expected True or False, got {describe(skip)}"
        raise UsageError(msg)
    given = positions(plan, angles)
    drive = to_si(plan, given)
    n = drive.shape[0]
    omega, epsilon, jerk = speeds
    rates = driver_rates(plan, omega, epsilon, n, jerk)
    chosen = selection(plan, with_forces, names)
    top = chosen.top if names is not None else min(chosen.top, _up_front(n))
    # the drivers' columns alone need none of the links' motions or reactions kept
    keep = names is None or any(c.family not in DRIVERS_ONLY for c in chosen.columns)
    troubles: list[Any] = []
    passed = _change_points(plan, given, drive)
    what = "forces" if chosen.forces else "kinematics"
    with progress(what, n, show, unit=" positions") as bar:
        tree = _passes(
            plan, given, drive, rates, top, chosen.forces, keep, passed, troubles, bar
        )
    state, force_state = _states(drive, rates, top, tree)
    if top == 0:
        # positions alone (columns=): a dead centre's velocity equations are not
        # solved, and its pose is sound: told, as near one, not a failure
        troubles = [
            (replace(t, what="near") if t.what == "singular" else t, start)
            for t, start in troubles
        ]
    ok = _report(plan, given, troubles, skip)
    again = None
    if not keep:
        again = Again(plan, given, drive, rates, chosen.forces, passed, ok)
    skipped = given[:0] if ok is None else given[~ok]
    state, force_state = _kept_rows(state, force_state, ok)
    if ok is not None:
        given = given[ok]
    return Table(
        plan,
        chosen.columns,
        given,
        state,
        force_state,
        skipped[:, 0] if skipped.shape[1] == 1 else skipped,
        _index=chosen.index,
        _families=chosen.families,
        _again=again,
    )


DRIVERS_ONLY = frozenset({"given", "balancing", "ideal"})
"""Families of columns read from the driver positions and balancing loads alone."""


def report_troubles(
    mech: Mechanism, given: Array, with_forces: bool, skip: bool
) -> None:
    """Raise the error of a sweep as :func:`kinematics` or :func:`forces` raise it.

    ``given`` (n, drivers) holds valid driver positions as given (deg or m), the
    drivers' rates are the file's. Only the positions are solved (with
    ``with_forces``, the balancing loads too: friction may lock), in the slices
    of a sweep, keeping no more than each failure's mask (a byte a position): the
    message names the whole sweep's counts and ranges in the memory of one slice.
    Returns when nothing fails (or ``skip`` leaves the failures out); warns of
    nothing.
    """
    plan = plan_of(mech)
    n = given.shape[0]
    chosen = selection(
        plan, with_forces, balancing_columns(plan) if with_forces else ["angle"]
    )
    rates = driver_rates(plan, None, None, n)
    loads = compile_loads(plan) if chosen.forces else None
    chunk = _state.CHUNK
    starts = range(0, n, chunk)
    troubles: list[Any] = []
    with held():  # the sweep's own warnings, told by it
        # a sweep passes a change point where one of its slices does (each slice's
        # range takes in the reference pose); each position's branch is its own
        passed = any(
            _change_points(
                plan, given[a : a + chunk], to_si(plan, given[a : a + chunk])
            )
            for a in starts
        )
        branch_of = _branch_of(plan) if passed else None
        for a in starts:
            rows = slice(a, min(a + chunk, n))
            drive = to_si(plan, given[rows])
            part = _at(rates, rows)
            _, _, found = _solve_slice(plan, drive, part, chosen.top, loads, branch_of)
            troubles += [(t, a) for t in found if t.what not in NOTICES]
    _report(plan, given, troubles, skip)
