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

PALETTE = ("#334155", "#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
           "#56b4e9", "#8c564b", "#6b7280", "#b8860b")
"""Group colours in order of attachment: the first driver slate, then Okabe-Ito hues."""
DIGITS = 6
"""Significant digits of the numbers embedded in the page."""
GUIDE_MARGIN = 0.08
"""Length a guide line runs past the slide's travel at each end, times the
mechanism's size."""
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
    Positions that cannot be assembled are left out and named in the page. A force
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
        msg = (f"report of {mechanism.name or 'the mechanism'}: no driver position of "
               "the sweep can be assembled; expected at least one")
        raise AssemblyError(msg)
    struct = structure(mechanism)
    data = report_data(plan, struct, table)
    return _page(mechanism, struct, table, data)


def write_report(mechanism: Mechanism, path: str | os.PathLike[str],
                 angles: Any = None) -> None:
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


def report_data(plan: Plan, struct: Structure, table: Table) -> dict[str, Any]:
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
        "driver": {"label": "driver position" if prismatic else "driver angle",
                   "unit": "m" if prismatic else "deg"},
        "rows": len(table),
        "angle": _floats(table["angle"]),
        "analysis": "forces" if table.force_state is not None else "kinematics",
        "groups": _groups(struct),
        "links": _links(plan, colours),
        "joints": [{"name": p.name, "kind": p.kind, "first": plan.bodies[p.first],
                    "second": plan.bodies[p.second],
                    "slot": "~" in plan.bodies[p.second]} for p in joints],
        "points": {name: {"x": _floats(table[f"{name}.x"]),
                          "y": _floats(table[f"{name}.y"])} for name in plan.points},
        "extra_points": [p.name for p in plan.mechanism.points],
        "guides": [_guide(plan, table, p) for p in joints if p.kind == "P"],
    }
    data["bounds"] = _bounds(plan, data)
    charts, columns = _charts(plan, table)
    data["charts"] = charts
    data["columns"] = {key: _floats(table[key]) for key in columns}
    data["forces"] = None
    if table.force_state is not None:
        data["forces"] = {"joints": [p.name for p in joints],
                          "balancing": _balancing(plan)[0]}
    return data


def _floats(values: Array) -> list[float | None]:
    """Round to DIGITS significant digits for a compact page; NaN becomes null."""
    return [float(f"{v:.{DIGITS}g}") if math.isfinite(v) else None
            for v in np.asarray(values, dtype=float).tolist()]


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
    return [{"label": "driver" if g.group_class == 1 else g.label,
             "class": g.group_class, "roman": ROMAN.get(g.group_class, str(g.group_class)),
             "order": g.order, "kind": g.kind,
             "links": [_public(x) for x in g.links if x != GROUND],
             "colour": PALETTE[i % len(PALETTE)]}
            for i, g in enumerate(_all_groups(struct))]


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
        out.append({"name": name, "colour": colours[name], "points": points,
                    "center": center})
    return out


def _guide(plan: Plan, table: Table, pair: Any) -> dict[str, Any]:
    """The slide line of a prismatic pair over the sweep, fixed in its first link."""
    slide = np.asarray(table[f"{pair.name}.s"])
    margin = GUIDE_MARGIN * plan.scale
    axis = np.asarray(pair.axis, dtype=float)
    # the reference point's offset from the first link's origin, in its own frame
    at = pair.d_first
    ends = [at + axis * (np.nanmin(slide) - margin), at + axis * (np.nanmax(slide) + margin)]
    phi = table.state.link[0, :, pair.first]
    origin = table.state.origin[0, :, pair.first]
    c, s = np.cos(phi), np.sin(phi)
    out: dict[str, Any] = {"joint": pair.name, "body": plan.bodies[pair.first]}
    for tag, (dx, dy) in (("1", ends[0]), ("2", ends[1])):
        out[f"x{tag}"] = _floats(origin[:, 0] + c * dx - s * dy)
        out[f"y{tag}"] = _floats(origin[:, 1] + s * dx + c * dy)
    out["ux"] = _floats(c * axis[0] - s * axis[1])
    out["uy"] = _floats(s * axis[0] + c * axis[1])
    return out


