"""The note's words and formulas say what its numbers do.

Each case is a slip a reader would copy: a formula whose sign disagrees with the
number under it, a couple printed with two values, a load left without a value, raw
TeX or an internal name in a sentence. The numbers are checked against the forces
table, not against the note.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import assur
from assur.explain import explain
from assur.explain._positions import _angle_sum
from assur.explain._tex import deg, half_turn

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"
DATA = Path(__file__).parent / "data" / "explain"


def _variant(tmp_path: Path, stem: str, *edits: tuple[str, str]) -> Path:
    """Write an example with text replaced; return its path."""
    text = (EXAMPLES / f"{stem}.toml").read_text(encoding="utf-8")
    for old, new in edits:
        assert old in text
        text = text.replace(old, new)
    path = tmp_path / f"{stem}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _friction_note(tmp_path: Path, stem: str, angle: float) -> tuple[str, str]:
    """Return a note with friction and its sentence on the balancing load's change.

    ``stem`` is an example's, or an ``omega = ...`` of the friction slider-crank.
    """
    if stem.startswith("omega"):
        path = _variant(tmp_path, "slider_crank_friction", ("omega = 200.0", stem))
    else:
        path = EXAMPLES / f"{stem}.toml"
    note = str(explain(assur.load(path), angle))
    return note, next(x for x in note.splitlines() if "friction changes it by" in x)


def _friction_sentence(tmp_path: Path, stem: str, angle: float) -> str:
    """Return the note's sentence on friction's change of the balancing load."""
    return _friction_note(tmp_path, stem, angle)[1]


FRICTION_NOTES = [
    ("slider_crank_friction", 45.0),
    ("slider_crank_locking", 90.0),
    ("four_bar_bearings", 45.0),
    ("omega = 209.4395102", 45.0),
]
"""Notes whose friction changes the balancing load: examples, and a speed whose
note writes fewer digits than it holds."""


def _number(note: str, before: str) -> float:
    """Return the number printed right after ``before`` (a literal text)."""
    found = re.search(
        re.escape(before) + r"\s*(-?[0-9.]+(?:\\cdot 10\^\{-?\d+\})?)", note
    )
    assert found, before
    mantissa, _, power = found.group(1).partition("\\cdot 10^{")
    return float(mantissa) * 10.0 ** float(power.rstrip("}") or 0)


def test_an_input_slider_gets_its_guide_s_couple() -> None:
    # the note gave the balancing force and the normal reaction, not the couple
    mech = assur.load(DATA / "ram_only.toml")
    note = str(explain(mech, 0.01))
    couple = _number(note, r"M_{\mathrm{drive}} = -\sum M_{\mathrm{drive}} =")
    want = float(assur.forces(mech, [0.01])["drive.M"][0])
    assert want == pytest.approx(-0.3)
    assert couple == pytest.approx(want, rel=1e-3)


@pytest.mark.parametrize("angle", [45.0, 200.0])
def test_the_force_sum_of_a_sliding_middle_pair_s_links(angle: float) -> None:
    # the pair pushes its first link with -N n: the formula wrote + for both links
    mech = assur.load(EXAMPLES / "scotch_yoke.toml")
    note = str(explain(mech, angle))
    table = assur.forces(mech, [angle])
    slot = mech.joint("slot")
    first, second = slot.links
    for link, sign in ((first, "-"), (second, "+")):
        line = next(
            x
            for x in note.splitlines()
            if x.startswith("$$ \\vec F_")
            and f",\\mathrm{{{link}}}}} = -\\left(\\sum \\vec F_{{\\mathrm{{known}}}}"
            in x
        )
        assert f"{sign} N_{{\\mathrm{{slot}}}}\\vec n\\right)" in line, line
    # the first link's printed sum is minus the table's reaction in its outer pair
    outer = next(j for j in mech.joints if first in j.links and j.name != "slot")
    line = next(
        x for x in note.splitlines()
        if f",\\mathrm{{{first}}}}} = -\\left(\\sum" in x
    )  # fmt: skip
    printed = line.split("= ")[2].split("\\ \\mathrm{N}")[0]
    fx, fy = (float(v) for v in printed.strip("()").split(",\\ "))
    sign = 1.0 if outer.links[1] == first else -1.0
    assert sign * table[f"{outer.name}.Fx"][0] == pytest.approx(fx, abs=0.01)
    assert sign * table[f"{outer.name}.Fy"][0] == pytest.approx(fy, abs=0.01)


def test_a_slider_that_is_its_pair_s_first_link_has_one_couple(tmp_path: Path) -> None:
    # M_guide was printed as -10.55 and then as 10.55
    path = _variant(
        tmp_path,
        "slider_crank_exercise",
        ('links = ["ground", "slider"]', 'links = ["slider", "ground"]'),
    )
    mech = assur.load(path)
    note = str(explain(mech, 100.0))
    want = float(assur.forces(mech, [100.0])["guide.M"][0])
    printed = [
        float(x)
        for x in re.findall(
            r"M_\{\\mathrm\{guide\}\} = "
            r"(?:\\sum M_\{\\mathrm\{guide\}\} = )?(-?[0-9.]+)",
            note,
        )
    ]
    assert len(printed) >= 2
    assert printed == pytest.approx([want] * len(printed), rel=1e-3, abs=1e-9)


def _prose(note: str) -> list[str]:
    """Return the note's sentences with their mathematics taken out."""
    text = re.sub(r"\$\$.*?\$\$", "", note, flags=re.S)
    text = re.sub(r"\$[^$]*\$", "", text)
    return [line for line in text.splitlines() if line.strip()]


