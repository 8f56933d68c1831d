"""Positions a one-driver mechanism cannot reach from its reference pose (assur._reach).

A closed-form dyad is assembled at each position on its reference branch; a position
on another circuit of a four-bar whose input only rocks, or past a PRP dyad's dead
centre (its pin at infinity), used to come out assembled there without a word. The
four-bar's rows are checked against a continuation of its own by small Newton steps.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import assur
from assur._reach import reach
from assur.cli import main
from assur.plan import plan_of

from .conftest import DATA, EXAMPLES

EDGE = DATA / "edge"
CIRCUITS = EDGE / "crank_rocker_two_circuits.toml"
PRP = EDGE / "prp_dead_centre.toml"
PRP45 = EDGE / "prp_dead_centre_45.toml"


def _continued(mech: assur.Mechanism, step_deg: float = 0.05) -> dict[float, float]:
    """Follow the four-bar from its reference pose by small Newton steps.

    Returns the rocker's angle (deg) at every input angle reached (deg), both ways
    from the reference pose until the loop no longer closes.
    """
    at = {j.name: np.array(j.at, dtype=float) for j in mech.joints}
    o2, a0, b0, o4 = at["O2"], at["A"], at["B"], at["O4"]
    crank = float(np.hypot(*(a0 - o2)))
    coupler = float(np.hypot(*(b0 - a0)))
    rocker = float(np.hypot(*(b0 - o4)))
    phi0 = math.degrees(math.atan2(*(a0 - o2)[::-1]))
    out = {}
    for sign in (1.0, -1.0):
        b = b0.copy()
        for k in range(int(360.0 / step_deg)):
            phi = phi0 + sign * k * step_deg
            t = math.radians(phi)
            a = o2 + crank * np.array([math.cos(t), math.sin(t)])
            for _ in range(30):
                f = np.array(
                    [(b - a) @ (b - a) - coupler**2, (b - o4) @ (b - o4) - rocker**2]
                )
                jac = 2.0 * np.array([b - a, b - o4])
                if abs(np.linalg.det(jac)) < 1e-6:
                    break
                b = b - np.linalg.solve(jac, f)
            if not np.max(np.abs(f)) < 1e-14:
                break
            out[round(phi, 6)] = math.degrees(math.atan2(*(b - o4)[::-1]))
    return out


def test_another_circuit_is_an_error_naming_the_group_and_the_range():
    mech = assur.load(CIRCUITS)
    with pytest.raises(assur.AssemblyError) as caught:
        assur.forces(mech, [30.0, 300.0])
    text = str(caught.value)
    assert text.startswith(
        "group RRR (coupler, rocker): driver position 300 deg is on another circuit "
        "of the mechanism (1 of 2 positions): it cannot reach it from its reference "
        "pose at 30 deg; "
    )
    assert "cannot be assembled between about 119.5 deg and 263 deg" in text
    assert "expected positions from about 16 deg to 119 deg" in text


def test_another_circuit_is_left_out_and_the_rows_kept_follow_the_motion():
    mech = assur.load(CIRCUITS)
    angles = np.arange(30.0, 391.0, 10.0)
    table = assur.forces(mech, angles, skip_unassembled=True)
    np.testing.assert_array_equal(table["angle"], [*range(30, 111, 10), 380, 390])
    np.testing.assert_array_equal(table.skipped, np.arange(120.0, 371.0, 10.0))
    path = _continued(mech)
    keys = np.array(sorted(path))
    # the circuit of the reference pose: input angles 15.9 to 119.4 deg
    assert 119.0 < keys.max() < 120.0
    assert 15.5 < keys.min() < 16.5
    for angle, rocker in zip(table["angle"], table["rocker.angle"], strict=True):
        # the same input angle a whole number of turns away, on the continued path
        phi = angle - 360.0 * round((angle - 30.0) / 360.0)
        near = keys[np.argmin(np.abs(keys - phi))]
        assert abs(near - phi) < 0.03
        gap = (rocker - path[float(near)] + 180.0) % 360.0 - 180.0
        assert abs(gap) < 0.1, (angle, rocker, path[float(near)])


def test_the_sweep_of_both_circuits_names_where_the_mechanism_assembles():
    mech = assur.load(CIRCUITS)
    with pytest.raises(
        # 380 to 390 deg (a turn on from 20 to 30) go on into 30 to 110 deg
        assur.AssemblyError,
        match=r"it assembles for 20 deg to 110 deg$",
    ):
        assur.kinematics(mech, np.arange(30.0, 391.0, 10.0))


def test_the_command_line_leaves_another_circuit_out_and_says_why(capsys):
    status = main(
        [
            "forces",
            str(CIRCUITS),
            "--angles",
            "30:390:10",
            "--skip-unassembled",
            "--csv",
            "-",
        ]
    )
    out, err = capsys.readouterr()
    assert status == 0, err
    rows = [line.split(",")[0] for line in out.splitlines()[1:]]
    assert [float(r) for r in rows] == [*range(30, 111, 10), 380, 390]
    assert "left out 26 positions" in err
    assert "or that the mechanism cannot reach from its reference pose" in err


@pytest.mark.parametrize("path", [PRP, PRP45], ids=["60", "45"])
def test_a_sweep_past_a_dead_centre_it_does_not_hit_is_an_error(path):
    mech = assur.load(path)
    angles = [60.0, 100.0, 170.0, 185.5, 200.0]
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(mech, angles)
    assert str(caught.value).startswith(
        "group PRP (block, ram): driver position 185.5 deg is beyond a dead centre of "
        "the group"
    )
    assert "at a dead centre at about 180 deg" in str(caught.value)
    table = assur.kinematics(mech, angles, skip_unassembled=True)
    np.testing.assert_array_equal(table["angle"], [60.0, 100.0, 170.0])
    np.testing.assert_array_equal(table.skipped, [185.5, 200.0])


@pytest.mark.parametrize("path", [PRP, PRP45], ids=["60", "45"])
def test_the_dynamic_model_of_a_crank_that_cannot_turn_fully_is_an_error(path):
    mech = assur.load(path)
    failures = (assur.AssemblyError, assur.SingularConfigurationError)
    # the counts are of the model's own grid, which the message names
    expected = (
        r"the crank cannot make a full turn \(on the model's grid of \d+ positions "
        r"a turn\): group PRP \(block, ram\)"
    )
    with pytest.raises(failures, match=expected):
        assur.flywheel(mech, 0.05)
    with pytest.raises(failures, match=expected):
        assur.dynamics(mech)


def test_a_crank_that_turns_fully_has_no_barrier():
    for path in (
        EXAMPLES / "four_bar.toml",
        EXAMPLES / "tenbar.toml",
        EDGE / "five_bar_parallelogram.toml",
    ):
        assert reach(plan_of(assur.load(path))) is None, path


@pytest.mark.parametrize(
    "mech",
    [
        assur.load(EDGE / "class3_parallelogram.toml"),
        assur.catalog.four_bar(crank=0.05, coupler=0.1, rocker=0.05, frame=0.1),
    ],
    ids=["triad-and-dyad", "four-bar"],
)
def test_a_parallelogram_passes_its_change_points(mech):
    assert reach(plan_of(mech)) is None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        # its change points (0 and 180 deg for the four-bar) are not hit: dead centres
        table = assur.kinematics(mech, np.arange(0.25, 720.0, 0.5))
    assert table.skipped.size == 0


def _narrow_gap(reference: float) -> assur.Mechanism:
    """A four-bar that cannot be assembled for input angles within 0.196 deg of 0.

    Input 0.3, coupler 0.25, rocker 0.20499, frame 0.255: the coupler and rocker
    reach 0.45499 at most, 0.04501 at least, and the input's pin comes 0.045 from the
    rocker's pivot at 0 deg. Its two circuits are a gap of 0.39 deg apart: the scan's
    grid of 0.5 deg steps over it when the reference pose is 30.25 deg.
    """
    a, b, c, d = 0.3, 0.25, 0.20499, 0.255
    t = math.radians(reference)
    ax, ay = a * math.cos(t), a * math.sin(t)
    dx, dy = d - ax, -ay
    r = math.hypot(dx, dy)
    along = (b * b - c * c + r * r) / (2 * r)
    h = math.sqrt(b * b - along * along)
    bx, by = ax + (along * dx - h * dy) / r, ay + (along * dy + h * dx) / r
    text = f"""
