"""A picture is measured on its laid-out figure without drawing it.

:func:`assur.plotting._bars.settled_renderer` used to draw the figure twice (no
paint, but every artist walked) each time a name was placed: a free-body diagram
four times over, eight draws before it was saved; savefig then drew a PNG twice.
Running the layout engine alone settles the same positions, so the draws are
counted here, not timed.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from matplotlib.figure import Figure

import assur
from assur import plotting
from assur.plotting._bars import settled_renderer

matplotlib.use("Agg")
import matplotlib.pyplot as plt

EXAMPLES = Path(__file__).parent.parent / "examples"


@pytest.fixture
def draws(monkeypatch: pytest.MonkeyPatch) -> Iterator[list[Figure]]:
    """Count the figures' draws, with or without painting."""
    drawn: list[Figure] = []
    draw = Figure.draw

    def counted(self: Figure, renderer: object) -> None:
        drawn.append(self)
        draw(self, renderer)

    monkeypatch.setattr(Figure, "draw", counted)
    yield drawn
    plt.close("all")


def _legend_beside() -> Figure:
    """Return a constrained figure whose legend beside the axes shrinks them."""
    fig, ax = plt.subplots(figsize=(5.0, 4.0), layout="constrained")
    ax.plot([0, 1], [0, 2], label="a rather long name for a line")
    ax.set_aspect("equal")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0))
    return fig


def _positions(fig: Figure) -> np.ndarray:
    """Return the axes' laid-out and shown positions, figure fraction."""
    ax = fig.axes[0]
    return np.array([ax.get_position(original=True).bounds, ax.get_position().bounds])


def test_settled_renderer_lays_out_as_two_draws_without_one(
    draws: list[Figure],
) -> None:
    settled = _legend_beside()
    settled_renderer(settled.axes[0])
    assert draws == []
    drawn = _legend_beside()
    drawn.draw_without_rendering()
    drawn.draw_without_rendering()
    # the legend made room: the axes moved, and both ways to the same place
    assert not np.allclose(_positions(settled), _positions(_legend_beside()))
    np.testing.assert_allclose(_positions(settled), _positions(drawn), atol=1e-12)


def test_settled_renderer_draws_a_figure_without_a_layout_engine(
    draws: list[Figure],
) -> None:
    fig, ax = plt.subplots()
    settled_renderer(ax)
    assert draws == [fig, fig]


def test_a_free_body_diagram_is_not_drawn_to_place_its_names(
    draws: list[Figure],
) -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    table = assur.forces(mech, [0.0])
    # the report's figure: made without pyplot, measured as Agg
    fig = Figure(figsize=(6.0, 5.0), layout="constrained")
    plotting.draw_free_body(table, 0, ax=fig.add_subplot())
    assert any(t.get_text() for t in fig.axes[0].texts)
    assert draws == []


@pytest.mark.parametrize("plan", ["velocity_plan", "zhukovsky_lever"])
def test_a_plan_is_not_drawn_before_it_is_saved(plan: str, draws: list[Figure]) -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    ax = getattr(plotting, plan)(assur.forces(mech, [0.0]))
    assert ax.texts
    assert draws == []


@pytest.mark.parametrize(
    "rc", [{}, {"figure.autolayout": True}, {"figure.constrained_layout.use": True}]
)
def test_a_png_is_drawn_once_and_as_savefig_writes_it(
    tmp_path: Path, draws: list[Figure], rc: dict[str, bool]
) -> None:
    # a user's rc asking for a layout engine set a fresh one when the figure's was
    # taken off to save it: the figure was laid out again after its box was taken
    with matplotlib.rc_context(rc):
        _drawn_once(tmp_path, draws)


def _drawn_once(tmp_path: Path, draws: list[Figure]) -> None:
    """Check one PNG of the Whitworth lever: one draw, savefig's pixels."""
    from matplotlib.image import imread

    from assur._picture_files import _write

    table = assur.forces(assur.load(EXAMPLES / "whitworth.toml"), [0.0])
    tight = plotting.zhukovsky_lever(table).figure
    tight.savefig(tmp_path / "tight.png", dpi=150, bbox_inches="tight")
    fig = plotting.zhukovsky_lever(table).figure
    engine = fig.get_layout_engine()
    del draws[:]
    _write(fig, tmp_path / "once.png", 150, "png")
    assert draws == [fig]
    assert fig.get_layout_engine() is engine
    once, expected = imread(tmp_path / "once.png"), imread(tmp_path / "tight.png")
    assert once.shape == expected.shape
    assert (once == expected).all()
