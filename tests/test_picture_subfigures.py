"""Every picture drawn into axes of a matplotlib SubFigure, as into a Figure's.

A SubFigure has no canvas to draw, lay out or measure with: the pictures that
place their names on the drawing as it is seen asked ``ax.figure`` for
``draw_without_rendering`` and failed with matplotlib's AttributeError.
"""

from __future__ import annotations

import functools
import inspect
import io
import types
from collections.abc import Callable
from typing import Any

import matplotlib
import numpy as np
import pytest

import assur
from assur import plotting
from assur.plotting._bars import root_figure

from .test_dynamics import crank, steady

matplotlib.use("Agg")
import matplotlib.pyplot as plt


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


@functools.cache
def _forces() -> assur.Table:
    return assur.forces(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 30.0))


@functools.cache
def _run() -> assur.Startup:
    return assur.startup(crank(motor=assur.Motor(2.0, 10.0)))


DRAWN: dict[str, Callable[[Any], Any]] = {
    "draw": lambda ax: plotting.draw(_forces(), ax=ax),
    "plot_motion": lambda ax: plotting.plot_motion(_forces(), ax=ax),
    "plot_paths": lambda ax: plotting.plot_paths(_forces(), ax=ax),
    "draw_free_body": lambda ax: plotting.draw_free_body(_forces(), 0, ax=ax),
    "plot_torque": lambda ax: plotting.plot_torque(_forces(), ax=ax),
    "velocity_plan": lambda ax: plotting.velocity_plan(_forces(), ax=ax),
    "acceleration_plan": lambda ax: plotting.acceleration_plan(_forces(), ax=ax),
    "instant_centres": lambda ax: plotting.instant_centres(_forces(), ax=ax),
    "zhukovsky_lever": lambda ax: plotting.zhukovsky_lever(_forces(), ax=ax),
    "plot_reduced_inertia": lambda ax: plotting.plot_reduced_inertia(
        steady("whitworth"), ax=ax
    ),
    "plot_reduced_torque": lambda ax: plotting.plot_reduced_torque(
        steady("whitworth"), ax=ax
    ),
    "plot_speed": lambda ax: plotting.plot_speed(steady("whitworth"), ax=ax),
    "plot_energy_mass": lambda ax: plotting.plot_energy_mass(
        steady("whitworth"), ax=ax
    ),
    "plot_startup": lambda ax: plotting.plot_startup(_run(), ax=ax),
    # the results' one-line forwards
    "Table.plot": lambda ax: _forces().plot(ax=ax),
    "Startup.plot": lambda ax: _run().plot(ax=ax),
}


def test_every_public_picture_taking_axes_is_drawn_here() -> None:
    taking = {
        name
        for name in plotting.__all__
        if "ax" in inspect.signature(getattr(plotting, name)).parameters
    }
    assert taking == {name for name in DRAWN if "." not in name}


@pytest.mark.parametrize("layout", [None, "constrained"])
@pytest.mark.parametrize("name", list(DRAWN))
def test_a_picture_is_drawn_into_a_subfigure_s_axes(name: str, layout: Any) -> None:
    fig = plt.figure(figsize=(12.0, 5.0), layout=layout)
    left, right = fig.subfigures(1, 2)
    ax = left.subplots()
    assert DRAWN[name](ax) is ax
    assert ax.lines or ax.patches or ax.collections
    assert not right.axes
    fig.savefig(io.BytesIO(), format="png")


def _shape(ax: Any) -> float:
    """The width of the view of ``ax`` over its height, once drawn."""
    root_figure(ax).canvas.draw()
    return float(np.ptp(ax.get_xlim()) / np.ptp(ax.get_ylim()))


@pytest.mark.parametrize(("size", "rows", "cols"), [((12.0, 5.0), 1, 2),
                                                    ((6.0, 10.0), 2, 1)])  # fmt: skip
def test_a_picture_in_a_subfigure_is_framed_as_in_a_figure_of_its_size(
    size: tuple[float, float], rows: int, cols: int
) -> None:
    # the free body's view is widened to fill its room: the room was measured as
    # a share of the whole figure, not of the subfigure (a view twice as wide, or
    # half as wide, as the same picture's in a 6 x 5 in figure)
    fig = plt.figure(figsize=(6.0, 5.0), layout="constrained")
    alone = plotting.draw_free_body(_forces(), 0, ax=fig.subplots())
    fig = plt.figure(figsize=size, layout="constrained")
    sub = fig.subfigures(rows, cols)[-1]
    inner = plotting.draw_free_body(_forces(), 0, ax=sub.subplots())
    np.testing.assert_allclose(_shape(inner), _shape(alone), rtol=0.05)


def test_the_root_figure_is_found_through_nested_subfigures() -> None:
    fig = plt.figure()
    inner = fig.subfigures(1, 2)[0].subfigures(2, 1)[1]
    ax = inner.subplots()
    assert root_figure(ax) is fig
    assert root_figure(fig.subplots()) is fig


def test_the_root_figure_before_matplotlib_3_10() -> None:
    # get_figure() took no root= before 3.10; a SubFigure's ``figure`` was its
    # root Figure then, and a Figure's itself
    class Old:
        def __init__(self, holder: object) -> None:
            self.figure = holder

        def get_figure(self) -> object:
            return self.figure

    root = plt.figure()
    sub = types.SimpleNamespace(figure=root)
    assert root_figure(Old(sub)) is root
