"""The equilibrium residuals of a table, against each link's loads summed one by one."""

from __future__ import annotations

import numpy as np
import pytest

import assur
from assur._crosscheck import residual
from assur._kinematics import motions
from assur._loads import compile_loads
from assur._vec import cross, freeze, full
from assur.groups._motion import point
from assur.kinetostatics import applied_loads, with_friction

from .conftest import EXAMPLES


def _one_by_one(plan, bodies, applied, forces, n):
    """Return the largest unbalanced force and moment, a link at a time."""
    force, moment = np.zeros(n), np.zeros(n)
    for b in range(1, len(plan.bodies)):
        fx, fy, tau = (full(v, n).copy() for v in applied.wrenches[b])
        for name, (rx, ry, couple) in forces.reactions.items():
            pair = plan.pairs[name]
            sign = 1.0 if pair.second == b else -1.0 if pair.first == b else 0.0
            if sign:
                qx, qy = point(bodies[pair.second], pair.d_second, 0)
                turn = cross(qx, qy, rx, ry)
                turn = turn + couple if pair.kind == "P" else turn
                fx, fy, tau = fx + sign * rx, fy + sign * ry, tau + sign * turn
        for d, value in zip(plan.drivers, forces.balancing, strict=True):
            if d.body == b and d.kind == "R":
                tau = tau + value
        m = bodies[b]
        tau = tau - m.ox[0] * fy + m.oy[0] * fx
        force = np.maximum(force, np.maximum(np.abs(fx), np.abs(fy)))
        moment = np.maximum(moment, np.abs(tau))
    return force, moment


@pytest.mark.parametrize(
    "name", ["whitworth.toml", "slider_crank_friction.toml", "four_bar.toml"]
)
def test_the_residuals_are_each_link_s_loads_summed(name):
    mech = assur.load(EXAMPLES / name)
    table = assur.forces(mech, np.arange(0.0, 360.0, 15.0), skip_unassembled=True)
    plan, state, forces = table.plan, table.state, table.force_state
    bodies = motions(plan, state)
    applied = applied_loads(plan, compile_loads(plan), bodies, state, forces.inertia)
    rubbed = with_friction(plan, bodies, applied, forces.friction, "R")
    out = np.empty((2, len(table)))
    residual(plan, bodies, rubbed, forces, out)
    force, moment = _one_by_one(plan, bodies, rubbed, forces, len(table))
    scale = np.max(table["A.F"]) if "A.F" in table else 1.0
    np.testing.assert_allclose(out[0], force, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(out[1], moment, rtol=0, atol=1e-12 * scale)
    assert np.array_equal(
        out, np.array([table["residual.force"], table["residual.moment"]])
    )


def test_a_link_s_unbalanced_nan_is_its_residual():
    # NaN anywhere in a link's sums is the position's residual, whatever the order
    table = assur.forces(assur.catalog.slider_crank(), [0.0, 90.0])
    plan, state, forces = table.plan, table.state, table.force_state
    bodies = motions(plan, state)
    applied = applied_loads(plan, compile_loads(plan), bodies, state, forces.inertia)
    wrenches = list(applied.wrenches)
    wrenches[2] = [np.array([np.nan, 0.0]), wrenches[2][1], wrenches[2][2]]
    out = np.empty((2, 2))
    residual(plan, bodies, type(applied)(tuple(wrenches), applied.inertia), forces, out)
    assert np.isnan(out[:, 0]).all()
    assert np.isfinite(out[:, 1]).all()


def test_freeze_reaches_every_array_of_nested_containers():
    arrays = [np.zeros(2) for _ in range(4)]
    tree = (arrays[0], [1.0, {"a": (arrays[1], None)}], {"b": [arrays[2]]})
    assert freeze(tree) is tree
    assert freeze(arrays[3]) is arrays[3]
    assert freeze(2.0) == 2.0
    assert not any(a.flags.writeable for a in arrays)


def test_full_gives_an_array_as_it_is_and_repeats_anything_else():
    values = np.arange(3.0)
    assert full(values, 3) is values
    for leaf, want in ((2.5, 2.5), (np.float64(-0.0), -0.0), (np.array(4.0), 4.0)):
        found = full(leaf, 3)
        assert found.shape == (3,)
        assert not found.flags.writeable
        assert np.array_equal(np.signbit(found), np.signbit([want] * 3))
        assert np.array_equal(found, [want] * 3)
    assert np.isnan(full(None, 2)).all()
