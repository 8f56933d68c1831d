"""Sweeps over driver positions: the library's main entry points.

:func:`kinematics` and :func:`forces` check their arguments, run the forward and
reverse passes over the whole sweep in slices (so temporaries stay in cache), report
the positions where a group failed, and return a :class:`~assur.table.Table` whose
columns are the mechanism file contract's.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from assur import _kinematics as _kin
from assur import kinetostatics as _kst
from assur._branches import branches
from assur._evaluate import SHORT
from assur._loads import compile_loads
from assur._paths import path_changes
from assur._progress import Callback, progress
from assur._text import counted, describe, position_text
from assur._vec import Array, Mask, gather, is_array
from assur.columns import balancing_columns, selection
from assur.errors import (
    AssemblyError,
    AssurWarning,
    ModelError,
    SelfLockingError,
    SingularConfigurationError,
    UsageError,
)
from assur.model import LARGEST, Mechanism
from assur.plan import Plan, plan_of
from assur.table import Columns, Table

__all__ = ["Columns", "Table", "default_positions", "forces", "kinematics"]

CHUNK = 8192
"""Driver positions solved at once; long sweeps run in slices of this size."""

EXACT_DEGREES = 1e4
"""Crank angles (deg) below which turning them into radians as they are loses no
more than reducing them to a turn first would."""

Rates = tuple[tuple[Any, ...], tuple[Any, ...]]
"""Each driver's speed and acceleration: a float, or an array with one value per
position."""


def default_positions(mech: Mechanism, step: float = 1.0) -> Array:
    """Return one full turn from the reference pose in steps of ``step`` degrees.

    For a prismatic driver: 101 positions over +-20 % of the mechanism's size.
    """
    plan = plan_of(mech)
    if not plan.drivers:
        raise _no_driver(plan)
    starts = []
    for d in plan.drivers:
        if d.kind == "R":
            starts.append(math.degrees(d.angle0) + np.arange(0.0, 360.0, step))
        else:
            starts.append(np.linspace(-0.2, 0.2, 101) * plan.scale)
    count = min(len(s) for s in starts)
    out = np.stack([s[:count] for s in starts], axis=-1)
    return out[:, 0] if out.shape[1] == 1 else out


def kinematics(
    mechanism: Mechanism,
    angles: Sequence[float] | Array,
    omega: Any = None,
    epsilon: Any = None,
    *,
    skip_unassembled: bool = False,
    columns: Sequence[str] | None = None,
    progress: bool | Callback = False,
) -> Table:
    """Positions, velocities, accelerations and jerks over driver positions.

    Parameters
    ----------
    mechanism : Mechanism
    angles : array_like
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers).
    omega, epsilon : float or array_like, optional
        The driver's speed (rad/s; m/s for a prismatic driver) and acceleration
        (rad/s^2; m/s^2) at every position, replacing the file's constants: a number
        (every driver's), or one value per position (shape (n,); (n, drivers) with
        several drivers).
    skip_unassembled : bool
        Leave out the positions where a group cannot be assembled, stands at a dead
        centre or is locked by friction, instead of raising; ``Table.skipped`` lists
        them.
    columns : sequence of str, optional
        Compute only these columns (and ``angle``). A table of the drivers' columns
        alone (``["driver.torque"]``, say) keeps none of the links' motions or
        reactions; they are solved again if asked for (see :class:`Table`).
    progress : bool or callable, optional
        Show a progress bar on standard error (True), or call ``progress(done,
        total)`` as slices of positions are solved.

    Returns
    -------
    Table

    Raises
    ------
    AssemblyError, SingularConfigurationError
        At the first driver position where a group cannot close or is at a dead
        centre, naming the group.
    UsageError
        When an argument cannot be used (shape, values, unknown column).

    Examples
    --------
    >>> from assur import catalog
    >>> t = kinematics(catalog.four_bar(), [0.0, 90.0])
    >>> t["crank.omega"].tolist()
    [10.0, 10.0]
    """
    return _sweep(
        mechanism, angles, False, skip_unassembled, omega, epsilon, columns, progress
    )


def forces(
    mechanism: Mechanism,
    angles: Sequence[float] | Array,
    omega: Any = None,
    epsilon: Any = None,
    *,
    skip_unassembled: bool = False,
    columns: Sequence[str] | None = None,
    progress: bool | Callback = False,
) -> Table:
    """Kinematics plus inertia loads, joint reactions and balancing loads.

    Parameters
    ----------
    mechanism : Mechanism
        With masses (and centres of mass and inertias) or loads.
    angles : array_like
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers).
    omega, epsilon : float or array_like, optional
        The drivers' speeds (rad/s; m/s) and accelerations (rad/s^2; m/s^2) at every
        position, replacing the file's constants, as in :func:`kinematics`.
    skip_unassembled : bool
        Leave out the positions where a group cannot be assembled, stands at a dead
        centre or is locked by friction, instead of raising.
    columns : sequence of str, optional
        Compute only these columns (and ``angle``), as in :func:`kinematics`.
    progress : bool or callable, optional
        A progress bar on standard error, or a callback ``progress(done, total)``.

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
        its centre of mass or inertia, or a load table does not cover the sweep.
    AssemblyError, SingularConfigurationError, SelfLockingError
        At the first driver position where a group cannot close, is at a dead centre
        or is locked by friction, naming the group.
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
    if compile_loads(plan).empty:
        msg = (
            "forces: no link has a mass and no load is applied; expected 'mass', "
            "'center' and 'inertia' on the links or [[loads]] for a force analysis"
        )
        raise ModelError(msg)
    return _sweep(
        mechanism, angles, True, skip_unassembled, omega, epsilon, columns, progress
    )


