"""A study's variants solved together in stacks, once built.

The template of a form, compiled once; the variants it does not serve, compiled one
by one and stacked by signature (``assur._stack``); their summaries put in their
rows. The C heap kept between batches.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._batch import stacked, summaries
from assur._drive import positions
from assur._loads import compile_loads
from assur._stack import Unstackable, signature
from assur._variants import Template, template
from assur._vec import Array
from assur.errors import AssurError
from assur.model import Mechanism
from assur.plan import Plan, compile_plan


def _template(
    templates: dict[Any, Template | None],
    key: Any,
    members: list[tuple[int, Mechanism]],
    rest: list[tuple[int, Mechanism]],
) -> Template | None:
    """Return the template of the form ``key``, compiling one of ``members`` if new.

    A member that does not compile moves to ``rest`` (compiled again there, it fails
    as a separate call does); None when the form's plans cannot be stacked (every
    member is then analysed on its own) or when no member compiles.
    """
    if key in templates:
        return templates[key]
    while members:
        try:
            model = template(members[0][1])
        except AssurError:
            rest.append(members.pop(0))
            continue
        if len(templates) >= 64:
            templates.clear()
        templates[key] = model
        return model
    return None


def _compiled(
    rows: list[dict[str, Any]],
    start: int,
    members: list[tuple[int, Mechanism]],
    angles: Array,
    size: int,
) -> list[tuple[int, Mechanism]]:
    """Solve ``members`` each compiled on its own, those of one signature stacked.

    Batches hold at most ``size`` variants. Returns the members to be analysed alone.
    """
    groups: dict[Any, list[tuple[int, Mechanism, Plan]]] = {}
    alone: list[tuple[int, Mechanism]] = []
    for i, mech in members:
        try:
            plan = compile_plan(mech)
            loads = compile_loads(plan)
            key = None if loads.empty else signature(plan, loads)
        except AssurError:
            key = None
        if key is None:
            alone.append((i, mech))
        else:
            groups.setdefault(key, []).append((i, mech, plan))
    for every in groups.values():
        for first in range(0, len(every), size):
            alone += _stacked(rows, start, every[first : first + size], angles)
    return alone


def _stacked(
    rows: list[dict[str, Any]],
    start: int,
    group: list[tuple[int, Mechanism, Plan]],
    angles: Array,
) -> list[tuple[int, Mechanism]]:
    """Solve the variants ``group``, of one signature, stacked; return those left."""
    plans = [plan for _, _, plan in group]
    try:
        found = summaries(
            stacked(plans, angles.shape[0]), plans[0], positions(plans[0], angles)
        )
    except Unstackable:
        found = [None] * len(plans)
    return _fill(rows, start, [(i, m) for i, m, _ in group], found)


def _fill(
    rows: list[dict[str, Any]],
    start: int,
    members: list[tuple[int, Mechanism]],
    found: list[dict[str, float] | None],
) -> list[tuple[int, Mechanism]]:
    """Put each member's summary in its row; return those without one."""
    alone = []
    for (i, mech), values in zip(members, found, strict=True):
        if values is None:
            alone.append((i, mech))
        else:
            rows[i - start].update(values)
    return alone


HEAP = 2 * 1024 * 1024
"""Values in the block freed once before a study (16 MB; see ``_keep_the_heap``)."""


def _keep_the_heap() -> None:
    """Free one large block, so that the C allocator keeps the batches' memory.

    glibc's malloc gives the free top of its heap back to the system whenever it
    exceeds a trim threshold (128 kB until a block served by mmap is freed; then
    twice that block's size). A study's batches allocate and free a few MB of
    temporaries each, and never a large array: every batch faulted its pages in
    again (measured on 10^4 variants: 730 000 page faults, 2 s of system time, a
    third of the study). A long sweep escapes this by freeing its large arrays;
    freeing one such block (never written) does the same. Elsewhere it costs an
    allocation.
    """
    block = np.empty(HEAP)
    del block