@pytest.mark.parametrize(
    ("path", "angle"),
    [
        (DATA / "slot_in_crank.toml", 20.0),
        (DATA / "dead_centre.toml", 32.230952635),
        (EXAMPLES / "slot_mechanism.toml", 50.0),
        (EXAMPLES / "class3.toml", 100.0),
        (EXAMPLES / "whitworth.toml", 50.0),
    ],
    ids=lambda x: getattr(x, "stem", x),
)
def test_sentences_hold_no_tex_and_no_internal_names(path: Path, angle: float) -> None:
    # "the root being 4.218 \cdot 10^{-7} m", "The pin slot~pin lies on ..."
    with pytest.warns() if path.stem == "dead_centre" else _Nothing():
        note = str(explain(assur.load(path), angle))
    for line in _prose(note):
        assert not re.search(r"\\|\^\{|_\{|~", line), line


class _Nothing:
    def __enter__(self) -> None:
        return None

    def __exit__(self, *args: object) -> None:
        return None


def test_a_load_that_is_zero_here_is_written_so() -> None:
    # the ram's load table gives 0 at 50 deg: the line was the bare symbol
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 50.0))
    assert (
        r"$$ \vec Q_{\mathrm{ram},1} = (0,\ 0)\ \mathrm{N},\quad \text{(its table "
        r"holds this value from } 15 \text{ to } 160\ \mathrm{deg}\text{)} $$"
    ) in note
    for line in note.splitlines():
        # a load's line (force, reaction, couple) always carries its value
        assert not re.fullmatch(r"\$\$ -?(\\vec [FQN]|[MT])_[^=]* \$\$", line), line


def test_an_external_force_is_no_force_of_one_link_on_another() -> None:
    # F_{left_rod,1} read as "the force of link left_rod on link 1"; at P_1, not C
    mech = assur.load(EXAMPLES / "five_bar_two_cranks.toml")
    note = str(explain(mech, [60.0, 120.0]))
    (load,) = mech.loads
    assert (load.link, load.at) == ("left_rod", "C")
    line = next(x for x in note.splitlines() if "Q_{\\mathrm{left\\_rod},1}" in x)
    assert line.startswith(
        "$$ \\vec Q_{\\mathrm{left\\_rod},1} = (0,\\ -50)\\ \\mathrm{N},"
    )
    assert "\\text{at}\\ \\mathrm{C} = " in line
    assert "P_{1}" not in note


@pytest.mark.parametrize("omega", [200.0, -200.0])
def test_friction_s_share_of_the_balancing_torque(tmp_path: Path, omega: float) -> None:
    # "friction takes -15.4 more, -18.2 % of it" when the crank turned clockwise
    path = _variant(
        tmp_path, "slider_crank_friction", ("omega = 200.0", f"omega = {omega}")
    )
    mech = assur.load(path)
    note = str(explain(mech, 45.0))
    sentence = next(x for x in note.splitlines() if "friction changes it by" in x)
    # clockwise the driver brakes here: it takes that power less back
    said = "W more" if omega > 0 else "W less back"
    power = float(re.search(rf"= (-?[0-9.]+)\$ {said}", sentence).group(1))  # type: ignore[union-attr]
    lost = -float(assur.forces(mech, [45.0])["friction.power"][0])
    assert lost > 0.0
    assert power == pytest.approx(lost, rel=1e-3)


