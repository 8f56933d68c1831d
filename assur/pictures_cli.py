"""Command line for pictures: ``assur plot|diagrams|animate|report``.

:mod:`assur.cli` calls :func:`register` to add these commands. Each handler reads the
mechanism file, runs the analysis and writes pictures with matplotlib's Agg backend,
closing every figure it opens; bad input raises an :class:`~assur.errors.AssurError`
that the command line prints as one line.
"""

from __future__ import annotations

import argparse
import contextlib
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np

from assur.errors import ModelError

__all__ = ["register"]

PICTURE_SUFFIXES = (".png", ".svg", ".pdf")
DPI = 150
"""Resolution of the PNG pictures, dots per inch."""


def register(sub: Any) -> dict[str, Callable[[argparse.Namespace], int]]:
    """Add the picture commands to the ``sub`` parsers; return their handlers."""
    angles = {
        "metavar": "START:STOP:STEP",
        "help": "driver positions, deg (m for a "
        "prismatic driver); default: one turn from the reference pose",
    }
    p = sub.add_parser("plot", help="draw the mechanism at one driver position")
    _common(p, "PATH", "picture to write: .png, .svg or .pdf", DPI)
    p.add_argument(
        "--angle",
        metavar="DEG",
        help="driver position, deg (m for a "
        "prismatic driver; one per driver, separated by commas); default: "
        "the reference pose",
    )
    p.add_argument(
        "--forces",
        action="store_true",
        help="draw inertia loads, joint reactions and balancing load",
    )
    p.add_argument("--scale", type=float, metavar="N", help="force scale: N per cm")
    p.add_argument("--no-labels", action="store_true", help="leave out the names")
    p = sub.add_parser("diagrams", help="write PNG diagrams over a sweep to a folder")
    _common(
        p,
        "DIR",
        "folder for motion.png, paths.png, decomposition.png and, with "
        "masses or loads, torque.png, hodographs.png, shaking.png",
        DPI,
    )
    p.add_argument("--angles", **angles)
    p = sub.add_parser("animate", help="write an animated GIF of the sweep")
    _common(p, "PATH", "GIF file to write", 80.0)
    p.add_argument("--angles", **angles)
    p.add_argument(
        "--frames",
        type=int,
        default=72,
        metavar="N",
        help="at most N frames, evenly spread over the sweep (default 72)",
    )
    p.add_argument(
        "--fps", type=float, default=20.0, help="frames per second (default 20)"
    )
    p.add_argument("--forces", action="store_true", help="draw the loads and reactions")
    p = sub.add_parser("report", help="write an HTML report of the analysis")
    _common(p, "PATH", "HTML file to write")
    p.add_argument("--angles", **angles)
    return {
        "plot": _cmd_plot,
        "diagrams": _cmd_diagrams,
        "animate": _cmd_animate,
        "report": _cmd_report,
    }


def _common(
    p: argparse.ArgumentParser, metavar: str, text: str, dpi: float | None = None
) -> None:
    p.add_argument("file", type=Path)
    p.add_argument(
        "-o", "--output", type=Path, required=True, metavar=metavar, help=text
    )
    if dpi is not None:
        p.add_argument(
            "--dpi",
            type=float,
            default=dpi,
            help=f"resolution, dots per inch (default {dpi:g})",
        )


def _check_dpi(args: argparse.Namespace) -> float:
    if not args.dpi > 0:
        msg = f"--dpi {args.dpi:g}: expected a positive resolution, dots per inch"
        raise ModelError(msg)
    return float(args.dpi)


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


def _suffix(path: Path, allowed: tuple[str, ...]) -> None:
    suffix = path.suffix.lower()
    if suffix not in allowed:
        wanted = " or ".join(allowed)
        msg = f"-o {path}: unknown file type {suffix or '(none)'!r}; expected {wanted}"
        raise ModelError(msg)


def _table(mech: Any, positions: Any, forces: bool) -> Any:
    from assur.analysis import forces as force_table
    from assur.analysis import kinematics

    return force_table(mech, positions) if forces else kinematics(mech, positions)


def _save(fig: Any, path: Path, dpi: float) -> None:
    """Write ``fig`` and close it; a path that cannot be written is bad input."""
    try:
        fig.savefig(path, dpi=dpi, bbox_inches="tight")
    except OSError as err:
        msg = f"-o {path}: cannot write the file ({err.strerror or err})"
        raise ModelError(msg) from err
    finally:
        _pyplot().close(fig)
    print(f"wrote {path}")


