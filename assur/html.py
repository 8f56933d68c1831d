"""A self-contained HTML report: structure, animated drawing, diagrams and tables.

The report is one file with inline CSS and JavaScript and its numbers embedded as JSON,
so it opens offline in any browser. Python gathers the data from the numerical core;
plain JavaScript in the page draws the mechanism and the diagrams as SVG.
"""

from __future__ import annotations

import json
import math
import os
from html import escape
from typing import Any

import numpy as np

from assur._vec import Array
from assur.analysis import Table, default_positions, forces, kinematics
from assur.errors import AssemblyError
from assur.loads import compile_loads
from assur.model import GROUND, Mechanism
from assur.plan import Plan, compile_plan
from assur.structure import ROMAN, Group, Structure, structure

__all__ = ["render_report", "write_report"]

PALETTE = (
    "#334155",
    "#0072b2",
    "#d55e00",
    "#009e73",
    "#cc79a7",
    "#e69f00",
    "#56b4e9",
    "#8c564b",
    "#6b7280",
    "#b8860b",
)
"""Group colours in order of attachment: the first driver slate, then Okabe-Ito hues."""
DIGITS = 6
"""Significant digits of the numbers embedded in the page."""
GUIDE_MARGIN = 0.08
"""Length a guide line runs past the slide's travel at each end, times the
mechanism's size."""
DRAWING_WIDTH = 556
"""Width (px) of the drawing inside its margins."""
ROTATING = 1e-12
"""Largest angular velocity (rad/s) of a link that counts as not rotating."""
ROUND_OFF = 1e-9
"""Values below this (N, N m, m, rad/s) are round-off and show as 0."""
LONG_TABLE = 60
"""Tables with more rows than this show every 10th row."""


def render_report(mechanism: Mechanism, angles: Any = None) -> str:
    """Return the HTML report of ``mechanism`` as one self-contained page.

    Parameters
    ----------
    mechanism : Mechanism
    angles : array_like, optional
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers). By default one turn from the reference pose in steps
        of 1 deg (:func:`assur.analysis.default_positions`).

    Returns
    -------
    str
        The page: structure report, an animated SVG drawing with a range slider
        (``id="angle"``), diagrams over the sweep and a table; the data as JSON in
        ``<script type="application/json" id="assur-data">``.

    Raises
    ------
    AssemblyError
        When no driver position of the sweep can be assembled.

    Notes
    -----
    Positions that cannot be assembled are left out and counted in the page. A force
    analysis runs when a link has a mass or a load is applied; otherwise the report
    shows the kinematics only.

    Examples
    --------
    >>> from assur import catalog
    >>> page = render_report(catalog.slider_crank(), angles=range(0, 360, 30))
    >>> page.startswith("<!DOCTYPE html>") and 'id="assur-data"' in page
    True
    """
    plan = compile_plan(mechanism)
    with_forces = not compile_loads(plan).empty
    if angles is None:
        angles = default_positions(mechanism)
    sweep = forces if with_forces else kinematics
    table = sweep(mechanism, angles, skip_unassembled=True)
    if len(table) == 0:
        msg = (
            f"report of {mechanism.name or 'the mechanism'}: no driver position of "
            "the sweep can be assembled; expected at least one"
        )
        raise AssemblyError(msg)
    struct = structure(mechanism)
    data = _report_data(plan, struct, table)
    return _page(plan, struct, table, data)


def write_report(
    mechanism: Mechanism, path: str | os.PathLike[str], angles: Any = None
) -> None:
    """Write the HTML report of ``mechanism`` to ``path`` (UTF-8).

    Parameters are those of :func:`render_report`.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from assur import catalog
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     target = pathlib.Path(tmp) / "four_bar.html"
    ...     write_report(catalog.four_bar(), target, angles=[0.0, 90.0])
    ...     target.read_text(encoding="utf-8").count("<html")
    1
    """
    text = render_report(mechanism, angles)
    with open(path, "w", encoding="utf-8", newline="\n") as stream:
        stream.write(text)


def _report_data(plan: Plan, struct: Structure, table: Table) -> dict[str, Any]:
    """Return the JSON-ready data the page draws from.

    Positions are in m, angles in deg (or m for a prismatic driver), forces in N,
    torques in N m; every per-position array has one value per table row.
    """
    colours = _body_colours(struct)
    joints = [p for p in plan.pairs.values() if not p.virtual]
    prismatic = plan.drivers[0].kind == "P"
    data: dict[str, Any] = {
        "name": plan.mechanism.name,
        "description": plan.mechanism.description,
        "driver": {
            "label": "driver position" if prismatic else "driver angle",
            "unit": "m" if prismatic else "deg",
        },
        "rows": len(table),
        "angle": _floats(table["angle"]),
        "analysis": "forces" if table.force_state is not None else "kinematics",
        "groups": _groups(struct),
        "links": _links(plan, colours),
        "joints": [
            {
                "name": p.name,
                "kind": p.kind,
                "first": plan.bodies[p.first],
                "second": plan.bodies[p.second],
                "slot": "~" in plan.bodies[p.second],
            }
            for p in joints
        ],
        "points": {
            name: {"x": _floats(table[f"{name}.x"]), "y": _floats(table[f"{name}.y"])}
            for name in plan.points
        },
        "extra_points": [p.name for p in plan.mechanism.points],
        "guides": [_guide(plan, table, p) for p in joints if p.kind == "P"],
    }
    data["bounds"] = _bounds(plan, data)
    data["charts"] = _charts(plan, table)
    data["current"] = _current(plan, table)
    # the series the page plots or lists, once each; positions are in "points"
    columns = [s["key"] for c in data["charts"] for s in c["series"]]
    columns += [
        key
        for rows in data["current"].values()
        for row in rows
        for key in row["keys"]
        if not key.endswith((".x", ".y"))
    ]
    columns = list(dict.fromkeys(columns))
    data["columns"] = {key: _floats(table[key]) for key in columns}
    data["forces"] = None
    if table.force_state is not None:
        data["forces"] = {
            "joints": [p.name for p in joints],
            "balancing": _balancing(plan)[0],
        }
    return data


