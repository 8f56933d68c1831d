"""Studies: many variants of a mechanism, each summarised over a sweep.

:func:`sweep` builds every variant from its parameters, solves the variants of one
form together in batches (``assur._batch``) and gathers one row of summary values
per variant (:meth:`Table.summary <assur.analysis.Table.summary>`). A batch's plan
is compiled at once from the variants' numbers against a template, one compiled
variant of the form (``assur._variants``): compiling each variant's plan on its own
cost more than solving its positions. Variants the template does not serve are
compiled one by one and stacked (``assur._stack``), or analysed alone. With a
dask.distributed client the variants are split into partitions that the cluster's
workers run. pandas, xarray and dask are imported only when a study needs them.
"""

from __future__ import annotations

import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from assur import _text
from assur._batch import CHUNK, near_change_points, summaries
from assur._drive import positions
from assur._progress import Callback, Progress
from assur._progress import progress as counted
from assur._study_inputs import (
    RESERVED as RESERVED,  # still assur.study.RESERVED, the names refused
)
from assur._study_inputs import (
    Factory,
    _angles,
    _built,
    _fitting,
    _optional,
    _parameters,
    _partitions,
    _takes,
    _variant,
)
from assur._study_stacks import (
    _alone,
    _compiled,
    _fill,
    _keep_the_heap,
    _line,
    _template,
    paced,
    told,
)
from assur._study_tables import _chosen, _columns, _tables, _wanted, ordered
from assur._variants import Template, compile_many, form, numbers
from assur._vec import Array
from assur._warn import held
from assur.errors import AssurError
from assur.model import Mechanism

if TYPE_CHECKING:
    from pandas import DataFrame

__all__ = ["Study", "sweep"]


# compared by identity, as a Table is: the generated == compared the parameters'
# arrays and the summary's DataFrame, and raised numpy's "truth value ... ambiguous"
@dataclass(frozen=True, eq=False)
class Study:
    """The summaries of a study's variants, and the means to recompute their tables.

    Attributes
    ----------
    factory : callable
        ``factory(**p)`` builds the mechanism of the variant with parameters ``p``.
    parameters : dict of str to ndarray
        The parameters, one value per variant (read-only arrays of equal length).
    angles : ndarray
        The driver positions of every variant's sweep, deg (m for a slider).
    summary : pandas.DataFrame
        One row per variant, indexed by the variant's number: its parameters, its
        summary values (NaN for a variant without them) and ``error``, the one-line
        reason a variant could not be built or analysed (empty when it could), and
        ``warning``, the warnings its analysis gave (empty when none). When no
        variant could be analysed there are no summary values: the parameters,
        ``error`` and ``warning`` alone.
    """

    factory: Factory
    parameters: dict[str, Array]
    angles: Array
    summary: Any = field(repr=False)

    def __len__(self) -> int:
        return len(self.summary)

    def __repr__(self) -> str:
        # the dataclass's repr spelt out every parameter's values and the angles
        failed = int((self.summary["error"] != "").sum())
        names = ", ".join(self.parameters) or "no parameters"
        n = len(self.angles)
        return (
            f"<assur.Study: {_text.counted(len(self), 'variant')} of {names}, "
            f"{_text.counted(n, 'position')} each, {failed} failed>"
        )

    def tables(
        self,
        variants: Sequence[int] | None = None,
        columns: Sequence[str] | None = None,
    ) -> Any:
        """Return the full force tables of some variants as an xarray Dataset.

        Each variant is analysed again on its own (compute on demand: the tables of
        a large study do not fit in memory; choose ``variants``).

        Parameters
        ----------
        variants : sequence of int, optional
            The variants' numbers; all of them by default.
        columns : sequence of str, optional
            The columns; every column of the variants analysed by default.

        Returns
        -------
        xarray.Dataset
            ``values`` with dimensions (variant, position, column), NaN for a variant
            that fails and a column it lacks; the parameters are coordinates along
            ``variant``, and ``angle`` holds the driver positions along ``position``
            (deg, or m for a slider; dimensions (position, driver) with several
            drivers) unless a parameter is called so.

        Raises
        ------
        UsageError
            For a variant number not the study's, a column none of the variants
            analysed has, ``columns`` as one string, no variant analysed without
            ``columns`` (no column known), or tables that would take more than half
            the memory to be had (the machine's, a container's, ``ulimit -v``).
        ImportError
            When xarray is not installed.
        """
        xr = _optional("xarray")
        chosen = _chosen(variants, len(self))
        wanted = _wanted(columns)
        found, every = _tables(
            self.factory, self.parameters, self.angles, chosen, wanted
        )
        names = _columns(wanted, every, chosen, self.summary["error"])
        data = np.full((len(chosen), self.angles.shape[0], len(names)), np.nan)
        for row, table in enumerate(found):
            for j, name in enumerate(names):
                if name in table:
                    data[row, :, j] = table[name]
        angles = self.angles
        along = ("position",) if angles.ndim == 1 else ("position", "driver")
        coords: dict[str, Any] = {
            "variant": chosen,
            "position": np.arange(angles.shape[0]),
            "column": names,
        }
        for name, values in self.parameters.items():
            coords[name] = ("variant", values[chosen])
        # the driver positions, unless a parameter took the name
        coords.setdefault("angle", (along, angles))
        return xr.Dataset(
            {"values": (("variant", "position", "column"), data)}, coords=coords
        )


