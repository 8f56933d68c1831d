"""The small helpers behind names in any script: each one's edges, one by one.

The command-line tests in test_unicode_names.py go through them with one file;
these pin what that file does not reach (a full-width letter, the micro sign, a
line separator in a comment, a logger left as it was found).
"""

from __future__ import annotations

import pytest

from assur._decimal_comma import comma_at


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
