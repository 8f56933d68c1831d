"""Mechanism files (TOML or JSON) and result tables (CSV, JSON).

Reading checks every key against the file contract and names the file and the entry
of any fault; writing gives back a file that reads to the same mechanism.
"""

from __future__ import annotations

import io
import json
import math
import re
import sys
from os import PathLike
from typing import TYPE_CHECKING, Any, NoReturn

from assur import _output
from assur._checks import LARGEST
from assur._output import (
    StdoutError,
    finishing,
    output_path,
    path_text,
    stdout_writer,
    write_text,
)
from assur._points import PointSpec
from assur._text import describe, key_text, suggest
from assur.errors import AssurError, ModelError, UsageError
from assur.model import (
    Driver,
    Joint,
    Link,
    Load,
    LoadTable,
    Mechanism,
    Motor,
    Point,
    Toward,
    mechanism_of,
)

if TYPE_CHECKING:
    from pathlib import Path

__all__ = ["dumps", "load", "loads", "parse", "save", "write_csv", "write_parquet"]

FORMAT_VERSION = 1
MAX_FILE_BYTES = 16 * 2**20
"""Largest mechanism file read, bytes (16 MiB; a mechanism takes a few kB)."""
KEYS = {
    "": (
        "format",
        "name",
        "description",
        "links",
        "joints",
        "drivers",
        "gravity",
        "loads",
        "points",
        "motor",
    ),
    "link": ("axis", "mass", "center", "inertia"),
    "joint": ("kind", "links", "at", "axis", "friction", "radius"),
    "driver": ("joint", "omega", "epsilon"),
    "gravity": ("g",),
    "motor": ("torque", "no_load_speed"),
    "load": ("link", "at", "force", "torque"),
    "point": ("link", "at"),
    "toward": ("from", "toward", "distance"),
    "force_table": ("x", "y", "over", "table"),
    "torque_table": ("values", "over", "table"),
}


def load(path: str | Path) -> Mechanism:
    """Read a mechanism file (``.toml`` or ``.json``).

    Parameters
    ----------
    path : str or path-like
        The file; at most 16 MiB (``MAX_FILE_BYTES``) of UTF-8 text (a byte-order
        mark is welcome). A ``.json`` suffix (any case) reads JSON, any other TOML.

    Returns
    -------
    Mechanism
        The mechanism the file describes, validated.

    Raises
    ------
    ModelError
        With a one-line message naming the file, the entry and what is wrong.
    UsageError
        When ``path`` is not a path.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from assur import catalog
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "four_bar.toml"
    >>> save(catalog.four_bar(), path)
    >>> load(path) == catalog.four_bar()
    True
    """
    from pathlib import Path

    path = Path(_path(path, "the mechanism file's"))
    where = path_text(path)
    data = _read(path, where)
    try:
        return loads(_decoded(data), json_format=path.suffix.lower() == ".json")
    except AssurError as err:
        msg = f"{where}: {err}"
        raise type(err)(msg) from err


def _read(path: Path, where: str) -> bytes:
    """Return the bytes of the file ``path``, at most :data:`MAX_FILE_BYTES`."""
    return read_capped(
        path,
        where,
        MAX_FILE_BYTES,
        "a TOML or JSON file",
        "a mechanism file (a few kilobytes of TOML or JSON)",
    )


def read_capped(path: Any, where: str, most: int, kind: str, expected: str) -> bytes:
    """Return the bytes of the file ``path``: at most ``most`` of them, whole MiB.

    ``where`` names the file in messages; ``kind`` is what a folder was expected
    to be, ``expected`` what a file too large was expected to be.

    Raises
    ------
    ModelError
        When the file cannot be read or holds more than ``most`` bytes.
    """
    try:
        with open(path, "rb") as stream:
            # one byte beyond the cap tells a file too large from one just large
            data = stream.read(most + 1)
    except IsADirectoryError as err:
        msg = f"{where}: cannot read the file (it is a folder); expected {kind}"
        raise ModelError(msg) from err
    except OSError as err:
        msg = f"{where}: cannot read the file ({err.strerror or err})"
        raise ModelError(msg) from err
    except ValueError as err:  # a name with a NUL character
        msg = f"{where}: cannot read the file ({err})"
        raise ModelError(msg) from err
    if len(data) > most:
        msg = f"{where}: larger than {most // 2**20} MiB; expected {expected}"
        raise ModelError(msg)
    return data


