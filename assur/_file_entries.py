"""The entries of a mechanism file, read one by one into a Mechanism.

:func:`parse` checks every key of a file's data (TOML or JSON, already decoded) against
the file contract (``KEYS``) and names the entry of any fault; :mod:`assur.io` reads
the files, :mod:`assur._file_text` writes the same keys back.
"""

from __future__ import annotations

from typing import Any, NoReturn

from assur._checks import JOINT_KINDS, LARGEST, POINT_FORMS
from assur._decimal_comma import HINT
from assur._points import PointSpec
from assur._text import describe, key_text, spoken, suggest
from assur.errors import ModelError
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
)

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


NEEDED = {
    "kind": f"the joint's kind: {spoken(JOINT_KINDS, 'or')}",
    "links": "the two links it joins, [first, second]",
    "at": f"where it is in the reference pose: {POINT_FORMS}",
    "joint": "the name of the joint it drives",
    "omega": "the driver's speed, rad/s (m/s for a prismatic joint)",
    "link": "the name of a moving link",
}
"""What a required key holds, said when it is missing (keys of several entries)."""


def _require(entry: str, data: dict[str, Any], *keys: str, what: str = "") -> None:
    """Fail on the first of ``keys`` missing from ``data``.

    ``what`` follows the key's name; a key of :data:`NEEDED` is then said what it
    holds (a user who left out ``at`` learns its forms, not only its name).
    """
    for key in keys:
        if key not in data:
            needed = f"; expected {NEEDED[key]}" if key in NEEDED and not what else ""
            _fail(entry, f"missing key {key!r}{what}{needed}")


def _vec(entry: str, value: Any) -> tuple[float, float]:
    if not (
        isinstance(value, list | tuple)
        and len(value) == 2
        and all(isinstance(v, int | float) and not isinstance(v, bool) for v in value)
    ):
        # [0,052, 0,052], two decimals with commas, reads as four whole numbers
        commas = isinstance(value, list) and len(value) in (3, 4)
        commas = commas and all(type(v) is int for v in value)
        hint = HINT if commas else ""
        _fail(entry, f"expected two numbers [x, y], got {_echo(value)}{hint}")
    return (_number(entry, value[0]), _number(entry, value[1]))


def _point(entry: str, value: Any) -> PointSpec:
    """Read a point: ``[x, y]``, a point's name or ``{from, toward, distance}``."""
    if isinstance(value, str):
        return value
    if isinstance(value, dict):
        d = _check_keys(entry, value, KEYS["toward"])
        _require(entry, d, *KEYS["toward"], what=" of a point {from, toward, distance}")
        return Toward(
            # the two ends are named: [x, y] there would be a point of its own
            _text(f"{entry}.from", d["from"], "a point's name"),
            _text(f"{entry}.toward", d["toward"], "a point's name"),
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


def _text(entry: str, value: Any, what: str = "a name") -> str:
    if not isinstance(value, str):
        _fail(entry, f"expected {what} in quotes, got {_echo(value)}")
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
    if not data:
        # an empty file (or {}): "no moving links" named one of many things missing
        _fail(
            "",
            "the file has no entries; expected a mechanism: format = 1, "
            "[links.NAME], [joints.NAME] and [[drivers]] (see the file format)",
        )
    _check_keys("", data, KEYS[""])
    version = _get(data, "format", FORMAT_VERSION)
    if type(version) is float and version == FORMAT_VERSION:
        version = FORMAT_VERSION  # JSON has one kind of number: 1.0 is 1
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
        description=_text("description", _get(data, "description", ""), "text"),
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
