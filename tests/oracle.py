"""Independent reference computations for the invariant tests.

Nothing here calls assur's solvers: everything is rebuilt from the mechanism's data
(points, axes, masses, loads) and the columns of a kinematics table.

- poses: each link's rotation from its angle column, the current position (velocity,
  acceleration) of any point given in the reference pose;
- kinematic invariants: rigid links, points on slide lines, finite differences in time,
  trapezoidal consistency of consecutive rows;
- kinetostatics: every link's applied loads (d'Alembert inertia loads, gravity,
  external loads), the equilibrium residual of each link under a table's reactions,
  and a global solve of all links' equilibrium equations at once.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

import assur

GROUND = "ground"


# ------------------------------------------------------------------------------------
# Reference pose


def resolve(mech: assur.Mechanism, spec) -> np.ndarray:
    """Reference-pose coordinates (m) of a point specification."""
    if isinstance(spec, str):
        for joint in mech.joints:
            if joint.name == spec:
                return resolve(mech, joint.at)
        for point in mech.points:
            if point.name == spec:
                return resolve(mech, point.at)
        raise KeyError(spec)
    if isinstance(spec, assur.Toward):
        a = resolve(mech, spec.start)
        b = resolve(mech, spec.toward)
        return a + (b - a) * spec.distance / np.hypot(*(b - a))
    return np.asarray(spec, dtype=float)


def angle0(mech: assur.Mechanism, link: str) -> float:
    """A link's angle in the reference pose (rad): its axis direction, or 0."""
    axis = mech.link(link).axis
    if axis is None:
        return 0.0
    d = resolve(mech, axis[1]) - resolve(mech, axis[0])
    return math.atan2(d[1], d[0])


def unit_axis(joint: assur.Joint) -> np.ndarray:
    axis = np.asarray(joint.axis, dtype=float)
    return axis / np.hypot(*axis)


def reported_points(mech: assur.Mechanism, link: str) -> list[tuple[str, np.ndarray]]:
    """Points of ``link`` that a table reports, with their reference positions.

    Revolute joints of the link; prismatic and slot joints whose second link it is
    (their point moves with the second link); its extra points; its centre of mass.
    """
    out = []
    for joint in mech.joints:
        if link in joint.links and (joint.kind == "revolute" or joint.links[1] == link):
            out.append((joint.name, resolve(mech, joint.at)))
    for point in mech.points:
        if point.link == link:
            out.append((point.name, resolve(mech, point.at)))
    data = mech.link(link)
    if data.center is not None and data.mass:
        out.append((f"{link}.G", resolve(mech, data.center)))
    return out


def column_pair(table: assur.Table, name: str, level: int) -> np.ndarray:
    """(n, 2) array of a reported point's position (0), velocity (1), acceleration (2)
    or jerk (3)."""
    sx, sy = (("x", "y"), ("vx", "vy"), ("ax", "ay"), ("jx", "jy"))[level]
    return np.stack([table[f"{name}.{sx}"], table[f"{name}.{sy}"]], axis=-1)