def _sweep(
    mech: Mechanism,
    angles: Any,
    with_forces: bool,
    skip: bool,
    omega: Any,
    epsilon: Any,
    names: Sequence[str] | None,
    show: bool | Callback = False,
) -> Table:
    plan = plan_of(mech)
    if not (
        isinstance(skip, bool | np.bool_) or (type(skip) is int and skip in (0, 1))
    ):
        # a speed given third, say, would else switch skipping on without a word
        msg = f"skip_unassembled: expected True or False, got {skip!r}"
        raise UsageError(msg)
    given = positions(plan, angles)
    drive = to_si(plan, given)
    n = drive.shape[0]
    rates = driver_rates(plan, omega, epsilon, n)
    chosen = selection(plan, with_forces, names)
    top = chosen.top if names is not None else min(chosen.top, _up_front(n))
    # the drivers' columns alone need none of the links' motions or reactions kept
    keep = names is None or any(c.family not in DRIVERS_ONLY for c in chosen.columns)
    troubles: list[Any] = []
    passed = _change_points(plan, given, drive)
    what = "forces" if chosen.forces else "kinematics"
    with progress(what, n, show) as bar:
        tree = _passes(
            plan, given, drive, rates, top, chosen.forces, keep, passed, troubles, bar
        )
    state, force_state = _states(drive, rates, top, tree)
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


def _passes(
    plan: Plan,
    given: Array,
    drive: Array,
    rates: Rates,
    top: int,
    with_forces: bool,
    keep: bool,
    passed: bool,
    troubles: list[Any],
    bar: Any,
) -> Any:
    """Solve the sweep slice by slice; return its states as one tree of leaves.

    The tree is ``(motion, slide, fields)`` (fields None for kinematics alone);
    without ``keep`` only the drivers' balancing loads are kept, the other fields
    empty. Troubles met are added to ``troubles`` with the start of their slice.
    """
    n = drive.shape[0]
    loads = compile_loads(plan) if with_forces else None
    branch_of = _branch_of(plan) if passed else None

    def pieces() -> Iterator[tuple[slice, Any]]:
        for start in range(0, max(n, 1), CHUNK):  # an empty sweep has one slice
            rows = slice(start, min(start + CHUNK, n))
            kin, fields, found = _solve_slice(
                plan, drive[rows], _at(rates, rows), top, loads, branch_of
            )
            troubles.extend((t, start) for t in found)
            _unexplained(plan, given[rows], (kin.motion, kin.slide, fields), found, top)
            bar.advance(rows.stop - rows.start)
            if keep:
                yield rows, (kin.motion, kin.slide, fields)
            else:
                kept: Any = None
                if fields is not None:
                    kept = ((), {}, fields[2], (), {}, fields[5])
                yield rows, ((), {}, kept)

    return gather(n, pieces())


