"""The note where friction locks a group: as far as the reverse pass goes, and why.

A slider-crank whose only friction is in its guide locks where the rod leans at
beta to the guide with f tan(beta) >= 1: the rod pushes the slider along its own
line, so each newton of friction the guide's normal force brings asks for
f tan(beta) newtons more of it. Repeated substitution's steps therefore grow by
exactly f tan(beta) each, checked here against the kinematics, and the lock sets in
where that ratio reaches 1.
"""

from __future__ import annotations

import math
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.cli import main
from assur.explain import explain

from .test_explain import check

LOCKING = Path(__file__).parent.parent / "docs" / "files" / "errors" / "locking.toml"
ANGLE = 250.0


def _guide_only(f: float) -> assur.Mechanism:
    """The locking slider-crank with friction ``f`` in its guide and none else."""
    text = LOCKING.read_text(encoding="utf-8")
    text = re.sub(r"friction = 0\.1\b", "friction = 0.0", text)
    text = text.replace("friction = 1.3", f"friction = {f!r}")
    return assur.loads(text)


def _locked_note(mech: assur.Mechanism, angle: float = ANGLE, **kw):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        note = explain(mech, angle, **kw)
    return note, [str(w.message) for w in caught]


def _tan_beta(mech: assur.Mechanism, angle: float = ANGLE) -> float:
    """tan of the rod's lean to the guide (the x axis), from the kinematics."""
    lean = float(assur.kinematics(mech, [angle])["rod.angle"][0])
    return abs(math.tan(math.radians(lean)))


def _rows(note) -> list[list[float]]:
    """The substitution table's rows of sizes (N)."""
    rows = re.findall(r"^\| (?:\d+|0 \(frictionless\)) \|(.*)\|$", str(note), re.M)
    return [[float(x.strip(" $")) for x in r.split("|")] for r in rows]


def test_the_note_goes_as_far_as_the_locked_group():
    mech = assur.load(LOCKING)
    with pytest.raises(assur.SelfLockingError):
        assur.forces(mech, [ANGLE])
    note, said = _locked_note(mech)
    assert said == [
        "group RRP (rod, slider): its friction locks it at crank angle 250 deg: the "
        "note shows the analysis as far as that group, and why it locks (no "
        "balancing load, no lever)"
    ]
    text = str(note)
    heads = re.findall(r"^## (.*)$", text, re.M)
    assert heads == [
        "1. Structure",
        "2. Kinematics, group by group",
        "3. Inertia loads",
        "4. Reactions, group by group in the reverse order",
    ]
    reverse = text.split("## 4.")[1]
    assert re.findall(r"^### (.*)$", reverse, re.M) == ["Group RRP (rod, slider)"]
    assert "friction locks the group here (self-locking)" in reverse
    assert text.startswith(
        "# Slider-crank with a self-locking guide at crank angle 250 deg: the "
        "analysis explained\n\nAt this position friction locks group RRP (rod, "
        "slider): the note stops at that group, in section 4, and shows why."
    )
    # the textbook's condition, by hand: the rod's lean to the guide (the x axis)
    lean = math.degrees(math.atan(_tan_beta(mech)))
    shown = (
        f"at $\\beta = {lean:.2f}^\\circ$ to the slide line of guide",
        f"$f\\tan\\beta = 1.3 \\cdot \\tan {lean:.2f}^\\circ = "
        f"{1.3 * _tan_beta(mech):.3f} \\ge 1$",
        f"$\\varphi = \\arctan f = {math.degrees(math.atan(1.3)):.2f}^\\circ$",
        f"$\\cot\\beta = {1.0 / _tan_beta(mech):.3f}$",
    )
    for said_ in shown:
        assert said_ in reverse, said_
    # no balancing load, no reaction of the group, no lever
    for absent in ("M_{b}", "The group's reactions", "Zhukovsky's lever\n"):
        assert absent not in reverse
    # the values: the kinematics and the inertia loads, the rest not reached (NaN)
    kin = assur.kinematics(mech, [ANGLE])
    free = assur.forces(_guide_only(0.0), [ANGLE])  # inertia loads need no friction
    assert list(note.values) == list(assur.forces(mech, [60.0]).columns)
    for name in kin.columns:
        np.testing.assert_array_equal(note.values[name], kin[name][0], err_msg=name)
    for name in ("rod.Fi.x", "rod.Fi.y", "rod.Mi", "slider.Fi.x"):
        np.testing.assert_allclose(note.values[name], free[name][0], rtol=1e-12)
    for name in ("B.F", "C.Fx", "guide.F", "A.F", "driver.torque", "shaking.Fx"):
        assert math.isnan(note.values[name]), name
    # every number printed agrees with the kinematics
    assert check(note, kin)


