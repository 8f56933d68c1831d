"""The numbers the report's script draws from, as JSON embedded in the page.

Every value is in the unit of its table column, and every unit shown is the column
schema's (positions in m, angles in deg, forces in N, torques in N·m); every
per-position array has one value per table row, rounded to DIGITS significant
digits, with null where a value is not finite.
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from assur._gaps import gaps
from assur._structure import Group, Structure
from assur._style import DRIVER_COLOUR, REACTION_COLOUR, group_colour, link_colours
from assur._text import public_name, roman
from assur._vec import Array, full
from assur.analysis import Table
from assur.groups._pairs import PairPlan
from assur.html._series import (
    balancing,
    charts,
    current,
    driver_label,
    units,
    visible_pairs,
)
from assur.model import GROUND
from assur.plan import Plan

DIGITS = 6
"""Significant digits of the numbers embedded in the page."""
GUIDE_MARGIN = 0.08
"""Length a guide line runs past the slide's travel at each end, times the
mechanism's size."""


def report_data(plan: Plan, struct: Structure, table: Table) -> dict[str, Any]:
    """Return the JSON-ready data the page draws from."""
    joints = visible_pairs(plan)
    data: dict[str, Any] = {
        "name": plan.mechanism.name,
        "description": plan.mechanism.description,
        "driver": driver_label(table),
        "rows": len(table),
        "angle": floats(table["angle"]),
        "gaps": gaps(table),
        "analysis": "forces" if table.force_state is not None else "kinematics",
        "groups": _groups(struct),
        "links": _links(plan, link_colours(plan)),
        "joints": [_joint(plan, p) for p in joints],
        "points": {
            name: {"x": floats(table[f"{name}.x"]), "y": floats(table[f"{name}.y"])}
            for name in plan.points
        },
        "extra_points": [p.name for p in plan.mechanism.points],
        "guides": [_guide(plan, table, p) for p in joints if p.kind == "P"],
    }
    data["bounds"] = _bounds(plan, data)
    data["charts"] = charts(plan, table)
    data["current"] = current(plan, table)
    data["columns"] = _columns(table, data)
    data["forces"] = None
    if table.force_state is not None:
        data["forces"] = {
            "joints": [p.name for p in joints],
            "balancing": balancing(table)[0],
            "unit": units(table, [f"{p.name}.F" for p in joints]),
            # the pictures' colour of a reaction: the report draws it alike
            "colour": REACTION_COLOUR,
        }
    return data


