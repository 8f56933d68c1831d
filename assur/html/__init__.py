"""A self-contained HTML report: structure, drawing, diagrams, dynamics and tables.

The report is one file with inline CSS and JavaScript and its numbers embedded as JSON,
so it opens offline in any browser. Python gathers the data from the numerical core;
plain JavaScript in the page draws the mechanism and the diagrams as SVG. The style
sheet, the script and the page template are data files of this package.
"""

from __future__ import annotations

import os
from typing import Any

from assur._loads import compile_loads
from assur._output import write_text
from assur._structure import structure
from assur.analysis import default_positions, forces, kinematics
from assur.errors import AssemblyError
from assur.html._data import report_data
from assur.html._dynamics import dynamics_part
from assur.html._page import assemble_page
from assur.model import Mechanism
from assur.plan import plan_of

__all__ = ["PAGE_PARTS", "render_report", "write_report"]

PAGE_PARTS = 4
"""The parts of the page made after the sweep, as ``parts`` is told of them: the
structure and data, the dynamics, the note and the free-body diagrams."""


def render_report(
    mechanism: Mechanism, angles: Any = None, progress: Any = False, parts: Any = None
) -> str:
    """Return the HTML report of ``mechanism`` as one self-contained page.

    Parameters
    ----------
    mechanism : Mechanism
    angles : array_like, optional
        Driver positions, deg (m for a prismatic driver); shape (n,) or, with several
        drivers, (n, drivers). By default one turn from the reference pose in steps
        of 1 deg (:func:`assur.analysis.default_positions`).
    progress : bool or callable, optional
        Show a progress bar of the sweep on standard error (True), or call
        ``progress(done, total)`` as its positions are solved.
    parts : callable, optional
        Called ``parts(done, total)`` as each part of the page is made after the
        sweep (:data:`PAGE_PARTS` of them; the free-body diagrams take the most).

    Returns
    -------
    str
        The page: structure report, an animated SVG drawing with a range slider
        (``id="angle"``), diagrams over the sweep and a table; for a mechanism with
        masses and one crank, its steady state (``id="dynamics"``, see
        :func:`assur.dynamics <assur.dynamics_model.dynamics>`); with forces, the
        note of the first position (``id="note"``,
        :func:`assur.explain <assur.explain.explain>`), the links' inertia loads there
        (``id="inertia"``) and each Assur group's free-body diagram as inline SVG
        (``id="free-bodies"``, :func:`assur.plotting.draw_free_body`); the data as
        JSON in ``<script type="application/json" id="assur-data">``.

    Raises
    ------
    AssemblyError
        When no driver position of the sweep can be assembled (the error of the
        first position: its group, or friction's lock, a
        :class:`~assur.errors.SelfLockingError`).

    Notes
    -----
    Positions that cannot be assembled are left out and counted in the page. A force
    analysis runs when a link has a mass or a load is applied; otherwise the report
    shows the kinematics only.

    Examples
    --------
    >>> from assur import catalog
    >>> page = render_report(catalog.slider_crank(), angles=range(0, 360, 30))
    >>> page.startswith("<!DOCTYPE html>") and 'id="assur-data"' in page
    True
    """
    plan = plan_of(mechanism)
    with_forces = not compile_loads(plan).empty
    if angles is None:
        angles = default_positions(mechanism)
    sweep = forces if with_forces else kinematics
    table = sweep(mechanism, angles, skip_unassembled=True, progress=progress)
    if len(table) == 0:
        # the sweep again, not skipping: its error names the group, the first
        # position and why (a pose that cannot be assembled, or friction's lock)
        sweep(mechanism, angles)
        msg = (
            f"report of {mechanism.name or 'the mechanism'}: no driver position of "
            "the sweep can be assembled; expected at least one"
        )
        raise AssemblyError(msg)
    made = [0]

    def told() -> None:
        made[0] += 1
        if parts is not None:
            parts(made[0], PAGE_PARTS)

    struct = structure(mechanism)
    data = report_data(plan, struct, table)
    told()
    section, data["dynamics"], columns = dynamics_part(table)
    data["columns"].update(columns)
    told()
    return assemble_page(plan, struct, table, data, section, told)


def write_report(
    mechanism: Mechanism,
    path: str | os.PathLike[str],
    angles: Any = None,
    progress: Any = False,
    parts: Any = None,
) -> None:
    """Write the HTML report of ``mechanism`` to ``path`` (UTF-8).

    Parameters are those of :func:`render_report`. The file is written whole or not
    at all: a failed write keeps an old file of that name.

    Raises
    ------
    OutputError
        When the file cannot be written.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from assur import catalog
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     target = pathlib.Path(tmp) / "four_bar.html"
    ...     write_report(catalog.four_bar(), target, angles=[0.0, 90.0])
    ...     target.read_text(encoding="utf-8").count("<html")
    1
    """
    write_text(path, render_report(mechanism, angles, progress, parts))
