"""The library's warnings are held per thread, never by swapping the warnings filters.

``warnings.catch_warnings`` swaps the whole process's filters: from two threads at
once it lost one thread's warnings, filed them under another call (a study's row),
or left an "ignore" filter behind for good.
"""

from __future__ import annotations

import sys
import threading
import warnings
from pathlib import Path
from unittest import mock

import numpy as np
import pytest

import assur
from assur import catalog
from assur._warn import held, warn


def test_held_warnings_are_the_holding_thread_s_alone():
    inside, outside = threading.Event(), threading.Event()
    kept: list[str] = []

    def holder() -> None:
        with held() as found:
            inside.set()
            outside.wait(5.0)  # the other thread warns meanwhile
            warn("mine")
        kept.extend(str(w.message) for w in found)

    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        thread = threading.Thread(target=holder)
        thread.start()
        inside.wait(5.0)
        warn("the other thread's")
        outside.set()
        thread.join()
    assert kept == ["mine"]
    assert [str(w.message) for w in shown] == ["the other thread's"]
    assert all(w.category is assur.AssurWarning for w in shown)


def test_a_warning_given_points_at_the_caller_s_line():
    def caller() -> None:
        warn("here", stacklevel=2)

    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        here = (caller(), sys._getframe().f_lineno)[1]  # the line it names
    assert shown[0].filename == __file__
    assert shown[0].lineno == here


PACKAGE = str(Path(assur.__file__).parent)
ENTER = warnings.catch_warnings.__enter__


def _entered(self: warnings.catch_warnings) -> object:
    """Enter ``self``, unless a module of the package asked (another's may)."""
    caller = sys._getframe(1).f_code.co_filename
    if caller.startswith(PACKAGE):
        msg = f"{caller} swapped the process's warnings filters"
        raise AssertionError(msg)
    return ENTER(self)


def test_the_library_never_swaps_the_warnings_filters():
    # each of the paths that held or recorded warnings with catch_warnings: a sweep
    # through a change point, the states a columns= table solves again, a study's
    # variant solved alone and its tables, the dynamic model's grid
    pytest.importorskip("pandas")
    parallelogram = catalog.four_bar(crank=0.04, coupler=0.10, rocker=0.04)
    angles = np.arange(0.0, 360.0, 3.0) + 46.0
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        with mock.patch.object(warnings.catch_warnings, "__enter__", _entered):
            table = assur.forces(parallelogram, angles, columns=["driver.torque"])
            assert table.state is not None
            study = assur.sweep(
                catalog.four_bar,
                {"crank": [0.04], "coupler": [0.10], "rocker": [0.04]},
                angles,
            )
            assur.dynamics(catalog.four_bar())
    said = [str(w.message) for w in shown]
    # the sweep's own warnings (change points at 180 and 360 deg, a dead centre),
    # once each; the study's variant's in its row, not given
    assert len(said) == 3
    assert sum("(a change point)" in s for s in said) == 2
    assert study.summary["warning"].iloc[0].count("(a change point)") == 2


def test_analyses_in_threads_give_a_call_alone_s_numbers_and_warnings():
    # what docs/conventions.rst says of threads: four threads at once, each its
    # sweep's numbers bit for bit and its warnings, none lost or doubled
    from concurrent.futures import ThreadPoolExecutor

    parallelogram = catalog.four_bar(crank=0.04, coupler=0.10, rocker=0.04)
    angles = np.arange(0.0, 360.0, 3.0) + 46.0
    jobs = [parallelogram, catalog.slider_crank(), parallelogram, catalog.four_bar()]
    with warnings.catch_warnings(record=True) as alone:
        warnings.simplefilter("always")
        want = [assur.forces(m, angles).arrays() for m in jobs]
    with warnings.catch_warnings(record=True) as shown:
        warnings.simplefilter("always")
        with ThreadPoolExecutor(4) as pool:
            found = list(pool.map(lambda m: assur.forces(m, angles).arrays(), jobs))
    for got, expected in zip(found, want, strict=True):
        for a, b in zip(got, expected, strict=True):
            np.testing.assert_array_equal(a, b)
    assert len(alone) == 6  # the parallelogram's two change points and dead centre
    assert sorted(str(w.message) for w in shown) == sorted(
        str(w.message) for w in alone
    )
