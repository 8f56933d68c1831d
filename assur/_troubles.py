"""What a sweep met on its way: errors raised, positions left out, warnings.

The sweep's slices hand their troubles here with the start of their slice; the
messages name the whole sweep's counts and ranges of driver positions (as given).
"""

from __future__ import annotations

import math
from typing import Any, NoReturn

import numpy as np

from assur._branches import at_change_point, branches
from assur._drive import to_si
from assur._paths import path_changes
from assur._reach import beyond, reach
from assur._runs import (
    digits_apart,
    failing,
    position_where,
    positions_where,
    runs_text,
)
from assur._vec import Array, Mask
from assur._warn import warn
from assur.errors import (
    AssemblyError,
    AssurWarning,
    SelfLockingError,
    SingularConfigurationError,
)
from assur.plan import Plan

SKIPPED_WHY = (
    "where a group cannot be assembled, stands at a dead centre or a change point, "
    "or is locked by friction"
)
"""What the positions ``skip_unassembled`` leaves out have in common."""
UNREACHED_WHY = "or that the mechanism cannot reach from its reference pose"
"""Added to :data:`SKIPPED_WHY` when some of them are beyond a barrier (see
:mod:`assur._reach`)."""


def skipped_why(plan: Plan | None, skipped: Array) -> str:
    """Return why the positions ``skipped`` (as given, deg or m) were left out.

    :data:`SKIPPED_WHY`, and :data:`UNREACHED_WHY` when some of them lie beyond a
    barrier of ``plan`` where every group assembles (those that fail to assemble
    there are told by the first).
    """
    if plan is None or len(plan.drivers) != 1 or reach(plan) is None:
        return SKIPPED_WHY
    x = np.ravel(skipped)
    x = np.radians(x) if plan.drivers[0].kind == "R" else x
    if not beyond(plan, x[:, None]).any():
        return SKIPPED_WHY
    return f"{SKIPPED_WHY}, {UNREACHED_WHY}"


def _report(plan: Plan, given: Array, troubles: list[Any], skip: bool) -> Mask | None:
    """Raise or warn about the troubles of a sweep.

    Returns the mask of the positions kept, or None when every position is.
    """
    if not troubles:
        return None
    n = given.shape[0]
    failures = [trouble for trouble, _ in troubles if trouble.what not in NOTICES]
    if failures and not skip:
        # the sweep's first failing position, whichever group fails there (the
        # lever's dyad was named at 270 deg where the ram's failed from 200 deg);
        # friction's locking after any other failure, whose message tells where
        # friction locks too
        def rank(t: Any) -> tuple[bool, int]:
            first = np.argmax(_all_failures(troubles, n, t.group, t.what))
            return t.what == "locked", int(first)

        _fail(plan, given, troubles, min(failures, key=rank))
    ok = np.ones(n, dtype=bool)
    notices: dict[tuple[str, str], Mask] = {}
    for trouble, start in troubles:
        mask = np.zeros(n, dtype=bool)
        mask[start : start + trouble.mask.shape[0]] = trouble.mask
        if trouble.what in NOTICES:
            key = (trouble.what, trouble.group)
            notices[key] = notices.get(key, mask) | mask
            continue
        ok &= ~mask
    for (what, group), mask in notices.items():
        mask &= ok
        if mask.any() and what == "near":
            # a triad has no one transmission angle: its equations' conditioning
            how = (
                "within about 2 degrees of transmission angle 0 or 180 deg"
                if group.split(" ")[0] in DYADS
                else "its position equations nearly singular"
            )
            warn(
                f"group {group}: near a dead centre ({how}) at "
                f"{positions_where(plan, given, mask)}",
                AssurWarning,
                stacklevel=4,
            )
        elif what == "other way":
            mask &= _short_way(plan, given)
            if mask.any():
                warn(_around(plan, given, group, mask, ok), AssurWarning, stacklevel=4)
    return None if ok.all() else ok