def _floats(values: Array) -> list[float | None]:
    """Round to DIGITS significant digits for a compact page; NaN becomes null."""
    return [
        float(f"{v:.{DIGITS}g}") if math.isfinite(v) else None
        for v in np.asarray(values, dtype=float).tolist()
    ]


def _public(name: str) -> str:
    return name.replace("~block", " (block)")


def _all_groups(struct: Structure) -> tuple[Group, ...]:
    return (*struct.drivers, *struct.groups)


def _body_colours(struct: Structure) -> dict[str, str]:
    colours = {}
    for i, g in enumerate(_all_groups(struct)):
        for link in g.links:
            if link != GROUND:
                colours[link] = PALETTE[i % len(PALETTE)]
    return colours


def _groups(struct: Structure) -> list[dict[str, Any]]:
    return [
        {
            "label": "driver" if g.group_class == 1 else g.label,
            "class": g.group_class,
            "roman": ROMAN.get(g.group_class, str(g.group_class)),
            "order": g.order,
            "kind": g.kind,
            "links": [_public(x) for x in g.links if x != GROUND],
            "colour": PALETTE[i % len(PALETTE)],
        }
        for i, g in enumerate(_all_groups(struct))
    ]


def _links(plan: Plan, colours: dict[str, str]) -> list[dict[str, Any]]:
    """Visible links, each with the points its bar or plate joins."""
    members: dict[int, list[str]] = {b: [] for b in range(1, len(plan.bodies))}
    for pair in plan.pairs.values():
        # a slot's virtual pin stands on the slot pair's point, which moves with the pin
        point = pair.name.split("~")[0]
        bodies = (pair.first, pair.second) if pair.kind == "R" else (pair.second,)
        for b in bodies:
            if b and point not in members[b]:
                members[b].append(point)
    for point in plan.mechanism.points:
        members[plan.body(point.link)].append(point.name)
    out = []
    for b, points in members.items():
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


def _guide(plan: Plan, table: Table, pair: Any) -> dict[str, Any]:
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
    phi = table.state.link[0, :, pair.first]
    origin = table.state.origin[:, pair.first]
    c, s = np.cos(phi), np.sin(phi)
    out: dict[str, Any] = {"joint": pair.name, "body": plan.bodies[pair.first]}
    for tag, (dx, dy) in (("1", ends[0]), ("2", ends[1])):
        out[f"x{tag}"] = _floats(origin[:, 0] + c * dx - s * dy)
        out[f"y{tag}"] = _floats(origin[:, 1] + s * dx + c * dy)
    out["ux"] = _floats(c * axis[0] - s * axis[1])
    out["uy"] = _floats(s * axis[0] + c * axis[1])
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


def _balancing(plan: Plan) -> tuple[list[dict[str, str]], str]:
    """Balancing-load series (column keys) and their unit."""
    series = []
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


def _moving_links(plan: Plan, table: Table) -> list[str]:
    """Visible links that rotate during the sweep."""
    out = []
    for name in plan.bodies[1:]:
        key = f"{name}.omega"
        if "~" in name or key not in table:
            continue
        if np.nanmax(np.abs(table[key])) > ROTATING:
            out.append(name)
    return out


def _current(plan: Plan, table: Table) -> dict[str, list[dict[str, Any]]]:
    """Rows of the live tables of values at the shown position (column keys)."""
    joints = [p for p in plan.pairs.values() if not p.virtual]
    forced = table.force_state is not None
    links = [
        {"name": x, "keys": [f"{x}.angle", f"{x}.omega", f"{x}.alpha"]}
        for x in _moving_links(plan, table)
    ]
    slides = [
        {"name": p.name, "keys": [f"{p.name}.s", f"{p.name}.v", f"{p.name}.a"]}
        for p in joints
        if p.kind == "P"
    ]
    suffixes = ("Fx", "Fy", "F") if forced else ("x", "y")
    points = [
        {"name": p.name, "keys": [f"{p.name}.{x}" for x in suffixes]} for p in joints
    ]
    return {"links": links, "slides": slides, "joints": points}


def _charts(plan: Plan, table: Table) -> list[dict[str, Any]]:
    """Diagram specifications: title, unit and the column key of each series."""
    charts = []
    if table.force_state is not None:
        series, unit = _balancing(plan)
        charts.append(
            {
                "id": "chart-balancing",
                "title": "Balancing load and its check",
                "unit": unit,
                "series": series,
            }
        )
        joints = [p.name for p in plan.pairs.values() if not p.virtual]
        charts.append(
            {
                "id": "chart-reactions",
                "title": "Joint reactions |F|",
                "unit": "N",
                "series": [{"name": j, "key": f"{j}.F"} for j in joints],
            }
        )
    links = _moving_links(plan, table)
    charts.append(
        {
            "id": "chart-omega",
            "title": "Angular velocities of the links",
            "unit": "rad/s",
            "series": [{"name": x, "key": f"{x}.omega"} for x in links],
        }
    )
    return charts