@pytest.mark.parametrize(
    ("stem", "angle", "said"),
    [
        ("slider_crank_friction", 45.0, "W more"),
        ("slider_crank_locking", 90.0, "W less back"),
        ("omega = 209.4395102", 45.0, "W more"),
        ("omega = 100.0", 45.0, "W more"),
    ],
)
def test_friction_s_power_is_said_as_the_driver_sees_it(
    stem: str, angle: float, said: str, tmp_path: Path
) -> None:
    # a braking driver "supplies 472 W more" read as if it drove; and 16.2 * 200
    # was written 3239.46, a product no hand gives (nor 17.76234 * 209.44)
    sentence = _friction_sentence(tmp_path, stem, angle)
    product = re.search(
        r"= (-?[0-9.]+) \\cdot \(?(-?[0-9.]+)\)? = (-?[0-9.]+)\$ " + said, sentence
    )
    assert product is not None, sentence
    a, b, c = (float(x) for x in product.groups())
    assert a * b == pytest.approx(c, abs=0.005)  # to the last digit written


def _redone(exact: float, written: str) -> bool:
    """Return whether ``written`` is ``exact`` rounded to its last written digit."""
    places = len(written.partition(".")[2])
    return abs(exact - float(written)) <= 0.5 * 10.0**-places * (1 + 1e-9)


@pytest.mark.parametrize(("stem", "angle"), FRICTION_NOTES)
def test_friction_s_change_is_redone_with_its_written_numbers(
    stem: str, angle: float, tmp_path: Path
) -> None:
    # "100.82 - 84.63 = 16.19731", and omega written 209.44 in the note but
    # 209.4395 in the power: no hand redoes either; and the difference, written
    # once, reads alike in its subtraction, its share and the power's factor
    # (16.2 and 16.19731 were taken for two torques)
    note, sentence = _friction_note(tmp_path, stem, angle)
    number = r"\(?(-?[0-9.]+)\)?"
    subtraction = re.search(rf"= {number} - {number} = {number}\\ ", sentence)
    share = re.search(rf"\\frac\{{{number}\}}\{{{number}\}} = {number}\\,\\%", sentence)
    power = re.search(rf"= {number} \\cdot {number} = {number}\$ W", sentence)
    assert subtraction is not None, sentence
    assert share is not None, sentence
    assert power is not None, sentence
    a, b, c = subtraction.groups()
    assert _redone(float(a) - float(b), c)
    part, whole, percent = share.groups()
    assert (part, whole) == (c.lstrip("-"), b.lstrip("-"))
    assert _redone(100.0 * float(part) / float(whole), percent)
    change, omega, product = power.groups()
    assert change == c
    assert _redone(float(change) * float(omega), product)
    # omega as the note's data give it, and as its lever divides by it
    data = re.search(r"\\omega_\{[^}]*\}\} = (-?[0-9.]+)\\ \\mathrm\{rad/s\}", note)
    assert data is not None
    assert omega == data.group(1)


def test_friction_rows_per_unit_speed_are_not_called_losses(tmp_path: Path) -> None:
    # per unit speed of one driver, a pair's friction power may be positive
    text = (EXAMPLES / "five_bar_two_cranks.toml").read_text(encoding="utf-8")
    text = re.sub(r'(kind = "revolute"\n)', r"\1friction = 0.1\nradius = 0.006\n", text)
    path = tmp_path / "rubbed.toml"
    path.write_text(text, encoding="utf-8")
    note = str(explain(assur.load(path), [60.0, 120.0]))
    assert "(a loss, so negative)" not in note
    assert note.count("of either sign") == 2  # one lever per driver
    one = str(explain(assur.load(EXAMPLES / "four_bar_bearings.toml"), 30.0))
    assert "(a loss, so negative)" in one


def test_answers_undefined_here_are_not_said_to_agree() -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    note = str(explain(mech, 45.0, answers={"slider.ic.x": 0.3}))
    assert "undefined here" in note
    assert "agrees" not in note.split("7. The given answers")[1]
    note = str(explain(mech, 45.0, answers={"slider.ic.x": 0.3, "crank.omega": 200}))
    assert "every other given answer agrees (1 undefined here)" in note


def test_the_given_answers_carry_their_units() -> None:
    # the table of answers had bare numbers: rad/s, m/s^2, N and N m alike
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    given = {"rod.omega": -54.2, "B.a": 2960.0, "rod.Fi": 1282.6, "driver.torque": 5}
    part = str(explain(mech, 45.0, answers=given)).split("7. The given answers")[1]
    assert "| quantity | given | here | unit | difference |  |" in part
    units = {
        line.split(" | ")[0].strip("| "): line.split(" | ")[3]
        for line in part.splitlines()
        if line.startswith("| ") and "$" in line
    }
    assert units == {
        "rod.omega": r"$\mathrm{rad/s}$",
        "B.a": r"$\mathrm{m/s^2}$",
        "rod.Fi": r"$\mathrm{N}$",
        "driver.torque": r"$\mathrm{N\,m}$",
    }


