"""A study's full tables: one variant's force table, the variants and columns chosen.

What :meth:`assur.study.Study.tables` computes on demand, variant by variant; and
the order of the summary's columns, one process's or many partitions'.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

import numpy as np

from assur._listed import listed
from assur._study_inputs import Factory, _built, _variant
from assur._text import describe, suggest
from assur._vec import Array, integer
from assur._warn import held
from assur.analysis import forces
from assur.errors import AssurError, UsageError


def _tables(
    factory: Factory,
    parameters: dict[str, Array],
    angles: Array,
    chosen: Sequence[int],
    wanted: Sequence[str] | None,
) -> tuple[list[dict[str, Array]], list[tuple[str, ...]]]:
    """Return the tables of the variants ``chosen`` and the columns each has.

    Refused once the first table's columns are known, if all of them would not fit
    in half the memory to be had (they are kept, then copied into one array).
    """
    found: list[dict[str, Array]] = []
    every: list[tuple[str, ...]] = []
    for i in chosen:
        table, has = _table(factory, _variant(parameters, i), angles, wanted)
        if has and not any(every):
            _fits(len(chosen), angles.shape[0], len(has if wanted is None else wanted))
        found.append(table)
        every.append(has)
    return found, every


def _fits(variants: int, positions: int, columns: int) -> None:
    """Refuse tables whose values would take more than half the memory to be had."""
    need = 2.0 * variants * positions * columns * 8.0
    found = _memory()
    if found is None:  # no such count here: not checked
        return
    have, whose = found
    if need > 0.5 * have:
        msg = (
            f"variants: {variants} tables of {positions} positions x {columns} "
            f"columns would take {need / 1e9:.3g} GB, more than half {whose} "
            f"{have / 1e9:.3g} GB; expected fewer variants (variants=[...]) or "
            "columns (columns=[...])"
        )
        raise UsageError(msg)


CGROUPS = "/sys/fs/cgroup"
"""Where the control groups are mounted."""
OWN_GROUPS = "/proc/self/cgroup"
"""This process's control groups, one line each: ``0::/path`` (v2) or
``N:memory:/path`` (v1)."""


def _limits() -> list[str]:
    """Return the files that may hold a memory limit on this process (cgroups).

    Its own group's and every group above it (a limit on a parent holds for all
    below), v2's ``memory.max`` and v1's ``memory.limit_in_bytes``; the mount's
    root too, which is the process's own group in a container.
    """
    paths = [f"{CGROUPS}/memory.max", f"{CGROUPS}/memory/memory.limit_in_bytes"]
    try:
        with open(OWN_GROUPS, encoding="utf-8") as file:
            lines = file.read().splitlines()
    except (OSError, ValueError):  # not Linux
        return paths
    for line in lines:
        _, controllers, path = [*line.split(":", 2), "", ""][:3]
        if controllers == "":
            base, name = CGROUPS, "memory.max"
        elif "memory" in controllers.split(","):
            base, name = f"{CGROUPS}/memory", "memory.limit_in_bytes"
        else:
            continue
        parts = [p for p in path.split("/") if p]
        for depth in range(len(parts), 0, -1):
            paths.append("/".join([base, *parts[:depth], name]))
    return paths


def _memory() -> tuple[float, str] | None:
    """Return the memory this process may take (bytes) and whose it is, in words.

    The machine's physical memory, or less: a container's limit (a cgroup's), or
    the process's own address-space limit (``ulimit -v``), which a process meets
    long before the machine runs out. None where none of these can be read.
    """
    found: list[tuple[float, str]] = []
    try:
        pages = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
        found.append((float(pages), "this machine's"))
    except (AttributeError, ValueError, OSError):
        pass
    for path in _limits():
        try:
            with open(path, encoding="ascii") as file:
                text = file.read().strip()
        except (OSError, ValueError):  # no such limit here
            continue
        if text.isdigit():  # "max" where there is none
            found.append((float(text), "its control group's limit of"))
    try:
        import resource

        soft = resource.getrlimit(resource.RLIMIT_AS)[0]
        if soft != resource.RLIM_INFINITY and soft > 0:
            found.append((float(soft), "this process's limit of"))
    except (ImportError, AttributeError, ValueError, OSError):  # not on Windows
        pass
    return min(found, key=lambda pair: pair[0]) if found else None


def _table(
    factory: Factory, p: dict[str, Any], angles: Array, wanted: Sequence[str] | None
) -> tuple[dict[str, Array], tuple[str, ...]]:
    """Return one variant's force table's columns ``wanted`` (all by default).

    Also the names of every column it has. Empty if the variant fails. Only the
    columns wanted are computed and kept: a study's tables hold no more than the
    Dataset asked for.
    """
    with held():  # the study's summary told them, variant by variant
        try:
            mech = _built(factory, p)
        except Exception:  # the factory's own error: the variant has no table
            return {}, ()
        try:
            table = forces(mech, angles)
        except AssurError:
            return {}, ()
        if wanted is None:
            return dict(zip(table.columns, table.arrays(), strict=True)), table.columns
        return {c: table[c] for c in wanted if c in table}, table.columns


def _columns(
    wanted: list[str] | None,
    tables: Sequence[Sequence[str]],
    chosen: Sequence[int],
    errors: Any,
) -> list[str]:
    """Return the columns of the Dataset: ``wanted``, checked, or every one found.

    ``tables`` holds each chosen variant's column names (none for one that
    fails) and ``errors`` the summary's ``error`` column.

    Raises
    ------
    UsageError
        For a name that no table has, or, without ``wanted``, when no chosen
        variant was analysed: a Dataset without a column said nothing of why.
    """
    if wanted is not None:
        return _known(wanted, tables)
    if chosen and not any(tables):
        first = chosen[0]
        why = str(errors.loc[first]) or "it failed when analysed again"
        msg = (
            f"variants: none of the {len(chosen)} asked for was analysed (variant "
            f"{first}: {why}); expected a variant with a table, or columns=[...] "
            "for NaN tables"
        )
        raise UsageError(msg)
    return _names(tables)


def _names(tables: Sequence[Sequence[str]]) -> list[str]:
    """Return the columns of the tables' names, in the order they are first met."""
    out: dict[str, None] = {}
    for names in tables:
        out.update(dict.fromkeys(names))
    return list(out)


