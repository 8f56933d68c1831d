"""Command line for pictures: ``assur plot|diagrams|animate|plans|report``.

:mod:`assur.cli` calls :func:`register` to add these commands. Each handler reads the
mechanism file, runs the analysis and writes pictures with matplotlib's Agg backend,
closing every figure it opens; bad input raises an :class:`~assur.errors.AssurError`
that the command line prints as one line. Every picture is written whole or not at
all (:mod:`assur._output`), the diagrams as one set.
"""

from __future__ import annotations

import argparse
import contextlib
import math
import re
import sys
import warnings
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from assur._cli_common import (
    add_angle_option,
    check_not_input,
    check_range,
    file_name,
    folder,
    input_file,
    load_mechanism,
    one_position,
    positions,
    quiet,
    terminal,
)
from assur._output import output_folder, output_path, path_text
from assur._text import counted, describe
from assur._troubles import SKIPPED_WHY
from assur.errors import AssemblyError, AssurError, AssurWarning, UsageError
from assur.plotting._style import titled

__all__ = ["register"]

PICTURE_SUFFIXES = (".png", ".svg", ".pdf")
DPI = 150
"""Resolution of the PNG pictures, dots per inch."""
DPI_RANGE = (10.0, 1200.0)
"""Resolutions accepted for pictures, dots per inch."""
GIF_DPI_RANGE = (10.0, 300.0)
"""Resolutions accepted for animations, dots per inch (every frame is kept)."""
FPS_RANGE = (0.1, 100.0)
"""Frame rates accepted, frames per second (a GIF counts in hundredths of a second)."""
FRAMES_RANGE = (1, 1000)
"""Numbers of frames accepted in an animation."""
DIAGRAMS = (
    "motion",
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
    angles = {
        "metavar": "START:STOP:STEP",
        "help": "driver positions, deg (m for a "
        "prismatic driver); default: one turn from the reference pose",
    }
    p = sub.add_parser("plot", help="draw the mechanism at one driver position")
    _common(p, "PATH", "picture to write: .png, .svg or .pdf", DPI)
    add_angle_option(p)
    p.add_argument(
        "--forces",
        action="store_true",
        help="draw inertia loads, joint reactions and balancing load",
    )
    p.add_argument("--scale", type=float, metavar="N", help="force scale: N per cm")
    p.add_argument(
        "--group",
        type=int,
        metavar="N",
        help="draw the free-body diagram of Assur group N (1: the first attached)",
    )
    p.add_argument("--no-labels", action="store_true", help="leave out the names")
    p = sub.add_parser("diagrams", help="write PNG diagrams over a sweep to a folder")
    _common(
        p,
        "DIR",
        "folder for motion.png, paths.png, decomposition.png; with masses or "
        "loads, torque.png, hodographs.png, shaking.png; with masses and one "
        "crank, dynamics.png",
        DPI,
    )
    p.add_argument("--angles", **angles)
    _skip_option(p)
    p = sub.add_parser("animate", help="write an animated GIF of the sweep")
    _common(p, "PATH", "GIF file to write", 80.0, GIF_DPI_RANGE)
    p.add_argument("--angles", **angles)
    _skip_option(p)
    p.add_argument(
        "--frames",
        type=int,
        default=72,
        metavar="N",
        help="at most N frames, evenly spread over the sweep (default 72, "
        f"{FRAMES_RANGE[0]} to {FRAMES_RANGE[1]})",
    )
    p.add_argument(
        "--fps",
        type=float,
        default=20.0,
        help=f"frames per second (default 20, {FPS_RANGE[0]:g} to {FPS_RANGE[1]:g})",
    )
    p.add_argument("--forces", action="store_true", help="draw the loads and reactions")
    p = sub.add_parser(
        "plans", help="velocity, acceleration and force plans, lever, instant centres"
    )
    _common(p, "DIR", "folder for the plans, each as PNG and SVG", DPI)
    add_angle_option(p)
    p = sub.add_parser("report", help="write an HTML report of the analysis")
    _common(p, "PATH", "HTML file to write")
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
    p.add_argument("file", type=input_file)
    # a file's name written as a folder's ("x.svg/") would lose its slash in a Path
    kind = folder if metavar == "DIR" else file_name
    p.add_argument(
        "-o", "--output", type=kind, required=True, metavar=metavar, help=text
    )
    if dpi is not None:
        p.add_argument(
            "--dpi",
            type=float,
            default=dpi,
            help=f"resolution, dots per inch (default {dpi:g}, {dpi_range[0]:g} to "
            f"{dpi_range[1]:g})",
        )


def _check_dpi(args: argparse.Namespace, bounds: tuple[float, float]) -> float:
    return check_range(
        "--dpi", args.dpi, *bounds, "a positive resolution", "dots per inch"
    )


def _pyplot() -> Any:
    """Return pyplot on the Agg backend: the command line never opens a window."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


@contextlib.contextmanager
def _figures() -> Iterator[Any]:
    """Yield pyplot on Agg; close every figure opened inside on the way out."""
    plt = _pyplot()
    before = set(plt.get_fignums())
    try:
        yield plt
    finally:
        for number in set(plt.get_fignums()) - before:
            plt.close(number)


def _output(args: argparse.Namespace, allowed: tuple[str, ...]) -> Path:
    """Return ``-o``, checked: a known suffix and not the mechanism file."""
    path: Path = args.output
    suffix = path.suffix.lower()
    if suffix not in allowed:
        wanted = " or ".join(allowed)
        msg = (
            f"-o {path_text(path)}: unknown file type {describe(suffix or '(none)')}; "
            f"expected {wanted}"
        )
        raise UsageError(msg)
    check_not_input("-o", path, args.file)
    return path


def _skip_option(p: argparse.ArgumentParser) -> None:
    """Add ``--skip-unassembled`` to a command drawing a sweep."""
    p.add_argument(
        "--skip-unassembled",
        action="store_true",
        help=f"leave out the positions {SKIPPED_WHY}",
    )


def _kept(mech: Any, positions: Any, forces: bool, skip: bool) -> tuple[Any, Any]:
    """Return the positions of a sweep that can be drawn, shape (n, drivers).

    Also the positions left out (deg, or m).

    One column is kept (memory stays that of the positions); what cannot be
    assembled raises, or with ``skip`` is left out, as a whole table would.
    """
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics
    from assur.columns import balancing_columns
    from assur.plan import plan_of

    if forces:  # friction may lock positions that assemble
        # the balancing loads alone: a torque or a force, as each driver moves
        loads = balancing_columns(plan_of(mech))
        table = force_table(
            mech, positions, skip_unassembled=skip, columns=["angle", *loads]
        )
    else:
        table = kinematics(mech, positions, skip_unassembled=skip, columns=["angle"])
    return _some_kept(table).given, table.skipped


def _table(mech: Any, positions: Any, forces: bool, skip: bool = False) -> Any:
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics

    analyse = force_table if forces else kinematics
    return _some_kept(analyse(mech, positions, skip_unassembled=skip))


def _say_skipped(args: argparse.Namespace, skipped: Any) -> None:
    """Note the positions left out of the sweep (``--skip-unassembled``), if any."""
    from assur._sliced import Skipped

    if len(skipped) and not quiet(args):
        found = Skipped()
        found.add(skipped)
        print(found.note(args.file), file=sys.stderr)


def _some_kept(table: Any) -> Any:
    """Return ``table``; an AssemblyError when every position was left out."""
    if len(table) or not len(table.skipped):
        return table
    msg = (
        f"every position of the sweep is left out ({SKIPPED_WHY}); expected "
        "positions where the mechanism moves"
    )
    raise AssemblyError(msg)


def _draw(fig: Any, path: Path, dpi: float) -> None:
    """Write ``fig`` to ``path`` in the format of its suffix and close it."""
    try:
        fig.savefig(path, dpi=dpi, bbox_inches="tight", format=path.suffix[1:].lower())
    finally:
        _pyplot().close(fig)


def _save(fig: Any, path: Path, dpi: float) -> None:
    """Write ``fig`` to ``path``, whole or not at all, and close it."""
    try:
        with output_path(path, any_error=True) as temporary:
            _draw(fig, temporary, dpi)
    finally:
        _pyplot().close(fig)


def _wrote(args: argparse.Namespace, text: str) -> None:
    """Say what was written, unless ``--quiet``."""
    if not quiet(args):
        print(f"wrote {text}")


def _show(args: argparse.Namespace) -> bool:
    """Whether to show progress bars: on a terminal, without ``--quiet``."""
    return terminal() and not quiet(args)


PLANS = (
    "velocity_plan",
    "acceleration_plan",
    "force_polygons",
    "zhukovsky_lever",
    "instant_centres",
)
"""Names of the plans ``assur plans`` writes (each as .png and .svg), in order, for
one driver; with several, one lever each: ``zhukovsky_lever_1``, ``_2``, ..."""


LEVER = re.compile(r"zhukovsky_lever_[0-9]+\.(png|svg)")
"""The file names of the levers of a mechanism with several drivers."""


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
    if out.exists() and not out.is_dir():
        msg = f"-o {path_text(out)}: is a file; expected a folder for the {what}"
        raise UsageError(msg)
    return out


def _cmd_plans(args: argparse.Namespace) -> int:
    from assur import plotting
    from assur._loads import compile_loads
    from assur.plan import plan_of

    dpi = _check_dpi(args, DPI_RANGE)
    out = _folder(args.output, "plans")
    mech = load_mechanism(args.file)
    angle = one_position(mech, args.angle)
    loaded = not compile_loads(plan_of(mech)).empty
    at = np.asarray(angle, dtype=float).reshape(1, -1)
    t = _table(mech, at if at.shape[1] > 1 else at[:, 0], loaded)
    makers: dict[str, Callable[[], Any]] = {
        "velocity_plan": lambda: plotting.velocity_plan(t).figure,
        "acceleration_plan": lambda: plotting.acceleration_plan(t).figure,
    }
    if loaded:
        if plan_of(mech).groups:  # a crank alone has no group: no polygon to draw
            makers["force_polygons"] = lambda: plotting.force_polygons(t)
        # one lever per driver, numbered in the file's order when there are several
        count = len(mech.drivers)
        for i in range(count):
            lever = "zhukovsky_lever" if count == 1 else f"zhukovsky_lever_{i + 1}"
            makers[lever] = _lever(plotting, t, i)
    elif not quiet(args):
        print(
            f"assur: note: {path_text(args.file)}: no force polygons and no lever: "
            "no link has a mass and no load is applied",
            file=sys.stderr,
        )
    makers["instant_centres"] = lambda: plotting.instant_centres(t).figure
    written = []
    with _figures(), output_folder(out, any_error=True) as folder:
        for name in makers:
            fig = makers[name]()
            for suffix in (".png", ".svg"):
                fig.savefig(folder / f"{name}{suffix}", dpi=dpi, bbox_inches="tight")
                written.append(f"{name}{suffix}")
            _pyplot().close(fig)
    ours = [f"{name}{suffix}" for name in PLANS for suffix in (".png", ".svg")]
    levers = [
        p.name for p in out.glob("zhukovsky_lever_*.*") if LEVER.fullmatch(p.name)
    ]
    _clear_stale(out, written, ours + levers)
    for name in written:
        _wrote(args, path_text(out / name))
    return 0


def _lever(plotting: Any, table: Any, driver: int) -> Callable[[], Any]:
    """Return what draws the lever of driver ``driver`` (its index) of ``table``."""
    return lambda: plotting.zhukovsky_lever(table, driver=driver).figure


def _cmd_plot(args: argparse.Namespace) -> int:
    from assur.plan import plan_of
    from assur.plotting import draw, draw_free_body

    output = _output(args, PICTURE_SUFFIXES)
    dpi = _check_dpi(args, DPI_RANGE)
    if args.scale is not None and not 0 < args.scale < math.inf:
        msg = f"--scale {args.scale:g}: expected a positive number of newtons per cm"
        raise UsageError(msg)
    mech = load_mechanism(args.file)
    # one position, as the rows of a sweep of one
    position = one_position(mech, args.angle)[np.newaxis]
    if args.group is not None:
        count = len(plan_of(mech).groups)
        if not 1 <= args.group <= count:
            expected = (
                f"expected 1 to {count}"
                if count
                else "expected no --group: only its input link moves"
            )
            msg = (
                f"--group {args.group}: the mechanism has "
                f"{counted(count, 'Assur group')}; " + expected
            )
            raise UsageError(msg)
        table = _table(mech, position, True)
        with _figures() as plt:
            fig, ax = plt.subplots(figsize=(9.0, 6.5), layout="constrained")
            draw_free_body(table, args.group - 1, ax=ax, scale=args.scale)
            _save(fig, output, dpi)
        _wrote(args, path_text(output))
        return 0
    table = _table(mech, position, args.forces)
    with _figures() as plt:
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


def _sweep(args: argparse.Namespace, forces: bool | None) -> tuple[Any, Any]:
    """Return the mechanism and its table over ``--angles`` (forces if it has loads)."""
    from assur._loads import compile_loads
    from assur.plan import plan_of

    mech = load_mechanism(args.file)
    loaded = not compile_loads(plan_of(mech)).empty
    return mech, _table(
        mech,
        _drawn(positions(mech, args.angles), "diagrams draw every position"),
        loaded if forces is None else forces,
        getattr(args, "skip_unassembled", False),
    )


DRAWN_MOST = 100_000
"""Most positions of a sweep that diagrams or a report hold whole (every one)."""


def _drawn(sweep: Any, why: str) -> Any:
    """Return ``sweep``; a UsageError when it holds more than :data:`DRAWN_MOST`."""
    if len(sweep) > DRAWN_MOST:
        msg = (
            f"--angles: {len(sweep)} positions; expected at most {DRAWN_MOST} "
            f"({why}; a larger step)"
        )
        raise UsageError(msg)
    return sweep


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
    _say_skipped(args, table.skipped)
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
    from assur._progress import progress

    fig, axes = plt.subplots(
        3, 1, figsize=(8.0, 9.0), sharex=True, layout="constrained"
    )
    for ax, quantity in zip(axes, ("angle", "omega", "alpha"), strict=True):
        plotting.plot_motion(table, quantity=quantity, ax=ax)
        ax.set_title("")
    axes[0].set_title(f"{titled(table.mechanism)}: motion of the links", fontsize=10)
    for ax in axes[:-1]:
        ax.set_xlabel("")
    figures = {
        "motion": lambda: fig,
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
    with progress("diagrams", len(figures), show) as bar:
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
        warnings.warn(f"no dynamics.png: {err}", AssurWarning, stacklevel=2)
        return None


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
        "--fps", args.fps, *FPS_RANGE, "a frame rate", "frames per second"
    )
    mech = load_mechanism(args.file)
    sweep = positions(mech, args.angles)
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
    _say_skipped(args, skipped)
    _wrote(args, f"{path_text(output)} ({count} frames)")
    return 0


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
    angles = (
        None
        if args.angles is None
        else _drawn(positions(mech, args.angles), "the page holds every position")
    )
    with _figures():
        write_report(mech, output, angles=angles)
    _wrote(args, path_text(output))
    return 0
