"""Friction in the explanatory note: every number it prints against the table.

The note of a mechanism with friction adds, for each group, the friction load of
each pair with its numbers, how repeated substitution finds the reactions' sizes
(step by step, and Newton's where it does not settle), and the
friction terms of the balancing load and of Zhukovsky's lever. The parser of
:mod:`tests.test_explain` reads them; here they are checked at many positions.
"""

from __future__ import annotations

import functools
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.explain import explain
from assur.explain._friction_text import rubbing
from assur.explain._group_friction_text import (
    _newton_steps,
    _spaced,
    _unsettled,
    group_sizing,
    newton_start,
    without_own,
)

from .test_explain import EXAMPLES, check, printed, statements, tex

FRICTION = EXAMPLES / "slider_crank_friction.toml"
BEARINGS = EXAMPLES / "four_bar_bearings.toml"
ANGLES = [0.0, 45.0, 100.0, 170.0, 200.0, 260.0, 315.0]


def _note_and_table(path, angle: float) -> tuple[str, assur.Table]:
    mech = assur.load(path)
    try:
        table = assur.forces(mech, [angle])
    except assur.AssurError as err:  # a position that locks, or a dead centre
        pytest.skip(f"{path.stem} at {angle} deg: {err}")
    return str(explain(mech, angle)), table


@pytest.mark.parametrize("path", [FRICTION, BEARINGS], ids=lambda p: p.stem)
@pytest.mark.parametrize("angle", ANGLES)
def test_every_friction_number_agrees_with_the_table(path, angle: float) -> None:
    note, table = _note_and_table(path, angle)
    check(note, table)
    shown = [lhs for lhs, last in statements(note) if printed(last) is not None]
    for pair in table.plan.pairs.values():
        if pair.friction > 0.0:
            # its load in its group (or the input link), and its power on the lever
            letter = "M" if pair.kind == "R" else "F"
            assert shown.count(f"{letter}_{{f,{tex(pair.name)}}}") >= 2, pair.name
    # the balancing load by both methods, the frictionless one and the losses
    lever, ideal = "M_{b}^{\\mathrm{lever}}", "M_{b}^{\\mathrm{ideal}}"
    for symbol in ("M_{b}", lever, ideal, "\\sum P_{f}"):
        assert symbol in shown, symbol
    # every group with friction says how it was solved
    assert note.count("found by repeated substitution") == _rubbing_groups(path, angle)


def _rubbing_groups(path, angle: float) -> int:
    """How many groups of the mechanism have a pair with friction."""
    from assur.explain._solve import position

    result = position(assur.load(path), angle).result
    assert result is not None
    return sum(any(p.friction > 0.0 for p in rec.pairs) for rec in result.groups)


def test_the_friction_loads_are_written_out() -> None:
    note, table = _note_and_table(FRICTION, 45.0)
    row = {c: float(table[c][0]) for c in table.columns}
    # the journal at B: rho = f r, the rod turning backwards relative to the crank
    assert (
        r"\rho_{\mathrm{B}} = f_{\mathrm{B}} r_{\mathrm{B}} = 0.1 \cdot 0.008" in note
    )
    assert r"\omega_{\mathrm{rod}} - \omega_{\mathrm{crank}} = -54.21 - 200" in note
    assert (
        r"\,\mathrm{sgn}(\omega_{\mathrm{rod}} - \omega_{\mathrm{crank}}) = -0.0008 "
        rf"\cdot {row['B.F']:.2f} \cdot (-1) = {row['B.Mf']:.3f}\ \mathrm{{N\,m}}"
    ) in note
    # the guide: the slider moving left, friction pushes it right
    assert rf"-0.15 \cdot {np.hypot(row['guide.Fy'], 0):.2f} \cdot (-1)" in note
    # the driver's own bearing is overcome by the balancing torque
    assert r"M_{b} = -\sum M_{\mathrm{A}} - M_{f,\mathrm{A}}" in note
    assert "19.14" in note.split("Without friction")[1].split("\n")[0]


