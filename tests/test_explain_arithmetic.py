"""Every substituted equation of the note follows from the numbers it prints.

Where the note writes ``10 \\cdot 800 = 8000`` or ``\\frac{-153.41}{0.2} =
-767.06``, the result must be what the printed operands give, within the rounding
of each printed number (interval arithmetic, :mod:`tests.notearith`). The forces
table is not read here: this checks the working a student would copy, not only
its results. Four significant digits bound what it can see: a slip of about 1e-3
of a result is found, one of 1e-5 hides in the rounding.
"""

from __future__ import annotations

import pytest

import assur
from assur.explain import explain

from .notearith import Interval, evaluate, number_interval, pieces_checked
from .test_explain import CASES, EXAMPLES
from .test_explain_friction import rubbed

FRICTION = [
    ("slider_crank_friction", 30.0),
    ("slider_crank_friction", 200.0),
    ("four_bar_bearings", 30.0),
    ("four_bar_bearings", 250.0),
    ("slider_crank_locking", 100.0),
]
RUBBED = [("six_bar_lecture", 30.0), ("whitworth", 60.0), ("class3", 20.0)]


def _steps(note: str, least: int) -> None:
    count, wrong = pieces_checked(note)
    assert wrong == []
    assert count >= least


@pytest.mark.parametrize(("stem", "angle"), CASES + FRICTION)
def test_every_step_of_the_examples_holds(stem: str, angle) -> None:
    note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), angle))
    _steps(note, 25)


@pytest.mark.parametrize(("stem", "angle"), RUBBED)
def test_every_step_holds_with_friction_everywhere(stem: str, angle) -> None:
    _steps(str(explain(rubbed(stem), angle)), 60)


def test_a_wrong_step_is_found() -> None:
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0))
    for right, wrong in (
        (r"10 \cdot 800 = 8000", r"10 \cdot 800 = 8010"),
        (r"-\frac{-16925}{200} = 84.63", r"-\frac{-16925}{200} = 84.73"),
        (r"0.5 \cdot 2565.13 = 1282.57", r"0.5 \cdot 2565.13 = 1283.57"),
    ):
        assert right in note
        _, found = pieces_checked(note.replace(right, wrong))
        assert len(found) == 1, right


def test_the_arithmetic_of_the_checker() -> None:
    assert number_interval("8000") == Interval(7999.995, 8000.005)
    assert number_interval("0.0006").hi == pytest.approx(0.00060005)
    assert number_interval("1.4 \\cdot 10^{-5}").lo == pytest.approx(1.3995e-5)
    (value,) = evaluate(r"-\frac{-16925 + (-3239.46)}{200}")
    assert value.lo < 100.82 < value.hi
    assert evaluate(r"(0,\ 0) + 10 \cdot (-0.025,\ 0.0433)") is not None
    x, y = evaluate(r"(1,\ 0) + 200 \cdot \vec k \times (0.05,\ 0.02)")
    assert x.lo < -3.0 < x.hi
    assert y.lo < 10.0 < y.hi
    assert evaluate(r"\sqrt{0.15^2 - 0.09049^2}\ \mathrm{m}") is not None
    assert evaluate(r"\omega_{\mathrm{rod}} - 3") is None  # a symbol: not checked
    assert evaluate(r"\frac{1}{0}") is None  # no bound: not checked
