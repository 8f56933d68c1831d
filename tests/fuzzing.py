"""Mutants of the bundled examples: a TOML writer and the mutations, text and data.

A case is an example of examples/*.toml mutated at one of two levels: its text
(characters and lines flipped, deleted, duplicated or swapped, tokens swapped, numbers
rewritten, the text cut short) or its parsed data (numbers replaced by extremes, values
by other types, keys deleted, duplicated or renamed; joint kinds, links and axes,
drivers, points, loads and gravity changed; the whole mechanism scaled or moved),
written back by :func:`toml_text` (or by ``assur.dumps`` when the data still reads).
Every draw comes from one ``random.Random``: a seed gives the same cases everywhere.
:mod:`tests.fuzz_run` runs the cases.
"""

from __future__ import annotations

import datetime as dt
import itertools
import json
import math
import random
import re
import tomllib
import warnings
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import assur

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
NAN, INF = math.nan, math.inf

ACCEPTED: tuple[Any, ...] = (
    0, 0.0, -0.0, -1, -1.0, 1, 1e-300, 5e-324, -5e-324, 1e-160, 1e-12, 1e-6, 1e6,
    1e12, 1e14, 1e15, -1e15, 2**49 + 1,
)  # fmt: skip
"""Extreme numbers that the model accepts (magnitudes up to 1e15)."""
REJECTED: tuple[Any, ...] = (
    1.0000001e15, 1e16, 1e300, 1e308, -1e308, NAN, INF, -INF, 2**53 + 1, 2**63,
    -(2**63) - 1, 10**30, 10**400,
)  # fmt: skip
"""Numbers beyond what the model accepts."""
EXTREMES = ACCEPTED + REJECTED
ODD: tuple[Any, ...] = (
    "", "x", "ground", "nan", "1.0", True, False, [], {}, [[]], [[0.0, 0.0]], [0.0],
    [0.0, 0.0, 0.0], ["A", "B"], [1, "x"], {"x": 1.0}, {"from": "A"},
    dt.date(1979, 5, 27), dt.datetime(1979, 5, 27, 7, 32),
    dt.datetime(1979, 5, 27, 7, 32, tzinfo=dt.UTC), dt.time(7, 32), 10**30, 1e308,
)  # fmt: skip
"""Values of other types (TOML datetimes included) that replace any value."""
NAMES = (
    "ground", "", "A", "crank", "a.b", "x~y", "a,b", "angle", "driver", "residual",
    "é", " ", "\t", "line\nbreak", "x" * 200, "1", "null", "\u202e", "🙂",
)  # fmt: skip
"""Names that replace a key or a reference."""
KINDS = ("revolute", "prismatic", "slot", "Prismatic", "weld", "")
AXES: tuple[Any, ...] = (
    [0.0, 0.0], [1e-300, 0.0], [5e-324, 5e-324], [1e15, 1e15], [1e300, 1.0],
    [-1.0, 0.0], [0.0, -1.0], [1.0, 1e-17], [NAN, 1.0], [3, 4], [1.0], "x",
)  # fmt: skip
FACTORS = (
    1e-300, 1e-160, 1e-12, 1e-9, 1e-6, 1e-3, 1e3, 1e6, 1e9, 1e12, 1e14, -1.0, 1e20,
)  # fmt: skip
"""Factors that scale the whole mechanism (every coordinate and distance)."""
OFFSETS = (1e2, 1e3, 1e4, 1e6, -1e6, 1e8, 1e9, 1e12, 1e15, 1e20)
"""Offsets that move the whole mechanism."""
CHARS = "[]{}=\"',.#\n 0123456789-+eE_axyzé\t\\\x00\x7f\u202e\ufeff🙂"
LITERALS = (
    "1e999", "-1e999", "nan", "-nan", "+inf", "-inf", "0", "-0.0", "5e-324",
    "1e-400", "1e308", "1e15", "1e16", "0x7fffffffffffffff", "0b1", "0o7", "1_000.5",
    "9" * 5000, "9" * 30, "1979-05-27", "1979-05-27T07:32:00Z", "07:32:00", "true",
    '"3.0"', "[]", "{}", "[1.0, 2.0, 3.0]", "'A'",
)  # fmt: skip
"""TOML literals (some invalid) that replace a number of the text."""
LINES = (
    "format = 2", "format = 1.0", "[links.ground]", "[links.extra]", "mass = 1.0",
    "friction = 0.1", '[[drivers]]\njoint = "A"\nomega = 1.0', "[gravity]", "x = 1",
    "links = []", "[joints]", "name = 1", '[points]\nQ = { link = "ground", at = "A" }',
)  # fmt: skip
"""Lines inserted into the text."""
TOKEN = re.compile(r'"[^"\n]*"|[A-Za-z_][\w.]*|[-+]?\d[\w.+-]*|\S')
NUMBER = re.compile(r"(?<![\w.\"])[-+]?\d[\d_]*(\.\d+)?([eE][-+]?\d+)?(?![\w.\"])")