def loads(text: str, json_format: bool = False) -> Mechanism:
    """Read a mechanism from TOML (or JSON) text.

    Parameters
    ----------
    text : str or bytes
        The text of a mechanism file (bytes are read as UTF-8, a byte-order mark
        welcome).
    json_format : bool, default False
        Read ``text`` as JSON instead of TOML.

    Returns
    -------
    Mechanism
        The mechanism the text describes, validated.

    Raises
    ------
    ModelError
        With a one-line message naming the entry and what is wrong.
    UsageError
        When ``text`` is not text (a file's path, say: read it with :func:`load`).
    """
    import tomllib

    if isinstance(text, bytes | bytearray):
        text = _decoded(bytes(text))
    if not isinstance(text, str):
        hint = " (read a file with assur.load)" if isinstance(text, PathLike) else ""
        msg = f"text: expected a mechanism file's text, got {type(text).__name__}{hint}"
        raise UsageError(msg)
    kind = "JSON" if json_format else "TOML"
    try:
        data = (
            json.loads(text, object_pairs_hook=_unique_keys)
            if json_format
            else tomllib.loads(text)
        )
    except (tomllib.TOMLDecodeError, json.JSONDecodeError) as err:
        msg = f"not valid {kind}: {_one_line(str(err))}"
        raise ModelError(msg) from err
    except RecursionError as err:
        msg = (
            f"not valid {kind}: nested too deeply (more than the parser can follow); "
            f"expected the few levels of a mechanism file"
        )
        raise ModelError(msg) from err
    except ValueError as err:  # an integer too long to convert
        msg = (
            _long_integer(text, json_format)
            or f"not valid {kind}: {_one_line(str(err))}"
        )
        raise ModelError(msg) from err
    _check_depth(data)
    return parse(data)


def _one_line(text: str) -> str:
    """Return a parser's message on one line."""
    return " ".join(text.split())


MAX_NESTING = 16
"""Deepest nesting of tables and arrays read; a mechanism file needs five levels."""


def _check_depth(data: Any) -> None:
    """Refuse data nested deeper than :data:`MAX_NESTING` (no recursion here)."""
    stack: list[tuple[Any, str, int]] = [(data, "", 0)]
    while stack:
        value, entry, depth = stack.pop()
        if depth > MAX_NESTING:
            _fail(
                entry,
                f"nested too deeply (more than {MAX_NESTING} levels); expected the "
                "few levels of a mechanism file",
            )
        if isinstance(value, dict):
            stack += [
                (v, f"{entry}.{key_text(k)}" if entry else key_text(k), depth + 1)
                for k, v in value.items()
            ]
        elif isinstance(value, list):
            stack += [(v, f"{entry}[{i}]", depth + 1) for i, v in enumerate(value)]


_HEADER = re.compile(r"^\s*(\[\[?)\s*([^\[\]#]+?)\s*\]\]?\s*(#.*)?$")
_TOML_KEY = re.compile(r"([A-Za-z0-9_.\- \"']+?)\s*=\s*[^={}]*$")
_JSON_KEY = re.compile(r'"([^"\\]{1,40})"\s*:\s*[^"{}:]*$')


def _long_integer(text: str, json_format: bool) -> str | None:
    """Return the message of an integer too long for Python, naming its entry."""
    limit = sys.get_int_max_str_digits()
    if limit == 0:
        return None
    for match in re.finditer(rf"[0-9][0-9_]{{{limit},}}", text):
        digits = sum(c.isdigit() for c in match.group())
        if digits <= limit:
            continue
        start = match.start()
        line = text.count("\n", 0, start) + 1
        before = text[text.rfind("\n", 0, start) + 1 : start]
        key = (_JSON_KEY if json_format else _TOML_KEY).search(before)
        entry = "" if key is None else key.group(1).strip().strip("\"'")
        if entry and not json_format:
            entry = _toml_table(text, start) + entry
        where = f"{key_text(entry)} (line {line})" if entry else f"line {line}"
        return (
            f"{where}: an integer of {digits} digits; expected a number of at most "
            f"{limit} digits"
        )
    return None


