"""Progress bars of the picture commands on a terminal, and --quiet."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from .conftest import run_cli as run

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
FOUR_BAR = EXAMPLES / "four_bar.toml"


@pytest.mark.pictures
def test_diagrams_show_a_bar_on_a_terminal(tmp_path, capsys, monkeypatch):
    from assur import _progress

    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    monkeypatch.setattr(_progress, "BAR_DELAY", 0.0)  # shown however quick
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles", "0:360:30", "-o", tmp_path / "d"
    )
    assert status == 0
    assert "diagrams:" in err
    # four-bar has masses and a crank: seven pictures, counted whole ("7.00/7.00")
    assert "7/7" in err
    assert " figures/s" in err
    assert out.count("wrote ") == 7


@pytest.mark.pictures
def test_plans_and_report_show_a_bar_on_a_terminal(tmp_path, capsys, monkeypatch):
    from assur import _picture_plans, _progress

    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    monkeypatch.setattr(_progress, "BAR_DELAY", 0.0)
    monkeypatch.setattr(_picture_plans, "BAR_DELAY", 0.0)
    status, out, err = run(capsys, "plans", FOUR_BAR, "-o", tmp_path / "p")
    assert status == 0
    assert out.count("wrote ") == 10  # PNG and SVG each
    # velocity and acceleration plans, force polygons, lever, instant centres
    assert "plans:" in err
    assert "5/5" in err
    status, out, err = run(
        capsys, "report", FOUR_BAR, "--angles", "0:360:2", "-o", tmp_path / "r.html"
    )
    assert (status, out.count("wrote ")) == (0, 1)
    assert "report:" in err
    assert "181/181" in err  # the stop included


@pytest.mark.pictures
def test_diagrams_without_a_terminal_or_quiet(tmp_path, capsys, monkeypatch):
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles", "0:360:30", "-o", tmp_path / "d"
    )
    assert (status, err) == (0, "")
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, out, err = run(
        capsys, "diagrams", FOUR_BAR, "--angles=0:360:30", "-o", tmp_path / "e", "-q"
    )
    assert (status, out, err) == (0, "", "")
    assert len(list((tmp_path / "e").iterdir())) == 7


@pytest.mark.pictures
def test_quiet_pictures_say_nothing(tmp_path, capsys):
    for args in (
        ["plot", FOUR_BAR, "-o", tmp_path / "p.png"],
        ["animate", FOUR_BAR, "--frames", "2", "-o", tmp_path / "a.gif"],
    ):
        status, out, err = run(capsys, "--quiet", *args)
        assert (status, out, err) == (0, "", "")
        assert Path(args[-1]).exists()


@pytest.mark.pictures
def test_animate_shows_a_bar_per_frame_on_a_terminal(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True)
    status, _, err = run(
        capsys, "animate", FOUR_BAR, "--frames", "3", "-o", tmp_path / "a.gif"
    )
    assert status == 0
    assert "animate:" in err
    assert "3/3" in err


def test_the_report_tells_a_callback_of_its_sweep():
    import assur
    from assur.html import render_report

    seen = []
    render_report(
        assur.load(FOUR_BAR),
        [0.0, 90.0, 180.0],
        progress=lambda d, t: seen.append((d, t)),
    )
    assert seen[-1] == (3, 3)


def test_animate_tells_a_callback_each_frame(tmp_path):
    import assur
    from assur.plotting import animate

    table = assur.kinematics(assur.load(FOUR_BAR), [0.0, 90.0, 180.0])
    seen = []
    count = animate(
        table, tmp_path / "a.gif", progress=lambda d, t: seen.append((d, t))
    )
    assert count == 3
    assert seen == [(1, 3), (2, 3), (3, 3)]
