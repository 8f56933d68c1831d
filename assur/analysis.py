"""Sweeps over driver positions: the library's main entry points and their tables.

:func:`kinematics` and :func:`forces` run the forward and reverse passes over a whole
sweep (in slices, so temporaries stay in cache) and return a :class:`Table` whose
columns are the mechanism file contract's.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur import _kinematics as _kin
from assur import kinetostatics as _kst
from assur._loads import compile_loads
from assur._text import suggest
from assur._vec import Array
from assur.errors import (
    AssemblyError,
    AssurWarning,
    ModelError,
    SingularConfigurationError,
)
from assur.model import Mechanism
from assur.plan import Plan, compile_plan

__all__ = ["Table", "default_positions", "forces", "kinematics"]

CHUNK = 8192
"""Driver positions solved at once; long sweeps run in slices of this size."""


@dataclass(frozen=True)
class Table:
    """Results per driver position, by column name.

    ``table["rod.omega"]`` is a read-only array with one value per position;
    ``columns`` lists the names in order. ``state`` and ``force_state`` keep the
    arrays the columns come from, for plotting.
    """

    mechanism: Mechanism
    columns: tuple[str, ...]
    data: dict[str, Array]
    state: _kin.KinematicState
    force_state: _kst.ForceState | None = None
    skipped: Array = field(default_factory=lambda: np.zeros(0))
    """Driver positions left out (deg, or m), with ``skip_unassembled``."""

    def __getitem__(self, name: str) -> Array:
        try:
            return self.data[name]
        except KeyError:
            msg = f"no column {name!r}{suggest(name, self.columns, listing=False)}"
            raise KeyError(msg) from None

    def __len__(self) -> int:
        return int(self.state.drive.shape[0])

    def __contains__(self, name: object) -> bool:
        return name in self.data

    def to_array(self) -> Array:
        """Return the table as one array (rows, columns)."""
        return np.column_stack([self.data[c] for c in self.columns])

    def to_csv(self, path: Any = None) -> str | None:
        """Write the table as CSV to ``path`` (a path, a file object or ``"-"``).

        Without ``path`` the CSV text is returned.
        """
        from assur.io import write_csv

        return write_csv(self, path)

    def to_dict(self) -> dict[str, Any]:
        """Return JSON-ready data: the mechanism's name, the columns and the rows."""
        rows = self.to_array()
        return {
            "name": self.mechanism.name,
            "columns": list(self.columns),
            "rows": [
                {c: _json_number(v) for c, v in zip(self.columns, row, strict=True)}
                for row in rows
            ],
        }

    def to_pandas(self) -> Any:
        """Return a pandas DataFrame (pandas must be installed)."""
        import pandas as pd

        return pd.DataFrame({c: self.data[c] for c in self.columns})

    def plot(self, angle: float | None = None, **kwargs: Any) -> Any:
        """Draw the mechanism at a driver position (see :func:`assur.plotting.draw`)."""
        from assur.plotting import draw

        return draw(self, angle=angle, **kwargs)


