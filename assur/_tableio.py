"""Result tables written a block of rows at a time: CSV, JSON and Parquet.

A writer takes the columns of a table (or of one slice of a long sweep after another)
and writes their rows as they come, so that neither the whole table nor its text is
ever held in memory. :func:`assur.io.write_csv`, :meth:`assur.table.Table.to_parquet`
and the command line's ``--csv``, ``--json`` and ``--parquet`` all write through here,
so a table written whole and one written slice by slice give the same bytes.
"""

from __future__ import annotations

import csv
import io
import json
import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from assur._csvtext import csv_lines
from assur._vec import Array
from assur.errors import UsageError

__all__ = [
    "PARQUET_ROWS",
    "ROWS",
    "CsvWriter",
    "JsonWriter",
    "ParquetWriter",
    "import_pyarrow",
    "table_columns",
]

ROWS = 8192
"""Most rows put together and written at once."""
VALUES = 1 << 20
"""Most numbers put together at once (8 MB): a table of many columns takes fewer rows
(17 736 columns: 59 rows, where 8192 made 1.2 GB)."""
PARQUET_ROWS = 65536
"""Rows of one Parquet row group when a whole table is written."""

Advance = Callable[[int], None]
"""Told the number of rows just written (a progress bar)."""


def table_columns(table: Any) -> list[Array]:
    """Return the arrays of every column of ``table``, in order.

    Raises
    ------
    UsageError
        For anything but a table of columns (None, a dict, a Mechanism).
    """
    if isinstance(table, dict) or not (
        hasattr(table, "columns") and hasattr(table, "__getitem__")
    ):
        msg = (
            "table: expected a table of assur.kinematics, assur.forces or "
            f"assur.dynamics, got {type(table).__name__}"
        )
        raise UsageError(msg)
    arrays = getattr(table, "arrays", None)
    if arrays is not None:  # a Table computes the columns not read yet together
        return arrays()  # type: ignore[no-any-return]
    return [table[name] for name in table.columns]


class CsvWriter:
    """Write a header line and then rows, 12 significant digits (``"%.12g"``).

    ``write`` takes bytes: a binary stream's ``write`` (see
    :func:`assur._output.write_all`). ``encode`` turns the header into bytes (UTF-8 by
    default; standard output uses its own encoding).
    """

    def __init__(
        self,
        write: Callable[[bytes], Any],
        names: Sequence[str],
        encode: Callable[[str], bytes] | None = None,
        advance: Advance | None = None,
    ) -> None:
        self._write = write
        self._advance = advance
        header = io.StringIO()
        # names may hold quotes: the header follows the CSV rules like any row
        csv.writer(header, lineterminator="\n").writerow(names)
        text = header.getvalue()
        write(text.encode("utf-8") if encode is None else encode(text))

    def write(self, columns: Sequence[Array]) -> None:
        """Write the rows of ``columns`` (arrays of equal length)."""
        count = len(columns[0]) if columns else 0
        step = _rows(columns)
        for start in range(0, count, step):
            rows = _block(columns, start, step)
            self._write(csv_lines(rows))
            if self._advance is not None:
                self._advance(rows.shape[0])

    def close(self) -> None:
        """Finish the table (nothing to add after the last row)."""


class JsonWriter:
    """Write ``{"name": ..., "columns": [...], "units": {...}, "rows": [...]}`` by rows.

    The text is that of ``json.dumps(table.to_dict())``: numbers as Python writes
    them, ``null`` for a value that is not a finite number.
    """

    def __init__(
        self,
        write: Callable[[bytes], Any],
        name: str,
        names: Sequence[str],
        encode: Callable[[str], bytes] | None = None,
        advance: Advance | None = None,
        head: dict[str, Any] | None = None,
        units: Sequence[str] = (),
    ) -> None:
        self._write = write
        self._encode = encode or (lambda text: text.encode("utf-8"))
        self._advance = advance
        # more entries (figures of the dynamics, say) go between the name and columns
        start = json.dumps(
            {
                "name": name,
                **(head or {}),
                "columns": list(names),
                # each column's unit by name, as the Parquet file's metadata has it
                **({"units": dict(zip(names, units, strict=True))} if units else {}),
            }
        )
        self._write(self._encode(start[:-1] + ', "rows": ['))
        # one template per row: '{"angle": %s, "crank.angle": %s, ...}'
        keys = ", ".join(f"{json.dumps(n).replace('%', '%%')}: %s" for n in names)
        self._row = "{" + keys + "}"
        self._first = True

    def write(self, columns: Sequence[Array]) -> None:
        """Write the rows of ``columns`` (arrays of equal length)."""
        count = len(columns[0]) if columns else 0
        step = _rows(columns)
        for start in range(0, count, step):
            rows = _block(columns, start, step)
            # repr is json.dumps's text of a finite float; mapped without a call of
            # ours per cell where every value of the block is finite
            number = repr if np.isfinite(rows).all() else _json_number
            texts = [self._row % tuple(map(number, row)) for row in rows.tolist()]
            lead = "" if self._first else ", "
            self._first = False
            self._write(self._encode(lead + ", ".join(texts)))
            if self._advance is not None:
                self._advance(rows.shape[0])

    def close(self) -> None:
        """Write the end of the object."""
        self._write(self._encode("]}"))


