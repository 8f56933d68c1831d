"""Columns kept by a table: read-only for good, whatever holds their memory.

A column computed from a table's states is a state's own array, a constant, or a row
of a block of columns computed together; :func:`keep` makes each read-only so that
no later call can make it writeable again.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from assur._vec import Array, set_writeable

__all__ = ["keep"]


def keep(
    found: dict[str, Array], index: Mapping[str, object], cache: dict[str, Array]
) -> None:
    """Put the columns ``found`` that ``index`` names into ``cache``, read-only.

    Every array that owns the memory of one of ``found`` (a block of columns
    computed together) is made read-only: a view's flag could else be set back.
    A column that owns its memory (a state's array) is kept as a read-only view,
    whose flag cannot be set back while the array's is not. A column already in
    ``cache`` is kept as it was.
    """
    # the rows of a block share its owner: its flag is looked at once
    seen: set[int] = set()
    for key, values in found.items():
        base = values.base
        if base is None:
            set_writeable(values, False)
            if key in index and key not in cache:
                # a view of a read-only array is read-only, and cannot be made
                # writeable again
                cache[key] = values.view()
            continue
        if id(base) not in seen:
            seen.add(id(base))
            if isinstance(base, np.ndarray) and base.flags.writeable:
                while isinstance(base.base, np.ndarray):
                    base = base.base
                set_writeable(base, False)
        if key in index and key not in cache:
            # a view made for this column (a row of a block): its owner is
            # read-only now, so its own flag is set once, with no new view
            set_writeable(values, False)
            cache[key] = values
