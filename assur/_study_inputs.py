"""A study's inputs: its parameters, driver positions and factory, checked.

What :func:`assur.study.sweep` is given is checked here before any variant is built:
the parameters and their names, the driver positions, the factory and what it
returns; with one variant's parameters and the optional libraries a study imports.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np

from assur._drive import _real
from assur._text import counted, describe, spoken
from assur._vec import Array, integer
from assur.errors import UsageError
from assur.model import Mechanism

Factory = Callable[..., Mechanism]
"""Builds one variant: ``factory(**parameters) -> Mechanism``."""


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
            f"({spoken(takes) or 'none by name'})"
        )
        raise UsageError(msg) from None


def _optional(module: str) -> Any:
    """Import an optional dependency of studies, saying how to install it."""
    from assur._optional import optional

    return optional(module, "a study", "study")


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


def _parameters(parameters: Any) -> dict[str, Array]:
    """Check the parameters; return them as read-only float arrays.

    A pandas DataFrame gives its columns (a table of samples, one row a variant);
    pandas Series must share one index, for their values are paired by position.
    """
    if _pandas(parameters, "DataFrame"):
        frame: Any = parameters
        if not frame.columns.is_unique:
            twice = next(str(c) for c in frame.columns[frame.columns.duplicated()])
            msg = f"parameters: column {twice!r} twice in the DataFrame; expected once"
            raise UsageError(msg)
        if frame.empty:
            msg = "parameters: an empty DataFrame; expected one row per variant"
            raise UsageError(msg)
        parameters = {str(name): frame[name] for name in frame.columns}
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
                f"expected another name (not {spoken(RESERVED, 'or')})"
            )
            raise UsageError(msg)
        try:
            arr = np.array(values)
        except (TypeError, ValueError) as err:
            msg = f"parameters.{name}: expected a 1-D array of real numbers"
            raise UsageError(msg) from err
        if arr.dtype.kind in "biuf" and arr.shape == (0,):  # 1-D, without a variant
            msg = f"parameters.{name}: no values; expected one value per variant"
            raise UsageError(msg)
        if arr.dtype.kind not in "biuf" or arr.ndim != 1:
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
    _one_index(parameters)
    return out


def _pandas(value: Any, kind: str) -> bool:
    """Whether ``value`` is a pandas object of class ``kind`` (pandas not imported)."""
    return type(value).__name__ == kind and type(value).__module__.startswith("pandas")


def _one_index(parameters: Mapping[str, Any]) -> None:
    """Refuse pandas Series of different indexes: a study pairs values by position.

    Two Series of one sample, one of them sorted, would pair the wrong values
    without a word.
    """
    indexed = {n: v.index for n, v in parameters.items() if _pandas(v, "Series")}
    if len(indexed) < 2:
        return
    first, *rest = indexed.items()
    odd = [name for name, index in rest if not index.equals(first[1])]
    if odd:
        msg = (
            f"parameters: pandas Series {first[0]!r} and {odd[0]!r} have different "
            "indexes, and a study pairs their values by position, not by label; "
            "expected one index (pandas.DataFrame({...}) aligns them) or arrays"
        )
        raise UsageError(msg)


def _partitions(partitions: Any) -> None:
    """Refuse ``partitions`` that is not None or a positive whole number.

    Checked with or without a client: a study run first on one machine is then
    refused the same way as on a cluster, not after its variants were run.
    """
    if partitions is not None and (integer(partitions) or 0) < 1:
        # "a positive number" refused 2.0 in words that 2.0 meets: a count is asked
        msg = (
            "partitions: expected a positive whole number (a count), got "
            f"{describe(partitions)}"
        )
        raise UsageError(msg)


def _fitting(factory: Factory, parameters: dict[str, Array], angles: Array) -> None:
    """Refuse driver positions whose shape does not fit the first variant's drivers.

    The positions are every variant's: a shape that does not fit made each variant
    fail alone, thousands of rows of one error after a study's whole run. The first
    of the first three variants that builds is asked; those that cannot be built
    are left to the study, which records why.
    """
    for i in range(min(3, len(next(iter(parameters.values()))))):
        p = _variant(parameters, i)
        try:
            drivers = len(_built(factory, p).drivers)
        except Exception:  # the factory's own error: the study's row says it
            continue
        break
    else:  # none of the first few built: their rows say why
        return
    if not drivers:  # each variant fails for want of a driver, as a call does
        return
    if drivers == 1 and (angles.ndim == 1 or angles.shape[1] == 1):
        return
    if angles.ndim == 2 and angles.shape[1] == drivers:
        return
    shape = "(n,) or (n, 1)" if drivers == 1 else f"(n, {drivers})"
    msg = (
        f"angles: shape {angles.shape} for variants of {counted(drivers, 'driver')} "
        f"({_shown(p)}); expected {shape}, the same for every variant"
    )
    raise UsageError(msg)


def _angles(angles: Any) -> Array:
    """Check the driver positions; return them as a read-only float array."""
    # the check of assur.kinematics: a float conversion took "30", True and b"3"
    # as numbers, and let an integer too large for a float raise OverflowError
    arr = np.array(_real(angles, "angles", "driver positions"), dtype=float)
    if arr.ndim not in (1, 2) or not arr.shape[0]:
        msg = (
            "angles: expected driver positions of shape (n,) or (n, drivers), got "
            f"shape {arr.shape}"
        )
        raise UsageError(msg)
    if not np.all(np.isfinite(arr)):
        bad = float(arr[~np.isfinite(arr)].flat[0])
        msg = (
            f"angles: expected finite driver positions, got {describe(bad)} among them"
        )
        raise UsageError(msg)
    arr.flags.writeable = False
    return arr
