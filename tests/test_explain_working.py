"""The note's working where a student's own goes wrong, step by step.

Sliding pairs: the guide's point under the slider must come from somewhere, the
Coriolis term needs a direction as well as a size, the two points at a slot (the
slider's and the guide's) need two names, and a guide that carries only a couple
has no point of action to compute. A tabulated load is read between two entries of
its table. A force on Zhukovsky's lever has an arm. Every number is checked against
the forces table or worked by hand, not against the note.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.explain import explain

from .notearith import pieces_checked

EXAMPLES = Path(__file__).parent.parent / "examples"
DATA = Path(__file__).parent / "data" / "explain"
NUMBER = r"(-?[0-9.]+(?: \\cdot 10\^\{-?\d+\})?)"
VECTOR = rf"\({NUMBER},\\ {NUMBER}\)"


def _float(text: str) -> float:
    """Return the value of a number as the note prints it."""
    mantissa, _, power = text.partition(" \\cdot 10^{")
    return float(mantissa) * 10.0 ** float(power.rstrip("}") or 0)


def _mechanism(tmp_path: Path, path: Path, clockwise: bool) -> assur.Mechanism:
    """Load ``path``; with ``clockwise``, its driver's speed turned the other way."""
    if not clockwise:
        return assur.load(path)
    text = path.read_text(encoding="utf-8")
    found = re.search(r"^omega = ([0-9.]+)$", text, flags=re.M)
    assert found, path
    copy = tmp_path / path.name
    copy.write_text(
        text.replace(found.group(0), f"omega = -{found.group(1)}"), encoding="utf-8"
    )
    return assur.load(copy)


def _rate(table: assur.Table, link: str, rate: str) -> float:
    """Return a link's rate (``omega`` or ``alpha``) in the table; 0 for the frame."""
    return 0.0 if link == "ground" else float(table[f"{link}.{rate}"][0])


CASES = [
    (EXAMPLES / "slot_mechanism.toml", 30.0),
    (EXAMPLES / "slot_mechanism.toml", 250.0),
    (EXAMPLES / "whitworth.toml", 60.0),
    (EXAMPLES / "whitworth.toml", 210.0),
    (DATA / "prp_tangent.toml", 30.0),
    (DATA / "slot_in_crank.toml", 20.0),
]
GUIDES = [
    (EXAMPLES / "lever_var9.toml", 20.0),
    (EXAMPLES / "lever_var9.toml", 250.0),
    (DATA / "prp_tangent.toml", 30.0),
    (DATA / "slot_in_crank.toml", -20.0),
]
"""Mechanisms with a slider on a moving guide (lever_var9's on link 2, whose pin B
moves)."""


@pytest.mark.parametrize("clockwise", [False, True])
@pytest.mark.parametrize(("path", "angle"), CASES)
def test_a_coriolis_term_points_along_the_relative_velocity_turned_as_the_guide_turns(
    tmp_path: Path, path: Path, angle: float, clockwise: bool
) -> None:
    # the note gave 2 w v_r as a signed product and no direction: the reader could
    # not draw the vector of the plan without the table
    mech = _mechanism(tmp_path, path, clockwise)
    note = str(explain(mech, angle))
    table = assur.kinematics(mech, [angle])
    coriolis = re.findall(
        rf"\\vec a\^{{k}}_{{(.+?)}} = {VECTOR}\\ \\mathrm{{m/s\^2}} \$\$\n\$\$ \\qquad "
        rf"2\\,\\omega_{{\\mathrm{{(\w+)}}}}(.*?)\\ a\^k = .* = {NUMBER}\\ "
        rf"\\mathrm{{m/s\^2}} \$\$",
        note,
    )
    turning = [c for c in coriolis if _rate(table, c[3], "omega") != 0.0]
    assert turning, "no Coriolis term of a turning guide"
    for slide, ax, ay, guide, middle, size in coriolis:
        a = np.array([_float(ax), _float(ay)])
        omega = _rate(table, guide, "omega")
        told = re.search(r"90\^\\circ\\ \\text\{([a-z-]+), as link \w+ turns", middle)
        sense = told.group(1) if told else ""
        found = re.search(rf"\\vec v\^{{r}}_{{{re.escape(slide)}}} = {VECTOR}", note)
        assert found, slide
        vr = np.array([_float(found.group(1)), _float(found.group(2))])
        if omega == 0.0 or np.allclose(vr, 0.0):
            # no direction to tell: the term is zero
            assert not sense
            assert _float(size) == 0.0
            assert np.allclose(a, 0.0)
            continue
        assert sense == ("counter-clockwise" if omega > 0 else "clockwise")
        assert _float(size) == pytest.approx(2 * abs(omega) * math.hypot(*vr), 2e-3)
        turn = 1.0 if sense == "counter-clockwise" else -1.0
        direction = turn * np.array([-vr[1], vr[0]]) / math.hypot(*vr)
        assert a == pytest.approx(_float(size) * direction, rel=3e-3, abs=2e-3)


