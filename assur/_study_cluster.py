"""Studies on a dask.distributed cluster: the variants in partitions, one per task.

:func:`assur.study.sweep` with a client splits the variants into partitions; each
worker runs :func:`assur.study.summarise` on its partitions, and the partitions'
summaries come back as one DataFrame.
"""

from __future__ import annotations

import contextlib
import itertools
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._progress import Progress
from assur._study_inputs import Factory, _optional
from assur._study_tables import ordered
from assur._vec import Array
from assur.errors import UsageError


def _distributed(
    client: Any,
    run: tuple[Callable[..., Any], Factory, dict[str, Array], Array],
    partitions: int | None,
    bar: Progress,
) -> Any:
    """Run the variants in partitions on a dask.distributed cluster; one DataFrame.

    ``run`` is ``(summarise, factory, parameters, angles)``: each partition is
    ``summarise(factory, parameters, angles, start)`` on a worker
    (:func:`assur.study.summarise`). ``bar`` is told of each partition gathered.
    The client and the factory were checked by :func:`ready`.
    """
    summarise, factory, parameters, angles = run
    import pandas as pd
    from distributed import KilledWorker

    count = len(next(iter(parameters.values())))
    if partitions is None:
        threads = sum(client.nthreads().values()) or 1
        partitions = 2 * threads
    bounds = np.linspace(0, count, min(count, max(1, partitions)) + 1).astype(int)
    futures: list[Any] = []
    try:
        for a, b in itertools.pairwise(bounds):
            part = {name: v[a:b] for name, v in parameters.items()}
            task = (summarise, factory, part, angles, int(a))
            futures.append(client.submit(*task, pure=False))
        frames = []
        for (a, b), future in zip(itertools.pairwise(bounds), futures, strict=True):
            try:
                frames.append(client.gather(future))
            except KilledWorker:
                # the partition is lost, not the others: its rows say so
                frames.append(_killed(parameters, int(a), int(b)))
            bar.advance(int(b - a))
    except BaseException:
        # stopped (Ctrl-C, a failure): the partitions not gathered would else run
        # on, and hold the cluster for the next study while a traceback is kept
        _cancel(client, futures)
        raise
    # partitions of other topologies bring their own columns: ordered as one run's
    return ordered(pd.concat(frames), list(parameters))


def ready(client: Any, factory: Factory) -> None:
    """Refuse a client that cannot run a study, or a factory it cannot be sent.

    Checked by :func:`assur.study.sweep` before any variant is built: a factory
    may take minutes a variant, and the first variants were built (to check the
    driver positions) before a closed client was refused.

    Raises
    ------
    UsageError
        For a ``client`` that is not a dask.distributed client or is closed, or a
        factory that does not pickle.
    ImportError
        When dask.distributed is not installed.
    """
    _optional("distributed")
    if not all(callable(getattr(client, f, None)) for f in ("submit", "gather")):
        msg = f"client: expected a dask.distributed Client, got {client!r}"
        raise UsageError(msg)
    if getattr(client, "status", None) in ("closing", "closed"):
        # else an AttributeError from deep inside the client, or ClosedClientError
        msg = f"client: {client!r} is closed; expected a running client"
        raise UsageError(msg)
    _sendable(factory)


def _sendable(factory: Factory) -> None:
    """Refuse a factory that cannot be sent to the workers (pickled as dask does).

    Else dask logs a traceback of its own and raises about its task graph, naming
    neither the factory nor what in it does not pickle.
    """
    import cloudpickle

    try:
        cloudpickle.dumps(factory)
    except Exception as err:  # whatever pickling meets is told
        why = (str(err).splitlines() or [""])[0][:200]
        msg = (
            f"factory: {factory!r} cannot be sent to the cluster's workers "
            f"({type(err).__name__}: {why}); expected a factory that pickles: a "
            "function of a module, or a closure over values that pickle (no locks, "
            "open files or clients)"
        )
        raise UsageError(msg) from None


def _cancel(client: Any, futures: list[Any]) -> None:
    """Cancel ``futures`` on ``client``; whatever cancelling meets is passed over."""
    if futures:
        # the study's own error is the one to raise, not one from cancelling
        with contextlib.suppress(Exception):
            client.cancel(futures)


def _killed(parameters: dict[str, Array], a: int, b: int) -> Any:
    """Return the rows of variants ``a`` to ``b - 1``, whose worker process died."""
    import pandas as pd

    why = (
        f"KilledWorker: the worker process running variants {a} to {b - 1} (one "
        "partition) died each time it held them: one of them, or a partition run "
        "beside them, ends its process (os._exit, a crash, out of memory); expected "
        "each variant to return or raise (run them in smaller partitions to find which)"
    )
    rows = {name: v[a:b] for name, v in parameters.items()}
    index = pd.RangeIndex(a, b, name="variant")
    return pd.DataFrame({**rows, "error": why, "warning": ""}, index=index)
