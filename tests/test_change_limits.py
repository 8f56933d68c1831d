"""The dynamic model through change points, where the sweep itself is singular.

A parallelogram four-bar passes its change points (0 and 180 deg) on the branch
whose velocities are continuous; its coupler translates, so its reduced inertia and
reduced torque are known by hand. With the crank's reference pose at 45 deg the
model's grid met 180 deg exactly, and the model was refused: "the crank cannot make
a full turn: dead centre at driver position 180 deg".
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur._change_limits import across_change_points
from assur.dynamics_reduced import reduce, reduced_at
from assur.plan import plan_of

EDGE = Path(__file__).parent / "data" / "edge"
INERTIA = 0.5 * 0.1**2 + 0.001 + 1.0 * 0.1**2
"""The crank's mass at A, its own inertia, the translating coupler (kg m^2)."""
G = 9.81
"""The file's gravity (m/s^2), the format's default."""


def parallelogram() -> assur.Mechanism:
    return assur.load(EDGE / "parallelogram_masses.toml")


def test_the_reduced_model_of_a_parallelogram_at_its_change_points():
    mech = parallelogram()
    with warnings.catch_warnings():
        # the model's grid names the change points it passed
        warnings.simplefilter("ignore", assur.AssurWarning)
        model = reduce(mech)
    degrees = np.degrees(model.angle) % 360.0
    assert np.any(np.isclose(degrees, 180.0, atol=1e-9))
    np.testing.assert_allclose(model.inertia, INERTIA, rtol=1e-8)
    # gravity on the crank's and the coupler's masses, both moving as A does:
    # V = g (0.5 + 1.0) 0.1 sin(phi), M = -dV/dphi
    torque = -G * 1.5 * 0.1 * np.cos(model.angle)
    np.testing.assert_allclose(model.torque, torque, atol=1e-8 * 1.5)


def test_values_at_a_change_point_are_the_limits_of_its_sides():
    """Interpolated at 180 deg and at 1e-7 rad from it; the sweep itself is
    refused there, and a millionth of a degree away its rounding is 1e-4."""
    mech = parallelogram()
    plan = plan_of(mech)
    angles = np.array([90.0, 180.0, 180.0 + math.degrees(1e-7), 270.0])

    def evaluate(a):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", assur.AssurWarning)
            return reduced_at(mech, a)[1:]

    inertia, slope, torque = across_change_points(plan, angles, evaluate)
    np.testing.assert_allclose(inertia, INERTIA, rtol=1e-8)
    # found: 4.7e-8 of the inertia, the rounding of the accelerations 0.11 deg away
    np.testing.assert_allclose(slope, 0.0, atol=1e-7 * INERTIA)
    expected = -G * 0.15 * np.cos(np.radians(angles))
    np.testing.assert_allclose(torque, expected, atol=1e-8)
    with pytest.raises(assur.SingularConfigurationError):
        evaluate(np.array([180.0]))


def test_the_dynamics_table_at_the_default_angles():
    """Its rows in 1 deg steps from 45 deg meet 180 deg: refused as a dead centre."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        table = assur.dynamics(parallelogram())
    assert 180.0 in table["angle"]
    np.testing.assert_allclose(table["reduced.inertia"], INERTIA, rtol=1e-8)
    np.testing.assert_allclose(table["reduced.inertia_slope"], 0.0, atol=1e-7 * INERTIA)


@pytest.mark.parametrize("off", [0.001, 0.01])
def test_a_grid_passing_near_a_change_point(off):
    """The crank's reference pose 45.001 deg: the model's grid passes 1.7e-5 rad
    from 180 deg, where the sweep's slope of J is 1.4 times J (rounding): the grid
    was refined to 65536 points and J' still peaked at 0.17 J."""
    text = (EDGE / "parallelogram_masses.toml").read_text(encoding="utf-8")
    t = math.radians(45.0 + off)
    ax, ay = 0.1 * math.cos(t), 0.1 * math.sin(t)
    text = text.replace(
        "at = [0.07071067811865475, 0.07071067811865475]", f"at = [{ax!r}, {ay!r}]"
    ).replace(
        "at = [0.37071067811865475, 0.07071067811865475]",
        f"at = [{ax + 0.3!r}, {ay!r}]",
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        model = reduce(assur.loads(text))
    assert model.angle.shape[0] == 2048
    np.testing.assert_allclose(model.inertia, INERTIA, rtol=1e-8)
    assert np.max(np.abs(model.splines[0](model.angle, 1))) < 1e-6 * INERTIA


def test_the_command_line_tells_each_warning_once(capsys):
    """The dynamic model, its table and the positions around a change point each
    warned of the same change point and of positions nobody asked for (181 deg):
    25 warnings for rows at 180.001 to 180.005 deg."""
    from assur.cli import main

    path = EDGE / "parallelogram_masses.toml"
    assert main(["dynamics", str(path), "--angles", "170:190:5"]) == 0
    lines = [x for x in capsys.readouterr().err.splitlines() if "warning" in x]
    assert lines
    assert len(lines) == len(set(lines))
    assert not any("181 deg" in x for x in lines)
    assert main(["dynamics", str(path), "--angles", "180.001:180.005:0.002"]) == 0
    lines = [x for x in capsys.readouterr().err.splitlines() if "warning" in x]
    assert len(lines) == len(set(lines)) <= 2