format = 1
name = "narrow gap"
[links.input]
axis = ["O2", "A"]
[links.coupler]
axis = ["A", "B"]
[links.rocker]
axis = ["O4", "B"]
[joints.O2]
kind = "revolute"
links = ["ground", "input"]
at = [0.0, 0.0]
[joints.A]
kind = "revolute"
links = ["input", "coupler"]
at = [{ax!r}, {ay!r}]
[joints.B]
kind = "revolute"
links = ["coupler", "rocker"]
at = [{bx!r}, {by!r}]
[joints.O4]
kind = "revolute"
links = ["ground", "rocker"]
at = [{d!r}, 0.0]
[[drivers]]
joint = "O2"
omega = 10.0
"""
    return assur.loads(text)


@pytest.mark.parametrize("reference", [30.0, 30.25])
def test_a_gap_narrower_than_the_scan_s_step_is_a_barrier(reference):
    """With the reference at 30.25 deg no grid point fell in the gap: the rows at
    -1 and -10 deg came out on the other circuit (the rocker reversed, -180 deg)."""
    mech = _narrow_gap(reference)
    found = reach(plan_of(mech))
    assert found is not None
    assert math.degrees(found.low) == pytest.approx(0.0, abs=0.2)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)  # near a dead centre
        table = assur.kinematics(
            mech, [reference, 10.0, 1.0, -1.0, -10.0], skip_unassembled=True
        )
        np.testing.assert_array_equal(table["angle"], [reference, 10.0, 1.0])
        with pytest.raises(assur.AssemblyError, match="is on another circuit"):
            assur.kinematics(mech, [reference, -10.0])


@pytest.mark.parametrize("beyond", [185.5, -100.0])
def test_the_range_a_prp_reaches_is_from_dead_centre_to_dead_centre(beyond):
    """Its dead centres are at 0 and 180 deg: positions past either are refused
    naming the whole range (its first end read 0.5 deg, a grid step in)."""
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(assur.load(PRP), [60.0, beyond])
    assert str(caught.value).endswith(
        "expected positions from about 0 deg to 180 deg (or whole turns from them)"
    )


def test_a_dead_centre_between_the_scan_s_grid_points_is_found_where_it_is():
    """The PRP's guide turned by 0.3 deg: its dead centres (the crank's slide line
    parallel to the guide) move to 0.3 and 180.3 deg, between the scan's points
    of 0.5 deg, and are found there by the sign change of the determinant."""
    text = PRP.read_text(encoding="utf-8")
    t = math.radians(0.3)
    turned = f"axis = [{math.cos(t)!r}, {math.sin(t)!r}]"
    text = text.replace("at = [0.0, 0.1]\naxis = [1, 0]", f"at = [0.0, 0.1]\n{turned}")
    mech = assur.loads(text)
    found = reach(plan_of(mech))
    assert found is not None
    assert math.degrees(found.low) == pytest.approx(0.3, abs=1e-9)
    assert math.degrees(found.high) == pytest.approx(180.3, abs=1e-9)
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(mech, [60.0, 185.5])
    assert "the group is at a dead centre at about 180.3 deg" in str(caught.value)


def _parallelogram_and_dyad() -> assur.Mechanism:
    """A parallelogram four-bar (crank 0.1, coupler 0.3) and a dyad on its coupler.

    The arm (0.3) hangs on E, the coupler's point 0.15 from A; the lever (0.27) on
    G = (0.15, 0.5). While the four-bar stays a parallelogram, E = (0.15 +
    0.1 cos t, 0.1 sin t) and |EG|^2 = 0.26 - 0.1 sin t: beyond the dyad's reach
    0.57 for sin t < -0.649, t from 220.47 to 319.53 deg. Past its change points
    (0 and 180 deg) a four-bar followed on one sign of its closed form crosses over
    (an antiparallelogram), where the dyad reaches at every angle.
    """
    t = math.radians(45.0)
    ax, ay = 0.1 * math.cos(t), 0.1 * math.sin(t)
    ex, ey, gx, gy, arm, lever = ax + 0.15, ay, 0.15, 0.5, 0.3, 0.27
    dx, dy = gx - ex, gy - ey
    r = math.hypot(dx, dy)
    along = (arm * arm - lever * lever + r * r) / (2 * r)
    h = math.sqrt(arm * arm - along * along)
    fx, fy = ex + (along * dx - h * dy) / r, ey + (along * dy + h * dx) / r
    joints = {
        "O": ("ground", "crank", 0.0, 0.0),
        "A": ("crank", "coupler", ax, ay),
        "B": ("coupler", "rocker", ax + 0.3, ay),
        "Q": ("ground", "rocker", 0.3, 0.0),
        "E": ("coupler", "arm", ex, ey),
        "F": ("arm", "lever", fx, fy),
        "G": ("ground", "lever", gx, gy),
    }
    # the crank's angle is that of O -> A (45 deg here)
    links = "".join(f"[links.{k}]\n" for k in ("coupler", "rocker", "arm", "lever"))
    text = 'format = 1\n[links.crank]\naxis = ["O", "A"]\n' + links
    for j, (a, b, x, y) in joints.items():
        text += f'[joints.{j}]\nkind = "revolute"\nlinks = ["{a}", "{b}"]\n'
        text += f"at = [{x!r}, {y!r}]\n"
    return assur.loads(text + '[[drivers]]\njoint = "O"\nomega = 10.0\n')


def test_the_reach_past_a_change_point_follows_the_sweep_s_branch():
    # scanned on one sign of the four-bar's closed form, the scan crossed over at
    # 180 deg to the antiparallelogram, where the dyad reaches at every angle, and
    # found no barrier: the sweep, on the parallelogram, fails from 220.47 deg
    span = reach(plan_of(_parallelogram_and_dyad()))
    assert span is not None
    edge = math.degrees(math.asin(0.0649 / 0.1))  # sin t = -0.649
    assert math.degrees(span.high) == pytest.approx(180.0 + edge, abs=0.1)
    assert math.degrees(span.low) == pytest.approx(-edge, abs=0.1)
