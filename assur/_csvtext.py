"""Numbers as the CSV tables write them: ``"%.12g"``, a block of rows at a time.

``numpy.savetxt(fmt="%.12g")`` formats one number at a time in Python. Here a block
of numbers is rounded to 12 significant digits with float arithmetic and spelt out
with integer and bit operations on whole arrays, giving the same bytes as ``"%.12g"``:
the rounding is exact (a number within a hair of a rounding tie is settled with an
error-free product, or by Python), and the text follows the rules of ``%g`` (fixed
notation for decimal exponents -4 to 11, trailing zeros removed, ``nan``, ``inf``).

Each number is built in three 64-bit words (24 bytes, little-endian, NUL-padded):
a separator, the sign and a ``0.000`` prefix, the digits with their dot, an exponent.
Deleting the NUL bytes of the block leaves the CSV text.
"""

from __future__ import annotations

import functools
import math
import sys
from typing import Any

import numpy as np
from numpy.typing import NDArray

from assur._vec import Array

__all__ = ["BLOCK_VALUES", "csv_lines"]

BLOCK_VALUES = 65536
"""Numbers formatted at once (512 rows of 128 columns): the temporaries of a block
stay in the processor's cache, and a table of 17 000 columns takes a few rows at a
time, not 512 (1.8 GB of temporaries)."""
NEAR_HALF = 2e-3
"""A scaled number closer than this to a rounding tie is rounded exactly (see below)."""
LIMIT = 290
"""Largest decimal exponent (either sign) spelt out here; Python formats the rest."""
LITTLE_ENDIAN = sys.byteorder == "little"
"""Whether the words of text are laid out as here (else Python formats every number)."""

_U = np.uint64
_ALL = _U(0xFFFF_FFFF_FFFF_FFFF)
_SPLIT = 134217729.0
"""2**27 + 1: Dekker's splitting constant for float64."""
_NO_EXPONENT = 0
_COMMA, _NEWLINE = 44, 10
Ints = NDArray[Any]
"""Integer arrays: words of text, indices, counts, masks."""


@functools.cache
def _tables() -> dict[str, Any]:
    """Return the lookup tables, built on first use."""

    def below(e: int, k: int) -> bool:  # 10**e <= 2**k, exactly
        return 10 ** max(e, 0) * 2 ** max(-k, 0) <= 2 ** max(k, 0) * 10 ** max(-e, 0)

    # per biased binary exponent b: E0 = floor(log10(2**(b - 1023))) and 10**(11 - E0)
    e0 = np.zeros(2048, np.int64)
    scale = np.full(2048, np.nan)
    scale[0] = 0.0  # zero stays zero; subnormals go to Python
    for b in range(1, 2047):
        k = b - 1023
        e = math.floor(k * math.log10(2.0))
        while below(e + 1, k):
            e += 1
        while not below(e, k):
            e -= 1
        e0[b] = e
        if -LIMIT <= e <= LIMIT:
            scale[b] = float(f"1e{11 - e}")
    quads = b"".join(b"%04d" % k for k in range(10000))
    prefixes = [
        sign + (b"0." + b"0" * (3 - c) if c < 4 else b"")
        for sign in (b"", b"-")
        for c in range(5)
    ]
    exponents = [b""] + [b"e%+03d" % e for e in range(-400, 401)]
    return {
        "e0": e0,
        "scale": scale,
        "exact": np.array([float(f"1e{k}") for k in range(23)]),
        "quad": np.frombuffer(quads, np.uint32).astype(_U),
        "zeros": np.array(
            [4]
            + [4 - len(quads[4 * k : 4 * k + 4].rstrip(b"0")) for k in range(1, 10000)]
        ),
        "prefix": np.array([_word(p) for p in prefixes], _U),
        "prefix_len": np.array([len(p) for p in prefixes], _U),
        "exponent": np.array([_word(e) for e in exponents], _U),
        "special": np.array([_word(s) for s in (b"nan", b"inf", b"-inf")], _U),
        "special_len": np.array([3, 3, 4], _U),
    }


def _word(text: bytes) -> int:
    """Return up to 8 bytes of text as a little-endian word."""
    return int.from_bytes(text.ljust(8, b"\0"), "little")


