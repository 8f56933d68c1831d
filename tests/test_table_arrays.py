"""Every column of a table at once: ``Table.arrays`` and the columns it keeps."""

from __future__ import annotations

import numpy as np
import pytest

import assur
from assur._evaluate import grouped, materialize


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two columns hold the same numbers, bit for bit (NaN, -0.0)."""
    return a.shape == b.shape and bytes(a.data) == bytes(b.data)


@pytest.mark.parametrize("analysis", [assur.kinematics, assur.forces])
def test_a_table_s_own_grouping_gives_every_column_as_one_by_one(example, analysis):
    angles = assur.analysis.default_positions(example, 7.0)
    try:
        table = analysis(example, angles, skip_unassembled=True)
    except assur.errors.ModelError:
        pytest.skip("no masses and no loads: nothing to analyse")
    together = grouped(table, table._families)
    apart = materialize(table, list(table.schema))
    for column in table.schema:
        assert _same(together[column.name], apart[column.name]), column.name


@pytest.mark.parametrize("analysis", [assur.kinematics, assur.forces])
def test_every_column_at_once_is_each_column_read_by_name(analysis):
    mech = assur.catalog.four_bar()
    angles = np.arange(0.0, 360.0, 5.0)
    at_once = analysis(mech, angles).arrays()
    by_name = analysis(mech, angles)
    for name, values in zip(by_name.columns, at_once, strict=True):
        assert _same(values, by_name[name]), name
        assert not values.flags.writeable


def test_storing_a_read_only_view_makes_its_owner_read_only():
    # a view read-only over a writeable block: the block's flag would let the
    # column be written through another view
    table = assur.kinematics(assur.catalog.slider_crank(), [0.0, 90.0])
    block = np.zeros((2, 2))
    view = block[1]
    view.flags.writeable = False
    table._store({"crank.omega": view, "not a column": block[0]})
    assert not block.flags.writeable
    assert table["crank.omega"] is view
    assert "not a column" not in table._cache


def test_angles_lose_their_turns_row_by_row():
    from assur._evaluate import _continuous

    rng = np.random.default_rng(3)
    smooth = np.cumsum(rng.uniform(-2.0, 2.0, (3, 50)), axis=-1)
    wrapped = np.angle(np.exp(1j * smooth))
    found = _continuous(wrapped.copy())
    # each row as np.unwrap gives it, the first angle kept within (-pi, pi]
    np.testing.assert_allclose(found, np.unwrap(wrapped), rtol=0, atol=1e-12)
    holed = wrapped.copy()
    holed[1, 20] = np.nan
    found = _continuous(holed)
    assert np.isnan(found[1, 20])
    np.testing.assert_allclose(found[1, :20], np.unwrap(wrapped[1, :20]), atol=1e-12)
