"""Given answers (a textbook's, a student's) compared with the note's, slips found.

Answers are keyed by table column (``rod.alpha``, ``B.F``) or by a magnitude:
``P.v`` and ``P.a`` for a point's speed and acceleration (``rod.G.a`` for a centre
of mass) and ``L.Fi`` for a link's inertia force. Where a given inertia force
differs from the note's but the given acceleration of the same link agrees, the
given force is not ``m a_G`` of its own acceleration: a slip in the multiplication.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping

from assur._text import describe, suggest
from assur._vec import real
from assur.errors import ModelError, UsageError
from assur.explain._note import Block, Display, Grid, Heading, Para
from assur.explain._position import Position
from assur.explain._tex import ZERO, name, num, plain

__all__ = ["AGREE", "answer_blocks", "computed", "read_answers"]

AGREE = 5e-4
"""Relative difference within which a given answer agrees (its printed digits)."""


PARTS = {"v": ("vx", "vy"), "a": ("ax", "ay"), "Fi": ("Fi.x", "Fi.y")}
"""The components of a magnitude an answer may give (a point's speed, say)."""
MAX_ANSWERS_BYTES = 2**20
"""Largest file of given answers read, bytes (1 MiB; such a file takes a few lines)."""


def read_answers(path: str | os.PathLike[str]) -> tuple[dict[str, float], str]:
    """Read a TOML file of given answers: ``[answers]`` and an optional ``source``.

    A key may be quoted (``"B.F" = 1928.5``) or not (``B.F = 1928.5``, which TOML
    reads as nested tables: they are joined again by dots).

    Raises
    ------
    ModelError
        When the file cannot be read or an answer is not a finite number.
    """
    import tomllib

    from assur._file_syntax import _decoded
    from assur.io import read_capped

    where = os.fspath(path)
    raw = read_capped(
        path,
        where,
        MAX_ANSWERS_BYTES,
        "a TOML file of given answers",
        "a file of given answers (a few lines of TOML)",
    )
    try:
        text = _decoded(raw, "a TOML file of given answers saved as UTF-8")
    except ModelError as err:
        msg = f"{where}: {err}"
        raise ModelError(msg) from err
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        msg = f"{where}: cannot read the answers ({err})"
        raise ModelError(msg) from err
    table = data.get("answers")
    if not isinstance(table, dict):
        msg = f"{where}: expected a table [answers] of quantity = value"
        raise ModelError(msg)
    if not table:
        msg = f"{where}: [answers] is empty; expected lines of quantity = value"
        raise ModelError(msg)
    answers = {}
    for key, value in _flat(table).items():
        number = real(value)
        if number is None or not math.isfinite(number):
            msg = (
                f"{where}: answers.{key}: expected a finite number, got "
                f"{describe(value)}"
            )
            raise ModelError(msg)
        answers[key] = number
    return answers, str(data.get("source", ""))


def checked_answers(answers: object) -> dict[str, float]:
    """Return given answers as floats by name, checked as :func:`read_answers` does.

    Raises
    ------
    UsageError
        For anything but a mapping of names to finite real numbers.
    """
    if not isinstance(answers, Mapping):
        msg = (
            "answers: expected a mapping of quantity names to numbers, got "
            f"{type(answers).__name__}"
        )
        raise UsageError(msg)
    out = {}
    for key, value in answers.items():
        if not isinstance(key, str):
            msg = f"answers: expected quantity names as keys, got {describe(key)}"
            raise UsageError(msg)
        number = real(value)
        if number is None or not math.isfinite(number):
            msg = f"answers.{key}: expected a finite number, got {describe(value)}"
            raise UsageError(msg)
        out[key] = number
    return out


def _flat(table: Mapping[str, object], prefix: str = "") -> dict[str, object]:
    """Return a nested table's values by their dotted keys (``B.F``)."""
    out: dict[str, object] = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(_flat(value, name + "."))
        else:
            out[name] = value
    return out


def computed(pos: Position, key: str) -> float:
    """Return the note's value of quantity ``key`` (see the module's keys).

    Raises
    ------
    ModelError
        When ``key`` names no quantity of the mechanism.
    """
    table = pos.table
    if key in table.columns:
        return float(table[key][0])
    owner, _, what = key.rpartition(".")
    pairs = PARTS
    if what in pairs and f"{owner}.{pairs[what][0]}" in table.columns:
        x, y = (float(table[f"{owner}.{c}"][0]) for c in pairs[what])
        return math.hypot(x, y)
    # the names a mistyped key may have meant: the columns and the magnitudes
    known = [*table.columns]
    for part, (first, _) in pairs.items():
        ending = f".{first}"
        known += [c[: -len(first)] + part for c in table.columns if c.endswith(ending)]
    hint = suggest(key, known, listing=False).removeprefix("; ")
    msg = (
        f"answers.{key}: no such quantity{f' ({hint})' if hint else ''}; expected a "
        "table column, 'P.v' or 'P.a' (a point's speed, acceleration) or 'L.Fi' (a "
        "link's inertia force)"
    )
    raise ModelError(msg)


def _unit(pos: Position, key: str) -> str:
    """Return the unit of quantity ``key`` (TeX): its column's, or its parts'."""
    columns = pos.table.columns
    if key not in columns:
        owner, _, what = key.rpartition(".")
        key = f"{owner}.{PARTS[what][0]}"
    thin = pos.table.column(key).unit.replace(" ", "\\,")
    return f"$\\mathrm{{{thin}}}$"


def _slip(pos: Position, link: str, given: Mapping[str, float]) -> str | None:
    """Say why a given inertia force of ``link`` differs, when its aG agrees."""
    force, accel = given.get(f"{link}.Fi"), given.get(f"{link}.G.a")
    if force is None or accel is None:
        return None
    mass = float(pos.loads.mass[pos.plan.body(link)])
    ours_a = computed(pos, f"{link}.G.a")
    ours_f = mass * ours_a
    if abs(accel - ours_a) > AGREE * ours_a or abs(force - ours_f) <= AGREE * ours_f:
        return None
    theirs = mass * accel
    return (
        f"The given $F_{{i,{name(link)}}} = {force:g}$ N is not $m a_G$ of the given "
        f"$a_G = {accel:g}\\ \\mathrm{{m/s^2}}$: $m a_G = {mass:g} \\cdot {accel:g} "
        f"= {theirs:.3f}$ N, "
        f"and with the exact acceleration $m a_G = {mass:g} \\cdot {ours_a:.3f} = "
        f"{ours_f:.3f}$ N. The acceleration agrees; the difference of "
        f"{force - ours_f:+.2f} N is a slip in the given multiplication."
    )


def _verdict(value: float, ours: float) -> tuple[str, str]:
    """Return the difference of a given answer from the note's, and the verdict.

    The difference is relative to the note's value (positive: the given one is
    larger). A value the note prints as 0 (round-off, below ``ZERO``) agrees with a
    given one that small too; an undefined one (a translating link's instant
    centre, say) is no verdict.
    """
    if not math.isfinite(ours):
        return "", "undefined here"
    if abs(ours) < ZERO:
        return "", "agrees" if abs(value) < ZERO else "differs"
    diff = (value - ours) / abs(ours)
    if abs(diff) < 1e4:
        shown = f"{100 * diff:+.3f}"
        # a difference that rounds to nothing is +0.000, not -0.000
        shown = "+0.000" if shown == "-0.000" else shown
    else:  # three digits of a difference too large to read so (nor to scale by 100)
        mantissa, power = f"{diff:+.2e}".split("e")
        shown = f"{mantissa}e{int(power) + 2:+03d}"
    return f"${shown}$ %", "agrees" if abs(diff) <= AGREE else "differs"


def answer_blocks(
    pos: Position, given: Mapping[str, float], source: str
) -> list[Block]:
    """Return the comparison of the given answers with the note's values."""
    rows = []
    for key, value in given.items():
        ours = computed(pos, key)
        rows.append(
            (
                plain(key),
                f"${value:g}$",
                f"${num(ours)}$",
                _unit(pos, key),
                *_verdict(value, ours),
            )
        )
    blocks: list[Block] = [
        Heading(2, "7. The given answers"),
        Para(
            f"The answers of {plain(source) or 'the given solution'} against the ones "
            f"above (an answer within {100 * AGREE:g} % of the note's value, the "
            "digits such answers are printed with, is taken to agree):"
        ),
        Grid(
            ("quantity", "given", "here", "unit", "difference", ""),
            tuple(rows),
            "The given answers against the note's values",
        ),
    ]
    links = {k[: -len(".Fi")] for k in given if k.endswith(".Fi")}
    for link in sorted(links):
        text = _slip(pos, link, given)
        if text:
            blocks.append(Para(text))
    verdicts = [r[5] for r in rows]
    undefined = verdicts.count("undefined here")
    if "differs" in verdicts or undefined == len(verdicts):
        return blocks
    if undefined:
        text = f"every other given answer agrees ({undefined} undefined here)"
    else:
        text = "every given answer agrees"
    blocks.append(Display((f"\\text{{{text}}}",)))
    return blocks
