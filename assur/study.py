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

import inspect
import itertools
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from assur._batch import CHUNK, near_change_points, stacked, summaries
from assur._drive import positions
from assur._loads import compile_loads
from assur._stack import Unstackable, signature
from assur._text import suggest
from assur._variants import Template, compile_many, form, numbers, template
from assur._vec import Array, integer
from assur.analysis import forces
from assur.errors import AssurError, AssurWarning, UsageError
from assur.model import Mechanism
from assur.plan import Plan, compile_plan

__all__ = ["Study", "sweep"]

Factory = Callable[..., Mechanism]
"""Builds one variant: ``factory(**parameters) -> Mechanism``."""


@dataclass(frozen=True)
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
            For a variant number that is not one of the study's, or a column that
            none of the variants analysed has.
        ImportError
            When xarray is not installed.
        """
        xr = _optional("xarray")
        chosen = _chosen(variants, len(self))
        found: list[dict[str, Array] | None] = []
        for i in chosen:
            found.append(
                _table(self.factory, _variant(self.parameters, i), self.angles)
            )
        names = _names(found) if columns is None else _known(list(columns), found)
        data = np.full((len(chosen), self.angles.shape[0], len(names)), np.nan)
        for row, table in enumerate(found):
            for j, name in enumerate(names):
                if table is not None and name in table:
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
    parameters: Mapping[str, Any],
    angles: Any,
    client: Any = None,
    *,
    partitions: int | None = None,
) -> Study:
    """Analyse many variants of a mechanism and summarise each over a sweep.

    Parameters
    ----------
    factory : callable
        ``factory(**p)`` returns the Mechanism of one variant; with ``client`` it
        must be picklable (a function of an importable module).
    parameters : mapping of str to array_like
        Each parameter's values, 1-D arrays of equal length: one variant per index.
    angles : array_like
        Driver positions of every variant's sweep, deg (m for a slider); shape (n,)
        or (n, drivers).
    client : dask.distributed.Client, optional
        Run the variants on this cluster's workers (each needs assur installed).
    partitions : int, optional
        Number of partitions with ``client`` (default: two per worker thread).

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
        a dask.distributed client or ``partitions`` that is not a positive integer.
    ImportError
        When pandas (or with ``client``, dask.distributed) is not installed.

    Notes
    -----
    A variant whose factory raises or returns something other than a Mechanism, or
    whose analysis raises an AssurError, is not fatal: its ``error`` says why, as
    ``assur.forces(factory(**p), angles)`` would have said. Variants that share a
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
    _optional("pandas")
    if client is None:
        table = summarise(factory, values, given)
    else:
        table = _distributed(client, factory, values, given, partitions)
    return Study(factory, values, given, table)