def _solve_slice(
    plan: Plan,
    drive: Array,
    rates: Rates,
    top: int,
    loads: Any,
    branch_of: _kin.BranchOf | None,
) -> tuple[_kin.KinematicState, Any, list[Any]]:
    """Solve one slice of a sweep; return its state, force fields and troubles."""
    # failed or dead-centre positions carry NaN through; _report names them
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        bodies, found = _kin.solve(plan, drive, *rates, top=top, branch_of=branch_of)
        kin = _kin.state_of(plan, bodies, drive, rates, top)
        fields = None
        if loads is not None:
            forces, result = _kst.solve(plan, loads, bodies, kin)
            fields = forces.fields()
            found += [
                _kin.Trouble(label, "locked", mask) for label, mask in result.locked
            ]
    return kin, fields, found


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
    starts = range(0, n, CHUNK)
    troubles: list[Any] = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", AssurWarning)
        # a sweep passes a change point where one of its slices does (each slice's
        # range takes in the reference pose); each position's branch is its own
        passed = any(
            _change_points(
                plan, given[a : a + CHUNK], to_si(plan, given[a : a + CHUNK])
            )
            for a in starts
        )
        branch_of = _branch_of(plan) if passed else None
        for a in starts:
            rows = slice(a, min(a + CHUNK, n))
            drive = to_si(plan, given[rows])
            part = _at(rates, rows)
            _, _, found = _solve_slice(plan, drive, part, chosen.top, loads, branch_of)
            troubles += [(t, a) for t in found if t.what not in NOTICES]
    _report(plan, given, troubles, skip)


def _states(
    drive: Array, rates: Rates, top: int, tree: Any
) -> tuple[_kin.KinematicState, _kst.ForceState | None]:
    """Return the kinematic and force states of a sweep's tree (see :func:`_passes`)."""
    motion, slide, fields = tree
    state = _kin.KinematicState(drive, rates[0], rates[1], motion, slide, top)
    return state, None if fields is None else _kst.ForceState(*fields)


def _kept_rows(
    state: _kin.KinematicState, forces: _kst.ForceState | None, ok: Mask | None
) -> tuple[_kin.KinematicState, _kst.ForceState | None]:
    """Return the states at the positions kept (``ok``; None keeps every one)."""
    if ok is None:
        return state, forces
    return state.rows(ok), None if forces is None else forces.rows(ok)


def _up_front(n: int) -> int:
    """Return the highest derivative a sweep of ``n`` positions solves in the call.

    A long sweep's jerks are solved when a jerk column is first read (unless asked
    for by name); a short one's with the rest, as solving them later linearises
    every group again (at 360 positions 0.09 ms, the forward pass's jerks 0.02 ms).
    """
    return 3 if n <= SHORT else 2


@dataclass(frozen=True)
class Again:
    """What solves a sweep again, keeping every state: for a table that kept few.

    The same positions in the same slices give the same numbers; the troubles were
    reported by the first solve (warnings are not repeated).
    """

    plan: Plan
    given: Array
    drive: Array
    rates: Rates
    with_forces: bool
    passed: bool
    ok: Mask | None

    def solve(self) -> tuple[_kin.KinematicState, _kst.ForceState | None]:
        """Return the kinematic and force states of every kept position."""
        n = self.drive.shape[0]
        with warnings.catch_warnings(), progress("", n, False) as bar:
            warnings.simplefilter("ignore", AssurWarning)
            tree = _passes(
                self.plan,
                self.given,
                self.drive,
                self.rates,
                _up_front(n),
                self.with_forces,
                True,
                self.passed,
                [],
                bar,
            )
        state, forces = _states(self.drive, self.rates, _up_front(n), tree)
        return _kept_rows(state, forces, self.ok)