@dataclass(frozen=True)
class Case:
    """One mutant: its number, the example it comes from, what was done, the text."""

    number: int
    base: str
    mutations: tuple[str, ...]
    text: str


def bases() -> list[tuple[str, str]]:
    """Every bundled example: its name and text."""
    return [
        (p.stem, p.read_text(encoding="utf-8")) for p in sorted(EXAMPLES.glob("*.toml"))
    ]


def make_case(number: int, rng: random.Random, base: tuple[str, str]) -> Case:
    """Return mutant ``number`` of ``base``: one to three mutations at one level.

    A quarter of the mutants change the text, the others the data (a tenth of these
    also get a change of the text written from it).
    """
    name, text = base
    done: list[str] = []
    level = rng.random()
    count = rng.choice((1, 1, 1, 2, 3))
    if level < 0.25:
        for _ in range(count):
            text = mutate_text(text, rng, done)
    else:
        data = tomllib.loads(text)
        for _ in range(count):
            mutate_data(data, rng, done)
        text = written(data, rng, done)
        if level > 0.9:
            text = mutate_text(text, rng, done)
    return Case(number, name, tuple(done), text)


def stream(seed: int) -> Iterator[Case]:
    """Yield the cases of the run seeded with ``seed``, one example after another."""
    rng = random.Random(seed)
    examples = bases()
    for number in itertools.count():
        yield make_case(number, rng, examples[number % len(examples)])


def cases(count: int, seed: int) -> list[Case]:
    """Return the first ``count`` cases of the run seeded with ``seed``."""
    return list(itertools.islice(stream(seed), count))


# --- the TOML writer --------------------------------------------------------------

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def toml_text(data: dict[str, Any]) -> str:
    """Return TOML text that ``tomllib`` reads back to ``data``.

    Tables of the top levels get headers (``[links.crank]``, ``[[drivers]]``); the
    rest is written inline. Floats as TOML writes them (``nan``, ``inf``), dates and
    times as TOML datetimes.
    """
    lines: list[str] = []
    _write_table(lines, [], data)
    return "\n".join(lines).lstrip("\n") + "\n"


def _write_table(lines: list[str], path: list[str], data: dict[str, Any]) -> None:
    for key, value in data.items():
        if not _is_table(value) and not _is_tables(value):
            lines.append(f"{_key(key)} = {_value(value)}")
    for key, value in data.items():
        here = [*path, _key(key)]
        if _is_table(value):
            lines.append(f"\n[{'.'.join(here)}]")
            _write_table(lines, here, value)
        elif _is_tables(value):
            for item in value:
                lines.append(f"\n[[{'.'.join(here)}]]")
                _write_table(lines, here, item)


def _is_table(value: Any) -> bool:
    return isinstance(value, dict)


def _is_tables(value: Any) -> bool:
    return isinstance(value, list) and bool(value) and all(map(_is_table, value))


def _key(key: str) -> str:
    return key if _BARE.match(key) else _string(key)


def _string(text: str) -> str:
    out = []
    for c in text:
        if c in '"\\':
            out.append("\\" + c)
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append(f"\\u{ord(c):04x}")
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


def _value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, dt.date | dt.time):  # datetimes are dates too
        return value.isoformat()
    if isinstance(value, list):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    if isinstance(value, dict):
        items = ", ".join(f"{_key(k)} = {_value(v)}" for k, v in value.items())
        return "{ " + items + " }" if items else "{}"
    msg = f"no TOML for {type(value).__name__}"
    raise TypeError(msg)