def _toml_table(text: str, end: int) -> str:
    """Return the dotted name, with a dot, of the TOML table open at ``end``."""
    table = ""
    counts: dict[str, int] = {}
    for line in text[:end].splitlines():
        match = _HEADER.match(line)
        if match is None:
            continue
        name = ".".join(part.strip().strip("\"'") for part in match.group(2).split("."))
        if match.group(1) == "[[":
            counts[name] = counts.get(name, -1) + 1
            table = f"{name}[{counts[name]}]."
        else:
            table = f"{name}."
    return table


class _Object(dict):  # type: ignore[type-arg]
    """A JSON object that remembers the keys it was given twice."""

    twice: tuple[str, ...] = ()


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """JSON object hook: a key given twice is an error, as it is in TOML."""
    out = _Object(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        twice = []
        for key, _ in pairs:
            if key in seen:
                twice.append(key)
            seen.add(key)
        out.twice = tuple(twice)
    return out


def _fail(entry: str, message: str) -> NoReturn:
    msg = f"{entry}: {message}" if entry else message
    raise ModelError(msg)


def _echo(value: Any) -> str:
    """Return a value of the file as a message echoes it (JSON's null included)."""
    return "null" if value is None else describe(value)


def _join(entry: str, key: Any) -> str:
    """Return the entry of ``key`` inside ``entry``."""
    return f"{entry}.{key_text(key)}" if entry else key_text(key)


def _check_twice(entry: str, data: Any) -> None:
    for key in getattr(data, "twice", ()):
        _fail(_join(entry, key), "given twice; expected every name once")


def _check_keys(entry: str, data: Any, allowed: tuple[str, ...]) -> dict[str, Any]:
    if not isinstance(data, dict):
        _fail(
            entry, f"expected a table of keys ({', '.join(allowed)}), got {_echo(data)}"
        )
    _check_twice(entry, data)
    for key in data:
        if key not in allowed:
            hint = suggest(key, allowed, listing=False) or (
                f"; expected one of {', '.join(allowed)}"
            )
            _fail(_join(entry, key), f"unknown key {describe(key)}{hint}")
    return data


def _require(entry: str, data: dict[str, Any], *keys: str, what: str = "") -> None:
    """Fail on the first of ``keys`` missing from ``data``."""
    for key in keys:
        if key not in data:
            _fail(entry, f"missing key {key!r}{what}")


def _vec(entry: str, value: Any) -> tuple[float, float]:
    if not (
        isinstance(value, list | tuple)
        and len(value) == 2
        and all(isinstance(v, int | float) and not isinstance(v, bool) for v in value)
    ):
        _fail(entry, f"expected two numbers [x, y], got {_echo(value)}")
    return (_number(entry, value[0]), _number(entry, value[1]))


def _point(entry: str, value: Any) -> PointSpec:
    """Read a point: ``[x, y]``, a point's name or ``{from, toward, distance}``."""
    if isinstance(value, str):
        return value
    if isinstance(value, dict):
        d = _check_keys(entry, value, KEYS["toward"])
        _require(entry, d, *KEYS["toward"], what=" of a point {from, toward, distance}")
        return Toward(
            _text(f"{entry}.from", d["from"]),
            _text(f"{entry}.toward", d["toward"]),
            _number(f"{entry}.distance", d["distance"]),
        )
    if (
        isinstance(value, list)
        and value
        and all(isinstance(v, list | dict | str) for v in value)
    ):
        _fail(
            entry,
            f"expected one point ([x, y], a point's name or "
            f"{{from, toward, distance}}), got {_echo(value)}",
        )
    return _vec(entry, value)


def _axis(entry: str, value: Any) -> tuple[PointSpec, PointSpec]:
    """Read a link's axis: two points of any form."""
    if not isinstance(value, list) or len(value) != 2:
        _fail(
            entry,
            "expected two points (each [x, y], a point's name or "
            f"{{from, toward, distance}}), got {_echo(value)}",
        )
    if all(isinstance(v, int | float) and not isinstance(v, bool) for v in value):
        _fail(
            entry,
            f"expected two points, got the direction {_echo(value)}; a direction "
            "[x, y] is the axis of a prismatic joint, a link's axis runs between "
            'two points such as ["A", "B"] or [[0.0, 0.0], [0.1, 0.0]]',
        )
    return (_point(f"{entry}[0]", value[0]), _point(f"{entry}[1]", value[1]))


def _table(entry: str, value: dict, comps: tuple[str, ...], kind: str) -> LoadTable:
    d = _check_keys(entry, value, KEYS[kind])
    _require(entry, d, *comps, "table", what=" of a tabulated load")
    seqs = []
    for key in (*comps, "table"):
        seq = d[key]
        if not isinstance(seq, list) or not all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in seq
        ):
            _fail(f"{entry}.{key}", f"expected a list of numbers, got {_echo(seq)}")
        seqs.append(tuple(_number(f"{entry}.{key}", v) for v in seq))
    return LoadTable(
        _text(f"{entry}.over", _get(d, "over", "driver")), seqs[-1], tuple(seqs[:-1])
    )


