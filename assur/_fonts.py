"""Fonts for names in any script on the pictures, and a word where none has them.

matplotlib's default font (DejaVu Sans) has Latin, Greek and Cyrillic letters but
no CJK ones: a link named "滑块" was drawn as two empty boxes, with one matplotlib
warning per character and per drawing. The pictures of the command line and the
report add the fonts installed for such scripts after the user's own font
(matplotlib takes a missing glyph from the next font of the family list), and the
command line turns what is still missing into one warning line.
"""

from __future__ import annotations

import contextlib
import re
import warnings
from collections.abc import Iterator
from typing import Any

__all__ = [
    "GLYPH_MISSING",
    "MATH_GLYPH_MISSING",
    "fallback_fonts",
    "glyphs_logged",
    "missing_glyphs",
]

FALLBACKS = (
    "Noto Sans CJK SC",
    "Noto Sans CJK JP",
    "Noto Sans CJK KR",
    "Source Han Sans SC",
    "WenQuanYi Zen Hei",
    "WenQuanYi Micro Hei",
    "Droid Sans Fallback",
    "Microsoft YaHei",
    "SimHei",
    "Yu Gothic",
    "MS Gothic",
    "Malgun Gothic",
    "PingFang SC",
    "Hiragino Sans",
    "Arial Unicode MS",
)
"""Fonts with CJK glyphs, on Linux, Windows and macOS, tried in this order."""

GLYPH_MISSING = re.compile(r"Glyph (\d+) \(.+\) missing from font\(s\) .+\.")
"""matplotlib's warning for a character its font cannot draw."""
MATH_GLYPH_MISSING = re.compile(
    r"Font '.+' does not have a glyph for '.+' \[U\+([0-9a-fA-F]+)\], "
    r"substituting with a dummy symbol\."
)
"""mathtext's log message for a character its font cannot draw."""


def fallback_fonts() -> dict[Any, Any]:
    """Return the rc settings that add the installed fallback fonts.

    Returns
    -------
    dict
        ``{"font.family": [the user's font, *fallbacks]}`` with the fallbacks that
        are installed, or ``{}`` where none is (nothing then changes).
    """
    import matplotlib as mpl
    from matplotlib import font_manager

    installed = {entry.name for entry in font_manager.fontManager.ttflist}
    extra = [name for name in FALLBACKS if name in installed]
    if not extra:
        return {}
    # the family the user's settings resolve to stays first: a glyph it has is
    # drawn exactly as before
    prop = font_manager.FontProperties(family=mpl.rcParams["font.family"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a font not found falls back quietly
        first = font_manager.get_font(font_manager.findfont(prop)).family_name
    return {"font.family": [first, *(n for n in extra if n != first)]}


@contextlib.contextmanager
def glyphs_logged() -> Iterator[list[str]]:
    """Yield a list that gathers mathtext's log of glyphs it cannot draw, meanwhile.

    A name in a label's subscript is set by mathtext, whose fonts take no fallback:
    it logs the glyph it replaces by a box (not a warning, so the command line
    said nothing of it).
    """
    import logging

    heard: list[str] = []

    class _Gather(logging.Handler):
        def emit(self, record: logging.LogRecord) -> None:
            heard.append(record.getMessage())

    logger = logging.getLogger("matplotlib.mathtext")
    level = logger.level
    # the command line keeps matplotlib's own words at ERROR (_plain_matplotlib):
    # this logger's warnings reach the list meanwhile, and go nowhere else
    logger.setLevel(logging.WARNING)
    gather = _Gather(logging.WARNING)
    logger.addHandler(gather)
    propagate, logger.propagate = logger.propagate, False
    try:
        yield heard
    finally:
        logger.removeHandler(gather)
        logger.setLevel(level)
        logger.propagate = propagate


def missing_glyphs(messages: list[str]) -> str | None:
    """Return one line for matplotlib's words on missing glyphs, None if none.

    Parameters
    ----------
    messages : list of str
        Warnings' and log messages; those not about a missing glyph are ignored.
    """
    chars: dict[str, None] = {}
    for message in messages:
        found = GLYPH_MISSING.fullmatch(message)
        if found:
            chars[chr(int(found.group(1)))] = None
        found = MATH_GLYPH_MISSING.fullmatch(message)
        if found:
            chars[chr(int(found.group(1), 16))] = None
    if not chars:
        return None
    shown = ", ".join(f"{c!r} (U+{ord(c):04X})" for c in chars)
    return (
        f"the pictures' fonts cannot draw {shown}, drawn as empty boxes; expected "
        "a font that has them installed where matplotlib finds it (the Noto fonts "
        "cover most scripts; a name in a symbol's subscript needs it as "
        "matplotlib's mathtext font)"
    )