def _cmd_plot(args: argparse.Namespace) -> int:
    from assur.analysis import default_positions
    from assur.cli import load_mechanism, parse_angles
    from assur.plotting import draw

    _suffix(args.output, PICTURE_SUFFIXES)
    dpi = _check_dpi(args)
    mech = load_mechanism(args.file)
    drivers = max(1, len(mech.drivers))
    if args.angle is None:
        position = default_positions(mech)[:1]
    else:
        position = parse_angles(args.angle.replace("--angles", "--angle"), drivers)
        if position.shape[0] != 1:
            msg = (
                f"--angle {args.angle}: {position.shape[0]} positions; expected one "
                "value per driver"
            )
            raise ModelError(msg)
    if args.scale is not None and not args.scale > 0:
        msg = f"--scale {args.scale:g}: expected a positive number of newtons per cm"
        raise ModelError(msg)
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
        _save(fig, args.output, dpi)
    return 0


def _sweep(args: argparse.Namespace, forces: bool | None) -> tuple[Any, Any]:
    """Return the mechanism and its table over ``--angles`` (forces if it has loads)."""
    from assur._loads import compile_loads
    from assur.cli import load_mechanism, positions
    from assur.plan import plan_of

    mech = load_mechanism(args.file)
    loaded = not compile_loads(plan_of(mech)).empty
    return mech, _table(
        mech, positions(mech, args.angles), loaded if forces is None else forces
    )


def _cmd_diagrams(args: argparse.Namespace) -> int:
    from assur import plotting

    dpi = _check_dpi(args)
    _, table = _sweep(args, None)
    out: Path = args.output
    if out.exists() and not out.is_dir():
        msg = f"-o {out}: is a file; expected a folder for the diagrams"
        raise ModelError(msg)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        msg = f"-o {out}: cannot create the folder ({err.strerror or err})"
        raise ModelError(msg) from err
    with _figures() as plt:
        _diagrams(plotting, plt, table, out, dpi)
    return 0


def _diagrams(plotting: Any, plt: Any, table: Any, out: Path, dpi: float) -> None:
    """Write the set of diagrams of ``table`` to the folder ``out``."""
    fig, axes = plt.subplots(
        3, 1, figsize=(8.0, 9.0), sharex=True, layout="constrained"
    )
    for ax, quantity in zip(axes, ("angle", "omega", "alpha"), strict=True):
        plotting.plot_motion(table, quantity=quantity, ax=ax)
        ax.set_title("")
    axes[0].set_title(
        f"{table.mechanism.name or 'Mechanism'}: motion of the links", fontsize=10
    )
    for ax in axes[:-1]:
        ax.set_xlabel("")
    _save(fig, out / "motion.png", dpi)
    _save(plotting.plot_paths(table).figure, out / "paths.png", dpi)
    _save(plotting.draw_decomposition(table), out / "decomposition.png", dpi)
    if table.force_state is not None:
        _save(plotting.plot_torque(table).figure, out / "torque.png", dpi)
        _save(plotting.plot_hodographs(table), out / "hodographs.png", dpi)
        _save(plotting.plot_shaking(table), out / "shaking.png", dpi)


def _cmd_animate(args: argparse.Namespace) -> int:
    from assur.cli import load_mechanism, positions
    from assur.plotting import animate

    _suffix(args.output, (".gif",))
    dpi = _check_dpi(args)
    if args.frames < 1 or not args.fps > 0:
        msg = (
            f"--frames {args.frames}, --fps {args.fps:g}: expected at least one frame "
            "and a positive frame rate"
        )
        raise ModelError(msg)
    mech = load_mechanism(args.file)
    sweep = positions(mech, args.angles)
    pick = np.unique(
        np.linspace(0, len(sweep) - 1, min(args.frames, len(sweep))).round().astype(int)
    )
    table = _table(mech, sweep[pick], args.forces)
    try:
        with _figures():
            count = animate(
                table, args.output, forces=args.forces, fps=args.fps, dpi=dpi
            )
    except OSError as err:
        msg = f"-o {args.output}: cannot write the file ({err.strerror or err})"
        raise ModelError(msg) from err
    print(f"wrote {args.output} ({count} frames)")
    return 0


def _cmd_report(args: argparse.Namespace) -> int:
    from assur.cli import load_mechanism, positions

    _suffix(args.output, (".html", ".htm"))
    try:
        from assur.html import write_report
    except ImportError as err:
        msg = (
            "report: the HTML report (assur.html) is not available in this installation"
        )
        raise ModelError(msg) from err
    mech = load_mechanism(args.file)
    angles = None if args.angles is None else positions(mech, args.angles)
    try:
        with _figures():
            write_report(mech, args.output, angles=angles)
    except OSError as err:
        msg = f"-o {args.output}: cannot write the file ({err.strerror or err})"
        raise ModelError(msg) from err
    print(f"wrote {args.output}")
    return 0
