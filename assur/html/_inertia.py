"""The report's inertia loads at its first position, one row per link with a mass.

d'Alembert's inertia force ``F_i = -m a_G`` at the centre of mass, its size and
direction, the inertia torque ``M_i = -J_G epsilon``, and the offset ``h = |M_i| /
F_i`` of the single force equivalent to both: the numbers a student draws on the
links before the force analysis. Every value is read from the forces table.
"""

from __future__ import annotations

import math
from html import escape

from assur._digits import largest
from assur._position_titles import row_position
from assur.analysis import Table
from assur.html._data import public
from assur.html._sections import caption, columns_row, number, wide_card
from assur.html._series import massive_links

__all__ = ["inertia_html"]

HEADINGS = (
    ("link", ""),
    ("m", "kg"),
    ("a_G", "m/s²"),
    ("F_i = m a_G", "N"),
    ("direction of F_i", "deg"),
    ("J_G", "kg·m²"),
    ("ε", "rad/s²"),
    ("M_i = −J_G ε", "N·m"),
    ("h = |M_i| / F_i", "m"),
)
"""Column headings of the inertia table and their units."""


def inertia_rows(table: Table, row: int = 0) -> list[tuple[str, list[float]]]:
    """Return each massive link's name and its inertia figures at ``row``.

    The figures are, in SI units: m, a_G, F_i, the direction of F_i (deg from +x,
    counter-clockwise), J_G, epsilon, M_i and h (NaN where F_i is zero). The links
    come in the order of the page's other tables (:func:`massive_links`).
    """
    out = []
    links = {x.name: x for x in table.mechanism.links}
    for name in massive_links(table):
        link = links[name]
        if not link.mass:
            continue
        fx, fy, mi, ax, ay, eps = (
            float(table[f"{name}.{c}"][row])
            for c in ("Fi.x", "Fi.y", "Mi", "G.ax", "G.ay", "alpha")
        )
        size = math.hypot(fx, fy)
        # an inertia force of zero has no direction and no equivalent offset
        direction = math.degrees(math.atan2(fy, fx)) if size > 0 else math.nan
        h = abs(mi) / size if size > 0 else math.nan
        figures = [link.mass, math.hypot(ax, ay), size, direction]
        out.append((name, [*figures, link.inertia or 0.0, eps, mi, h]))
    return out


def _scales(
    rows: list[tuple[str, list[float]]], turn: float, size: float
) -> list[float | None]:
    """Return what each column of the inertia table is told from round-off by.

    Accelerations by the largest of the links' or the motion's own, the square of
    the fastest link's angular speed ``turn`` (rad/s), times the mechanism's
    ``size`` (m) for a point's (a yoke at mid-stroke has 1e-11 m/s^2 where a
    crank's pin has 20; every link of a parallelogram turning steadily has
    1e-13 rad/s^2); the inertia loads by the link's own mass or moment of
    inertia times those, the offsets h by the mechanism's size; the masses and
    moments of inertia are the file's own, shown however small (None). The
    inertia loads' scales are their accelerations', to be multiplied by each
    row's mass or moment of inertia (:func:`_sizes`).
    """
    columns = [largest(c) for c in zip(*(v for _, v in rows), strict=True)]
    point = max(columns[1], turn * turn * size)
    angular = max(columns[5], turn * turn)
    return [
        None,
        point,
        point,
        columns[3],
        None,
        angular,
        angular,
        max(columns[7], size),  # an offset beside the mechanism's size
    ]


def _sizes(scales: list[float | None], values: list[float]) -> list[float | None]:
    """Return what each of a row's ``values`` is told from round-off by.

    The columns' ``scales``, the inertia force's times the link's mass and the
    inertia torque's times its moment of inertia.
    """
    out = list(scales)
    for load, datum in ((2, 0), (6, 4)):
        scale = scales[load]
        out[load] = None if scale is None else values[datum] * scale
    return out


def inertia_html(table: Table) -> str:
    """Return the inertia section of a forces table at its first row (or nothing)."""
    if table.force_state is None or len(table) == 0:
        return ""
    rows = inertia_rows(table)
    if not rows:
        return ""
    head = columns_row(
        [f"{escape(title)}{f' ({unit})' if unit else ''}" for title, unit in HEADINGS]
    )
    turn = largest([table[f"{x.name}.omega"][0] for x in table.mechanism.links])
    scales = _scales(rows, turn, float(table.plan.scale))
    body = "\n".join(
        f'<tr data-link="{escape(name)}"><th scope="row">{escape(public(name))}</th>'
        + "".join(
            f"<td>{number(v, s)}</td>"
            for v, s in zip(values, _sizes(scales, values), strict=True)
        )
        + "</tr>"
        for name, values in rows
    )
    title = f"Inertia loads at the first position ({row_position(table, 0)})"
    return wide_card(
        "inertia",
        escape(title),
        '<p class="note">Each link with a mass carries the inertia force F_i = '
        "−m a_G at its centre of mass and the inertia torque M_i = −J_G ε; together "
        "they are one force of size F_i moved off the centre of mass by h, to the "
        "side where its moment about G turns like M_i. Directions are measured "
        "from +x, counter-clockwise.</p>\n"
        '<div class="table-wrap"><table class="values inertia">'
        f"{caption(title)}{head}\n<tbody>\n{body}\n</tbody></table></div>",
    )