def test_the_note_s_values_are_the_table_s() -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    note = explain(mech, 45.0)
    table = assur.forces(mech, [45.0])
    assert list(note.values) == list(table.columns)
    for name in ("driver.torque", "B.F", "rod.alpha"):
        assert note.values[name] == float(table[name][0])


def test_a_plan_draws_the_guide_s_point_under_a_slider() -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import plans

    # the chain of a slot in a moving crank started at an unmarked point
    table = assur.kinematics(assur.load(DATA / "slot_in_crank.toml"), [20.0])
    for draw in (plans.velocity_plan, plans.acceleration_plan):
        ax = draw(table)
        try:
            labels = [t.get_text() for t in ax.texts]
            legend = [t.get_text() for t in ax.get_legend().get_texts()]
        finally:
            plt.close(ax.figure)
        assert "the guide's point under the slider" in legend
        assert any("slot" in x and "crank" in x for x in labels), labels


def test_a_prp_polygon_has_no_tangential_parts() -> None:
    # its outer pairs slide: only the normal forces are unknown
    note = str(explain(assur.load(DATA / "prp_tangent.toml"), 50.0))
    polygon = next(x for x in note.splitlines() if x.startswith("Force polygon"))
    assert "tangential" not in polygon
    assert polygon.startswith("Force polygon of the group: the known forces and two ")
    assert r"\sum \vec F^{t}" not in note


@pytest.mark.parametrize(
    ("path", "angle"),
    [(EXAMPLES / "slot_mechanism.toml", 50.0),  # the slot's block: no load
     (EXAMPLES / "five_bar_two_cranks.toml", [60.0, 120.0]),
     (EXAMPLES / "class3.toml", 100.0)],
    ids=lambda x: getattr(x, "stem", str(x)),
)  # fmt: skip
def test_a_sum_of_no_terms_is_written_once(path: Path, angle) -> None:
    # a link with no known load wrote "\sum M_C = 0 = 0"
    note = str(explain(assur.load(path), angle))
    assert "= 0 = 0" not in note


def test_a_fixed_pivot_reached_through_its_link_sums_to_zero():
    # the sum was judged against its own size: (-5.879 * 10^{-18}, 0) for the
    # velocity of a frame pivot, whose size the same line gave as 0; a triad's
    # link now starts from its pin to the frame, whose motion is known
    note = str(explain(assur.load(EXAMPLES / "class3.toml"), 0.0))
    line = next(x for x in note.splitlines() if x.startswith(r"$$ \vec v_{\mathrm{F}}"))
    assert line == (
        r"$$ \vec v_{\mathrm{F}} = (0,\ 0)\ \mathrm{m/s},\quad "
        r"\text{known: a point of ground} $$"
    )
    found = re.findall(r"10\^\{-1[3-9]\}", note.replace(note.split("lever}")[-1], ""))
    assert not found
    # a dyad's equation whose terms cancel (a slot tangent to the crank's circle)
    tangent = str(explain(assur.load(DATA / "prp_tangent.toml"), 0.0))
    line = next(x for x in tangent.splitlines() if r"\vec a_{\mathrm{C}} = " in x)
    assert (
        r"= (0,\ 0)\ \mathrm{m/s^2},\quad a_{\mathrm{C}} = 0\ \mathrm{m/s^2} $$" in line
    )


def test_a_dollar_in_the_name_is_bare_in_the_page_s_title():
    mech = dataclasses.replace(assur.catalog.four_bar(), name="$x$ bar")
    page = explain(mech, 45.0).to_html()
    assert (
        "<title>$x$ bar at crank angle 45 deg: the analysis explained</title>" in page
    )


@pytest.mark.parametrize(
    ("stem", "angle", "where"),
    [
        ("four_bar", 100.0, "crank angle 100 deg"),
        (
            "five_bar_two_cranks",
            [60.0, 120.0],
            "driver positions left_crank at 60 deg and right_crank at 120 deg",
        ),
    ],
)
def test_the_title_says_which_position_the_note_is_for(stem, angle, where) -> None:
    note = explain(assur.load(EXAMPLES / f"{stem}.toml"), angle)
    assert f"at {where}" in note.title
    assert str(note).splitlines()[0].startswith("# ")
    assert f"at {where}" in str(note).splitlines()[0]
    page = note.to_html()
    for tag in ("title", "h1"):
        shown = page.split(f"<{tag}>")[1].split(f"</{tag}>")[0]
        assert f"at {where}" in shown
    latex = note.to_latex().split("\\title{")[1].split("}\n")[0]
    assert f"at {where}" in latex.replace("\\_", "_")


