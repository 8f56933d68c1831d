"""The small helpers behind names in any script: each one's edges, one by one.

The command-line tests in test_unicode_names.py go through them with one file;
these pin what that file does not reach (a full-width letter, the micro sign, a
line separator in a comment, a logger left as it was found).
"""

from __future__ import annotations

import logging
import unicodedata

import pytest

from assur._decimal_comma import comma_at
from assur._fonts import glyphs_logged, missing_glyphs
from assur._lookalike import lookalike, spelled_apart
from assur._width import shown_width


def test_a_line_separator_in_a_comment_leaves_the_comma_found():
    # tomllib counts lines at "\n" alone; str.splitlines also splits at U+2028,
    # so the place named fell on another line and the hint was not given
    import tomllib

    text = "# a note\u2028more\nmass = 0,5\n"
    with pytest.raises(tomllib.TOMLDecodeError) as caught:
        tomllib.loads(text)
    assert comma_at(text, str(caught.value))


def test_a_place_past_the_last_line_is_no_comma():
    assert not comma_at("mass = 0,5", "Expected newline (at line 3, column 9)")


def test_the_micro_sign_looks_like_the_greek_mu():
    # a German keyboard's AltGr+M gives U+00B5, compatibility-equal to U+03BC
    assert lookalike("\u00b5", ["\u03bc", "nu"]) == "\u03bc"


def test_two_look_alikes_name_none_of_them():
    # Latin O given, Cyrillic and Greek O known: the hint cannot tell which
    assert lookalike("O", ["\u041e", "\u039f"]) is None


def test_a_name_is_no_look_alike_of_itself():
    assert lookalike("O", ["O", "A"]) is None


@pytest.mark.parametrize("count", [3, 4])
def test_the_characters_told_apart_are_three_at_most(count):
    # four Cyrillic letters against their Latin look-alikes: three named, "..."
    ours, theirs = "OPEC"[:count], "\u041e\u0420\u0415\u0421"[:count]
    said = spelled_apart(ours, theirs)
    named = [unicodedata.name(c) for c in theirs]
    for name in named[:3]:
        assert name in said
    assert (", ..." in said) is (count > 3)


@pytest.mark.parametrize(
    ("wide", "narrow"),
    [
        ("\uff21", "AA"),  # FULLWIDTH LATIN CAPITAL LETTER A: East Asian "F"
        ("a\u200f", "a"),  # RIGHT-TO-LEFT MARK: a format character, no column
        ("a\u200b", "a"),  # ZERO WIDTH SPACE
    ],
)
def test_full_width_and_format_characters_take_their_columns(wide, narrow):
    assert shown_width(wide) == shown_width(narrow) == len(narrow)


def test_a_glyph_missing_from_the_text_font_alone_is_told():
    char = "\u0c85"
    said = missing_glyphs(
        [
            f"Glyph {ord(char)} (\\N{{KANNADA LETTER A}}) missing from font(s) "
            "DejaVu Sans."
        ]
    )
    assert said is not None
    assert f"{char!r} (U+{ord(char):04X})" in said


def test_the_mathtext_logger_is_left_as_it_was_found(monkeypatch, caplog):
    # the command line keeps matplotlib's words to itself: what mathtext logs
    # meanwhile is gathered, reaches no other handler, and the logger is then as
    # the caller had set it
    logger = logging.getLogger("matplotlib.mathtext")
    monkeypatch.setattr(logger, "level", logging.DEBUG)
    before = (logger.level, logger.propagate, list(logger.handlers))
    with caplog.at_level(logging.WARNING), glyphs_logged() as heard:
        logger.warning("Font 'rm' does not have a glyph")
    assert heard == ["Font 'rm' does not have a glyph"]
    assert caplog.records == []
    assert (logger.level, logger.propagate, list(logger.handlers)) == before


def test_no_fallback_font_installed_changes_nothing(monkeypatch):
    from assur import _fonts

    monkeypatch.setattr(_fonts, "FALLBACKS", ())
    assert _fonts.fallback_fonts() == {}


@pytest.mark.parametrize(
    "mark", list("\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")
)
def test_every_embedding_override_and_isolate_is_a_control(mark):
    # Unicode's explicit directional formatting characters, all nine: each one
    # turns the text after it around
    from assur._checks import _control

    assert _control(f"rod{mark}_1") == mark


def test_a_place_before_a_line_s_start_names_no_decimal_comma():
    # a JSON fault at a line's first column is given one column back, column 0:
    # the slice up to it read the whole line as lying before the place
    assert not comma_at('{"a": 1,\n"mass": 1,5}', "(at line 2, column 0)")
    assert comma_at('{"a": 1,\n"mass": 1,5}', "(at line 2, column 10)")
