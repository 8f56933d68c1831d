"""Why a summary's value (or a study's row's) is not a number, in words.

Only the efficiency can be undefined in a summary; a study's row lacks the values of
a variant not analysed, or of a part its mechanism does not have.
"""

from __future__ import annotations

import math
from typing import Any

__all__ = ["FRICTION", "undefined"]


def undefined(values: dict[str, float]) -> dict[str, str]:
    """Return why each value of a summary that is not a number is not one, by name.

    Only the efficiency can be undefined (see :func:`efficiency`). In a study's row
    (:func:`assur.sweep <assur.study.sweep>`) a value is NaN also where the variant
    was not analysed (its ``error`` says why) or has no such value: no friction in
    its joints (the losses, the power without friction, the efficiency), or no such
    joint. Values that are not numbers (the text of a study's row) are passed over.
    """
    out = {}
    for name, value in values.items():
        if not isinstance(value, int | float) or math.isfinite(value):
            continue
        if "." not in name and name != "efficiency":
            # a study's parameter (an identifier: no dot, never "efficiency"),
            # NaN as the user gave it, not a value the summary left undefined
            continue
        out[name] = _why(name, values)
    return out


FRICTION = ("friction.loss", "driver.power_ideal.mean", "efficiency")
"""The summary's values with friction (and every ``<joint>.friction.loss``)."""


def _why(name: str, values: dict[str, Any]) -> str:
    """Return why the value ``name`` of a summary (or a study's row) is NaN."""
    error = values.get("error")
    if isinstance(error, str) and error:
        return "the variant was not analysed (see its error)"
    rubbing = math.isfinite(values.get("driver.power_ideal.mean", math.nan))
    if (name in FRICTION or name.endswith(".friction.loss")) and not rubbing:
        return "no friction in this variant: no losses, no efficiency"
    if name == "efficiency" and not values["driver.power.mean"] > 0.0:
        return "the driver does no net work (mean power <= 0): the loads drive"
    if name == "efficiency":
        return (
            "the loads give back work (mean power without friction < 0) that the "
            "driver still supplies"
        )
    if error == "":
        return "not a value of this variant (its mechanism has no such part)"
    return "not defined over these positions"