def _drawing_height(bounds: list[float]) -> int:
    """Height (px) of the 640 px wide drawing that fits the mechanism's box."""
    ratio = (bounds[3] - bounds[2]) / (bounds[1] - bounds[0])
    return int(min(max(round(DRAWING_WIDTH * ratio) + 90, 260), 560))


def _number(v: float) -> str:
    """Format a table value; round-off below ROUND_OFF shows as 0."""
    if not math.isfinite(v):
        return "–"
    return "0" if abs(v) < ROUND_OFF else f"{v:.5g}"


def _meta(struct: Structure, table: Table, data: dict[str, Any]) -> str:
    driver = data["driver"]
    angle = np.asarray(table["angle"])
    parts = [
        f"W = {struct.dof}",
        f"class {ROMAN.get(struct.mechanism_class)} mechanism",
        f"{len(table)} positions, {driver['label']} {_number(angle[0])} to "
        f"{_number(angle[-1])} {driver['unit']}",
        "force analysis" if data["forces"] else "kinematics only (no masses or loads)",
    ]
    if table.skipped.size:
        total = len(table) + table.skipped.shape[0]
        parts.append(
            f"{table.skipped.shape[0]} of {total} positions left out (the mechanism "
            "cannot be assembled there)"
        )
    return " · ".join(escape(p) for p in parts)


def _structure_html(struct: Structure, data: dict[str, Any]) -> str:
    rows = []
    for step, (g, info) in enumerate(
        zip(_all_groups(struct), data["groups"], strict=True), 1
    ):
        kind = "input link" if g.group_class == 1 else g.kind
        cells = [
            f'<span class="swatch" style="background:{info["colour"]}"></span>',
            str(step),
            info["roman"],
            str(g.order),
            kind,
            ", ".join(info["links"]),
            ", ".join(_public(x) for x in g.internal),
            ", ".join(_public(x) for x in g.external),
        ]
        rows.append(
            "<tr>"
            + "".join(
                f"<td>{c if i == 0 else escape(c)}</td>" for i, c in enumerate(cells)
            )
            + "</tr>"
        )
    head = "".join(
        f"<th>{h}</th>"
        for h in (
            "",
            "Step",
            "Class",
            "Order",
            "Kind",
            "Links",
            "Internal pairs",
            "External pairs",
        )
    )
    formula = escape(struct.formula.replace(" -> ", " → "))
    return (
        f'<p class="formula">{formula}</p>\n'
        f'<table class="groups"><thead><tr>{head}</tr></thead>\n<tbody>'
        + "\n".join(rows)
        + "</tbody></table>\n"
        + _report_html(str(struct))
    )


def _report_html(text: str) -> str:
    """Return the teaching report as HTML, one block per line.

    A line that wraps goes on indented under its start.
    """
    lines = []
    for line in text.splitlines():
        indent = len(line) - len(line.lstrip(" "))
        body = escape(line.strip()) or "&nbsp;"
        lines.append(
            f'<div style="padding-left:{indent + 4}ch;text-indent:-4ch">{body}</div>'
        )
    return '<div class="report">' + "\n".join(lines) + "</div>"


def _legend_html(data: dict[str, Any]) -> str:
    items = []
    for g in data["groups"]:
        what = "driver" if g["class"] == 1 else f"order {g['order']} · {g['kind']}"
        text = f"{g['roman']} · {what} · {', '.join(g['links'])}"
        swatch = f'<span class="swatch" style="background:{g["colour"]}"></span>'
        items.append(f"<li>{swatch}{escape(text)}</li>")
    return '<ul class="legend">' + "".join(items) + "</ul>"


def _table_columns(
    plan: Plan, table: Table, data: dict[str, Any]
) -> list[tuple[str, str]]:
    driver = data["driver"]
    columns = [("angle", f"{driver['label']} ({driver['unit']})")]
    joints = [p for p in plan.pairs.values() if not p.virtual]
    if table.force_state is not None:
        columns += [(f"{p.name}.F", f"|F| {p.name} (N)") for p in joints]
        for s in _balancing(plan)[0]:
            unit = "N·m" if s["key"].endswith(("torque", "torque_check")) else "N"
            columns.append((s["key"], f"{s['name']} ({unit})"))
        return columns
    columns += [(f"{x}.omega", f"ω {x} (rad/s)") for x in _moving_links(plan, table)]
    columns += [
        (f"{p.name}.s", f"slide {p.name} (m)")
        for p in joints
        if p.kind == "P" and "~" not in plan.bodies[p.second]
    ]
    return columns


def _table_html(plan: Plan, table: Table, data: dict[str, Any]) -> str:
    columns = _table_columns(plan, table, data)
    step = 10 if len(table) > LONG_TABLE else 1
    values = [np.asarray(table[key]) for key, _ in columns]
    head = "".join(f"<th>{escape(title)}</th>" for _, title in columns)
    rows = [
        f'<tr data-row="{i}">'
        + "".join(f"<td>{_number(float(v[i]))}</td>" for v in values)
        + "</tr>"
        for i in range(0, len(table), step)
    ]
    note = (
        f"Every {step}th of {len(table)} positions."
        if step > 1
        else f"All {len(table)} positions."
    )
    return (
        f'<p class="note">{note} The highlighted row is the position shown in the '
        'drawing.</p>\n<div class="table-wrap"><table class="values" id="values">'
        f"<thead><tr>{head}</tr></thead>\n<tbody>"
        + "\n".join(rows)
        + "</tbody></table></div>"
    )