def written(data: dict[str, Any], rng: random.Random, done: list[str]) -> str:
    """Write ``data`` as TOML; a quarter of the time through ``assur.dumps``."""
    text = toml_text(data)
    if rng.random() < 0.25:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                text = assur.dumps(assur.loads(text))
            done.append("written by assur.dumps")
        except Exception:  # the run meets the same error and classifies it
            pass
    return text


# --- mutations of the text --------------------------------------------------------


def mutate_text(text: str, rng: random.Random, done: list[str]) -> str:
    """Apply one mutation to the text; record it in ``done``."""
    what = rng.choice(
        ("flip", "delete", "duplicate", "line", "line", "tokens", "number", "number",
         "insert", "truncate")
    )  # fmt: skip
    n = max(len(text), 1)
    i = rng.randrange(n)
    lines = text.split("\n")
    k = rng.randrange(len(lines))
    if what == "flip":
        c = rng.choice(CHARS)
        text = text[:i] + c + text[i + 1 :]
        done.append(f"text: character {i} -> {c!r}")
    elif what == "delete":
        size = rng.randint(1, 4)
        text = text[:i] + text[i + size :]
        done.append(f"text: delete {size} characters at {i}")
    elif what == "duplicate":
        size = rng.randint(1, 20)
        text = text[: i + size] + text[i : i + size] + text[i + size :]
        done.append(f"text: duplicate {size} characters at {i}")
    elif what == "line":
        op = rng.choice(("delete", "duplicate", "swap"))
        if op == "delete":
            del lines[k]
        elif op == "duplicate":
            lines.insert(k, lines[k])
        else:
            j = rng.randrange(len(lines))
            lines[k], lines[j] = lines[j], lines[k]
        text = "\n".join(lines)
        done.append(f"text: {op} line {k + 1}")
    elif what == "tokens":
        tokens = list(TOKEN.finditer(text))
        if len(tokens) > 1:
            first, second = sorted(rng.sample(range(len(tokens)), 2))
            a, b = tokens[first], tokens[second]
            text = (
                text[: a.start()] + b.group() + text[a.end() : b.start()]
                + a.group() + text[b.end() :]
            )  # fmt: skip
            done.append(f"text: swap {a.group()!r} and {b.group()!r}")
    elif what == "number":
        numbers = list(NUMBER.finditer(text))
        if numbers:
            m = rng.choice(numbers)
            new = rng.choice(LITERALS)
            text = text[: m.start()] + new + text[m.end() :]
            done.append(f"text: number {m.group()!r} -> {new[:20]!r}")
    elif what == "insert":
        new = rng.choice(LINES)
        lines.insert(k, new)
        text = "\n".join(lines)
        done.append(f"text: insert {new!r} at line {k + 1}")
    else:
        text = text[:i]
        done.append(f"text: truncate at {i}")
    return text


# --- mutations of the data --------------------------------------------------------

Node = tuple[Any, Any, str]
"""A place in the data: its container, its key (or index) there, its path."""


def nodes(data: Any, path: str = "") -> list[Node]:
    """Every place in ``data`` below the top, depth first."""
    out: list[Node] = []
    items = (
        data.items() if isinstance(data, dict)
        else enumerate(data) if isinstance(data, list) else ()
    )  # fmt: skip
    for key, value in items:
        here = f"{path}.{key}" if isinstance(key, str) else f"{path}[{key}]"
        out.append((data, key, here.lstrip(".")))
        out += nodes(value, here)
    return out


def _is_number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _times(value: Any, factor: float) -> Any:
    """``value * factor``; a number too large for a float stays as it is."""
    try:
        return value * factor
    except OverflowError:
        return value


def _plus(value: Any, offset: float) -> Any:
    try:
        return float(value) + offset
    except OverflowError:
        return value


def _entries(data: dict[str, Any], section: str) -> list[tuple[str, dict[str, Any]]]:
    """The (name, table) entries of a section of tables, whatever it became."""
    value = data.get(section)
    if isinstance(value, dict):
        return [(str(k), v) for k, v in value.items() if isinstance(v, dict)]
    if isinstance(value, list):
        return [(str(i), v) for i, v in enumerate(value) if isinstance(v, dict)]
    return []


def _names(data: dict[str, Any], section: str) -> list[str]:
    value = data.get(section)
    return [str(k) for k in value] if isinstance(value, dict) else []