def test_a_slider_driven_note_s_title_gives_its_position_in_m() -> None:
    note = explain(assur.load(DATA / "slider_driven.toml"), 0.03)
    assert note.title.endswith("at driver position 0.03 m: the analysis explained")


CRANK_ONLY = """name = "crank"
[links.crank]
[joints.A]
kind = "revolute"
links = ["ground", "crank"]
at = [0.0, 0.0]
[[drivers]]
joint = "A"
omega = 1.0
"""


def test_the_structure_s_counts_agree_with_their_nouns() -> None:
    # "$p_4 = 1$ higher pairs" and "$n = 1$ moving links"
    note = str(explain(assur.load(EXAMPLES / "slot_mechanism.toml"), 30.0))
    assert "$p_5 = 5$ lower pairs and $p_4 = 1$ higher pair." in note
    crank = str(explain(assur.loads(CRANK_ONLY), 30.0))
    assert "$n = 1$ moving link, $p_5 = 1$ lower pair and $p_4 = 0$ higher pairs." in (
        crank
    )


def test_an_rpr_note_says_why_its_links_angles_differ():
    """'Both links turn together' was followed by two different angles (26.8 and
    -169.09 deg) with no word of how each is measured."""
    text = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 60.0))
    assert "their angles below differ by a constant" in text


@pytest.mark.parametrize(
    ("path", "angle"),
    [
        (EXAMPLES / "class3.toml", 70.0),
        (Path(__file__).parent / "data" / "edge" / "triadP.toml", 300.0),
    ],
)
def test_a_triad_s_note_says_whose_load_each_unknown_is(path: Path, angle: float):
    # twelve equations in F_x^B ... with no word of which link's force on which
    from assur.plan import compile_plan

    mech = assur.load(path)
    note = str(explain(mech, angle))
    (line,) = [x for x in note.splitlines() if x.startswith("The unknowns are")]
    assert "each of the joint's first link on its second" in line
    plan = compile_plan(mech)
    (triad,) = plan.groups
    bodies = {plan.body(x) for x in triad.links}
    told = dict(
        part.split(": ") for part in line.rstrip(".").split(". ")[1].split("; ")
    )
    # every joint of the triad's links is told, with the first link on the second
    want = {
        name: f"{plan.bodies[pair.first]} on {plan.bodies[pair.second]}"
        for name, pair in plan.pairs.items()
        if {pair.first, pair.second} & bodies
    }
    assert told == want
    assert len(told) == 6
    sliding = any(pair.kind == "P" for pair in plan.pairs.values())
    assert ("normal force $N^{J}$" in line) == sliding


def test_round_off_is_told_as_zero() -> None:
    # the yoke at mid-stroke: its inertia force was (-1.492e-11, -2.63e-12) N
    path = Path(__file__).parent / "data" / "edge" / "inclined_scotch_yoke.toml"
    mech = assur.load(path)
    table = assur.forces(mech, [70.0])
    pin = np.hypot(table["B.ax"][0], table["B.ay"][0])
    yoke = np.hypot(table["yoke.G.ax"][0], table["yoke.G.ay"][0])
    assert 0.0 < yoke < 1e-9 * pin  # round-off, not nothing
    note = str(explain(mech, 70.0))
    assert r"\vec F_{i,\mathrm{yoke}} = (0,\ 0)\ \mathrm{N}" in note
    assert r"a_{G_{\mathrm{yoke}}} = 0\ \mathrm{m/s^2}" in note
    # no power of ten below 1e-9, the lever's relative check neither (0 %)
    tiny = [x for x in note.splitlines() if re.search(r"10\^\{-(1\d|9)\}", x)]
    assert tiny == []


def test_a_load_s_point_of_round_off_is_told_as_zero() -> None:
    # the Scotch yoke at 180 deg: its yoke's centre, on the slide's axis, was
    # "at G = (-1.388 \cdot 10^{-17}, 0)", the machine's round-off of x = 0
    mech = assur.load(EXAMPLES / "scotch_yoke.toml")
    table = assur.kinematics(mech, [180.0])
    x = table["yoke.G.x"][0]
    assert abs(x) < 1e-12 * table.plan.scale  # round-off, of either sign
    note = str(explain(mech, 180.0))
    assert r"\text{at}\ G_{\mathrm{yoke}} = (0,\ 0)" in note
    assert not re.search(r"10\^\{-(1\d|9)\}", note)