@pytest.mark.parametrize(("path", "angle"), GUIDES)
def test_a_moving_guide_s_point_under_the_slider_is_worked_out_from_its_pin(
    path: Path, angle: float
) -> None:
    # it was printed bare ("the point of crank at slot"), used before it was derived
    mech = assur.load(path)
    note = str(explain(mech, angle))
    table = assur.kinematics(mech, [angle])
    lines = [
        line
        for line in note.splitlines()
        if "\\text{the point of " in line and "\\text{the point of ground" not in line
    ]
    assert lines
    for line in lines:
        found = re.search(
            rf"\\vec ([va])_{{.+?}} = \\vec [va]_{{\\mathrm{{(\w+)}}}} \+ "
            rf"\\(?:omega|varepsilon)_{{\\mathrm{{(\w+)}}}}.*? = {VECTOR} \+ "
            rf"\(?{NUMBER}\)? \\cdot \\vec k \\times",
            line,
        )
        assert found, line
        level, pin, link = found.group(1), found.group(2), found.group(3)
        rate = {"v": ("vx", "vy", "omega"), "a": ("ax", "ay", "alpha")}[level]
        want = [float(table[f"{pin}.{c}"][0]) for c in rate[:2]]
        got = [_float(found.group(k)) for k in (4, 5)]
        slack = 1e-9 + 1e-3 * max(map(abs, want))
        assert got == pytest.approx(want, rel=1e-3, abs=slack)
        assert _float(found.group(6)) == pytest.approx(
            _rate(table, link, rate[2]), rel=1e-3, abs=1e-9
        )


def test_a_slot_s_guide_point_and_slider_point_have_two_names() -> None:
    # v_B = v_O4 + v_BO4 + v_rB used B for two points, and ended "v_B = v_B"
    note = str(explain(assur.load(EXAMPLES / "slot_mechanism.toml"), 30.0))
    assert (
        "\\vec v_{\\mathrm{B}} = \\vec v_{\\mathrm{O4}} + "
        "\\vec v_{\\mathrm{B}_{\\mathrm{rocker}}\\mathrm{O4}} + "
        "\\vec v^{r}_{\\mathrm{B}}"
    ) in note
    assert "\\vec v_{\\mathrm{B}} = \\vec v_{\\mathrm{B}} =" not in note
    assert "\\vec a_{\\mathrm{B}} = \\vec a_{\\mathrm{B}} =" not in note


@pytest.mark.parametrize("angle", [30.0, 75.0, 200.0])
def test_a_guide_that_carries_a_couple_alone_is_said_to(angle: float) -> None:
    # the note said "N then acts x along the guide" and gave no x: N was zero
    mech = assur.load(EXAMPLES / "scotch_yoke.toml")
    note = str(explain(mech, angle))
    table = assur.forces(mech, [angle])
    force = math.hypot(float(table["guide.Fx"][0]), float(table["guide.Fy"][0]))
    alone = "N_{\\mathrm{guide}}$ is zero here" in note
    assert alone == (force < 1e-9 * float(table["B.F"][0]))
    assert alone != ("x_{\\mathrm{guide}} = \\frac" in note)
    assert alone