def _text(entry: str, value: Any) -> str:
    if not isinstance(value, str):
        _fail(entry, f"expected a name in quotes, got {_echo(value)}")
    return value


def _number(entry: str, value: Any) -> float:
    if not isinstance(value, int | float) or isinstance(value, bool):
        _fail(entry, f"expected a number, got {_echo(value)}")
    try:
        return float(value)
    except OverflowError:
        _fail(
            entry,
            f"the number is too large ({describe(value)}); expected a number of "
            f"magnitude at most {LARGEST:g}",
        )


def parse(data: dict[str, Any]) -> Mechanism:
    """Build a :class:`~assur.model.Mechanism` from a mechanism file's contents.

    Raises
    ------
    ModelError
        With a one-line message naming the entry and what is wrong.
    """
    _check_keys("", data, KEYS[""])
    version = _get(data, "format", FORMAT_VERSION)
    if type(version) is not int or version != FORMAT_VERSION:
        _fail(
            "format",
            f"version {_echo(version)} is not supported; expected {FORMAT_VERSION}",
        )
    links = [
        _link(f"links.{key_text(name)}", name, d)
        for name, d in _section("links", _get(data, "links", {})).items()
    ]
    joints = [
        _joint(f"joints.{key_text(name)}", name, d)
        for name, d in _section("joints", _get(data, "joints", {})).items()
    ]
    drivers = [
        _driver(f"drivers[{i}]", d)
        for i, d in enumerate(_list("drivers", _get(data, "drivers", [])))
    ]
    gravity = None
    if data.get("gravity") is not None:
        g = _check_keys("gravity", data["gravity"], KEYS["gravity"])
        gravity = _vec("gravity.g", _get(g, "g", [0.0, -9.81]))
    loads_ = [
        _load(f"loads[{i}]", d)
        for i, d in enumerate(_list("loads", _get(data, "loads", [])))
    ]
    points = []
    for name, d in _section("points", _get(data, "points", {})).items():
        entry = f"points.{key_text(name)}"
        _check_keys(entry, d, KEYS["point"])
        _require(entry, d, "link", "at")
        points.append(
            Point(
                name, _text(f"{entry}.link", d["link"]), _point(f"{entry}.at", d["at"])
            )
        )
    return Mechanism(
        tuple(links),
        tuple(joints),
        tuple(drivers),
        name=_text("name", _get(data, "name", "")),
        description=_text("description", _get(data, "description", "")),
        gravity=gravity,
        loads=tuple(loads_),
        points=tuple(points),
        motor=None if data.get("motor") is None else _motor("motor", data["motor"]),
    )


