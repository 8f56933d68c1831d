"""The kinematics of the note gives every result with its unit.

A result is the right-hand side that ends a line or a ``\\quad`` piece of it:
a position (m), a velocity (m/s), an acceleration (m/s^2), an angular velocity
(rad/s) or acceleration (rad/s^2). Intermediate arithmetic carries no units.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import assur
from assur.explain import explain

EXAMPLES = Path(__file__).parent.parent / "examples"

UNITS = {
    r"\vec r": r"\ \mathrm{m}",
    r"\vec v": r"\ \mathrm{m/s}",
    "v_": r"\ \mathrm{m/s}",
    r"\vec a": r"\ \mathrm{m/s^2}",
    "a_": r"\ \mathrm{m/s^2}",
    "a^": r"\ \mathrm{m/s^2}",
    r"\omega": r"\ \mathrm{rad/s}",
    r"\varepsilon": r"\ \mathrm{rad/s^2}",
    r"\dot s": r"\ \mathrm{m/s}",
    r"\ddot s": r"\ \mathrm{m/s^2}",
    "s =": r"\ \mathrm{m}",
}
"""What a result piece starts with, and the unit it must end with."""


def _kinematics(stem: str, angle: float = 45.0) -> list[str]:
    """Return the display lines of section 2 of an example's note."""
    note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), angle))
    part = note.split("## 2.")[1].split("## 3.")[0]
    return [x[3:-3] for x in part.splitlines() if x.startswith("$$ ")]


def _results(lines: list[str]) -> list[str]:
    """Return the pieces of the lines that end in a result (a number or vector)."""
    pieces = [p for x in lines for p in re.split(r",\\quad ", x)]
    # the last side a number or a vector; a component equation (x: ...), the
    # determinant or a direction is not a result
    return [
        p
        for p in pieces
        if re.match(r"\s*[-(\d]", p.split(" = ")[-1])
        and not re.match(r"[xy]:|\\Delta|\\vec e|\\text", p)
        and ":\\ " not in p
    ]


@pytest.mark.parametrize(
    "stem",
    [
        "slider_crank_exercise",
        "four_bar",
        "class3",
        "whitworth",
        "scotch_yoke",
        "slot_mechanism",
        "six_bar_lecture",
        "lever_var9",
    ],
)
def test_every_kinematic_result_has_its_unit(stem: str) -> None:
    checked = 0
    for piece in _results(_kinematics(stem)):
        start = piece.lstrip()
        for head, unit in sorted(UNITS.items(), key=lambda u: -len(u[0])):
            if start.startswith(head):
                assert piece.rstrip().endswith(unit), piece
                checked += 1
                break
    assert checked > 10


def test_slider_crank_velocities_end_with_metres_per_second() -> None:
    lines = _kinematics("slider_crank_exercise")
    velocities = [x for x in _results(lines) if x.startswith(r"\vec v")]
    assert len(velocities) >= 6
    for piece in velocities:
        assert piece.endswith(r"\ \mathrm{m/s}"), piece
    speed = next(x for x in lines if x.startswith(r"\vec v_{\mathrm{B}} = \vec v"))
    assert speed.endswith(r"v_{\mathrm{B}} = 14.8\ \mathrm{m/s}")
    turn = next(x for x in lines if x.startswith(r"\omega_{\mathrm{rod}} = -54.21"))
    assert turn == (
        r"\omega_{\mathrm{rod}} = -54.21\ \mathrm{rad/s},\quad "
        r"\omega_{\mathrm{slider}} = 0\ \mathrm{rad/s}"
    )
    assert r"\dot s_{\mathrm{guide}} = \frac{-2.568}{0.193} = -13.3\ \mathrm{m/s}" in (
        lines
    )
    assert r"\vec r_{\mathrm{B}} = (0.05233,\ 0.05233)\ \mathrm{m}" in lines
    assert any(x.endswith(r"= 587.84\ \mathrm{m/s^2}") for x in lines)


@pytest.mark.parametrize(("asked", "shown"), [(200.0, "200"), (420.0, "420")])
def test_the_crank_angle_is_printed_as_asked(asked: float, shown: str) -> None:
    lines = _kinematics("slider_crank_exercise", asked)
    assert lines[0].startswith(rf"\varphi_{{\mathrm{{crank}}}} = {shown}^\circ,")


def test_each_crank_angle_is_printed_as_asked() -> None:
    note = str(explain(assur.load(EXAMPLES / "five_bar_two_cranks.toml"), [200, 420]))
    assert r"\varphi_{\mathrm{left\_crank}} = 200^\circ," in note
    assert r"\varphi_{\mathrm{right\_crank}} = 420^\circ," in note


@pytest.mark.parametrize(
    "stem", ["whitworth", "slider_crank_exercise", "six_bar_lecture"]
)
def test_the_reactions_solved_by_cramer_s_rule_have_units(stem):
    """A force polygon's two unknowns (F^n, N) in N, a sliding pair's couple M in
    N m, and the lever's balancing load: they were bare numbers."""
    note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), 45.0))
    solved = [
        x[3:-3]
        for x in note.splitlines()
        if x.startswith("$$ ") and r"\frac{" in x and re.match(r"\$\$ (N|M|F)_", x)
    ]
    assert solved
    for line in solved:
        wanted = r"\ \mathrm{N\,m}" if line.startswith("M_") else r"\ \mathrm{N}"
        assert line.rstrip().endswith(wanted), line
