"""A group's closeness to a dead centre, told against its own size.

A slider dyad and the Newton solver's triads weighed their equations in metres against
those in radians by the whole mechanism's size: in a chain 12 m long, ten RPR groups
0.3 m across were warned of as near a dead centre at every driver position (each of
them alone was not), and a slider group a million times smaller than its machine was
refused as at a dead centre.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

import assur
from assur import Driver, Joint, Link, Mechanism
from assur.plan import compile_plan

TURN = np.arange(0.0, 360.0, 1.0)
"""A whole turn of the crank, deg."""


def _groups(pattern: str, small: float = 1.0) -> tuple[list[Link], list[Joint]]:
    """A crank driving one group per letter, each on the one before, ``small`` m/m.

    ``R`` an RRR dyad, ``P`` an RPR (a block on the last output link, its guide
    pivoted on the frame), ``T`` the class III triad of examples/class3.toml; each
    about 0.3 m across (times ``small``) and its output 0.3 m further along.
    """
    links = [Link("crank", mass=1.0, center="A", inertia=0.01)]
    joints = [Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0))]
    x, y = 0.1 * math.cos(0.5), 0.1 * math.sin(0.5)
    last, pin = "crank", "B0"

    def at(dx: float, dy: float) -> tuple[float, float]:
        return (small * (x + dx), small * (y + dy))

    for i, kind in enumerate(pattern):
        out = (0.3, 0.0)
        if kind == "R":
            names = [f"u{i}", f"v{i}"]
            joints += [
                Joint(pin, "revolute", (last, names[0]), at(0.0, 0.0)),
                Joint(f"C{i}", "revolute", tuple(names), at(0.22, 0.10)),
                Joint(f"G{i}", "revolute", (names[1], "ground"), at(0.25, -0.15)),
            ]
        elif kind == "P":
            names = [f"b{i}", f"g{i}"]
            joints += [
                Joint(pin, "revolute", (last, names[0]), at(0.0, 0.0)),
                Joint(f"S{i}", "prismatic", (names[1], names[0]), at(0, 0), (-1, 0.6)),
                Joint(f"G{i}", "revolute", ("ground", names[1]), at(0.25, -0.15)),
            ]
        else:
            names = [f"rod{i}", f"plate{i}", f"lr{i}", f"rr{i}"]
            rod, plate, lr, rr = names
            joints += [
                Joint(pin, "revolute", (last, rod), at(0.0, 0.0)),
                Joint(f"C{i}", "revolute", (rod, plate), at(0.205, -0.05)),
                Joint(f"E{i}", "revolute", (plate, lr), at(0.165, 0.0)),
                Joint(f"F{i}", "revolute", (plate, rr), at(0.265, 0.01)),
                Joint(f"H{i}", "revolute", ("ground", lr), at(0.165, 0.18)),
                Joint(f"K{i}", "revolute", ("ground", rr), at(0.275, 0.19)),
            ]
            out = (0.325, 0.01)
        links += [Link(n, mass=0.5, center=pin, inertia=0.001) for n in names]
        x, y, last, pin = x + out[0], y + out[1], names[-1], f"D{i}"
    return links, joints


def chain(pattern: str, small: float = 1.0) -> Mechanism:
    """A crank driving the groups of ``pattern`` in a row (see :func:`_groups`)."""
    links, joints = _groups(pattern, small)
    return Mechanism(
        links=tuple(links),
        joints=tuple(joints),
        drivers=(Driver("A", 10.0),),
        name=pattern[:8],
    )


def near(mech: Mechanism, positions: np.ndarray = TURN) -> dict[str, str]:
    """The groups warned of as near a dead centre over ``positions``, and where."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assur.kinematics(mech, positions)
    found = {}
    for w in caught:
        text = str(w.message)
        if "near a dead centre" in text:
            group, _, where = text.partition(": near a dead centre")
            found[group.removeprefix("group ")] = where
    return found


