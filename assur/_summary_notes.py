"""What is said with a summary: which sign drives, what its means are over.

The command line prints these lines under the summary's values and the HTML report
beside them (:mod:`assur._cli_summary`, :mod:`assur.html._sections`).
"""

from __future__ import annotations

import math

from assur._loads import compile_loads, driver_steps
from assur._text import spoken
from assur.summary import Summary

__all__ = ["notes", "turning"]

WHOLE = 1e-9
"""Relative slack by which a crank's positions may fall short of whole turns."""
COARSE = 2.0
"""A crank's positions further apart than this (deg) may miss a peak between them:
the four-bar's shaking force at 30 deg steps read 10 % below its largest."""


def turning(summary: Summary) -> list[str]:
    """Return the lines saying which cranks turn clockwise, and what signs mean.

    Torques are counter-clockwise positive: a clockwise crank's driving torque
    is negative, and its largest driving torque is the ``.min``. Empty when no
    crank turns clockwise.
    """
    joints = summary.clockwise
    if not joints:
        return []
    if summary.drivers == 1:
        which, it = "the crank turns", "it"
    elif len(joints) == 1:
        which, it = f"the crank at {joints[0]} turns", "it"
    else:
        which, it = f"the cranks at {spoken(joints)} turn", "them"
    return [
        f"{which} clockwise and torques are counter-clockwise positive:",
        f"a torque that drives {it} is negative; a positive power is work the",
        "drivers supply",
    ]


def notes(summary: Summary) -> list[str]:
    """Return what a reader of the summary's numbers must know, one line each.

    What the means are over where it is not plain (a varying driver speed: over
    time), a crank's sweep short of a whole turn (means and efficiency are not
    a cycle's), one too coarse to be sure of its peaks, and the load tables'
    steps it did not count half on each side.
    """
    out = []
    over, why = summary.means_over()
    if why:
        out.append(f"means and RMS values are over {over} ({why})")
    covered = summary.covered()
    if covered is not None and summary.count > 1:
        turns = covered / 360.0
        # a span beyond the largest float (positions near it) is no whole turns
        if (
            not math.isfinite(turns)
            or turns < 1.0 - WHOLE
            or abs(turns - round(turns)) > WHOLE * turns
        ):
            first, last = summary.span() or (0.0, 0.0)
            out.append(
                f"positions from {first:g} to {last:g} deg, not whole turns: means, "
                "RMS and efficiency are of these positions, not of a cycle"
            )
        step = summary.spacing
        if step > COARSE:
            out.append(
                f"positions {step:.3g} deg apart: the largest values are those at "
                "these positions, and a finer sweep may find larger ones between them"
            )
    return out + _idle(summary) + _turned(summary) + _steps(summary)


def _turned(summary: Summary) -> list[str]:
    """Return how to read a peak's position (deg) that lies outside 0 to 360.

    A turn from a reference pose at 60 deg runs from 60 to 419 deg, as the table's
    angles do, and the peaks' positions are the table's: 375 deg read as a fault to
    an engineer looking for 15 deg on the crank.
    """
    if summary.variants != 1 or not summary.count:
        return []
    beyond = [
        value
        for key, value in summary.result().items()
        if key.endswith(".at")
        and summary.units.get(key) == "deg"
        and math.isfinite(value)
        and not 0.0 <= value < 360.0
    ]
    if not beyond:
        return []
    first = beyond[0]
    within = first % 360.0
    return [
        "positions (.at) are the table's, which run on from the reference pose: "
        f"{first:g} deg is the crank at {within:g} deg"
    ]


def _idle(summary: Summary) -> list[str]:
    """Return why the efficiency is 0 where it is: no load takes work over the cycle.

    A mechanism loaded by its inertia alone gives back over a cycle all the work
    its inertia takes: the driver's work goes to friction, and a bare 0 read as a
    fault.
    """
    if summary.variants != 1 or not summary.count:
        return []
    values = summary.result()
    if values.get("efficiency") != 0.0:
        return []
    return [
        "efficiency 0: the loads take no work over the cycle "
        "(driver.power_ideal.mean is 0), so all the driver's work goes to friction"
    ]


def _steps(summary: Summary) -> list[str]:
    """Return what is to be said of the load tables' steps the sweep crossed.

    A step a position landed on counts half on each side (the trapezoid rule); one
    between two positions is counted by the positions around it, as any value is,
    and a table of a few columns counts the one it landed on on one side.
    """
    span = summary.span()
    if summary.plan is None or span is None or summary.variants != 1:
        return []
    turning = summary.plan.drivers[0].kind == "R"
    unit = "deg" if turning else "m"
    lo = min(span)
    # the sweep's reach: a step on a turn's end is met a step past the last
    reach = summary.covered() if turning else None
    hi = lo + reach if reach is not None else max(span)
    missed: dict[str, list[float]] = {}
    for entry, _, jumps in driver_steps(compile_loads(summary.plan), summary.plan):
        for s in jumps.tolist():
            if turning:
                # the step is met where the sweep passes it, a whole turn apart
                crossed = s + 360.0 * math.ceil((lo - s) / 360.0) < hi
            else:
                crossed = lo <= s <= hi
            if crossed and (entry, s) not in summary.landed:
                missed.setdefault(entry, []).append(s)
    out = [
        f"{entry} steps at {spoken([f'{s:g}' for s in steps])} {unit}, between the "
        "positions analysed: means there are right only to first order in their "
        "spacing; a position on each step counts it half on each side"
        for entry, steps in missed.items()
    ]
    if summary.one_sided:
        out.append(
            "a table of a few columns (columns=) counts a load table's step on the "
            "side after it: a full table counts it half on each side"
        )
    return out
