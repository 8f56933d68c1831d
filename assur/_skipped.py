"""The positions a sweep left out (``--skip-unassembled``), and the note naming them."""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import pairwise
from typing import Any

import numpy as np

from assur._position_titles import position_text
from assur._runs import runs_text, telling_apart
from assur._stdin import input_text
from assur._text import counted
from assur._troubles import skipped_why
from assur._vec import Array, Mask
from assur.errors import AssemblyError

__all__ = ["Skipped"]

SKIPPED_SHOWN = 20
"""Positions left out that the note lists."""
EXPECTED = "; expected positions where the mechanism moves"
"""What a sweep with no position kept expects."""


@dataclass
class Skipped:
    """The positions left out over the sweep (``--skip-unassembled``)."""

    count: int = 0
    values: list[list[float]] = field(default_factory=list)
    """The first positions left out, one list of the drivers' positions each."""
    more: bool = False
    why: str = ""
    kinds: tuple[str, ...] = ("R",)
    """Each driver's pair kind: "R" for a crank (deg), "P" for a slider (m)."""
    marks: list[Mask] | None = field(default_factory=list)
    """Which positions of each slice were left out, in the sweep's order (None once
    a slice came without its positions)."""
    plan: Any = None

    def add(self, positions: Array, plan: Any = None, among: Any = None) -> None:
        """Count the positions left out of one slice (of the mechanism ``plan``).

        ``among`` is the slice's every position, in order: given with each slice,
        the note names the runs of positions left out ("131 deg to 266 deg")
        instead of the first twenty one by one.
        """
        why = skipped_why(plan, positions)
        self.why = why if len(why) > len(self.why) else self.why
        self.count += len(positions)
        rows = _rows(positions)
        if among is None or self.marks is None:
            self.marks = None
        else:
            self.marks.append(_left_out(_rows(among), rows))
        room = SKIPPED_SHOWN - len(self.values)
        self.values += rows[:room].tolist()
        self.more |= len(rows) > room
        if plan is not None:
            self.kinds = tuple(d.kind for d in plan.drivers)
            self.plan = plan

    def none_kept(self, first: str = "") -> AssemblyError:
        """Return the error of a sweep whose every position was left out.

        ``first`` is the error the sweep's first position gives when it is not
        left out: what fails there, and where the mechanism assembles.
        """
        which = "the one position" if self.count == 1 else "every position"
        if self.count > 1:
            # the first position's error counts itself alone, "(1 of 1 position
            # fails)", where the sweep left out every one of its own
            first = first.replace(" (1 of 1 position fails)", "")
            first = first.replace(" (1 of 1 position)", "")
        lead = "there" if self.count == 1 else "at the first"
        why = f"; {lead}, {first}" if first else ""
        # one "expected": the first position's error may say what it expects
        expected = "" if "; expected" in first else EXPECTED
        return AssemblyError(
            f"{which} of the sweep is left out ({self.why}){why}{expected}"
        )

    def note(self, source: Any, sweep: Any = None) -> str:
        """Return the note naming the positions left out of ``source``'s sweep.

        With ``sweep`` (every position of it, in order, as each slice's ``among``)
        the note names runs of positions, as the sweep lists them (a run that
        goes on into a turn's closing pose is not joined to the first); else the
        first ones, one by one.
        """
        left = counted(self.count, "position")
        lead = f"assur: note: {input_text(source)}: left out {left} {self.why}"
        marks = self.marks
        if sweep is not None and marks and self.plan is not None:
            sweep = _rows(sweep)
            mask = np.concatenate(marks)
            if mask.shape[0] == sweep.shape[0]:
                return f"{lead}: {runs_text(self.plan, sweep, mask)}"
        more = ", ..." if self.more else ""
        # neighbours written with the digits that tell them apart (a step of 1e-5
        # deg gave "197.555" twenty times)
        rows = [np.array(v) for v in self.values]
        digits = telling_apart(list(pairwise(rows)))
        if len(self.kinds) == 1:
            # one driver: its positions, the unit once
            shown = ", ".join(f"{v[0]:.{digits}g}" for v in self.values) + more
            shown += " deg" if self.kinds[0] == "R" else " m"
        else:
            # several: each position as messages write it, "(129 deg, 0.0648 m)"
            shown = "; ".join(position_text(self.kinds, v, digits) for v in self.values)
            shown += more.replace(",", ";")
        return f"{lead}: {shown}"


def _rows(positions: Any) -> Array:
    """Return driver positions as rows, shape (n, drivers)."""
    rows = np.asarray(positions, dtype=float)
    return rows[:, np.newaxis] if rows.ndim == 1 else rows


def _left_out(among: Array, left: Array) -> Mask:
    """Return which rows of ``among`` are among the rows ``left`` (left out).

    The rows left out are copies of some of ``among``'s: compared whole, each row
    as one value of its bytes.
    """
    if not left.shape[0]:
        return np.zeros(among.shape[0], dtype=bool)
    if left.shape[0] == among.shape[0]:
        return np.ones(among.shape[0], dtype=bool)

    def whole(rows: Array) -> Any:
        rows = np.ascontiguousarray(rows)
        return rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1])))[:, 0]

    return np.isin(whole(among), whole(left))
