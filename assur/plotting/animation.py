"""An animated GIF of a sweep, one frame per row of a table.

Every frame has the same limits, layout and force scale, so that the mechanism and
its arrows can be compared from frame to frame.
"""

from __future__ import annotations

import math
from os import PathLike
from typing import TYPE_CHECKING, Any

import numpy as np

from assur._output import output_path
from assur._progress import Callback
from assur._progress import progress as shown
from assur._text import describe
from assur._vec import real
from assur.errors import UsageError
from assur.plotting._axes import _handles
from assur.plotting._bars import label_box, root_figure
from assur.plotting._context import _Context, _context, _need_forces
from assur.plotting._forces import _overview_arrows, _scale
from assur.plotting._geometry import _extent
from assur.plotting.mechanism import _draw_row

if TYPE_CHECKING:
    from assur.analysis import Table

__all__ = ["animate"]

WIDTH = 6.0
"""Width of the drawing in every frame, in."""
HEIGHTS = (2.0, 6.0)
"""Least and most height of the drawing in a frame, in (it follows the sweep's
shape between them)."""
MARGINS = (1.1, 0.95)
"""A frame's width and height beyond the drawing and its legend, in: the axes'
numbers and names, the title."""
BELOW = 0.55
"""Room below the drawing for the axis' numbers and name, in."""
LEGEND_FONT = 8.0
"""Size of the legend's text, points (as the still pictures'): it is read at a
film's low resolution."""
LEGEND_COLUMNS = 2
"""Columns of the legend below the drawing: beside it, it took a third of a frame."""
LEGEND_CHARACTERS = 60
"""Longest entry of a film's legend, characters; a longer one is cut with "…"."""
LEGEND_SMALLEST = 5.0
"""Smallest size the legend's text is made to fit a frame's width, points."""
LEGEND_ROW = 1.6 * LEGEND_FONT / 72.0
"""Height of a row of the legend, in (its text and the space between rows)."""
LEGEND_ROWS = 6
"""Rows of the legend that the largest frame holds room for (twelve entries)."""
LARGEST_FRAME = (WIDTH + MARGINS[0], HEIGHTS[1] + MARGINS[1] + LEGEND_ROWS * LEGEND_ROW)
"""Size of the largest frame, in: the most a film's frame takes at a resolution."""
INSIDE = 2.0
"""Room kept between a label and the axes' frame, pixels."""
MOST_FPS = 50.0
"""Fastest frame rate, frames per second: a GIF's delays are whole hundredths of a
second, and browsers play a delay of 1 or less as 10 (a film at 60 played at 10)."""
FILM_BYTES = 2 * 1024**3
"""Most bytes of frames a film may hold: the GIF writer keeps every frame, in RGBA,
until the last is drawn (1000 frames at 300 dpi would take 20 GB)."""


def frame_bytes(dpi: float) -> int:
    """Return the bytes of the largest frame at ``dpi`` dots per inch, in RGBA.

    Examples
    --------
    >>> frame_bytes(80)
    1456352
    """
    width, height = (round(side * dpi) for side in LARGEST_FRAME)
    return 4 * width * height


def animate(
    table: Table,
    path: Any,
    forces: bool = False,
    fps: float = 20,
    dpi: float = 80,
    progress: bool | Callback = False,
) -> int:
    """Write an animated GIF of the sweep, one frame per row of ``table``.

    Parameters
    ----------
    table : Table
    path : str or path-like
        The GIF file to write.
    forces : bool
        Draw the joint reactions and the other loads too, at one scale for the whole
        sweep (needs a forces table).
    fps : float
        Frames per second.
    dpi : float
        Resolution of the frames, dots per inch (the drawing is 6 inches wide).
    progress : bool or callable
        Show a progress bar on standard error (True), or call ``progress(done,
        total)`` after each frame.

    Returns
    -------
    int
        The number of frames written.

    Raises
    ------
    UsageError
        For a ``path`` that is not a file's path, ``fps`` or ``dpi`` not above 0,
        ``fps`` above 50, or frames that would take more than 2 GiB of memory.
    OutputError
        When the file cannot be written (it is written whole or not at all).
    """
    import matplotlib.pyplot as plt
    from matplotlib.animation import PillowWriter

    if not isinstance(path, str | PathLike):
        msg = f"path: expected the GIF file's path, got {type(path).__name__}"
        raise UsageError(msg)
    fps, dpi = _above_zero("fps", fps), _above_zero("dpi", dpi)
    if fps > MOST_FPS:
        msg = (
            f"fps: {fps:g}; expected at most {MOST_FPS:g} (a GIF's delays are whole "
            "hundredths of a second, and browsers play 1 or less as 10)"
        )
        raise UsageError(msg)
    film = len(table) * frame_bytes(dpi)
    if film > FILM_BYTES:
        # the writer keeps every frame until the last: the system killed the work
        msg = (
            f"table: {len(table)} frames of up to {frame_bytes(dpi) / 1e6:.3g} MB, "
            f"{film / 1e9:.3g} GB in all, kept in memory until the last is drawn; "
            f"expected at most {FILM_BYTES / 1024**3:g} GiB of frames (fewer rows, "
            "or a lower dpi)"
        )
        raise UsageError(msg)
    if forces:
        _need_forces(table, "animate(forces=True)")
    ctx = _context(table)
    corners, scale = _film_limits(ctx, forces)
    fig, ax = plt.subplots()
    try:
        # the legend's entries, for its room: drawn again as the first frame
        entries = _draw_row(ax, ctx, 0, forces, scale, True, True, corners, False)
        _film_layout(fig, ctx, corners, entries)
        # matplotlib's stubs say int, but the writer only uses 1000 / fps
        writer = PillowWriter(fps=fps)  # type: ignore[arg-type]
        with (
            output_path(path, any_error=True) as temporary,
            shown("animate", len(table), progress) as bar,
        ):
            # not writer.saving: its finish, run when a stop (Ctrl-C) cuts the film
            # short, would fail on no frames and hide the stop
            writer.setup(fig, str(temporary), dpi)
            for r in range(len(table)):
                _wipe(ax)
                _draw_row(ax, ctx, r, forces, scale, True, True, corners, False)
                keep_inside(ax)
                writer.grab_frame()
                bar.advance(1)
            writer.finish()
    finally:
        plt.close(fig)
    return len(table)


