"""The report's dynamics section: the steady state of the crank and its diagrams.

For a mechanism with masses and one crank, the figures of the steady state (the
coefficient of speed fluctuation, the flywheel, the motor torque) as an HTML table,
and three diagrams for the page's script to draw over the same crank angles as the
others: the reduced inertia, the reduced and motor torques, the crank's speed.
"""

from __future__ import annotations

from html import escape
from typing import Any

import numpy as np

from assur._dynamics_text import motor_text, speed_text, swing_text
from assur._text import crank_angle_text
from assur.analysis import Table
from assur.columns import pretty_unit
from assur.dynamics_shown import SHOWN_DELTA, has_dynamics, shown
from assur.errors import AssurError
from assur.html._data import floats
from assur.html._sections import caption, number, wide_card

__all__ = ["dynamics_part"]

CHARTS = (
    ("chart-inertia", "Reduced inertia J(φ)", (("J", "reduced.inertia", False),)),
    (
        "chart-reduced-torque",
        "Reduced torque of the loads and the motor torque",
        (("loads", "reduced.torque", False), ("motor", "driver.motor", True)),
    ),
    ("chart-speed", "Crank speed in the steady state", (("ω", "driver.omega", False),)),
)
"""The section's diagrams: id, title, and each series' name, column and dashing."""
FIGURES_CAPTION = "Figures of the steady state"
"""What the section's table holds, said to a screen reader."""


def dynamics_part(
    table: Table,
) -> tuple[str, dict[str, Any] | None, dict[str, list[float | None]]]:
    """Return the section's HTML, its data for the script and its columns.

    Nothing (``""``, None, ``{}``) for a mechanism without masses or without one
    crank; the section says why when its crank cannot turn round.
    """
    mech = table.mechanism
    if table.force_state is None or not has_dynamics(mech):
        return "", None, {}
    try:
        result = shown(mech, table["angle"])
    except AssurError as err:
        note = f"No steady state to show: {err}"
        return _section(f'<p class="note">{escape(note)}</p>'), None, {}
    charts = []
    for ident, title, series in CHARTS:
        unit = pretty_unit(result.column(series[0][1]).unit)
        charts.append(
            {
                "id": ident,
                "title": title,
                "unit": unit,
                "series": [
                    {"name": name, "key": key, "dashed": dashed}
                    for name, key, dashed in series
                ],
            }
        )
    columns = {
        key: floats(np.asarray(result[key]))
        for _, _, series in CHARTS
        for _, key, _ in series
    }
    body = _figures_html(result) + '\n<div class="charts" id="dynamics-charts"></div>'
    return _section(body), {"charts": charts, "summary": result.summary()}, columns


def _section(body: str) -> str:
    """Return the section around ``body``."""
    return wide_card("dynamics", "Dynamics: the mechanism reduced to its crank", body)


def _figures_html(result: Any) -> str:
    """Return the figures of the steady state as a small table, and a note."""
    kgm2 = pretty_unit("kg m^2")
    top, low = (
        crank_angle_text(a, "°", number) for a in (result.angle_max, result.angle_min)
    )
    rows = [
        ("coefficient of speed fluctuation δ", number(result.delta)),
        ("flywheel on the crank", f"{number(result.flywheel)} {kgm2}"),
        ("motor torque", motor_text(result, "N·m", number)),
        (
            "largest speed",
            f"{number(result.speed_max)} rad/s at {top}",
        ),
        (
            "smallest speed",
            f"{number(result.speed_min)} rad/s at {low}",
        ),
        ("energy swing", swing_text(result, number)),
    ]
    if not result.speed_max > result.speed_min:
        # nothing varies over the turn: no place of the largest or smallest speed
        rows[3:5] = [("crank speed", f"constant, {number(abs(result.omega))} rad/s")]
    cells = "".join(
        f'<tr><th scope="row">{escape(k)}</th><td>{escape(v)}</td></tr>'
        for k, v in rows
    )
    why = (
        f"with the flywheel that holds δ to {SHOWN_DELTA:g} (without one, the crank "
        "would come to rest within a turn at this mean speed)"
        if result.flywheel
        else "without a flywheel"
    )
    note = (
        # the largest and smallest speeds are sizes: the nominal one is told alike
        f"Steady state at the nominal speed {speed_text(result.omega, number)} "
        "(the mean of the largest and "
        f"the smallest), {why}, under the constant motor torque "
        # a motor that brakes (the loads drive the crank) takes work, it gives none
        "whose work over a turn balances the loads'."
    )
    if any(j.friction for j in result.mechanism.joints):
        # the summary above counts friction's loss: say why the motor does not
        note += (
            " The dynamic model leaves the joints' friction out (the force tables "
            "and the summary count it)."
        )
    return (
        f'<p class="note">{escape(note)}</p>\n'
        f'<table class="figures">{caption(FIGURES_CAPTION)}<tbody>{cells}</tbody>'
        "</table>"
    )