def test_substitution_starts_frictionless_and_grows_by_f_tan_beta():
    f = 1.3
    mech = _guide_only(f)
    note, said = _locked_note(mech)
    assert len(said) == 1
    assert "locks it" in said[0]
    rows = np.array(_rows(note))
    # one size: the guide's normal force (the pins have no friction)
    assert "| step | $\\vert N_{\\mathrm{guide}}\\vert $ |" in str(note)
    # the first row: the same mechanism without friction, solved by the table
    free = assur.forces(_guide_only(0.0), [ANGLE])
    np.testing.assert_allclose(rows[0], [free["guide.F"][0]], atol=0.006)
    # each step of |N| is f tan(beta) times the one before (to its printed digits)
    steps = np.diff(rows[:, 0])
    np.testing.assert_allclose(steps[1:] / steps[:-1], f * _tan_beta(mech), rtol=2e-4)
    said = f"by about {f * _tan_beta(mech):.3f} times the step before"
    assert said in str(note)


@pytest.mark.parametrize("share", [0.97, 1.0, 1.03])
def test_the_lock_sets_in_where_f_tan_beta_reaches_one(share):
    """Hand-checkable: below f = 1 / tan(beta) a note with its balancing torque,
    above it the locked note."""
    f = share / _tan_beta(_guide_only(0.0))
    note, said = _locked_note(_guide_only(f))
    text = str(note)
    if share < 1.0:
        assert said == []
        assert "## 5. The input link" in text
        assert "friction locks the group here" not in text
        # just short of it: the substitution settles slowly, at f tan(beta)
        assert f"by about {share:.2f} times the step before (near 1" in text
    else:
        assert len(said) == 1
        # at the threshold itself the steps keep their size
        grows = "so the steps grow" if share > 1.0 else "so the steps do not shrink"
        assert grows in text
        assert "## 5." not in text
        assert "friction locks the group here" in text


@pytest.mark.parametrize("ulps", [-2, -1, 1, 2])
def test_the_threshold_is_said_alike_an_ulp_either_side(ulps):
    # f tan(beta) = 1 but for its last bits, which the machine's sin, cos and
    # BLAS set: an ulp more of f gave a step ratio of 0.9999999999999984 and the
    # note said the substitution "settles slowly" instead of the threshold
    f = 1.0 / _tan_beta(_guide_only(0.0))
    for _ in range(abs(ulps)):
        f = float(np.nextafter(f, math.inf if ulps > 0 else -math.inf))
    note, said = _locked_note(_guide_only(f))
    text = str(note)
    assert len(said) == 1
    assert "so the steps do not shrink" in text
    assert "settles slowly" not in text


SIX_BAR = """
[links.l5]
axis = ["E", "F"]
mass = 0.3
center = { from = "E", toward = "F", distance = 0.1 }
inertia = 0.0005

[links.l6]
axis = ["G", "F"]
mass = 0.3
center = { from = "G", toward = "F", distance = 0.1 }
inertia = 0.0005

[joints.E]
kind = "revolute"
links = ["rod", "l5"]
at = [0.11123724356957945, 0.04330127018922193]

[joints.F]
kind = "revolute"
links = ["l5", "l6"]
at = [0.19438938252741778, 0.24698171055288654]

[joints.G]
kind = "revolute"
links = ["ground", "l6"]
at = [0.0, 0.35]

"""
"""A dyad hung from the rod, without friction: solved before the locked group."""