def test_a_small_rate_the_user_gave_is_kept() -> None:
    # an epsilon of 1e-7 beside an omega of 20 was written 0 as round-off
    mech = assur.load(EXAMPLES / "four_bar.toml")
    driver = dataclasses.replace(mech.drivers[0], epsilon=1e-7)
    note = str(explain(dataclasses.replace(mech, drivers=(driver,)), 45.0))
    assert r"\varepsilon_{\mathrm{crank}} = 1 \cdot 10^{-7}\ \mathrm{rad/s^2}" in note


def test_an_answer_a_hair_below_ours_differs_by_plus_zero() -> None:
    # "-0.000 %" stood in the answers' table for a given value 1e-9 below the note's
    from assur.explain._answers import _verdict

    assert _verdict(84.625 * (1 - 1e-9), 84.625) == ("$+0.000$ %", "agrees")
    assert _verdict(84.625 * (1 - 1e-4), 84.625) == ("$-0.010$ %", "agrees")


def test_a_sliding_pair_s_couple_carries_its_unit() -> None:
    # "M_{guide} = -0.0005197 (joint guide)": the couple's figure stood bare
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 30.0))
    lines = [x for x in note.splitlines() if "\\text{(joint guide)}" in x]
    assert lines
    for line in lines:
        assert re.search(r"M_\{\\mathrm\{guide\}\} = [^,]*\\mathrm\{N\\,m\}", line), (
            line
        )


def test_a_turning_link_s_arm_is_the_same_vector_in_both_terms() -> None:
    # "200 \cdot (-0.05233, 0.05233)" stood for omega x r_AB beside "200^2 \cdot
    # (0.05233, 0.05233)": r turned by 90 degrees and r, under one symbol
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0))
    line = next(x for x in note.splitlines() if x.startswith(r"$$ \vec a_{\mathrm{B}}"))
    arm = r"(0.05233,\ 0.05233)"
    assert rf"0 \cdot \vec k \times {arm} - 200^2 \cdot {arm}" in line
    assert r"\vec k \times (x,\ y) = (-y,\ x)" in note


def test_a_triad_s_points_start_from_known_pins_each_once() -> None:
    # v_C and v_D stood bare, the frame's pivots F and G were derived from them
    # (to 0), and v_D was written twice
    note = str(explain(assur.load(EXAMPLES / "class3.toml"), 30.0))
    triad = note.split("### Group triad")[1].split("## 3.")[0]
    for k in "va":
        lines = [x for x in triad.splitlines() if x.startswith(rf"$$ \vec {k}_{{")]
        named = [re.match(rf"\$\$ \\vec {k}_\{{(.*?)\}} = ", x)[1] for x in lines]
        assert len(named) == len(set(named)), named
        bare = [
            x for x in lines if r" + \omega" not in x and r" + \varepsilon" not in x
        ]
        # every point given without a formula is a pin on a link outside the group
        assert [re.match(rf"\$\$ \\vec {k}_\{{(.*?)\}} = ", x)[1] for x in bare] == [
            r"\mathrm{B}",
            r"\mathrm{F}",
            r"\mathrm{G}",
        ]
        assert all(r"\text{known: a point of " in x for x in bare)


def test_a_triad_starts_only_from_pins_to_links_known_before_it() -> None:
    # H joins left_rocker to a dyad solved after the triad: it is not known yet
    note = str(explain(assur.load(DATA / "triad_then_dyad.toml"), 30.0))
    triad = note.split("### Group triad")[1].split("### Group")[0]
    known = re.findall(r"\\text\{known: a point of (\w+)\}", triad)
    assert set(known) == {"crank", "ground"}
    assert r"\vec v_{\mathrm{H}} = \vec v_{\mathrm{F}} + " in triad


def test_a_slot_s_two_pairs_are_told_apart() -> None:
    # the sliding pair and the pin were both "(joint B)"; the block was "B\ block"
    note = str(explain(assur.load(EXAMPLES / "slot_mechanism.toml"), 30.0))
    assert r"\text{(joint B: the block in the slot)}" in note
    assert r"\text{(joint B: the pin in the block)}" in note
    assert r"\text{(joint B)}" not in note
    assert r"\mathrm{B\ (block)}" in note
    assert r"\vec d_{B (block)}" not in note


