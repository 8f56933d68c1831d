"""Edge cases found in review: each was a traceback, a wrong answer or a lost pose.

Mechanism files in tests/data/edge: a class III triad with a prismatic pair whose
crank positions past 114 deg are reached only the other way round the circle, a
triad with three parallel links that stands at a dead centre at 90 deg, and two
triads whose crank can only rock, past whose limits Newton's method finds another
assembly.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.cli import main
from assur.plan import plan_of

from .conftest import DATA, EXAMPLES

EDGE = DATA / "edge"


def test_still_prismatic_driver_has_forces():
    """A slider driven at zero speed: the virtual-power check needs its own rates."""
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    mech = dataclasses.replace(mech, drivers=(assur.Driver("guide", 0.0),))
    t = assur.forces(mech, [0.0, 0.01])
    np.testing.assert_allclose(t["driver.force"], t["driver.force_check"], rtol=1e-9)


def test_triad_reached_the_other_way_round():
    mech = assur.load(EDGE / "triadP.toml")
    t = assur.kinematics(mech, [300.0, -60.0])
    np.testing.assert_allclose(t["plate.angle"][0], t["plate.angle"][1], atol=1e-9)
    np.testing.assert_allclose(t["D.x"][0], t["D.x"][1], atol=1e-12)


@pytest.mark.parametrize(
    ("name", "start", "stop", "limit", "side"),
    [
        ("triad_past_its_lock.toml", -100.0, 0.0, -63.0, -1.0),
        ("triad_locks_ahead.toml", 100.0, 118.0, 116.6, 1.0),
    ],
)
def test_a_triad_past_its_limit_is_not_assembled_on_another_branch(
    name, start, stop, limit, side
):
    """The crank can rock up to ``limit`` (deg from its reference) on one ``side``."""
    # a step past the crank's limit may converge to another assembly of the triad;
    # the step back to where it started finds that assembly, not the pose it came
    # from, and the position fails instead of jumping there
    mech = assur.load(EDGE / name)
    ref = math.degrees(plan_of(mech).drivers[0].reference)
    at = ref + np.arange(start, stop + 0.25, 0.5)
    with pytest.raises(assur.AssemblyError, match=r"triad \(rod, plate, left, right\)"):
        assur.kinematics(mech, at)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)  # near the limit
        table = assur.kinematics(mech, at, skip_unassembled=True)
    beyond = (at - ref - limit) * side > 0.0
    np.testing.assert_array_equal(table["angle"], at[~beyond])
    # what is left is one branch: C moves little from a position to the next
    moves = np.hypot(np.diff(table["C.x"]), np.diff(table["C.y"]))
    assert moves.max() < 20.0 * np.median(moves)
    # a position alone is refused too
    with pytest.raises(assur.AssemblyError):
        assur.kinematics(mech, [ref + limit + 2.0 * side])


def test_triad_at_a_dead_centre_gives_one_error(capsys):
    """Three parallel links: the reference pose itself is a dead centre."""
    path = EDGE / "triad_singular.toml"
    with pytest.raises(
        assur.ModelError, match=r"triad \(rod, plate, left, right\).*dead"
    ):
        assur.forces(assur.load(path), [80.0, 90.0])
    assert main(["forces", str(path), "--angles", "90"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith("assur: error:")


def test_reference_pose_at_a_dead_centre_is_refused():
    mech = assur.catalog.four_bar()
    coupler = mech.joint("B").at
    # put the rocker's pivot on the line B-C beyond C: coupler and rocker in line
    c = np.asarray(mech.joint("C").at)
    d = c + 0.08 * (c - np.asarray(coupler)) / np.hypot(*(c - np.asarray(coupler)))
    joints = tuple(
        dataclasses.replace(j, at=tuple(d)) if j.name == "D" else j for j in mech.joints
    )
    with pytest.raises(assur.ModelError, match=r"RRR \(coupler, rocker\).*dead centre"):
        assur.kinematics(dataclasses.replace(mech, joints=joints), [60.0])


def test_mechanism_built_from_lists_and_arrays():
    joints = [
        assur.Joint("A", "revolute", ["ground", "crank"], [0.0, 0.0]),
        assur.Joint("B", "revolute", ["crank", "rod"], np.array([0.05, 0.0])),
        assur.Joint("C", "revolute", ["rod", "slider"], [0.25, 0.0]),
        assur.Joint("g", "prismatic", ["ground", "slider"], [0.25, 0.0], [1, 0]),
    ]
    links = [assur.Link("crank", ["A", "B"]), assur.Link("rod"), assur.Link("slider")]
    mech = assur.Mechanism(links, joints, [assur.Driver("A", 10.0)])
    t = assur.kinematics(mech, [0.0, 90.0])
    np.testing.assert_allclose(t["C.x"][0], 0.25, rtol=1e-12)
    assert mech == assur.loads(assur.dumps(mech))


@pytest.mark.parametrize("name", ["shaking", "residual", "driver", "angle"])
def test_names_of_table_columns_are_reserved(name):
    mech = assur.catalog.slider_crank()
    joints = tuple(
        dataclasses.replace(j, name=name) if j.name == "guide" else j
        for j in mech.joints
    )
    with pytest.raises(
        assur.ModelError, match=f"joints.{name}: the name '{name}' is taken"
    ):
        dataclasses.replace(mech, joints=joints)


@pytest.mark.parametrize("value", ["true", "1.5", "2"])
def test_format_must_be_the_integer_one(value):
    """1.0 is 1 (JSON writes it so: tests/test_contract_audit.py); true is not."""
    text = assur.dumps(assur.catalog.four_bar()).replace(
        "format = 1", f"format = {value}"
    )
    with pytest.raises(assur.ModelError, match=r"format: version .* is not supported"):
        assur.loads(text)


def test_huge_number_is_one_error():
    text = assur.dumps(assur.catalog.four_bar()).replace(
        "omega = 10.0", "omega = 1" + "0" * 400
    )
    with pytest.raises(assur.ModelError, match=r"drivers\[0\]\.omega: the number"):
        assur.loads(text)


def test_unwritable_csv_is_one_error(tmp_path, capsys):
    path = str(EXAMPLES / "four_bar.toml")
    assert main(["kinematics", path, "--angles", "0", "--csv", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "cannot write" in err


def test_too_many_positions_is_one_error(capsys):
    path = str(EXAMPLES / "four_bar.toml")
    assert main(["kinematics", path, "--angles", "0:1e12:1e-3"]) == 2
    assert "expected at most" in capsys.readouterr().err


def test_massless_link_has_zero_inertia_columns():
    mech = assur.catalog.four_bar()
    links = tuple(
        dataclasses.replace(link, mass=None) if link.name == "rocker" else link
        for link in mech.links
    )
    # its inertia, left as it was, is said to be left out
    with pytest.warns(assur.AssurWarning) as caught:
        t = assur.forces(dataclasses.replace(mech, links=links), [0.0, 45.0])
    assert str(caught[0].message) == (
        "links.rocker.inertia: 8.53333e-05 kg m^2 on a link with no mass is left "
        "out: the link is massless; give it a mass > 0 for its inertia to count"
    )
    for column in ("rocker.Fi.x", "rocker.Fi.y", "rocker.Mi"):
        np.testing.assert_array_equal(t[column], 0.0)


def test_an_inertia_on_a_mass_of_0_is_said_to_be_left_out():
    # its Mi was 0, not -J alpha, without a word
    mech = assur.catalog.four_bar()
    links = tuple(
        dataclasses.replace(link, mass=0.0, inertia=0.1) if link.name == "coupler"
        else link
        for link in mech.links
    )  # fmt: skip
    with pytest.warns(
        assur.AssurWarning,
        match=r"links\.coupler\.inertia: 0\.1 kg m\^2 on a link with a mass of 0 is "
        "left out",
    ):
        assur.forces(dataclasses.replace(mech, links=links), [0.0])


@pytest.mark.parametrize(
    "name", ["slider_crank_exercise", "six_bar_lecture", "class3", "slot_mechanism"]
)
def test_residual_columns_are_round_off(name):
    """The table's own equilibrium check stays at round-off over a turn."""
    mech = assur.load(EXAMPLES / f"{name}.toml")
    t = assur.forces(mech, np.arange(0.0, 360.0, 10.0))
    largest = max(float(np.max(t[c])) for c in t.columns if c.endswith(".F"))
    assert np.max(t["residual.force"]) <= 1e-9 * largest
    assert np.max(t["residual.moment"]) <= 1e-9 * largest * 1.0