def _unexplained(
    plan: Plan, given: Array, tree: Any, found: list[Any], top: int
) -> None:
    """Warn of values that are not finite where no failed position explains them.

    An overflow or a singular force system, say; the warning names what and where.
    """
    arrays = _arrays(tree, top)
    if not arrays:
        return
    # one sum of them all is finite when each of them is (an overflow of the sum,
    # or inf - inf, sends the search below, which looks at each)
    with np.errstate(invalid="ignore", over="ignore"):
        total = arrays[0] + arrays[1] if len(arrays) > 1 else arrays[0].copy()
        for x in arrays[2:]:
            total += x
    if np.isfinite(total).all():
        return
    explained = np.zeros(given.shape[0], dtype=bool)
    for trouble in found:
        if trouble.what not in NOTICES:
            explained |= trouble.mask
    owners = _owners(plan, tree)
    bad = np.zeros(given.shape[0], dtype=bool)
    named: list[str] = []
    for owner, value in owners:
        if is_array(value):
            wrong = ~np.isfinite(value) & ~explained
            if wrong.any():
                bad |= wrong
                if owner not in named:
                    named.append(owner)
    if bad.any():
        warnings.warn(
            f"values of {', '.join(named[:6])}{', ...' if len(named) > 6 else ''} are "
            f"not finite at driver positions {_ranges(plan, given, bad)}, where no "
            "group fails: the inputs are out of the range the arithmetic can follow",
            AssurWarning,
            stacklevel=7,
        )


def _arrays(tree: Any, top: int) -> list[Array]:
    """Return the arrays a value that is not finite would reach.

    NaN and inf spread from a position to its derivatives, so each link's highest
    derivative stands for its motion; and from a reaction to the frame's loads.
    """
    motion, _, fields = tree
    levels = top + 1
    out = [
        x
        for entries in motion
        for x in entries[top : 3 * levels : levels]
        if x.__class__ is np.ndarray
    ]
    if fields is not None:
        _, reactions, balancing, shaking, *_ = fields
        for group in (*reactions.values(), balancing, shaking):
            out += [x for x in group if x.__class__ is np.ndarray]
    return out


def _owners(plan: Plan, tree: Any) -> list[tuple[str, Any]]:
    """Pair every leaf of a sweep's states with the link or joint it belongs to."""
    motion, slide, fields = tree
    out = [
        (f"link {plan.bodies[b]}", x)
        for b, entries in enumerate(motion)
        for x in entries
    ]
    out += [(f"joint {name}", x) for name, values in slide.items() for x in values]
    if fields is not None:
        inertia, reactions, balancing, shaking, *_ = fields
        out += [
            (f"link {plan.bodies[b]}", x)
            for b, values in enumerate(inertia)
            for x in values or ()
        ]
        out += [
            (f"joint {name}", x) for name, values in reactions.items() for x in values
        ]
        out += [("driver", x) for x in balancing]
        out += [("shaking", x) for x in shaking]
    return out


def _change_points(plan: Plan, given: Array, drive: Array) -> bool:
    """Warn of the change points the sweep passes; return whether it passes any."""
    if len(plan.drivers) > 1:
        return _path_change_points(plan, given, drive)
    passed = branches(plan, drive)[1]
    for g, position in passed:
        d = plan.drivers[0]
        value = math.degrees(position) if d.kind == "R" else position
        warnings.warn(
            f"group {plan.solvers[g].label}: its two assembly branches meet at driver "
            f"position {_where(plan, np.array([value]))} (a change point); the motion "
            "is carried through onto the branch whose velocities are continuous",
            AssurWarning,
            stacklevel=4,
        )
    return bool(passed)


def _path_change_points(plan: Plan, given: Array, drive: Array) -> bool:
    """Warn of the change points on the positions' paths (several drivers)."""
    count = path_changes(plan, drive).count
    for g, c in count.items():
        warnings.warn(
            f"group {plan.solvers[g].label}: its two assembly branches meet on the "
            "straight path from the reference pose to driver positions "
            f"{_ranges(plan, given, c > 0)} (a change point); the motion is carried "
            "through onto the branch whose velocities are continuous",
            AssurWarning,
            stacklevel=5,
        )
    return bool(count)


def _branch_of(plan: Plan) -> _kin.BranchOf:
    """Return the groups' branches past change points as a function of position."""
    if len(plan.drivers) > 1:
        return lambda at: path_changes(plan, at).branch
    return lambda at: branches(plan, at)[0]


def _at(rates: Rates, rows: Any) -> Rates:
    """Return the rates at ``rows``: floats stay floats."""
    speed, accel = rates
    return (
        tuple(v if isinstance(v, float) else v[rows] for v in speed),
        tuple(v if isinstance(v, float) else v[rows] for v in accel),
    )


