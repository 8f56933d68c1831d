"""What is said with a summary: which sign drives, what its means are over.

The command line prints these lines under the summary's values and the HTML report
beside them (:mod:`assur._cli_summary`, :mod:`assur.html._sections`).
"""

from __future__ import annotations

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
        which, it = f"the cranks at {', '.join(joints)} turn", "them"
    return [
        f"{which} clockwise and torques are counter-clockwise positive:",
        f"a torque that drives {it} is negative; a positive power is work the",
        "drivers supply",
    ]


def notes(summary: Summary) -> list[str]:
    """Return what a reader of the summary's numbers must know, one line each.

    What the means are over where it is not plain (a varying crank speed: over
    time), a crank's sweep short of a whole turn (means and efficiency are not
    a cycle's) and one too coarse to be sure of its peaks.
    """
    out = []
    over, why = summary.means_over()
    if why:
        out.append(f"means and RMS values are over {over}: {why}")
    covered = summary.covered()
    if covered is not None and summary.count > 1:
        turns = covered / 360.0
        if turns < 1.0 - WHOLE or abs(turns - round(turns)) > WHOLE * turns:
            out.append(
                f"the positions cover {covered:.6g} deg, not whole turns: means, RMS "
                "and efficiency are of these positions, not of a cycle"
            )
        step = covered / summary.count if not summary.closes() else None
        if step is None:
            step = covered / (summary.count - 1)
        if step > COARSE:
            out.append(
                f"positions {step:.3g} deg apart: the largest values are those at "
                "these positions, and a finer sweep may find larger ones between them"
            )
    return out
