"""Studies on a dask.distributed cluster: what the workers' threads and processes do.

A study run on a cluster must give the rows one process gives: each variant's
warnings its own, whatever the worker's threads; and a variant that kills its worker
process must not take the finished partitions with it.
"""

from __future__ import annotations

import numpy as np
import pytest

import assur
from assur import catalog

pytest.importorskip("pandas")
distributed = pytest.importorskip("distributed")


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
    with (
        distributed.LocalCluster(
            n_workers=1,
            processes=False,
            threads_per_worker=4,
            dashboard_address=":0",
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        found = assur.sweep(
            catalog.slider_crank, parameters, angles, client, partitions=16
        ).summary
    said = found["warning"].to_numpy()
    assert all("change point" in w for w in said[::2])
    assert all(w == "" for w in said[1::2])
