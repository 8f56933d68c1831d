"""A sweep's slices: :data:`assur._state.CHUNK` positions, read when a sweep runs.

Tests make the slice small to cross it with few positions; what crosses slices
gives the numbers and the troubles of one slice.
"""

from __future__ import annotations

import numpy as np
import pytest

import assur
from assur import _passes, _state, analysis


@pytest.fixture
def solved(monkeypatch) -> list[int]:
    """The sizes of the slices solved, in order."""
    sizes: list[int] = []
    solve = _passes._solve_slice

    def counted(plan, drive, *args):
        sizes.append(drive.shape[0])
        return solve(plan, drive, *args)

    monkeypatch.setattr(_passes, "_solve_slice", counted)
    monkeypatch.setattr(analysis, "_solve_slice", counted)
    return sizes


def test_a_sweep_runs_in_the_slices_set_when_it_runs(monkeypatch, solved):
    mech = assur.catalog.four_bar()
    angles = np.arange(0.0, 360.0, 18.0)
    whole = assur.forces(mech, angles).to_array()
    solved.clear()
    monkeypatch.setattr(_state, "CHUNK", 8)
    sliced = assur.forces(mech, angles).to_array()
    assert solved == [8, 8, 4]
    np.testing.assert_allclose(sliced, whole, rtol=1e-12, atol=1e-9)


def test_a_sweep_s_troubles_are_sought_in_the_same_slices(monkeypatch, solved):
    monkeypatch.setattr(_state, "CHUNK", 8)
    given = np.arange(0.0, 360.0, 18.0)[:, None]
    analysis.report_troubles(assur.catalog.four_bar(), given, True, False)
    assert solved == [8, 8, 4]
