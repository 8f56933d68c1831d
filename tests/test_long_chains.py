"""Sizes of many points, long chains of groups, and studies far along the turns.

Paths that only a mechanism with more than 64 joints, or driver angles of tens of
turns, take: the mechanism's size from its convex hull (which scales every
tolerance), a chain of 24 dyads solved group after group, and a study's batch at
angles past 10^4 deg.
"""

from __future__ import annotations

import dataclasses
import itertools
import math

import numpy as np
import pytest

import assur
from assur import Driver, Joint, Link, Mechanism
from assur.plan import FEW, _diameter

from .conftest import EXAMPLES


def brute(points: np.ndarray) -> float:
    """The largest distance between two of ``points``, every pair compared."""
    gap = points[:, None, :] - points[None, :, :]
    return max(1e-12, float(np.sqrt((gap * gap).sum(axis=-1)).max()))


@pytest.mark.parametrize("seed", range(40))
def test_the_size_of_many_points_is_their_farthest_pair(seed: int) -> None:
    rng = np.random.default_rng(seed)
    count = int(rng.integers(FEW + 1, 200))
    kind = seed % 4
    if kind == 0:  # scattered
        points = rng.normal(size=(count, 2))
    elif kind == 1:  # on a line: the hull has two corners
        points = np.outer(rng.uniform(-1, 1, count), [3.0, -4.0])
    elif kind == 2:  # few distinct points, each many times
        points = rng.normal(size=(5, 2))[rng.integers(0, 5, count)]
    else:  # a mechanism far from the origin
        points = 1e6 + rng.uniform(0.0, 0.3, (count, 2))
    assert _diameter(points) == pytest.approx(brute(points), rel=1e-12)
    assert _diameter(np.zeros((FEW + 36, 2))) == 1e-12


def chain(count: int) -> Mechanism:
    """A crank driving ``count`` RRR dyads in a row, each on the one before."""
    links = [Link("crank", mass=1.0, center="B", inertia=0.01)]
    half = 0.5
    joints = [
        Joint("A", "revolute", ("ground", "crank"), (0.0, 0.0)),
        Joint(
            "B",
            "revolute",
            ("crank", "u0"),
            (0.1 * math.cos(half), 0.1 * math.sin(half)),
        ),
    ]
    for i in range(count):
        x = 0.3 * i
        links += [
            Link(f"u{i}", mass=0.5, center=f"C{i}", inertia=0.001),
            Link(f"v{i}", mass=0.5, center=f"G{i}", inertia=0.001),
        ]
        joints += [
            Joint(f"C{i}", "revolute", (f"u{i}", f"v{i}"), (x + 0.32, 0.25)),
            Joint(f"G{i}", "revolute", (f"v{i}", "ground"), (x + 0.35, 0.0)),
        ]
        if i + 1 < count:
            joints.append(
                Joint(f"D{i}", "revolute", (f"v{i}", f"u{i + 1}"), (x + 0.4, 0.15))
            )
    return Mechanism(
        links=tuple(links),
        joints=tuple(joints),
        drivers=(Driver("A", 10.0),),
        name="chain",
    )


def test_a_chain_of_24_dyads_is_solved_group_after_group() -> None:
    # 73 joints: its size comes from the hull of its points
    mech = chain(24)
    assert len(mech.joints) > FEW
    s = assur.structure(mech)
    assert len(s.groups) == 24
    assert all(g.kind == "RRR" for g in s.groups)
    table = assur.forces(mech, np.arange(25.0, 36.0, 5.0))
    # the balancing torque against the virtual power of every load, and each
    # link's equilibrium
    np.testing.assert_allclose(
        table["driver.torque"], table["driver.torque_check"], rtol=1e-9
    )
    assert np.max(np.abs(table["residual.force"])) < 1e-8
    # the motion comes down the chain, smaller at each dyad, to the last
    swings = [float(np.ptp(table[f"v{i}.angle"])) for i in range(24)]
    assert swings[0] > 1.0
    assert all(a > b > 0.0 for a, b in itertools.pairwise(swings))


def test_a_study_far_along_the_turns_is_each_variant_s_own_call() -> None:
    pytest.importorskip("pandas")
    base = assur.load(EXAMPLES / "slider_crank_exercise.toml")

    def heavier(m: float) -> Mechanism:
        links = tuple(
            dataclasses.replace(x, mass=x.mass * m) if x.mass else x for x in base.links
        )
        return dataclasses.replace(base, links=links)

    # thirty turns on: angles past 10^4 deg, which the batch reduces to one turn
    angles = 45.0 + 360.0 * 30 + np.arange(0.0, 360.0, 15.0)
    found = assur.sweep(heavier, {"m": [1.0, 2.0]}, angles).summary
    for i, m in enumerate((1.0, 2.0)):
        alone = assur.forces(heavier(m), angles).summary()
        for name in ("driver.torque.max", "B.F.max", "B.F.at"):
            assert found[name].iloc[i] == pytest.approx(alone[name], rel=1e-12)
    assert found["B.F.at"].iloc[0] > 1e4
