"""The sweeps the picture commands draw: analysed, checked and the left out noted.

``--skip-unassembled``, the positions that can be drawn, a table with some position
kept, and the most positions a diagram or a report holds.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

from assur._cli_common import load_mechanism, positions, quiet
from assur._troubles import SKIPPED_WHY, UNREACHED_WHY
from assur.errors import UsageError


def _skip_option(p: argparse.ArgumentParser) -> None:
    """Add ``--skip-unassembled`` to a command drawing a sweep."""
    p.add_argument(
        "--skip-unassembled",
        action="store_true",
        help=f"leave out the positions {SKIPPED_WHY}, {UNREACHED_WHY}",
    )


def _kept(mech: Any, positions: Any, forces: bool, skip: bool) -> tuple[Any, Any]:
    """Return the positions of a sweep that can be drawn, shape (n, drivers).

    Also the positions left out (deg, or m).

    One column is kept (memory stays that of the positions); what cannot be
    assembled raises, or with ``skip`` is left out, as a whole table would.
    """
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics
    from assur.columns import balancing_columns
    from assur.plan import plan_of

    if forces:  # friction may lock positions that assemble
        # the balancing loads alone: a torque or a force, as each driver moves
        loads = balancing_columns(plan_of(mech))
        table = force_table(
            mech, positions, skip_unassembled=skip, columns=["angle", *loads]
        )
    else:
        table = kinematics(mech, positions, skip_unassembled=skip, columns=["angle"])
    return _some_kept(table).given, table.skipped


def _table(mech: Any, positions: Any, forces: bool, skip: bool = False) -> Any:
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics

    analyse = force_table if forces else kinematics
    return _some_kept(analyse(mech, positions, skip_unassembled=skip))


def _say_skipped(args: argparse.Namespace, skipped: Any, plan: Any) -> None:
    """Note the positions left out of the sweep of ``plan`` (``--skip-unassembled``)."""
    from assur._skipped import Skipped

    if len(skipped) and not quiet(args):
        # the sweep again, as given: the note names the runs of positions left out
        sweep = positions(plan.mechanism, args.angles)
        found = Skipped()
        found.add(skipped, plan, sweep)
        print(found.note(args.file, sweep), file=sys.stderr)


def _some_kept(table: Any) -> Any:
    """Return ``table``; an AssemblyError when every position was left out."""
    from assur._skipped import Skipped

    if len(table) or not len(table.skipped):
        return table
    from assur._sliced import _first_failure
    from assur.analysis import forces, kinematics

    found = Skipped()
    found.add(table.skipped, table.plan)
    analyse = forces if table.force_state is not None else kinematics
    first = table.skipped[:1]
    raise found.none_kept(_first_failure(analyse, table.mechanism, first))


def _sweep(args: argparse.Namespace, forces: bool | None) -> tuple[Any, Any]:
    """Return the mechanism and its table over ``--angles`` (forces if it has loads)."""
    from assur._loads import compile_loads
    from assur.plan import plan_of

    mech = load_mechanism(args.file)
    loaded = not compile_loads(plan_of(mech)).empty
    return mech, _table(
        mech,
        _on_axis(_drawn(positions(mech, args.angles), "diagrams draw every position")),
        loaded if forces is None else forces,
        getattr(args, "skip_unassembled", False),
    )


DRAWN_MOST = 100_000
"""Most positions of a sweep that diagrams or a report hold whole (every one)."""


DRAWN_REACH = 1e300
"""Largest driver position (deg, or m for a prismatic driver) a diagram's axis spans.

Near the largest float (``--angles=-1.7e308:1.7e308:1e308``, a range a table takes)
matplotlib's axis overflowed: numpy's warnings with their source lines, then the
diagrams' folder named as the fault ("cannot write the file (ValueError: ...)")."""


def _on_axis(sweep: Any) -> Any:
    """Return ``sweep``; a UsageError for a position beyond :data:`DRAWN_REACH`."""
    import numpy as np

    farthest = float(np.max(np.abs(sweep))) if np.size(sweep) else 0.0
    if farthest > DRAWN_REACH:
        msg = (
            f"--angles: a position of magnitude {farthest:g}; expected positions "
            f"within +-{DRAWN_REACH:g}, which the diagrams' axes can span"
        )
        raise UsageError(msg)
    return sweep


def _drawn(sweep: Any, why: str) -> Any:
    """Return ``sweep``; a UsageError when it holds more than :data:`DRAWN_MOST`."""
    if len(sweep) > DRAWN_MOST:
        msg = (
            f"--angles: {len(sweep)} positions; expected at most {DRAWN_MOST} "
            f"({why}; a larger step)"
        )
        raise UsageError(msg)
    return sweep
