"""The note and the lever at a dead centre, where the balancing load is round-off.

At a slider-crank's dead centres the loads' powers cancel: the balancing torque is
zero to round-off (about 1e-15 N m), and so is the frictionless one. Measured
against it, the lever's check and friction's share were said as hundreds of percent
and 10^18 percent; the lever picture wrote its shares to 300 decimals.
"""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import pytest

import assur
from assur.explain import explain
from assur.explain._lever import _percent
from assur.explain._solve import table_at
from assur.plotting import lever

from .conftest import EXAMPLES

matplotlib.use("Agg")

EXERCISE = EXAMPLES / "slider_crank_exercise.toml"


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_the_lever_check_at_a_dead_centre_is_the_difference(angle: float) -> None:
    """It said |M_b^lever - M_b| / |M_b| = 3.7 10^2 % at 0 deg (both are round-off)."""
    table = assur.forces(assur.load(EXERCISE), [angle])
    # the two ways agree: both are round-off next to the loads' sizes
    assert abs(table["driver.torque"][0]) < 1e-12
    assert abs(table["driver.torque_check"][0]) < 1e-12
    note = str(explain(assur.load(EXERCISE), angle))
    assert r"|M_{b}^{\mathrm{lever}} - M_{b}| = 0\ \mathrm{N\,m} $$" in note
    assert r"{|M_{b}|}" not in note


def test_the_lever_check_away_from_a_dead_centre_is_a_percentage() -> None:
    note = str(explain(assur.load(EXERCISE), 45.0))
    assert r"\frac{|M_{b}^{\mathrm{lever}} - M_{b}|}{|M_{b}|} = " in note


@pytest.mark.parametrize(("stem", "angle"), [("four_bar", 0.0), ("class3", 0.0)])
def test_a_lever_check_that_agrees_but_for_round_off_is_0_percent(stem, angle):
    # the two ways differ by 1e-14 of the load or by nothing, as the machine's
    # arithmetic has it: "4.2 \cdot 10^{-14} %" here was "0 %" on another
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    table = assur.forces(mech, [angle])
    torque, check = table["driver.torque"][0], table["driver.torque_check"][0]
    assert abs(torque) > 1e-3  # away from a dead centre
    assert abs(check - torque) < 1e-12 * abs(torque)  # the same but for round-off
    note = str(explain(mech, angle))
    said = r"\frac{|M_{b}^{\mathrm{lever}} - M_{b}|}{|M_{b}|} = "
    assert f"{said}0\\,\\%" in note


@pytest.mark.parametrize("stem", ["slider_crank_friction", "slider_crank_locking"])
@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_friction_s_share_of_a_zero_ideal_load_is_not_a_percentage(
    stem: str, angle: float
) -> None:
    """It said 100 14.76/0 = 1.303 10^18 % of its size."""
    note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), angle))
    (said,) = [line for line in note.splitlines() if "Without friction" in line]
    assert "M_{b}^{\\mathrm{ideal}} = 0\\ \\mathrm{N\\,m}$" in said
    assert r"\%" not in said


def test_friction_s_share_of_a_load_is_a_percentage() -> None:
    note = str(explain(assur.load(EXAMPLES / "slider_crank_friction.toml"), 100.0))
    (said,) = [line for line in note.splitlines() if "Without friction" in line]
    # M_b = -51.26, ideal -62.8 (a reviewer's own fixed-point solution)
    share = re.search(r"= ([0-9.]+)\\,\\%\$ of \$\|M_\{b\}\^", said)
    assert share is not None, said
    assert float(share.group(1)) == pytest.approx(100 * 11.54 / 62.8, rel=2e-3)


def test_a_percentage_s_power_of_ten_is_written_plainly() -> None:
    """It was 10^{+02} and 10^{-05}."""
    assert _percent(370.0) == r"3.7 \cdot 10^{2}"
    assert _percent(1.23e-5) == r"1.2 \cdot 10^{-5}"
    assert _percent(0.0) == "0"


def test_the_lever_of_zero_shares_is_written_to_four_decimals() -> None:
    """A Scotch yoke at 0 deg: every share is 0, and the list was written to 304
    decimals (a picture 5001 pixels wide)."""
    import matplotlib.pyplot as plt

    table = table_at(assur.load(EXAMPLES / "scotch_yoke.toml"), 0.0)
    ax = lever.zhukovsky_lever(table)
    (text,) = [t.get_text() for t in ax.texts if "balancing load" in t.get_text()]
    plt.close(ax.figure)
    lines = text.splitlines()
    assert max(len(line) for line in lines) < 80, lines
    # nothing is written 0, the shares and their sum
    assert lines[-1] == "sum = balancing load: 0 N·m"
    assert all(line.endswith(":  0") for line in lines[2:-1]), lines


def test_the_lever_writes_a_link_s_speed_as_mathtext() -> None:
    """'ω_L/ω' was written with a literal underscore beside the lever."""
    import matplotlib.pyplot as plt

    table = table_at(assur.load(EXERCISE), 45.0)
    ax = lever.zhukovsky_lever(table)
    (text,) = [t.get_text() for t in ax.texts if "balancing load" in t.get_text()]
    plt.close(ax.figure)
    assert "ω_L" not in text
    assert r"$\omega_L$" in text


def test_a_link_at_rest_in_its_turning_has_a_speed_ratio_of_zero() -> None:
    # the Whitworth rod at 90 deg: "omega_L/omega = 2.6986e-16" stood in the list
    import matplotlib.pyplot as plt

    mech = assur.load(Path(__file__).parent.parent / "examples" / "whitworth.toml")
    table = table_at(mech, 90.0)
    assert abs(float(table["rod.omega"][0])) < 1e-12
    ax = lever.zhukovsky_lever(table)
    (text,) = [t.get_text() for t in ax.texts if "balancing load" in t.get_text()]
    plt.close(ax.figure)
    assert r"$\omega_L$/ω = 0)" in text or r"$\omega_L$/ω = 0;" in text
    assert "e-1" not in text
