"""The vectorised ``%.12g`` text of the CSV tables against ``numpy.savetxt``.

Every number must come out byte for byte as ``"%.12g" % x``: reference tables and
round trips depend on it. The values below aim at the corners of the method: ties
and near ties of the 12th digit, powers of ten, the ends of fixed notation, huge and
tiny exponents, subnormals, negative zero, NaN and infinities, integers.
"""

from __future__ import annotations

import io

import numpy as np
import pytest

import assur
from assur import _csvtext
from assur._csvtext import csv_lines


def savetxt(values: np.ndarray) -> bytes:
    buffer = io.StringIO()
    np.savetxt(buffer, values, fmt="%.12g", delimiter=",")
    return buffer.getvalue().encode()


def corners() -> np.ndarray:
    """Values where a formatter of %g goes wrong first."""
    powers = np.array([float(f"1e{k}") for k in range(-330, 310)])
    special = [
        0.0,
        -0.0,
        np.nan,
        -np.nan,
        np.inf,
        -np.inf,
        5e-324,
        -5e-324,
        2.2250738585072014e-308,
        2.225073858507201e-308,
        1.7976931348623157e308,
        2.0**-18,  # 3.814697265625e-06: a tie at the 13th digit
        2.0**-40,
        0.5,
        0.125,
        999999999999.5,  # rounds up to 1e+12
        999999999999.4,
        99999999999.95,
        123456789012.5,
        1234567890125.0,
        9.999999999995e-5,
        9.9999999999949e-5,
        0.0001,
        0.00009999999999999,
        1e-5,
        45.0,
        -1.0,
        0.1 + 0.2,
        1e22,
        1e23,
        4503599627370496.5,
    ]
    ties = (np.arange(1, 2000) + 0.5) * 10.0 ** np.arange(-14, 10)[:, None]
    halves = np.arange(1, 4000) * 0.02197265625 + 0.0001234  # binary-exact steps
    base = np.concatenate([powers, special, ties.ravel(), halves])
    with np.errstate(all="ignore"):
        near = [np.nextafter(base, np.inf), np.nextafter(base, -np.inf)]
    return np.concatenate([base, -base, *near])


def random_values(seed: int, count: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return np.concatenate(
        [
            rng.standard_normal(count) * 10.0 ** rng.integers(-40, 40, count),
            rng.integers(-(10**6), 10**6, count // 4).astype(float),
            rng.integers(-(10**15), 10**15, count // 4).astype(float) / 2.0,
            np.round(rng.standard_normal(count // 4), rng.integers(0, 14)),
            # any bit pattern: subnormals, NaN payloads, huge and tiny exponents
            np.frombuffer(rng.bytes(8 * count), np.float64),
        ]
    )


def as_table(values: np.ndarray, columns: int) -> np.ndarray:
    values = values[: values.size // columns * columns]
    return values.reshape(-1, columns)


@pytest.mark.parametrize("columns", [1, 7, 109])
def test_corners_as_savetxt_writes_them(columns):
    table = as_table(corners(), columns)
    assert csv_lines(table) == savetxt(table)


@pytest.mark.parametrize("seed", [1, 2])
def test_random_values_as_savetxt_writes_them(seed):
    table = as_table(random_values(seed, 40_000), 9)
    assert csv_lines(table) == savetxt(table)


def test_the_exact_rounding_agrees_everywhere(monkeypatch):
    # a margin of one half sends every number to the error-free rounding (or, out of
    # its range, to Python): the text must not change
    table = as_table(random_values(3, 5_000), 5)
    monkeypatch.setattr(_csvtext, "NEAR_HALF", 0.5)
    assert csv_lines(table) == savetxt(table)


def test_constant_columns_keep_their_sign_and_their_rows():
    rows = 1500  # three blocks of rows
    table = np.zeros((rows, 5))
    table[:, 1] = 200.0
    table[:, 2] = -0.0
    table[: rows // 2, 3] = -0.0  # zeros of both signs: not one constant
    table[:, 4] = np.nan
    assert csv_lines(table) == savetxt(table)
    assert csv_lines(table).splitlines()[0] == b"0,200,-0,-0,nan"


def test_a_real_table_as_savetxt_writes_it():
    mech = assur.load("examples/slider_crank_exercise.toml")
    table = assur.forces(mech, np.linspace(-40.0, 400.0, 2500))
    values = table.to_array()
    assert csv_lines(values) == savetxt(values)


def test_python_formats_on_a_big_endian_machine(monkeypatch):
    table = as_table(corners(), 7)
    monkeypatch.setattr(_csvtext, "LITTLE_ENDIAN", False)
    assert csv_lines(table) == savetxt(table)


def test_no_rows_no_text():
    assert csv_lines(np.zeros((0, 4))) == b""