def point_slots(data: dict[str, Any]) -> list[Node]:
    """Every place that holds a point: joints' and loads' ``at``, centres, axes."""
    out: list[Node] = []
    for section, keys in (("joints", ("at",)), ("links", ("center",)),
                          ("loads", ("at",)), ("points", ("at",))):  # fmt: skip
        for name, entry in _entries(data, section):
            out += [(entry, k, f"{section}.{name}.{k}") for k in keys if k in entry]
    for name, link in _entries(data, "links"):
        axis = link.get("axis")
        if isinstance(axis, list):
            out += [(axis, i, f"links.{name}.axis[{i}]") for i in range(len(axis))]
    return out


def _point(data: dict[str, Any], rng: random.Random) -> Any:
    joints = _names(data, "joints") + _names(data, "points") or ["A"]
    a, b = rng.choice(joints), rng.choice(joints)
    return rng.choice((
        a, rng.choice(_names(data, "links") or ["x"]), rng.choice(NAMES),
        [0.0, 0.0], [rng.uniform(-1, 1), rng.uniform(-1, 1)], [1e15, -1e15],
        {"from": a, "toward": b, "distance": rng.choice((0.0, 0.05, -0.05))},
        {"from": a, "toward": a, "distance": 0.1},
        {"from": a, "toward": b, "distance": rng.choice(EXTREMES)},
        {"from": a, "toward": b}, [[0.0, 0.0], [1.0, 1.0]], [a, b],
    ))  # fmt: skip


def _extreme(data: dict[str, Any], rng: random.Random) -> str | None:
    found = [n for n in nodes(data) if _is_number(n[0][n[1]])]
    if not found:
        return None
    container, key, path = rng.choice(found)
    container[key] = value = rng.choice(ACCEPTED if rng.random() < 0.75 else REJECTED)
    return f"{path} = {_short(value)}"


def _odd(data: dict[str, Any], rng: random.Random) -> str | None:
    found = nodes(data)
    if not found:
        return None
    container, key, path = rng.choice(found)
    container[key] = value = _copy(rng.choice(ODD))
    return f"{path} = {_short(value)}"


def _swap_type(data: dict[str, Any], rng: random.Random) -> str | None:
    found = [n for n in nodes(data) if _is_number(n[0][n[1]])]
    if not found:
        return None
    container, key, path = rng.choice(found)
    value = container[key]
    if isinstance(value, int):
        container[key] = float(value) if abs(value) < 1e308 else 1e308
    elif math.isfinite(value) and value == int(value):
        container[key] = int(value)
    else:
        container[key] = round(value) if math.isfinite(value) else 0
    return f"{path} = {_short(container[key])} (int/float swapped)"


def _delete(data: dict[str, Any], rng: random.Random) -> str | None:
    found = nodes(data)
    if not found:
        return None
    container, key, path = rng.choice(found)
    del container[key]
    return f"delete {path}"


def _duplicate(data: dict[str, Any], rng: random.Random) -> str | None:
    found = nodes(data)
    entries = [n for n in found if n[2].count(".") + n[2].count("[") == 1]
    if entries and rng.random() < 0.7:
        found = entries  # a link, a joint, a driver, a load or a point
    if not found:
        return None
    container, key, path = rng.choice(found)
    if isinstance(container, list):
        container.append(_copy(container[key]))
    else:
        container[f"{key}2"] = _copy(container[key])
    return f"duplicate {path}"


def _rename(data: dict[str, Any], rng: random.Random) -> str | None:
    found = [n for n in nodes(data) if isinstance(n[0], dict)]
    if not found:
        return None
    container, key, path = rng.choice(found)
    others = [k for k in container if k != key]
    new = rng.choice([*NAMES, *others] if others else NAMES)
    items = list(container.items())
    container.clear()
    for k, v in items:
        if k == new and k != key:
            continue  # the renamed entry replaces the one of that name
        container[new if k == key else k] = v
    return f"rename {path} -> {new[:20]!r}"


def _kind(data: dict[str, Any], rng: random.Random) -> str | None:
    joints = _entries(data, "joints")
    if not joints:
        return None
    name, joint = rng.choice(joints)
    joint["kind"] = kind = rng.choice(KINDS)
    if kind in ("prismatic", "slot") and "axis" not in joint and rng.random() < 0.7:
        joint["axis"] = rng.choice(([1.0, 0.0], [0.0, 1.0], [0.6, 0.8]))
    elif kind == "revolute" and rng.random() < 0.7:
        joint.pop("axis", None)
    return f"joints.{name}.kind = {kind!r}"