def test_closed_pipe_is_quiet():
    """``assur forces FILE | head`` stops without an error line."""
    import subprocess
    import sys

    path = EXAMPLES / "slider_crank_exercise.toml"
    run = subprocess.run(
        f"{sys.executable} -m assur forces {path} --csv - | head -1",
        shell=True,
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.stdout.startswith("angle")
    assert "error" not in run.stderr
    assert "Traceback" not in run.stderr


@pytest.mark.parametrize("option", ["--csv /dev/stdout", "--parquet /dev/stdout"])
def test_a_closed_pipe_named_dev_stdout_is_quiet_too(option):
    """``--csv /dev/stdout | head`` ends as ``--csv - | head`` does: status 0.

    It said "cannot write the file (Broken pipe)", status 2.
    """
    import subprocess
    import sys

    if option.startswith("--parquet"):
        pytest.importorskip("pyarrow")
    path = EXAMPLES / "slider_crank_exercise.toml"
    run = subprocess.run(
        f"set -o pipefail; {sys.executable} -m assur forces {path} --angles "
        f"0:99999:1 {option} | head -c 10 > /dev/null",
        shell=True,
        executable="/bin/bash",
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""


def test_summary_leaves_out_the_residual(capsys):
    assert (
        main(["forces", str(EXAMPLES / "slider_crank_exercise.toml"), "--angles", "45"])
        == 0
    )
    header = capsys.readouterr().out.splitlines()[0].split()
    assert header == [
        "angle",
        "A.F",
        "B.F",
        "C.F",
        "guide.F",
        "driver.torque",
        "driver.torque_check",
    ]


def test_graph_of_every_example():
    """Links as nodes, joints as edges keyed by name, one connected mechanism."""
    import networkx as nx

    for path in sorted(EXAMPLES.glob("*.toml")):
        mech = assur.load(path)
        g = assur.graph(mech)
        assert set(g.nodes) == {"ground", *(link.name for link in mech.links)}
        assert sorted(k for _, _, k in g.edges(keys=True)) == sorted(
            j.name for j in mech.joints
        )
        assert nx.is_connected(g)


def test_an_empty_sweep_gives_an_empty_table(example):
    # a class III group is followed by continuation: with no position, nothing to
    # walk to (this was a TypeError)
    from .test_kinetostatics import needs_forces

    runs = [assur.kinematics] + ([assur.forces] if needs_forces(example) else [])
    drivers = len(example.drivers)
    none = np.zeros(0) if drivers == 1 else np.zeros((0, drivers))
    for run in runs:
        table = run(example, none)
        assert len(table) == 0
        assert table.to_array().shape == (0, len(table.columns))


@pytest.mark.parametrize(
    ("mech", "angle", "group", "what"),
    [
        # coupler and rocker stretched out exactly: the pin's height computes as the
        # root of -8e-17, and the pose was said not to assemble; crank + frame =
        # coupler + rocker, so the branches meet there (a change point)
        (assur.catalog.four_bar(crank=0.04, coupler=0.06, rocker=0.06, frame=0.08),
         180.0, "RRR (coupler, rocker)", "change point"),
        # the rod square to the slide line, its length the crank's: the pin of the
        # slider comes back over the crank's pivot, the branches meet there too
        (assur.catalog.slider_crank(rod=0.074), 90.0, "RRP (rod, slider)",
         "change point"),
        # coupler and rocker stretched out at the end of the crank's swing: the
        # branches meet there and the crank turns back (a limit, not a change point)
        (assur.catalog.four_bar(crank=0.03, coupler=0.025, rocker=0.025, frame=0.04),
         90.0, "RRR (coupler, rocker)", "dead centre"),
    ],
)  # fmt: skip
def test_a_group_stretched_out_exactly_stands_at_a_dead_centre(
    mech, angle, group, what
):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        with pytest.raises(assur.SingularConfigurationError) as caught:
            assur.kinematics(mech, [angle])
        assert str(caught.value).startswith(
            f"group {group}: {what} at driver position {angle:g} deg"
        )
        # a sweep that skips it keeps its neighbours
        table = assur.kinematics(
            mech, [angle - 10.0, angle, angle + 10.0], skip_unassembled=True
        )
    # past the end of a swing nothing assembles
    left_out = [angle] if what == "change point" else [angle, angle + 10.0]
    assert table.skipped.tolist() == left_out
    assert len(table) == 3 - len(left_out)


# ------------------------------------------------------------------------------------
# A triad near a change point: the continuation keeps to the branch it is on


NEAR = EDGE / "triad_near_change_point.toml"


def _triad_path(targets: list[float], step_deg: float = 0.05) -> dict[float, tuple]:
    """Follow the triad of ``NEAR`` from its reference pose, in fine steps.

    An independent continuation (not assur's): the unknowns are the plate's
    rotation and its pin C, the equations the rod's and the rockers' lengths, solved
    by Newton's method from the last pose at every step of ``step_deg`` along the
    crank's straight path to each target (deg). A step that does not converge, or
    moves the pose by more than 0.02 (rad, m), ends the path: the branch's limit.
    Returns C (m) and the plate's rotation (rad) at each target reached.
    """
    import tomllib

    data = tomllib.loads(NEAR.read_text(encoding="utf-8"))
    at = {k: np.array(v["at"], float) for k, v in data["joints"].items()}
    o, b0, c0 = at["O2"], at["B"], at["C"]
    rc = np.linalg.norm(b0 - o)
    ref = math.degrees(math.atan2(b0[1] - o[1], b0[0] - o[0]))
    rod = np.linalg.norm(c0 - b0)
    hangs = [(at["D"] - c0, at["F"]), (at["E"] - c0, at["G"])]
    lengths = [np.linalg.norm(at["D"] - at["F"]), np.linalg.norm(at["E"] - at["G"])]

    def solve(q, theta):
        for _ in range(30):
            b = o + rc * np.array([math.cos(theta), math.sin(theta)])
            c, s = math.cos(q[0]), math.sin(q[0])
            res = [np.sum((q[1:] - b) ** 2) - rod**2]
            jac = [[0.0, *(2.0 * (q[1:] - b))]]
            for (d, pivot), length in zip(hangs, lengths, strict=True):
                u = np.array([c * d[0] - s * d[1], s * d[0] + c * d[1]])
                gap = q[1:] + u - pivot
                res.append(gap @ gap - length**2)
                jac.append([2.0 * gap @ np.array([-u[1], u[0]]), *(2.0 * gap)])
            if max(abs(r) for r in res) < 1e-16:
                return q
            q = q - np.linalg.solve(np.array(jac), np.array(res))
        return None

    out = {}
    for side in (1.0, -1.0):
        q = np.array([0.0, *c0])
        theta = ref
        ahead = [t for t in targets if (t - ref) * side >= 0]
        for target in sorted(ahead, key=lambda t: abs(t - ref)):
            count = max(1, math.ceil(abs(target - theta) / step_deg))
            begin = theta
            for i in range(1, count + 1):
                theta = begin + (target - begin) * i / count
                new = solve(q, math.radians(theta))
                if new is None or np.max(np.abs(new - q)) > 0.02:
                    break
                q = new
            else:
                out[target] = (q[1], q[2], q[0])
                continue
            break
    return out


def _triad_oracle(angles) -> dict[float, tuple]:
    """The oracle's pose at each crank angle (deg), as assur takes a crank angle.

    The angle within half a turn of the reference pose (60 deg); where the branch
    ends before it, the same angle a turn the other way round.
    """
    near = {a: 60.0 + (a - 60.0 + 180.0) % 360.0 - 180.0 for a in angles}
    other = {a: w - 360.0 if w > 60.0 else w + 360.0 for a, w in near.items()}
    path = _triad_path(sorted(set(near.values()) | set(other.values())))
    return {a: path.get(near[a], path.get(other[a])) for a in angles}


@pytest.mark.parametrize(
    "angles",
    [
        np.arange(0.0, 361.0, 45.0),
        np.arange(95.0, 105.01, 0.25),
        np.arange(0.0, 360.0, 1.0),
    ],
    ids=["coarse", "dense", "one-degree"],
)
def test_a_triad_near_a_change_point_keeps_to_its_branch(angles):
    """Past 99.2 deg the 5-deg continuation once jumped onto the other assembly
    (joint C 7.6 mm off at 100 deg, 55 mm at 150 deg, without a word), and a dense
    sweep said that 99.25 deg cannot be assembled."""
    oracle = _triad_oracle(angles.tolist())
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(assur.load(NEAR), angles)
    # the positions past the fold at 214.3 deg are reached the other way, and said
    said = [str(w.message) for w in caught]
    assert all("reached turning the other way round" in s for s in said), said
    assert len(said) == int(np.any((angles > 214.3) & (angles < 240.0)))
    want = np.array([oracle[a] for a in angles.tolist()])
    np.testing.assert_allclose(table["C.x"], want[:, 0], rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["C.y"], want[:, 1], rtol=0, atol=1e-9)
    turned = np.radians(table["plate.angle"]) - want[:, 2]
    np.testing.assert_allclose(np.sin(turned), 0.0, atol=1e-9)


def test_a_triad_near_a_change_point_folds_where_the_oracle_does():
    """214 deg is on the branch the forward way; 214.5 deg lies past its fold and
    is reached the other way round (as -145.5 deg), as the oracle finds."""
    with pytest.warns(assur.AssurWarning, match=r"position 214\.5 deg is reached"):
        table = assur.kinematics(assur.load(NEAR), [214.0, 214.5, -145.5])
    path = _triad_path([214.0, 214.5, -145.5])
    assert 214.5 not in path
    want = [path[214.0][0], path[-145.5][0], path[-145.5][0]]
    np.testing.assert_allclose(table["C.x"], want, rtol=0, atol=1e-9)


@pytest.mark.parametrize("step", [1.0, 0.04])
def test_positions_reached_the_other_way_round_are_said_once(monkeypatch, step):
    """A one-degree sweep got 215 deg as -145 deg, on the backward path, past the
    forward path's fold at 214.3 deg: the poses jumped between 214 and 215 deg
    without a word. Said once, for a sweep of several slices too (0.04 deg)."""
    from assur import _state

    monkeypatch.setattr(_state, "CHUNK", 4096)  # 9000 positions: three slices
    angles = np.arange(0.0, 360.0, step)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(assur.load(NEAR), angles)
    said = [str(w.message) for w in caught]
    assert len(said) == 1, said
    first = angles[angles > 214.3][0]
    last = angles[angles < 240.0][-1]
    below = angles[angles < 214.3][-1]
    reached = (
        (f"position {first:g} deg is reached", "it")
        if first == last
        else (f"positions {first:g} deg to {last:g} deg are reached", "them")
    )
    assert said[0] == (
        f"group triad (rod, plate, left_rocker, right_rocker): driver {reached[0]} "
        "turning the other way round from the reference pose (60 deg); the group "
        f"cannot follow the crank to {reached[1]} the short way (its branch folds "
        f"between {below:g} deg and {first:g} deg)"
    )
    # the numbers are those of the backward path, as before
    other = assur.kinematics(assur.load(NEAR), [first - 360.0])
    row = np.flatnonzero(angles == first)[0]
    np.testing.assert_allclose(table["C.x"][row], other["C.x"][0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("step", [45.0, 1.0, 0.5, 0.013])
def test_a_triad_through_its_change_points_stays_a_parallelogram(step):
    """The continuation's halved steps near a change point once followed the other
    assembly (the plate turned 7.5 deg at 239.5 deg in a 0.5-deg sweep)."""
    mech = assur.load(EDGE / "triad_parallelogram.toml")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)  # near a dead centre
        table = assur.kinematics(mech, np.arange(0.0, 360.0, step))
    np.testing.assert_allclose(table["plate.angle"], 0.0, atol=1e-6)
    np.testing.assert_allclose(
        table["left_rocker.angle"], table["right_rocker.angle"], atol=1e-6
    )


# ------------------------------------------------------------------------------------
# A dyad's change points after a triad


@pytest.mark.parametrize("step", [45.0, 0.5])
def test_a_dyad_after_a_triad_stays_a_parallelogram(step):
    """The dyad's change points were looked for only before the first triad: the
    sweep flipped to an antiparallelogram near 77.4 deg (po.omega -2.28 -> +6.85
    rad/s between 77 and 77.5 deg) with a dead centre's warning alone."""
    mech = assur.load(EDGE / "class3_parallelogram.toml")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(mech, np.arange(0.0, 360.0, step))
    said = [str(w.message) for w in caught]
    changes = [s for s in said if "change point" in s]
    assert all(s.startswith("group RRR (pc, po)") for s in changes), said
    assert any("77.4" in s for s in changes), said
    # po stays parallel to the rocker's F-H: it turns as the rocker does
    gap = (table["po.angle"] - table["left_rocker.angle"] + 180.0) % 360.0 - 180.0
    np.testing.assert_allclose(gap - gap[0], 0.0, atol=1e-6)
    far = np.abs(table["angle"] - 77.414) > 1.0
    np.testing.assert_allclose(
        table["po.omega"][far], table["left_rocker.omega"][far], rtol=1e-9, atol=1e-9
    )


# ------------------------------------------------------------------------------------
# Where a mechanism assembles, for positions given out of order


def test_where_it_assembles_is_told_in_order_for_positions_out_of_order():
    """The runs were taken in the order given: "420 deg to 45 deg; 430 deg to 40 deg;
    400 deg" for a double rocker that assembles from 24 to 96 deg (a turn on, 384 to
    456 deg) on the circuit of its reference pose."""
    mech = assur.catalog.four_bar(
        crank=0.1, coupler=0.05, rocker=0.08, frame=0.1, angle=60.0
    )
    at = [420.0, 45.0, 0.0, 430.0, 40.0, 180.0, 400.0]
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(mech, at)
    assert str(caught.value).endswith(
        "it assembles for 40 deg to 45 deg; 400 deg to 430 deg"
    ), str(caught.value)
    # in order, the runs are as they were
    with pytest.raises(assur.AssemblyError) as caught:
        assur.kinematics(mech, sorted(at, reverse=True))
    assert str(caught.value).endswith(
        "it assembles for 430 deg to 400 deg; 45 deg to 40 deg"
    ), str(caught.value)


# ------------------------------------------------------------------------------------
# Change points on the straight paths of two drivers


FIVE_PARALLELOGRAM = EDGE / "five_bar_parallelogram.toml"


@pytest.mark.parametrize(
    "angles",
    [
        np.repeat(np.arange(60.0, 421.0, 45.0)[:, None], 2, axis=1),
        np.array([[195.0, -30.0], [-170.0, 400.0], [425.0, 95.0], [-250.0, 60.0]]),
        np.stack(np.meshgrid(np.arange(-300.0, 400.0, 41.0), [-90.0, 120.0, 500.0]))
        .reshape(2, -1)
        .T,
        # the right crank held at its reference pose: the path is sampled by the
        # crank that moves (by the one that does not, two samples missed 180 deg)
        np.column_stack([np.arange(60.0, 421.0, 45.0), np.full(9, 120.0)]),
    ],
    ids=["together", "apart", "grid", "one-held"],
)
def test_a_dyad_on_two_cranks_stays_a_parallelogram(angles):
    """With two drivers the change points were not looked for: the sweep switched
    to an antiparallelogram past 180 deg without a word (po.omega -19.03 rad/s at
    195 deg for the crank's 10) and back past 360 deg."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = assur.kinematics(assur.load(FIVE_PARALLELOGRAM), angles)
    said = [str(w.message) for w in caught]
    assert len(said) == 1, said
    assert said[0].startswith(
        "group RRR (pc, po): its two assembly branches meet on the straight path "
        "from the reference pose to driver positions "
    )
    # po stays parallel to the crank's A-H: it turns as the crank does
    np.testing.assert_allclose(table["po.omega"], 10.0, rtol=1e-9)
    np.testing.assert_allclose(table["po.alpha"], 0.0, atol=1e-6)
    gap = (table["po.angle"] - table["left_crank.angle"] + 180.0) % 360.0 - 180.0
    np.testing.assert_allclose(gap, 0.0, atol=1e-6)


def test_the_warning_names_the_positions_whose_path_meets_a_change_point():
    """60 and 150 deg are reached from 60 deg without passing 180 deg; 195 deg
    and beyond are not."""
    angles = np.repeat(np.arange(60.0, 421.0, 45.0)[:, None], 2, axis=1)
    with pytest.warns(assur.AssurWarning) as caught:
        assur.kinematics(assur.load(FIVE_PARALLELOGRAM), angles)
    (message,) = [str(w.message) for w in caught]
    assert (
        "driver positions (195 deg, 195 deg) to (420 deg, 420 deg) (a change point)"
        in message
    )


def test_a_five_bar_without_change_points_is_quiet_and_unchanged():
    """The two-crank five-bar's rods never line up: nothing changes branch, and its
    numbers are those of before the paths were scanned."""
    angles = [[60, 120], [200, -30], [-170, 400], [425, 95], [359.5, 0.5]]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        table = assur.kinematics(
            assur.load(EXAMPLES / "five_bar_two_cranks.toml"), angles
        )
    # C.x, C.y (m) and left_rod.omega (rad/s) at each position
    want = [
        [0.075, 0.14129466118988526, -3.6363636363636349],
        [0.0748116039182648, 0.02834770117108968, 2.784079139125752],
        [0.06401067182693168, 0.05394597156943192, 5.7738812476720129],
        [0.07890902265289888, 0.1389921175492778, -1.3584105490595861],
        [0.11456250709743848, 0.09367330508974633, 0.037479502265329513],
    ]
    got = np.stack([table["C.x"], table["C.y"], table["left_rod.omega"]], axis=1)
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_a_ram_alone_moves_a_fifth_of_its_drawn_size_by_default():
    # its one joint gives it no size: the default stroke was +-2e-13 m, 101 rows of
    # one pose; its centre of mass 0.05 m off the slide line gives it one
    from assur.analysis import default_positions

    ram = assur.load(Path(__file__).parent / "data" / "explain" / "ram_only.toml")
    positions = default_positions(ram)
    assert len(positions) == 101
    assert positions[0] == pytest.approx(-0.01, rel=1e-12)
    assert positions[-1] == pytest.approx(0.01, rel=1e-12)
    # a mechanism with a size keeps it: the drag link's joints span 0.3 m, a
    # fifth of it 0.06 m, whose round stroke is 0.05 m
    drag = assur.load(
        Path(__file__).parent / "data" / "edge" / "drag_link_beside_a_ram.toml"
    )
    assert default_positions(drag)[-1, 1] == pytest.approx(0.05, rel=1e-12)


@pytest.mark.parametrize(
    "path",
    [
        "users/wedge_lifter.toml",
        "explain/slider_driven.toml",
        "users/trammel_slider_driven.toml",
        "explain/ram_only.toml",
    ],
)
def test_a_prismatic_driver_s_default_stroke_is_a_round_number(path: str) -> None:
    # +-20 % of the wedge lifter's size gave -0.0223607 m in steps of 0.000447214
    from assur.analysis import default_positions
    from assur.plan import plan_of

    mech = assur.load(Path(__file__).parent / "data" / path)
    positions = default_positions(mech)
    stroke = float(positions[-1])
    mantissa = f"{stroke:e}".partition("e")[0]
    assert float(mantissa) in (1.0, 2.0, 5.0)
    # the largest so round within a fifth of the size, and symmetric about the
    # reference pose in 100 equal steps
    bound = 0.2 * plan_of(mech).scale
    if bound > 1e-9:  # a ram alone: its drawn size, tested above
        assert stroke <= bound < 2.5 * stroke
    np.testing.assert_allclose(positions, np.linspace(-stroke, stroke, 101))
    assert float(f"{positions[1]:.6g}") == float(f"{positions[1]:.3g}")


@pytest.mark.parametrize(
    ("bound", "stroke"),
    [
        (0.0223607, 0.02),
        (0.06, 0.05),
        (0.3, 0.2),
        (0.5, 0.5),
        (9.99, 5.0),
        (1e-5, 1e-5),
    ],
)
def test_the_round_stroke_is_the_largest_within_its_bound(bound, stroke) -> None:
    from assur.analysis import round_stroke

    assert round_stroke(bound) == stroke
