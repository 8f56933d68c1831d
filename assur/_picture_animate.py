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
    pick = np.unique(
        np.linspace(0, len(sweep) - 1, min(args.frames, len(sweep))).round().astype(int)
    )
    table = _table(mech, sweep[pick], args.forces)
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