def _json(data: dict[str, Any]) -> str:
    """JSON safe inside a script element: no '<', '>' or '&' can end or open a tag."""
    text = json.dumps(data, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _page(plan: Plan, struct: Structure, table: Table, data: dict[str, Any]) -> str:
    mech = plan.mechanism
    title = escape(mech.name or "Mechanism")
    description = (
        f'<p class="description">{escape(mech.description)}</p>'
        if mech.description
        else ""
    )
    forces_note = '<p class="note" id="force-note"></p>' if data["forces"] else ""
    table_title = "Reactions and balancing load" if data["forces"] else "Kinematics"
    n = len(table)
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title} · assur report</title>
<style>{CSS}</style>
</head>
<body>
<header>
<h1>{title}</h1>
{description}
<p class="meta">{_meta(struct, table, data)}</p>
</header>
<main>
<div class="column">
<section class="card" id="drawing">
<h2>Mechanism</h2>
<svg id="mechanism" viewBox="0 0 640 {_drawing_height(data["bounds"])}" role="img"
 aria-label="Drawing of the mechanism">
<defs>
<pattern id="hatch" width="6" height="6" patternUnits="userSpaceOnUse"
 patternTransform="rotate(45)">
<line x1="0" y1="0" x2="0" y2="6" stroke="#9ca3af" stroke-width="1.6"/></pattern>
<marker id="arrowhead" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6"
 markerHeight="6" orient="auto-start-reverse">
<path d="M0,0 L10,5 L0,10 z" fill="#c2185b"/></marker>
</defs>
</svg>
<div class="controls">
<button type="button" id="play">Play</button>
<input type="range" id="angle" min="0" max="{n - 1}" step="1" value="0"
 aria-label="Driver position">
<output id="readout" for="angle"></output>
</div>
{_legend_html(data)}
{forces_note}
</section>
<section class="card" id="position">
<h2>At this position</h2>
<div class="current" id="current"></div>
</section>
</div>
<div class="column">
<section class="card" id="structure">
<h2>Structure</h2>
{_structure_html(struct, data)}
</section>
</div>
<section class="card wide" id="diagrams">
<h2>Diagrams</h2>
<div class="charts" id="charts"></div>
</section>
<section class="card wide" id="table">
<h2>{table_title}</h2>
{_table_html(plan, table, data)}
</section>
</main>
<footer>assur report · SI units: m, N, N·m, rad/s; angles in degrees · the drawing and
diagrams need JavaScript, the tables do not.</footer>
<script type="application/json" id="assur-data">{_json(data)}</script>
<script>{SCRIPT}</script>
</body>
</html>
"""


CSS = """
:root { --ink: #1f2937; --muted: #6b7280; --line: #e5e7eb; --paper: #f6f7f9;
  --card: #ffffff; --accent: #2563eb; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: var(--paper);
  font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial,
  sans-serif; }