def _motor(entry: str, d: Any) -> Motor:
    """Read the ``[motor]`` table: its torque and, optionally, its no-load speed."""
    _check_keys(entry, d, KEYS["motor"])
    _require(entry, d, "torque", what=" (the motor's torque at standstill, N m)")
    return Motor(
        _number(f"{entry}.torque", d["torque"]),
        _opt_number(f"{entry}.no_load_speed", d.get("no_load_speed")),
    )


def _link(entry: str, name: str, d: Any) -> Link:
    _check_keys(entry, d, KEYS["link"])
    return Link(
        name,
        None if d.get("axis") is None else _axis(f"{entry}.axis", d["axis"]),
        _opt_number(f"{entry}.mass", d.get("mass")),
        None if d.get("center") is None else _point(f"{entry}.center", d["center"]),
        _opt_number(f"{entry}.inertia", d.get("inertia")),
    )


def _joint(entry: str, name: str, d: Any) -> Joint:
    _check_keys(entry, d, KEYS["joint"])
    _require(entry, d, "kind", "links", "at")
    pair = d["links"]
    if not (
        isinstance(pair, list)
        and len(pair) == 2
        and all(isinstance(x, str) for x in pair)
    ):
        _fail(f"{entry}.links", f"expected two link names, got {_echo(pair)}")
    return Joint(
        name,
        _text(f"{entry}.kind", d["kind"]),
        (pair[0], pair[1]),
        _point(f"{entry}.at", d["at"]),
        None if d.get("axis") is None else _vec(f"{entry}.axis", d["axis"]),
        _number(f"{entry}.friction", _get(d, "friction", 0.0)),
        _opt_number(f"{entry}.radius", d.get("radius")),
    )


def _driver(entry: str, d: Any) -> Driver:
    _check_keys(entry, d, KEYS["driver"])
    _require(entry, d, "joint", "omega")
    return Driver(
        _text(f"{entry}.joint", d["joint"]),
        _number(f"{entry}.omega", d["omega"]),
        _number(f"{entry}.epsilon", _get(d, "epsilon", 0.0)),
    )


def _section(entry: str, value: Any) -> dict[str, Any]:
    if not isinstance(value, dict):
        _fail(entry, f"expected a table of named entries, got {_echo(value)}")
    _check_twice(entry, value)
    return value


def _list(entry: str, value: Any) -> list[Any]:
    if not isinstance(value, list):
        _fail(entry, f"expected a list of tables ([[{entry}]]), got {_echo(value)}")
    return value


def _opt_number(entry: str, value: Any) -> float | None:
    return None if value is None else _number(entry, value)


def _get(data: dict[str, Any], key: str, default: Any) -> Any:
    """Return ``data[key]``, or ``default`` when the key is missing or JSON's null."""
    value = data.get(key)
    return default if value is None else value


def _load(entry: str, d: Any) -> Load:
    _check_keys(entry, d, KEYS["load"])
    _require(entry, d, "link")
    force = d.get("force")
    if isinstance(force, dict):
        force = _table(f"{entry}.force", force, ("x", "y"), "force_table")
    elif force is not None:
        force = _vec(f"{entry}.force", force)
    torque = d.get("torque")
    if isinstance(torque, dict):
        torque = _table(f"{entry}.torque", torque, ("values",), "torque_table")
    elif torque is not None:
        torque = _number(f"{entry}.torque", torque)
    at = None if d.get("at") is None else _point(f"{entry}.at", d["at"])
    return Load(_text(f"{entry}.link", d["link"]), at, force, torque)


_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(name: str) -> str:
    return name if _BARE.match(name) else _quoted(name)


def _quoted(text: str) -> str:
    """Return ``text`` as a TOML basic string.

    JSON's escapes are TOML's, but JSON leaves DEL (U+007F) as it is, which TOML
    forbids in a string.
    """
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")