def sweep(
    factory: Factory,
    parameters: Mapping[str, ArrayLike] | DataFrame,
    angles: ArrayLike,
    client: Any = None,
    *,
    partitions: int | None = None,
    progress: bool | Callback = False,
) -> Study:
    """Analyse many variants of a mechanism and summarise each over a sweep.

    Parameters
    ----------
    factory : callable
        ``factory(**p)`` returns the Mechanism of one variant. With ``client`` it
        is sent to the workers with cloudpickle: a function of a module is sent by
        name (the workers must import that module), one defined in a script or a
        notebook (a lambda too) by value; whatever it calls must be importable on
        the workers.
    parameters : mapping of str to array_like, or pandas.DataFrame
        Each parameter's values, 1-D arrays of equal length: one variant per index
        (paired by position: pandas Series of different indexes are refused). A
        DataFrame gives its columns, one row a variant.
    angles : array_like
        Driver positions of every variant's sweep, deg (m for a slider); shape (n,)
        or (n, drivers).
    client : dask.distributed.Client, optional
        Run the variants on this cluster's workers (each needs assur installed).
    partitions : int, optional
        Number of partitions with ``client`` (default: two per worker thread).
    progress : bool or callable, optional
        Show a progress bar of the variants done on standard error (True), or call
        ``progress(done, total)`` as they are (counted by blocks of a batch or
        more, about a second each at most, or by partition with ``client``).

    Returns
    -------
    Study
        ``Study.summary`` has one row per variant (see :class:`Study`).

    Raises
    ------
    UsageError
        For parameters that are not equal-length 1-D arrays of real numbers, that
        the factory does not take or that are named as a column of the summary
        (``error``, ``warning``, ``variant``, ``efficiency``) or of
        :meth:`Study.tables` (``position``, ``column``, ``values``, ``driver``);
        driver positions that are not finite real numbers; a ``client`` that is not
        a dask.distributed client or is closed, or ``partitions`` that is not a
        positive integer.
    ImportError
        When pandas (or with ``client``, dask.distributed) is not installed.

    Notes
    -----
    A variant whose factory raises or returns something other than a Mechanism, or
    whose analysis raises an AssurError, is not fatal: its ``error`` says why, as
    ``assur.forces(factory(**p), angles)`` would have said. A variant that ends its
    process ends a study without ``client``; with one, the rows of its partition say
    ``KilledWorker: ...`` once dask gives the partition up (``docs/study.rst``,
    "On a cluster"), the others are kept. Variants that share a
    topology are solved together, the plan's structure once and their numbers
    stacked over variants x positions. Integer and boolean parameters reach the
    factory as Python ints and bools, the others as floats.

    Examples
    --------
    >>> from assur import catalog
    >>> study = sweep(catalog.slider_crank, {"rod": [0.2, 0.25]}, range(0, 360, 10))
    >>> study.summary["driver.torque.max"].round(1).tolist()
    [90.9, 81.0]
    """
    values = _parameters(parameters)
    _takes(factory, values)
    given = _angles(angles)
    _partitions(partitions)
    _optional("pandas")
    if client is not None:
        from assur._study_cluster import ready

        ready(client, factory)
    count = len(next(iter(values.values())))
    # the bar made first: it checks ``progress``, before any variant is built
    with counted("variants", count, progress) as bar:
        _fitting(factory, values, given)
        if client is None:
            table = summarise(factory, values, given, bar=bar)
        else:
            from assur._study_cluster import _distributed

            run = (summarise, factory, values, given)
            table = _distributed(client, run, partitions, bar)
    return Study(factory, values, given, table)