def test_the_builder_s_groups_are_well_conditioned_alone() -> None:
    """The premise of the tests below: each group alone is warned of nowhere."""
    assert near(chain("RPRT")) == {}


def truss(far: float) -> tuple[list[Link], list[Joint]]:
    """A rigid dyad on the frame from ``far`` / 2 to ``far`` m along x (far, m)."""
    return [Link("t1"), Link("t2")], [
        Joint("T1", "revolute", ("ground", "t1"), (far, 0.0)),
        Joint("T2", "revolute", ("t1", "t2"), (0.75 * far, 0.25 * far)),
        Joint("T3", "revolute", ("t2", "ground"), (0.5 * far, 0.0)),
    ]


def machine(pattern: str, small: float = 1.0, far: float = 0.0) -> Mechanism:
    """:func:`chain` beside a :func:`truss` ``far`` m away (none at 0)."""
    links, joints = _groups(pattern, small)
    if far:
        more = truss(far)
        links, joints = links + more[0], joints + more[1]
    return Mechanism(
        links=tuple(links), joints=tuple(joints), drivers=(Driver("A", 10.0),)
    )


def test_a_long_chain_warns_no_more_than_its_groups_alone() -> None:
    """At 40 groups (12 m) every RPR was near a dead centre from 0 to 359 deg."""
    mech = chain("RPRP" * 10)
    assert compile_plan(mech).scale > 10.0
    assert near(mech) == near(chain("RPRP")) == {}


def test_a_triad_in_a_large_machine_warns_no_more_than_alone() -> None:
    """Its position equations were 'nearly singular' at every driver position."""
    assert near(machine("RRT", far=40.0)) == near(chain("RRT")) == {}


def test_a_small_slider_group_in_a_large_machine_is_not_refused() -> None:
    """An RPR 6 um across beside a truss 20 m across was at a 'dead centre'."""
    mech = machine("P", small=2e-5, far=20.0)
    plan = compile_plan(mech)
    assert plan.scale > 1e6 * plan.solvers[0].size  # type: ignore[attr-defined]
    table = assur.kinematics(mech, [0.0, 90.0])
    assert np.isfinite(table["g0.omega"]).all()
    assert near(mech) == {}


def test_a_group_near_its_dead_centre_in_a_large_machine_is_still_warned_of() -> None:
    """An RPR on the crank, its guide's pivot 1 mm outside the crank pin's circle.

    Warned of at the same positions alone and beside a chain of 39 dyads (12 m).
    """
    pin = -0.1 * np.array([math.cos(0.5), math.sin(0.5)])
    pivot = 0.101 * np.array([math.cos(2.0), math.sin(2.0)])
    extra = (
        Joint("BX", "revolute", ("crank", "block"), tuple(pin)),
        Joint("SX", "prismatic", ("guide", "block"), tuple(pin), tuple(pin - pivot)),
        Joint("GX", "revolute", ("ground", "guide"), tuple(pivot)),
    )
    found = []
    for pattern in ("", "R" * 39):
        links, joints = _groups(pattern)
        links += [Link("block"), Link("guide", mass=0.5, center="GX")]
        mech = Mechanism(
            links=tuple(links),
            joints=tuple(joints) + extra,
            drivers=(Driver("A", 10.0),),
        )
        found.append(near(mech))
    assert list(found[0]) == ["RPR (block, guide)"]
    assert found[1] == found[0]


def test_a_triad_with_a_sliding_pair_in_a_large_machine_warns_as_alone() -> None:
    """A prismatic pair's rotation equation is weighed by the group's own size too."""
    alone = assur.load(Path(__file__).parent / "data" / "edge" / "triadP.toml")
    links, joints = truss(40.0)
    big = Mechanism(
        links=alone.links + tuple(links),
        joints=alone.joints + tuple(joints),
        drivers=alone.drivers,
    )
    assert compile_plan(big).scale > 100.0 * compile_plan(alone).scale
    positions = np.arange(0.0, 110.0, 1.0)
    assert near(big, positions) == near(alone, positions) == {}