def _bounds(plan: Plan, data: dict[str, Any]) -> list[float]:
    """Box (m) holding every point and guide over the sweep, never thinner than a tenth
    of the mechanism's size."""
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
        series.append({"name": f"check by virtual power{tag}",
                       "key": f"{key}.{what}_check", "dashed": True})
    return series, " or ".join(sorted(units))


def _moving_links(plan: Plan, table: Table) -> list[str]:
    """Visible links that rotate during the sweep."""
    out = []
    for name in plan.bodies[1:]:
        key = f"{name}.omega"
        if "~" not in name and key in table and np.nanmax(np.abs(table[key])) > 1e-12:
            out.append(name)
    return out


def _charts(plan: Plan, table: Table) -> tuple[list[dict[str, Any]], list[str]]:
    """Diagram specifications and the table columns they need."""
    charts = []
    if table.force_state is not None:
        series, unit = _balancing(plan)
        charts.append({"id": "chart-balancing", "title": "Balancing load and its check",
                       "unit": unit, "series": series})
        joints = [p.name for p in plan.pairs.values() if not p.virtual]
        charts.append({"id": "chart-reactions", "title": "Joint reactions |F|",
                       "unit": "N", "series": [{"name": j, "key": f"{j}.F"} for j in joints]})
    links = _moving_links(plan, table)
    charts.append({"id": "chart-omega", "title": "Angular velocities of the links",
                   "unit": "rad/s",
                   "series": [{"name": x, "key": f"{x}.omega"} for x in links]})
    columns = [s["key"] for c in charts for s in c["series"]]
    if table.force_state is not None:
        for p in plan.pairs.values():
            if not p.virtual:
                columns += [f"{p.name}.Fx", f"{p.name}.Fy"]
    return charts, list(dict.fromkeys(columns))


def _number(v: float) -> str:
    return f"{v:.5g}" if math.isfinite(v) else "–"


def _meta(struct: Structure, table: Table, data: dict[str, Any]) -> str:
    driver = data["driver"]
    angle = np.asarray(table["angle"])
    parts = [f"W = {struct.dof}", f"class {ROMAN.get(struct.mechanism_class)} mechanism",
             f"{len(table)} positions, {driver['label']} {_number(angle[0])} to "
             f"{_number(angle[-1])} {driver['unit']}",
             "force analysis" if data["forces"] else "kinematics only (no masses or loads)"]
    if table.skipped.size:
        parts.append(f"{table.skipped.shape[0]} positions left out: they cannot be assembled")
    return " · ".join(escape(p) for p in parts)


def _structure_html(struct: Structure, data: dict[str, Any]) -> str:
    rows = []
    for step, (g, info) in enumerate(zip(_all_groups(struct), data["groups"]), 1):
        kind = "input link" if g.group_class == 1 else g.kind
        cells = [f'<span class="swatch" style="background:{info["colour"]}"></span>',
                 str(step), info["roman"], str(g.order), kind,
                 ", ".join(info["links"]), ", ".join(_public(x) for x in g.internal),
                 ", ".join(_public(x) for x in g.external)]
        rows.append("<tr>" + "".join(f"<td>{c if i == 0 else escape(c)}</td>"
                                     for i, c in enumerate(cells)) + "</tr>")
    head = "".join(f"<th>{h}</th>" for h in ("", "Step", "Class", "Order", "Kind",
                                                 "Links", "Internal pairs",
                                                 "External pairs"))
    formula = escape(struct.formula.replace(" -> ", " → "))
    return (f'<p class="formula">{formula}</p>\n'
            f'<table class="groups"><thead><tr>{head}</tr></thead>\n<tbody>'
            + "\n".join(rows) + "</tbody></table>\n"
            f'<pre class="report">{escape(str(struct))}</pre>')