def summarise(
    factory: Factory, parameters: dict[str, Array], angles: Array, start: int = 0
) -> Any:
    """Return the summary DataFrame of variants numbered from ``start`` (one process).

    What :func:`sweep` runs, or each partition of it on a worker.
    """
    import pandas as pd

    count = len(next(iter(parameters.values())))
    frames = []
    size = max(1, min(CHUNK // max(1, angles.shape[0]), BLOCK // GROUPED))
    _keep_the_heap()
    templates: dict[Any, Template | None] = {}
    for first in range(0, count, GROUPED * size):
        block = range(first, min(first + GROUPED * size, count))
        rows = _block(factory, parameters, angles, block, templates, size)
        # a block's rows as columns: a dict per variant costs ten times as much
        frames.append(pd.DataFrame(rows, index=pd.RangeIndex(block.start, block.stop)))
    frame = ordered(pd.concat(frames), list(parameters))
    frame.index = pd.RangeIndex(start, start + count, name="variant")
    return frame


def ordered(frame: Any, parameters: list[str]) -> Any:
    """Return the summary ``frame`` with its columns in order.

    The parameters, the summary values in the order met, then ``error`` and
    ``warning``.
    """
    last = ["error", "warning"]
    rest = [c for c in frame.columns if c not in parameters and c not in last]
    return frame.reindex(columns=[*parameters, *rest, *last])


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
    for i in block:
        p = _variant(parameters, i)
        rows.append({**p, "error": "", "warning": ""})
        try:
            mech = _built(factory, p)
        except Exception as err:  # the factory's own error, recorded
            rows[-1]["error"] = _line(err)
            continue
        forms.setdefault(form(mech), []).append((i, mech))
    alone: list[tuple[int, Mechanism]] = []
    rest: list[tuple[int, Mechanism]] = []
    if angles.shape[0] > CHUNK:
        # a sweep longer than a batch: each variant summarised slice by slice
        forms = {None: [x for members in forms.values() for x in members]}
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
        for start in range(0, good.size, size):
            chosen = good[start : start + size]
            many = compiled.batch(chosen, angles.shape[0])
            part = near[start : start + size]
            found = summaries(many, model.plan, given, part)
            alone += _fill(rows, block.start, [members[i] for i in chosen], found)
    alone += _compiled(rows, block.start, rest, angles, size)
    for i, mech in alone:
        rows[i - block.start].update(_alone(mech, angles))
    return rows


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


def _alone(mech: Mechanism, angles: Array) -> dict[str, Any]:
    """Return one variant's summary from a call of its own, or why it failed.

    A sweep longer than a batch is summarised slice by slice, as the command line
    does: in bounded memory, with the numbers, errors and warnings of one call.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            if angles.shape[0] > CHUNK:
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
    from assur._sliced import Skipped, slices
    from assur.summary import Summary

    summary = Summary()
    for part in slices(mech, angles, True, False, Skipped()):
        summary.add(part.table)
    return dict(summary.result())


def _built(factory: Factory, p: dict[str, Any]) -> Mechanism:
    """Return the mechanism ``factory(**p)``, checked to be one.

    Raises
    ------
    UsageError
        When the factory returns something else.
    """
    mech = factory(**p)
    if not isinstance(mech, Mechanism):
        msg = (
            f"the factory returned {type(mech).__name__} for {_shown(p)}; expected "
            "an assur.Mechanism"
        )
        raise UsageError(msg)
    return mech


def _shown(p: dict[str, Any]) -> str:
    """Return a variant's parameters as text: ``rod=0.2, crank=0.07``."""
    return ", ".join(f"{name}={value!r}" for name, value in p.items())


def _table(factory: Factory, p: dict[str, Any], angles: Array) -> dict[str, Array]:
    """Return every column of one variant's force table; empty if it fails."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", AssurWarning)
        try:
            mech = _built(factory, p)
        except Exception:  # the factory's own error: the variant has no table
            return {}
        try:
            table = forces(mech, angles)
        except AssurError:
            return {}
    return dict(zip(table.columns, table.arrays(), strict=True))


def _names(tables: list[dict[str, Array] | None]) -> list[str]:
    """Return the columns of the tables, in the order they are first met."""
    out: dict[str, None] = {}
    for table in tables:
        out.update(dict.fromkeys(table or {}))
    return list(out)


def _known(names: list[str], tables: list[dict[str, Array] | None]) -> list[str]:
    """Return ``names``, checked against the columns of ``tables`` that have any.

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


def _chosen(variants: Sequence[int] | None, count: int) -> list[int]:
    """Return the variants' numbers, checked to be the study's (0 to count - 1).

    Raises
    ------
    UsageError
        For a number that is not an integer from 0 to ``count - 1``.
    """
    if variants is None:
        return list(range(count))
    out = []
    for given in variants:
        i = integer(given)
        if i is None:
            msg = f"variants: expected variant numbers, got {given!r}"
            raise UsageError(msg)
        if not 0 <= i < count:
            msg = f"variants: no variant {i}; expected numbers from 0 to {count - 1}"
            raise UsageError(msg)
        out.append(i)
    return out


def _takes(factory: Factory, parameters: dict[str, Array]) -> None:
    """Check that ``factory`` takes the parameters by name, before any variant.

    A callable whose signature cannot be read is left to its calls.

    Raises
    ------
    UsageError
        When the factory is not callable or does not take these parameters.
    """
    if not callable(factory):
        msg = f"factory: expected a function returning a Mechanism, got {factory!r}"
        raise UsageError(msg)
    try:
        signature = inspect.signature(factory)
    except (TypeError, ValueError):
        return
    try:
        signature.bind(**dict.fromkeys(parameters, 0.0))
    except TypeError as err:
        name = getattr(factory, "__qualname__", type(factory).__name__)
        kind = inspect.Parameter
        by_name = (kind.POSITIONAL_OR_KEYWORD, kind.KEYWORD_ONLY)
        takes = [p.name for p in signature.parameters.values() if p.kind in by_name]
        msg = (
            f"parameters: the factory {name} {err}; expected its parameters "
            f"({', '.join(takes) or 'none by name'})"
        )
        raise UsageError(msg) from None


def _optional(module: str) -> Any:
    """Import an optional dependency of studies, saying how to install it."""
    from assur._optional import optional

    return optional(module, "a study", "study")


def _line(err: BaseException) -> str:
    """Return an error as one line: its class and its message."""
    return f"{type(err).__name__}: {' '.join(str(err).split())}"


def _variant(parameters: dict[str, Array], i: int) -> dict[str, Any]:
    """Return the parameters of variant ``i`` (Python floats, ints or bools)."""
    return {name: values[i].item() for name, values in parameters.items()}


RESERVED = (
    "error",
    "warning",
    "variant",
    "position",
    "column",
    "values",
    "driver",
    "efficiency",
)
"""Names of the summary's and the tables' own columns and dimensions."""


def _parameters(parameters: Mapping[str, Any]) -> dict[str, Array]:
    """Check the parameters; return them as read-only float arrays."""
    if not isinstance(parameters, Mapping) or not parameters:
        msg = (
            "parameters: expected a mapping of names to 1-D arrays (one value per "
            f"variant), got {type(parameters).__name__}"
            f"{' (empty)' if isinstance(parameters, Mapping) else ''}"
        )
        raise UsageError(msg)
    out: dict[str, Array] = {}
    for name, values in parameters.items():
        if not isinstance(name, str) or not name.isidentifier():
            msg = f"parameters: expected names that are identifiers, got {name!r}"
            raise UsageError(msg)
        if name in RESERVED:
            msg = (
                f"parameters: {name!r} names a column of the study's results; "
                f"expected another name (not {', '.join(RESERVED)})"
            )
            raise UsageError(msg)
        try:
            arr = np.array(values)
        except (TypeError, ValueError) as err:
            msg = f"parameters.{name}: expected a 1-D array of real numbers"
            raise UsageError(msg) from err
        if arr.dtype.kind not in "biuf" or arr.ndim != 1 or not arr.size:
            what = f"shape {arr.shape}" if arr.dtype.kind in "biuf" else str(arr.dtype)
            msg = f"parameters.{name}: expected a 1-D array of real numbers, got {what}"
            raise UsageError(msg)
        # counts and choices stay integers; the rest are floats
        out[name] = arr.astype(float) if arr.dtype.kind == "f" else arr.copy()
        out[name].flags.writeable = False
    lengths = {name: len(v) for name, v in out.items()}
    if len(set(lengths.values())) > 1:
        told = ", ".join(f"{name} {n}" for name, n in lengths.items())
        msg = (
            "parameters: expected arrays of one length (one value per variant), "
            f"got {told}"
        )
        raise UsageError(msg)
    return out


def _angles(angles: Any) -> Array:
    """Check the driver positions; return them as a read-only float array."""
    try:
        arr = np.array(angles, dtype=float)
    except (TypeError, ValueError) as err:
        msg = (
            "angles: expected real numbers (driver positions), got "
            f"{type(angles).__name__}"
        )
        raise UsageError(msg) from err
    if arr.ndim not in (1, 2) or not arr.shape[0]:
        msg = (
            "angles: expected driver positions of shape (n,) or (n, drivers), got "
            f"shape {arr.shape}"
        )
        raise UsageError(msg)
    if not np.all(np.isfinite(arr)):
        bad = float(arr[~np.isfinite(arr)].flat[0])
        msg = f"angles: expected finite driver positions, got {bad!r} among them"
        raise UsageError(msg)
    arr.flags.writeable = False
    return arr


def _distributed(
    client: Any,
    factory: Factory,
    parameters: dict[str, Array],
    angles: Array,
    partitions: int | None,
) -> Any:
    """Run the variants in partitions on a dask.distributed cluster; one DataFrame."""
    import pandas as pd

    _optional("distributed")
    if not all(callable(getattr(client, f, None)) for f in ("submit", "gather")):
        msg = f"client: expected a dask.distributed Client, got {client!r}"
        raise UsageError(msg)
    if partitions is not None and (integer(partitions) or 0) < 1:
        msg = f"partitions: expected a positive number, got {partitions!r}"
        raise UsageError(msg)
    count = len(next(iter(parameters.values())))
    if partitions is None:
        threads = sum(client.nthreads().values()) or 1
        partitions = 2 * threads
    bounds = np.linspace(0, count, min(count, max(1, partitions)) + 1).astype(int)
    futures = [
        client.submit(
            summarise,
            factory,
            {name: v[a:b] for name, v in parameters.items()},
            angles,
            int(a),
            pure=False,
        )
        for a, b in itertools.pairwise(bounds)
    ]
    # partitions of other topologies bring their own columns: ordered as one run's
    return ordered(pd.concat(client.gather(futures)), list(parameters))
