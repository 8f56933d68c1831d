"""Which table columns the report plots, lists and tabulates.

The diagrams, the live tables at the shown position and the HTML table each pick
their series here, by column key of :class:`assur.analysis.Table`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur.analysis import Table
from assur.groups._pairs import PairPlan
from assur.plan import Plan

ROTATING = 1e-12
"""Largest angular velocity (rad/s) of a link that counts as not rotating."""


def visible_pairs(plan: Plan) -> list[PairPlan]:
    """Return the pairs of the mechanism, leaving out the slots' virtual pins."""
    return [p for p in plan.pairs.values() if not p.virtual]


def driver_label(plan: Plan) -> dict[str, str]:
    """Return the name and unit of the driver position (the diagrams' abscissa)."""
    prismatic = plan.drivers[0].kind == "P"
    return {
        "label": "driver position" if prismatic else "driver angle",
        "unit": "m" if prismatic else "deg",
    }


def balancing(plan: Plan) -> tuple[list[dict[str, Any]], str]:
    """Return the balancing-load series (column keys) and their unit."""
    series: list[dict[str, Any]] = []
    units = set()
    for d in plan.drivers:
        what = "torque" if d.kind == "R" else "force"
        units.add("N·m" if d.kind == "R" else "N")
        key = "driver" if len(plan.drivers) == 1 else d.pair.name
        tag = f" at {d.pair.name}" if len(plan.drivers) > 1 else ""
        series.append({"name": f"balancing {what}{tag}", "key": f"{key}.{what}"})
        series.append(
            {
                "name": f"check by virtual power{tag}",
                "key": f"{key}.{what}_check",
                "dashed": True,
            }
        )
    return series, " or ".join(sorted(units))


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


def current(plan: Plan, table: Table) -> dict[str, list[dict[str, Any]]]:
    """Return the rows of the live tables of values at the shown position."""
    joints = visible_pairs(plan)
    links = [
        {"name": x, "keys": [f"{x}.angle", f"{x}.omega", f"{x}.alpha"]}
        for x in moving_links(plan, table)
    ]
    slides = [
        {"name": p.name, "keys": [f"{p.name}.s", f"{p.name}.v", f"{p.name}.a"]}
        for p in joints
        if p.kind == "P"
    ]
    suffixes = ("Fx", "Fy", "F") if table.force_state is not None else ("x", "y")
    points = [
        {"name": p.name, "keys": [f"{p.name}.{x}" for x in suffixes]} for p in joints
    ]
    return {"links": links, "slides": slides, "joints": points}


def charts(plan: Plan, table: Table) -> list[dict[str, Any]]:
    """Return the diagrams: id, title, unit and the column key of each series."""
    out = []
    if table.force_state is not None:
        series, unit = balancing(plan)
        out.append(
            {
                "id": "chart-balancing",
                "title": "Balancing load and its check",
                "unit": unit,
                "series": series,
            }
        )
        out.append(
            {
                "id": "chart-reactions",
                "title": "Joint reactions |F|",
                "unit": "N",
                "series": [
                    {"name": p.name, "key": f"{p.name}.F"} for p in visible_pairs(plan)
                ],
            }
        )
    out.append(
        {
            "id": "chart-omega",
            "title": "Angular velocities of the links",
            "unit": "rad/s",
            "series": [
                {"name": x, "key": f"{x}.omega"} for x in moving_links(plan, table)
            ],
        }
    )
    return out


def table_columns(plan: Plan, table: Table) -> list[tuple[str, str]]:
    """Return the HTML table's columns as (column key, heading with unit)."""
    driver = driver_label(plan)
    columns = [("angle", f"{driver['label']} ({driver['unit']})")]
    joints = visible_pairs(plan)
    if table.force_state is not None:
        columns += [(f"{p.name}.F", f"|F| {p.name} (N)") for p in joints]
        for s in balancing(plan)[0]:
            unit = "N·m" if s["key"].endswith(("torque", "torque_check")) else "N"
            columns.append((s["key"], f"{s['name']} ({unit})"))
        return columns
    columns += [(f"{x}.omega", f"ω {x} (rad/s)") for x in moving_links(plan, table)]
    columns += [
        (f"{p.name}.s", f"slide {p.name} (m)")
        for p in joints
        if p.kind == "P" and "~" not in plan.bodies[p.second]
    ]
    return columns
