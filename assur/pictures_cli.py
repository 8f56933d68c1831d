"""Command line for pictures: ``assur plot|diagrams|animate|plans|report``.

:mod:`assur.cli` calls :func:`register` to add these commands. Each handler reads the
mechanism file, runs the analysis and writes pictures with matplotlib's Agg backend,
closing every figure it opens; bad input raises an :class:`~assur.errors.AssurError`
that the command line prints as one line. Every picture is written whole or not at
all (:mod:`assur._output`), the diagrams as one set.
Its parts: the files (``assur._picture_files``), the sweeps drawn
(``assur._picture_sweeps``), ``assur plans`` (``assur._picture_plans``) and
``assur animate`` (``assur._picture_animate``).
"""

from __future__ import annotations

import argparse
import contextlib
import math
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from assur._cli_common import (
    add_angle_option,
    check_not_input,
    load_mechanism,
    one_position,
    positions,
)
from assur._cli_types import (
    ANGLES_HELP,
    add_file_argument,
    file_name,
    folder,
    number,
    whole_number,
)
from assur._output import output_folder, path_text
from assur._picture_animate import FPS_RANGE, FRAMES_RANGE, _cmd_animate
from assur._picture_files import (
    DPI,
    DPI_RANGE,
    GIF_DPI_RANGE,
    PICTURE_SUFFIXES,
    _check_dpi,
    _clear_stale,
    _draw,
    _figures,
    _folder,
    _output,
    _save,
    _show,
    _wrote,
)
from assur._picture_panels import motion_figure, slides_figure
from assur._picture_plans import PLANS as PLANS  # still assur.pictures_cli.PLANS
from assur._picture_plans import _cmd_plans
from assur._picture_sweeps import (
    _drawn,
    _kept,
    _say_skipped,
    _skip_option,
    _sweep,
    _table,
)
from assur._text import counted
from assur._warn import warn
from assur.errors import AssurError, AssurWarning, UsageError

__all__ = ["register"]

DIAGRAMS = (
    "motion",
    "slides",
    "paths",
    "decomposition",
    "torque",
    "hodographs",
    "shaking",
    "dynamics",
)
"""Names of the diagrams (PNG files) that ``assur diagrams`` writes."""


def register(sub: Any) -> dict[str, Callable[[argparse.Namespace], int]]:
    """Add the picture commands to the ``sub`` parsers; return their handlers."""
    angles = {"metavar": "START:STOP:STEP", "help": ANGLES_HELP}
    forces = "draw the inertia loads, the joint reactions and the balancing load"
    p = sub.add_parser("plot", help="draw the mechanism at one driver position")
    _common(p, "PICTURE", "picture to write: .png, .svg or .pdf", DPI)
    add_angle_option(p)
    p.add_argument("--forces", action="store_true", help=forces)
    p.add_argument(
        "--scale",
        type=number,
        metavar="NPERCM",
        help="force scale, newtons per cm on the axes (with --forces or --group; "
        "default: a round one, the largest force about a quarter of the "
        "mechanism's size)",
    )
    p.add_argument(
        "--group",
        type=whole_number,
        metavar="N",
        help="draw the free-body diagram of Assur group N (1: the first attached)",
    )
    p.add_argument(
        "--no-labels",
        action="store_true",
        help="leave out the names of the joints, links and forces, and their values",
    )
    p = sub.add_parser("diagrams", help="write PNG diagrams over a sweep to a folder")
    _common(
        p,
        "FOLDER",
        "folder for motion.png, paths.png, decomposition.png; with prismatic "
        "pairs, slides.png; with masses or loads, torque.png, hodographs.png, "
        "shaking.png; with masses and one crank, dynamics.png",
        DPI,
    )
    p.add_argument("--angles", **angles)
    _skip_option(p)
    p = sub.add_parser("animate", help="write an animated GIF of the sweep")
    _common(p, "GIF", "GIF file to write", 80.0, GIF_DPI_RANGE)
    p.add_argument("--angles", **angles)
    _skip_option(p)
    p.add_argument(
        "--frames",
        type=whole_number,
        default=72,
        metavar="N",
        help="at most N frames, evenly spread over the sweep (a whole turn's end "
        "not repeated; default 72, "
        f"{FRAMES_RANGE[0]} to {FRAMES_RANGE[1]}; at most 2 GiB of frames at --dpi)",
    )
    p.add_argument(
        "--fps",
        type=number,
        default=20.0,
        help=f"frames per second (default 20, {FPS_RANGE[0]:g} to {FPS_RANGE[1]:g}: "
        "faster GIFs play slower in browsers)",
    )
    p.add_argument("--forces", action="store_true", help=forces)
    p = sub.add_parser(
        "plans", help="velocity, acceleration and force plans, lever, instant centres"
    )
    _common(p, "FOLDER", "folder for the plans, each as PNG and SVG", DPI)
    add_angle_option(p)
    p = sub.add_parser("report", help="write an HTML report of the analysis")
    _common(p, "HTML", "HTML file to write")
    p.add_argument("--angles", **angles)
    return {
        "plot": _cmd_plot,
        "diagrams": _cmd_diagrams,
        "animate": _cmd_animate,
        "report": _cmd_report,
        "plans": _cmd_plans,
    }