DYADS = frozenset({"RRR", "RRP", "RPR", "PRP", "RPP"})
"""The kinds of class II group, whose dead centres are a transmission angle's."""
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
        stop = f"before {position_where(plan, given[first])}"
        if near.any():
            last = np.flatnonzero(near)[np.argmax(ahead[near] * side)]
            stop = f"between {position_where(plan, given[last])} and {stop[7:]}"
        limits.append(stop)
    verb, them = ("is", "it") if np.count_nonzero(mask) == 1 else ("are", "them")
    return (
        f"group {group}: {positions_where(plan, given, mask)} {verb} reached turning "
        "the other way round from the reference pose "
        f"({position_where(plan, np.array([reference]))}); the group cannot follow "
        f"the crank to {them} the short way (its branch folds {' and '.join(limits)})"
    )


def _unreached(plan: Plan, given: Array, mask: Mask, group: str) -> str:
    """Return the error of positions the mechanism cannot reach (one driver).

    Names the first of them, the barrier on its way from the reference pose and the
    range of positions reached (:mod:`assur._reach`).
    """
    span = reach(plan)
    assert span is not None
    d = plan.drivers[0]

    def at(x: float) -> str:
        return _reached_at(plan, x)

    row = given[int(np.flatnonzero(mask)[0])]
    x = math.radians(row[0]) if d.kind == "R" else float(row[0])
    barrier = (span.above if x > d.reference else span.below) or span.above
    barrier = barrier or span.below
    assert barrier is not None
    if barrier.kind == "assembly":
        head = "is on another circuit of the mechanism"
        why = (
            f"it cannot reach it from its reference pose at {at(d.reference)}; the "
            f"group cannot be assembled between about {at(barrier.start)} and "
            f"{at(barrier.end)}"
        )
    else:
        head = "is beyond a dead centre of the group"
        why = (
            "the mechanism cannot reach it from its reference pose at "
            f"{at(d.reference)}; the group is at a dead centre at about "
            f"{at(barrier.start)}, which the driver cannot carry it through"
        )
    return (
        f"group {group}: driver position {position_where(plan, row)} {head} "
        f"({failing(int(mask.sum()), mask.shape[0], '')}): {why}; expected "
        f"positions {_reached(plan, span)}"
    )


def _none_of_them(plan: Plan, n: int) -> str:
    """Say that none of the ``n`` positions given assembles, and where it does.

    One position asked for (``assur plot --angle 350``) said "it assembles for
    none of them" alone.
    """
    span = reach(plan) if len(plan.drivers) == 1 else None
    if span is None:
        alone = "it does not assemble there"
        return alone if n == 1 else "it assembles for none of them"
    where = _reached(plan, span)
    if n == 1:
        return f"the mechanism reaches only positions {where}"
    return f"it assembles for none of them: the mechanism reaches positions {where}"


def _reached_at(plan: Plan, x: float) -> str:
    """Return a driver position of :mod:`assur._reach` (rad, or m) for a message."""
    d = plan.drivers[0]
    # a barrier found by root finding lands within rounding of a round number
    value = round(math.degrees(x) if d.kind == "R" else x / plan.scale, 6)
    value = value if d.kind == "R" else value * plan.scale
    return position_where(plan, np.array([value + 0.0]))


def _reached(plan: Plan, span: Any) -> str:
    """Return the positions ``span`` (a :class:`~assur._reach.Reach`) spans."""
    if span.below is None:
        expected = f"up to about {_reached_at(plan, span.last)}"
    elif span.above is None:
        expected = f"from about {_reached_at(plan, span.first)}"
    else:
        first, last = _reached_at(plan, span.first), _reached_at(plan, span.last)
        expected = f"from about {first} to {last}"
    if span.period is not None:
        expected += " (or whole turns from them)"
    return expected


