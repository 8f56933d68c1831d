"""Studies on a dask.distributed cluster: what the workers' threads and processes do.

A study run on a cluster must give the rows one process gives: each variant's
warnings its own, whatever the worker's threads; and a variant that kills its worker
process must not take the finished partitions with it.
"""

from __future__ import annotations

import os

import numpy as np
import pytest

import assur
from assur import catalog

from .conftest import local_client

pytest.importorskip("pandas")
pytest.importorskip("distributed")


def test_warnings_stay_with_their_variant_on_a_worker_of_several_threads():
    # a slide line through the crank's pivot (offset 0) passes no change point; one
    # offset by more than the crank does (a warning). The speed differs from variant
    # to variant, so each is analysed alone, recording its warnings: on a worker of
    # four threads the records were shared, and warnings were lost or misplaced
    n = 80
    parameters = {
        "offset": np.tile([0.126, 0.0], n // 2),
        "angle": np.full(n, 90.0),
        "omega": np.linspace(100.0, 200.0, n),
    }
    angles = np.arange(0.5, 360.0, 2.0)
    with local_client(threads=4) as client:
        found = assur.sweep(
            catalog.slider_crank, parameters, angles, client, partitions=16
        ).summary
    said = found["warning"].to_numpy()
    assert all("change point" in w for w in said[::2])
    assert all(w == "" for w in said[1::2])


def ending(rod: float) -> assur.Mechanism:
    """A slider-crank, except for a rod of 0.3 m: its process ends at once."""
    if rod == 0.3:
        os._exit(3)
    return catalog.slider_crank(rod=rod)


def test_a_variant_that_kills_its_worker_costs_its_partition_not_the_study():
    # a worker process that died (os._exit, a crash, out of memory) took the study
    # with it: KilledWorker, and every finished partition lost
    dask = pytest.importorskip("dask")
    rods = [0.2, 0.21, 0.22, 0.3, 0.23, 0.24]
    angles = np.arange(0.0, 360.0, 10.0)
    with (
        # a partition is given up at the first death (the default waits for four)
        dask.config.set({"distributed.scheduler.allowed-failures": 0}),
        local_client(processes=True) as client,
    ):
        found = assur.sweep(ending, {"rod": rods}, angles, client, partitions=3)
    summary = found.summary
    assert summary["rod"].tolist() == rods
    killed = "KilledWorker: the worker process running variants {} to {} (one part"
    assert summary["error"][3].startswith(killed.format(2, 3))
    assert np.isnan(summary["B.F.max"][3])
    # a partition the worker held when it died (queued, or its result not yet
    # fetched) is lost with it; the others are kept
    kept = [i for i in range(len(rods)) if summary["error"][i] == ""]
    assert kept
    for i in range(len(rods)):
        first = i - i % 2
        if i not in kept:
            assert summary["error"][i].startswith(killed.format(first, first + 1))
            continue
        want = assur.forces(catalog.slider_crank(rod=rods[i]), angles).summary()
        assert summary["B.F.max"][i] == pytest.approx(want["B.F.max"], rel=1e-12)


@pytest.mark.parametrize("partitions", [None, 2])
def test_a_closed_client_is_refused(partitions):
    # an AttributeError ('NoneType' object has no attribute 'ncores') from the
    # client's own code, or its ClosedClientError
    with local_client() as client:
        pass
    with pytest.raises(assur.UsageError, match=r"^client: <Client: .* is closed; exp"):
        assur.sweep(
            catalog.slider_crank, {"rod": [0.2]}, [0.0], client, partitions=partitions
        )


def test_a_factory_that_does_not_pickle_is_refused_by_name():
    # else dask's own traceback on the log, and a TypeError about its task graph
    import threading

    lock = threading.Lock()

    def holding(rod, _lock=lock):
        return catalog.slider_crank(rod=rod)

    with (
        local_client() as client,
        pytest.raises(
            assur.UsageError,
            match=r"^factory: <function .*holding.* cannot be sent to the cluster's "
            r"workers \(TypeError: cannot pickle '_thread.lock' object\); expected",
        ),
    ):
        assur.sweep(holding, {"rod": [0.2, 0.25]}, [0.0, 90.0], client)


def test_a_study_stopped_leaves_no_partition_running():
    # Ctrl-C (here from the progress callback) while partitions run: those not
    # gathered ran on, holding the cluster for the next study while a notebook
    # kept the traceback
    def stop(done, total):
        raise KeyboardInterrupt

    # partitions that would run some 6 s on: cancelled, they are gone in a moment
    parameters = {"rod": np.linspace(0.2, 0.3, 1600)}
    with local_client() as client:
        with pytest.raises(KeyboardInterrupt) as caught:
            assur.sweep(
                catalog.slider_crank,
                parameters,
                np.arange(0.0, 360.0, 0.05),
                client,
                partitions=160,
                progress=stop,
            )

        def states(dask_scheduler=None):
            return [str(t.state) for t in dask_scheduler.tasks.values()]

        def running() -> list[str]:
            left = client.run_on_scheduler(states)
            return [s for s in left if s in ("waiting", "queued", "processing")]

        # the scheduler releases the cancelled tasks a moment later (0.1 s here,
        # more on a loaded machine); left running, they would hold it for seconds
        import time

        deadline = time.monotonic() + 2.0
        while running() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert caught.value is not None  # the traceback kept, as a notebook keeps it
        assert not running()


def test_progress_counts_the_partitions_gathered():
    told = []
    parameters = {"rod": np.linspace(0.2, 0.3, 10)}
    with local_client() as client:
        assur.sweep(
            catalog.slider_crank,
            parameters,
            np.arange(0.0, 360.0, 30.0),
            client,
            partitions=3,
            progress=lambda done, total: told.append((done, total)),
        )
    # three partitions of 3, 3 and 4 variants (np.linspace bounds 0, 3, 6, 10)
    assert told == [(3, 10), (6, 10), (10, 10)]
