"""The film's frame (assur.plotting.animate): its legend below, its labels inside."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
import pytest

import assur
from assur.plotting import animate
from assur.plotting._bars import label_box

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"


@pytest.fixture
def frames(monkeypatch: pytest.MonkeyPatch) -> list[dict[str, Any]]:
    """Record, at each frame grabbed, the boxes (pixels) of its axes, legend, labels."""
    from matplotlib.animation import PillowWriter

    seen: list[dict[str, Any]] = []
    grab = PillowWriter.grab_frame

    def grab_frame(self: Any, **kwargs: Any) -> None:
        fig = self.fig
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        (ax,) = fig.axes
        seen.append({
            "figure": fig.bbox.extents,
            "axes": ax.get_window_extent(renderer).extents,
            "legend": fig.legends[0].get_window_extent(renderer).extents,
            "labels": {t.get_text(): label_box(t, renderer) for t in ax.texts
                       if t.get_visible() and t.get_text()},
        })  # fmt: skip
        grab(self, **kwargs)

    monkeypatch.setattr(PillowWriter, "grab_frame", grab_frame)
    return seen


def test_the_legend_is_below_the_drawing(tmp_path, frames) -> None:
    # beside the drawing the legend took about 35 % of the frame's width
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    table = assur.forces(mech, [45.0, 135.0, 225.0, 315.0])
    assert animate(table, tmp_path / "a.gif", forces=True, dpi=80) == 4
    for frame in frames:
        legend, axes, figure = frame["legend"], frame["axes"], frame["figure"]
        assert legend[3] < axes[1]
        assert legend[0] >= figure[0]
        assert legend[2] <= figure[2]
        # the drawing takes most of the frame's width
        assert axes[2] - axes[0] > 0.75 * (figure[2] - figure[0])
        frame_box = np.asarray(axes)
        for text, box in frame["labels"].items():
            assert (box[:2] >= frame_box[:2]).all(), text
            assert (box[2:] <= frame_box[2:]).all(), text


def test_a_label_past_the_frame_is_moved_inside() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting.animation import keep_inside

    fig, ax = plt.subplots()
    try:
        ax.set_xlim(0.0, 1.0)
        ax.set_ylim(0.0, 1.0)
        ax.set_aspect("equal", adjustable="box")
        # right-aligned at the left edge: all of it past the frame
        label = ax.text(0.0, 0.5, "$F_{i,crank}$", ha="right", bbox={"pad": 1})
        inside = ax.text(0.5, 0.5, "rod")
        before = inside.get_position()
        keep_inside(ax)
        renderer = fig.canvas.get_renderer()
        frame = ax.get_window_extent(renderer).extents
        box = label_box(label, renderer)
        assert box[0] >= frame[0]
        assert box[0] - frame[0] < 5.0
        assert inside.get_position() == before
    finally:
        plt.close(fig)


def test_a_legend_of_long_names_fits_the_frame(tmp_path, frames) -> None:
    # the class III example with links named at length: its two-column legend ran
    # past both sides of the frame, which crops it
    text = (EXAMPLES / "class3.toml").read_text(encoding="utf-8")
    for short in ("left_rocker", "right_rocker", "plate", "rod", "crank"):
        text = text.replace(f'"{short}"', f'"{short}_of_the_triad_in_the_example"')
        text = text.replace(
            f"links.{short}]", f"links.{short}_of_the_triad_in_the_example]"
        )
    path = tmp_path / "long.toml"
    path.write_text(text, encoding="utf-8")
    table = assur.forces(assur.load(path), [30.0, 90.0])
    assert animate(table, tmp_path / "a.gif", forces=True, dpi=80) == 2
    for frame in frames:
        legend, figure = frame["legend"], frame["figure"]
        assert legend[0] >= figure[0] - 1.0
        assert legend[2] <= figure[2] + 1.0


@pytest.mark.pictures
def test_wiping_a_frame_draws_the_film_that_clearing_its_axes_drew(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # each frame removes what the last one drew and keeps the axes' ticks, which
    # clearing the axes made anew every frame: the same pixels, in less time
    from PIL import Image

    from assur.plotting import animation

    table = assur.forces(assur.load(EXAMPLES / "class3.toml"), [10.0, 100.0, 250.0])
    animate(table, tmp_path / "wiped.gif", forces=True)
    monkeypatch.setattr(animation, "_wipe", lambda ax: ax.clear())
    animate(table, tmp_path / "cleared.gif", forces=True)
    films = []
    for name in ("wiped", "cleared"):
        with Image.open(tmp_path / f"{name}.gif") as gif:
            films.append([])
            for i in range(gif.n_frames):
                gif.seek(i)
                films[-1].append(np.asarray(gif.convert("RGBA")))
    assert len(films[0]) == len(films[1]) == 3
    for wiped, cleared in zip(*films, strict=True):
        assert np.array_equal(wiped, cleared)
    assert not np.array_equal(films[0][0], films[0][1])  # the frames move