def _known(names: list[str], tables: Sequence[Sequence[str]]) -> list[str]:
    """Return ``names``, checked against the columns of the tables that have any.

    ``tables`` holds each table's column names.

    Raises
    ------
    UsageError
        For a name that no table has (when some variant was analysed).
    """
    found = _names(tables)
    if found:
        for name in names:
            if name not in found:
                msg = (
                    f"columns: no column {name!r} in the variants analysed"
                    f"{suggest(name, found, listing=False)}"
                )
                raise UsageError(msg)
    return names


def _wanted(columns: Sequence[str] | None) -> list[str] | None:
    """Return the columns asked for as a list (None for all), a lone name refused.

    Raises
    ------
    UsageError
        For one name given as a string, which was walked letter by letter: "no
        column 'B'" for ``columns="B.Fx"``.
    """
    if columns is None:
        return None
    if isinstance(columns, str | bytes):
        msg = (
            f"columns: expected a sequence of column names, got {describe(columns)}; "
            f"write columns=[{describe(columns)}] for one column"
        )
        raise UsageError(msg)
    return listed(columns, "columns", "column")


def _chosen(variants: Sequence[int] | None, count: int) -> list[int]:
    """Return the variants' numbers, checked to be the study's (0 to count - 1).

    Raises
    ------
    UsageError
        For a number that is not an integer from 0 to ``count - 1``.
    """
    if variants is None:
        return list(range(count))
    if isinstance(variants, str | bytes) or np.ndim(variants) == 0:
        # a lone number or a name: not walked digit by digit or letter by letter
        msg = (
            f"variants: expected a sequence of variant numbers, got "
            f"{describe(variants)}"
        )
        raise UsageError(msg)
    out = []
    for given in variants:
        i = integer(given)
        if i is None:
            msg = f"variants: expected variant numbers, got {describe(given)}"
            raise UsageError(msg)
        if not 0 <= i < count:
            msg = f"variants: no variant {i}; expected numbers from 0 to {count - 1}"
            raise UsageError(msg)
        out.append(i)
    return out


def ordered(frame: Any, parameters: list[str]) -> Any:
    """Return the summary ``frame`` with its columns in order.

    The parameters, the summary values in the order met, then ``error`` and
    ``warning``.
    """
    last = ["error", "warning"]
    rest = [c for c in frame.columns if c not in parameters and c not in last]
    return frame.reindex(columns=[*parameters, *rest, *last])
