"""Studies on a dask.distributed cluster: the variants in partitions, one per task.

:func:`assur.study.sweep` with a client splits the variants into partitions; each
worker runs :func:`assur.study.summarise` on its partitions, and the partitions'
summaries come back as one DataFrame.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._progress import Progress
from assur._study_inputs import Factory, _optional
from assur._study_tables import ordered
from assur._vec import Array, integer
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
    """
    summarise, factory, parameters, angles = run
    import pandas as pd

    _optional("distributed")
    from distributed import KilledWorker

    if not all(callable(getattr(client, f, None)) for f in ("submit", "gather")):
        msg = f"client: expected a dask.distributed Client, got {client!r}"
        raise UsageError(msg)
    if partitions is not None and (integer(partitions) or 0) < 1:
        msg = f"partitions: expected a positive number, got {partitions!r}"
        raise UsageError(msg)
    if getattr(client, "status", None) in ("closing", "closed"):
        # else an AttributeError from deep inside the client, or ClosedClientError
        msg = f"client: {client!r} is closed; expected a running client"
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
    frames = []
    for (a, b), future in zip(itertools.pairwise(bounds), futures, strict=True):
        try:
            frames.append(client.gather(future))
        except KilledWorker:
            # the partition is lost, not the others: its rows say so
            frames.append(_killed(parameters, int(a), int(b)))
        bar.advance(int(b - a))
    # partitions of other topologies bring their own columns: ordered as one run's
    return ordered(pd.concat(frames), list(parameters))


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
