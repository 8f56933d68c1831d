"""The characters pdflatex sets with the note's preamble, and those it cannot.

The LaTeX note is set in T1 fonts with the UTF-8 input of LaTeX (see
:data:`assur.explain._latex.PREAMBLE`): Latin letters with their accents and the
usual punctuation. A name in Cyrillic, Greek or CJK letters, or with a combining
accent, stopped pdflatex at its first character ("Unicode character К (U+041A)
not set up for use with LaTeX"); the note now says so, in its first lines and in
a warning, since no preamble that every TeX installation compiles sets them.
"""

from __future__ import annotations

import functools

__all__ = ["unset"]

SET = (
    "A0-B7 B9-125 128-137 139-13E 141-148 14A-165 168-17E 192 1C4-1D4 1E2-1E3 "
    "1E6-1EB 1F0 1F4-1F5 218-21B 232-233 237 2C7 2D8-2D9 2DB 2DD E3F 1E02-1E03 "
    "1E0D 1E1E-1E21 1E25 1E30-1E31 1E37 1E43 1E45 1E47 1E5B 1E63 1E6D 1E8E-1E91 "
    "1E9E 1EF2-1EF3 200C 2010-2016 2018-201A 201C-201E 2020-2022 2030-2031 "
    "2039-203B 203D 2044 204E 2052 20A1 20A4 20A6 20A9 20AB-20AC 20B1 2103 "
    "2116-2117 211E 2120 2122 2126-2127 212E 2190-2193 2329-232A 2422-2423 25E6 "
    "25EF 266A 27E8-27E9 3008-3009 FB00-FB06 FEFF "
)
"""Code points (hexadecimal, ranges with '-') that LaTeX's t1enc.dfu, ts1enc.dfu and
omsenc.dfu (LaTeX 2023) declare, and those the preamble declares itself (U+2192)."""


@functools.cache
def _ranges() -> tuple[tuple[int, int], ...]:
    """Return :data:`SET` as pairs of first and last code points."""
    pairs = []
    for word in SET.split():
        first, _, last = word.partition("-")
        pairs.append((int(first, 16), int(last or first, 16)))
    return tuple(pairs)


def unset(text: str) -> list[str]:
    """Return the characters of ``text`` pdflatex cannot set, each once, in order.

    Parameters
    ----------
    text : str
        The LaTeX of the note.

    Examples
    --------
    >>> unset("manivelle_é, кривошип, 滑块")
    ['к', 'р', 'и', 'в', 'о', 'ш', 'п', '滑', '块']
    >>> unset("Système bielle–manivelle, 45°")
    []
    """
    ranges = _ranges()
    found: dict[str, None] = {}
    for char in text:
        code = ord(char)
        if code >= 0x80 and not any(a <= code <= b for a, b in ranges):
            found[char] = None
    return list(found)