def turn(angle: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotate the fixed vector(s) ``v`` by the angles ``angle`` (n,): shape (n, 2)."""
    c, s = np.cos(angle), np.sin(angle)
    v = np.asarray(v, dtype=float)
    return np.stack(
        [c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1
    )


def perp(v: np.ndarray) -> np.ndarray:
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


@dataclass
class Pose:
    """A link's motion from its table columns: rotation from the reference pose and
    its derivatives (rad, rad/s, ...), and an anchor point with its motion."""

    rotation: np.ndarray
    rates: tuple[np.ndarray, np.ndarray, np.ndarray]
    anchor_ref: np.ndarray
    anchor: tuple[np.ndarray, ...]

    def point(self, ref: np.ndarray, level: int = 0) -> np.ndarray:
        """Position (0), velocity (1) or acceleration (2) of a body point given by its
        reference-pose coordinates."""
        u = turn(self.rotation, np.asarray(ref, dtype=float) - self.anchor_ref)
        if level == 0:
            return self.anchor[0] + u
        w = self.rates[0][:, None]
        if level == 1:
            return self.anchor[1] + w * perp(u)
        a = self.rates[1][:, None]
        return self.anchor[2] + a * perp(u) - w * w * u


def pose(mech: assur.Mechanism, table: assur.Table, link: str) -> Pose:
    """The motion of ``link`` (the frame included) read from ``table``."""
    n = len(table)
    if link == GROUND:
        zero = np.zeros(n)
        fixed = np.zeros((n, 2))
        return Pose(zero, (zero, zero, zero), np.zeros(2), (fixed, fixed, fixed, fixed))
    rotation = np.radians(table[f"{link}.angle"]) - angle0(mech, link)
    rates = (table[f"{link}.omega"], table[f"{link}.alpha"], table[f"{link}.jerk"])
    points = reported_points(mech, link)
    if not points:
        msg = f"link {link!r} has no reported point"
        raise ValueError(msg)
    name, ref = points[0]
    anchor = tuple(column_pair(table, name, k) for k in range(4))
    return Pose(rotation, rates, ref, anchor)


# ------------------------------------------------------------------------------------
# Kinematic invariants


def rigid_errors(mech: assur.Mechanism, table: assur.Table) -> dict[str, float]:
    """Largest error (m) per link of its reported points against the rigid motion
    given by its angle column and one of its points; and of pairwise distances."""
    out = {}
    for link in (lk.name for lk in mech.links):
        pts = reported_points(mech, link)
        p = pose(mech, table, link)
        worst = 0.0
        for name, ref in pts:
            now = column_pair(table, name, 0)
            worst = max(worst, float(np.max(np.abs(now - p.point(ref)))))
            for other, ref2 in pts:
                length = np.hypot(*(ref2 - ref))
                got = np.hypot(*(column_pair(table, other, 0) - now).T)
                worst = max(worst, float(np.max(np.abs(got - length))))
        out[link] = worst
    return out


def slide_errors(
    mech: assur.Mechanism, table: assur.Table
) -> dict[str, tuple[float, ...]]:
    """Per prismatic or slot joint: distance (m) of its point from the slide line fixed
    in its first link, relative rotation of its links (rad, prismatic only), and the
    error (m) of its slide column."""
    out = {}
    for joint in mech.joints:
        if joint.kind == "revolute":
            continue
        first, second = joint.links
        p1 = pose(mech, table, first)
        at = resolve(mech, joint.at)
        base = p1.point(at)
        direction = turn(p1.rotation, unit_axis(joint))
        gap = column_pair(table, joint.name, 0) - base
        off = float(
            np.max(np.abs(gap[:, 0] * direction[:, 1] - gap[:, 1] * direction[:, 0]))
        )
        rot = 0.0
        if joint.kind == "prismatic":
            rel = pose(mech, table, second).rotation - p1.rotation
            rot = float(np.max(np.abs(np.angle(np.exp(1j * rel)))))
        slide = np.sum(gap * direction, axis=-1)
        # a slot's slide is its pin's (its block's) along the slot
        assert f"{joint.name}.s" in table, f"no slide column for {joint.name}"
        err = float(np.max(np.abs(slide - table[f"{joint.name}.s"])))
        out[joint.name] = (off, rot, err)
    return out


def families(table: assur.Table) -> dict[str, list[np.ndarray]]:
    """Every quantity with its three time derivatives, in SI units (angles in rad)."""
    out: dict[str, list[np.ndarray]] = {}
    for column in table.columns:
        if column.endswith(".angle"):
            base = column[:-6]
            out[base + ".angle"] = [np.radians(table[column])] + [
                table[f"{base}.{k}"] for k in ("omega", "alpha", "jerk")
            ]
        elif column.endswith(".x") and f"{column[:-2]}.vx" in table:
            base = column[:-2]
            for c in ("x", "y"):
                out[f"{base}.{c}"] = [
                    table[f"{base}.{p}{c}"] for p in ("", "v", "a", "j")
                ]
        elif column.endswith(".s") and f"{column[:-2]}.j" in table:
            base = column[:-2]
            out[f"{base}.s"] = [table[f"{base}.{k}"] for k in ("s", "v", "a", "j")]
    return out


def driver_rates(mech: assur.Mechanism) -> np.ndarray:
    return np.array([d.omega for d in mech.drivers])


def driver_accelerations(mech: assur.Mechanism) -> np.ndarray:
    return np.array([d.epsilon for d in mech.drivers])


def driver_kinds(mech: assur.Mechanism) -> list[str]:
    return [mech.joint(d.joint).kind for d in mech.drivers]


def to_table_units(mech: assur.Mechanism, drive: np.ndarray) -> np.ndarray:
    """Driver positions (n, d) in SI (rad, m) to table units (deg, m)."""
    scale = np.array(
        [180.0 / math.pi if k == "revolute" else 1.0 for k in driver_kinds(mech)]
    )
    out = drive * scale
    return out[:, 0] if out.shape[1] == 1 else out


def stencil_table(
    mech: assur.Mechanism,
    centres: np.ndarray,
    tau: float,
    jerk: np.ndarray | None = None,
) -> assur.Table:
    """Kinematics at ``centres`` (n, d) (SI) and a time step ``tau`` before and after,
    along the drivers' motion: rows (-, 0, +) per centre.

    Each driver moves at its ``omega`` and ``epsilon`` from the centre, its jerk zero
    (the file's constants, as the contract has them): ``q + omega t + epsilon t^2 / 2``
    at the speed ``omega + epsilon t``, which the rows are given. With ``jerk`` (d,)
    (rad/s^3, m/s^3) the drivers follow ``q + omega t + epsilon t^2/2 + jerk t^3/6``
    instead, every row given its speed, acceleration and jerk.
    """
    rates, accels = driver_rates(mech), driver_accelerations(mech)
    t = np.array([-tau, 0.0, tau])[None, :, None]
    cubic = np.zeros(len(rates)) if jerk is None else np.asarray(jerk, dtype=float)
    drive = (
        centres[:, None, :] + t * rates + 0.5 * t * t * accels + t**3 / 6.0 * cubic
    ).reshape(-1, len(rates))
    if not accels.any() and jerk is None:  # the speed is the file's at every row
        return assur.kinematics(mech, to_table_units(mech, drive))
    shape = (len(centres), 3, len(rates))

    def rows(value: np.ndarray) -> np.ndarray:
        out = np.broadcast_to(value, shape).reshape(drive.shape)
        return out[:, 0] if len(rates) == 1 else out

    return assur.kinematics(
        mech,
        to_table_units(mech, drive),
        omega=rows(rates + t * accels + 0.5 * t * t * cubic),
        epsilon=rows(accels + t * cubic),
        jerk=None if jerk is None else rows(cubic),
    )


def difference_errors(
    mech: assur.Mechanism,
    centres: np.ndarray,
    h: float = 1e-3,
    jerk: np.ndarray | None = None,
) -> dict[str, tuple[float, float]]:
    """Compare each derivative column with the central difference of the one below.

    ``centres`` are SI driver positions (n, d); the time step moves the fastest driver
    by ``h`` (rad, or ``h`` times 0.1 m for a prismatic driver); ``jerk`` (d,), the
    drivers' own jerk (see :func:`stencil_table`). Returns, per quantity
    and level, the largest error and the tolerance: three times the difference's own
    truncation error ``tau^2/6 |x^(k+2)|`` (the fourth and fifth derivatives estimated
    from the jerk's own differences) plus a rounding allowance.
    """
    rates = driver_rates(mech)
    moves = np.array([h if k == "revolute" else 0.1 * h for k in driver_kinds(mech)])
    tau = float(np.min(moves / np.maximum(np.abs(rates), 1e-300)))
    table = stencil_table(mech, centres, tau, jerk)
    size = mechanism_size(mech)
    speed = float(
        np.max(
            np.abs(rates)
            / np.where(np.array(driver_kinds(mech)) == "revolute", 1.0, size)
        )
    )
    out = {}
    for name, levels in families(table).items():
        x = [v.reshape(-1, 3) for v in levels]
        x3 = x[3]
        x4 = (x3[:, 2] - x3[:, 0]) / (2 * tau)
        x5 = (x3[:, 2] - 2 * x3[:, 1] + x3[:, 0]) / tau**2
        higher = {
            1: np.max(np.abs(x3[:, 1])),
            2: np.max(np.abs(x4)),
            3: np.max(np.abs(x5)),
        }
        length = 1.0 if name.endswith(".angle") else size
        for k in (1, 2, 3):
            below = x[k - 1]
            if k == 1 and name.endswith(".angle"):
                step = np.angle(np.exp(1j * (below[:, 2] - below[:, 0])))
            else:
                step = below[:, 2] - below[:, 0]
            fd = step / (2 * tau)
            err = float(np.max(np.abs(fd - x[k][:, 1])))
            tol = (
                3.0 * tau**2 / 6.0 * higher[k]
                + 1e-12
                * max(float(np.max(np.abs(below))), length * speed ** (k - 1))
                / tau
                + 1e-10 * length * speed**k
            )
            out[f"{name}[{k}]"] = (err, tol)
    return out


def mechanism_size(mech: assur.Mechanism) -> float:
    """Extent plus largest distance from the origin (m) of the joints and points."""
    pts = np.array(
        [resolve(mech, j.at) for j in mech.joints]
        + [resolve(mech, p.at) for p in mech.points]
    )
    return max(float(np.max(np.ptp(pts, axis=0)) + np.max(np.abs(pts))), 1e-3)


def trapezoid_errors(
    table: assur.Table, dt: np.ndarray, size: float = 1.0
) -> dict[str, tuple[float, float]]:
    """Consecutive rows against the trapezoidal rule.

    x_{i+1} - x_i ~ (v_i + v_{i+1}) dt/2 with error at most dt^3/12 |x'''|; a jump to
    another branch breaks it.

    ``dt`` (n-1,) is the time between consecutive rows at the drivers' rates; ``size``
    (m) scales the rounding allowance.
    """
    out = {}
    for name, levels in families(table).items():
        x, v, _, j = levels
        step = np.diff(x)
        if name.endswith(".angle"):
            step = np.angle(np.exp(1j * step))
        err = np.abs(step - 0.5 * (v[1:] + v[:-1]) * dt)
        bound = dt**3 / 12.0 * np.maximum(np.abs(j[1:]), np.abs(j[:-1]))
        # jerk may peak between rows: allow for its variation over the step
        length = 1.0 if name.endswith(".angle") else size
        bound = (
            3.0 * bound
            + dt**3 / 12.0 * np.abs(np.diff(j)) * 3.0
            + 1e-12 * (np.abs(x[1:]) + np.abs(v[1:] * dt) + length)
        )
        worst = int(np.argmax(err / bound))
        out[name] = (float(err[worst]), float(bound[worst]))
    return out


# ------------------------------------------------------------------------------------
# Kinetostatics


def load_value(
    mech: assur.Mechanism, table: assur.Table, value, components: int
) -> list:
    """A constant or tabulated load component by component, one array (n,) each."""
    n = len(table)
    if not isinstance(value, assur.LoadTable):
        vals = np.atleast_1d(np.asarray(value, dtype=float))
        return [np.full(n, v) for v in vals[:components]]
    xs = np.asarray(value.table, dtype=float)
    values = [np.asarray(v, dtype=float) for v in value.values]
    if value.over == "driver":
        at = table["angle"]
        if mech.joint(mech.drivers[0].joint).kind == "revolute":
            # read within the turn from the table's first position, closed one turn
            # on by its first value; np.interp's own period= would sort the steps'
            # twin positions apart and merge 0 with 360
            start = xs[0]
            at = start + np.mod(at - start, 360.0)
            if xs[-1] < start + 360.0:
                xs = np.append(xs, start + 360.0)
                values = [np.append(v, v[0]) for v in values]
        return [np.interp(at, xs, v) for v in values]
    at = table[f"{value.over}.s"]
    return [np.interp(at, xs, v) for v in values]


@dataclass
class Applied:
    """Per link: resultant force (n, 2), moment about the fixed origin (n,) and power
    (n,) of its inertia loads, gravity and external loads."""

    force: dict[str, np.ndarray]
    moment: dict[str, np.ndarray]
    power: dict[str, np.ndarray]
    inertia_force: dict[str, np.ndarray]
    inertia_torque: dict[str, np.ndarray]


def applied_loads(
    mech: assur.Mechanism, table: assur.Table, inertia: bool = True
) -> Applied:
    """Every moving link's applied loads, from the mechanism's data and the table's
    kinematics: ``-m a_G`` at G, ``-J alpha``, ``m g`` at G, forces and torques."""
    n = len(table)
    gravity = (
        np.zeros(2) if mech.gravity is None else np.asarray(mech.gravity, dtype=float)
    )
    force, moment, power, fi, mi = {}, {}, {}, {}, {}
    for link in mech.links:
        name = link.name
        f = np.zeros((n, 2))
        m = np.zeros(n)
        p = np.zeros(n)
        w = table[f"{name}.omega"]
        if link.mass:
            g_at = column_pair(table, f"{name}.G", 0)
            g_vel = column_pair(table, f"{name}.G", 1)
            fi[name] = -link.mass * column_pair(table, f"{name}.G", 2)
            # a link that only translates may leave its inertia out (it never enters)
            mi[name] = -(link.inertia or 0.0) * table[f"{name}.alpha"]
            total = link.mass * gravity + (fi[name] if inertia else np.zeros((n, 2)))
            couple = mi[name] if inertia else np.zeros(n)
            f += total
            m += g_at[:, 0] * total[:, 1] - g_at[:, 1] * total[:, 0] + couple
            p += np.sum(total * g_vel, axis=-1) + couple * w
        force[name], moment[name], power[name] = f, m, p
    for load in mech.loads:
        name = load.link
        body = pose(mech, table, name)
        if load.force is not None:
            ref = resolve(mech, load.at)
            at, vel = body.point(ref, 0), body.point(ref, 1)
            fx, fy = load_value(mech, table, load.force, 2)
            vec = np.stack([fx, fy], axis=-1)
            force[name] = force[name] + vec
            moment[name] = moment[name] + at[:, 0] * fy - at[:, 1] * fx
            power[name] = power[name] + np.sum(vec * vel, axis=-1)
        if load.torque is not None:
            (tau,) = load_value(mech, table, load.torque, 1)
            moment[name] = moment[name] + tau
            power[name] = power[name] + tau * table[f"{name}.omega"]
    return Applied(force, moment, power, fi, mi)


@dataclass
class Reactions:
    """Per joint the force by its first link on its second (n, 2) and the couple (n,)
    about its point (prismatic and slot joints); per driver the balancing load."""

    force: dict[str, np.ndarray]
    couple: dict[str, np.ndarray]
    balancing: np.ndarray


def _driver_link(mech: assur.Mechanism, driver: assur.Driver) -> str:
    a, b = mech.joint(driver.joint).links
    return b if a == GROUND else a


def _unit_wrenches(
    mech: assur.Mechanism, table: assur.Table, joint: assur.Joint
) -> list:
    """Wrenches (force (n, 2), couple (n,)) on the joint's second link per unit unknown,
    with the point they act at (n, 2)."""
    n = len(table)
    at = column_pair(table, joint.name, 0)
    zero = np.zeros(n)
    if joint.kind == "revolute":
        return [
            (np.tile([1.0, 0.0], (n, 1)), zero, at),
            (np.tile([0.0, 1.0], (n, 1)), zero, at),
        ]
    normal = turn(pose(mech, table, joint.links[0]).rotation, perp(unit_axis(joint)))
    wrenches = [(normal, zero, at)]
    if joint.kind == "prismatic":
        wrenches.append((np.zeros((n, 2)), np.ones(n), at))
    return wrenches


def global_solve(mech: assur.Mechanism, table: assur.Table) -> Reactions:
    """Solve every link's three equilibrium equations at once for all the reactions and
    balancing loads (two unknowns per revolute or prismatic joint, one per slot, one
    per driver), batch over the table's rows."""
    n = len(table)
    links = [lk.name for lk in mech.links]
    row = {name: 3 * i for i, name in enumerate(links)}
    columns = []  # per unknown: list of (link, sign, force, couple, at)
    owners = []
    for joint in mech.joints:
        for k, (f, c, at) in enumerate(_unit_wrenches(mech, table, joint)):
            columns.append(
                [(joint.links[1], 1.0, f, c, at), (joint.links[0], -1.0, f, c, at)]
            )
            owners.append((joint.name, k))
    for i, driver in enumerate(mech.drivers):
        link = _driver_link(mech, driver)
        joint = mech.joint(driver.joint)
        if joint.kind == "revolute":
            wrench = (np.zeros((n, 2)), np.ones(n), np.zeros((n, 2)))
        else:
            wrench = (
                np.tile(unit_axis(joint), (n, 1)),
                np.zeros(n),
                column_pair(table, joint.name, 0),
            )
        columns.append([(link, 1.0, *wrench)])
        owners.append(("driver", i))
    size = 3 * len(links)
    if len(columns) != size:
        msg = f"{len(columns)} unknowns for {size} equations"
        raise ValueError(msg)
    mat = np.zeros((n, size, size))
    for j, entries in enumerate(columns):
        for link, sign, f, c, at in entries:
            if link == GROUND:
                continue
            r = row[link]
            mat[:, r, j] += sign * f[:, 0]
            mat[:, r + 1, j] += sign * f[:, 1]
            mat[:, r + 2, j] += sign * (at[:, 0] * f[:, 1] - at[:, 1] * f[:, 0] + c)
    loads = applied_loads(mech, table)
    rhs = np.zeros((n, size))
    for link in links:
        r = row[link]
        rhs[:, r : r + 2] = -loads.force[link]
        rhs[:, r + 2] = -loads.moment[link]
    x = np.linalg.solve(mat, rhs[..., None])[..., 0]
    force, couple = {}, {}
    balancing = np.zeros((n, len(mech.drivers)))
    for j, (owner, k) in enumerate(owners):
        if owner == "driver":
            balancing[:, k] = x[:, j]
            continue
        joint = mech.joint(owner)
        f, c, _ = _unit_wrenches(mech, table, joint)[k]
        force[owner] = force.get(owner, np.zeros((n, 2))) + x[:, j, None] * f
        couple[owner] = couple.get(owner, np.zeros(n)) + x[:, j] * c
    return Reactions(force, couple, balancing)


def relative_speed(table: assur.Table, joint: assur.Joint) -> np.ndarray:
    """What a joint's friction opposes: the relative angular speed of its second link
    (rad/s), or its slide's speed (m/s), from the table's columns."""
    if joint.kind == "revolute":
        first, second = (
            np.zeros(len(table)) if link == GROUND else table[f"{link}.omega"]
            for link in joint.links
        )
        return second - first
    return table[f"{joint.name}.v"]


def _at_rest(
    mech: assur.Mechanism, table: assur.Table, speed: np.ndarray, joint: assur.Joint
) -> np.ndarray:
    """Rows where a joint's relative speed is rounding rather than motion: below 1e-10
    of the fastest link rotation or joint speed per mechanism size of that row."""
    size = mechanism_size(mech)
    fastest = np.zeros(len(table))
    for link in mech.links:
        fastest = np.maximum(fastest, np.abs(table[f"{link.name}.omega"]))
    for j in mech.joints:
        fastest = np.maximum(
            fastest, np.hypot(table[f"{j.name}.vx"], table[f"{j.name}.vy"]) / size
        )
    limit = 1e-10 * fastest * (1.0 if joint.kind == "revolute" else size)
    return np.abs(speed) <= limit


RAISES = 12
"""Steps in which :func:`global_solve_friction` raises the friction from zero."""


def global_solve_friction(
    mech: assur.Mechanism, table: assur.Table, raises: int = RAISES
) -> tuple[Reactions, dict[str, np.ndarray]]:
    """The global solve with Coulomb friction: every link's three equations at once,
    one nonlinear system per position, by Newton's method from the frictionless
    solution.

    A revolute joint's friction is the couple ``-f r |R| sign(w2 - w1)`` on its second
    link; a prismatic (or slot) joint's the force ``-f |N| sign(v)`` along its slide
    line at its point. Returns the reactions (a prismatic joint's force includes its
    friction) and each joint's friction. The solution is the one that grows from the
    frictionless one as the friction is raised from zero, in ``raises`` steps.
    """
    n = len(table)
    links = [lk.name for lk in mech.links]
    row = {name: 3 * i for i, name in enumerate(links)}
    ideal = global_solve(mech, table)
    # unknowns: the frictionless solve's, in its order
    joints = list(mech.joints)
    layout = []  # (joint, k) per unknown, then ("driver", i)
    for joint in joints:
        for k in range(len(_unit_wrenches(mech, table, joint))):
            layout.append((joint, k))
    for i in range(len(mech.drivers)):
        layout.append(("driver", i))
    units = {j.name: _unit_wrenches(mech, table, j) for j in joints}
    loads = applied_loads(mech, table)
    speeds = {j.name: relative_speed(table, j) for j in joints}
    for j in joints:
        speeds[j.name] = np.where(
            _at_rest(mech, table, speeds[j.name], j), 0.0, speeds[j.name]
        )
    axes = {
        j.name: turn(pose(mech, table, j.links[0]).rotation, unit_axis(j))
        for j in joints
        if j.kind != "revolute"
    }
    out_force = {j.name: np.zeros((n, 2)) for j in joints}
    out_couple = {j.name: np.zeros(n) for j in joints}
    out_friction = {j.name: np.zeros(n) for j in joints}
    balancing = np.zeros((n, len(mech.drivers)))

    def start(r: int, guess: Reactions) -> np.ndarray:
        x = []
        for item, k in layout:
            if item == "driver":
                x.append(guess.balancing[r, k])
                continue
            f, _c, _ = units[item.name][k]
            force = guess.force[item.name][r]
            if item.kind == "revolute":
                x.append(force[k])
            elif k == 0:
                x.append(float(np.dot(force, f[r])))  # the normal force
            else:
                x.append(guess.couple[item.name][r])
        return np.asarray(x)

    def equations(
        x: np.ndarray, r: int, out: dict | None = None, weight: float = 1.0
    ) -> np.ndarray:
        force = {L: np.zeros(2) for L in [*links, GROUND]}
        moment = dict.fromkeys([*links, GROUND], 0.0)
        for L in links:
            force[L] = force[L] + loads.force[L][r]
            moment[L] += loads.moment[L][r]

        def push(link: str, vec: np.ndarray, couple: float, at: np.ndarray) -> None:
            force[link] = force[link] + vec
            moment[link] += at[0] * vec[1] - at[1] * vec[0] + couple

        total = {j.name: np.zeros(2) for j in joints}
        normal = {j.name: 0.0 for j in joints}
        for value, (item, k) in zip(x, layout, strict=True):
            if item == "driver":
                driver = mech.drivers[k]
                joint = mech.joint(driver.joint)
                link = _driver_link(mech, driver)
                if joint.kind == "revolute":
                    push(link, np.zeros(2), value, np.zeros(2))
                else:
                    at = column_pair(table, joint.name, 0)[r]
                    push(link, value * unit_axis(joint), 0.0, at)
                continue
            f, c, at = units[item.name][k]
            vec, couple, where = value * f[r], value * c[r], at[r]
            push(item.links[1], vec, couple, where)
            push(item.links[0], -vec, -couple, where)
            total[item.name] = total[item.name] + vec
            if item.kind != "revolute" and k == 0:
                normal[item.name] = value
        for joint in joints:
            fr = float(joint.friction) * weight
            if not fr:
                continue
            sense = float(np.sign(speeds[joint.name][r]))
            at = column_pair(table, joint.name, 0)[r]
            if joint.kind == "revolute":
                mf = -fr * float(joint.radius) * float(np.hypot(*total[joint.name]))
                mf *= sense
                push(joint.links[1], np.zeros(2), mf, at)
                push(joint.links[0], np.zeros(2), -mf, at)
                value = mf
            else:
                ff = -fr * abs(normal[joint.name]) * sense
                vec = ff * axes[joint.name][r]
                push(joint.links[1], vec, 0.0, at)
                push(joint.links[0], -vec, 0.0, at)
                total[joint.name] = total[joint.name] + vec
                value = ff
            if out is not None:
                out[joint.name] = (total[joint.name], value)
        res = np.zeros(3 * len(links))
        for L in links:
            res[row[L] : row[L] + 2] = force[L]
            res[row[L] + 2] = moment[L]
        return res

    from scipy.optimize import fsolve

    size = mechanism_size(mech)

    def settled(x: np.ndarray, r: int, weight: float = 1.0) -> tuple[np.ndarray, bool]:
        for _ in range(3):  # polish: fsolve stops early near its own tolerance
            with warnings.catch_warnings():
                # "no further improvement": the residual check below judges
                warnings.simplefilter("ignore", RuntimeWarning)
                x = fsolve(equations, x, args=(r, None, weight), xtol=1e-15)
        scale = max(1.0, float(np.max(np.abs(x))))
        left = np.max(np.abs(equations(x, r, None, weight)))
        return x, bool(left <= 1e-11 * scale * max(1.0, size))

    def raised(r: int) -> tuple[np.ndarray, bool]:
        # Coulomb's law may hold twice (a slider jammed in its guide beside the
        # motion that grows from no friction): the friction is raised from zero in
        # small steps, each solve starting from the last, to follow the latter
        x, good = start(r, ideal), True
        for weight in np.arange(1, raises + 1) / raises:
            x, good = settled(x, r, float(weight))
            if not good:
                break
        return x, good

    for r in range(n):
        x, good = raised(r)
        if not good:
            # no such motion all the way: from the answer under test (a wrong one
            # is not a root of these equations and is moved or left unconverged)
            x, good = settled(start(r, table_reactions(mech, table)), r)
        if not good:
            msg = f"the friction solve did not converge at row {r}"
            raise ValueError(msg)
        found: dict = {}
        equations(x, r, found)
        for joint in joints:
            _vec, value = found.get(joint.name, (None, 0.0))
            out_friction[joint.name][r] = value
        for value, (item, k) in zip(x, layout, strict=True):
            if item == "driver":
                balancing[r, k] = value
                continue
            f, c, _ = units[item.name][k]
            out_force[item.name][r] += value * f[r]
            out_couple[item.name][r] += value * c[r]
        for joint in joints:
            if joint.friction and joint.kind != "revolute":
                out_force[joint.name][r] += (
                    out_friction[joint.name][r] * (axes[joint.name][r])
                )
    return Reactions(out_force, out_couple, balancing), out_friction


def assert_same_reactions(
    mech: assur.Mechanism,
    got: Reactions,
    expected: Reactions,
    rtol: float,
    force: float,
    size: float,
) -> None:
    """Assert two sets of reactions and balancing loads agree to ``rtol`` of the
    load scale ``force`` (N; forces) and ``force * size`` (N m; couples)."""
    for joint in mech.joints:
        name = joint.name
        np.testing.assert_allclose(
            got.force[name],
            expected.force[name],
            rtol=0,
            atol=rtol * force,
            err_msg=f"{name}: force",
        )
        np.testing.assert_allclose(
            got.couple[name],
            expected.couple[name],
            rtol=0,
            atol=rtol * force * size,
            err_msg=f"{name}: couple",
        )
    np.testing.assert_allclose(
        got.balancing,
        expected.balancing,
        rtol=0,
        atol=rtol * force * size,
        err_msg="balancing loads",
    )


def table_reactions(mech: assur.Mechanism, table: assur.Table) -> Reactions:
    """The reactions and balancing loads as the table gives them."""
    force, couple = {}, {}
    for joint in mech.joints:
        force[joint.name] = np.stack(
            [table[f"{joint.name}.Fx"], table[f"{joint.name}.Fy"]], axis=-1
        )
        couple[joint.name] = (
            table[f"{joint.name}.M"]
            if joint.kind != "revolute"
            else np.zeros(len(table))
        )
    balancing = np.stack(
        [balancing_column(mech, table, i) for i in range(len(mech.drivers))], axis=-1
    )
    return Reactions(force, couple, balancing)


def balancing_column(
    mech: assur.Mechanism, table: assur.Table, i: int, check: bool = False
) -> np.ndarray:
    driver = mech.drivers[i]
    what = "torque" if mech.joint(driver.joint).kind == "revolute" else "force"
    suffix = "_check" if check else ""
    if len(mech.drivers) == 1:
        return table[f"driver.{what}{suffix}"]
    return table[f"{driver.joint}.{what}{suffix}"]


def link_residuals(
    mech: assur.Mechanism, table: assur.Table, reactions: Reactions
) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each moving link's unbalanced force (n, 2) and moment about the origin (n,)
    under its applied loads, the given reactions and balancing loads."""
    loads = applied_loads(mech, table)
    force = {k: v.copy() for k, v in loads.force.items()}
    moment = {k: v.copy() for k, v in loads.moment.items()}
    force[GROUND] = np.zeros((len(table), 2))
    moment[GROUND] = np.zeros(len(table))
    for joint in mech.joints:
        f = reactions.force[joint.name]
        at = column_pair(table, joint.name, 0)
        tau = at[:, 0] * f[:, 1] - at[:, 1] * f[:, 0] + reactions.couple[joint.name]
        for link, sign in ((joint.links[1], 1.0), (joint.links[0], -1.0)):
            force[link] = force[link] + sign * f
            moment[link] = moment[link] + sign * tau
    for i, driver in enumerate(mech.drivers):
        link = _driver_link(mech, driver)
        joint = mech.joint(driver.joint)
        b = reactions.balancing[:, i]
        if joint.kind == "revolute":
            moment[link] = moment[link] + b
            moment[GROUND] = moment[GROUND] - b
        else:
            f = b[:, None] * unit_axis(joint)
            at = column_pair(table, joint.name, 0)
            tau = at[:, 0] * f[:, 1] - at[:, 1] * f[:, 0]
            force[link] = force[link] + f
            moment[link] = moment[link] + tau
            force[GROUND] = force[GROUND] - f
            moment[GROUND] = moment[GROUND] - tau
    return {k: (force[k], moment[k]) for k in force}


def load_scale(mech: assur.Mechanism, table: assur.Table) -> tuple[float, float]:
    """The largest force (N) among applied loads and reactions, and the mechanism's size
    (m), to scale tolerances."""
    loads = applied_loads(mech, table)
    biggest = max(float(np.max(np.abs(f))) for f in loads.force.values())
    for joint in mech.joints:
        biggest = max(
            biggest,
            float(np.max(np.abs(table[f"{joint.name}.Fx"]))),
            float(np.max(np.abs(table[f"{joint.name}.Fy"]))),
        )
    pts = np.array([resolve(mech, j.at) for j in mech.joints])
    size = float(np.max(np.ptp(pts, axis=0))) + float(np.max(np.abs(pts)))
    return max(biggest, 1e-12), max(size, 1e-3)


# ------------------------------------------------------------------------------------
# Assertions shared by the test modules


def assert_rigid(
    mech: assur.Mechanism, table: assur.Table, rtol: float = 1e-10
) -> None:
    """Every link's reported points move rigidly with its angle column."""
    limit = rtol * mechanism_size(mech)
    errors = rigid_errors(mech, table)
    bad = {k: v for k, v in errors.items() if not v <= limit}
    assert not bad, f"points off their rigid link (m, limit {limit:.3g}): {bad}"


def assert_slides(
    mech: assur.Mechanism, table: assur.Table, rtol: float = 1e-10
) -> None:
    """Every prismatic or slot joint's point stays on the line fixed in its first link,
    prismatic joints keep their links' relative rotation, slide columns agree."""
    size = mechanism_size(mech)
    for name, (off, rot, err) in slide_errors(mech, table).items():
        assert off <= rtol * size, f"{name}: point {off:.3g} m off its slide line"
        assert rot <= rtol, f"{name}: links turned {rot:.3g} rad relative to each other"
        assert err <= rtol * size, f"{name}: slide column off by {err:.3g} m"


def assert_reference_pose(
    mech: assur.Mechanism, table: assur.Table, row: int, rtol: float = 1e-10
) -> None:
    """Row ``row`` (at the reference drive) puts every reported point where it is in the
    reference pose."""
    limit = rtol * mechanism_size(mech)
    for link in mech.links:
        for name, ref in reported_points(mech, link.name):
            got = column_pair(table, name, 0)[row]
            assert np.max(np.abs(got - ref)) <= limit, (
                f"{name}: {got} in the reference pose, expected {ref}"
            )


def assert_differences(
    mech: assur.Mechanism,
    centres: np.ndarray,
    h: float = 1e-3,
    jerk: np.ndarray | None = None,
) -> None:
    """Velocity, acceleration and jerk columns equal the central differences in time of
    the columns below them (``centres``: SI driver positions (n, d); ``jerk`` (d,):
    the drivers' own jerk, SI, zero without it)."""
    errors = difference_errors(
        mech, np.asarray(centres, dtype=float).reshape(len(centres), -1), h, jerk
    )
    bad = {k: v for k, v in errors.items() if not v[0] <= v[1]}
    assert not bad, f"derivative != finite difference (error, tolerance): {bad}"


def assert_continuous(table: assur.Table, dt: float) -> None:
    """Consecutive rows (``dt`` s apart) are linked by the trapezoidal rule: no jump."""
    errors = trapezoid_errors(
        table, np.full(len(table) - 1, dt), mechanism_size(table.mechanism)
    )
    bad = {k: v for k, v in errors.items() if not v[0] <= v[1]}
    assert not bad, f"rows jump (error, bound): {bad}"


def si(mech: assur.Mechanism, positions: np.ndarray) -> np.ndarray:
    """Table-unit driver positions (n,) or (n, d) to SI (n, d)."""
    arr = np.asarray(positions, dtype=float).reshape(len(positions), -1)
    scale = np.array(
        [math.pi / 180.0 if k == "revolute" else 1.0 for k in driver_kinds(mech)]
    )
    return arr * scale


def moved_columns(
    mech: assur.Mechanism,
    table: assur.Table,
    angle: float,
    shift=(0.0, 0.0),
    scale: float = 1.0,
) -> dict[str, np.ndarray]:
    """What ``table``'s columns become for the mechanism turned by ``angle`` (rad),
    scaled by ``scale`` and shifted by ``shift`` (see ``mechanisms.moved``).

    Angle columns (deg) are to be compared modulo 360.
    """
    c, s = math.cos(angle), math.sin(angle)
    off = np.asarray(shift, dtype=float)
    deg = math.degrees(angle)
    out: dict[str, np.ndarray] = {}
    kinds = {d.joint: mech.joint(d.joint).kind for d in mech.drivers}

    def turned(name: str, x: str, y: str, k: float, add=(0.0, 0.0)) -> None:
        vx, vy = table[f"{name}{x}"], table[f"{name}{y}"]
        out[f"{name}{x}"] = k * (c * vx - s * vy) + add[0]
        out[f"{name}{y}"] = k * (s * vx + c * vy) + add[1]

    def drive(values: np.ndarray, joint: str) -> np.ndarray:
        if kinds[joint] != "revolute":
            return values * scale
        a, b = mech.joint(joint).links
        link = b if a == GROUND else a
        return values + (deg if mech.link(link).axis is not None else 0.0)

    out["angle"] = drive(table["angle"], mech.drivers[0].joint)
    for d in mech.drivers:
        if f"{d.joint}.drive" in table:
            out[f"{d.joint}.drive"] = drive(table[f"{d.joint}.drive"], d.joint)
    for link in mech.links:
        name = link.name
        out[f"{name}.angle"] = table[f"{name}.angle"] + (deg if link.axis else 0.0)
        for key in ("omega", "alpha", "jerk"):
            out[f"{name}.{key}"] = table[f"{name}.{key}"]
        if f"{name}.Fi.x" in table:
            turned(f"{name}.Fi", ".x", ".y", scale)
            out[f"{name}.Mi"] = table[f"{name}.Mi"] * scale**2
    for column in table.columns:
        if column.endswith(".vx"):
            base = column[:-3]
            turned(base, ".x", ".y", scale, off)
            for p in ("v", "a", "j"):
                turned(base, f".{p}x", f".{p}y", scale)
        if column.endswith(".j") and f"{column[:-2]}.s" in table:
            base = column[:-2]
            for key in ("s", "v", "a", "j"):
                out[f"{base}.{key}"] = table[f"{base}.{key}"] * scale
    if "shaking.Fx" not in table:
        return out
    for joint in mech.joints:
        turned(joint.name, ".Fx", ".Fy", scale)
        out[f"{joint.name}.F"] = table[f"{joint.name}.F"] * scale
        if joint.kind != "revolute":
            out[f"{joint.name}.M"] = table[f"{joint.name}.M"] * scale**2
            out[f"{joint.name}.offset"] = table[f"{joint.name}.offset"] * scale
    for column in table.columns:
        if column.startswith("driver.") or column.endswith(
            (".torque", ".torque_check", ".force", ".force_check")
        ):
            k = scale**2 if "torque" in column else scale
            out[column] = table[column] * k
    turned("shaking", ".Fx", ".Fy", scale)
    out["shaking.M"] = (
        table["shaking.M"] * scale**2
        + off[0] * out["shaking.Fy"]
        - off[1] * out["shaking.Fx"]
    )
    return out


ORDER = {"x": 0, "y": 0, "s": 0, "vx": 1, "vy": 1, "v": 1, "omega": 1, "ax": 2, "ay": 2}
ORDER.update({"a": 2, "alpha": 2, "jx": 3, "jy": 3, "j": 3, "jerk": 3})
"""Time-derivative order of each kind of kinematic column."""


def assert_columns(
    mech: assur.Mechanism, table: assur.Table, expected: dict[str, np.ndarray]
) -> None:
    """``table`` (of ``mech``) has the ``expected`` columns: angles to 1e-7 deg modulo
    360, kinematics and loads to 1e-8 relative with floors from the mechanism's size,
    speed and largest load."""
    size = mechanism_size(mech)
    speed = max(max(abs(d.omega) for d in mech.drivers), 1.0)
    force = length = rounding = None
    for column, want in expected.items():
        got = table[column]
        key = column.rsplit(".", 1)[-1]
        if key in ("angle", "drive"):
            diff = got - want
            if column != "angle" and key != "drive":
                diff = (diff + 180.0) % 360.0 - 180.0
            assert np.max(np.abs(diff)) < 1e-7, f"{column}: off by {diff}"
            continue
        if key == "offset":
            continue
        if key in ORDER:
            scale = 1.0 if key in ("omega", "alpha", "jerk") else size
            atol = 1e-10 * scale * speed ** ORDER[key]
        else:
            if force is None:
                force, length = load_scale(mech, table)
                # a mechanism's coordinates hold eps times their size: a centre of
                # mass 3e-12 m off its pivot, shifted 1 m away, is 7e-5 off itself,
                # and so is its inertia force m w^2 r (every mass, every speed)
                mass = sum(x.mass or 0.0 for x in mech.links)
                rounding = 16.0 * np.finfo(float).eps * mass * speed**2 * length
            moment = key in ("M", "Mi") or "torque" in column
            atol = (1e-9 * force + rounding) * (length if moment else 1.0) + 1e-15
        np.testing.assert_allclose(got, want, rtol=1e-8, atol=atol, err_msg=column)


# ------------------------------------------------------------------------------------
# Dynamics of a crank-driven mechanism


def kinetic_energy(mech: assur.Mechanism, table: assur.Table) -> np.ndarray:
    """Kinetic energy (J) of the moving links at every row: the table's own
    velocities of the centres of mass and angular velocities."""
    energy = np.zeros(len(table))
    for link in mech.links:
        if link.mass:
            v = column_pair(table, f"{link.name}.G", 1)
            w = table[f"{link.name}.omega"]
            inertia = link.inertia or 0.0  # left out only where the link never turns
            energy += 0.5 * (link.mass * np.sum(v * v, axis=-1) + inertia * w * w)
    return energy


def loads_power(mech: assur.Mechanism, table: assur.Table) -> np.ndarray:
    """Power (W) of gravity and the external loads at every row (no inertia loads)."""
    powers = applied_loads(mech, table, inertia=False).power
    return np.sum([powers[link.name] for link in mech.links], axis=0)


def crank_reduction(
    mech: assur.Mechanism, angles: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Reduced inertia (kg m^2) and reduced torque (N m) at crank angles (deg), from a
    forces table at the file's crank speed: ``2 T / w^2`` and ``P / w``."""
    table = assur.forces(mech, angles)
    w = mech.drivers[0].omega
    return 2.0 * kinetic_energy(mech, table) / w**2, loads_power(mech, table) / w


@dataclass
class CrankModel:
    """The equation of motion of a crank, rebuilt on a grid of ``count`` angles from
    0 to 360 deg: periodic cubic splines of the reduced inertia and torque."""

    inertia: object
    torque: object
    motor: float
    flywheel: float

    def acceleration(self, phi: float, w: float, motor: float) -> float:
        """``phi''`` from ``J phi'' + 0.5 J' phi'^2 = motor + M``."""
        j = float(self.inertia(phi)) + self.flywheel
        slope = float(self.inertia(phi, 1))
        return (motor + float(self.torque(phi)) - 0.5 * slope * w * w) / j


def crank_model(
    mech: assur.Mechanism, flywheel: float = 0.0, count: int = 7200
) -> CrankModel:
    """The oracle's own reduction of ``mech`` to its crank over a turn."""
    from scipy.interpolate import CubicSpline

    deg = np.arange(count) * 360.0 / count
    inertia, torque = crank_reduction(mech, deg)
    knots = np.radians(np.append(deg, 360.0))
    splines = [
        CubicSpline(knots, np.append(v, v[0]), bc_type="periodic")
        for v in (inertia, torque)
    ]
    for s in splines:
        s.extrapolate = "periodic"
    return CrankModel(splines[0], splines[1], -float(np.mean(torque)), flywheel)


def integrate_turn(
    model: CrankModel,
    phi0: float,
    w0: float,
    motor: float,
    steps: int = 3000,
    no_load: float | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Integrate the equation of motion in time with the classical fourth-order
    Runge-Kutta method, fixed step, from crank angle ``phi0`` (rad) at speed ``w0``
    (rad/s) under a ``motor`` torque (N m) for about one turn: constant, or with a
    ``no_load`` speed (rad/s) the electric motor's ``motor (1 - w / no_load)``.

    Returns the times (s), crank angles (rad) and speeds (rad/s) of every step."""
    dt = 2.0 * math.pi / abs(w0) / steps
    t, phi, w = [0.0], [phi0], [w0]

    def f(p: float, v: float) -> tuple[float, float]:
        drive = motor if no_load is None else motor * (1.0 - v / no_load)
        return v, model.acceleration(p, v, drive)

    p, v = phi0, w0
    while abs(p - phi0) < 2.0 * math.pi:
        k1 = f(p, v)
        k2 = f(p + 0.5 * dt * k1[0], v + 0.5 * dt * k1[1])
        k3 = f(p + 0.5 * dt * k2[0], v + 0.5 * dt * k2[1])
        k4 = f(p + dt * k3[0], v + dt * k3[1])
        p += dt / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        v += dt / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        t.append(t[-1] + dt)
        phi.append(p)
        w.append(v)
        if len(t) > 100 * steps:
            msg = "the crank does not turn"
            raise RuntimeError(msg)
    return np.array(t), np.array(phi), np.array(w)


def energy_over_turn(
    mech: assur.Mechanism, count: int
) -> tuple[np.ndarray, np.ndarray]:
    """The reduced inertia (kg m^2) and the work (J) from 0 deg at
    ``count + 1`` crank angles to 360 deg: the work is the trapezoidal integral of
    the oracle's reduced torque less its mean (a steady state's constant motor)."""
    deg = np.arange(count + 1) * 360.0 / count
    inertia, torque = crank_reduction(mech, deg)
    net = torque - np.mean(torque[:-1])
    step = math.radians(360.0 / count)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (net[1:] + net[:-1]) * step)])
    return inertia, work


def wittenbauer_flywheel(
    mech: assur.Mechanism, delta: float, count: int = 7200
) -> float:
    """The flywheel (kg m^2) for a coefficient of speed fluctuation ``delta`` from the
    energy-mass diagram with the exact tangent slopes ``w_max^2 / 2`` and
    ``w_min^2 / 2``, where ``w_max, w_min = w (1 +- delta / 2)``.

    The tangent points are the grid's."""
    inertia, work = energy_over_turn(mech, count)
    w = abs(mech.drivers[0].omega)
    upper = 0.5 * (w * (1.0 + 0.5 * delta)) ** 2
    lower = 0.5 * (w * (1.0 - 0.5 * delta)) ** 2
    top = np.max(work - upper * inertia)
    bottom = np.min(work - lower * inertia)
    return float((top - bottom) / (upper - lower))


def mertsalov_flywheel(mech: assur.Mechanism, delta: float, count: int = 7200) -> float:
    """The flywheel (kg m^2) for ``delta`` by Mertsalov's method, as a textbook works
    it: the links' kinetic energy at the nominal speed, ``(J - J_c) w^2 / 2`` with
    ``J_c`` the crank's own inertia about its pivot (``J_G + m OG^2``, from the file),
    taken from the work; the swing of what is left over ``w^2 delta`` is the
    constant inertia ``J_I``, the flywheel ``J_I - J_c``."""
    inertia, work = energy_over_turn(mech, count)
    w = abs(mech.drivers[0].omega)
    joint = next(j for j in mech.joints if j.name == mech.drivers[0].joint)
    crank = next(x for x in mech.links if x.name in joint.links)
    own = 0.0
    if crank.mass:
        arm = resolve(mech, crank.center) - resolve(mech, joint.at)
        own = (crank.inertia or 0.0) + crank.mass * float(arm @ arm)
    left = work - 0.5 * (inertia - own) * w * w
    return float((np.max(left) - np.min(left)) / (w * w * delta)) - own