def _common(
    p: argparse.ArgumentParser,
    metavar: str,
    text: str,
    dpi: float | None = None,
    dpi_range: tuple[float, float] = DPI_RANGE,
) -> None:
    add_file_argument(p)
    # a file's name written as a folder's ("x.svg/") would lose its slash in a Path
    kind = folder if metavar == "FOLDER" else file_name
    p.add_argument(
        "-o", "--output", type=kind, required=True, metavar=metavar, help=text
    )
    if dpi is not None:
        p.add_argument(
            "--dpi",
            type=number,
            default=dpi,
            help=f"resolution, dots per inch (default {dpi:g}, {dpi_range[0]:g} to "
            f"{dpi_range[1]:g})",
        )


def _cmd_plot(args: argparse.Namespace) -> int:
    from assur.plan import plan_of
    from assur.plotting import draw, draw_free_body

    output = _output(args, PICTURE_SUFFIXES)
    dpi = _check_dpi(args, DPI_RANGE)
    if args.scale is not None and not 0 < args.scale < math.inf:
        msg = f"--scale {args.scale:g}: expected a positive number of newtons per cm"
        raise UsageError(msg)
    if args.scale is not None and not (args.forces or args.group is not None):
        # nothing would be drawn to it: the option was silently ignored
        msg = (
            f"--scale {args.scale:g}: a force scale, for --forces or --group; "
            "expected one of them with it"
        )
        raise UsageError(msg)
    mech = load_mechanism(args.file)
    # one position, as the rows of a sweep of one
    position = one_position(mech, args.angle)[np.newaxis]
    if args.group is not None:
        count = len(plan_of(mech).groups)
        if not 1 <= args.group <= count:
            expected = (
                f"expected 1 to {count}"
                if count > 1
                else "expected --group 1"  # not "1 to 1"
                if count
                else "expected no --group: only its input link moves"
            )
            msg = (
                f"--group {args.group}: the mechanism has "
                f"{counted(count, 'Assur group')}; " + expected
            )
            raise UsageError(msg)
        table = _table(mech, position, True)
        with _figures(), _scale_option(args.scale):
            # its own figure: a flat group's is made lower (plotting._axes.fit_height)
            ax = draw_free_body(
                table, args.group - 1, scale=args.scale, labels=not args.no_labels
            )
            _save(ax.figure, output, dpi)
        _wrote(args, path_text(output))
        return 0
    table = _table(mech, position, args.forces)
    with _figures() as plt, _scale_option(args.scale):
        fig, ax = plt.subplots(figsize=(9.0, 6.0), layout="constrained")
        draw(
            table,
            ax=ax,
            forces=args.forces,
            scale=args.scale,
            labels=not args.no_labels,
        )
        _save(fig, output, dpi)
    _wrote(args, path_text(output))
    return 0


@contextlib.contextmanager
def _scale_option(scale: float | None) -> Iterator[None]:
    """Spell a force scale that draws the forces far too long as ``--scale``."""
    from assur.plotting._context import ScaleError

    try:
        yield
    except ScaleError as err:
        msg = f"--scale {scale:g}: {err.reason}"
        raise UsageError(msg) from None


