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


@pytest.mark.parametrize("value", ["true", "1.0", "2"])
def test_format_must_be_the_integer_one(value):
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
    ("mech", "angle", "group"),
    [
        # coupler and rocker stretched out exactly: the pin's height computes as the
        # root of -8e-17, and the pose was said not to assemble
        (assur.catalog.four_bar(crank=0.04, coupler=0.06, rocker=0.06, frame=0.08),
         180.0, "RRR (coupler, rocker)"),
        # the rod square to the slide line, its length the crank's
        (assur.catalog.slider_crank(rod=0.074), 90.0, "RRP (rod, slider)"),
    ],
)  # fmt: skip
def test_a_group_stretched_out_exactly_stands_at_a_dead_centre(mech, angle, group):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", assur.AssurWarning)
        with pytest.raises(assur.SingularConfigurationError) as caught:
            assur.kinematics(mech, [angle])
        assert str(caught.value).startswith(
            f"group {group}: dead centre at driver position {angle:g} deg"
        )
        # a sweep that skips it keeps its neighbours
        table = assur.kinematics(
            mech, [angle - 10.0, angle, angle + 10.0], skip_unassembled=True
        )
    assert table.skipped.tolist() == [angle]
    assert len(table) == 2