def _links(data: dict[str, Any], rng: random.Random) -> str | None:
    joints = _entries(data, "joints")
    if not joints:
        return None
    name, joint = rng.choice(joints)
    known = ["ground", *_names(data, "links"), "nowhere"]
    old = joint.get("links")
    pair = list(old) if isinstance(old, list) and len(old) == 2 else ["ground", "x"]
    what = rng.choice(("replace", "reverse", "same", "three", "one"))
    if what == "replace":
        pair[rng.randrange(2)] = rng.choice(known)
    elif what == "reverse":
        pair.reverse()
    elif what == "same":
        pair = [pair[0], pair[0]]
    elif what == "three":
        pair = [*pair, rng.choice(known)]
    else:
        pair = pair[:1]
    joint["links"] = pair
    return f"joints.{name}.links = {pair}"


def _axis(data: dict[str, Any], rng: random.Random) -> str | None:
    if rng.random() < 0.6:
        joints = _entries(data, "joints")
        if not joints:
            return None
        name, joint = rng.choice(joints)
        joint["axis"] = axis = _copy(rng.choice(AXES))
        return f"joints.{name}.axis = {_short(axis)}"
    links = _entries(data, "links")
    if not links:
        return None
    name, link = rng.choice(links)
    a, b = _point(data, rng), _point(data, rng)
    old = link.get("axis")
    flipped = old[::-1] if isinstance(old, list) else [b, a]
    axis = rng.choice(([a, b], [a, a], [a], [b, a, b], flipped))
    link["axis"] = axis
    return f"links.{name}.axis = {_short(axis)}"


def _driver(data: dict[str, Any], rng: random.Random) -> str | None:
    drivers = data.get("drivers")
    if not isinstance(drivers, list) or not drivers:
        data["drivers"] = drivers = [{"joint": "A", "omega": 1.0}]
    i = rng.randrange(len(drivers))
    d = drivers[i]
    if not isinstance(d, dict):
        return None
    joints = _names(data, "joints") or ["A"]
    what = rng.choice(("omega", "omega", "epsilon", "epsilon", "joint", "drop", "add"))
    if what == "omega":
        d["omega"] = value = rng.choice((0.0, 0, -20.0, 1e15, 1e-300, 5e-324, 1e14))
    elif what == "epsilon":
        d["epsilon"] = value = rng.choice((1e15, -1e15, 1e12, 1e-300, 0.0, 1e300))
    elif what == "joint":
        d["joint"] = value = rng.choice(joints)
    elif what == "drop":
        del drivers[i]
        return f"delete drivers[{i}]"
    else:
        drivers.append({"joint": (value := rng.choice(joints)), "omega": 5.0})
        return f"add a driver at {value!r}"
    return f"drivers[{i}].{what} = {_short(value)}"


def _point_spec(data: dict[str, Any], rng: random.Random) -> str | None:
    slots = point_slots(data)
    if not slots:
        return None
    container, key, path = rng.choice(slots)
    container[key] = value = _point(data, rng)
    return f"{path} = {_short(value)}"


def _load(data: dict[str, Any], rng: random.Random) -> str | None:
    links = _names(data, "links") or ["x"]
    joints = _names(data, "joints") or ["A"]
    wild = rng.random() < 0.2
    load: dict[str, Any] = {
        "link": rng.choice([*links, "ground", "nowhere"] if wild else links)
    }
    if rng.random() < 0.9:
        load["at"] = _point(data, rng) if wild else rng.choice(joints)
    overs = ("driver",) * 6 + (*joints, "nonsense", "", "ground", links[0])
    tables = (
        [0.0, 90.0, 180.0, 270.0, 360.0], [0.0, 180.0, 90.0, 360.0], [0.0, 0.0, 360.0],
        [0.0], [], [-1e15, 1e15], [0.0, NAN, 360.0], [0.0, 1e-300, 360.0],
        [-0.1, 0.0, 0.1], [1e14, 1e15], [0, 360],
    )  # fmt: skip
    table = _copy(tables[0] if rng.random() < 0.4 else rng.choice(tables))
    n = len(table) if rng.random() < 0.8 else max(len(table) - 1, 0)
    values = [rng.choice((0.0, 100.0, -50.0, 1e15, 1e-300, 5e-324)) for _ in range(n)]
    what = rng.choice(("force", "force", "table", "torque", "torque table", "both"))
    if what in ("force", "both"):
        load["force"] = [rng.choice(ACCEPTED), rng.choice((0.0, -10.0, 1e15, 1e16))]
    if what == "table":
        ys = [0.0] * n if rng.random() < 0.8 else [0.0]
        load["force"] = {
            "x": values,
            "y": ys,
            "over": rng.choice(overs),
            "table": table,
        }
    if what in ("torque", "both"):
        load["torque"] = rng.choice(ACCEPTED)
    if what == "torque table":
        load["torque"] = {"values": values, "over": rng.choice(overs), "table": table}
    loads = data.setdefault("loads", [])
    if not isinstance(loads, list):
        return None
    loads.append(load)
    return f"add load {_short(load)}"