def _wipe(ax: Any) -> None:
    """Remove what a frame drew on ``ax``: its lines, shapes, texts and images.

    Not ``ax.clear()``: that also drops the axes' ticks, which matplotlib then made
    anew for every frame, a fifth of a film's time. The limits, labels and title
    are set again by every frame.
    """
    drawn = (ax.lines, ax.patches, ax.texts, ax.collections, ax.images, ax.artists)
    for artist in [a for kind in drawn for a in kind]:
        artist.remove()


def _above_zero(name: str, value: Any) -> float:
    """Return ``value`` as a finite number above 0; a UsageError naming it if not."""
    number = real(value)
    if number is None or not (math.isfinite(number) and number > 0.0):
        msg = f"{name}: expected a number above 0, got {describe(value)}"
        raise UsageError(msg)
    return number


def _film_limits(ctx: _Context, forces: bool) -> tuple[list[Any], float | None]:
    """Corners of a frame that holds every row (m) and the force scale (N per cm)."""
    rows = range(len(ctx.table))
    limits = [p for r in rows for p in _extent(ctx, ctx.pose(r))]
    scale = None
    if forces:
        # one scale and one frame for the whole film, so arrows compare across frames
        arrows = [a for r in rows for a in _overview_arrows(ctx, ctx.pose(r), r)]
        scale = _scale(arrows, ctx.size)
        limits += [
            a.at + a.force / (scale * 100.0) for a in arrows if a.force is not None
        ]
    return [np.nanmin(limits, axis=0), np.nanmax(limits, axis=0)], scale


def _film_layout(
    fig: Any, ctx: _Context, corners: list[Any], entries: list[tuple[str, str]]
) -> None:
    """Size ``fig`` to the drawing, set its axes and put the legend of ``entries``.

    The axes must not jump between frames, so their place is set by hand; the
    legend, one for the whole film, goes below them, outside the axes redrawn.
    """
    # an entry naming a group's long links (171 characters) would not fit a column
    # at any size: it is cut, the frame showing the links themselves
    entries = [
        (
            text
            if len(text) <= LEGEND_CHARACTERS
            else f"{text[: LEGEND_CHARACTERS - 1]}…",
            c,
        )
        for text, c in entries
    ]
    span = corners[1] - corners[0] + 0.2 * max(ctx.size, *(corners[1] - corners[0]))
    height = float(np.clip(WIDTH * span[1] / span[0], *HEIGHTS))
    # at most LEGEND_ROWS rows, the frame's size bound counts no more (a mechanism
    # of many groups takes more columns instead)
    columns = max(LEGEND_COLUMNS, math.ceil(len(entries) / LEGEND_ROWS))
    legend = math.ceil(len(entries) / columns) * LEGEND_ROW
    size = (WIDTH + MARGINS[0], height + MARGINS[1] + legend)
    fig.set_size_inches(size)
    fig.subplots_adjust(
        left=0.8 / size[0],
        right=(0.8 + WIDTH) / size[0],
        bottom=(BELOW + legend) / size[1],
        top=1.0 - 0.4 / size[1],
    )
    font = LEGEND_FONT
    while entries:
        shown = fig.legend(
            handles=_handles(entries),
            loc="lower center",
            ncols=columns,
            fontsize=font,
            bbox_to_anchor=((0.8 + WIDTH / 2) / size[0], 0.05 / size[1]),
            frameon=False,
            borderpad=0.0,
            columnspacing=1.5,
            handlelength=1.5,
        )
        # long names make a legend wider than the frame, which crops it: its
        # text is made smaller until it fits (down to LEGEND_SMALLEST)
        wide = shown.get_window_extent(fig.canvas.get_renderer()).width
        room = size[0] * fig.dpi
        if wide <= room or font <= LEGEND_SMALLEST:
            break
        shown.remove()
        font = max(LEGEND_SMALLEST, font * room / wide * 0.98)


def keep_inside(ax: Any) -> None:
    """Move every label of ``ax`` that runs past its frame back inside it.

    A film's limits hold the links and arrows of every frame, not their labels:
    a label beside an arrow at the edge was cut there. Each is moved, in
    display units, by just what runs out (and :data:`INSIDE` more).
    """
    from assur.plotting._placing import _put

    renderer = root_figure(ax).canvas.get_renderer()
    ax.apply_aspect()  # the equal-aspect axes shrink to their place when drawn
    frame = ax.get_window_extent(renderer).extents + INSIDE * np.array([1, 1, -1, -1])
    for text in ax.texts:
        if not (text.get_visible() and text.get_text()):
            continue
        box = label_box(text, renderer)
        shift = np.maximum(frame[:2] - box[:2], 0) - np.maximum(box[2:] - frame[2:], 0)
        if shift.any():
            # _put centres the text: from the middle of its box, moved
            _put(ax, text, (box[:2] + box[2:]) / 2 + shift)
