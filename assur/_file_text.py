"""The text of a mechanism file: a Mechanism written as TOML.

Every key is one of the file contract's (:data:`assur._file_entries.KEYS`), every
value written so that reading it back gives the same number, name or point.
"""

from __future__ import annotations

import json
import math
import re
from typing import Any

from assur._file_entries import FORMAT_VERSION, KEYS
from assur.model import LoadTable, Mechanism, Toward

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


def toml_text(mech: Mechanism) -> str:
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
