"""Pictures of the dynamic model and of the start-up, on the Agg backend.

The tests check the artists: the curves hold the result's numbers, the tangents of the
energy-mass diagram touch the curve at the largest and smallest speeds.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

import assur
from assur import plotting

from .test_dynamics import crank, example, steady

matplotlib.use("Agg")
import matplotlib.pyplot as plt


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_the_four_pictures_of_the_steady_state():
    t = steady("whitworth")
    fig = t.plot()
    inertia, torques, speed, witt = fig.axes
    np.testing.assert_array_equal(inertia.lines[0].get_ydata(), t["reduced.inertia"])
    np.testing.assert_array_equal(torques.lines[0].get_ydata(), t["reduced.torque"])
    assert torques.lines[1].get_ydata()[0] == t.motor
    np.testing.assert_array_equal(speed.lines[0].get_ydata(), t["driver.omega"])
    assert f"δ = {t.delta:.4g}" in speed.get_title()
    # energy-mass diagram: W against the mechanism's own J
    np.testing.assert_allclose(
        witt.lines[0].get_xdata(), t["reduced.inertia"] - t.flywheel
    )
    np.testing.assert_array_equal(witt.lines[0].get_ydata(), t["reduced.work"])


@pytest.mark.parametrize("which", [2, 3])
def test_the_tangents_touch_the_energy_mass_curve(which):
    """No point of the curve lies above the tangent of the largest speed or below
    the tangent of the smallest; the closest points touch them."""
    t = assur.dynamics(
        example("whitworth"),
        np.arange(0.0, 360.0, 0.25),
        flywheel=steady("whitworth").flywheel,
    )
    ax = plotting.plot_energy_mass(t)
    x = t["reduced.inertia"] - t.flywheel
    y = t["reduced.work"]
    speed = t.speed_max if which == 2 else t.speed_min
    line = 0.5 * speed**2 * (x + t.flywheel) - t.energy
    gap = (y - line) if which == 2 else (line - y)
    assert np.max(gap) <= 1e-9 * t.energy_swing
    assert np.max(gap) >= -2e-4 * t.energy_swing  # touches, on a 0.25 deg grid
    assert len(ax.lines) == 4
    # the legend gives the tangent's speed with its unit
    name = "max" if which == 2 else "min"
    assert ax.lines[which].get_label() == f"tangent ω {name} = {speed:.5g} rad/s"


def test_the_start_up_picture():
    run = assur.startup(crank(motor=assur.Motor(2.0, 10.0)))
    ax = run.plot()
    np.testing.assert_array_equal(ax.lines[0].get_xdata(), run.time)
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), run.omega)
    assert ax.lines[2].get_xdata()[0] == run.settle_time
    assert "periodic after" in ax.get_title()


def test_diagrams_leave_out_a_crank_that_cannot_turn_round():
    from assur.pictures_cli import _steady

    rocker = assur.catalog.four_bar(crank=0.09, coupler=0.06, rocker=0.08)
    table = assur.forces(rocker, [60.0, 70.0])
    with pytest.warns(assur.AssurWarning, match="no dynamics.png: dynamics: the crank"):
        assert _steady(table) is None
    assert _steady(assur.kinematics(example("whitworth"), [0.0])) is None
    assert _steady(assur.forces(example("whitworth"), [0.0])).delta == pytest.approx(
        0.05
    )


def _texts(ax) -> list[str]:
    return [t.get_text() for t in ax.texts]


def test_a_mechanism_without_loads_says_so_at_a_readable_scale():
    """With no loads the reduced torque and the work are zero: the panels showed a
    flat line on an axis of +-2e-13 J (round-off)."""
    from assur.plotting import dynamics as pictures

    result = assur.dynamics(example("slider_crank_exercise"))
    kinetic = 0.5 * np.max(result["reduced.inertia"]) * result.omega**2
    ax = pictures.plot_energy_mass(result)
    low, high = ax.get_ylim()
    assert high - low >= 0.09 * kinetic
    assert any("no loads" in t for t in _texts(ax))
    ax = pictures.plot_reduced_torque(result)
    low, high = ax.get_ylim()
    assert high - low >= 0.09 * kinetic
    assert any("no loads" in t for t in _texts(ax))


def test_a_mechanism_with_loads_draws_its_curves():
    from assur.plotting import dynamics as pictures

    result = assur.dynamics(example("whitworth"), flywheel=10.0)
    for draw in (pictures.plot_energy_mass, pictures.plot_reduced_torque):
        ax = draw(result)
        assert not any("no loads" in t for t in _texts(ax))


def test_the_reduced_inertia_says_the_flywheel_is_in_it():
    # 13.39 to 13.42 kg m^2 was drawn as 0 to 0.03 over an offset: a spike
    result = assur.dynamics(example("whitworth"), flywheel=10.0)
    ax = plotting.plot_reduced_inertia(result)
    try:
        ax.figure.canvas.draw()
        assert "the flywheel's 10 kg·m² included" in ax.get_title()
        assert ax.yaxis.get_offset_text().get_text() == ""
        ticks = [float(t.get_text().replace("−", "-")) for t in ax.get_yticklabels()]
        assert min(ticks) >= 9.0
    finally:
        plt.close(ax.figure)
    bare = plotting.plot_reduced_inertia(assur.dynamics(example("four_bar")))
    try:
        assert bare.get_title() == "Reduced inertia"
    finally:
        plt.close(bare.figure)