def test_an_input_slider_s_forces_are_written_term_by_term() -> None:
    # "F_b = -\sum F.e = -15.69 = -15.69 N", and N_guide first seen as a divisor
    note = str(explain(assur.load(DATA / "slider_driven.toml"), 0.03))
    driver = note.split("## 5. The input link")[1].split("## 6.")[0]
    lines = driver.splitlines()
    force = next(x for x in lines if x.startswith(r"$$ F_{b} = "))
    assert r"-15.69 = -15.69" not in force
    assert force.count(r"\cdot 0.9659") == 3  # three loads along e
    normal = next(x for x in lines if x.startswith(r"$$ N_{\mathrm{guide}} = "))
    assert r"= 3.239\ \mathrm{N}" in normal
    assert lines.index(normal) < next(
        i for i, x in enumerate(lines) if x.startswith(r"$$ x_{\mathrm{guide}}")
    )


def test_the_note_s_headings_go_down_one_level_at_a_time() -> None:
    for stem, angle in (("five_bar_two_cranks", [60.0, 120.0]), ("class3", 30.0)):
        note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), angle))
        levels = [
            len(x) - len(x.lstrip("#")) for x in note.splitlines() if x[:1] == "#"
        ]
        assert all(b <= a + 1 for a, b in itertools.pairwise(levels))
    two = str(explain(assur.load(EXAMPLES / "five_bar_two_cranks.toml"), [60.0, 120.0]))
    assert "## 5. The input links\n" in two


def test_round_off_of_a_force_or_a_speed_at_a_dead_centre_is_zero() -> None:
    # at 0 deg the guide's normal force is round-off: it was written (0, 1.426 *
    # 10^{-14}) N in the polygon and (0, 1.626 * 10^{-14}) N among the reactions, the
    # slider's speed 5.1 * 10^{-16} m/s and its power 8.3 * 10^{-13} W on the lever
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 0.0))
    tiny = [x for x in note.splitlines() if re.search(r"10\^\{-(1\d|9)\}", x)]
    assert tiny == []
    lines = [
        x
        for x in note.splitlines()
        if r"\vec F_{\mathrm{ground},\mathrm{slider}} =" in x
    ]
    assert lines
    assert all(r"= (0,\ 0)\ \mathrm{N}" in x for x in lines)


def test_the_title_of_a_note_at_minus_zero_reads_zero() -> None:
    # "--angle -0" titled the note "at crank angle -0 deg"
    note = explain(assur.load(EXAMPLES / "four_bar.toml"), -0.0)
    assert str(note).splitlines()[0] == (
        "# Crank-rocker four-bar at crank angle 0 deg: the analysis explained"
    )


# a step "a ± b = c" of angles in degrees, as printed; a left edge so that no step
# starts inside a number
ANGLE_STEP = re.compile(
    r"(?<![\d.-])(?=(-?[\d.]+)\^\\circ ([+-]) \(?(-?[\d.]+)\^\\circ\)? = "
    r"(-?[\d.]+)\^\\circ)"
)


@pytest.mark.parametrize(
    ("path", "angle"),
    [(EXAMPLES / "whitworth.toml", 160.0), (DATA / "crank_shaper.toml", 100.0)],
)
def test_the_slotted_lever_s_turn_adds_up_in_degrees(path: Path, angle: float) -> None:
    # the RPR dyad's turn printed "theta_n = theta_D + psi = -177.5" for 92.5 + 90
    # and "theta_n - nu = -177.5 - 166.1 = 16.39": both right only modulo 360
    mech = assur.load(path)
    note = str(explain(mech, angle))
    line = next(x for x in note.splitlines() if "\\theta_n = \\theta_D" in x)
    steps = [m.groups() for m in ANGLE_STEP.finditer(line)]
    assert len(steps) >= 2, line
    for a, sign, b, c in steps:
        total = float(a) + float(b) if sign == "+" else float(a) - float(b)
        # each of the three printed to 0.01 at least: half of it each way
        assert total == pytest.approx(float(c), abs=0.015 + 1e-9), line
    # the last value is the block's turn from the reference pose (it has no axis)
    turn = float(assur.kinematics(mech, [angle])["block.angle"][0])
    last = float(steps[-1][3])
    assert -180.0 < last <= 180.0
    assert abs(math.remainder(last - turn, 360.0)) < 0.01


def test_a_half_turn_is_written_and_summed_alike(tmp_path: Path) -> None:
    # the lever's pivot level with the crank's centre: at -180 deg D points left,
    # 3.5e-18 below the axis; theta_D was written 180 deg and summed as -180 deg
    pivot = 'links = ["ground", "lever"]\nat = '
    path = _variant(tmp_path, "whitworth", (pivot + "[0.0, 0.03]", pivot + "[0.03, 0]"))
    note = str(explain(assur.load(path), -180.0))
    written = re.search(r"\\theta_D = (-?[\d.]+)\^\\circ", note)
    summed = re.search(r"\\theta_D [+-] \\psi = (-?[\d.]+)\^\\circ", note)
    assert written is not None
    assert summed is not None
    assert written.group(1) == summed.group(1) == "180"