def _value(value: Any) -> str:
    if isinstance(value, str):
        return _quoted(value)
    if isinstance(value, Toward):
        return (
            f"{{ from = {_value(value.start)}, toward = {_value(value.toward)}, "
            f"distance = {_value(value.distance)} }}"
        )
    if isinstance(value, tuple | list):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else json.dumps(str(value))
    return repr(value)


def _table_text(t: LoadTable, comps: tuple[str, ...]) -> str:
    parts = [f"{c} = {_value(v)}" for c, v in zip(comps, t.values, strict=False)]
    return (
        "{ "
        + ", ".join([*parts, f"over = {_value(t.over)}", f"table = {_value(t.table)}"])
        + " }"
    )


def dumps(mechanism: Mechanism, json_format: bool = False) -> str:
    """Return the text of a mechanism file for ``mechanism``, TOML or JSON.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism to write.
    json_format : bool, default False
        Write JSON of the same keys and values instead of TOML.

    Returns
    -------
    str
        The file's text; :func:`loads` (with the same ``json_format``) reads it back
        as an equal mechanism.

    Raises
    ------
    UsageError
        When ``mechanism`` is not a :class:`~assur.model.Mechanism`.
    """
    if json_format:
        import tomllib

        # the TOML text's data, which holds exactly the mechanism's numbers
        text = dumps(mechanism)
        return json.dumps(tomllib.loads(text), indent=2, ensure_ascii=False)
    mech = mechanism_of(mechanism)
    out = [f"format = {FORMAT_VERSION}", f"name = {_value(mech.name)}"]
    if mech.description:
        out.append(f"description = {_value(mech.description)}")
    for link in mech.links:
        out.append(f"\n[links.{_key(link.name)}]")
        for key in KEYS["link"]:
            if getattr(link, key) is not None:
                out.append(f"{key} = {_value(getattr(link, key))}")
    for joint in mech.joints:
        out.append(f"\n[joints.{_key(joint.name)}]")
        out += [
            f"kind = {_value(joint.kind)}",
            f"links = {_value(joint.links)}",
            f"at = {_value(joint.at)}",
        ]
        if joint.axis is not None:
            out.append(f"axis = {_value(joint.axis)}")
        if joint.friction:
            out.append(f"friction = {_value(joint.friction)}")
        if joint.radius is not None:
            out.append(f"radius = {_value(joint.radius)}")
    for driver in mech.drivers:
        out += [
            "\n[[drivers]]",
            f"joint = {_value(driver.joint)}",
            f"omega = {_value(driver.omega)}",
            f"epsilon = {_value(driver.epsilon)}",
        ]
    if mech.gravity is not None:
        out += ["\n[gravity]", f"g = {_value(mech.gravity)}"]
    for load in mech.loads:
        out += ["\n[[loads]]", f"link = {_value(load.link)}"]
        if load.at is not None:
            out.append(f"at = {_value(load.at)}")
        if isinstance(load.force, LoadTable):
            out.append(f"force = {_table_text(load.force, ('x', 'y'))}")
        elif load.force is not None:
            out.append(f"force = {_value(load.force)}")
        if isinstance(load.torque, LoadTable):
            out.append(f"torque = {_table_text(load.torque, ('values',))}")
        elif load.torque is not None:
            out.append(f"torque = {_value(load.torque)}")
    if mech.motor is not None:
        out += ["\n[motor]", f"torque = {_value(mech.motor.torque)}"]
        if mech.motor.no_load_speed is not None:
            out.append(f"no_load_speed = {_value(mech.motor.no_load_speed)}")
    if mech.points:
        out.append("\n[points]")
        for p in mech.points:
            out.append(
                f"{_key(p.name)} = {{ link = {_value(p.link)}, at = {_value(p.at)} }}"
            )
    return "\n".join(out) + "\n"


