"""What every table of results offers: its columns by name, and their export.

:class:`Columns` is the base of the sweep's :class:`~assur.table.Table` and of the
dynamics' tables: arrays, CSV, Parquet, JSON-ready data and pandas, from the columns.
"""

from __future__ import annotations

import math
from abc import ABCMeta, abstractmethod
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._text import describe, python_value
from assur._vec import Array
from assur.columns import Column
from assur.errors import UnknownNameError
from assur.model import Mechanism

if TYPE_CHECKING:  # pandas is an optional extra, imported when asked for
    import pandas as pd

__all__ = ["Columns", "column_name"]


def column_name(name: object) -> str:
    """Return ``name`` as a table looks it up; refuse what is no str.

    Raises
    ------
    UnknownNameError
        For a value that is no column's name: a number, a slice, a list (which
        as a dict key raised TypeError: unhashable), bytes (told as bytes, not as
        the list of numbers they also are).
    """
    if isinstance(name, str):
        return name
    shown = (
        python_value(name) if isinstance(name, bytes | bytearray) else describe(name)
    )
    msg = (
        f"no column {shown}; expected a column's name, a str (table.columns lists them)"
    )
    raise UnknownNameError(msg)


class Columns(metaclass=ABCMeta):
    """What every table of results offers: its columns by name, and their export.

    A subclass gives ``columns`` (the names, in order), ``column(name)`` (a
    ``Column``: owner, quantity, unit), ``table[name]`` (a read-only array, one
    value per row), ``len(table)`` and ``mechanism``; the rest follows from them.
    An abstract base (``abc``): a table of another kind may be registered as a
    :class:`~assur.analysis.Table` (the dynamic model's is).
    """

    __slots__ = ()

    if TYPE_CHECKING:  # given by each table, as a field or a property

        @property
        def columns(self) -> tuple[str, ...]:
            """The column names, in order."""

        @property
        def mechanism(self) -> Mechanism:
            """The mechanism the table was computed for."""

    @abstractmethod
    def column(self, name: str) -> Column:  # pragma: no cover - every table's own
        """Return the description of column ``name`` (owner, quantity, unit)."""
        raise NotImplementedError

    @abstractmethod
    def __getitem__(self, name: str) -> Array:  # pragma: no cover - every table's own
        raise NotImplementedError

    @abstractmethod
    def __len__(self) -> int:  # pragma: no cover - every table's own
        raise NotImplementedError

    def __iter__(self) -> Iterator[str]:
        # iteration would read as rows to one library and as columns to another
        msg = (
            f"a {type(self).__name__} is not iterable; expected table.columns for the "
            "names, table.arrays() for the values, or table.to_pandas()"
        )
        raise TypeError(msg)

    def __setstate__(self, state: dict[str, Any]) -> None:
        """Take ``state`` unpickled or deep-copied, its arrays read-only again.

        numpy gives an array back writeable, whatever it was: a column read before
        pickling, once written to, changed ``summary()`` of the copy.
        """
        self.__dict__.update(state)
        for value in state.values():
            for x in value.values() if isinstance(value, dict) else (value,):
                if isinstance(x, np.ndarray):
                    x.flags.writeable = False

    def arrays(self) -> list[Array]:
        """Return every column, in order."""
        return [self[name] for name in self.columns]

    def to_array(self) -> Array:
        """Return the table as one array (rows, columns).

        The array is in Fortran order (each column contiguous): it is filled a
        column at a time, and a long table's rows would otherwise be written with a
        stride of a whole row (at 10^6 positions, several times slower).
        """
        if not self.columns:
            return np.empty((len(self), 0))
        # one copy of every column into a block (columns, rows), seen transposed
        return np.array(self.arrays()).T

    def to_csv(self, path: Any = None) -> str | None:
        """Write the table as CSV to ``path`` (a path, a file object or ``"-"``).

        Parameters
        ----------
        path : str, path-like, file object or "-", optional
            Where to write: a file (written whole or not at all), an open text or
            binary stream (UTF-8), or ``"-"`` for standard output. Without it the
            CSV text is returned.

        Returns
        -------
        str or None
            The CSV text when ``path`` is not given, else None.

        Raises
        ------
        OutputError
            When the file cannot be written; an old file of that name is kept.
        """
        from assur.io import write_csv

        return write_csv(self, path)

    def to_parquet(self, path: Any) -> None:
        """Write the table to a Parquet file at ``path`` (pyarrow must be installed).

        Columns are float64 under the table's column names, each with its unit in
        the field metadata (key ``unit``); the file is written whole or not at all.
        See :func:`assur.io.write_parquet`.

        Parameters
        ----------
        path : str or path-like
            The file to write.

        Raises
        ------
        ImportError
            When pyarrow is not installed.
        """
        from assur.io import write_parquet

        write_parquet(self, path)

    def to_dict(self) -> dict[str, Any]:
        """Return JSON-ready data: the name, the columns, their units and the rows.

        NaN is None; a negative zero is 0.0, as the JSON and CSV files write it.
        """
        rows = self.to_array() + 0.0
        return {
            "name": self.mechanism.name,
            "columns": list(self.columns),
            "units": {name: self.column(name).unit for name in self.columns},
            "rows": [
                {c: _json_number(v) for c, v in zip(self.columns, row, strict=True)}
                for row in rows.tolist()
            ],
        }

    def to_pandas(self) -> pd.DataFrame:
        """Return a pandas DataFrame (pandas must be installed).

        Its ``attrs["units"]`` gives each column's unit by name (``"N"``,
        ``"rad/s"``; angles in ``"deg"``), as the Parquet file's metadata does.

        Returns
        -------
        pandas.DataFrame
            One column per column of the table, one row per row.

        Raises
        ------
        ImportError
            When pandas is not installed (or fails to import), saying what to do.
        """
        from assur._optional import optional

        pandas = optional("pandas", "Table.to_pandas()", "study")

        frame = pandas.DataFrame(dict(zip(self.columns, self.arrays(), strict=True)))
        frame.attrs["units"] = {name: self.column(name).unit for name in self.columns}
        return frame


def _json_number(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None
