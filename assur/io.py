"""Mechanism files (TOML or JSON) and result tables (CSV, JSON).

Reading checks every key against the file contract and names the file and the entry
of any fault; writing gives back a file that reads to the same mechanism.
"""

from __future__ import annotations

import io as _io
import json
import math
import re
import sys
import tomllib
from pathlib import Path
from typing import Any

import numpy as np

from assur._text import suggest
from assur.errors import AssurError, ModelError
from assur.model import Driver, Joint, Link, Load, LoadTable, Mechanism, Point, Toward

__all__ = ["dumps", "load", "loads", "parse", "save", "write_csv"]

FORMAT_VERSION = 1
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
    ),
    "link": ("axis", "mass", "center", "inertia"),
    "joint": ("kind", "links", "at", "axis"),
    "driver": ("joint", "omega", "epsilon"),
    "gravity": ("g",),
    "load": ("link", "at", "force", "torque"),
    "point": ("link", "at"),
    "toward": ("from", "toward", "distance"),
    "force_table": ("x", "y", "over", "table"),
    "torque_table": ("values", "over", "table"),
}


def load(path: str | Path) -> Mechanism:
    """Read a mechanism file (``.toml`` or ``.json``).

    Raises
    ------
    ModelError
        With a one-line message naming the file, the entry and what is wrong.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from assur import catalog
    >>> path = pathlib.Path(tempfile.mkdtemp()) / "four_bar.toml"
    >>> save(catalog.four_bar(), path)
    >>> load(path) == catalog.four_bar()
    True
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")  # a byte-order mark is welcome
    except OSError as err:
        msg = f"{path}: cannot read the file ({err.strerror or err})"
        raise ModelError(msg) from err
    except UnicodeDecodeError as err:
        msg = (
            f"{path}: not UTF-8 text (byte {err.start} cannot be decoded); expected a "
            "TOML or JSON file saved as UTF-8"
        )
        raise ModelError(msg) from err
    try:
        return loads(text, json_format=path.suffix.lower() == ".json")
    except AssurError as err:
        msg = f"{path}: {err}"
        raise type(err)(msg) from err


def loads(text: str, json_format: bool = False) -> Mechanism:
    """Read a mechanism from TOML (or JSON) text."""
    try:
        data = (
            json.loads(text, object_pairs_hook=_unique_keys)
            if json_format
            else tomllib.loads(text)
        )
    except (tomllib.TOMLDecodeError, json.JSONDecodeError) as err:
        kind = "JSON" if json_format else "TOML"
        msg = f"not valid {kind}: {err}"
        raise ModelError(msg) from err
    return parse(data)


class _Object(dict):  # type: ignore[type-arg]
    """A JSON object that remembers the keys it was given twice."""

    twice: tuple[str, ...] = ()


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """JSON object hook: a key given twice is an error, as it is in TOML."""
    out = _Object(pairs)
    if len(out) != len(pairs):
        seen: set[str] = set()
        out.twice = tuple(k for k, _ in pairs if k in seen or seen.add(k))
    return out


def _fail(entry: str, message: str) -> None:
    msg = f"{entry}: {message}" if entry else message
    raise ModelError(msg)


def _check_twice(entry: str, data: Any) -> None:
    for key in getattr(data, "twice", ()):
        _fail(
            f"{entry}.{key}" if entry else key, "given twice; expected every name once"
        )


def _check_keys(entry: str, data: Any, allowed: tuple[str, ...]) -> dict[str, Any]:
    if not isinstance(data, dict):
        _fail(entry, f"expected a table of keys ({', '.join(allowed)}), got {data!r}")
    _check_twice(entry, data)
    for key in data:
        if key not in allowed:
            hint = suggest(key, allowed, listing=False) or (
                f"; expected one of {', '.join(allowed)}"
            )
            where = f"{entry}.{key}" if entry else key
            _fail(where, f"unknown key {key!r}{hint}")
    return data


def _vec(entry: str, value: Any) -> tuple[float, float]:
    if not (
        isinstance(value, list | tuple)
        and len(value) == 2
        and all(isinstance(v, int | float) and not isinstance(v, bool) for v in value)
    ):
        _fail(entry, f"expected two numbers [x, y], got {value!r}")
    return (_number(entry, value[0]), _number(entry, value[1]))


def _point(entry: str, value: Any) -> Any:
    if isinstance(value, str):
        return value
    if isinstance(value, dict):
        d = _check_keys(entry, value, KEYS["toward"])
        for key in KEYS["toward"]:
            if key not in d:
                _fail(
                    entry, f"missing key {key!r} of a point {{from, toward, distance}}"
                )
        if not isinstance(d["distance"], int | float) or isinstance(
            d["distance"], bool
        ):
            _fail(f"{entry}.distance", f"expected a number, got {d['distance']!r}")
        return Toward(
            _text(f"{entry}.from", d["from"]),
            _text(f"{entry}.toward", d["toward"]),
            float(d["distance"]),
        )
    return _vec(entry, value)


def _table(entry: str, value: dict, comps: tuple[str, ...], kind: str) -> LoadTable:
    d = _check_keys(entry, value, KEYS[kind])
    for key in (*comps, "table"):
        if key not in d:
            _fail(entry, f"missing key {key!r} of a tabulated load")
    seqs = []
    for key in (*comps, "table"):
        seq = d[key]
        if not isinstance(seq, list) or not all(
            isinstance(v, int | float) and not isinstance(v, bool) for v in seq
        ):
            _fail(f"{entry}.{key}", f"expected a list of numbers, got {seq!r}")
        seqs.append(tuple(float(v) for v in seq))
    return LoadTable(
        _text(f"{entry}.over", d.get("over", "driver")), seqs[-1], tuple(seqs[:-1])
    )


def _text(entry: str, value: Any) -> str:
    if not isinstance(value, str):
        _fail(entry, f"expected a name in quotes, got {value!r}")
    return value


def _number(entry: str, value: Any) -> float:
    if not isinstance(value, int | float) or isinstance(value, bool):
        _fail(entry, f"expected a number, got {value!r}")
    try:
        return float(value)
    except OverflowError:
        _fail(entry, f"the number {value} is too large; expected a finite number")
        raise  # unreachable: _fail raises


def parse(data: dict[str, Any]) -> Mechanism:
    """Build a :class:`~assur.model.Mechanism` from a mechanism file's contents."""
    _check_keys("", data, KEYS[""])
    version = data.get("format", FORMAT_VERSION)
    if type(version) is not int or version != FORMAT_VERSION:
        _fail(
            "format", f"version {version!r} is not supported; expected {FORMAT_VERSION}"
        )
    links = []
    for name, d in _section("links", data.get("links", {})).items():
        entry = f"links.{name}"
        _check_keys(entry, d, KEYS["link"])
        axis = d.get("axis")
        if axis is not None and not (
            isinstance(axis, list)
            and len(axis) == 2
            and all(isinstance(a, str) for a in axis)
        ):
            _fail(f"{entry}.axis", f"expected two point names, got {axis!r}")
        links.append(
            Link(
                name,
                None if axis is None else tuple(axis),
                _opt_number(f"{entry}.mass", d.get("mass")),
                None
                if d.get("center") is None
                else _point(f"{entry}.center", d["center"]),
                _opt_number(f"{entry}.inertia", d.get("inertia")),
            )
        )
    joints = []
    for name, d in _section("joints", data.get("joints", {})).items():
        entry = f"joints.{name}"
        _check_keys(entry, d, KEYS["joint"])
        for key in ("kind", "links", "at"):
            if key not in d:
                _fail(entry, f"missing key {key!r}")
        pair = d["links"]
        if not (isinstance(pair, list) and all(isinstance(x, str) for x in pair)):
            _fail(f"{entry}.links", f"expected two link names, got {pair!r}")
        joints.append(
            Joint(
                name,
                _text(f"{entry}.kind", d["kind"]),
                tuple(pair),
                _point(f"{entry}.at", d["at"]),
                None if d.get("axis") is None else _vec(f"{entry}.axis", d["axis"]),
            )
        )
    drivers = []
    for i, d in enumerate(_list("drivers", data.get("drivers", []))):
        entry = f"drivers[{i}]"
        _check_keys(entry, d, KEYS["driver"])
        for key in ("joint", "omega"):
            if key not in d:
                _fail(entry, f"missing key {key!r}")
        drivers.append(
            Driver(
                _text(f"{entry}.joint", d["joint"]),
                _number(f"{entry}.omega", d["omega"]),
                _number(f"{entry}.epsilon", d.get("epsilon", 0.0)),
            )
        )
    gravity = None
    if "gravity" in data:
        g = _check_keys("gravity", data["gravity"], KEYS["gravity"])
        gravity = _vec("gravity.g", g.get("g", [0.0, -9.81]))
    loads_ = [
        _load(f"loads[{i}]", d)
        for i, d in enumerate(_list("loads", data.get("loads", [])))
    ]
    points = []
    for name, d in _section("points", data.get("points", {})).items():
        entry = f"points.{name}"
        _check_keys(entry, d, KEYS["point"])
        for key in ("link", "at"):
            if key not in d:
                _fail(entry, f"missing key {key!r}")
        points.append(
            Point(
                name, _text(f"{entry}.link", d["link"]), _point(f"{entry}.at", d["at"])
            )
        )
    return Mechanism(
        tuple(links),
        tuple(joints),
        tuple(drivers),
        name=_text("name", data.get("name", "")),
        description=_text("description", data.get("description", "")),
        gravity=gravity,
        loads=tuple(loads_),
        points=tuple(points),
    )


