"""Newton's method on a group's reaction sizes, on small systems built by hand.

``s = |R(s)|`` with ``R(s) = start + s * response`` for one pair: the tolerance a
caller gives (:func:`assur._newton._sizes`), the side a sliding pair's normal force
is held on (:func:`assur._newton._signs`) and the steps the note counts
(:func:`assur._friction.newton_steps`) where Newton settles on the solution that
grows from no friction, on the jammed one, or on none.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from assur._friction import Sizing, newton_steps
from assur._newton import TOLERANCE, _signs, _sizes


def _revolute(start: tuple[float, float], response: tuple[float, float]) -> Sizing:
    """One revolute pair's system: its reaction ``start + s * response`` (N)."""
    return Sizing(
        (SimpleNamespace(kind="R"),),
        frozenset(),
        {},
        (np.array([start]),),
        ((np.array([response]),),),
        SimpleNamespace(),
    )


def _solve(system: Sizing, sizes: float, scale: float, tolerance: float) -> int:
    """Return Newton's steps from ``sizes`` (N) to settle, at ``tolerance``."""
    _, settled, _, count = _sizes(
        system.start, system.response, np.array([[sizes]]), np.array([scale]),
        tolerance=tolerance,
    )  # fmt: skip
    assert settled[0]
    return count


def test_a_step_within_the_tolerance_given_of_the_scale_settles() -> None:
    system = _revolute((3.0, 4.0), (0.5, 0.2))
    strict = _solve(system, 500.0, 1e6, TOLERANCE)
    # the first step, from far off, is far larger than the sizes it lands on, yet
    # below the scale given: it settles there at a share of one
    assert _solve(system, 500.0, 1e6, 1.0) == 1 < strict


def test_a_step_within_the_tolerance_given_of_the_sizes_settles() -> None:
    system = _revolute((3.0, 4.0), (0.5, 0.2))
    # a scale of nothing: the sizes found alone tell a step from round-off
    strict = _solve(system, 12.0, 1e-300, TOLERANCE)
    assert _solve(system, 12.0, 1e-300, 1.0) == 1 < strict


def test_a_normal_force_is_held_on_the_side_given() -> None:
    # round-off without friction (1e-14 N) on one side, the solution's on the other
    start, response = [np.array([[1e-14]])], [[np.array([[0.3]])]]
    signed, turned, responses = _signs(start, response, [np.array([[-5.0]])])
    assert signed == (True,)
    assert turned[0][0, 0] < 0.0
    assert responses[0][0][0, 0] < 0.0
    # without a side given, the frictionless one
    _, turned, _ = _signs(start, response)
    assert turned[0][0, 0] > 0.0


def test_newton_steps_are_counted_where_the_growing_solution_is_reached() -> None:
    # s = |(1 + s/2, 0)|: s = 2, reached from the frictionless size 1
    steps = newton_steps(_revolute((1.0, 0.0), (0.5, 0.0)), [], None, 1e-6)
    assert isinstance(steps, int)
    assert steps >= 1


def test_newton_steps_are_none_on_the_jammed_solution() -> None:
    # s = |1 - 3 s|: from s = 1 Newton lands on s = 1/2, where R = -1/2 and the
    # Jacobian's determinant is negative (s = 1/4 is the one that grows)
    system = _revolute((1.0, 0.0), (-3.0, 0.0))
    _, settled, growing, _ = _sizes(
        system.start, system.response, np.array([[1.0]]), np.array([1.0])
    )
    assert settled[0]
    assert not growing[0]
    assert newton_steps(system, [], None, 1e-6) is None


def test_newton_steps_are_none_where_newton_does_not_settle() -> None:
    # s = |1 + 2 s| has no solution: Newton swings between -1 and -1/3
    system = _revolute((1.0, 0.0), (2.0, 0.0))
    assert newton_steps(system, [], None, 1e-6) is None


def test_a_sizing_cannot_be_changed_once_made() -> None:
    start, response = np.array([[3.0, 4.0]]), np.array([[0.5, 0.2]])
    unit = np.array([-0.1])
    system = Sizing(
        [SimpleNamespace(kind="R", name="B")], {1, 2}, {"B": [0.0, 0.0, unit]},
        [start], [[response]], SimpleNamespace(),
    )  # fmt: skip
    assert isinstance(system.pairs, tuple)
    assert isinstance(system.inside, frozenset)
    assert isinstance(system.start, tuple)
    assert all(isinstance(row, tuple) for row in system.response)
    with pytest.raises(TypeError):
        system.units["C"] = (0.0, 0.0, 0.0)  # type: ignore[index]
    for array in (system.start[0], system.response[0][0], system.units["B"][2]):
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 0.0
    # the record holds read-only views: the caller's own arrays are left as they were
    assert start.flags.writeable
    assert response.flags.writeable