def _block(columns: Sequence[Array], start: int, step: int) -> Array:
    """Return rows ``start`` to ``start + step`` of ``columns``, one row a position.

    A negative zero (the speed of a point at rest, rounded) would read "-0", a sign
    with no number behind it: adding +0 makes it 0, and changes nothing else.
    """
    rows = np.stack([c[start : start + step] for c in columns], axis=-1)
    if rows.dtype.kind == "f":
        rows += 0.0
    return rows


def _rows(columns: Sequence[Array]) -> int:
    """Return the rows of ``columns`` to put together at once (at least one)."""
    return max(1, min(ROWS, VALUES // max(1, len(columns))))


def _json_number(value: float) -> str:
    """Return a number as ``json.dumps`` writes it; ``null`` if it is not finite."""
    return repr(value) if math.isfinite(value) else "null"


def import_pyarrow() -> tuple[Any, Any]:
    """Return ``pyarrow`` and ``pyarrow.parquet``.

    Raises
    ------
    ImportError
        When pyarrow is not installed, saying how to install it.
    """
    from assur._optional import optional

    parquet = optional("pyarrow.parquet", "writing Parquet", "parquet")
    return optional("pyarrow", "writing Parquet", "parquet"), parquet


class ParquetWriter:
    """Write float64 columns to a Parquet file, one row group per ``write``.

    Every field carries its unit in its metadata (key ``unit``); the schema carries
    the mechanism's name (key ``assur.name``).
    """

    def __init__(
        self,
        path: Any,
        name: str,
        names: Sequence[str],
        units: Sequence[str],
        advance: Advance | None = None,
    ) -> None:
        pa, pq = import_pyarrow()
        self._pa = pa
        self._advance = advance
        fields = [
            pa.field(n, pa.float64(), metadata={"unit": u})
            for n, u in zip(names, units, strict=True)
        ]
        self._schema = pa.schema(fields, metadata={"assur.name": name})
        # a stream of our own: pyarrow's files ask where they are (a FIFO cannot say)
        self._stream = open(path, "wb")  # noqa: SIM115 - closed by close()/abort()
        try:
            sink = pa.PythonFile(_Counted(self._stream), mode="w")
            # floats rarely repeat: a dictionary only slows writing (3x) and grows
            # the file
            self._writer = pq.ParquetWriter(sink, self._schema, use_dictionary=False)
        except BaseException:
            self._stream.close()
            raise

    def write(self, columns: Sequence[Array]) -> None:
        """Write ``columns`` (arrays of equal length) as one row group."""
        arrays = [self._pa.array(np.asarray(c, dtype=np.float64)) for c in columns]
        if arrays and len(arrays[0]):
            self._writer.write_table(
                self._pa.Table.from_arrays(arrays, schema=self._schema)
            )
            if self._advance is not None:
                self._advance(len(arrays[0]))

    def close(self) -> None:
        """Write the file's footer."""
        try:
            self._writer.close()
        finally:
            self._stream.close()

    def abort(self) -> None:
        """Let go of the file after a failure (it is removed)."""
        self.close()


class _Counted:
    """A binary stream that counts what is written: its position, for pyarrow."""

    def __init__(self, stream: Any) -> None:
        self._stream = stream
        self._position = 0
        self.closed = False

    def write(self, data: Any) -> int:
        """Write ``data``; return its length."""
        self._stream.write(data)
        self._position += len(data)
        return len(data)

    def tell(self) -> int:
        """Return the number of bytes written."""
        return self._position

    def flush(self) -> None:
        """Flush the stream."""
        self._stream.flush()

    def close(self) -> None:
        """Mark the stream closed (its owner closes the file)."""
        self.closed = True

    def writable(self) -> bool:
        """Say that the stream is written to."""
        return True

    def seekable(self) -> bool:
        """Say that the stream cannot seek (a FIFO, a pipe)."""
        return False

    def readable(self) -> bool:
        """Say that the stream is not read."""
        return False
