"""Which table columns the report plots, lists and tabulates.

The diagrams, the live tables at the shown position and the HTML table each pick
their series here, by column key of :class:`assur.analysis.Table`, and write every
unit as the column schema gives it (through :func:`assur.columns.pretty_unit`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur.analysis import Table
from assur.columns import pretty_unit
from assur.groups._pairs import PairPlan
from assur.plan import Plan

ROTATING = 1e-12
"""Largest angular velocity (rad/s) of a link that counts as not rotating."""


def visible_pairs(plan: Plan) -> list[PairPlan]:
    """Return the pairs of the mechanism, leaving out the slots' virtual pins."""
    return [p for p in plan.pairs.values() if not p.virtual]


def unit(table: Table, key: str) -> str:
    """Return the unit of column ``key`` as the report writes it ("N·m", "rad/s²")."""
    return pretty_unit(table.column(key).unit)


def units(table: Table, keys: list[str]) -> str:
    """Return the units of the columns ``keys``, each once: "N·m" or "N·m or N"."""
    return " or ".join(dict.fromkeys(unit(table, key) for key in keys))


def driver_label(table: Table) -> dict[str, Any]:
    """Return the name and unit of the driver position (the diagrams' abscissa).

    With several drivers, ``others`` names the position column of each driver
    after the first (the abscissa), which the readout shows too.
    """
    drivers = table.plan.drivers
    prismatic = drivers[0].kind == "P"
    others = [{"name": d.pair.name, "key": f"{d.pair.name}.drive"} for d in drivers[1:]]
    for other in others:
        other["unit"] = unit(table, other["key"])
    return {
        "label": "driver position" if prismatic else "driver angle",
        "unit": unit(table, "angle"),
        "others": others,
    }


def balancing(table: Table) -> tuple[list[dict[str, Any]], str]:
    """Return the balancing-load series (column keys, units) and their units."""
    drivers = table.plan.drivers
    series: list[dict[str, Any]] = []
    for d in drivers:
        what = "torque" if d.kind == "R" else "force"
        key = f"{'driver' if len(drivers) == 1 else d.pair.name}.{what}"
        tag = f" at {d.pair.name}" if len(drivers) > 1 else ""
        series.append({"name": f"balancing {what}{tag}", "key": key})
        series.append(
            {
                "name": f"check by virtual power{tag}",
                "key": f"{key}_check",
                "dashed": True,
            }
        )
    for item in series:
        item["unit"] = unit(table, item["key"])
    return series, units(table, [item["key"] for item in series])


def moving_links(plan: Plan, table: Table) -> list[str]:
    """Return the visible links that rotate during the sweep."""
    out = []
    for name in plan.bodies[1:]:
        key = f"{name}.omega"
        if "~" in name or key not in table:
            continue
        if np.nanmax(np.abs(table[key])) > ROTATING:
            out.append(name)
    return out


def massive_links(table: Table) -> list[str]:
    """Return the links with inertia loads in the table, in the plan's link order.

    The plan's order (input links, then group by group) is that of the other
    tables of the page; the file's order of links would differ from it.
    """
    if table.force_state is None:
        return []
    masses = {x.name: x.mass for x in table.mechanism.links}
    return [
        x
        for x in table.plan.bodies[1:]
        if masses.get(x) and f"{x}.Fi.x" in table.columns
    ]