def _legend_html(data: dict[str, Any]) -> str:
    items = []
    for g in data["groups"]:
        what = ("driver" if g["class"] == 1
                else f"order {g['order']} · {g['kind']}")
        text = f"{g['roman']} · {what} · {', '.join(g['links'])}"
        items.append(f'<li><span class="swatch" style="background:{g["colour"]}"></span>'
                     f"{escape(text)}</li>")
    return '<ul class="legend">' + "".join(items) + "</ul>"


def _table_columns(plan: Plan, table: Table, data: dict[str, Any]) -> list[tuple[str, str]]:
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
    columns += [(f"{p.name}.s", f"slide {p.name} (m)") for p in joints if p.kind == "P"
                and "~" not in plan.bodies[p.second]]
    return columns


def _table_html(plan: Plan, table: Table, data: dict[str, Any]) -> str:
    columns = _table_columns(plan, table, data)
    step = 10 if len(table) > LONG_TABLE else 1
    values = [np.asarray(table[key]) for key, _ in columns]
    head = "".join(f"<th>{escape(title)}</th>" for _, title in columns)
    rows = [f'<tr data-row="{i}">' + "".join(f"<td>{_number(float(v[i]))}</td>"
                                             for v in values) + "</tr>"
            for i in range(0, len(table), step)]
    note = (f"Every {step}th of {len(table)} positions." if step > 1
            else f"All {len(table)} positions.")
    return (f'<p class="note">{note} The highlighted row is the position shown in the '
            'drawing.</p>\n<div class="table-wrap"><table class="values" id="values">'
            f"<thead><tr>{head}</tr></thead>\n<tbody>" + "\n".join(rows)
            + "</tbody></table></div>")


def _json(data: dict[str, Any]) -> str:
    """JSON safe inside a script element: no '<', '>' or '&' can end or open a tag."""
    text = json.dumps(data, separators=(",", ":"), allow_nan=False, ensure_ascii=False)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def _page(mech: Mechanism, struct: Structure, table: Table, data: dict[str, Any]) -> str:
    title = escape(mech.name or "Mechanism")
    description = (f'<p class="description">{escape(mech.description)}</p>'
                   if mech.description else "")
    forces_note = ('<p class="note" id="force-note"></p>' if data["forces"] else "")
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
<section class="card" id="drawing">
<h2>Mechanism</h2>
<svg id="mechanism" viewBox="0 0 640 460" role="img" aria-label="Drawing of the mechanism">
<defs>
<pattern id="hatch" width="6" height="6" patternUnits="userSpaceOnUse" patternTransform="rotate(45)"><line x1="0" y1="0" x2="0" y2="6" stroke="#9ca3af" stroke-width="1.6"/></pattern>
<marker id="arrowhead" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#c2185b"/></marker>
</defs>
</svg>
<div class="controls">
<button type="button" id="play">Play</button>
<input type="range" id="angle" min="0" max="{n - 1}" step="1" value="0" aria-label="Driver position">
<output id="readout" for="angle"></output>
</div>
{_legend_html(data)}
{forces_note}
</section>
<section class="card" id="structure">
<h2>Structure</h2>
{_structure_html(struct, data)}
</section>
<section class="card wide" id="diagrams">
<h2>Diagrams</h2>
<div class="charts" id="charts"></div>
</section>
<section class="card wide" id="table">
<h2>{table_title}</h2>
{_table_html(compile_plan(mech), table, data)}
</section>
</main>
<footer>assur report · SI units: m, N, N·m, rad/s; angles in degrees · the drawing and
diagrams need JavaScript, the tables do not.</footer>
<script type="application/json" id="assur-data">{_json(data)}</script>
<script>{SCRIPT}</script>
</body>
</html>
"""