def _cmd_diagrams(args: argparse.Namespace) -> int:
    from assur import plotting

    dpi = _check_dpi(args, DPI_RANGE)
    out = _folder(args.output, "diagrams")
    for name in DIAGRAMS:
        check_not_input("-o", out / f"{name}.png", args.file)
    _, table = _sweep(args, None)
    with _figures() as plt, output_folder(out, any_error=True) as folder:
        written = _diagrams(plotting, plt, table, folder, dpi, _show(args))
    _clear_stale(out, written, [f"{name}.png" for name in DIAGRAMS])
    _say_skipped(args, table.skipped, table.plan)
    for name in written:
        _wrote(args, path_text(out / name))
    return 0


def _diagrams(
    plotting: Any,
    plt: Any,
    table: Any,
    out: Path,
    dpi: float,
    show: bool = False,
) -> list[str]:
    """Write the set of diagrams of ``table`` to the folder ``out``; name them.

    ``show``: a progress bar of the pictures on standard error.
    """
    from assur._progress import BAR_DELAY, progress

    figures = {"motion": lambda: motion_figure(plotting, plt, table)}
    sliding = [j.name for j in table.mechanism.joints if j.kind == "prismatic"]
    if sliding:
        figures["slides"] = lambda: slides_figure(plotting, plt, table, sliding)
    figures |= {
        "paths": lambda: plotting.plot_paths(table).figure,
        "decomposition": lambda: plotting.draw_decomposition(table),
    }
    if table.force_state is not None:
        figures |= {
            "torque": lambda: plotting.plot_torque(table).figure,
            "hodographs": lambda: plotting.plot_hodographs(table),
            "shaking": lambda: plotting.plot_shaking(table),
        }
    steady = _steady(table)
    if steady is not None:
        figures["dynamics"] = lambda: plotting.plot_dynamics(steady)
    written = []
    with progress("diagrams", len(figures), show, BAR_DELAY, " figures") as bar:
        for name, make in figures.items():
            _draw(make(), out / f"{name}.png", dpi)
            written.append(f"{name}.png")
            bar.advance(1)
    return written


def _steady(table: Any) -> Any:
    """Return the steady state to draw in dynamics.png, or None.

    None without masses or a crank; a crank that cannot turn round is warned of.
    """
    from assur.dynamics_shown import has_dynamics, shown

    mech = table.mechanism
    if table.force_state is None or not has_dynamics(mech):
        return None
    try:
        return shown(mech, table["angle"])
    except AssurError as err:
        warn(f"no dynamics.png: {err}", AssurWarning, stacklevel=2)
        return None


def _cmd_report(args: argparse.Namespace) -> int:
    output = _output(args, (".html", ".htm"))
    try:
        from assur.html import write_report
    except ImportError as err:
        msg = (
            "report: the HTML report (assur.html) is not available in this installation"
        )
        raise UsageError(msg) from err
    mech = load_mechanism(args.file)
    sweep = positions(mech, args.angles)  # the default sweep when none is given
    angles = (
        None if args.angles is None else _drawn(sweep, "the page holds every position")
    )
    from assur._progress import BAR_DELAY, progress

    shown = progress("report", len(sweep), _show(args), BAR_DELAY, " positions")
    with _figures(), shown as bar, contextlib.ExitStack() as stack:
        page: list[Any] = []

        def made(done: int, total: int) -> None:
            # the page's parts after the sweep (its free-body diagrams take
            # seconds): a bar of their own, the sweep's gone
            if not page:
                bar.close()
                parts = progress("report page", total, _show(args), BAR_DELAY, " parts")
                page.append(stack.enter_context(parts))
            page[0].advance(done - page[0].done)

        # the sweep's positions (most of the work on a long one), told to the bar
        told = lambda done, _: bar.advance(done - bar.done)  # noqa: E731
        write_report(mech, output, angles, told, made)
    # the page leaves out the positions that cannot be assembled, as
    # --skip-unassembled does elsewhere: said here as there, not on the page alone
    from assur._loads import compile_loads
    from assur.plan import plan_of

    plan = plan_of(mech)
    _, skipped = _kept(mech, sweep, not compile_loads(plan).empty, True)
    _say_skipped(args, skipped, plan)
    _wrote(args, path_text(output))
    return 0
