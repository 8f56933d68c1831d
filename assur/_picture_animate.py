"""``assur animate``: an animated GIF of the sweep, its film checked first.

The frame rate a GIF can hold and the frames that fit in memory are refused before
anything is analysed; the sweep is then solved whole and the frames spread over it.
"""

from __future__ import annotations

import argparse

import numpy as np

from assur._cli_common import check_range, load_mechanism, positions
from assur._output import path_text
from assur._picture_files import (
    GIF_DPI_RANGE,
    _check_dpi,
    _figures,
    _output,
    _show,
    _wrote,
)
from assur._picture_sweeps import _kept, _say_skipped, _table
from assur._text import counted
from assur.errors import UsageError

__all__ = ["FPS_RANGE", "FRAMES_RANGE", "_cmd_animate"]

FPS_RANGE = (0.1, 50.0)
"""Frame rates accepted, frames per second (to the library's most,
:data:`assur.plotting.animation.MOST_FPS`)."""
FPS_WHY = (
    "(a GIF's delays are whole hundredths of a second, and browsers play 1 or less "
    "as 10)"
)
"""Why the frame rate stops at 50, as ``--fps`` says it."""
FRAMES_RANGE = (1, 1000)
"""Numbers of frames accepted in an animation."""


def _cmd_animate(args: argparse.Namespace) -> int:
    from assur.plan import plan_of
    from assur.plotting import animate

    output = _output(args, (".gif",))
    dpi = _check_dpi(args, GIF_DPI_RANGE)
    if not FRAMES_RANGE[0] <= args.frames <= FRAMES_RANGE[1]:
        msg = (
            f"--frames {args.frames}: expected at least one frame and at most "
            f"{FRAMES_RANGE[1]}"
        )
        raise UsageError(msg)
    fps = check_range(
        "--fps", args.fps, *FPS_RANGE, "a frame rate", f"frames per second {FPS_WHY}"
    )
    mech = load_mechanism(args.file)
    sweep = positions(mech, args.angles)
    _check_film(args.frames, min(args.frames, len(sweep)), dpi)
    # the whole sweep first: what cannot be assembled is counted over it, not the
    # frames, and the frames are spread over the positions kept
    kept, skipped = _kept(mech, sweep, args.forces, args.skip_unassembled)
    sweep = kept[:, 0] if kept.shape[1] == 1 else kept
    drivers = plan_of(mech).drivers
    crank = len(drivers) == 1 and drivers[0].kind == "R" and not len(skipped)
    table = _table(mech, _frames(sweep, args.frames, crank), args.forces)
    with _figures():
        # written whole or not at all by animate itself
        count = animate(
            table,
            output,
            forces=args.forces,
            fps=fps,
            dpi=dpi,
            progress=_show(args),
        )
    _say_skipped(args, skipped, table.plan)
    _wrote(args, f"{path_text(output)} ({counted(count, 'frame')})")
    return 0


TURN_TOLERANCE = 1e-6
"""A sweep spanning 360 degrees within this many degrees is a whole turn."""


def _frames(sweep: np.ndarray, count: int, crank: bool) -> np.ndarray:
    """Return at most ``count`` positions of ``sweep`` for frames, evenly spread.

    ``crank``: one revolute driver, every position of the sweep kept. A sweep of
    one whole turn (0:360:5 with its end, or the default 360 steps without) gets
    frames ``360 / count`` degrees apart from its start, its end not repeated, so
    that the film loops smoothly; spread over indices, 12 frames of the 360 steps
    were 32.6 degrees apart, and 1 degree from the last back to the first.

    Examples
    --------
    >>> _frames(np.arange(45.0, 405.0), 4, True)
    array([ 45., 135., 225., 315.])
    >>> _frames(np.arange(0.0, 361.0, 90.0), 8, True)
    array([  0.,  90., 180., 270.])
    """
    n = len(sweep)
    # in halves: positions near the largest float span more than a float holds
    # (numpy's overflow warning, with its source line); such a sweep is no turn
    half = float(sweep[-1]) / 2 - float(sweep[0]) / 2 if crank and n >= 2 else 0.0
    if crank and n >= 2 and abs(half) <= 360.0:
        span = 2.0 * half
        step = span / (n - 1)
        even = np.allclose(np.diff(sweep), step, rtol=0.0, atol=TURN_TOLERANCE)
        for closing, covered in ((True, span), (False, span + step)):
            if even and abs(abs(covered) - 360.0) <= TURN_TOLERANCE:
                k = min(count, n - closing)
                return sweep[0] + np.copysign(360.0, span) * np.arange(k) / k
    pick = np.linspace(0, n - 1, min(count, n)).round().astype(int)
    return sweep[np.unique(pick)]


def _check_film(asked: int, frames: int, dpi: float) -> None:
    """Refuse ``frames`` (of the ``asked``) that would not fit in :data:`FILM_BYTES`.

    Found before the analysis: a film too large for memory was killed by the
    system, without a word, once its frames were drawn.
    """
    from assur.plotting.animation import FILM_BYTES, frame_bytes

    size = frame_bytes(dpi)
    if frames * size <= FILM_BYTES:
        return
    msg = (
        f"--frames {asked} --dpi {dpi:g}: {frames} frames of up to "
        f"{size / 1e6:.3g} MB, {frames * size / 1e9:.3g} GB in all, kept in memory "
        f"until the last is drawn; expected at most {FILM_BYTES / 1024**3:g} GiB of "
        f"frames: at most {FILM_BYTES // size} frames at --dpi {dpi:g}, or a lower "
        "--dpi"
    )
    raise UsageError(msg)