def test_the_substitution_starts_frictionless_and_settles_on_the_table() -> None:
    # the slider-crank has one group: its start is the frictionless solution, its
    # rows the hand method's steps, its last the table's sizes
    note, table = _note_and_table(FRICTION, 45.0)
    ideal = assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [45.0])
    head = (
        r"| step | $F_{\mathrm{rod},\mathrm{slider}}$ | "
        r"$F_{\mathrm{crank},\mathrm{rod}}$ | $\vert N_{\mathrm{guide}}\vert $ |"
    )
    rows = note.split(head)[1].split("\n\n")[0].strip().splitlines()[1:]
    sizes = [[float(x) for x in re.findall(r"\$(-?[\d.]+)\$", r)] for r in rows]
    assert rows[0].startswith("| 0 (frictionless) |")
    np.testing.assert_allclose(
        sizes[0][:2], [ideal["C.F"][0], ideal["B.F"][0]], atol=0.01
    )
    np.testing.assert_allclose(
        sizes[-1][:2], [table["C.F"][0], table["B.F"][0]], atol=0.01
    )
    assert 3 <= len(rows) <= 13
    assert sizes[-1] == sizes[-2]  # settled, to the digits written
    assert re.search(r"The sizes settle; .* finds the same in 2 steps", note)


def test_a_pair_at_rest_has_no_friction_in_the_note() -> None:
    # at 0 deg the slider is at its dead centre: the guide does not slide
    note, table = _note_and_table(FRICTION, 0.0)
    assert float(table["guide.Ff"][0]) == 0.0
    assert r"\dot s_{\mathrm{guide}} = 0\ \mathrm{m/s}" in note
    # and the law's 0 is said why, not left as a bare product
    assert note.count(r"\text{(no relative motion: no kinetic friction)}") == 1
    # its normal force is there, the sense of its slide is not
    assert r"-0.15 \cdot 17.93 \cdot 0 = 0\ \mathrm{N}" in note
    assert "| guide | $F_{f,\\mathrm{guide}} = 0$ |" in note


