"""Driver positions named in messages: one position, and runs of them.

A sweep of one crank over a whole turn closes on itself: a run that reaches its
last position goes on at its first one, and where the runs are of the whole sweep
(an error's ranges) the two are told as one range. A warning's runs are of one slice
of a long sweep at a time, merged by the command line: those are never joined.
"""

from __future__ import annotations

import numpy as np

from assur._position_titles import position_text
from assur._text import counted
from assur._vec import Array, Mask
from assur.plan import Plan

__all__ = [
    "digits_apart",
    "failing",
    "position_where",
    "positions_where",
    "runs_text",
    "telling_apart",
]

MOST_RUNS = 6
"""Runs named in one message; more are written as an ellipsis."""


def position_where(plan: Plan, position: Array, digits: int = 6) -> str:
    """Describe one position of the drivers (as given) for a message."""
    return position_text([d.kind for d in plan.drivers], position.tolist(), digits)


def positions_where(plan: Plan, given: Array, mask: Mask) -> str:
    """Return "driver position P", or "driver positions" and their runs."""
    noun = "position" if int(np.count_nonzero(mask)) == 1 else "positions"
    return f"driver {noun} {runs_text(plan, given, mask)}"


def failing(count: int, total: int, verb: str = "fail") -> str:
    """Return "3 of 72 positions fail", "1 of 72 positions fails" (``verb`` "")."""
    said = f"{count} of {counted(total, 'position')}"
    if not verb:
        return said
    return f"{said} {verb}s" if count == 1 else f"{said} {verb}"


def telling_apart(pairs: list[tuple[Array, Array]]) -> int:
    """Return the significant digits (6 to 17) that write each pair's two apart.

    A run's end and the position just past it, a failing position and the last
    good one: at a step of 1e-4 deg both were "149.528 deg".
    """
    for digits in range(6, 17):
        if all(
            position_text("R" * len(a), a.tolist(), digits)
            != position_text("R" * len(b), b.tolist(), digits)
            for a, b in pairs
            if not np.array_equal(a, b)
        ):
            return digits
    return 17


def digits_apart(given: Array, first: int) -> int:
    """Return the digits that write position ``first`` apart from its neighbours.

    Its nearest positions by value on either side (with one driver), or the one
    given before it: at a step of 1e-4 deg a failing position and the last good
    one were both "149.528 deg".
    """
    here = given[first]
    if given.shape[1] == 1:
        x = given[:, 0]
        lower, higher = x[x < here[0]], x[x > here[0]]
        near = [
            np.array([v.max() if v is lower else v.min()])
            for v in (lower, higher)
            if v.size
        ]
    else:
        near = [given[first - 1]] if first else []
    return telling_apart([(here, other) for other in near])


def runs_text(plan: Plan, given: Array, mask: Mask, join: bool = False) -> str:
    """Describe the runs of consecutive positions in ``mask``.

    One driver's positions given out of order are taken in increasing order: a run
    is then of neighbours among all the positions given. A crank's sweep over a
    whole turn joins its last run to its first with ``join`` (``given`` is then the
    whole sweep): "-11 deg to 41 deg", not "40 deg to 41 deg; 349 deg to 399 deg"
    for a sweep from 40 to 399 deg.
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
    n = given.shape[0]
    ends_in = join and len(starts) > 1 and mask[0] and mask[-1]
    turn = _turn(plan, given) if ends_in else 0.0
    # each end written apart from the position just past it; every run named is
    # among them (the joined one too, from its start a turn back)
    shown = list(zip(starts, ends, strict=True))[: MOST_RUNS + 2]
    pairs = [(given[a], given[a - 1]) for a, _ in shown if a > 0]
    pairs += [(given[b], given[b + 1]) for _, b in shown if b < n - 1]
    if turn:
        s, e = starts[-1], ends[0]
        # the joined run told from its start a turn back, into the first run; or
        # from the first run on into the last a turn on, where that is nearer
        # zero by more than half a turn (from 355 down to 0 deg: "195 deg to -15
        # deg", not "555 deg to 345 deg"; from -350 to 10 deg still "-355 deg to
        # -9 deg", not "5 deg to 351 deg")
        back = max(abs(float(given[s, 0] - turn)), abs(float(given[e, 0])))
        on = max(abs(float(given[s, 0])), abs(float(given[e, 0] + turn)))
        if on < back - 180.0:
            shift = (0.0, turn)
            pairs.append((given[e] + turn, given[e + 1] + turn))
        else:
            shift = (-turn, 0.0)
            pairs.append((given[s] - turn, given[s - 1] - turn))
    digits = telling_apart(pairs)
    runs = []
    if turn:
        # the last run goes on into the first: told from where the last begins,
        # a turn back, to where the first ends (one position when they meet)
        first = position_where(plan, given[starts[-1]] + shift[0], digits)
        last = position_where(plan, given[ends[0]] + shift[1], digits)
        runs.append(first if first == last else f"{first} to {last}")
        starts, ends = starts[1:-1], ends[1:-1]
    for a, b in zip(starts, ends, strict=True):
        first = position_where(plan, given[a], digits)
        last = position_where(plan, given[b], digits)
        runs.append(first if a == b else f"{first} to {last}")
    more = "; ..." if len(runs) > MOST_RUNS else ""
    return "; ".join(runs[:MOST_RUNS]) + more


def _turn(plan: Plan, given: Array) -> float:
    """Return +-360 when one crank's sweep (in order) spans a whole turn, else 0.

    A whole turn: the step after the last position would reach the first one a
    turn on (a sweep from 40 to 399 deg in steps of 1), or the last position is
    the first one a turn on (0 to 360 deg).
    """
    if len(plan.drivers) != 1 or plan.drivers[0].kind != "R" or given.shape[0] < 3:
        return 0.0
    x = given[:, 0]
    span, step = float(x[-1] - x[0]), float(x[-1] - x[-2])
    if step == 0.0 or (span > 0) != (step > 0):
        return 0.0
    turn = 360.0 if span > 0 else -360.0
    # to the rounding of a sweep's positions (a few units of their last place),
    # and always well inside a step
    tiny = 1e-9 * 360.0 + 8.0 * float(np.spacing(np.max(np.abs(x))))
    if not tiny < 0.5 * abs(step):
        return 0.0
    return turn if abs(span + step - turn) <= tiny or abs(span - turn) <= tiny else 0.0