def csv_lines(values: Array) -> bytes:
    r"""Return the rows of ``values`` as CSV lines, each number as ``"%.12g"`` gives it.

    Parameters
    ----------
    values : ndarray (n, c)
        Numbers, any float64 (NaN, infinities, subnormals, negative zero).

    Returns
    -------
    bytes
        ``n`` lines of ``c`` numbers separated by commas, each line ending in a
        newline: the text of ``numpy.savetxt(stream, values, fmt="%.12g",
        delimiter=",")``.

    Examples
    --------
    >>> import numpy as np
    >>> csv_lines(np.array([[0.1 + 0.2, -0.0, 1e-5], [12345678901234.0, np.nan, 45.0]]))
    b'0.3,-0,1e-05\n1.23456789012e+13,nan,45\n'
    """
    values = np.asarray(values, dtype=np.float64)
    if not values.size:
        return b""
    if not LITTLE_ENDIAN:  # the words below are laid out little-end first
        line = ",".join(["%.12g"] * values.shape[1]) + "\n"
        return "".join(line % tuple(row) for row in values.tolist()).encode()
    rows = max(1, BLOCK_VALUES // values.shape[1])
    blocks = [
        _block(values[start : start + rows])
        for start in range(0, values.shape[0], rows)
    ]
    return b"".join(blocks)


def _block(values: Array) -> bytes:
    """Return the CSV lines of a few rows."""
    rows, cols = values.shape
    separator = np.full(cols, _COMMA, _U)
    separator[0] = _NEWLINE  # before every line; the first is dropped below
    # column by column: a column that holds one number throughout (a constant
    # speed, a zero) is spelt out once
    columns = values.T
    same = np.all(columns == columns[:, :1], axis=1)
    same &= np.all(np.signbit(columns) == np.signbit(columns[:, :1]), axis=1)
    vary = ~same
    words = np.empty((cols, rows, 3), _U)
    if same.any():
        words[same] = _words(columns[same, 0], separator[same])[:, None, :]
    if vary.any():
        x = columns[vary].ravel()
        found = _words(x, np.repeat(separator[vary], rows))
        words[vary] = found.reshape(-1, rows, 3)
    text = words.transpose(1, 0, 2).tobytes().translate(None, b"\0")
    return text[1:] + b"\n"


def _words(x: Array, separator: Ints) -> Ints:
    """Return the text of every number of ``x`` after its separator: words (n, 3)."""
    t = _tables()
    bits = x.view(_U)
    binary = ((bits >> _U(52)) & _U(0x7FF)).astype(np.intp)
    negative = (bits >> _U(63)).astype(np.intp)
    ax = np.abs(x)
    # y: |x| scaled to [1e11, 1e12), e its decimal exponent
    with np.errstate(invalid="ignore"):  # a signalling NaN
        y = ax * t["scale"][binary]
    e = t["e0"][binary]
    over = y >= 1e12
    y[over] *= 0.1
    e += over
    d = np.rint(y)
    special = binary == 2047
    with np.errstate(invalid="ignore"):
        python = ~(np.abs(np.abs(y - d) - 0.5) > NEAR_HALF)  # NaN scales too
    python |= (binary == 0) & (ax != 0)
    python &= ~special
    near = np.flatnonzero(python & (binary != 0) & (e >= -11) & (e <= 11))
    if near.size:
        d[near] = _round_exactly(ax[near], t["exact"][11 - e[near]])
        python[near] = False
    d[python | special] = 0.0
    top = d >= 1e12
    d[top] = 1e11
    e += top
    # twelve digits in two words (little-endian: the first digit in the lowest byte)
    g0 = np.floor(d / 1e8)
    d -= g0 * 1e8
    g1 = np.floor(d / 1e4)
    d -= g1 * 1e4
    g0i, g1i, g2i = g0.astype(np.intp), g1.astype(np.intp), d.astype(np.intp)
    lo = t["quad"][g1i] << _U(32)
    lo |= t["quad"][g0i]
    hi = t["quad"][g2i]
    digits = 12 - _trailing_zeros(t["zeros"], g0i, g1i, g2i)
    fixed = (e >= -4) & (e <= 11)
    small = fixed & (e < 0)
    before = np.where(fixed, np.maximum(e + 1, 0), 1).astype(_U)  # digits before "."
    keep = np.maximum(digits.astype(_U), before)
    dot = (keep > before) & ~small
    lo, hi = _insert_dot(lo, hi, before, keep, dot)
    case = negative * 5 + np.where(small, e + 4, 4)
    prefix_len = t["prefix_len"][case]
    shift = (prefix_len + _U(1)) * _U(8)
    words = np.empty((x.size, 3), _U)
    words[:, 0] = (lo << shift) | (t["prefix"][case] << _U(8)) | separator
    words[:, 1] = (hi << shift) | (lo >> (_U(64) - shift))
    words[:, 2] = hi >> (_U(64) - shift)
    scientific = np.flatnonzero(~fixed & ~python & ~special)
    if scientific.size:
        at = (1 + prefix_len + keep + dot)[scientific]
        _place(words, scientific, t["exponent"][e[scientific] + 401], at)
    odd = np.flatnonzero(special)
    if odd.size:
        kind = np.where(np.isnan(x[odd]), 0, 1 + negative[odd])
        words[odd, 0] = (t["special"][kind] << _U(8)) | (words[odd, 0] & _U(0xFF))
        words[odd, 1:] = 0
    for i in np.flatnonzero(python).tolist():
        text = bytes([int(separator[i])]) + b"%.12g" % x[i]
        words[i] = np.frombuffer(text.ljust(24, b"\0"), _U)
    return words


def _round_exactly(ax: Array, scale: Array) -> Array:
    """Round ``ax * scale`` to the nearest integer, ties to even, exactly.

    ``scale`` is an exact power of ten (up to 1e22), and the product lies in
    [1e11, 1e12) near a half: Dekker's error-free product gives the rounding error
    of ``y = ax * scale``, and the exact comparison of ``frac(y) - 0.5`` with it
    decides (Dekker 1971, Numerische Mathematik 18, 224-242).
    """
    y = ax * scale
    a_hi, a_lo = _split(ax)
    s_hi, s_lo = _split(scale)
    error = ((a_hi * s_hi - y) + a_hi * s_lo + a_lo * s_hi) + a_lo * s_lo
    floor = np.floor(y)
    half = (y - floor) - 0.5  # exact: y has at most 16 bits below the point
    up = (half > -error) | ((half == -error) & (np.fmod(floor, 2.0) == 1.0))
    return floor + up


def _split(a: Array) -> tuple[Array, Array]:
    """Split float64 numbers into two halves of 26 bits (Dekker)."""
    c = _SPLIT * a
    high = c - (c - a)
    return high, a - high


def _trailing_zeros(zeros: Ints, g0: Ints, g1: Ints, g2: Ints) -> Ints:
    """Return the trailing zeros of 12 digits given as three groups of four."""
    count = zeros[g2]
    more = np.flatnonzero(count == 4)
    if more.size:
        extra = zeros[g1[more]]
        again = extra == 4
        extra[again] += zeros[g0[more[again]]]
        count[more] += extra
    return count


def _insert_dot(
    lo: Ints, hi: Ints, before: Ints, keep: Ints, dot: Ints
) -> tuple[Ints, Ints]:
    """Keep ``keep`` digits and put a dot after the first ``before`` where ``dot``."""
    at = before * _U(8)
    end = keep * _U(8)
    mask_lo = _ALL << at  # the digits after the dot
    mask_hi = _ALL << (np.maximum(at, _U(64)) - _U(64))
    tail_lo = lo & mask_lo & ~(_ALL << end)
    tail_hi = hi & mask_hi & ~(_ALL << (np.maximum(end, _U(64)) - _U(64)))
    step = dot.astype(_U) * _U(8)
    point = dot.astype(_U) * _U(46)
    new_lo = (lo & ~mask_lo) | (tail_lo << step) | (point << at)
    new_hi = (
        (hi & ~mask_hi)
        | (tail_hi << step)
        | (tail_lo >> (_U(64) - step))
        | (point << (at - _U(64)))
    )
    return new_lo, new_hi


def _place(words: Ints, rows: Ints, suffix: Ints, at: Ints) -> None:
    """Write ``suffix`` words after ``at`` bytes of the numbers ``rows``."""
    bits = at * _U(8)
    words[rows, 0] |= suffix << bits
    words[rows, 1] |= (suffix << (bits - _U(64))) | (suffix >> (_U(64) - bits))
    words[rows, 2] |= (suffix << (bits - _U(128))) | (suffix >> (_U(128) - bits))