def to_json(data: dict[str, Any]) -> str:
    """Return the data as JSON that no '<', '>' or '&' can end or break out of."""
    text = json.dumps(data, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def floats(values: Array) -> list[float | None]:
    """Round to DIGITS significant digits for a compact page; NaN becomes null."""
    return [
        float(f"{v:.{DIGITS}g}") if math.isfinite(v) else None
        for v in np.asarray(values, dtype=float).tolist()
    ]


def public(name: str) -> str:
    """Return a link's or pair's name as the reader knows it: "B (block)", "B (pin)".

    :func:`assur._text.public_name`, which the text reports use: one spelling.
    """
    return public_name(name)


def all_groups(struct: Structure) -> tuple[Group, ...]:
    """Return the drivers and the Assur groups in order of attachment."""
    return (*struct.drivers, *struct.groups)


def _columns(table: Table, data: dict[str, Any]) -> dict[str, list[float | None]]:
    """Return the series the page plots or lists, once each, by column key.

    Positions are left out: they are in ``data["points"]`` already.
    """
    keys = [s["key"] for c in data["charts"] for s in c["series"]]
    keys += [other["key"] for other in data["driver"]["others"]]
    keys += [
        key
        for part in data["current"].values()
        for row in part["rows"]
        for key in row["keys"]
        if not (key.endswith((".x", ".y")) and key[:-2] in data["points"])
    ]
    return {key: floats(table[key]) for key in dict.fromkeys(keys)}


def _groups(struct: Structure) -> list[dict[str, Any]]:
    """Return the drivers and groups with their class, kind, links and colour.

    The colours are those of the pictures (:mod:`assur._style`).
    """
    colours = [DRIVER_COLOUR] * len(struct.drivers)
    colours += [group_colour(k) for k in range(len(struct.groups))]
    return [
        {
            "label": "driver" if g.group_class == 1 else g.label,
            "class": g.group_class,
            "roman": roman(g.group_class),
            "order": g.order,
            "kind": g.kind,
            "links": [public(x) for x in g.links if x != GROUND],
            "colour": colour,
        }
        for g, colour in zip(all_groups(struct), colours, strict=True)
    ]


def _joint(plan: Plan, pair: PairPlan) -> dict[str, Any]:
    """Return a pair's name, kind and links; ``slot`` when it slides in a slot."""
    return {
        "name": pair.name,
        "kind": pair.kind,
        "first": plan.bodies[pair.first],
        "second": plan.bodies[pair.second],
        "slot": "~" in plan.bodies[pair.second],
    }


def _members(plan: Plan) -> dict[int, list[str]]:
    """Return the points each moving body's bar or plate joins, by body index."""
    members: dict[int, list[str]] = {b: [] for b in range(1, len(plan.bodies))}
    for pair in plan.pairs.values():
        # a slot's virtual pin stands on the slot pair's point, which moves with the pin
        point = pair.name.split("~")[0]
        bodies = (pair.first, pair.second) if pair.kind == "R" else (pair.second,)
        for b in bodies:
            if b and point not in members[b]:
                members[b].append(point)
    for extra in plan.mechanism.points:
        members[plan.body(extra.link)].append(extra.name)
    return members


def _links(plan: Plan, colours: dict[str, str]) -> list[dict[str, Any]]:
    """Return the visible links, each with the points its bar or plate joins."""
    out = []
    for b, points in _members(plan).items():
        name = plan.bodies[b]
        if "~" in name:
            continue
        center = f"{name}.G" if f"{name}.G" in plan.points else None
        guides = [
            p.name
            for p in plan.pairs.values()
            if p.kind == "P" and p.first == b and not p.virtual
        ]
        out.append(
            {
                "name": name,
                "colour": colours[name],
                "points": points,
                "guides": guides,
                "center": center,
            }
        )
    return out


def _guide(plan: Plan, table: Table, pair: PairPlan) -> dict[str, Any]:
    """Return a prismatic pair's slide line (ends, m; direction) over the sweep.

    The line is fixed in the pair's first link and covers the slide's travel.
    """
    slide = np.asarray(table[f"{pair.name}.s"])
    margin = GUIDE_MARGIN * plan.scale
    axis = np.asarray(pair.axis, dtype=float)
    # the reference point's offset from the first link's origin, in its own frame
    at = pair.d_first
    ends = [
        at + axis * (np.nanmin(slide) - margin),
        at + axis * (np.nanmax(slide) + margin),
    ]
    n = len(table)
    phi = full(table.state.rotation(pair.first, 0), n)
    ox, oy = (full(v, n) for v in table.state.origin(pair.first, 0))
    origin = np.column_stack((ox + plan.shift[0], oy + plan.shift[1]))
    c, s = np.cos(phi), np.sin(phi)
    out: dict[str, Any] = {"joint": pair.name, "body": plan.bodies[pair.first]}
    for tag, (dx, dy) in (("1", ends[0]), ("2", ends[1])):
        out[f"x{tag}"] = floats(origin[:, 0] + c * dx - s * dy)
        out[f"y{tag}"] = floats(origin[:, 1] + s * dx + c * dy)
    out["ux"] = floats(c * axis[0] - s * axis[1])
    out["uy"] = floats(s * axis[0] + c * axis[1])
    return out


def _bounds(plan: Plan, data: dict[str, Any]) -> list[float]:
    """Return the box (m) that holds every point and guide over the sweep.

    The box is never thinner than a tenth of the mechanism's size.
    """
    xs = [v for p in data["points"].values() for v in p["x"] if v is not None]
    ys = [v for p in data["points"].values() for v in p["y"] if v is not None]
    for g in data["guides"]:
        xs += [v for v in g["x1"] + g["x2"] if v is not None]
        ys += [v for v in g["y1"] + g["y2"] if v is not None]
    box = [min(xs), max(xs), min(ys), max(ys)]
    least = 0.1 * plan.scale
    for lo in (0, 2):
        if box[lo + 1] - box[lo] < least:
            middle = 0.5 * (box[lo] + box[lo + 1])
            box[lo], box[lo + 1] = middle - 0.5 * least, middle + 0.5 * least
    return box