def test_a_tabulated_load_is_read_from_its_table_step_by_step() -> None:
    # the note gave a tabulated load's value alone: the reader could not tell it
    # came from two entries of a table, and which
    mech = assur.load(DATA / "load_tables.toml")
    note = str(explain(mech, 30.0))
    # by hand: -1000 + (30 - 0) / (90 - 0) * (-200 - (-1000)), 0 + 30 / 90 * 50
    line = (
        "\\vec Q_{\\mathrm{slider},1} = (-1000,\\ 0) + \\frac{30 - 0}{90 - 0} \\cdot "
        "\\left((-200,\\ 50) - (-1000,\\ 0)\\right) = (-733.33,\\ 16.67)\\ \\mathrm{N}"
    )
    assert line in note
    assert "linear between its entries at } 0 \\text{ and } 90\\ \\mathrm{deg}" in note
    slide = float(assur.kinematics(mech, [30.0])["guide.s"][0])
    torque = -5.0 + (slide + 0.05) / 0.05 * (5.0 - -5.0)
    assert f"= {torque:.4g}\\ \\mathrm{{N\\,m}}" in note
    said = "over the slide of guide, read at } s_{\\mathrm{guide}} = "
    assert said + f"{slide:.4g}" in note
    count, wrong = pieces_checked(note)
    assert wrong == []
    assert count >= 25


@pytest.mark.parametrize(
    ("angle", "said"),
    [
        (90.0, "(the entry of its table at } 90\\ \\mathrm{deg}"),
        # a turn is read from the table's first position: -100 deg is 260 deg
        (-100.0, "read at } -100\\ \\mathrm{deg} \\to 260\\ \\mathrm{deg}"),
    ],
)
def test_a_tabulated_load_says_where_its_table_is_read(angle: float, said: str) -> None:
    note = str(explain(assur.load(DATA / "load_tables.toml"), angle))
    assert said in note
    assert pieces_checked(note)[1] == []


def test_a_flat_stretch_of_a_load_table_is_said_to_hold() -> None:
    # the cut holds from 165 deg on through the turn's end to 10 deg: "from 165 to
    # 360" left its hold past 0 unsaid
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 210.0))
    assert (
        "(its table holds this value from } 165 \\text{ through } 360 \\text{ to } 10"
        in note
    )
    assert "\\frac{210 - 165}" not in note
    # read in the turn's first stretch, the same stretch
    early = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 5.0))
    assert "holds this value from } 165 \\text{ through } 360 \\text{ to } 10" in early


def test_a_flat_stretch_across_the_turn_s_end_is_said_whole() -> None:
    # the crank shaper's cut steps on at 350 deg and off at 190 deg: at 355 deg it
    # was said to hold "from 350 to 360", at 100 deg "from 0 to 190"
    mech = assur.load(DATA / "crank_shaper.toml")
    (cut,) = (x.force for x in mech.loads)
    on, off = (cut.table[k] for k in (3, 2))  # the steps, as the file gives them
    said = f"from }} {on:g} \\text{{ through }} 360 \\text{{ to }} {off:g}"
    for angle in (355.0, 100.0, -5.0):
        note = str(explain(mech, angle))
        assert said in note, angle
        assert pieces_checked(note)[1] == []


@pytest.mark.parametrize(
    ("stem", "angle"), [("slider_crank_exercise", 45.0), ("four_bar", 120.0)]
)
def test_a_force_s_arm_on_the_lever_is_its_line_s_distance_from_the_pole(
    stem: str, angle: float
) -> None:
    # the lever listed powers only; a textbook's lever takes moments, F times arm
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    note = str(explain(mech, angle)).split("## 6. Check by Zhukovsky's lever")[1]
    table = assur.forces(mech, [angle])
    rows = [line.split(" | ") for line in note.splitlines() if line.startswith("| $")]
    forces = [r for r in rows if r[0].startswith("| $\\vec F_{i,")]
    assert forces
    for cells in forces:
        link = re.search(r"F_\{i,\\mathrm\{(\w+)\}\}", cells[0])
        assert link
        f = np.array([float(table[f"{link.group(1)}.Fi.{c}"][0]) for c in "xy"])
        v = np.array([float(table[f"{link.group(1)}.G.v{c}"][0]) for c in "xy"])
        # the force at the image of G on the plan turned by +90 degrees: its line's
        # distance from the pole
        image = np.array([-v[1], v[0]])
        want = abs(image[0] * f[1] - image[1] * f[0]) / math.hypot(*f)
        assert _float(cells[3].strip("$")) == pytest.approx(want, rel=1e-3, abs=1e-9)
    couples = [r for r in rows if r[0].startswith("| $M_{i,")]
    assert all(cells[3] == "" for cells in couples)


