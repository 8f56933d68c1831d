"""``assur plans``: the velocity, acceleration and force plans of one position.

With the lever of each driver and the instant centres, each as PNG and SVG in one
folder, and the plans left from another mechanism removed.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._cli_common import load_mechanism, one_position, quiet
from assur._output import output_folder, path_text
from assur._picture_files import (
    DPI_RANGE,
    _check_dpi,
    _clear_stale,
    _figures,
    _folder,
    _pyplot,
    _show,
    _write,
    _wrote,
)
from assur._picture_sweeps import _table
from assur._progress import BAR_DELAY, progress
from assur._stdin import input_text

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
            f"assur: note: {input_text(args.file)}: no force polygons and no lever: "
            "no link has a mass and no load is applied",
            file=sys.stderr,
        )
    makers["instant_centres"] = lambda: plotting.instant_centres(t).figure
    written = []
    shown = progress("plans", len(makers), _show(args), BAR_DELAY, " pictures")
    with _figures(), output_folder(out, any_error=True) as folder, shown as bar:
        for name in makers:
            fig = makers[name]()
            for suffix in (".png", ".svg"):
                _write(fig, folder / f"{name}{suffix}", dpi, suffix[1:])
                written.append(f"{name}{suffix}")
            _pyplot().close(fig)
            bar.advance(1)
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
