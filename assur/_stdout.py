"""Blocks of bytes written whole, to a file or to standard output, or an error.

:func:`write_all` writes every byte of a block (to a file or standard output);
:func:`stdout_writer` gives the table writers standard output's bytes and their
encoding, checked; :func:`write_stdout` writes text. A failed write to standard
output is a :class:`StdoutError` (or its OSError), told apart from a file's.
"""

from __future__ import annotations

import codecs
import errno
import sys
from collections.abc import Callable
from typing import Any

from assur.errors import OutputError

__all__ = ["StdoutError", "stdout_writer", "unmarked", "write_all", "write_stdout"]

_ASCII = "".join(map(chr, range(32, 127))) + "\n"
"""The characters of a table's rows and JSON: written as ASCII bytes, whatever the
encoding of standard output."""


def write_all(stream: Any, data: bytes) -> None:
    """Write every byte of ``data`` to a binary stream, or raise its OSError.

    A buffered stream may write part of a large block and drop the rest when the
    disk fills up; writing again what is left makes the fault show.
    """
    view = memoryview(data)
    while view:
        count = stream.write(view)
        if not count:
            msg = "the stream took no data"
            raise OSError(errno.EIO, msg)
        view = view[count:]
    stream.flush()


def write_stdout(text: str) -> None:
    """Write ``text`` to standard output, all of it or an OSError.

    Characters that its encoding cannot show are written as backslash escapes.
    """
    stream = sys.stdout
    buffer = getattr(stream, "buffer", None)
    if buffer is None:  # a notebook's stream: no bytes below
        stream.write(text)
        return
    stream.flush()
    write_all(buffer, text.encode(_encoding(stream), "backslashreplace"))


def as_written(text: str) -> str:
    """Return ``text`` as :func:`write_stdout` shows it, escapes included.

    What standard output's encoding cannot write (a Greek name on a Windows-1251
    output) is written as backslash escapes: a table aligned on the text before
    its escapes was out of line after them.
    """
    stream = sys.stdout
    if getattr(stream, "buffer", None) is None:  # a notebook's stream: as it is
        return text
    encoding = _encoding(stream)
    try:
        return text.encode(encoding, "backslashreplace").decode(encoding)
    except LookupError:
        return text


class StdoutError(Exception):
    """A write to standard output failed (``error``, an OSError).

    Not an OSError itself, so that :func:`output_path` around it does not take the
    fault for its own file's; the caller raises ``error`` once the files are cleaned
    up.
    """

    def __init__(self, error: OSError) -> None:
        super().__init__(str(error))
        self.error = error


def stdout_writer() -> tuple[Callable[[bytes], None], Callable[[str], bytes]]:
    """Return ``write(bytes)`` to standard output and the ``encode(text)`` it needs.

    Text that the output's encoding cannot show (a column's name in Cyrillic on an
    ASCII output) raises :class:`~assur.errors.OutputError`: escaped, the names in
    the table would change without a word. A failed write raises
    :class:`StdoutError`.
    """
    stream = sys.stdout
    encoding = _encoding(stream)
    buffer = getattr(stream, "buffer", None)
    if buffer is not None and not _ascii_numbers(encoding):
        # the rows' numbers go out as ASCII bytes: under UTF-16 the names would not
        msg = (
            f"standard output: its encoding ({encoding}) does not write numbers as "
            "ASCII; expected a file (written in UTF-8) or standard output in UTF-8 "
            "(PYTHONIOENCODING=utf-8)"
        )
        raise OutputError(msg)

    def encode(text: str) -> bytes:
        try:
            data = text.encode(encoding)
        except UnicodeEncodeError as err:
            bad = err.object[err.start : err.end]
            msg = (
                f"standard output: its encoding ({encoding}) cannot write {bad!r} "
                "of the table; expected a file (written in UTF-8) or standard "
                "output in UTF-8 (PYTHONIOENCODING=utf-8)"
            )
            raise OutputError(msg) from None
        return data

    def write(data: bytes) -> None:
        try:
            if buffer is None:  # a notebook's stream: no bytes below
                stream.write(data.decode(encoding))
            else:
                write_all(buffer, data)
        except OSError as err:
            raise StdoutError(err) from err

    stream.flush()
    return write, encode


def _encoding(stream: Any) -> str:
    """Return the encoding text is written to ``stream`` in, bytes below it.

    UTF-8 with a byte-order mark is UTF-8: each write of its own would put a mark
    inside the text (the command line sets standard output so, print() included).
    """
    return unmarked(stream.encoding or "utf-8")


def unmarked(encoding: str) -> str:
    """Return ``encoding``, UTF-8 for UTF-8 with a byte-order mark (``utf-8-sig``)."""
    try:
        return "utf-8" if codecs.lookup(encoding).name == "utf-8-sig" else encoding
    except LookupError:
        return encoding


def _ascii_numbers(encoding: str) -> bool:
    """Whether ``encoding`` writes the rows' characters as ASCII does."""
    try:
        return _ASCII.encode(encoding) == _ASCII.encode("ascii")
    except (LookupError, UnicodeError):
        return False
