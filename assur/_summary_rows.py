"""The rows a summary adds for one slice of a sweep, each value with its weight.

The table's own rows, and at a position on a load table's step a second row with
the loads before the step (:mod:`assur._steps`): the position then counts half with
each, the trapezoid rule across the step. Every value carries two weights: its share
of its position, and that times the time the position stands for (see
:meth:`assur.summary.Summary.timed`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from assur._evaluate import friction_powers
from assur._loads import compile_loads, step_hits
from assur._steps import before_steps
from assur._vec import Array, full

__all__ = ["Rows", "rows_of"]


@dataclass(frozen=True)
class Rows:
    """A slice's values to summarise, one row per variant.

    ``parts`` are the table and, at load tables' steps, the table of the rows
    before them; ``where`` (variants, m) is each value's driver position,
    ``weights`` (2, variants, m) its share of its position and of time (None where
    every one is 1), ``last`` the indices of the values of the slice's last
    position.
    """

    parts: tuple[Any, ...]
    variants: int
    where: Array
    weights: Array | None
    last: Any
    landed: frozenset[Any] = frozenset()
    """The steps of load tables a position landed on, as ``(entry, step)``."""
    one_sided: bool = False
    """Positions on steps counted on one side only (a table of a few columns)."""

    def _joined(self, got: list[Any]) -> Array:
        """Return the parts' values side by side, one row per variant."""
        arrays = [np.asarray(g, dtype=float).reshape(self.variants, -1) for g in got]
        return arrays[0] if len(arrays) == 1 else np.concatenate(arrays, axis=1)

    def column(self, name: str) -> Array:
        """Return a column of every part."""
        return self._joined([t[name] for t in self.parts])

    def size(self, *names: str) -> Array:
        """Return the length of a vector of columns (one column: its size)."""
        got = [[np.asarray(t[c], dtype=float) for c in names] for t in self.parts]
        return self._joined(
            [np.abs(c[0]) if len(c) == 1 else np.hypot(*c) for c in got]
        )

    def _driver(self, field: str, i: int) -> Array:
        """Return driver ``i``'s leaf ``field`` of the parts' states, one per row."""
        got = []
        for t in self.parts:
            state = t.state if field == "speed" else t.force_state
            got.append(full(getattr(state, field)[i], len(t)))
        return self._joined(got)

    def speed(self, i: int) -> Array:
        """Return driver ``i``'s speed (rad/s or m/s)."""
        return self._driver("speed", i)

    def balancing(self, i: int) -> Array:
        """Return driver ``i``'s balancing load (N m or N)."""
        return self._driver("balancing", i)

    def ideal(self, i: int) -> Array:
        """Return driver ``i``'s balancing load without friction (N m or N)."""
        return self._driver("ideal", i)

    def friction(self) -> dict[str, Array]:
        """Return each pair's friction power (W), by the pair's name."""
        every = [friction_powers(t) for t in self.parts]
        return {name: self._joined([p[name] for p in every]) for name in every[0]}


def rows_of(table: Any, variants: int, shares: Array) -> Rows:
    """Return the rows to summarise of ``table``, ``shares`` the positions' times."""
    n = len(table)
    shape = (variants, n // variants)
    where = (table.given[:, 0] if n else np.zeros(0)).reshape(shape)
    last = np.arange(shape[1] - 1, shape[1]) if shape[1] else np.zeros(0, int)
    hits, landed = np.zeros(n, dtype=bool), frozenset[Any]()
    if variants == 1 and n:
        found = step_hits(compile_loads(table.plan), table.plan, table.state.drive)
        hits, landed = found[0], frozenset(found[1])
    if not hits.any() or table.partial:
        uniform = bool(np.all(shares == 1.0))
        weights = None if uniform else np.stack([np.ones(shape), shares])
        # a table of a few columns keeps too little of the motion to solve the
        # forces again before its steps: summarised on its rows as they are
        return Rows((table,), variants, where, weights, last, landed, bool(hits.any()))
    rows = np.flatnonzero(hits)
    before = _before(table, rows)
    weights = np.stack([np.ones(shape), shares])
    weights[:, :, rows] *= 0.5
    # the before rows follow the table's: the last position's own is among them
    again = shape[1] + np.flatnonzero(rows == shape[1] - 1)
    return Rows(
        (table, before),
        variants,
        np.concatenate([where, where[:, rows]], axis=1),
        np.concatenate([weights, weights[:, :, rows]], axis=2),
        np.concatenate([last, again]),
        landed,
    )


def _before(table: Any, rows: Any) -> Any:
    """Return the table of ``rows``, on load tables' steps, with the loads before."""
    forces = before_steps(table.plan, table.state, rows)
    state = table.state.rows(rows)
    return type(table)(table.plan, table.schema, table.given[rows], state, forces)
