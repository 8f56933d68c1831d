"""A sweep solved slice by slice: the forward and reverse passes over its slices.

Each slice's states are gathered into one tree of leaves, then into the sweep's frozen
states; :class:`Again` solves a sweep again for a table that kept few of them.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from assur import _kinematics as _kin
from assur import _state
from assur import kinetostatics as _kst
from assur._branches import branch_function
from assur._drive import Rates, _at
from assur._evaluate import SHORT
from assur._loads import compile_loads
from assur._paths import PathBranches
from assur._progress import progress
from assur._quiet import quiet
from assur._reach import unreached
from assur._state import jerks
from assur._unexplained import _unexplained
from assur._vec import Array, Mask, gather
from assur._warn import held
from assur.plan import Plan

__all__ = ["Again"]


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
        chunk = _state.CHUNK
        for start in range(0, max(n, 1), chunk):  # an empty sweep has one slice
            rows = slice(start, min(start + chunk, n))
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
    with quiet():
        speed, acceleration, jerk = rates
        bodies, found = _kin.solve(
            plan, drive, speed, acceleration, top, branch_of, jerk
        )
        # a closed-form group assembles where the mechanism cannot go too
        found += unreached(plan, drive, found)
        kin = _kin.state_of(plan, bodies, drive, rates, top)
        fields = None
        if loads is not None:
            forces, result = _kst.solve(plan, loads, bodies, kin)
            fields = forces.fields()
            found += [
                _kin.Trouble(label, "locked", mask) for label, mask in result.locked
            ]
    return kin, fields, found


def _states(
    drive: Array, rates: Rates, top: int, tree: Any
) -> tuple[_kin.KinematicState, _kst.ForceState | None]:
    """Return the kinematic and force states of a sweep's tree (see :func:`_passes`)."""
    motion, slide, fields = tree
    state = _kin.KinematicState(
        drive, rates[0], rates[1], motion, slide, top, jerks(rates)
    )
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
        with held(), progress("", n, False) as bar:  # told by the first solve
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


def _branch_of(plan: Plan) -> _kin.BranchOf:
    """Return the groups' branches past change points as a function of position."""
    if len(plan.drivers) > 1:
        return PathBranches(plan)
    return branch_function(plan)