def test_a_sliding_pair_s_couple_on_the_next_link_carries_its_symbol(
    tmp_path: Path,
) -> None:
    # the crank's known loads ended ", 0.3 N m": a couple without a name or sign
    path = tmp_path / "prp.toml"
    torque = '\n[[loads]]\nlink = "block1"\ntorque = 2.0\n'
    path.write_text(
        (DATA / "prp_tangent.toml").read_text(encoding="utf-8") + torque,
        encoding="utf-8",
    )
    mech = assur.load(path)
    note = str(explain(mech, 30.0)).split("## 5. The input link")[1]
    # the pair's couple is the crank's on block1: on the crank it is minus that
    found = re.search(
        rf",\\ -M_{{\\mathrm{{slot}}}} = {NUMBER}\\ \\mathrm{{N\\,m}}", note
    )
    assert found, note[:400]
    want = -float(assur.forces(mech, [30.0])["slot.M"][0])
    assert abs(want) > 1.0
    assert _float(found.group(1)) == pytest.approx(want, rel=1e-3)


def test_the_guide_s_point_under_a_sliding_middle_pair_is_derived() -> None:
    # the yoke's other points started from v_{slot_yoke}, used before it was found;
    # the slot's point is the block's pin B, the yoke's point under it B_yoke
    mech = assur.load(EXAMPLES / "scotch_yoke.toml")
    note = str(explain(mech, 30.0))
    found = re.search(
        r"\\vec v_{\\mathrm{B}_{\\mathrm{yoke}}} = \\vec v_{\\mathrm{B}_"
        rf"{{\\mathrm{{ground}}}}}} \+ \\vec v\^{{r}}_{{\\mathrm{{guide}}}} = {VECTOR}",
        note,
    )
    assert found
    table = assur.kinematics(mech, [30.0])
    # the yoke slides without turning: its every point moves as its guide's point
    want = [float(table["guide.vx"][0]), float(table["guide.vy"][0])]
    got = [_float(found.group(1)), _float(found.group(2))]
    assert got == pytest.approx(want, rel=1e-3, abs=1e-9)


@pytest.mark.parametrize("stem", sorted(p.stem for p in EXAMPLES.glob("*.toml")))
def test_no_symbol_has_two_subscripts(stem: str) -> None:
    # slot_{yoke}_{ground}: a guide's point named twice over, which TeX refuses
    mech = assur.load(EXAMPLES / f"{stem}.toml")
    try:
        note = str(explain(mech, 30.0))
    except assur.AssurError:
        pytest.skip("not at 30 deg")
    assert re.search(r"_\{\\mathrm\{[^{}]*\}\}_\{", note) is None


def test_a_slot_s_pin_is_among_its_link_s_points() -> None:
    # the crank's B appeared first as "known" in the slot's group
    note = str(explain(assur.load(EXAMPLES / "slot_mechanism.toml"), 30.0))
    crank = note.split("### Input link crank")[1].split("### Group")[0]
    assert "\\vec v_{\\mathrm{B}} = \\vec v_{\\mathrm{O2}} + " in crank
    assert "\\vec a_{\\mathrm{B}} = \\vec a_{\\mathrm{O2}} + " in crank


def test_a_fixed_guide_has_no_coriolis_term() -> None:
    # "a^k = 2 . 0 . 0.1863 = 0" for the frame's guide was noise
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0))
    assert "a^{k}_{\\mathrm{guide}}" not in note
    assert "\\omega_{\\mathrm{ground}}" not in note


def test_a_line_through_points_of_long_names_is_told_apart() -> None:
    # "along Dslot (pin)" read as one name; "along BC" is as a textbook writes it
    note = str(explain(assur.load(DATA / "slot_in_crank.toml"), 20.0))
    assert "(along D–slot (pin))" in note
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0))
    assert "(along BC)" in note


def test_a_coriolis_term_names_its_guide_as_a_link():
    # a link's name may be a number: "as 3 turns" read as a count, not a link
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 30.0))
    assert "\\text{counter-clockwise, as link lever turns}" in note