def _section(entry: str, value: Any) -> dict[str, Any]:
    if not isinstance(value, dict):
        _fail(entry, f"expected a table of named entries, got {value!r}")
    _check_twice(entry, value)
    return value


def _list(entry: str, value: Any) -> list[Any]:
    if not isinstance(value, list):
        _fail(entry, f"expected a list of tables ([[{entry}]]), got {value!r}")
    return value


def _opt_number(entry: str, value: Any) -> float | None:
    return None if value is None else _number(entry, value)


def _load(entry: str, d: Any) -> Load:
    _check_keys(entry, d, KEYS["load"])
    if "link" not in d:
        _fail(entry, "missing key 'link'")
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
    return name if _BARE.match(name) else json.dumps(name, ensure_ascii=False)


def _value(value: Any) -> str:
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
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


def dumps(mech: Mechanism) -> str:
    """Return the TOML text of a mechanism file for ``mech``."""
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
    if mech.points:
        out.append("\n[points]")
        for p in mech.points:
            out.append(
                f"{_key(p.name)} = {{ link = {_value(p.link)}, at = {_value(p.at)} }}"
            )
    return "\n".join(out) + "\n"


def save(mech: Mechanism, path: str | Path) -> None:
    """Write ``mech`` as a TOML mechanism file."""
    Path(path).write_text(dumps(mech), encoding="utf-8")


def write_csv(table: Any, path: Any = None) -> str | None:
    """Write a result table as CSV (12 significant digits); return it without path."""
    buffer = _io.StringIO()
    buffer.write(",".join(table.columns) + "\n")
    if len(table):
        np.savetxt(buffer, table.to_array(), fmt="%.12g", delimiter=",")
    text = buffer.getvalue()
    if path is None:
        return text
    if path == "-":
        sys.stdout.write(text)
    elif hasattr(path, "write"):
        path.write(text)
    else:
        Path(path).write_text(text, encoding="utf-8")
    return None
