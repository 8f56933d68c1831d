"""The figures ``assur dynamics`` gives: the steady state's and the start-up's.

As aligned lines of text, as the JSON document's head, and the start-up's samples
as CSV.
"""

from __future__ import annotations

from typing import Any

from assur._dynamics_text import figure_lines
from assur._width import ljust, shown_width


def _head(result: Any, sizing: Any, run: Any) -> dict[str, Any]:
    """Return the JSON document's figures: what comes before its columns."""
    data: dict[str, Any] = {"dynamics": result.summary()}
    if sizing is not None:
        data["flywheel"] = {
            "delta": sizing.delta,
            "exact": sizing.exact,
            "wittenbauer": sizing.wittenbauer,
            "energy_swing": sizing.energy_swing,
            "mertsalov": sizing.mertsalov,
        }
    if run is not None:
        data["startup"] = _startup_data(run)
    return data


def startup_csv(run: Any) -> str:
    """Return the start-up's samples as CSV text: time (s), angle (deg), omega (rad/s).

    Numbers are written with 17 significant digits (``repr``), so reading the file
    gives back the same floats.
    """
    rows = ["time,angle,omega"]
    rows += [
        f"{t!r},{a!r},{w!r}"
        for t, a, w in zip(
            run.time.tolist(), run.angle.tolist(), run.omega.tolist(), strict=True
        )
    ]
    return "\n".join(rows) + "\n"


def _figures(result: Any, sizing: Any, run: Any) -> str:
    """Return the figures of the steady state (and start-up) as aligned lines."""
    return _header(result.mechanism, figure_lines(result, sizing, run))


def _header(mechanism: Any, lines: list[tuple[str, str]]) -> str:
    """Return the mechanism's name over the figures' ``lines``, aligned."""
    name = mechanism.name or "Mechanism"
    width = max(shown_width(k) for k, _ in lines)
    body = "\n".join(f"  {ljust(k, width)}  {v}" for k, v in lines)
    return f"{name}: dynamic model reduced to the crank\n{body}"


def _startup_data(run: Any) -> dict[str, Any]:
    """Return a start-up's figures and its motion, JSON-ready."""
    return {
        "settle_time": run.settle_time,
        "turns": run.turns,
        "period": run.period,
        "mean_speed": run.mean_speed,
        "speed_max": run.speed_max,
        "speed_min": run.speed_min,
        "delta": run.delta,
        "time": run.time.tolist(),
        "angle": run.angle.tolist(),
        "omega": run.omega.tolist(),
    }