def _no_driver(plan: Plan) -> ModelError:
    """Return the error of a mechanism without drivers: a structure, or one missing.

    Such a file passes the count of degrees of freedom only when it has none (a
    rigid chain, whose groups stand on the frame): a driver would not help it.
    """
    from assur._structure import mobility

    if mobility(plan.mechanism) <= 0:
        msg = (
            "drivers: the mechanism has no driver, and W = 0: its links cannot move "
            "(a rigid structure); expected links that can move, with a [[drivers]] "
            "entry for each degree of freedom"
        )
    else:
        msg = "drivers: the mechanism has no driver; expected a [[drivers]] entry"
    return ModelError(msg)


def positions(plan: Plan, angles: Any) -> Array:
    """Return the driver positions as given (deg, or m), shape (n, drivers).

    Raises
    ------
    UsageError
        For positions that are not real finite numbers of the right shape.
    """
    d = len(plan.drivers)
    if d == 0:
        raise _no_driver(plan)
    arr = _real(angles, "angles", "driver positions")
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim == 1 and d > 1:
        if arr.shape[0] != d:
            msg = (
                f"angles: the mechanism has {d} drivers; expected an array of shape "
                f"(n, {d}), got shape {arr.shape}"
            )
            raise UsageError(msg)
        arr = arr[None, :]
    if arr.ndim == 1:
        arr = arr[:, None]
    if arr.ndim != 2 or arr.shape[1] != d:
        msg = (
            f"angles: expected shape (n, {d}) for {counted(d, 'driver')}, got "
            f"{arr.shape}"
        )
        raise UsageError(msg)
    if not np.all(np.isfinite(arr)):
        msg = "angles: expected finite driver positions"
        raise UsageError(msg)
    # the table's own copy: the caller's array may change after the call
    arr = np.array(arr, dtype=float)
    arr.flags.writeable = False
    return arr


def _real(values: Any, entry: str, what: str) -> Array:
    """Return ``values`` as a float array; refuse complex numbers and other types.

    Booleans and masked arrays are refused too: True is no angle, and a mask would
    be dropped (the masked values analysed).
    """
    if isinstance(values, np.ma.MaskedArray):
        msg = (
            f"{entry}: expected real numbers ({what}), got a masked array; expected "
            "the values to analyse alone (values[~mask])"
        )
        raise UsageError(msg)
    try:
        arr = np.asarray(values)
    except (TypeError, ValueError) as err:
        msg = f"{entry}: expected real numbers ({what}), got {type(values).__name__}"
        raise UsageError(msg) from err
    if arr.dtype.kind == "b":
        msg = f"{entry}: expected real numbers ({what}), got True or False"
        raise UsageError(msg)
    if arr.dtype.kind not in "iuf":
        kind = "complex numbers" if arr.dtype.kind == "c" else f"{arr.dtype} values"
        msg = f"{entry}: expected real numbers ({what}), got {kind}"
        raise UsageError(msg)
    return arr.astype(float, copy=False)


def to_si(plan: Plan, given: Array) -> Array:
    """Return driver positions in SI units (rad or m).

    A crank's angle is reduced exactly in degrees to within half a turn of the
    reference pose when a group is solved by continuation (so the path from the
    reference pose is short) or when it is large (so no digits are lost).
    """
    out = np.empty_like(given)
    for i, d in enumerate(plan.drivers):
        if d.kind == "R":
            values = given[:, i]
            out[:, i] = np.radians(values)
            # decided position by position, so a slice of a sweep is solved as the
            # whole sweep is: a closed form needs no reduction of moderate angles
            far = np.abs(values) >= EXACT_DEGREES
            if plan.newton:
                far[:] = True
            if far.any():
                # reducing in degrees is exact; radians of a huge angle are not
                low = math.degrees(d.reference) - 180.0
                turn = np.remainder(values[far], 360.0)
                out[far, i] = np.radians(np.remainder(turn - low, 360.0) + low)
        else:
            out[:, i] = given[:, i]
    return out