header, main, footer { max-width: 1320px; margin: 0 auto; padding: 0 28px; }
header { padding-top: 24px; }
h1 { font-size: 1.55rem; margin: 0 0 2px; letter-spacing: -0.01em; }
h2 { font-size: 1rem; margin: 0 0 12px; color: #111827; }
.description { margin: 0 0 4px; color: #374151; }
.meta, .note, footer { color: var(--muted); font-size: 0.85rem; }
main { display: grid; grid-template-columns: minmax(0, 7fr) minmax(0, 5fr); gap: 18px;
  padding-top: 12px; padding-bottom: 18px; align-items: start; }
.card { background: var(--card); border: 1px solid var(--line); border-radius: 10px;
  padding: 16px 18px; min-width: 0; }
.wide { grid-column: 1 / -1; }
#mechanism { display: block; width: 100%; height: auto; background: #fcfcfd;
  border: 1px solid var(--line); border-radius: 8px; }
.controls { display: flex; align-items: center; gap: 12px; margin: 12px 0 6px; }
.controls input { flex: 1; accent-color: var(--accent); }
button { font: inherit; font-size: 0.9rem; padding: 3px 14px; border-radius: 6px;
  border: 1px solid #d1d5db; background: #fff; color: var(--ink); cursor: pointer; }
button:hover { background: #f3f4f6; }
output { font-variant-numeric: tabular-nums; font-size: 0.9rem; min-width: 15em; }
.legend { list-style: none; display: flex; flex-wrap: wrap; gap: 4px 18px; padding: 0;
  margin: 6px 0; font-size: 0.85rem; }
.swatch { display: inline-block; width: 12px; height: 12px; border-radius: 3px;
  margin-right: 6px; vertical-align: -1px; }
.formula { font-weight: 600; margin: 0 0 10px; }
.report { font: 12px/1.5 ui-monospace, SFMono-Regular, Menlo, Consolas, monospace;
  background: #f3f4f6; border-radius: 6px; padding: 10px 12px; margin: 14px 0 0; }
.report div { white-space: pre-wrap; }
.column { display: flex; flex-direction: column; gap: 18px; min-width: 0; }
.current { display: flex; flex-wrap: wrap; gap: 10px 28px; align-items: flex-start; }
.current table td { text-align: right; min-width: 5.5em; }
.current table td:first-child { text-align: left; min-width: 0; font-weight: 600; }
.current table th { text-align: right; }
.current table th:first-child { text-align: left; }
table { border-collapse: collapse; font-size: 0.85rem;
  font-variant-numeric: tabular-nums; }
th, td { padding: 3px 9px; border-bottom: 1px solid var(--line); }
th { font-weight: 600; text-align: left; color: #374151; }
table.groups td:first-child { padding-right: 0; }
.table-wrap { max-height: 420px; overflow: auto; border: 1px solid var(--line);
  border-radius: 6px; }
table.values th { position: sticky; top: 0; background: #f9fafb; text-align: right; }
table.values td { text-align: right; }
table.values tr.shown td { background: #e0ecff; }
.charts { display: grid; grid-template-columns: repeat(auto-fit, minmax(340px, 1fr));
  gap: 14px 22px; }
figure { margin: 0; }
.charts figure { max-width: 640px; }
figcaption { font-size: 0.9rem; font-weight: 600; margin-bottom: 4px; }
figure svg { display: block; width: 100%; height: auto; }
.chart-legend { display: flex; flex-wrap: wrap; gap: 2px 14px; font-size: 0.8rem;
  color: #374151; }
.chart-legend i { display: inline-block; width: 16px; margin-right: 5px;
  vertical-align: 3px; border-top: 2.5px solid; }
.chart-legend i.dashed { border-top-style: dashed; }
svg text { font-family: system-ui, -apple-system, "Segoe UI", Roboto, Arial,
  sans-serif; }
.label { font-size: 12px; fill: #374151; paint-order: stroke; stroke: #fcfcfd;
  stroke-width: 3px; stroke-linejoin: round; }
.axis text { font-size: 11px; fill: var(--muted); }
footer { padding-bottom: 28px; }
@media (max-width: 960px) { main { grid-template-columns: 1fr; } }
"""

SCRIPT = r"""
(function () {
  "use strict";
  const errors = window.assurErrors = [];
  window.addEventListener("error", (event) => errors.push(String(event.message)));
  const data = JSON.parse(document.getElementById("assur-data").textContent);
  const svg = document.getElementById("mechanism");
  const NS = svg.namespaceURI;
  const W = svg.viewBox.baseVal.width, H = svg.viewBox.baseVal.height, PAD = 42;
  const slider = document.getElementById("angle");
  const readout = document.getElementById("readout");
  const n = data.angle.length;
  const SERIES = ["#2563eb", "#dc2626", "#059669", "#d97706", "#7c3aed", "#db2777",
    "#0891b2", "#65a30d", "#4b5563", "#9333ea", "#ea580c", "#0d9488", "#be123c"];

  function el(name, attrs, parent) {
    const node = document.createElementNS(NS, name);
    set(node, attrs);
    if (parent) parent.appendChild(node);
    return node;
  }
  function set(node, attrs) {
    for (const key in attrs) node.setAttribute(key, attrs[key]);
  }
  function fmt(v) {
    if (v === null || v === undefined || !isFinite(v)) return "–";
    // round-off (a frictionless guide's 1e-14 N) reads as the zero it is
    return Math.abs(v) < 1e-9 ? "0" : String(Number(v.toPrecision(4)));
  }

  // model (m, y up) to drawing (px, y down), one scale for the whole sweep
  const [bx0, bx1, by0, by1] = data.bounds;
  const k = Math.min((W - 2 * PAD) / (bx1 - bx0), (H - 2 * PAD) / (by1 - by0));
  const ox = (W - k * (bx1 - bx0)) / 2 - k * bx0;
  const oy = (H + k * (by1 - by0)) / 2 + k * by0;
  const X = (x) => ox + k * x, Y = (y) => oy - k * y;
  function at(name, i) {
    const p = data.points[name];
    return [X(p.x[i]), Y(p.y[i])];
  }
  const colour = {};
  for (const link of data.links) colour[link.name] = link.colour;

  const layer = {};
  for (const name of ["guides", "links", "blocks", "pivots", "joints", "marks",
    "forces", "labels"]) layer[name] = el("g", {class: name}, svg);

  // guides: a hatched rail on the frame, a slot (channel) in a moving link
  const guides = data.guides.map((g) => {
    const group = el("g", {"data-guide": g.joint}, layer.guides);
    const item = {g: g, frame: g.body === "ground"};
    if (item.frame) {
      item.hatch = el("polygon", {fill: "url(#hatch)"}, group);
      item.rail = el("line", {stroke: "#4b5563", "stroke-width": 2}, group);
      item.axis = el("line", {stroke: "#9ca3af", "stroke-width": 1,
        "stroke-dasharray": "8 3 2 3"}, group);
    } else {
      item.outer = el("line", {stroke: colour[g.body], "stroke-width": 15,
        "stroke-linecap": "round", "stroke-opacity": 0.45}, group);
      item.inner = el("line", {stroke: "#fff", "stroke-width": 7,
        "stroke-linecap": "round"}, group);
    }
    return item;
  });
  function drawGuide(item, i) {
    const g = item.g;
    const a = [X(g.x1[i]), Y(g.y1[i])], b = [X(g.x2[i]), Y(g.y2[i])];
    const ends = {x1: a[0], y1: a[1], x2: b[0], y2: b[1]};
    if (!item.frame) {
      set(item.outer, ends);
      set(item.inner, ends);
      return;
    }
    // the rail runs under the block, on the side facing down (or right) on screen
    let nx = g.uy[i], ny = g.ux[i];
    if (ny < 0 || (Math.abs(ny) < 1e-9 && nx < 0)) { nx = -nx; ny = -ny; }
    const h = 10, w = 7;
    set(item.axis, ends);
    set(item.rail, {x1: a[0] + nx * h, y1: a[1] + ny * h, x2: b[0] + nx * h,
      y2: b[1] + ny * h});
    set(item.hatch, {points: [a, b, b, a].map((p, j) => {
      const d = j < 2 ? h : h + w;
      return (p[0] + nx * d) + "," + (p[1] + ny * d);
    }).join(" ")});
  }

  // links: a bar between two points, a plate through three or more; a guide fixed in
  // a link counts as a point at its middle, so that the link reaches its slot
  const guideOf = {};
  for (const g of data.guides) guideOf[g.joint] = g;
  function anchor(a, i) {
    if (!a.guide) return at(a.name, i);
    const g = guideOf[a.name];
    return [X((g.x1[i] + g.x2[i]) / 2), Y((g.y1[i] + g.y2[i]) / 2)];
  }
  const links = data.links.map((l) => {
    let order = l.points.map((name) => ({name: name, guide: false}))
      .concat(l.guides.map((name) => ({name: name, guide: true})));
    if (order.length < 2) return null;
    const p = order.map((a) => anchor(a, 0));
    let area = 0;
    p.forEach((q, j) => {
      const r = p[(j + 1) % p.length];
      area += q[0] * r[1] - r[0] * q[1];
    });
    if (Math.abs(area) < 1e-3 * W * H) {
      // (nearly) on one line: a bar between the two points farthest apart
      let best = [0, 1], far = -1;
      for (let a = 0; a < p.length; a++) {
        for (let b = a + 1; b < p.length; b++) {
          const d = Math.hypot(p[a][0] - p[b][0], p[a][1] - p[b][1]);
          if (d > far) { far = d; best = [a, b]; }
        }
      }
      order = best.map((j) => order[j]);
    } else {
      const cx = p.reduce((sum, q) => sum + q[0], 0) / p.length;
      const cy = p.reduce((sum, q) => sum + q[1], 0) / p.length;
      order = order.map((a, j) => [Math.atan2(p[j][1] - cy, p[j][0] - cx), a])
        .sort((u, v) => u[0] - v[0]).map((u) => u[1]);
    }
    const attrs = {"data-link": l.name, stroke: l.colour, "stroke-linecap": "round",
      "stroke-linejoin": "round"};
    const node = order.length === 2
      ? el("line", Object.assign(attrs, {"stroke-width": 9, "stroke-opacity": 0.9}),
        layer.links)
      : el("polygon", Object.assign(attrs, {"stroke-width": 6, fill: l.colour,
        "fill-opacity": 0.2}), layer.links);
    return {node: node, order: order};
  }).filter((item) => item !== null);
  function drawLink(item, i) {
    const p = item.order.map((a) => anchor(a, i));
    if (item.order.length === 2) {
      set(item.node, {x1: p[0][0], y1: p[0][1], x2: p[1][0], y2: p[1][1]});
    } else {
      set(item.node, {points: p.map((q) => q.join(",")).join(" ")});
    }
  }

  const moving = (node, x, y, deg) => set(node, {transform:
    "translate(" + x + " " + y + ")" + (deg ? " rotate(" + deg + ")" : "")});
  const blocks = [], pivots = [], circles = [], labels = [], marks = [];
  const together = (a, b) => data.points[a].x.every((x, i) => x === null ||
    Math.hypot(x - data.points[b].x[i], data.points[a].y[i] - data.points[b].y[i]) <
    1e-6 * (bx1 - bx0));
  function label(name, offset) {
    const same = labels.find((item) => together(item.name, name));
    if (same) {
      same.node.textContent += ", " + name;
      return;
    }
    const text = el("text", {class: "label", dx: offset, dy: -offset}, layer.labels);
    text.textContent = name;
    labels.push({node: text, name: name});
  }
  for (const j of data.joints) {
    if (j.kind === "P" && !j.slot) {
      const group = el("g", {"data-block": j.name}, layer.blocks);
      el("rect", {x: -18, y: -10, width: 36, height: 20, rx: 3, fill: colour[j.second],
        "fill-opacity": 0.25, stroke: colour[j.second], "stroke-width": 2.5}, group);
      el("rect", {x: -18, y: -10, width: 36, height: 20, rx: 3, fill: "none",
        stroke: "#111827", "stroke-opacity": 0.25, "stroke-width": 1}, group);
      blocks.push({node: group, name: j.name, guide: guideOf[j.name]});
    } else {
      if (j.first === "ground" || j.second === "ground") {
        const group = el("g", {"data-pivot": j.name}, layer.pivots);
        el("polygon", {points: "0,0 -10,16 10,16", fill: "#e5e7eb", stroke: "#374151",
          "stroke-width": 1.5, "stroke-linejoin": "round"}, group);
        el("rect", {x: -16, y: 16, width: 32, height: 7, fill: "url(#hatch)"}, group);
        el("line", {x1: -16, y1: 16, x2: 16, y2: 16, stroke: "#374151",
          "stroke-width": 2}, group);
        pivots.push({node: group, name: j.name});
      }
      const circle = el("circle", {r: 5.5, fill: "#fff", stroke: "#111827",
        "stroke-width": 2, "data-joint": j.name}, layer.joints);
      circles.push({node: circle, name: j.name});
    }
    label(j.name, 9);
  }
  for (const name of data.extra_points) {
    const link = data.links.find((l) => l.points.includes(name));
    const dot = el("circle", {r: 4, fill: link ? link.colour : "#111827",
      "data-point": name}, layer.joints);
    circles.push({node: dot, name: name});
    label(name, 8);
  }
  if (data.forces) {
    for (const l of data.links) {
      if (!l.center) continue;
      const group = el("g", {"data-center": l.name}, layer.marks);
      el("circle", {r: 5, fill: "#fff", stroke: "#111827", "stroke-width": 1.3}, group);
      el("path", {d: "M0,0 L5,0 A5,5 0 0,1 0,5 Z M0,0 L-5,0 A5,5 0 0,1 0,-5 Z",
        fill: "#111827"}, group);
      marks.push({node: group, name: l.center});
    }
  }

  // reaction arrows: one scale for the whole sweep, stated by the bar in the corner
  const arrows = [];
  let perNewton = 0;
  if (data.forces) {
    let most = 0;
    for (const j of data.forces.joints) {
      for (const v of data.columns[j + ".F"]) if (v !== null) most = Math.max(most, v);
    }
    const BAR = 60;
    const raw = most * BAR / (0.24 * Math.min(W, H)) || 1;
    const mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const newtons = [1, 2, 5, 10].map((m) => m * mag)
      .find((s) => s >= raw * (1 - 1e-9));
    perNewton = BAR / newtons;
    for (const j of data.forces.joints) {
      const line = el("line", {stroke: "#c2185b", "stroke-width": 2.2,
        "marker-end": "url(#arrowhead)", "data-force": j}, layer.forces);
      arrows.push({node: line, name: j});
    }
    const bar = el("g", {class: "scale"}, svg);
    el("line", {x1: 14, y1: H - 16, x2: 14 + BAR, y2: H - 16, stroke: "#c2185b",
      "stroke-width": 2.2, "marker-end": "url(#arrowhead)"}, bar);
    const label = el("text", {x: 20 + BAR, y: H - 12, class: "label"}, bar);
    label.textContent = fmt(newtons) + " N";
    document.getElementById("force-note").textContent = "Arrows: the reaction at " +
      "each joint, the force of its first link on its second (the bar in the lower " +
      "left corner is " + fmt(newtons) + " N). Filled circles mark the centres of " +
      "mass.";
  }

  function drawMechanism(i) {
    for (const item of guides) drawGuide(item, i);
    for (const item of links) drawLink(item, i);
    for (const item of blocks) {
      const p = at(item.name, i), g = item.guide;
      const deg = g ? -Math.atan2(g.uy[i], g.ux[i]) * 180 / Math.PI : 0;
      moving(item.node, p[0], p[1], deg);
    }
    for (const item of pivots) moving(item.node, ...at(item.name, i));
    for (const item of marks) moving(item.node, ...at(item.name, i));
    for (const item of circles) {
      const p = at(item.name, i);
      set(item.node, {cx: p[0], cy: p[1]});
    }
    for (const item of labels) {
      const p = at(item.name, i);
      set(item.node, {x: p[0], y: p[1]});
    }
    for (const item of arrows) {
      const p = at(item.name, i);
      const fx = data.columns[item.name + ".Fx"][i];
      const fy = data.columns[item.name + ".Fy"][i];
      const shown = Math.hypot(fx, fy) * perNewton > 3;
      set(item.node, {x1: p[0], y1: p[1], x2: p[0] + fx * perNewton,
        y2: p[1] - fy * perNewton, visibility: shown ? "visible" : "hidden"});
    }
  }

  // diagrams against the driver position, with a marker at the current one
  function ticks(lo, hi, count, degrees) {
    const span = hi - lo;
    let step;
    if (degrees && span > 150) {
      step = span > 800 ? 180 : 90;
    } else {
      const raw = span / count, mag = Math.pow(10, Math.floor(Math.log10(raw)));
      step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw);
    }
    return step;
  }
  function chart(spec) {
    const CW = 480, CH = 250, m = {l: 58, r: 14, t: 10, b: 40};
    const figure = document.createElement("figure");
    const caption = document.createElement("figcaption");
    caption.textContent = spec.title;
    figure.appendChild(caption);
    const s = el("svg", {viewBox: "0 0 " + CW + " " + CH, id: spec.id, role: "img",
      "aria-label": spec.title}, figure);
    const legend = document.createElement("div");
    legend.className = "chart-legend";
    figure.appendChild(legend);
    document.getElementById("charts").appendChild(figure);
    const xs = data.angle;
    const series = spec.series.map((item, j) => Object.assign({
      values: data.columns[item.key],
      colour: item.dashed ? "#111827" : SERIES[j % SERIES.length]}, item));
    const finite = series.flatMap((item) => item.values.filter((v) => v !== null));
    let lo = Math.min(...finite), hi = Math.max(...finite);
    if (!(hi - lo > 1e-12 * Math.max(1, Math.abs(hi)))) {
      const half = Math.abs(hi) * 0.1 || 1;
      lo -= half; hi += half;
    }
    const ystep = ticks(lo, hi, 5, false);
    lo = Math.floor(lo / ystep) * ystep; hi = Math.ceil(hi / ystep) * ystep;
    const x0 = xs[0], x1 = xs[xs.length - 1] === x0 ? x0 + 1 : xs[xs.length - 1];
    const xa = Math.min(x0, x1), xb = Math.max(x0, x1);
    const px = (x) => m.l + (x - xa) / (xb - xa) * (CW - m.l - m.r);
    const py = (y) => CH - m.b - (y - lo) / (hi - lo) * (CH - m.t - m.b);
    const axis = el("g", {class: "axis"}, s);
    for (let y = lo, j = 0; y <= hi + ystep * 1e-6 && j < 60; y = lo + (++j) * ystep) {
      const zero = Math.abs(y) < ystep * 1e-6;
      el("line", {x1: m.l, x2: CW - m.r, y1: py(y), y2: py(y), stroke: zero ? "#9ca3af"
        : "#eef0f3", "stroke-width": 1}, axis);
      el("text", {x: m.l - 6, y: py(y) + 4, "text-anchor": "end"}, axis).textContent =
        fmt(zero ? 0 : y);
    }
    const degrees = data.driver.unit === "deg";
    const xstep = ticks(xa, xb, 6, degrees);
    for (let x = Math.ceil(xa / xstep - 1e-9) * xstep, j = 0; x <= xb + 1e-9 && j < 60;
      x += xstep, j++) {
      el("line", {x1: px(x), x2: px(x), y1: m.t, y2: CH - m.b, stroke: "#eef0f3"},
        axis);
      el("text", {x: px(x), y: CH - m.b + 15, "text-anchor": "middle"}, axis)
        .textContent = fmt(x);
    }
    el("rect", {x: m.l, y: m.t, width: CW - m.l - m.r, height: CH - m.t - m.b,
      fill: "none", stroke: "#d1d5db"}, axis);
    el("text", {x: (m.l + CW - m.r) / 2, y: CH - 6, "text-anchor": "middle"}, axis)
      .textContent = data.driver.label + " (" + data.driver.unit + ")";
    const middle = (m.t + CH - m.b) / 2;
    el("text", {x: 13, y: middle, "text-anchor": "middle",
      transform: "rotate(-90 13 " + middle + ")"}, axis).textContent = spec.unit;
    const cursor = el("line", {y1: m.t, y2: CH - m.b, stroke: "#6b7280",
      "stroke-dasharray": "3 3", class: "cursor"}, s);
    const dots = [];
    for (const item of series) {
      let d = "", pen = "M";
      item.values.forEach((v, i) => {
        if (v === null) { pen = "M"; return; }
        d += pen + px(xs[i]).toFixed(1) + "," + py(v).toFixed(1);
        pen = "L";
      });
      el("path", {d: d, fill: "none", stroke: item.colour, "stroke-width": item.dashed
        ? 1.6 : 2, "stroke-dasharray": item.dashed ? "5 4" : "none",
        "stroke-linejoin": "round"}, s);
      dots.push(el("circle", {r: 3.5, fill: item.colour, stroke: "#fff",
        "stroke-width": 1.2}, s));
      const key = document.createElement("span");
      const swatch = document.createElement("i");
      swatch.style.borderColor = item.colour;
      if (item.dashed) swatch.className = "dashed";
      key.appendChild(swatch);
      key.appendChild(document.createTextNode(item.name));
      legend.appendChild(key);
    }
    return function mark(i) {
      set(cursor, {x1: px(xs[i]), x2: px(xs[i])});
      series.forEach((item, j) => {
        const v = item.values[i];
        set(dots[j], {cx: px(xs[i]), cy: v === null ? -10 : py(v),
          visibility: v === null ? "hidden" : "visible"});
      });
    };
  }
  const cursors = data.charts.filter((spec) => spec.series.length).map(chart);

  // live tables of the values at the shown position
  const live = [];
  const value = (key, i) => key in data.columns ? data.columns[key][i]
    : data.points[key.slice(0, -2)][key.slice(-1)][i];
  function liveTable(head, rows) {
    if (!rows.length) return;
    const table = document.createElement("table");
    const tr = table.createTHead().insertRow();
    for (const text of head) {
      const th = document.createElement("th");
      th.textContent = text;
      tr.appendChild(th);
    }
    const body = table.createTBody();
    for (const row of rows) {
      const line = body.insertRow();
      line.insertCell().textContent = row.name;
      for (const key of row.keys) live.push({cell: line.insertCell(), key: key});
    }
    document.getElementById("current").appendChild(table);
  }
  liveTable(["link", "angle (deg)", "ω (rad/s)", "α (rad/s²)"], data.current.links);
  liveTable(["slide", "s (m)", "v (m/s)", "a (m/s²)"], data.current.slides);
  liveTable(data.forces ? ["joint", "Fx (N)", "Fy (N)", "|F| (N)"]
    : ["joint", "x (m)", "y (m)"], data.current.joints);

  const rows = {};
  for (const row of document.querySelectorAll("#values tr[data-row]")) {
    rows[row.dataset.row] = row;
  }
  let current = null;
  function update(i) {
    drawMechanism(i);
    cursors.forEach((mark) => mark(i));
    for (const item of live) item.cell.textContent = fmt(value(item.key, i));
    let text = data.driver.label + " " + fmt(data.angle[i]) +
      (data.driver.unit === "deg" ? "°" : " m");
    if (data.forces) {
      for (const item of data.forces.balancing) {
        if (item.dashed) continue;
        text += " · " + item.name + " " + fmt(data.columns[item.key][i]) +
          (item.key.includes("torque") ? " N·m" : " N");
      }
    }
    readout.textContent = text;
    if (current) current.classList.remove("shown");
    current = rows[i] || null;
    if (current) current.classList.add("shown");
  }
  slider.addEventListener("input", () => update(Number(slider.value)));

  let timer = null;
  const play = document.getElementById("play");
  play.addEventListener("click", () => {
    if (timer) {
      clearInterval(timer);
      timer = null;
      play.textContent = "Play";
      return;
    }
    play.textContent = "Pause";
    timer = setInterval(() => {
      slider.value = String((Number(slider.value) + 1) % n);
      update(Number(slider.value));
    }, 40);
  });
  update(0);
  document.documentElement.dataset.ready = "true";
})();
"""