def summarise(
    factory: Factory,
    parameters: dict[str, Array],
    angles: Array,
    start: int = 0,
    bar: Progress | None = None,
) -> Any:
    """Return the summary DataFrame of variants numbered from ``start`` (one process).

    What :func:`sweep` runs, or each partition of it on a worker; ``bar`` is told
    of each block of variants done (see :func:`assur._study_stacks.paced`).
    """
    import pandas as pd

    count = len(next(iter(parameters.values())))
    frames = []
    size = max(1, min(CHUNK // max(1, angles.shape[0]), BLOCK // GROUPED))
    templates: dict[Any, Template | None] = {}
    _keep_the_heap()
    first, step = 0, size  # one batch first, which times the factory
    while first < count:
        block = range(first, min(first + step, count))
        began = time.monotonic()
        rows = _block(factory, parameters, angles, block, templates, size)
        # a block's rows as columns: a dict per variant costs ten times as much
        frames.append(pd.DataFrame(rows, index=pd.RangeIndex(block.start, block.stop)))
        if bar is not None:
            bar.advance(len(block))
        step = paced(len(block), time.monotonic() - began, size, GROUPED * size)
        first = block.stop
    frame = ordered(pd.concat(frames), list(parameters))
    frame.index = pd.RangeIndex(start, start + count, name="variant")
    return frame


GROUPED = 8
"""Batches of variants built and compiled together: the checks of a compilation cost
about as much for a few hundred variants as for the few dozen of one batch."""
BLOCK = 4096
"""Most variants built at once (their mechanisms and rows are held together)."""


def _block(
    factory: Factory,
    parameters: dict[str, Array],
    angles: Array,
    block: range,
    templates: dict[Any, Template | None],
    size: int,
) -> list[dict[str, Any]]:
    """Return the rows of the variants ``block``, those of one form batched.

    The variants of one :func:`assur._variants.form` are compiled at once against
    its template (kept in ``templates`` from block to block) and solved in batches
    of ``size`` variants; those the template does not serve are compiled one by one
    and stacked (:func:`_compiled`).
    """
    rows: list[dict[str, Any]] = []
    forms: dict[Any, list[tuple[int, Mechanism]]] = {}
    built: list[tuple[int, Mechanism]] = []
    batched: set[int] = set()
    for i in block:
        p = _variant(parameters, i)
        rows.append({**p, "error": "", "warning": ""})
        try:
            mech = _built(factory, p)
        except Exception as err:  # the factory's own error, recorded
            rows[-1]["error"] = _line(err)
            continue
        forms.setdefault(form(mech), []).append((i, mech))
        built.append((i, mech))
    if angles.shape[0] > CHUNK:
        # a sweep longer than a batch: each variant summarised slice by slice
        forms = {None: [x for members in forms.values() for x in members]}
    # compilations' warnings are said in each row they concern (told), not here
    with held():
        alone = _batched(rows, block.start, forms, templates, angles, size, batched)
    for i, mech in alone:
        rows[i - block.start].update(_alone(mech, angles, angles.shape[0] > CHUNK))
    told(rows, block.start, built, batched)
    return rows


def _batched(
    rows: list[dict[str, Any]],
    offset: int,
    forms: dict[Any, list[tuple[int, Mechanism]]],
    templates: dict[Any, Template | None],
    angles: Array,
    size: int,
    batched: set[int],
) -> list[tuple[int, Mechanism]]:
    """Solve the variants ``forms`` in batches; return those to be analysed alone.

    ``rows`` holds the variants from number ``offset`` on; those summarised against
    a template are added to ``batched``.
    """
    alone: list[tuple[int, Mechanism]] = []
    rest: list[tuple[int, Mechanism]] = []
    for key, members in forms.items():
        if key is None or (key not in templates and len(members) == 1):
            # a form of one variant (one crank speed of a study over speeds, say)
            # costs a template's compilation and a batch: a separate call is less
            alone += members
            continue
        model = _template(templates, key, members, rest)
        if model is None or model.loads.empty:
            # a form without loads fails as a separate call does: analysed alone
            alone += members
            continue
        try:
            given = positions(model.plan, angles)
        except AssurError:
            # angles of another shape than the drivers': each says so alone
            alone += members
            continue
        table = np.array([numbers(mech) for _, mech in members])
        compiled, doubtful = compile_many(model, table)
        rest += [x for x, d in zip(members, doubtful.tolist(), strict=True) if d]
        good = np.flatnonzero(~doubtful)
        if not good.size:
            continue
        # the change-point screen of every batch at once (its cost is mostly per call)
        near = near_change_points(compiled.screen(good), model.plan, given)
        for first in range(0, good.size, size):
            chosen = [members[i] for i in good[first : first + size]]
            many = compiled.batch(good[first : first + size], angles.shape[0])
            part = near[first : first + size]
            found = summaries(many, model.plan, given, part)
            left = _fill(rows, offset, chosen, found)
            batched.update(i for i, _ in chosen)
            batched.difference_update(i for i, _ in left)
            alone += left
    return alone + _compiled(rows, offset, rest, angles, size)