def driver_rates(plan: Plan, omega: Any, epsilon: Any, n: int) -> Rates:
    """Return each driver's speed and acceleration for a sweep of ``n`` positions.

    Without ``omega`` (``epsilon``) the file's constants; a number (every driver's),
    or one value per position (per position and driver with several), otherwise.
    """
    d = len(plan.drivers)
    out: list[tuple[Any, ...]] = []
    for entry, value, default in (
        ("omega", omega, [p.omega for p in plan.drivers]),
        ("epsilon", epsilon, [p.epsilon for p in plan.drivers]),
    ):
        if value is None:
            out.append(tuple(float(v) for v in default))
            continue
        if isinstance(value, bool | np.bool_):
            # the third argument was skip_unassembled before omega took its place
            msg = (
                f"{entry}: expected real numbers, got {value}; expected "
                "skip_unassembled=... by name to leave out unassembled positions"
            )
            raise UsageError(msg)
        arr = _real(value, entry, "rad/s or m/s" if entry == "omega" else "rad/s^2")
        if not np.all(np.isfinite(arr)):
            msg = f"{entry}: expected finite numbers"
            raise UsageError(msg)
        if arr.size and np.max(np.abs(arr)) > LARGEST:
            msg = (
                f"{entry}: {describe(float(np.max(np.abs(arr))))} is out of range; "
                f"expected magnitudes up to {LARGEST:g}"
            )
            raise UsageError(msg)
        if arr.ndim == 0:
            out.append((float(arr),) * d)  # every driver at that rate
        # copies: the caller's arrays may change after the call, a table's may not
        elif arr.ndim == 1 and d == 1 and arr.shape[0] == n:
            out.append((np.array(arr),))
        elif arr.ndim == 2 and arr.shape == (n, d):
            out.append(tuple(np.array(arr[:, i]) for i in range(d)))
        else:
            shape = "(n,)" if d == 1 else f"(n, {d})"
            msg = (
                f"{entry}: expected a number or one value per position, shape "
                f"{shape} with n = {n}; got shape {arr.shape}"
            )
            raise UsageError(msg)
    return out[0], out[1]


SKIPPED_WHY = (
    "where a group cannot be assembled, stands at a dead centre or is locked by "
    "friction"
)
"""What the positions ``skip_unassembled`` leaves out have in common."""


def _report(plan: Plan, given: Array, troubles: list[Any], skip: bool) -> Mask | None:
    """Raise or warn about the troubles of a sweep.

    Returns the mask of the positions kept, or None when every position is.
    """
    if not troubles:
        return None
    n = given.shape[0]
    ok = np.ones(n, dtype=bool)
    notices: dict[tuple[str, str], Mask] = {}
    for trouble, start in troubles:
        mask = np.zeros(n, dtype=bool)
        mask[start : start + trouble.mask.shape[0]] = trouble.mask
        if trouble.what in NOTICES:
            key = (trouble.what, trouble.group)
            notices[key] = notices.get(key, mask) | mask
            continue
        if not skip:
            # every slice's positions of this trouble: the counts are the sweep's
            mask = _all_failures(troubles, n, trouble.group, trouble.what)
            first = int(np.flatnonzero(mask)[0])
            where = _where(plan, given[first])
            if trouble.what == "assembly":
                # where the mechanism assembles, whatever else stops it there
                closes = ~_all_failures(troubles, n, what="assembly")
                good = _ranges(plan, given, closes)
                msg = (
                    f"group {trouble.group}: cannot be assembled at driver position "
                    f"{where} ({int(mask.sum())} of {n} positions fail); it assembles "
                    f"for {good or 'none of them'}"
                )
                locked = closes & _all_failures(troubles, n, what="locked")
                if locked.any():
                    msg += (
                        f" (where friction locks it at {_ranges(plan, given, locked)})"
                    )
                raise AssemblyError(msg)
            if trouble.what == "locked":
                msg = (
                    f"group {trouble.group}: its friction locks it at driver position "
                    f"{where} ({int(mask.sum())} of {n} positions): no driving load "
                    "moves it there (self-locking, or too near it to settle); "
                    "expected less friction, or positions where it can be driven"
                )
                raise SelfLockingError(msg)
            msg = (
                f"group {trouble.group}: dead centre at driver position {where} "
                "(its velocity equations are singular there); expected positions "
                "away from dead centres"
            )
            raise SingularConfigurationError(msg)
        ok &= ~mask
    for (what, group), mask in notices.items():
        mask &= ok
        if mask.any() and what == "near":
            warnings.warn(
                f"group {group}: near a dead centre (within about 2 degrees of "
                f"transmission angle 0 or 180) at driver positions "
                f"{_ranges(plan, given, mask)}",
                AssurWarning,
                stacklevel=4,
            )
        elif what == "other way" and (mask & _short_way(plan, given)).any():
            mask &= _short_way(plan, given)
            warnings.warn(_around(plan, given, group, mask, ok), AssurWarning, 4)
    return None if ok.all() else ok


