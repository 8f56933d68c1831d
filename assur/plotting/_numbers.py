"""The one way the pictures write a number with its unit: "1928 N", "2.35 MN".

Labels, legends and titles of :mod:`assur.plotting` write their forces, torques
and scales through :func:`quantity`, so that no picture writes "1.93e+03 N".
"""

from __future__ import annotations

import math

from assur._digits import settled

PLAIN_RANGE = (1e-4, 1e6)
"""Magnitudes written in plain digits: up to six digits before the point."""
PREFIXED = ("N", "N·m", "W", "J")
"""Units that take an SI prefix beyond :data:`PLAIN_RANGE` (not "kg", not "N/mm")."""
PREFIXES = {6: "M", 9: "G", 12: "T"}
"""SI prefixes by power of ten, above :data:`PLAIN_RANGE`. None below it: a tiny
value is mostly round-off (a conservative cycle's mean torque), written in the
axis's own unit, "1.5e-08 N·m", not "15 nN·m"."""


def number(value: float, digits: int = 4) -> str:
    """Return ``value`` with ``digits`` significant digits, in plain digits.

    Every digit before the point is written (1928.4 is "1928", not "1930"); the
    trailing zeros after it are not. Beyond :data:`PLAIN_RANGE` the scientific
    form, as ``format(value, "g")`` writes it.

    Examples
    --------
    >>> number(1928.4, 3), number(12.8199), number(-0.5), number(11268.3)
    ('1928', '12.82', '-0.5', '11268')
    >>> number(2.5e7, 3), number(0.0), number(999999.7)
    ('2.5e+07', '0', '1e+06')
    """
    value = settled(value)  # a decimal tie rounds alike on every machine
    size = abs(value)
    if not math.isfinite(value) or size == 0.0:
        return f"{value + 0.0:g}"
    # the range as the value is written: 999999.7 rounds to a seventh digit
    size = abs(float(f"{value:.{digits}g}"))
    if not PLAIN_RANGE[0] <= size < PLAIN_RANGE[1]:
        return f"{value:.{digits}g}"
    before = math.floor(math.log10(size)) + 1
    text = f"{value:.{max(0, digits - before)}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def quantity(value: float, unit: str, digits: int = 4) -> str:
    """Return ``value`` and its ``unit``, SI-prefixed above plain digits.

    Examples
    --------
    >>> quantity(1928.4, "N", 3), quantity(-1.45e4, "N·m", 3)
    ('1928 N', '-14500 N·m')
    >>> quantity(2.345e7, "N", 3), quantity(1.5e-8, "N·m"), quantity(2e7, "N/mm")
    ('23.4 MN', '1.5e-08 N·m', '2e+07 N/mm')
    >>> quantity(999999.7, "N"), quantity(9.9996e8, "N")
    ('1 MN', '1 GN')
    """
    # the range and the prefix as the value is written, rounded: 9.9996e8 N is
    # "1 GN", not "1000 MN"
    size = abs(float(f"{value:.{digits}g}")) if math.isfinite(value) else abs(value)
    plain = size == 0.0 or PLAIN_RANGE[0] <= size < PLAIN_RANGE[1]
    if plain or not math.isfinite(value) or unit not in PREFIXED:
        return f"{number(value, digits)} {unit}".rstrip()
    power = 3 * math.floor(math.log10(size) / 3)
    if power not in PREFIXES:
        return f"{number(value, digits)} {unit}"
    return f"{number(value / 10.0**power, digits)} {PREFIXES[power]}{unit}"
