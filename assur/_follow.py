"""Continuation steps of the Newton-solved groups: predictor, corrector, step control.

A step moves every position of a batch from a solved pose towards its target driver
position: the pose plus its velocity coefficients times the step predicts where the
branch goes, Newton's method corrects the prediction, and the step is accepted only
when the correction stays small, the path's tangent turns little and the Jacobian's
determinant keeps its sign; otherwise it is halved. The driving links' motions for
the steps are made here too (the forward pass uses the same ones).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from assur._quiet import quiet
from assur._vec import Array, Mask
from assur.groups._motion import Motion
from assur.groups.driver import motion
from assur.plan import Plan

__all__ = [
    "BranchOf",
    "Branches",
    "advance",
    "drivers",
    "frame",
    "layout",
    "nested",
    "packed",
    "tangents",
]

BRANCH_TOLERANCE = 1e-6
"""A corrector's change to the predicted pose always accepted: this many radians and
this fraction of the group's reach."""
CORRECTION = 0.5
"""Largest corrector's change to the predicted pose, as a fraction of the step (the
larger of the driver's and the predicted motion of the group's links)."""
TURN = 0.5
"""Largest turn of the path's tangent over one step, rad, in the space of the driver's
position and the groups' poses (angles in rad, lengths in units of the reach)."""
HALVINGS = 10
"""A step is halved at most this many times below the largest step (5 deg / 1024, about
0.005 deg, for a crank). A step that small which changes the Jacobian's sign with a
tangent that turns little passes a point where two assemblies meet (a change point,
or two that pass closer than such a step resolves): it is taken, and the motion
carries on with continuous velocities. Any other step refused at that size fails."""
PASSES = 2000
"""Most trial steps of a batch; positions not arrived by then fail."""

BranchOf = Callable[[Array, int], dict[int, Array]]
"""Each closed-form group's branch at driver positions (n, d), SI units, by solver
index; a group absent keeps its reference pose's branch. The second argument is a
solver index: the groups before it are all the caller reads."""
Branches = BranchOf | dict[int, Array] | None
"""The closed-form groups' branches for a step: a :data:`BranchOf`, the branch of
each group at each of the step's positions (n,) by solver index, or None for the
reference pose's."""


def drivers(
    plan: Plan, drive: Array, speed: Any, acceleration: Any, jerk: Any = ()
) -> list[Motion]:
    """Return every body at rest but the driving links, which move as prescribed.

    ``jerk`` holds each driver's jerk as ``speed`` its speed; none given, zero.
    """
    bodies: list[Motion] = [frame(plan)] * len(plan.bodies)
    for i, d in enumerate(plan.drivers):
        m = motion(d, drive[:, i], speed[i], acceleration[i], jerk[i] if jerk else 0.0)
        m.finish()
        bodies[d.body] = m
    return bodies


def frame(plan: Plan) -> Motion:
    """Return the frame's motion, made once per plan (it never changes)."""
    found = plan.memo.get("frame")
    if found is None:
        found = plan.memo["frame"] = Motion.fixed()
    return found  # type: ignore[no-any-return]


def layout(plan: Plan) -> list[int]:
    """Return the number of links of each Newton-solved group."""
    return [len(solver.bodies) for solver in plan.solvers if solver.newton]


def packed(poses: list[Any]) -> Array:
    """Return the Newton groups' poses (or rates) as one array (values, positions)."""
    return np.array([v for group in poses for pose in group for v in pose])


def nested(plan: Plan, values: Array) -> list[Any]:
    """Return what :func:`packed` made, as each group's list of link poses."""
    rows = iter(values)
    return [
        [tuple(next(rows) for _ in range(3)) for _ in range(size)]
        for size in layout(plan)
    ]


def _weights(plan: Plan) -> Array:
    """Return the weight of each packed value: 1 for an angle, 1/reach for a length."""
    out = []
    for solver in plan.solvers:
        if solver.newton:
            reach = solver.reach  # type: ignore[attr-defined]
            out += [1.0, 1.0 / reach, 1.0 / reach] * len(solver.bodies)
    return np.array(out)


def _units(plan: Plan) -> Array:
    """Return each driver position's weight: 1 for a crank, 1/size for a slider."""
    return np.array([1.0 if d.kind == "R" else 1.0 / plan.scale for d in plan.drivers])


def tangents(
    plan: Plan,
    at: Array,
    guess: list[Any] | None,
    direction: Array,
    branch_of: Branches,
) -> tuple[Array, Mask, Array, Array]:
    """Solve the Newton groups at driver positions ``at`` (n, d) from ``guess``.

    Returns their poses (packed) and where each failed (groups, n), their rates of
    change as the drivers move by ``direction`` (n, d) per unit (packed) and the signs
    of their Jacobians' determinants (groups, n). ``guess`` None: the reference pose.
    """
    n = at.shape[0]
    still = [0.0] * len(plan.drivers)
    bodies = drivers(plan, at, list(direction.T), still)
    last = max(i for i, solver in enumerate(plan.solvers) if solver.newton)
    if branch_of is None or isinstance(branch_of, dict):
        branch = branch_of or {}
    else:
        branch = branch_of(at, last)
    found: list[Any] = []
    failed = []
    rates = []
    signs = []
    with quiet():
        for index, solver in enumerate(plan.solvers[: last + 1]):
            if solver.newton:
                start = None if guess is None else guess[len(found)]
                assembly = solver.assemble(bodies, n, start)
                found.append(assembly.guess)
                failed.append(assembly.failed)
                signs.append(solver.tangent(bodies))  # type: ignore[attr-defined]
                for b in solver.bodies:
                    m = bodies[b]
                    rates.append((m.phi[1], m.ox[1], m.oy[1]))
            else:
                solver.assemble(bodies, n, branch=branch.get(index))
                solver.derivative(bodies, 1, solver.linearize(bodies))
            for b in solver.bodies:
                bodies[b].finish()
    rate = np.array([np.broadcast_to(v, (n,)) for pose in rates for v in pose])
    return packed(found), np.array(failed), rate, np.array(signs)