def test_an_angle_of_minus_zero_to_the_left_is_summed_as_written() -> None:
    # atan2(-0.0, -1) is -pi: written 180 deg, it was summed as -180 deg
    theta = math.atan2(-0.0, -1.0)
    assert deg(half_turn(theta)) == deg(theta) == "180^\\circ"
    assert _angle_sum(half_turn(theta), "+", 0.5, wrap=False).startswith("180^")
    text = _angle_sum(0.5, "-", theta, wrap=False)
    first, second, total = (float(x) for x in re.findall(r"-?[\d.]+(?=\^)", text))
    assert second == 180.0
    assert first - second == pytest.approx(total, abs=0.015)


def test_a_load_table_s_words_are_set_off_alike() -> None:
    # on a step the words followed the value with a bare \quad, off a step with
    # ",\quad": "(0, 0) N\quad (its table steps here" beside "N,\quad (its table"
    mech = assur.load(DATA / "crank_shaper.toml")
    (cut,) = (x.force for x in mech.loads)
    for angle in (100.0, *cut.table[1:4]):
        note = str(explain(mech, angle))
        said = [x for x in note.splitlines() if "\\text{(its table" in x]
        assert said, angle
        for line in said:
            assert line.count("\\text{(its table") == line.count(
                ",\\quad \\text{(its table"
            ), line


def test_an_angle_sum_is_wrapped_only_where_asked_and_brackets_a_negative() -> None:
    # theta_n is left as its sum gives it (the next line subtracts from it as
    # printed); a negative operand is bracketed, "a - (-b)", never "a - -b"
    a, b = math.radians(150.0), math.radians(60.0)
    kept = _angle_sum(a, "+", b, wrap=False)
    wrapped = _angle_sum(a, "+", b, wrap=True)
    assert wrapped.startswith(kept)
    assert "360" not in kept
    assert "360" in wrapped
    assert re.search(r"- \(-[\d.]+\^\\circ\)", _angle_sum(a, "-", -b, wrap=True))


def _degrees(member: str) -> float | None:
    """Return a member of an equality chain worked out (deg), or None for a symbol."""
    text = member.replace("^\\circ", "").replace("(", "").replace(")", "").strip()
    if not re.fullmatch(r"-?[\d.]+(?: [+-] -?[\d.]+)*", text):
        return None
    parts = text.split(" ")
    total = float(parts[0])
    for sign, value in zip(parts[1::2], parts[2::2], strict=True):
        total += float(value) if sign == "+" else -float(value)
    return total


@pytest.mark.parametrize(
    ("a", "sign", "b"), [(150.0, "+", 60.0), (-80.46, "-", 106.32)]
)
def test_a_wrapped_angle_sum_equates_only_equal_angles(
    a: float, sign: str, b: float
) -> None:
    # it read "-80.46 - 106.32 = -186.78 + 360 = 173.22": the chain's middle
    # equated -186.78 deg with 173.22 deg, a whole turn apart
    text = _angle_sum(math.radians(a), sign, math.radians(b), wrap=True)
    assert "360" in text
    for chain in text.split(","):
        chain = re.sub(r"\\ \\text\{[^}]*\}\\ ", "", chain)
        values = [_degrees(m) for m in chain.split(" = ")]
        worked = [v for v in values if v is not None]
        assert len(worked) >= 2, text
        for x, y in itertools.pairwise(worked):
            assert x == pytest.approx(y, abs=0.015), text


@pytest.mark.parametrize(("force", "word"), [(1e-170, "drives"), (-1e-170, "brakes")])
def test_whether_the_balancing_load_drives_is_told_by_signs(tmp_path, force, word):
    # the sign of value * speed was read, and 6.7e-172 * 1e-170 is 0: a crank that
    # drives the slider against its load was said to brake
    text = (EXAMPLES / "slider_crank_exercise.toml").read_text(encoding="utf-8")
    text = text.replace("omega = 200.0", "omega = 1e-170")
    text += f'\n[[loads]]\nlink = "slider"\nat = "C"\nforce = [{force}, 0.0]\n'
    path = tmp_path / "tiny.toml"
    path.write_text(text)
    mech = assur.load(path)
    # the slider moves to -x at 45 deg: a load to +x resists, and the crank drives
    assert assur.kinematics(mech, [45.0])["C.vx"][0] < 0.0
    note = str(explain(mech, 45.0))
    assert f"It {word} the link" in note