def _fail(plan: Plan, given: Array, troubles: list[Any], trouble: Any) -> NoReturn:
    """Raise the error of ``trouble``, counted over every slice of the sweep."""
    n = given.shape[0]
    mask = _all_failures(troubles, n, trouble.group, trouble.what)
    first = int(np.flatnonzero(mask)[0])
    where = position_where(plan, given[first], digits_apart(given, first))
    if trouble.what == "unreached":
        raise AssemblyError(_unreached(plan, given, mask, trouble.group))
    if trouble.what == "assembly":
        # where the mechanism assembles and goes, whatever else stops it there
        apart = ~_all_failures(troubles, n, what="assembly")
        closes = apart & ~_all_failures(troubles, n, what="unreached")
        good = runs_text(plan, given, closes, join=True)
        count = int(mask.sum())
        # the group's own count; other groups' failures, and positions out of
        # reach, are the sweep's too: each said by name
        others, away = int(n - apart.sum()) - count, int(apart.sum() - closes.sum())
        more = "".join(
            f", {k} more {what}"
            for k, what in (
                (others, "where other groups cannot be assembled"),
                (away, "out of reach from the reference pose"),
            )
            if k
        )
        msg = (
            f"group {trouble.group}: cannot be assembled at driver position "
            f"{where} ({failing(count, n)}{more}); "
            + (f"it assembles for {good}" if good else _none_of_them(plan, n))
        )
        locked = closes & _all_failures(troubles, n, what="locked")
        if locked.any():
            locks = runs_text(plan, given, locked, join=True)
            msg += f" (where friction locks it at {locks})"
        raise AssemblyError(msg)
    if trouble.what == "locked":
        msg = (
            f"group {trouble.group}: its friction locks it at driver position "
            f"{where} ({failing(int(mask.sum()), n, '')}): no driving load "
            "moves it there (self-locking, or too near it to settle); "
            "expected less friction, or positions where it can be driven"
        )
        raise SelfLockingError(msg)
    if _change_point(plan, given[first], trouble.group):
        # the warning before it said the motion is carried through this point:
        # the positions beyond it are, the point itself has no velocities
        msg = (
            f"group {trouble.group}: change point at driver position {where} (its "
            "two assembly branches meet there: its velocity equations are "
            "singular, with no branch to choose); expected positions away from "
            "change points"
        )
        raise SingularConfigurationError(msg)
    msg = (
        f"group {trouble.group}: dead centre at driver position {where} "
        "(its velocity equations are singular there); expected positions "
        "away from dead centres"
    )
    raise SingularConfigurationError(msg)


def _change_point(plan: Plan, position: Array, group: str) -> bool:
    """Return whether ``position`` (as given) is a change point of ``group``."""
    if len(plan.drivers) > 1:
        return False
    x = float(to_si(plan, position[None, :])[0, 0])
    return any(
        at_change_point(plan, g, x)
        for g, s in enumerate(plan.solvers)
        if s.label == group
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


def _change_points(plan: Plan, given: Array, drive: Array) -> bool:
    """Warn of the change points the sweep passes; return whether it passes any."""
    if len(plan.drivers) > 1:
        return _path_change_points(plan, given, drive)
    passed = branches(plan, drive)[1]
    for g, position in passed:
        d = plan.drivers[0]
        value = math.degrees(position) if d.kind == "R" else position
        warn(
            f"group {plan.solvers[g].label}: its two assembly branches meet at driver "
            f"position {position_where(plan, np.array([value]))} (a change point); "
            "the motion is carried through onto the branch whose velocities are "
            "continuous",
            AssurWarning,
            stacklevel=4,
        )
    return bool(passed)


def _path_change_points(plan: Plan, given: Array, drive: Array) -> bool:
    """Warn of the change points on the positions' paths (several drivers)."""
    count = path_changes(plan, drive).count
    for g, c in count.items():
        warn(
            f"group {plan.solvers[g].label}: its two assembly branches meet on the "
            "straight path from the reference pose to driver positions "
            f"{runs_text(plan, given, c > 0)} (a change point); the motion is carried "
            "through onto the branch whose velocities are continuous",
            AssurWarning,
            stacklevel=5,
        )
    return bool(count)
