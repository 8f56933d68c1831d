"""Values that are not finite where no failed position explains them: a warning.

An overflow, or a force system singular without a group failing, sends NaN or inf
through a sweep's states; the warning names the links and joints it reaches and
the positions.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._quiet import quiet
from assur._runs import positions_where
from assur._text import listing
from assur._troubles import NOTICES
from assur._vec import Array, is_array
from assur._warn import warn
from assur.errors import AssurWarning
from assur.plan import Plan

__all__ = ["_unexplained"]


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
    # or inf - inf, sends the search below, which looks at each); summed in place
    # into one array of a position each: the arrays laid end to end and summed in
    # one call were a copy of the whole slice, out of the cache (a long four-bar
    # sweep with every column read took 11 % longer)
    with quiet():
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
        warn(
            f"values of {listing(named)} are "
            f"not finite at {positions_where(plan, given, bad)}, where no "
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