def test_friction_note_as_html_and_latex(tmp_path) -> None:
    import shutil
    import subprocess
    import xml.etree.ElementTree as ET

    note = explain(assur.load(FRICTION), 45.0)
    for m in re.findall(r"<math\b.*?</math>", note.to_html(), re.S):
        ET.fromstring(m)  # every equation, friction's too, is well-formed MathML
    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        pytest.skip("pdflatex not found (apt-get install texlive-latex-recommended)")
    note.write(tmp_path / "note.tex")
    result = subprocess.run(
        [pdflatex, "-interaction=nonstopmode", "-halt-on-error", "note.tex"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=180,
    )
    assert result.returncode == 0, result.stdout[-2000:]


@pytest.mark.parametrize(
    "stem", ["slider_crank_exercise", "six_bar_lecture", "whitworth", "class3"]
)
def test_frictionless_notes_say_nothing_of_friction(stem: str) -> None:
    note = str(explain(assur.load(EXAMPLES / f"{stem}.toml"), 45.0))
    assert "friction" not in note.lower()
    assert "ideal" not in note
    assert not [lhs for lhs, _ in statements(note) if lhs.startswith("M_{f")]


def test_the_lecture_s_torque_is_unchanged() -> None:
    note = str(explain(assur.load(EXAMPLES / "slider_crank_exercise.toml"), 45.0))
    assert r"M_{b} = -\sum M_{\mathrm{A}} = 84.63\ \mathrm{N\,m}" in note
    lever = (
        r"M_{b}^{\mathrm{lever}} = -\frac{\sum P}{\omega} = -\frac{-16925}{200} = 84.63"
    )
    assert lever in note


# every example with friction in every joint: groups of every kind, passed friction
RUBBED = [
    ("six_bar_lecture", 30.0),
    ("six_bar_lecture", 250.0),
    ("whitworth", 60.0),
    ("whitworth", 210.0),
    ("scotch_yoke", 30.0),
    ("slot_mechanism", 120.0),
    ("class3", 20.0),
    ("offset_slider_crank", 300.0),
    ("five_bar_two_cranks", (40.0, 100.0)),
]


def rubbed(stem: str) -> assur.Mechanism:
    """An example with friction 0.1 in every joint (journal radius 5 mm)."""
    from .test_friction import with_friction

    mech = assur.load(EXAMPLES / f"{stem}.toml")
    return with_friction(mech, {j.name: 0.1 for j in mech.joints}, 0.005)


@pytest.mark.parametrize(("stem", "angle"), RUBBED)
def test_every_example_with_friction_agrees_with_the_table(stem: str, angle) -> None:
    mech = rubbed(stem)
    at = np.atleast_1d(np.asarray(angle, dtype=float))[None, :]
    at = at if at.shape[1] > 1 else at[:, 0]
    try:
        table = assur.forces(mech, at)
    except assur.AssurError as err:
        pytest.skip(f"{stem} at {angle}: {err}")
    note = str(explain(mech, angle))
    check(note, table)
    shown = [lhs for lhs, last in statements(note) if printed(last) is not None]
    for d in table.plan.drivers:
        letter = "M" if d.kind == "R" else "F"
        many = len(table.plan.drivers) > 1
        sym = f"{letter}_{{b,{tex(d.pair.name)}}}" if many else f"{letter}_{{b}}"
        assert f"{sym}^{{\\mathrm{{lever}}}}" in shown, sym
    assert note.count("found by repeated substitution") == _rubbing_groups_of(
        mech, angle
    )


def _rubbing_groups_of(mech: assur.Mechanism, angle) -> int:
    """How many groups of ``mech`` have a pair with friction."""
    from assur.explain._solve import position

    result = position(mech, angle).result
    assert result is not None
    return sum(any(p.friction > 0.0 for p in rec.pairs) for rec in result.groups)


@pytest.mark.parametrize("rubbing", [False, True], ids=["ideal", "friction"])
def test_every_driver_has_its_lever(rubbing: bool) -> None:
    # the two-crank five-bar: one lever per driver, each equal to the table's load
    stem, angle = "five_bar_two_cranks", (40.0, 100.0)
    mech = rubbed(stem) if rubbing else assur.load(EXAMPLES / f"{stem}.toml")
    table = assur.forces(mech, np.array([angle]))
    note = str(explain(mech, angle))
    lever = note.split("## 6. Check by Zhukovsky's lever")[1]
    assert "each balancing load has its own lever" in lever
    assert lever.count("per unit speed of this driver, the others held") == 2
    check(note, table)
    shown = {lhs: printed(last) for lhs, last in statements(lever) if printed(last)}
    for joint in ("A", "E"):
        sym = f"M_{{b,{tex(joint)}}}"
        ((got, half),) = shown[f"{sym}^{{\\mathrm{{lever}}}}"]
        assert abs(got - float(table[f"{joint}.torque"][0])) <= half
        if rubbing:
            ((ideal, half),) = shown[f"{sym}^{{\\mathrm{{ideal}}}}"]
            assert abs(ideal - float(table[f"{joint}.torque_ideal"][0])) <= half
    # the primed powers: per unit speed, not watts: in N m, as the torques
    assert "\\sum P' = " in lever
    assert "power per unit speed (N m)" in lever
    assert "W" not in next(x for x in lever.splitlines() if "\\sum P' = " in x)
    assert ("\\sum P_{f}' = " in lever) == rubbing


def test_the_documented_friction_numbers_are_the_note_s() -> None:
    # docs/explain.rst quotes the friction example's note at 45 degrees
    note, _ = _note_and_table(FRICTION, 45.0)
    for text in (
        r"-0.0008 \cdot 1994.59 \cdot (-1) = 1.596\ \mathrm{N\,m}",
        r"-0.15 \cdot 473.94 \cdot (-1) = 71.09\ \mathrm{N}",
        r"| 0 (frictionless) | $962.04$ | $1928.5$ | $443.17$ |",
        r"| 1 | $1034.42$ | $1990.24$ | $472.17$ |",
        r"| 4 | $1039.33$ | $1994.59$ | $473.94$ |",
        "finds the same in 2 steps",
        r"(0,\ -473.94) + (71.09,\ 0) = (71.09,\ -473.94)",
        r"-0.00096 \cdot 9658.16 \cdot 1 = -9.272",
        r"91.55 - (-9.272) = 100.82\ \mathrm{N\,m}",
        r"-\frac{-16925 + (-3239.46)}{200} = 100.82",
        r"P_{f,\mathrm{guide}} = 71.09 \cdot (-13.3) = -945.64",
        r"= 100.82231 - 84.625 = 16.19731\ \mathrm{N\,m}",
        r"= 19.14\,\%$",
    ):
        assert text in note, text
    zero, _ = _note_and_table(FRICTION, 0.0)
    assert r"-0.15 \cdot 17.93 \cdot 0 = 0" in zero


def test_the_documented_count_of_substitution_steps_is_the_note_s() -> None:
    # docs/explain.rst said "in four steps" beside Newton's "2, its steps counted
    # alike", where the note's table, counted alike, ends on its fifth step
    note, _ = _note_and_table(FRICTION, 45.0)
    steps = re.findall(r"^\| (\d+) \| \$", note, flags=re.MULTILINE)
    docs = (EXAMPLES.parent / "docs" / "explain.rst").read_text(encoding="utf-8")
    said = re.search(r"473\.94 N in (\w+) steps", " ".join(docs.split()))
    assert said is not None
    words = ("one", "two", "three", "four", "five", "six", "seven", "eight")
    assert words.index(said.group(1)) + 1 == int(steps[-1]), said.group(0)


def test_a_group_rubbing_in_its_guide_alone_states_the_sliding_law_alone() -> None:
    """Its paragraph opened with a revolute pair's couple, which it has none of."""
    import dataclasses

    mech = assur.load(EXAMPLES / "slider_crank_friction.toml")
    joints = tuple(
        j if j.kind == "prismatic" else dataclasses.replace(j, friction=0.0)
        for j in mech.joints
    )
    note = str(explain(dataclasses.replace(mech, joints=joints), 45.0))
    assert "Friction in guide: a sliding pair's force" in note
    assert "revolute pair's couple" not in note
    both = str(explain(mech, 45.0))
    assert "a revolute pair's couple" in both
    # each law has commas of its own: a semicolon stands between the two
    assert "relative to its first); a sliding pair's force" in both


def test_the_friction_laws_read_without_brackets_side_by_side() -> None:
    # "... its couple $M$ makes none in this model) (kinetic friction only: a pair
    # at rest has none)": two brackets in a row, the first's "none" of no noun
    note = " ".join(str(explain(assur.load(FRICTION), 45.0)).split())
    start = note.index("Friction in ")
    paragraph = note[start : note.index("(sizes in N)", start)]
    assert ") (" not in paragraph
    assert "its couple $M$ adds no friction in this model)" in paragraph


def test_near_self_locking_the_substitution_is_said_to_settle_slowly() -> None:
    import dataclasses

    # the locking example with friction 1.3 in its guide, at 240 deg: each step of
    # the hand method grows the sizes by 0.92 of the step before (f tan(beta))
    mech = assur.load(EXAMPLES / "slider_crank_locking.toml")
    joints = tuple(
        dataclasses.replace(j, friction=1.3) if j.name == "guide" else j
        for j in mech.joints
    )
    mech = dataclasses.replace(mech, joints=joints)
    table = assur.forces(mech, [240.0])
    note = str(explain(mech, 240.0))
    assert (
        "The substitution settles slowly here: each step moves the sizes the same "
        "way by about 0.92 times the step before (near 1, the group is near "
        "self-locking), about 127 steps more."
    ) in note
    found = re.search(r"\| found \| \$([\d.]+)\$ \| \$([\d.]+)\$", note)
    assert found is not None
    assert float(found.group(2)) == pytest.approx(float(table["B.F"][0]), abs=0.01)
    assert len(re.findall(r"^\| \d+ \|", note, flags=re.MULTILINE)) == 12


def test_a_substitution_that_jumps_about_gives_no_ratio() -> None:
    # the steep RPP's sizes jump (0.92, 0.65, 0.04): "about 0.48 times the step
    # before, near self-locking" read a steady loop into them; and Newton's steps
    # (151) were its continuation's, friction raised from zero: no count is given
    path = Path(__file__).parent / "data" / "friction" / "rpp_steep.toml"
    note = str(explain(assur.load(path), 132.0))
    assert "The substitution does not settle here: its steps jump about." in note
    assert "times the step before" not in note
    assert "(with the friction raised from zero step by step)" in note
    assert "(with large friction it can allow two)" in note


def test_a_substitution_that_swings_is_not_called_near_locking() -> None:
    # the locking example at 90 deg: the slider drives (the crank brakes), and the
    # steps overshoot by -0.73 of the one before; "near 1: near self-locking" was
    # said of the ratio's size alone
    note = str(explain(assur.load(EXAMPLES / "slider_crank_locking.toml"), 90.0))
    assert (
        "each step overshoots and swings back, by about 0.73 times the step before "
        "(ratio -0.73; a swing says nothing of self-locking)"
    ) in note
    assert "the group is near self-locking" not in note


def test_an_input_slider_s_guide_is_written_in_the_order_it_is_found() -> None:
    # the whole reaction N + F_f was written before N and F_f were found
    path = Path(__file__).parent / "data" / "friction" / "ram_up_a_steep_guide.toml"
    note = str(explain(assur.load(path), 0.0))
    driver = note.split("## 5. The input link")[1].split("## 6.")[0]
    order = [
        driver.index(r"N_{\mathrm{guide}} = -\sum \vec F \cdot \vec n"),
        driver.index(r"F_{f,\mathrm{guide}} = -f_{\mathrm{guide}}"),
        driver.index(r"F_{b} = -\sum \vec F \cdot \vec e"),
        driver.index(r"\vec F_{\mathrm{ground},\mathrm{slider}} = \vec N_{"),
    ]
    assert order == sorted(order)
    assert "an efficiency means little there" in driver


def test_newton_s_steps_left_uncounted_leave_no_words() -> None:
    # where Newton's steps from the frictionless sizes do not settle and the
    # friction was not raised (the analysis found the sizes on its second try)
    # the note counts none: no "in None steps", no empty brackets or spaces
    assert _spaced(_newton_steps(None)) == ""
    assert _spaced(_newton_steps(3)) == " in 3 steps"
    tried = [{"A": 1.0}, {"A": 2.0}, {"A": 2.5}, {"A": 2.8}, {"A": 3.0}]
    said = _unsettled(tried, _newton_steps(None))
    assert "Newton's method on them, which the analysis uses" in said
    assert "()" not in said


@pytest.mark.parametrize("path", [FRICTION, BEARINGS], ids=lambda p: p.stem)
def test_the_note_solves_a_group_without_its_friction_once(monkeypatch, path) -> None:
    from assur.explain._solve import position

    pos = position(assur.load(path), 45.0)
    assert pos.result is not None
    solver_of = {s.bodies: s for s in pos.plan.solvers}
    groups = [rec for rec in pos.result.groups if rubbing(rec.pairs)]
    assert groups
    for rec in groups:
        solver, loads = solver_of[rec.bodies], without_own(pos, rec)
        calls: list[bool] = []
        solve = type(solver).equilibrium

        def counted(self, bodies, given, solve=solve, calls=calls, loads=loads):
            calls.append(given is loads)  # the loads without the group's friction
            return solve(self, bodies, given)

        monkeypatch.setattr(type(solver), "equilibrium", counted)
        newton_start(pos, rec, solver, loads, group_sizing(pos, solver, loads))
        monkeypatch.undo()
        # the start, Newton's solve and its steps read one solve without friction;
        # then one per pair for a unit of its friction, one with the friction found
        assert calls.count(True) == 1
        assert len(calls) == len(rubbing(rec.pairs)) + 2


@pytest.mark.parametrize(
    ("path", "angle"),
    [
        (FRICTION, 45.0),
        (BEARINGS, 100.0),
        (EXAMPLES / "slider_crank_locking.toml", 240.0),  # settles slowly
        (EXAMPLES.parent / "docs/files/errors/locking.toml", 250.0),  # it locks
    ],
    ids=lambda x: getattr(x, "stem", x),
)
def test_the_note_s_substitution_solves_without_friction_once_a_group(
    monkeypatch, path: Path, angle: float
) -> None:
    from assur.explain import _group_friction_text as worked
    from assur.explain import _locked_text as locked
    from assur.explain._solve import position

    # each step of repeated substitution solved the group without its friction
    # again, only to read its pairs and links
    mech = assur.load(path)
    kinds = {type(s) for s in position(mech, 0.0).plan.solvers}
    given: list[list] = []  # the loads without each group's friction, as made
    solves: list[int] = []  # how often each was solved as it is

    def kept(pos, rec, made=without_own):
        given.append(made(pos, rec))
        solves.append(0)
        return given[-1]

    def counted(self, bodies, loads, solve):
        for k, own in enumerate(given):
            solves[k] += loads is own
        return solve(self, bodies, loads)

    for kind in kinds:
        wrapped = functools.partialmethod(counted, solve=kind.equilibrium)
        monkeypatch.setattr(kind, "equilibrium", wrapped)
    monkeypatch.setattr(worked, "without_own", kept)
    monkeypatch.setattr(locked, "without_own", kept)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)  # where it locks
        note = str(explain(mech, angle))
    monkeypatch.undo()
    assert given  # a group's friction was worked out by hand
    steps = note.count("| 2 |")
    assert steps >= 1, "the substitution took fewer than two steps"
    assert solves == [1] * len(given)
