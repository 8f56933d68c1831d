"""Tables written by blocks of rows: CSV as before, JSON as json.dumps, Parquet."""

from __future__ import annotations

import csv
import errno
import io
import json
import re
import sys
from pathlib import Path

import numpy as np
import pytest

import assur
from assur import _output, _stdout, _tableio
from assur.errors import OutputError

from .conftest import file_names as names

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


@pytest.fixture(scope="module")
def forces_table():
    # the slider translates: its instant centre is NaN in every row
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    return assur.forces(mech, np.arange(-90.0, 2000.0, 0.7))


def old_csv_text(table) -> str:
    """The CSV text as assur wrote it before the block writer: csv header, savetxt."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerow(table.columns)
    # but a negative zero, which assur writes 0
    np.savetxt(buffer, table.to_array() + 0.0, fmt="%.12g", delimiter=",")
    return buffer.getvalue()


def test_csv_text_is_what_it_was(forces_table, monkeypatch):
    assert forces_table.to_csv() == old_csv_text(forces_table)
    monkeypatch.setattr(_tableio, "ROWS", 700)  # several blocks of rows
    assert forces_table.to_csv() == old_csv_text(forces_table)


@pytest.mark.parametrize("values", [100, 1000])
def test_many_columns_are_written_a_few_rows_at_a_time(
    forces_table, monkeypatch, values
):
    # rows by numbers, not a fixed count: 8192 rows of 17 736 columns took 1.2 GB,
    # 512 rows of them 1.8 GB of the CSV's temporaries; the same bytes either way
    from assur import _csvtext

    monkeypatch.setattr(_tableio, "VALUES", values)
    monkeypatch.setattr(_csvtext, "BLOCK_VALUES", values)
    assert _tableio._rows(forces_table.arrays()) == max(1, values // 109)
    assert forces_table.to_csv() == old_csv_text(forces_table)
    parts: list[bytes] = []
    names = forces_table.columns
    units = [forces_table.column(c).unit for c in names]
    name = forces_table.mechanism.name
    writer = _tableio.JsonWriter(parts.append, name, names, units=units)
    writer.write(_tableio.table_columns(forces_table))
    writer.close()
    assert b"".join(parts).decode() == json.dumps(forces_table.to_dict())


def test_csv_to_a_path_a_stream_and_stdout(tmp_path, capsys):
    table = assur.kinematics(assur.catalog.four_bar(), np.arange(0.0, 360.0, 7.5))
    expected = old_csv_text(table)
    table.to_csv(tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_text(encoding="utf-8") == expected
    stream = io.StringIO()
    table.to_csv(stream)
    assert stream.getvalue() == expected
    table.to_csv("-")
    assert capsys.readouterr().out == expected


def test_csv_writes_no_negative_zero(forces_table):
    # 429 "-0" in the slider-crank's 360 rows: a sign with no number behind it
    text = forces_table.to_csv()
    assert np.any(np.signbit(forces_table.to_array()) & (forces_table.to_array() == 0))
    assert ",-0," not in text
    assert ",-0\n" not in text
    assert "\n-0," not in text
    values = np.loadtxt(io.StringIO(text), delimiter=",", skiprows=1)
    np.testing.assert_allclose(values, forces_table.to_array(), rtol=1e-11)


def test_csv_of_no_rows_is_the_header():
    mech = assur.catalog.four_bar()
    table = assur.kinematics(mech, [0.0, 180.0], skip_unassembled=True)
    empty = type(table)(
        table.plan, table.schema, table.given[:0], table.state.rows(slice(0, 0))
    )
    assert empty.to_csv() == ",".join(table.columns) + "\n"


def test_json_by_rows_is_json_dumps(forces_table, monkeypatch):
    monkeypatch.setattr(_tableio, "ROWS", 300)
    names = forces_table.columns
    assert np.isnan(forces_table["slider.ic.x"]).all()
    parts: list[bytes] = []
    units = [forces_table.column(c).unit for c in names]
    name = forces_table.mechanism.name
    writer = _tableio.JsonWriter(parts.append, name, names, units=units)
    columns = _tableio.table_columns(forces_table)
    for start in range(0, len(forces_table), 1000):  # slices of a sweep
        writer.write([c[start : start + 1000] for c in columns])
    writer.close()
    text = b"".join(parts).decode()
    # a negative zero written 0.0 (as to_dict gives it)
    assert not re.search(r" -0\.0[,}]", text)
    assert text == json.dumps(forces_table.to_dict())
    # each column's unit by its name, as the Parquet file's metadata has it
    units = json.loads(text)["units"]
    assert list(units) == list(names)
    assert units["driver.torque"] == "N m"
    assert units["crank.alpha"] == "rad/s^2"


def test_json_of_odd_names():
    parts: list[bytes] = []
    names = ['a "quoted" %s name', "é"]
    writer = _tableio.JsonWriter(parts.append, "m%d", names)
    writer.write([np.array([1.0, np.inf]), np.array([-0.0, 2.5])])
    writer.write([np.array([0.1]), np.array([-0.0])])  # a block all finite
    writer.close()
    # a negative zero is written 0.0
    rows = [{names[0]: 1.0, names[1]: 0.0}, {names[0]: None, names[1]: 2.5}]
    rows.append({names[0]: 0.1, names[1]: 0.0})
    expected = {"name": "m%d", "columns": names, "rows": rows}
    assert b"".join(parts).decode() == json.dumps(expected)


# --- Parquet -------------------------------------------------------------------------


@pytest.fixture
def pq():
    pytest.importorskip("pyarrow", reason="pyarrow is not installed (assur[parquet])")
    import pyarrow.parquet

    return pyarrow.parquet


def test_parquet_round_trip(pq, forces_table, tmp_path, monkeypatch):
    monkeypatch.setattr(_tableio, "PARQUET_ROWS", 700)
    target = tmp_path / "t.parquet"
    forces_table.to_parquet(target)
    read = pq.read_table(target)
    assert read.column_names == list(forces_table.columns)
    assert pq.ParquetFile(target).num_row_groups == -(-len(forces_table) // 700)
    for name in forces_table.columns:
        field = read.schema.field(name)
        assert str(field.type) == "double"
        assert field.metadata == {b"unit": forces_table.column(name).unit.encode()}
        np.testing.assert_array_equal(read.column(name).to_numpy(), forces_table[name])
    assert read.schema.metadata == {b"assur.name": b"Slider-crank exercise"}
    assert read.schema.field("rod.alpha").metadata[b"unit"] == b"rad/s^2"
    assert names(tmp_path) == {"t.parquet"}


def test_parquet_is_written_whole_or_not_at_all(pq, tmp_path, monkeypatch):
    table = assur.kinematics(assur.catalog.four_bar(), np.arange(0.0, 360.0, 1.0))
    target = tmp_path / "t.parquet"
    target.write_bytes(b"old")
    monkeypatch.setattr(_tableio, "PARQUET_ROWS", 100)
    real = _tableio.ParquetWriter.write
    calls = []

    def fail_on_the_third(self, columns):
        calls.append(1)
        if len(calls) == 3:
            raise OSError(errno.ENOSPC, "No space left on device")
        real(self, columns)

    monkeypatch.setattr(_tableio.ParquetWriter, "write", fail_on_the_third)
    with pytest.raises(OutputError, match="No space left on device"):
        table.to_parquet(target)
    assert target.read_bytes() == b"old"
    assert names(tmp_path) == {"t.parquet"}


def test_parquet_without_pyarrow_says_how_to_get_it(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    table = assur.kinematics(assur.catalog.four_bar(), [0.0])
    with pytest.raises(ImportError, match=r"needs pyarrow.*pip install"):
        table.to_parquet(tmp_path / "t.parquet")
    assert names(tmp_path) == set()


def test_outputs_name_their_own_file(tmp_path, monkeypatch):
    # a failing standard output is not the fault of a file written alongside it
    def broken(stream, data):
        raise BrokenPipeError(errno.EPIPE, "Broken pipe")

    monkeypatch.setattr(_stdout, "write_all", broken)
    write, _ = _output.stdout_writer()
    with pytest.raises(_output.StdoutError) as caught:
        write(b"x")
    assert isinstance(caught.value.error, BrokenPipeError)
