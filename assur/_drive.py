"""Driver positions and speeds of a sweep, as given and in SI units.

Reads the positions (deg, or m) and the drivers' speeds and accelerations handed to
:func:`~assur.analysis.kinematics` and :func:`~assur.analysis.forces`, refuses what
cannot be used (naming the argument), and turns the positions into radians exactly.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from assur._checks import LARGEST
from assur._text import counted, describe
from assur._vec import Array, set_writeable
from assur.errors import ModelError, UsageError
from assur.plan import Plan

EXACT_DEGREES = 1e4
"""Crank angles (deg) below which turning them into radians as they are loses no
more than reducing them to a turn first would."""

Rates = tuple[tuple[Any, ...], tuple[Any, ...], tuple[Any, ...]]
"""Each driver's speed, acceleration and jerk: a float, or an array with one value
per position."""


def _at(rates: Rates, rows: Any) -> Rates:
    """Return the rates at ``rows``: floats stay floats."""
    speed, accel, jerk = rates
    return (
        tuple(v if isinstance(v, float) else v[rows] for v in speed),
        tuple(v if isinstance(v, float) else v[rows] for v in accel),
        tuple(v if isinstance(v, float) else v[rows] for v in jerk),
    )


def _no_driver(plan: Plan) -> ModelError:
    """Return the error of a mechanism without drivers: a structure, or one missing.

    Such a file passes the count of degrees of freedom only when it has none (a
    rigid chain, whose groups stand on the frame): a driver would not help it.
    """
    from assur._diagnosis import no_driver
    from assur._structure import mobility

    w = mobility(plan.mechanism)
    if w <= 0:
        msg = no_driver(plan.mechanism, w)
    else:
        msg = "drivers: the mechanism has no driver; expected a [[drivers]] entry"
    return ModelError(msg)


def positions(plan: Plan, angles: Any, entry: str = "angles") -> Array:
    """Return the driver positions as given (deg, or m), shape (n, drivers).

    ``entry`` names the argument in messages (``angle`` for one position).

    Raises
    ------
    UsageError
        For positions that are not real finite numbers of the right shape.
    """
    d = len(plan.drivers)
    if d == 0:
        raise _no_driver(plan)
    arr = _real(angles, entry, "driver positions")
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim == 1 and d > 1:
        if arr.shape[0] != d:
            wanted = f"an array of shape (n, {d})"
            if entry == "angle":  # one position: a number per driver
                wanted = f"one position, {d} numbers (one per driver)"
            msg = (
                f"{entry}: the mechanism has {d} drivers; expected {wanted}, got "
                f"shape {arr.shape}"
            )
            raise UsageError(msg)
        arr = arr[None, :]
    if arr.ndim == 1:
        arr = arr[:, None]
    if arr.ndim != 2 or arr.shape[1] != d:
        msg = (
            f"{entry}: expected shape (n, {d}) for {counted(d, 'driver')}, got "
            f"{arr.shape}"
        )
        raise UsageError(msg)
    if not np.isfinite(arr).all():
        msg = f"{entry}: expected finite driver positions"
        raise UsageError(msg)
    # the table's own copy: the caller's array may change after the call
    arr = np.array(arr, dtype=float)
    set_writeable(arr, False)
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
        if arr.dtype.kind in "US":
            # text, an array of it or bytes: told as the strings they are
            kind = f"text {describe(arr.astype(str).tolist())}"
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


UNITS = {"omega": "rad/s or m/s", "epsilon": "rad/s^2", "jerk": "rad/s^3 or m/s^3"}
"""What each of a driver's rates is expected in (the message of one that is not)."""
MOST = {"jerk": LARGEST**2}
"""Largest magnitude of a rate other than the file numbers' ``LARGEST``: a jerk grows
as the cube of the speed (the dynamic model's steady motion at 1e5 rad/s has 1.5e15
rad/s^3), and times a length of 1e15 m it is still far from overflowing."""


def driver_rates(
    plan: Plan, omega: Any, epsilon: Any, n: int, jerk: Any = None
) -> Rates:
    """Return each driver's speed, acceleration and jerk for a sweep of ``n`` positions.

    Without ``omega`` (``epsilon``) the file's constants, without ``jerk`` zero (a
    driver whose acceleration holds); a number (every driver's), or one value per
    position (per position and driver with several), otherwise.
    """
    d = len(plan.drivers)
    out: list[tuple[Any, ...]] = []
    for entry, value, default in (
        ("omega", omega, [p.omega for p in plan.drivers]),
        ("epsilon", epsilon, [p.epsilon for p in plan.drivers]),
        ("jerk", jerk, [0.0] * d),
    ):
        if value is None:
            out.append(tuple(float(v) for v in default))
            continue
        if isinstance(value, bool | np.bool_) and entry != "jerk":
            # the third argument was skip_unassembled before omega took its place
            msg = (
                f"{entry}: expected real numbers, got {value}; expected "
                "skip_unassembled=... by name to leave out unassembled positions"
            )
            raise UsageError(msg)
        arr = _real(value, entry, UNITS[entry])
        if not np.all(np.isfinite(arr)):
            msg = f"{entry}: expected finite numbers"
            raise UsageError(msg)
        most = MOST.get(entry, LARGEST)
        if arr.size and np.max(np.abs(arr)) > most:
            msg = (
                f"{entry}: {describe(float(np.max(np.abs(arr))))} is out of range; "
                f"expected magnitudes up to {most:g}"
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
    return out[0], out[1], out[2]
