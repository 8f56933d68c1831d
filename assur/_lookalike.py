"""Names that look the same and are not: the hint of a message about an unknown name.

A student who types a joint's name in Latin ("O") in one place and in Cyrillic
("О") in another, or an accent as one character in one place and as a letter with
a combining mark in another (editors differ), was told "unknown joint 'O' (known:
A, B, О)" or "did you mean 'é'?" for an 'é': both look the same on the screen.
"""

from __future__ import annotations

import difflib
import unicodedata
from collections.abc import Iterable

__all__ = ["lookalike", "spelled_apart"]

_LATIN = dict(
    zip(
        "АВЕЅІЈКМНОРСТХУаеѕіјорсхуΑΒΕΖΗΙΚΜΝΟΡΤΥΧοϲ",
        "ABESIJKMHOPCTXYaesijopcxyABEZHIKMNOPTYXoc",
        strict=True,
    )
)
"""Cyrillic and Greek letters drawn as a Latin one, and that Latin letter."""


def _key(text: str) -> str:
    """Return ``text`` as it looks, to compare two names by.

    Compatibility-normalised, without format characters (U+200B, say), with Latin
    letters for their look-alikes.
    """
    text = unicodedata.normalize("NFKC", text)
    text = "".join(c for c in text if unicodedata.category(c) != "Cf")
    return "".join(_LATIN.get(c, c) for c in text)


def lookalike(name: str, known: Iterable[str]) -> str | None:
    r"""Return the one of ``known`` that looks like ``name`` and is not it, or None.

    Parameters
    ----------
    name : str
        A name the file or the call gave, found nowhere.
    known : iterable of str
        The names it may stand for.

    Examples
    --------
    >>> lookalike("O", ["A", "\u041e"])  # Latin O, Cyrillic O
    'О'
    >>> lookalike("e\u0301", ["\xe9"]) == "\xe9"
    True
    >>> lookalike("rod", ["crank"]) is None
    True
    """
    wanted = _key(name)
    found = [k for k in known if k != name and _key(k) == wanted]
    return found[0] if len(found) == 1 else None


def spelled_apart(name: str, other: str) -> str:
    r"""Return the words that tell ``name`` from its look-alike ``other``.

    Only the characters that differ are named, by code point and Unicode name.

    Examples
    --------
    >>> print(spelled_apart("O", "\u041e").replace(" where", "\nwhere"))
    they look alike, but the known name has U+041E CYRILLIC CAPITAL LETTER O
    where this one has U+004F LATIN CAPITAL LETTER O
    """
    apart = difflib.SequenceMatcher(None, name, other, autojunk=False).get_opcodes()
    ours = "".join(name[i:j] for tag, i, j, _, _ in apart if tag != "equal")
    theirs = "".join(other[i:j] for tag, _, _, i, j in apart if tag != "equal")
    return (
        f"they look alike, but the known name has {_points(theirs)} where this one has "
        f"{_points(ours)}"
    )


def _points(text: str) -> str:
    """Return the first characters of ``text`` by code point and name."""
    named = [f"U+{ord(c):04X} {unicodedata.name(c, '')}".rstrip() for c in text[:3]]
    return ", ".join(named) + (", ..." if len(text) > 3 else "") or "nothing"
