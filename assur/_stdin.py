"""The mechanism file read from standard input: ``-`` in place of its name.

``assur structure - < four_bar.toml``, or the end of a pipe. The text is TOML, or
JSON when it starts with ``{``; messages name it ``<stdin>``.
"""

from __future__ import annotations

import sys
from typing import Any

from assur.errors import AssurError, ModelError

__all__ = ["STDIN", "from_stdin", "input_text"]

STDIN = "-"
"""The name that stands for standard input on the command line."""
WHERE = "<stdin>"
"""How messages name standard input."""


def input_text(path: Any) -> str:
    """Return how messages name the mechanism file ``path`` (``<stdin>`` for -)."""
    from assur._output import path_text

    return WHERE if str(path) == STDIN else path_text(path)


def _terminal(stream: Any) -> bool:
    """Whether ``stream`` is a terminal."""
    try:
        return bool(stream.isatty())
    except (AttributeError, OSError, ValueError):
        return False


def from_stdin() -> Any:
    """Return the mechanism read from standard input, validated.

    Raises
    ------
    ModelError
        With a message naming ``<stdin>``: closed or a terminal, larger than the
        cap of a mechanism file, not UTF-8, or a fault of the mechanism.
    """
    from assur._file_syntax import _decoded
    from assur.io import MAX_FILE_BYTES, loads

    stream = getattr(sys.stdin, "buffer", None)
    if stream is None:
        msg = f"{WHERE}: standard input is closed; expected a mechanism file piped in"
        raise ModelError(msg)
    if _terminal(sys.stdin):
        # reading would wait, without a word, for a file typed in
        msg = (
            f"{WHERE}: standard input is a terminal; expected a mechanism file piped "
            "in (assur structure - < four_bar.toml)"
        )
        raise ModelError(msg)
    try:
        # one byte beyond the cap tells a file too large from one just large
        data = stream.read(MAX_FILE_BYTES + 1)
    except (OSError, ValueError) as err:
        msg = f"{WHERE}: cannot read standard input ({err})"
        raise ModelError(msg) from err
    if len(data) > MAX_FILE_BYTES:
        msg = (
            f"{WHERE}: larger than {MAX_FILE_BYTES // 2**20} MiB; expected a "
            "mechanism file (a few kilobytes of TOML or JSON)"
        )
        raise ModelError(msg)
    try:
        text = _decoded(data)
        # a mechanism's JSON is one object; TOML cannot start with a brace
        return loads(text, json_format=text.lstrip().startswith("{"))
    except AssurError as err:
        msg = f"{WHERE}: {err}"
        raise type(err)(msg) from err
