"""A study's variants solved together in stacks, once built, or each alone.

The template of a form, compiled once; the variants it does not serve, compiled one
by one and stacked by signature (``assur._stack``); their summaries put in their
rows, with the warnings a separate call gives; the variants left, analysed alone.
The C heap kept between batches.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur._batch import stacked, summaries
from assur._drive import positions
from assur._loads import compile_loads, massless_texts
from assur._metres import metres_text
from assur._stack import Unstackable, signature
from assur._variants import Template, template
from assur._vec import Array
from assur._warn import held
from assur.analysis import forces
from assur.errors import AssurError, AssurWarning
from assur.model import Mechanism
from assur.plan import Plan, compile_plan, drawn_size


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


PACE = 1.0
"""Seconds a block of variants should take at most, so that progress is told."""


def paced(done: int, took: float, least: int, most: int) -> int:
    """Return the variants of the next block, from the last's ``done`` in ``took`` s.

    ``most`` (a few batches, up to 4096 variants) when they take less than
    :data:`PACE`, fewer down to ``least`` (one batch) when the factory is slow: a
    progress bar was told once a block, and a factory of 2 ms a variant left it
    still for 8 s. The numbers do not depend on the blocks: each variant's are
    those of a separate call.
    """
    fit = int(done * PACE / took) if took > 0.0 else most
    return max(least, min(most, fit))


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


def told(
    rows: list[dict[str, Any]],
    start: int,
    built: list[tuple[int, Mechanism]],
    batched: set[int],
) -> None:
    """Put in each row the warnings compiling its variant gives a separate call.

    A plan is compiled once per mechanism (cached) and a template once per form:
    their warnings reached the first call alone, or none of the variants batched
    against it. Said again here, first in each row, as a separate call says them.
    A variant batched against a template is not large enough to be warned of its
    size (``compile_many`` compiles those on their own).
    """
    for i, mech in built:
        notes = massless_texts(mech)
        if i not in batched:
            try:
                size = metres_text(drawn_size(mech))
            except AssurError:  # its error is in the row
                size = None
            notes = ([size] if size else []) + notes
        row = rows[i - start]
        said = [s for s in row["warning"].split(" | ") if s]
        notes = [" ".join(s.split()) for s in notes]
        row["warning"] = " | ".join(notes + [s for s in said if s not in notes])


def _alone(mech: Mechanism, angles: Array, long: bool) -> dict[str, Any]:
    """Return one variant's summary from a call of its own, or why it failed.

    A ``long`` sweep (longer than a batch) is summarised slice by slice, as the
    command line does: in bounded memory, with the numbers, errors and warnings of
    one call.
    """
    with held() as caught:
        try:
            if long:
                out: dict[str, Any] = _summed(mech, angles)
            else:
                out = dict(forces(mech, angles).summary())
        except AssurError as err:
            out = {"error": _line(err)}
    said = [str(w.message) for w in caught if issubclass(w.category, AssurWarning)]
    if said:
        out["warning"] = " | ".join(" ".join(s.split()) for s in said)
    return out


def _summed(mech: Mechanism, angles: Array) -> dict[str, Any]:
    """Return the summary of a long sweep, computed a slice of positions at a time."""
    from assur._skipped import Skipped
    from assur._sliced import slices
    from assur.summary import Summary

    summary = Summary()
    for part in slices(mech, angles, True, False, Skipped()):
        summary.add(part.table)
    return dict(summary.result())


def _line(err: BaseException) -> str:
    """Return an error as one line: its class and its message."""
    said = " ".join(str(err).split())
    return f"{type(err).__name__}: {said}" if said else type(err).__name__