def _json_number(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None


def default_positions(mech: Mechanism, step: float = 1.0) -> Array:
    """Return one full turn from the reference pose in steps of ``step`` degrees.

    For a prismatic driver: 101 positions over +-20 % of the mechanism's size.
    """
    plan = compile_plan(mech)
    starts = []
    for d in plan.drivers:
        if d.kind == "R":
            starts.append(math.degrees(d.angle0) + np.arange(0.0, 360.0, step))
        else:
            starts.append(np.linspace(-0.2, 0.2, 101) * plan.scale)
    count = min(len(s) for s in starts)
    out = np.stack([s[:count] for s in starts], axis=-1)
    return out[:, 0] if out.shape[1] == 1 else out


def _to_si(plan: Plan, angles: Any) -> Array:
    arr = np.asarray(angles, dtype=float)
    d = len(plan.drivers)
    if d == 0:
        msg = "drivers: the mechanism has no driver; expected a [[drivers]] entry"
        raise ModelError(msg)
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim == 1 and d > 1:
        if arr.shape[0] != d:
            msg = (
                f"angles: the mechanism has {d} drivers; expected an array of shape "
                f"(n, {d}), got shape {arr.shape}"
            )
            raise ModelError(msg)
        arr = arr[None, :]
    if arr.ndim == 1:
        arr = arr[:, None]
    if arr.ndim != 2 or arr.shape[1] != d:
        msg = f"angles: expected shape (n, {d}) for {d} driver(s), got {arr.shape}"
        raise ModelError(msg)
    if not np.all(np.isfinite(arr)):
        msg = "angles: expected finite driver positions"
        raise ModelError(msg)
    scale = np.array(
        [math.radians(1.0) if p.kind == "R" else 1.0 for p in plan.drivers]
    )
    return arr * scale


def kinematics(
    mechanism: Mechanism,
    angles: Sequence[float] | Array,
    skip_unassembled: bool = False,
) -> Table:
    """Positions, velocities, accelerations and jerks over driver positions.

    Parameters
    ----------
    mechanism : Mechanism
    angles : array_like
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers).
    skip_unassembled : bool
        Leave out the positions where a group cannot be assembled instead of raising;
        ``Table.skipped`` lists them.

    Returns
    -------
    Table

    Raises
    ------
    AssemblyError, SingularConfigurationError
        At the first driver position where a group cannot close or is at a dead
        centre, naming the group.

    Examples
    --------
    >>> from assur import catalog
    >>> t = kinematics(catalog.four_bar(), [0.0, 90.0])
    >>> t["crank.omega"].tolist()
    [10.0, 10.0]
    """
    return _sweep(mechanism, angles, False, skip_unassembled)


def forces(
    mechanism: Mechanism,
    angles: Sequence[float] | Array,
    skip_unassembled: bool = False,
) -> Table:
    """Kinematics plus inertia loads, joint reactions and balancing loads.

    Parameters are those of :func:`kinematics`.

    Raises
    ------
    ModelError
        When no link has a mass and no load is applied, when a link with a mass lacks
        its centre of mass or inertia, or a load table does not cover the sweep.

    Examples
    --------
    >>> from assur import catalog
    >>> t = forces(catalog.slider_crank(), [45.0])
    >>> bool(abs(t["driver.torque"][0] - t["driver.torque_check"][0]) < 1e-9)
    True
    """
    plan = compile_plan(mechanism)
    if compile_loads(plan).empty:
        msg = (
            "forces: no link has a mass and no load is applied; expected 'mass', "
            "'center' and 'inertia' on the links or [[loads]] for a force analysis"
        )
        raise ModelError(msg)
    return _sweep(mechanism, angles, True, skip_unassembled)


def _sweep(mech: Mechanism, angles: Any, with_forces: bool, skip: bool) -> Table:
    from assur.columns import build_columns

    plan = compile_plan(mech)
    drive = _to_si(plan, angles)
    n = drive.shape[0]
    state = _kin.allocate(plan, n)
    force_state = _kst.allocate(plan, n) if with_forces else None
    troubles = []
    for start in range(0, n, CHUNK):
        chunk = drive[start : start + CHUNK]
        # failed or dead-centre positions carry NaN through; _report names them
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            bodies, found = _kin.solve(plan, chunk)
            part = _kin.collect(plan, bodies, chunk.shape[0], state, start)
            if force_state is not None:
                _kst.solve(plan, bodies, part, force_state, start)
        troubles.extend((t, start) for t in found)
    ok = _report(plan, drive, troubles, skip)
    state = _kin.freeze(state)
    if force_state is not None:
        force_state = _kst.freeze(force_state)
    if not ok.all():
        state = _take_state(state, ok)
        force_state = _take_forces(force_state, ok) if force_state else None
    given = np.asarray(angles, dtype=float).reshape(n, len(plan.drivers))
    columns, data = build_columns(plan, state, force_state, given[ok])
    skipped = given[~ok]
    return Table(
        mech,
        columns,
        data,
        state,
        force_state,
        skipped[:, 0] if skipped.shape[1] == 1 else skipped,
    )


def _report(plan: Plan, drive: Array, troubles: list, skip: bool) -> Array:
    """Raise or warn about the troubles of a sweep; return the good positions' mask."""
    n = drive.shape[0]
    ok = np.ones(n, dtype=bool)
    near: dict[str, Array] = {}
    for trouble, start in troubles:
        mask = np.zeros(n, dtype=bool)
        mask[start : start + trouble.mask.shape[0]] = trouble.mask
        if trouble.what == "near":
            near[trouble.group] = near.get(trouble.group, mask) | mask
            continue
        if not skip:
            first = int(np.flatnonzero(mask)[0])
            where = _position_text(plan, drive[first])
            good = _ranges(plan, drive, ~_all_failures(troubles, n))
            if trouble.what == "assembly":
                msg = (
                    f"group {trouble.group}: cannot be assembled at driver position "
                    f"{where} ({int(mask.sum())} of {n} positions fail); it assembles "
                    f"for {good or 'none of them'}"
                )
                raise AssemblyError(msg)
            msg = (
                f"group {trouble.group}: dead centre at driver position {where} "
                "(its velocity equations are singular there); expected positions "
                "away from dead centres"
            )
            raise SingularConfigurationError(msg)
        ok &= ~mask
    for group, mask in near.items():
        mask &= ok
        if mask.any():
            warnings.warn(
                f"group {group}: near a dead centre (within about 2 degrees of "
                f"transmission angle 0 or 180) at driver positions "
                f"{_ranges(plan, drive, mask)}",
                AssurWarning,
                stacklevel=4,
            )
    return ok


def _all_failures(troubles: list, n: int) -> Array:
    bad = np.zeros(n, dtype=bool)
    for trouble, start in troubles:
        if trouble.what != "near":
            bad[start : start + trouble.mask.shape[0]] |= trouble.mask
    return bad


def _position_text(plan: Plan, position: Array) -> str:
    parts = [
        f"{math.degrees(x):.6g} deg" if d.kind == "R" else f"{x:.6g} m"
        for d, x in zip(plan.drivers, position, strict=False)
    ]
    return ", ".join(parts)


def _ranges(plan: Plan, drive: Array, mask: Array) -> str:
    """Describe the runs of consecutive positions in ``mask``."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return ""
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = np.r_[idx[0], idx[breaks + 1]]
    ends = np.r_[idx[breaks], idx[-1]]
    runs = []
    for a, b in zip(starts, ends, strict=False):
        first, last = _position_text(plan, drive[a]), _position_text(plan, drive[b])
        runs.append(first if a == b else f"{first} to {last}")
    return "; ".join(runs[:6]) + ("; ..." if len(runs) > 6 else "")


def _take_state(s: _kin.KinematicState, ok: Array) -> _kin.KinematicState:
    return _kin.KinematicState(
        s.drive[ok],
        s.link[:, ok],
        s.origin[ok],
        s.point[:, ok],
        {k: v[:, ok] for k, v in s.slide.items()},
    )


def _take_forces(p: _kst.ForceState, ok: Array) -> _kst.ForceState:
    return _kst.ForceState(
        p.inertia_force[ok],
        p.inertia_torque[ok],
        {k: (v[0][ok], v[1][ok]) for k, v in p.reactions.items()},
        p.balancing[ok],
        p.check[ok],
        p.shaking[ok],
        p.residual[ok],
        {k: v[ok] for k, v in p.magnitude.items()},
        {k: v[ok] for k, v in p.offset.items()},
    )
