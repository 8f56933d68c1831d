"""The picture commands' files: pyplot on Agg, and each picture written whole.

Resolutions and suffixes checked, every figure closed, a folder's stale files of a
command removed, and what was written said.
"""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from assur._cli_common import (
    OTHER_SUFFIXES,
    check_not_input,
    check_range,
    folder_there,
    is_stdout,
    quiet,
    terminal,
)
from assur._output import output_path, path_text
from assur._targets import missing_folder
from assur._text import describe, spoken
from assur.errors import OutputError, UsageError

PICTURE_SUFFIXES = (".png", ".svg", ".pdf")
TIMELESS = {"svg": {"Date": None}, "pdf": {"CreationDate": None}}
"""Metadata left out of a vector file: the time it was written, by which the same
picture would differ from run to run."""
DPI = 150
"""Resolution of the PNG pictures, dots per inch."""
DPI_RANGE = (10.0, 1200.0)
"""Resolutions accepted for pictures, dots per inch."""
GIF_DPI_RANGE = (10.0, 300.0)
"""Resolutions accepted for animations, dots per inch (every frame is kept)."""


def _pyplot() -> Any:
    """Return pyplot on the Agg backend: the command line never opens a window."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


@contextlib.contextmanager
def _figures() -> Iterator[Any]:
    """Yield pyplot on Agg; close every figure opened inside on the way out.

    Inside, text is set without LaTeX whatever the user's matplotlibrc says: the
    pictures' text is matplotlib's own mathtext, and ``text.usetex`` needs a LaTeX
    the machine may not have (it failed with a traceback from inside a drawing).
    The fonts installed for names in CJK scripts follow the user's own
    (:func:`assur._fonts.fallback_fonts`).
    """
    import matplotlib

    from assur._fonts import fallback_fonts

    plt = _pyplot()
    before = set(plt.get_fignums())
    try:
        with matplotlib.rc_context({"text.usetex": False, **fallback_fonts()}):
            yield plt
    finally:
        for number in set(plt.get_fignums()) - before:
            plt.close(number)


def _output(args: argparse.Namespace, allowed: tuple[str, ...]) -> Path:
    """Return ``-o``, checked: a known suffix and not the mechanism file."""
    path: Path = args.output
    suffix = path.suffix.lower()
    wanted = spoken(allowed, "or")
    if is_stdout(path):
        # "-" is standard output for tables and notes: here it had no suffix
        what = {".gif": "an animation", ".html": "a report"}.get(allowed[0])
        msg = (
            f"-o {path_text(path)}: standard output cannot take "
            f"{what or 'a picture'}; expected a file name ending in {wanted}"
        )
        raise UsageError(msg)
    if path.is_dir():
        msg = (
            f"-o {path_text(path)}: is a folder; expected a file name ending in "
            f"{wanted}"
        )
        raise UsageError(msg)
    if suffix not in allowed:
        # "-o film" (or "-o .gif", a hidden name) said "unknown file type '(none)'"
        what = f"unknown file type {describe(suffix)}" if suffix else "no suffix"
        msg = f"-o {path_text(path)}: {what}; expected {wanted}"
        raise UsageError(msg)
    check_not_input("-o", path, args.file)
    folder_there(path)
    return path


def _draw(fig: Any, path: Path, dpi: float) -> None:
    """Write ``fig`` to ``path`` in the format of its suffix and close it."""
    try:
        _write(fig, path, dpi, path.suffix[1:].lower())
    finally:
        _pyplot().close(fig)


def _write(fig: Any, path: Any, dpi: float, form: str) -> None:
    """Write ``fig`` to ``path`` as ``form``, cropped to what it shows.

    As ``savefig(bbox_inches="tight")`` writes it, with one layout fewer for a
    PNG: savefig draws a figure with a layout engine once, unpainted, to lay it
    out and crop it before it paints it, and walking every artist was half that
    draw; the engine alone (as Agg at the file's resolution, as savefig does)
    places the axes the same. A vector file is laid out as its backend measures
    text, so it is left to savefig.
    """
    import matplotlib as mpl

    from assur.plotting._bars import lay_out

    engine = fig.get_layout_engine()
    measured = hasattr(fig.canvas, "get_renderer")  # pyplot's Agg canvas
    if form != "png" or engine is None or not fig.axes or not measured:
        _saved(fig, path, dpi, "tight", form)
        return
    shown = fig.dpi
    try:
        fig.dpi = dpi
        lay_out(fig, engine)
        pad = mpl.rcParams["savefig.pad_inches"]
        box = fig.get_tightbbox(fig.canvas.get_renderer()).padded(pad)
        # no engine, whatever the rc says (figure.autolayout would set a fresh one
        # that lays the figure out again after the box was taken)
        with mpl.rc_context(
            {"figure.autolayout": False, "figure.constrained_layout.use": False}
        ):
            fig.set_layout_engine(None)
    finally:
        fig.dpi = shown
    try:
        _saved(fig, path, dpi, box, form)
    finally:
        fig.set_layout_engine(engine)


def _saved(fig: Any, path: Any, dpi: float, box: Any, form: str) -> None:
    """Write ``fig`` to ``path``: the same bytes for the same picture, every run."""
    import matplotlib as mpl

    # an SVG's clip paths are named from a salt, random unless set
    with mpl.rc_context({"svg.hashsalt": "assur"}):
        metadata = TIMELESS.get(form)
        fig.savefig(path, dpi=dpi, bbox_inches=box, format=form, metadata=metadata)


def _save(fig: Any, path: Path, dpi: float) -> None:
    """Write ``fig`` to ``path``, whole or not at all, and close it."""
    try:
        with output_path(path, any_error=True) as temporary:
            _draw(fig, temporary, dpi)
    finally:
        _pyplot().close(fig)


def _clear_stale(out: Path, written: list[str], ours: list[str]) -> None:
    """Remove the files of ``ours`` in ``out`` that this run did not write.

    A folder written before keeps its other files; the command's own, left from
    another mechanism (its force polygons, its levers), would mix with the new set.
    """
    for name in set(ours) - set(written):
        with contextlib.suppress(FileNotFoundError):
            (out / name).unlink()


def _folder(out: Path, what: str) -> Path:
    """Return ``-o``'s folder for ``what``; a file of that name is a UsageError."""
    if str(out) == "-":
        msg = (
            f"-o -: standard output cannot take a folder of {what}; expected a "
            "folder's name"
        )
        raise UsageError(msg)
    if out.exists() and not out.is_dir():
        msg = f"-o {path_text(out)}: is a file; expected a folder for the {what}"
        raise UsageError(msg)
    if not out.is_dir() and out.suffix.lower() in OTHER_SUFFIXES:
        # -o x.png made a folder named x.png: a picture's name, surely
        msg = (
            f"-o {path_text(out)}: a {out.suffix} file's name; expected a folder for "
            f"the {what}"
        )
        raise UsageError(msg)
    fault = None if out.is_dir() else missing_folder(out)
    if fault is not None:
        # only the last folder is made: a misspelt parent made a whole new tree
        msg = (
            f"{path_text(out)}: cannot make the folder ({fault}: "
            f"{path_text(out.parent)}); expected a folder in an existing one"
        )
        raise OutputError(msg)
    return out


def _check_dpi(args: argparse.Namespace, bounds: tuple[float, float]) -> float:
    return check_range(
        "--dpi", args.dpi, *bounds, "a positive resolution", "dots per inch"
    )


def _show(args: argparse.Namespace) -> bool:
    """Whether to show progress bars: on a terminal, without ``--quiet``."""
    return terminal() and not quiet(args)


def _wrote(args: argparse.Namespace, text: str) -> None:
    """Say what was written, unless ``--quiet``."""
    if not quiet(args):
        print(f"wrote {text}")