def current(plan: Plan, table: Table) -> dict[str, dict[str, Any]]:
    """Return the live tables of values at the shown position.

    Each has a caption (what it holds, for a screen reader), a head and rows. A
    row names a link or joint and the column keys of its values; a head's
    headings carry the units of the first row's columns.
    """
    joints = visible_pairs(plan)
    links = [
        {"name": x, "keys": [f"{x}.angle", f"{x}.omega", f"{x}.alpha"]}
        for x in moving_links(plan, table)
    ]
    forced = table.force_state is not None
    sliding = [p.name for p in joints if p.kind == "P"]
    # a prismatic pair's couple is its reaction's third part: shown with its slide
    couples = forced and all(f"{name}.M" in table.columns for name in sliding)
    motion = ("s", "v", "a", "M") if couples else ("s", "v", "a")
    slides = [
        {"name": name, "keys": [f"{name}.{x}" for x in motion]} for name in sliding
    ]
    suffixes = ("Fx", "Fy", "F") if forced else ("x", "y")
    points = [
        {"name": p.name, "keys": [f"{p.name}.{x}" for x in suffixes]} for p in joints
    ]
    # the inertia loads follow the slider too: d'Alembert's loads at that position
    inertia = [
        {"name": x, "keys": [f"{x}.Fi.x", f"{x}.Fi.y", f"{x}.Mi"]}
        for x in massive_links(table)
    ]
    parts = {
        "links": ("link", ("angle", "ω", "α"), links),
        "slides": ("slide", motion, slides),
        "joints": ("joint", ("Fx", "Fy", "|F|") if forced else ("x", "y"), points),
        "inertia": ("inertia of", ("Fi,x", "Fi,y", "Mi"), inertia),
    }
    captions = {
        "links": "Angle and its rates of each link",
        "slides": "Slide and its rates in each sliding pair",
        "joints": "Reaction in each joint" if forced else "Place of each joint",
        "inertia": "Inertia loads of each link with a mass",
    }
    return {
        part: {
            "caption": f"{captions[part]} at the position shown",
            "head": _head(table, first, symbols, rows),
            "rows": rows,
        }
        for part, (first, symbols, rows) in parts.items()
    }


def _head(
    table: Table, first: str, symbols: tuple[str, ...], rows: list[dict[str, Any]]
) -> list[str]:
    """Return the headings of a live table: ``first``, then each symbol and unit."""
    if not rows:
        return [first]
    keys = rows[0]["keys"]
    return [first] + [
        f"{s} ({unit(table, k)})" for s, k in zip(symbols, keys, strict=True)
    ]


def charts(plan: Plan, table: Table) -> list[dict[str, Any]]:
    """Return the diagrams: id, title, unit and the column key of each series."""
    out = []
    if table.force_state is not None:
        series, unit_text = balancing(table)
        out.append(
            {
                "id": "chart-balancing",
                "title": "Balancing load and its check",
                "unit": unit_text,
                "series": series,
            }
        )
        reactions = [
            {"name": p.name, "key": f"{p.name}.F"} for p in visible_pairs(plan)
        ]
        out.append(
            {
                "id": "chart-reactions",
                "title": "Joint reactions |F|",
                "unit": units(table, [s["key"] for s in reactions]),
                "series": reactions,
            }
        )
    omegas = [{"name": x, "key": f"{x}.omega"} for x in moving_links(plan, table)]
    out.append(
        {
            "id": "chart-omega",
            "title": "Angular velocities of the links",
            "unit": units(table, [s["key"] for s in omegas]),
            "series": omegas,
        }
    )
    return out


def table_columns(plan: Plan, table: Table) -> list[tuple[str, str]]:
    """Return the HTML table's columns as (column key, heading with unit)."""
    driver = driver_label(table)
    columns = [("angle", driver["label"])]
    columns += [(x["key"], f"position of {x['name']}") for x in driver["others"]]
    joints = visible_pairs(plan)
    if table.force_state is not None:
        columns += [(f"{p.name}.F", f"|F| {p.name}") for p in joints]
        columns += [(s["key"], s["name"]) for s in balancing(table)[0]]
    else:
        columns += [(f"{x}.omega", f"ω {x}") for x in moving_links(plan, table)]
        columns += [
            (f"{p.name}.s", f"slide {p.name}")
            for p in joints
            if p.kind == "P" and "~" not in plan.bodies[p.second]
        ]
    return [(key, f"{text} ({unit(table, key)})") for key, text in columns]