NOTICES = frozenset({"near", "other way"})
"""Troubles that are told, not failures: near a dead centre, reached the other way."""


def _short_way(plan: Plan, given: Array) -> Mask:
    """Return where a crank's angle as given turns the way of its short path.

    The short path from the reference pose is the way a position reached the other
    way round did not go.

    -145.5 deg given for a reference pose at 60 deg asks for the way back, and is
    not said to be reached the other way when it is reached that way round.
    """
    gap = given[:, 0] - math.degrees(plan.drivers[0].reference)
    short = np.remainder(gap + 180.0, 360.0) - 180.0
    return np.sign(gap) == np.sign(short)  # type: ignore[no-any-return]


def _around(plan: Plan, given: Array, group: str, mask: Mask, ok: Mask) -> str:
    """Return the warning of positions reached the other way round the circle.

    Names, on each side of the reference pose, the last position reached the short
    way and the first that is not (the group's branch folds between them).
    """
    reference = math.degrees(plan.drivers[0].reference)
    ahead = np.remainder(given[:, 0] - reference + 180.0, 360.0) - 180.0
    limits = []
    for side in (1.0, -1.0):
        far = mask & (ahead * side > 0.0)
        if not far.any():
            continue
        first = np.flatnonzero(far)[np.argmin(ahead[far] * side)]
        near = ok & ~mask & (ahead * side >= 0.0) & (ahead * side < ahead[first] * side)
        stop = f"before {_where(plan, given[first])}"
        if near.any():
            last = np.flatnonzero(near)[np.argmax(ahead[near] * side)]
            stop = f"between {_where(plan, given[last])} and {stop[7:]}"
        limits.append(stop)
    return (
        f"group {group}: driver positions {_ranges(plan, given, mask)} are reached "
        "turning the other way round from the reference pose "
        f"({_where(plan, np.array([reference]))}); the group cannot follow the crank "
        f"to them the short way (its branch folds {' and '.join(limits)})"
    )


def _all_failures(
    troubles: list[Any], n: int, group: str | None = None, what: str | None = None
) -> Mask:
    """Return the positions where the sweep fails (not those near a dead centre).

    With ``group`` and ``what``, those of that group's trouble of that kind only.
    """
    bad = np.zeros(n, dtype=bool)
    for trouble, start in troubles:
        if trouble.what in NOTICES or (group is not None and trouble.group != group):
            continue
        if what is None or trouble.what == what:
            bad[start : start + trouble.mask.shape[0]] |= trouble.mask
    return bad


def _where(plan: Plan, position: Array) -> str:
    """Describe one position of the drivers (as given) for a message."""
    return position_text([d.kind for d in plan.drivers], position.tolist())


def _ranges(plan: Plan, given: Array, mask: Mask) -> str:
    """Describe the runs of consecutive positions in ``mask``.

    One driver's positions given out of order are taken in increasing order: a run
    is then of neighbours among all the positions given.
    """
    if given.shape[1] == 1 and given.shape[0] > 1:
        x = given[:, 0]
        # compared in place: a long sweep's steps would take 8 bytes a position
        if not (np.all(x[1:] >= x[:-1]) or np.all(x[1:] <= x[:-1])):
            order = np.argsort(x, kind="stable")
            given, mask = given[order], mask[order]
    if not mask.any():
        return ""
    # the runs' ends alone, not the index of every position in them
    edges = np.flatnonzero(mask[1:] != mask[:-1]) + 1
    starts = edges[mask[edges]]
    ends = edges[~mask[edges]] - 1
    if mask[0]:
        starts = np.r_[0, starts]
    if mask[-1]:
        ends = np.r_[ends, mask.shape[0] - 1]
    runs = []
    for a, b in zip(starts, ends, strict=True):
        first, last = _where(plan, given[a]), _where(plan, given[b])
        runs.append(first if a == b else f"{first} to {last}")
    return "; ".join(runs[:6]) + ("; ..." if len(runs) > 6 else "")