def test_a_group_solved_before_the_locked_one_is_shown_and_compared():
    text = LOCKING.read_text(encoding="utf-8").replace(
        "[[drivers]]", SIX_BAR + "[[drivers]]"
    )
    mech = assur.loads(text)
    # its reactions do not depend on the guide's friction (solved before it)
    free = assur.forces(assur.loads(text.replace("friction = 1.3", "")), [ANGLE])
    given = {j: float(free[j][0]) for j in ("E.F", "F.F", "G.F", "B.F")}
    note, said = _locked_note(mech, answers=given)
    assert len(said) == 1
    assert "group RRP (rod, slider)" in said[0]
    reverse = str(note).split("## 4.")[1]
    assert re.findall(r"^### (.*)$", reverse, re.M) == [
        "Group RRR (l5, l6)",
        "Group RRP (rod, slider)",
    ]
    part = str(note).split("## 5. The given answers")[1]
    verdicts = dict(re.findall(r"^\| ([\w.]+) \|.*\| (\w[\w ]*) \|$", part, re.M))
    assert verdicts == {
        "E.F": "agrees",
        "F.F": "agrees",
        "G.F": "agrees",
        "B.F": "undefined here",
    }


def test_answers_at_a_locked_position():
    mech = assur.load(LOCKING)
    kin = assur.kinematics(mech, [ANGLE])
    free = assur.forces(_guide_only(0.0), [ANGLE])  # inertia loads need no friction
    given = {
        "rod.omega": float(kin["rod.omega"][0]),
        "rod.Fi": math.hypot(free["rod.Fi.x"][0], free["rod.Fi.y"][0]),
        "slider.Fi.x": float(free["slider.Fi.x"][0]),
        "rod.Mi": float(free["rod.Mi"][0]),
        "driver.torque": 100.0,
        "B.F": 300.0,
    }
    note, _ = _locked_note(mech, answers=given)
    part = str(note).split("## 5. The given answers")[1]
    verdicts = re.findall(r"^\| ([\w.]+) \|.*\| (\w[\w ]*) \|$", part, re.M)
    assert dict(verdicts) == {
        "rod.omega": "agrees",
        "rod.Fi": "agrees",
        "slider.Fi.x": "agrees",
        "rod.Mi": "agrees",
        "driver.torque": "undefined here",
        "B.F": "undefined here",
    }
    with pytest.raises(
        assur.ModelError, match=r"answers\.rod\.omgea: no such quantity"
    ):
        _locked_note(mech, answers={"rod.omgea": 1.0})


def test_the_command_writes_the_note_and_warns(tmp_path, capsys):
    out = tmp_path / "note.html"
    assert main(["explain", str(LOCKING), "--angle", "250", "-o", str(out)]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith(f"assur: warning: {LOCKING}: group RRP (rod, slider)")
    assert "friction locks the group here" in out.read_text(encoding="utf-8")
    # a position where it moves: the full note, no warning
    assert main(["explain", str(LOCKING), "--angle", "60", "-q"]) == 0
    done = capsys.readouterr()
    assert done.err == ""
    assert "## 6. Check by Zhukovsky's lever" in done.out


def test_what_the_reverse_pass_had_left_is_named():
    from types import SimpleNamespace

    from assur.explain._locked_text import _left

    def pos(drivers: int) -> SimpleNamespace:
        return SimpleNamespace(plan=SimpleNamespace(drivers=[None] * drivers))

    assert _left(pos(1), 0) == "The input link"
    assert _left(pos(1), 1) == "The group left and the input link"
    assert _left(pos(2), 3) == "The 3 groups left and the input links"
    text = str(_locked_note(assur.load(LOCKING))[0])
    assert "The input link would take this group's reactions" in text


def test_where_the_pins_friction_tips_the_guide_over():
    """At 295 deg the rod leans 37.17 deg, below 90 - arctan 1.3 = 37.57: the guide
    alone would let the slider move (f tan beta = 0.986), the pins' friction makes
    the group lock all the same; no guide friction is then proposed."""
    note, said = _locked_note(assur.load(LOCKING), 295.0)
    assert len(said) == 1
    text = str(note)
    lean = math.degrees(math.atan(_tan_beta(assur.load(LOCKING), 295.0)))
    assert lean < 90.0 - math.degrees(math.atan(1.3))
    assert (
        f"\\tan {lean:.2f}^\\circ = {1.3 * math.tan(math.radians(lean)):.4f} < 1$: "
        "the guide alone would let the push move the slider; the pins' friction "
        "tips the group over."
    ) in text
    assert "\\cot\\beta" not in text
