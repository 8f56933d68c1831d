"""Table columns of the file contract, built as views of the solved arrays.

The order is: ``angle``; every moving link's angle and its derivatives; every joint's,
extra point's and centre of mass's position and derivatives (prismatic joints also
their slide); then the loads and reactions of a force analysis.
"""

from __future__ import annotations

import math

import numpy as np

from assur._kinematics import KinematicState
from assur._vec import Array
from assur.kinetostatics import ForceState
from assur.plan import Plan

__all__ = ["build_columns"]

POINT_SUFFIXES = ("x", "y", "vx", "vy", "ax", "ay", "jx", "jy")


def build_columns(
    plan: Plan,
    state: KinematicState,
    forces: ForceState | None,
    given: Array | None = None,
) -> tuple[tuple[str, ...], dict[str, Array]]:
    """Return the column names and a name-to-array mapping for a solved sweep.

    ``given`` holds the driver positions as the user gave them (deg or m), which the
    ``angle`` columns repeat exactly.
    """
    data: dict[str, Array] = {}
    drivers = plan.drivers
    if given is None:  # positions as the user would give them: deg for a crank
        scale = [180.0 / math.pi if d.kind == "R" else 1.0 for d in drivers]
        given = state.drive * np.asarray(scale)
    drive = [np.array(given[:, i]) for i in range(len(drivers))]
    data["angle"] = drive[0]
    if len(drivers) > 1:
        for d, values in zip(drivers, drive, strict=False):
            data[f"{d.pair.name}.drive"] = values
    driven = {d.body for d in drivers}
    for b, name in enumerate(plan.bodies):
        if b == 0 or "~" in name:
            continue
        angle = plan.angle0[b] + state.link[0, :, b]
        if b in driven:
            i = next(i for i, d in enumerate(drivers) if d.body == b)
            if drivers[i].kind == "R":
                data[f"{name}.angle"] = drive[i]
            else:
                data[f"{name}.angle"] = angle * (180.0 / math.pi)
        else:
            data[f"{name}.angle"] = (_continuous(angle) if angle.size else angle) * (
                180.0 / math.pi
            )
        for k, key in ((1, "omega"), (2, "alpha"), (3, "jerk")):
            data[f"{name}.{key}"] = state.link[k, :, b]
    for name in plan.points:
        p = plan.point_index[name]
        for k in range(4):
            data[f"{name}.{POINT_SUFFIXES[2 * k]}"] = state.point[k, :, p, 0]
            data[f"{name}.{POINT_SUFFIXES[2 * k + 1]}"] = state.point[k, :, p, 1]
        if name in state.slide:
            for k, key in enumerate(("s", "v", "a", "j")):
                data[f"{name}.{key}"] = state.slide[name][k]
    if forces is not None:
        _force_columns(plan, state, forces, data)
    for values in data.values():
        if values.flags.owndata:
            values.flags.writeable = False
    return tuple(data), data


def _continuous(angle: Array) -> Array:
    """Remove the jumps of a turn from angles (rad); the first is put in (-pi, pi]."""
    first = angle[0]
    shift = first - (math.pi - (math.pi - first) % (2.0 * math.pi))
    turns = np.round(np.diff(angle) * (0.5 / math.pi))
    if turns.any():
        angle = angle - 2.0 * math.pi * np.concatenate(([0.0], np.cumsum(turns)))
    return angle - shift if shift else angle


def _force_columns(
    plan: Plan, state: KinematicState, forces: ForceState, data: dict[str, Array]
) -> None:
    for b, name in enumerate(plan.bodies):
        if b and "~" not in name:
            data[f"{name}.Fi.x"] = forces.inertia_force[:, b, 0]
            data[f"{name}.Fi.y"] = forces.inertia_force[:, b, 1]
            data[f"{name}.Mi"] = forces.inertia_torque[:, b]
    for name, pair in plan.pairs.items():
        if pair.virtual:
            continue
        force, couple = forces.reactions[name]
        data[f"{name}.Fx"] = force[:, 0]
        data[f"{name}.Fy"] = force[:, 1]
        data[f"{name}.F"] = forces.magnitude[name]
        if pair.kind == "P":
            data[f"{name}.M"] = couple
            data[f"{name}.offset"] = forces.offset[name]
    for i, d in enumerate(plan.drivers):
        what = "torque" if d.kind == "R" else "force"
        if i == 0:
            data[f"driver.{what}"] = forces.balancing[:, 0]
            data[f"driver.{what}_check"] = forces.check[:, 0]
        if len(plan.drivers) > 1:
            data[f"{d.pair.name}.{what}"] = forces.balancing[:, i]
            data[f"{d.pair.name}.{what}_check"] = forces.check[:, i]
    data["shaking.Fx"] = forces.shaking[:, 0]
    data["shaking.Fy"] = forces.shaking[:, 1]
    data["shaking.M"] = forces.shaking[:, 2]
    data["residual.force"] = forces.residual[:, 0]
    data["residual.moment"] = forces.residual[:, 1]