def _gravity(data: dict[str, Any], rng: random.Random) -> str | None:
    g = _copy(rng.choice((
        {"g": [0.0, -9.81]}, {"g": [0.0, 0.0]}, {"g": [1e15, -1e15]}, {"g": [NAN, 0.0]},
        {}, {"g": [0.0, -9.81, 0.0]}, {"g": 9.81}, {"g": [5e-324, -1e-300]}, None,
    )))  # fmt: skip
    if g is None:
        data.pop("gravity", None)
        return "delete gravity"
    data["gravity"] = g
    return f"gravity = {_short(g)}"


def _scale(data: dict[str, Any], rng: random.Random) -> str | None:
    factor = rng.choice(FACTORS)
    for container, key, _ in point_slots(data):
        value = container[key]
        if isinstance(value, list) and len(value) == 2 and all(map(_is_number, value)):
            container[key] = [_times(v, factor) for v in value]
        elif isinstance(value, dict) and _is_number(value.get("distance")):
            value["distance"] = _times(value["distance"], factor)
    masses = rng.random() < 0.3
    if masses:
        for _, link in _entries(data, "links"):
            for key, power in (("mass", 1), ("inertia", 3)):
                if _is_number(link.get(key)):
                    link[key] = _times(link[key], abs(factor) ** power)
    return f"scale by {factor:g}" + (" (masses and inertias too)" if masses else "")


def _move(data: dict[str, Any], rng: random.Random) -> str | None:
    dx, dy = rng.choice(OFFSETS), rng.choice((0.0, *OFFSETS))
    for container, key, _ in point_slots(data):
        value = container[key]
        if isinstance(value, list) and len(value) == 2 and all(map(_is_number, value)):
            container[key] = [_plus(value[0], dx), _plus(value[1], dy)]
    return f"move by ({dx:g}, {dy:g})"


Mutation = Callable[[dict[str, Any], random.Random], str | None]
"""A mutation of the data: changes it in place and says what it did, or None."""
DATA_MUTATIONS: tuple[tuple[Mutation, int], ...] = (
    (_extreme, 8), (_odd, 3), (_swap_type, 2), (_delete, 2), (_duplicate, 2),
    (_rename, 2), (_kind, 3), (_links, 2), (_axis, 2), (_driver, 4),
    (_point_spec, 3), (_load, 4), (_gravity, 1), (_scale, 4), (_move, 2),
)  # fmt: skip
"""Each mutation of the data, with its weight."""


def mutate_data(data: dict[str, Any], rng: random.Random, done: list[str]) -> None:
    """Apply one mutation to ``data`` in place; record it in ``done``."""
    functions = [f for f, _ in DATA_MUTATIONS]
    weights = [w for _, w in DATA_MUTATIONS]
    for _ in range(10):
        what = rng.choices(functions, weights)[0](data, rng)
        if what is not None:
            done.append(what)
            return


def _copy(value: Any) -> Any:
    """A deep copy of plain data (lists and tables), the rest shared."""
    if isinstance(value, list):
        return [_copy(v) for v in value]
    if isinstance(value, dict):
        return {k: _copy(v) for k, v in value.items()}
    return value


def _short(value: Any) -> str:
    """A value for a list of mutations: JSON-like, cut at 80 characters."""
    text = json.dumps(value, default=str, ensure_ascii=False)
    if isinstance(value, int) and abs(value) > 10**20:
        text = f"an integer of {len(str(abs(value)))} digits"
    return text if len(text) <= 80 else text[:77] + "..."