def advance(
    plan: Plan,
    start: Array,
    target: Array,
    begun: tuple[Array, Array, Array],
    branch_of: Branches,
    top: Array,
) -> tuple[Array, Array, Array, Mask]:
    """Follow the Newton groups from driver positions ``start`` to ``target`` (n, d).

    ``begun`` holds their packed poses at ``start``, rates of change per unit of the
    path ``target - start`` and Jacobians' signs (see :func:`tangents`); ``top`` (n,)
    the largest step, as a fraction of the path; ``branch_of`` the closed-form
    groups' branches (a dict: one per position, kept over the whole step). Each
    position takes steps of its own: a prediction along the tangent, corrected by
    Newton's method, accepted only when the correction is small, the tangent turns
    little and the Jacobian keeps its sign; otherwise the step is halved, at most
    :data:`HALVINGS` times, after which the groups still refusing it fail there (the
    others go on). Returns the same three at ``target`` and where each group failed
    (groups, n; its pose then NaN).
    """
    path = target - start
    pose, rate, sign = (a.copy() for a in begun)
    n = start.shape[0]
    t = np.zeros(n)
    h = top.copy()
    bottom = top / 2.0**HALVINGS
    owner = np.repeat(np.arange(sign.shape[0]), [3 * k for k in layout(plan)])
    # nothing starts from a pose that failed before
    groups = range(sign.shape[0])
    gone: Mask = np.array([~np.isfinite(pose[owner == g]).all(axis=0) for g in groups])
    active: Mask = np.logical_not(gone.all(axis=0))
    weight = _weights(plan)[:, None]
    move = path * _units(plan)
    for _ in range(PASSES):
        rows = np.flatnonzero(active)
        if not rows.size:
            break
        trial = np.minimum(t[rows] + h[rows], 1.0)
        dt = trial - t[rows]
        guess = pose[:, rows] + rate[:, rows] * dt
        branch = branch_of
        if isinstance(branch, dict):
            branch = {g: values[rows] for g, values in branch.items()}
        found, bad, new, signs = tangents(
            plan,
            start[rows] + path[rows] * trial[:, None],
            nested(plan, guess),
            path[rows],
            branch,
        )
        new = np.where(np.isfinite(new), new, rate[:, rows])
        floor = dt <= bottom[rows] * (1.0 + 1e-9)
        ok = _accepted(
            (guess * weight, found * weight, rate[:, rows] * weight, new * weight),
            owner,
            dt,
            move[rows],
            ~bad & (sign[:, rows] == signs),
            floor,
        )
        ok |= gone[:, rows]  # a group that failed before has no say
        taken = ok.all(axis=0)
        go = rows[taken]
        t[go], pose[:, go], rate[:, go], sign[:, go] = (
            trial[taken],
            found[:, taken],
            new[:, taken],
            signs[:, taken],
        )
        h[go] = np.minimum(2.0 * dt[taken], top[go])
        again = ~taken & ~floor
        h[rows[again]] = 0.5 * dt[again]
        # at the smallest step, the groups refusing it fail; the others go on
        lost = ~taken & floor
        gone[:, rows[lost]] |= ~ok[:, lost]
        active[rows] &= ~gone[:, rows].all(axis=0)
        active[go[t[go] >= 1.0]] = False
    gone[:, active] = True
    pose[gone[owner]] = np.nan
    return pose, rate, sign, gone


def _accepted(
    arrays: tuple[Array, Array, Array, Array],
    owner: Any,
    dt: Array,
    move: Array,
    kept: Mask,
    floor: Mask,
) -> Mask:
    """Return where each group takes its trial step (groups, positions).

    ``arrays`` are the predicted and corrected poses and the tangents at the start
    and the end, all weighted (:func:`_weights`), ``owner`` each row's group;
    ``move`` the drivers' path (weighted); ``kept`` where each group converged with
    its Jacobian's sign unchanged; ``floor`` where the step is as small as steps go.
    """
    change, before, after = arrays[0] - arrays[1], arrays[2], arrays[3]
    driver = np.max(np.abs(move), axis=1) * dt
    along = np.sum(move * move, axis=1)
    out = []
    with quiet():
        for g in range(kept.shape[0]):
            mine = owner == g
            correction = np.max(np.abs(change[mine]), axis=0)
            predicted = np.max(np.abs(before[mine]), axis=0) * dt
            small = correction <= CORRECTION * np.maximum(driver, predicted)
            small |= correction <= BRANCH_TOLERANCE
            a, b = before[mine], after[mine]
            cosine = (along + np.sum(a * b, axis=0)) / np.sqrt(
                (along + np.sum(a * a, axis=0)) * (along + np.sum(b * b, axis=0))
            )
            # no motion at all (a position at its start) turns nothing: NaN passes
            straight = ~(cosine < math.cos(TURN))
            converged = np.isfinite(correction)
            out.append(converged & small & straight & (kept[g] | floor))
    return np.array(out)