def save(mechanism: Mechanism, path: str | Path) -> None:
    """Write ``mechanism`` as a mechanism file, whole or not at all.

    JSON for a ``.json`` suffix (any case), TOML for any other, as :func:`load` reads
    them. The file is written whole or not at all: to a temporary file beside it, then
    moved over it in one step.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism to write.
    path : str or path-like
        The file to write; a ``.json`` suffix writes JSON, any other TOML.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept.
    UsageError
        When ``path`` is not a path or ``mechanism`` not a Mechanism.
    """
    from pathlib import Path

    path = _path(path, "the file's")
    json_format = Path(path).suffix.lower() == ".json"
    write_text(path, dumps(mechanism, json_format=json_format))


def _path(path: Any, whose: str) -> Any:
    """Return ``path``, checked to be a file's path (str or path-like)."""
    if not isinstance(path, str | PathLike):
        msg = f"path: expected {whose} path, got {type(path).__name__}"
        raise UsageError(msg)
    return path


def _decoded(data: bytes) -> str:
    """Return a mechanism file's bytes as text (UTF-8, a byte-order mark welcome)."""
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        msg = (
            f"not UTF-8 text (byte {err.start} cannot be decoded); expected a TOML or "
            "JSON file saved as UTF-8"
        )
        raise ModelError(msg) from err


def write_csv(table: Any, path: Any = None) -> str | None:
    """Write a result table as CSV (12 significant digits); return it without path.

    Parameters
    ----------
    table : Table
    path : str, path-like, file object or "-", optional
        Where to write: a file (written whole or not at all: to a temporary file
        moved over it), an open text or binary stream (UTF-8), or ``"-"``
        for standard output.

    Raises
    ------
    OutputError
        When the file cannot be written; an old file of that name is kept.

    Examples
    --------
    >>> from assur import catalog, kinematics
    >>> text = write_csv(kinematics(catalog.four_bar(), [0.0, 90.0]))
    >>> text.splitlines()[0].split(",")[:3]
    ['angle', 'crank.angle', 'crank.omega']
    """
    from assur._tableio import CsvWriter, table_columns

    columns = table_columns(table)
    if path is None:
        parts: list[bytes] = []
        CsvWriter(parts.append, table.columns).write(columns)
        return b"".join(parts).decode("utf-8")
    if isinstance(path, str) and path == "-":
        write, encode = stdout_writer()
        try:
            CsvWriter(write, table.columns, encode).write(columns)
        except StdoutError as err:
            raise err.error from None
    elif hasattr(path, "write"):
        # a binary stream (open(..., "wb"), io.BytesIO) takes the UTF-8 bytes
        binary = isinstance(path, io.RawIOBase | io.BufferedIOBase) or "b" in str(
            getattr(path, "mode", "")
        )
        write = path.write if binary else (lambda data: path.write(data.decode()))
        CsvWriter(write, table.columns).write(columns)
    else:
        path = _path(path, "a CSV file's")
        with output_path(path) as temporary, temporary.open("wb") as stream:
            # looked up when called: tests put a failing writer in its place
            CsvWriter(
                lambda data: _output.write_all(stream, data), table.columns
            ).write(columns)
    return None


def write_parquet(table: Any, path: Any) -> None:
    """Write a result table to a Parquet file (needs pyarrow).

    Every column is float64, named as in the table, with its unit in the field's
    metadata (key ``unit``); the schema's metadata holds the mechanism's name (key
    ``assur.name``). The rows go in groups of 65536 (``PARQUET_ROWS``). The file is
    written whole or not at all.

    Raises
    ------
    ImportError
        When pyarrow is not installed.
    OutputError
        When the file cannot be written; an old file of that name is kept.
    """
    from assur._tableio import (
        PARQUET_ROWS,
        ParquetWriter,
        import_pyarrow,
        table_columns,
    )

    import_pyarrow()
    columns = table_columns(table)
    units = [table.column(name).unit for name in table.columns]
    with output_path(_path(path, "a Parquet file's")) as temporary:
        writer = ParquetWriter(temporary, table.mechanism.name, table.columns, units)
        with finishing(writer):
            for start in range(0, len(table), PARQUET_ROWS):
                writer.write([c[start : start + PARQUET_ROWS] for c in columns])
