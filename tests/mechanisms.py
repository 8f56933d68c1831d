"""Test mechanisms with closed-form reference poses, and Hypothesis strategies for them.

Every builder places its points where they are in one assembled pose, computed in
closed form from the dimensions it is given, and returns a :class:`Case`: the
mechanism, the Assur group it must decompose into, the range of driver positions over
which the group assembles away from dead centres (checked by the same closed form),
and a branch indicator whose sign must not change along a sweep.

Each moving link carries two extra points (``<link>_p``, ``<link>_q``) and, mostly, a
mass, a centre and an inertia (some links are massless); loads (gravity, a force, a
torque, a force table over the driver) are optional. The strategies draw dimensions
for which the dyad assembles on the whole range, with transmission angles kept away
from 0 and 180 degrees.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

import assur

GROUND = "ground"
MU_MIN = 25.0
"""Smallest transmission angle (deg) any builder allows over its range."""


@dataclass(frozen=True)
class LinkDecor:
    """Extra points (offsets p, q from the link's anchor, m), centre offset, mass
    properties, and which axis the link gets (0 none, 1 two joints, 2 its points)."""

    p: tuple[float, float] = (0.03, 0.01)
    q: tuple[float, float] = (-0.01, 0.04)
    center: tuple[float, float] = (0.01, 0.005)
    mass: float | None = 0.3
    inertia: float = 1e-3
    axis: int = 1


@dataclass(frozen=True)
class LoadDecor:
    """Gravity, a force at an offset from a link's anchor, a torque, a force table."""

    gravity: tuple[float, float] | None = (0.0, -9.81)
    force: tuple[float, float] = (30.0, -20.0)
    force_link: int = 0
    force_at: tuple[float, float] = (0.01, -0.02)
    torque: float = 0.5
    torque_link: int = 1
    table: tuple[float, ...] | None = None


@dataclass(frozen=True)
class Case:
    """A test mechanism and what is known about it.

    ``span`` holds the lowest and highest driver positions (deg, or m for a prismatic
    driver), shape (2, drivers), of a range that assembles without dead centres and
    contains the reference pose; ``branch`` maps a table to an array whose sign stays
    that of the reference pose along any sweep inside the span.
    """

    mechanism: assur.Mechanism
    kind: str
    group: frozenset[str]
    span: np.ndarray
    reference: np.ndarray
    branch: Callable[[assur.Table], np.ndarray] | None = None
    notes: dict = field(default_factory=dict)

    @property
    def full_turn(self) -> bool:
        return bool(np.all(self.span[1] - self.span[0] >= 360.0 - 1e-9))

    def path(self, count: int) -> tuple[np.ndarray, float]:
        """``count`` positions along the motion at the drivers' constant rates, inside
        the span, and the time (s) between them."""
        rates = []
        for driver in self.mechanism.drivers:
            kind = self.mechanism.joint(driver.joint).kind
            rates.append(
                math.degrees(driver.omega) if kind == "revolute" else driver.omega
            )
        rates = np.array(rates)
        width = self.span[1] - self.span[0]
        duration = float(np.min(width / np.abs(rates)))
        start = np.where(rates > 0, self.span[0], self.span[1])
        t = np.linspace(0.0, duration, count)[:, None]
        out = start + rates * t
        return (out[:, 0] if out.shape[1] == 1 else out), duration / (count - 1)

    def sweep(self, count: int, margin: float = 0.0) -> np.ndarray:
        """``count`` driver positions evenly over the span, less ``margin`` each end."""
        lo, hi = self.span[0] + margin, self.span[1] - margin
        t = np.linspace(0.0, 1.0, count)[:, None]
        out = lo + t * (hi - lo)
        return out[:, 0] if out.shape[1] == 1 else out


def unit(angle: float) -> np.ndarray:
    return np.array([math.cos(angle), math.sin(angle)])


def perp(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def xy(v: np.ndarray) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def circles(
    p1: np.ndarray, r1: float, p2: np.ndarray, r2: float, branch: float
) -> np.ndarray:
    """Where circles (p1, r1) and (p2, r2) cross, left (+1) or right (-1) of p1->p2."""
    gap = p2 - p1
    length = float(np.hypot(*gap))
    a = (r1 * r1 - r2 * r2 + length * length) / (2.0 * length)
    h = math.sqrt(r1 * r1 - a * a)
    g = gap / length
    return p1 + a * g + branch * h * perp(g)


def diagonal_range(
    l2: float, l3: float, mu_lo: float, mu_hi: float
) -> tuple[float, float]:
    """Distances between the outer pins of an RRR dyad for transmission angles
    ``mu_lo`` .. ``mu_hi`` (deg) by the law of cosines."""

    def diag(mu: float) -> float:
        return math.sqrt(l2 * l2 + l3 * l3 - 2.0 * l2 * l3 * math.cos(math.radians(mu)))

    return diag(mu_lo), diag(mu_hi)


def rotation_of(table: assur.Table, link: str) -> np.ndarray:
    """A link's rotation from the reference pose (rad), from its two extra points."""
    mech = table.mechanism
    p_ref = np.array(_resolve(mech, f"{link}_p"))
    q_ref = np.array(_resolve(mech, f"{link}_q"))
    d_ref = q_ref - p_ref
    d = np.stack(
        [
            table[f"{link}_q.x"] - table[f"{link}_p.x"],
            table[f"{link}_q.y"] - table[f"{link}_p.y"],
        ],
        axis=-1,
    )
    return np.arctan2(cross(d_ref, d), d @ d_ref)


def _resolve(mech: assur.Mechanism, name: str) -> tuple[float, float]:
    for point in mech.points:
        if point.name == name:
            assert isinstance(point.at, tuple)
            return point.at
    raise KeyError(name)


def _links(
    names: list[str],
    anchors: dict[str, np.ndarray],
    axes: dict[str, tuple[str, str]],
    decor: list[LinkDecor],
) -> tuple[list[assur.Link], list[assur.Point]]:
    links, points = [], []
    if all(d.mass is None for d in decor):  # keep a force analysis possible
        decor = [
            *decor[:-1],
            LinkDecor(
                decor[-1].p, decor[-1].q, decor[-1].center, 0.5, 1e-3, decor[-1].axis
            ),
        ]
    for name, d in zip(names, decor, strict=True):
        anchor = anchors[name]
        p = anchor + np.array(d.p)
        q = anchor + np.array(d.q)
        if np.hypot(*(q - p)) < 1e-3:
            q = p + np.array([0.02, 0.01])
        points += [
            assur.Point(f"{name}_p", name, xy(p)),
            assur.Point(f"{name}_q", name, xy(q)),
        ]
        axis = {0: None, 1: axes.get(name), 2: (f"{name}_p", f"{name}_q")}[d.axis]
        if d.mass is None:
            links.append(assur.Link(name, axis))
        else:
            links.append(
                assur.Link(
                    name, axis, d.mass, xy(anchor + np.array(d.center)), d.inertia
                )
            )
    return links, points


def _loads(
    names: list[str], anchors: dict[str, np.ndarray], loads: LoadDecor | None
) -> tuple[tuple[float, float] | None, tuple[assur.Load, ...]]:
    if loads is None:
        return None, ()
    out = []
    f_link = names[loads.force_link % len(names)]
    at = xy(anchors[f_link] + np.array(loads.force_at))
    out.append(assur.Load(f_link, at=at, force=loads.force))
    t_link = names[loads.torque_link % len(names)]
    out.append(assur.Load(t_link, torque=loads.torque))
    if loads.table is not None:
        grid = tuple(float(x) for x in np.linspace(0.0, 360.0, len(loads.table) + 1))
        values = (*loads.table, loads.table[0])
        table = assur.LoadTable(
            "driver", grid, (values, tuple(0.5 * v for v in values))
        )
        out.append(
            assur.Load(
                names[-1],
                at=at if f_link == names[-1] else xy(anchors[names[-1]]),
                force=table,
            )
        )
    return loads.gravity, tuple(out)


def _mechanism(
    name: str,
    names: list[str],
    joints: list[assur.Joint],
    drivers: list[assur.Driver],
    anchors: dict[str, np.ndarray],
    axes: dict[str, tuple[str, str]],
    decor: list[LinkDecor],
    loads: LoadDecor | None,
    reverse: bool = False,
) -> assur.Mechanism:
    links, points = _links(names, anchors, axes, decor)
    gravity, load_list = _loads(names, anchors, loads)
    if reverse:
        links = links[::-1]
        joints = joints[::-1]
    return assur.Mechanism(
        tuple(links),
        tuple(joints),
        tuple(drivers),
        name=name,
        gravity=gravity,
        loads=load_list,
        points=tuple(points),
    )


def _rev(name: str, a: str, b: str, at: np.ndarray, flip: bool) -> assur.Joint:
    return assur.Joint(name, "revolute", (b, a) if flip else (a, b), xy(at))


def _pri(
    name: str,
    a: str,
    b: str,
    at: np.ndarray,
    axis: np.ndarray,
    flip: bool,
    kind: str = "prismatic",
) -> assur.Joint:
    return assur.Joint(name, kind, (b, a) if flip else (a, b), xy(at), xy(axis))


def _crank(origin: np.ndarray) -> assur.Joint:
    return assur.Joint("A", "revolute", (GROUND, "crank"), xy(origin))


TURN = np.array([[0.0], [360.0]])
"""A whole turn of the crank from the reference pose."""


def reference_drive(mech: assur.Mechanism) -> np.ndarray:
    """The drivers' positions in the reference pose, in table units: a crank's angle
    (deg) is its axis direction, 0 without an axis; a slider's position is 0."""
    out = []
    for driver in mech.drivers:
        joint = mech.joint(driver.joint)
        link = joint.links[1] if joint.links[0] == GROUND else joint.links[0]
        axis = mech.link(link).axis
        if joint.kind != "revolute" or axis is None:
            out.append(0.0)
            continue
        ends = [_point_at(mech, name) for name in axis]
        out.append(
            math.degrees(math.atan2(ends[1][1] - ends[0][1], ends[1][0] - ends[0][0]))
        )
    return np.array(out)


def steady(mech: assur.Mechanism, **changes: Any) -> assur.Mechanism:
    """``mech`` with its drivers at constant speed (epsilon 0) or as ``changes`` say."""
    changes = {"epsilon": 0.0, **changes}
    drivers = tuple(dataclasses.replace(d, **changes) for d in mech.drivers)
    return dataclasses.replace(mech, drivers=drivers)


def one_turn(
    mech: assur.Mechanism, count: int, *, endpoint: bool = True
) -> tuple[np.ndarray, float]:
    """One turn of the fastest crank from the reference pose, every driver at its own
    rate: ``count`` positions (deg) and the time between rows (s).

    With ``endpoint`` the last row closes the turn, as ``numpy.linspace`` does;
    without, the rows are 1/count turn apart and the last is one step short of it.
    """
    rates = np.degrees([d.omega for d in mech.drivers])
    period = 360.0 / float(np.max(np.abs(rates)))
    if endpoint:
        t = np.linspace(0.0, period, count)[:, None]
        step = period / (count - 1)
    else:
        t = np.arange(count)[:, None] * (period / count)
        step = period / count
    out = reference_drive(mech) + rates * t
    return (out[:, 0] if out.shape[1] == 1 else out), step


def _point_at(mech: assur.Mechanism, name: str) -> tuple[float, float]:
    for item in (*mech.joints, *mech.points):
        if item.name == name:
            assert isinstance(item.at, tuple)
            return item.at
    raise KeyError(name)


def _case(
    mech: assur.Mechanism,
    kind: str,
    group: set[str],
    rotation: np.ndarray,
    branch: Callable | None,
    **notes,
) -> Case:
    """A case whose span is ``rotation`` (2, d) (deg or m) about the reference pose."""
    ref = reference_drive(mech)
    return Case(
        mech,
        kind,
        frozenset(group),
        ref + np.asarray(rotation, dtype=float),
        ref,
        branch,
        notes,
    )


# ------------------------------------------------------------------------------------
# Dyads on a crank. The crank turns about A; ``theta0`` is its reference angle (rad).


def _bcd_branch(branch: float) -> Callable[[assur.Table], np.ndarray]:
    """Branch indicator of an RRR dyad B-C-D: the sign of (C - B) x (D - C)."""

    def indicator(table: assur.Table) -> np.ndarray:
        u2 = np.stack([table["C.x"] - table["B.x"], table["C.y"] - table["B.y"]], -1)
        u3 = np.stack([table["D.x"] - table["C.x"], table["D.y"] - table["C.y"]], -1)
        return -branch * cross(u2, u3)

    return indicator


def rrr(
    origin,
    theta0,
    omega,
    l2,
    l3,
    mu_lo,
    mu_hi,
    phi_d,
    branch,
    flip,
    decor,
    loads,
    reverse=False,
) -> Case:
    """Crank AB and an RRR dyad: link2 B-C, link3 C-D, D on the frame.

    The frame length AD and crank AB are chosen from the transmission angle range
    ``mu_lo .. mu_hi`` (deg): |BD| runs over |AD| -+ |AB|, the diagonals of those
    angles, so the crank turns fully and the angle at C stays within the range.
    """
    lo, hi = diagonal_range(l2, l3, mu_lo, mu_hi)
    d, r = 0.5 * (lo + hi), 0.5 * (hi - lo)
    a = np.asarray(origin, dtype=float)
    b = a + r * unit(theta0)
    dd = a + d * unit(phi_d)
    c = circles(b, l2, dd, l3, branch)
    joints = [
        _crank(a),
        _rev("B", "crank", "link2", b, flip),
        _rev("C", "link2", "link3", c, flip),
        _rev("D", GROUND, "link3", dd, flip),
    ]
    anchors = {"crank": a, "link2": b, "link3": dd}
    axes = {"crank": ("A", "B"), "link2": ("B", "C"), "link3": ("D", "C")}
    mech = _mechanism(
        "RRR on a crank",
        ["crank", "link2", "link3"],
        joints,
        [assur.Driver("A", omega)],
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )

    indicator = _bcd_branch(branch)

    return _case(mech, "RRR", {"link2", "link3"}, TURN, indicator, crank=r, frame=d)


def rrp(
    origin,
    theta0,
    omega,
    l2,
    r_frac,
    e_frac,
    f,
    gamma,
    phi_d,
    shift,
    branch,
    attach,
    flip,
    decor,
    loads,
    reverse=False,
) -> Case:
    """Crank and an RRP dyad, attached two ways.

    ``attach == "crank"``: link2 (rod) pinned to the crank at B, slider link3 on a frame
    guide at angle ``gamma``: the offset slider-crank. ``attach == "frame"``: link2
    pivoted on the frame at D, slider link3 on a guide fixed in the crank. ``f`` is the
    slider pin's offset from its slide line, ``flip`` lists each joint's links the other
    way round (the slide line then fixed in the slider).
    """
    a = np.asarray(origin, dtype=float)
    l2 = float(l2)
    reach = 0.85 * l2  # largest distance from the rod's pivot to the pin's line
    if attach == "crank":
        r = r_frac * reach
        e = e_frac * (reach - r)  # signed distance of the pin's line from A
        b = a + r * unit(theta0)
        t = unit(gamma)
        n = perp(t)
        pivot, pivot_name = b, "B"
        line_normal = n
    else:
        r = 0.6 * l2
        dist = r_frac * reach
        e = e_frac * (reach - dist)
        pivot = a + dist * unit(phi_d)
        pivot_name = "D"
        t = unit(theta0 + gamma)
        n = perp(t)
        line_normal = n
        b = a + r * unit(theta0)
    # the pin C lies on the line n . (X - A) = e, at distance l2 from the pivot
    foot = pivot + (e - float(line_normal @ (pivot - a))) * line_normal
    along = math.sqrt(l2 * l2 - float(np.hypot(*(foot - pivot))) ** 2)
    c = foot + branch * along * t
    q = c - f * n + shift * t  # the slider's point on its slide line
    if attach == "crank":
        joints = [
            _crank(a),
            _rev("B", "crank", "link2", b, flip),
            _rev("C", "link2", "link3", c, flip),
            _pri("P", GROUND, "link3", q, t, flip),
        ]
        anchors = {"crank": a, "link2": b, "link3": c}
        axes = {"crank": ("A", "B"), "link2": ("B", "C")}
    else:
        joints = [
            _crank(a),
            _rev("D", GROUND, "link2", pivot, flip),
            _rev("C", "link2", "link3", c, flip),
            _pri("P", "crank", "link3", q, t, flip),
        ]
        anchors = {"crank": a, "link2": pivot, "link3": c}
        axes = {"crank": ("crank_p", "crank_q"), "link2": ("D", "C")}
    mech = _mechanism(
        f"RRP on a crank ({attach})",
        ["crank", "link2", "link3"],
        joints,
        [assur.Driver("A", omega)],
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )

    def indicator(table: assur.Table) -> np.ndarray:
        turn = rotation_of(table, "crank") if attach == "frame" else 0.0
        tx = np.cos(turn) * t[0] - np.sin(turn) * t[1]
        ty = np.sin(turn) * t[0] + np.cos(turn) * t[1]
        gx = table["C.x"] - table[f"{pivot_name}.x"]
        gy = table["C.y"] - table[f"{pivot_name}.y"]
        return branch * (gx * tx + gy * ty)

    return _case(mech, "RRP", {"link2", "link3"}, TURN, indicator, attach=attach)


def rpr(
    origin,
    theta0,
    omega,
    r,
    d_extra,
    phi_d,
    c_frac,
    e_g,
    shift,
    axis_sign,
    branch,
    guide,
    flip,
    decor,
    loads,
    reverse=False,
    slot=False,
) -> Case:
    """Crank and an RPR dyad: link2 pinned to the crank at B, link3 to the frame at D,
    sliding along each other.

    ``guide`` names the link whose slide line the prismatic joint lists first
    (``"link3"``: a block on the crank pin in a slotted lever; ``"link2"``: an
    oscillating cylinder). The pins' signed distance across the slide line is
    ``c = c_frac * (|AD| - |AB|)``, so the dyad closes at every crank angle.

    With ``slot`` the crank's pin B slides directly in a slot of link3 (a ``"slot"``
    joint, no link2; ``guide`` must be ``"link3"``); the structure adds a block.
    """
    a = np.asarray(origin, dtype=float)
    d = r + d_extra
    b = a + r * unit(theta0)
    dd = a + d * unit(phi_d)
    c = c_frac * (d - r)
    g_pin, h_pin = (dd, b) if guide == "link3" else (b, dd)
    v = h_pin - g_pin
    length = float(np.hypot(*v))
    psi = math.acos(c / length)
    n = unit(math.atan2(v[1], v[0]) - branch * psi)
    t = axis_sign * perp(n)
    point = g_pin + e_g * n + shift * t
    other = "link2" if guide == "link3" else "link3"
    anchors = {"crank": a, "link2": b, "link3": dd}
    axes = {"crank": ("A", "B"), "link2": ("B", "link2_p"), "link3": ("D", "link3_p")}
    g_name, h_name = ("D", "B") if guide == "link3" else ("B", "D")
    if slot:
        assert guide == "link3"
        joints = [
            _crank(a),
            assur.Joint("B", "slot", ("link3", "crank"), xy(b), xy(t)),
            _rev("D", GROUND, "link3", dd, flip),
        ]
        mech = _mechanism(
            "RPR on a crank (slot)",
            ["crank", "link3"],
            joints,
            [assur.Driver("A", omega)],
            anchors,
            axes,
            decor[:2],
            loads,
            reverse,
        )
        group = {"B~block", "link3"}
    else:
        joints = [
            _crank(a),
            _rev("B", "crank", "link2", b, flip),
            _pri("P", guide, other, point, t, flip),
            _rev("D", GROUND, "link3", dd, flip),
        ]
        mech = _mechanism(
            f"RPR on a crank (guide {guide})",
            ["crank", "link2", "link3"],
            joints,
            [assur.Driver("A", omega)],
            anchors,
            axes,
            decor,
            loads,
            reverse,
        )
        group = {"link2", "link3"}

    def indicator(table: assur.Table) -> np.ndarray:
        turn = rotation_of(table, guide)
        nx = np.cos(turn) * n[0] - np.sin(turn) * n[1]
        ny = np.sin(turn) * n[0] + np.cos(turn) * n[1]
        vx = table[f"{h_name}.x"] - table[f"{g_name}.x"]
        vy = table[f"{h_name}.y"] - table[f"{g_name}.y"]
        return -branch * (vx * ny - vy * nx)

    return _case(mech, "RPR", group, TURN, indicator, guide=guide)


def prp(
    origin,
    theta0,
    omega,
    nu2,
    beta0,
    c_off,
    e2,
    e3,
    shifts,
    flips,
    decor,
    loads,
    reverse=False,
) -> Case:
    """Crank and a PRP dyad: block link2 slides on a line fixed in the crank, block
    link3 on a frame guide, pinned together at C.

    The crank line's normal makes the angle ``beta`` with the guide's; the span keeps
    ``beta`` within 35..145 degrees (mod 180) so the lines never come near parallel.
    ``beta0`` (deg, in 40..140) is its reference value.
    """
    a = np.asarray(origin, dtype=float)
    n2 = unit(theta0 + nu2)
    n3 = unit(theta0 + nu2 - math.radians(beta0))
    c = a + np.asarray(c_off, dtype=float)
    t2, t3 = perp(n2), perp(n3)
    q2 = c - e2 * n2 + shifts[0] * t2
    q3 = c - e3 * n3 + shifts[1] * t3
    joints = [
        _crank(a),
        _pri("P2", "crank", "link2", q2, t2, flips[0]),
        _rev("C", "link2", "link3", c, flips[2]),
        _pri("P3", GROUND, "link3", q3, t3, flips[1]),
    ]
    anchors = {"crank": a, "link2": c, "link3": c}
    axes = {"crank": ("crank_p", "crank_q")}
    mech = _mechanism(
        "PRP on a crank",
        ["crank", "link2", "link3"],
        joints,
        [assur.Driver("A", omega)],
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )
    span = np.array([[35.0 - beta0], [145.0 - beta0]])
    return _case(mech, "PRP", {"link2", "link3"}, span, None, beta0=beta0)


def rpp(
    origin,
    theta0,
    omega,
    r,
    pivot,
    angles,
    points,
    attach,
    flips,
    decor,
    loads,
    reverse=False,
    slot=False,
) -> Case:
    """Crank and an RPP dyad, attached two ways.

    ``attach == "crank"``: block link2 pinned to the crank pin B slides in link3, which
    slides on a frame guide (a Scotch yoke with slanted slot and guide).
    ``attach == "frame"``: link2 pivoted on the frame at D slides in link3, which slides
    on a line fixed in the crank. The two slide directions differ by 30..150 degrees.
    With ``slot`` link2 is left out: the crank's pin B (or a pin of the frame at D)
    slides directly in link3's slot.
    """
    a = np.asarray(origin, dtype=float)
    b = a + r * unit(theta0)
    t_mid = unit(theta0 + angles[0])
    t_ext = unit(theta0 + angles[0] + angles[1])
    m_at = a + np.asarray(points[0], dtype=float)
    e_at = a + np.asarray(points[1], dtype=float)
    if attach == "crank":
        pin, pin_name, known = b, "B", ("crank", GROUND)
    else:
        pin, pin_name, known = (
            a + np.asarray(pivot, dtype=float),
            "D",
            (GROUND, "crank"),
        )
    anchors = {"crank": a, "link2": pin, "link3": e_at}
    axes = {"crank": ("crank_p", "crank_q")}
    if slot:
        joints = [
            _crank(a),
            assur.Joint(pin_name, "slot", ("link3", known[0]), xy(pin), xy(t_mid)),
            _pri("E", known[1], "link3", e_at, t_ext, flips[1]),
        ]
        names = ["crank", "link3"]
        group = {f"{pin_name}~block", "link3"}
    else:
        joints = [
            _crank(a),
            _rev(pin_name, known[0], "link2", pin, flips[2]),
            _pri("M", "link3", "link2", m_at, t_mid, flips[0]),
            _pri("E", known[1], "link3", e_at, t_ext, flips[1]),
        ]
        names = ["crank", "link2", "link3"]
        group = {"link2", "link3"}
    mech = _mechanism(
        f"RPP on a crank ({attach})",
        names,
        joints,
        [assur.Driver("A", omega)],
        anchors,
        axes,
        decor[: len(names)],
        loads,
        reverse,
    )
    return _case(mech, "RPP", group, TURN, None, attach=attach)


# ------------------------------------------------------------------------------------
# Two cranks, a prismatic driver, a class III triad


def five_bar(
    origin,
    theta1,
    theta2,
    omega1,
    omega2,
    l1,
    l2,
    mu_lo,
    mu_hi,
    split,
    phi_e,
    branch,
    flip,
    decor,
    loads,
    reverse=False,
) -> Case:
    """Two cranks A-B and E-D on the frame joined by the RRR dyad B-C-D.

    |BD| stays within |AE| -+ (|AB| + |ED|) for any pair of crank angles; those bounds
    are the diagonals of the transmission angles ``mu_lo`` and ``mu_hi``.
    """
    lo, hi = diagonal_range(l1, l2, mu_lo, mu_hi)
    d, r_sum = 0.5 * (lo + hi), 0.5 * (hi - lo)
    r1, r2 = split * r_sum, (1.0 - split) * r_sum
    a = np.asarray(origin, dtype=float)
    e = a + d * unit(phi_e)
    b = a + r1 * unit(theta1)
    dd = e + r2 * unit(theta2)
    c = circles(b, l1, dd, l2, branch)
    joints = [
        _rev("A", GROUND, "crank", a, False),
        _rev("B", "crank", "link2", b, flip),
        _rev("C", "link2", "link3", c, flip),
        _rev("D", "link3", "crank2", dd, flip),
        _rev("E", GROUND, "crank2", e, False),
    ]
    anchors = {"crank": a, "link2": b, "link3": dd, "crank2": e}
    axes = {
        "crank": ("A", "B"),
        "link2": ("B", "C"),
        "link3": ("D", "C"),
        "crank2": ("E", "D"),
    }
    names = ["crank", "link2", "link3", "crank2"]
    drivers = [assur.Driver("A", omega1), assur.Driver("E", omega2)]
    mech = _mechanism(
        "Two-crank five-bar",
        names,
        joints,
        drivers,
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )

    indicator = _bcd_branch(branch)

    return _case(
        mech,
        "RRR",
        {"link2", "link3"},
        np.array([[0.0, 0.0], [360.0, 360.0]]),
        indicator,
        r1=r1,
        r2=r2,
    )


def slider_driven(
    origin,
    gamma,
    omega,
    l2,
    l3,
    mu_lo,
    mu_hi,
    h_frac,
    side,
    f,
    branch,
    flip,
    decor,
    loads,
    reverse=False,
) -> Case:
    """A slider driven along a frame guide (prismatic driver) and an RRR dyad: link2
    from the slider's pin B to C, link3 from C to the frame pivot D.

    The span of slides keeps |BD| between the diagonals of the transmission angles.
    """
    lo, hi = diagonal_range(l2, l3, mu_lo, mu_hi)
    dd = np.asarray(origin, dtype=float)
    t = unit(gamma)
    n = perp(t)
    h = h_frac * lo
    x_lo, x_hi = math.sqrt(lo * lo - h * h), math.sqrt(hi * hi - h * h)
    x0 = 0.5 * (x_lo + x_hi)
    b = dd + h * n + side * x0 * t
    c = circles(b, l2, dd, l3, branch)
    s_at = b - f * n
    joints = [
        assur.Joint("S", "prismatic", (GROUND, "slider"), xy(s_at), xy(t)),
        _rev("B", "slider", "link2", b, flip),
        _rev("C", "link2", "link3", c, flip),
        _rev("D", GROUND, "link3", dd, flip),
    ]
    anchors = {"slider": b, "link2": b, "link3": dd}
    axes = {
        "slider": ("slider_p", "slider_q"),
        "link2": ("B", "C"),
        "link3": ("D", "C"),
    }
    mech = _mechanism(
        "Slider-driven RRR",
        ["slider", "link2", "link3"],
        joints,
        [assur.Driver("S", omega)],
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )
    half = 0.5 * (x_hi - x_lo) * 0.98

    indicator = _bcd_branch(branch)

    return _case(
        mech, "RRR", {"link2", "link3"}, np.array([[-half], [half]]), indicator
    )


CLASS3 = {
    "O2": (0.0, 0.0),
    "C": (0.24, -0.03),
    "D": (0.20, 0.02),
    "E": (0.30, 0.03),
    "F": (0.20, 0.20),
    "G": (0.31, 0.21),
}
"""Frame pivots and plate pins of examples/class3.toml (reference crank at 30 deg)."""


def triad(crank, theta0, omega, moves, decor, loads, reverse=False, check=True) -> Case:
    """A crank and a class III triad: rod B-C, plate C-D-E, rockers F-D and G-E.

    The points of the bundled class III example, each moved by ``moves`` (m). With
    ``check`` the sweep range is the turn (or the part of it around the reference) on
    which :func:`triad_track` finds the triad assembled and well conditioned.
    """
    pts = {
        k: np.array(v, dtype=float) + np.asarray(moves.get(k, (0.0, 0.0)))
        for k, v in CLASS3.items()
    }
    a = pts["O2"]
    b = a + crank * unit(theta0)
    joints = [
        _crank(a),
        _rev("B", "crank", "rod", b, False),
        _rev("C", "rod", "plate", pts["C"], False),
        _rev("D", "plate", "left", pts["D"], False),
        _rev("E", "plate", "right", pts["E"], False),
        _rev("F", GROUND, "left", pts["F"], False),
        _rev("G", GROUND, "right", pts["G"], False),
    ]
    names = ["crank", "rod", "plate", "left", "right"]
    anchors = {
        "crank": a,
        "rod": b,
        "plate": pts["C"],
        "left": pts["F"],
        "right": pts["G"],
    }
    axes = {
        "crank": ("A", "B"),
        "rod": ("B", "C"),
        "plate": ("D", "E"),
        "left": ("F", "D"),
        "right": ("G", "E"),
    }
    mech = _mechanism(
        "Class III triad on a crank",
        names,
        joints,
        [assur.Driver("A", omega)],
        anchors,
        axes,
        decor,
        loads,
        reverse,
    )
    span = TURN
    if check:
        span = np.array([triad_track(pts, crank, theta0)]).T
    return _case(
        mech, "triad", {"rod", "plate", "left", "right"}, span, None, points=pts
    )


def triad_track(
    pts: dict[str, np.ndarray],
    crank: float,
    theta0: float,
    step: float = 2.0,
    limit: float = 0.08,
) -> tuple[float, float]:
    """Follow the triad from the reference pose both ways by Newton's method (own code).

    Returns the range of crank rotation (deg, relative to the reference) reached before
    the triad's dimensionless Jacobian has a reciprocal condition number below
    ``limit`` or Newton fails; a whole turn gives (0, 360).
    """
    a = pts["O2"]
    plate_ref = pts["C"]
    rel = {k: pts[k] - plate_ref for k in ("C", "D", "E")}
    b0 = a + crank * unit(theta0)
    lengths = {
        "C": np.hypot(*(pts["C"] - b0)),
        "D": np.hypot(*(pts["D"] - pts["F"])),
        "E": np.hypot(*(pts["E"] - pts["G"])),
    }
    size = 0.2

    def pins(q: np.ndarray, theta: float) -> tuple[dict, dict]:
        c, s = math.cos(q[2]), math.sin(q[2])
        rot = np.array([[c, -s], [s, c]])
        at = {k: q[:2] + rot @ v for k, v in rel.items()}
        base = {"C": a + crank * unit(theta), "D": pts["F"], "E": pts["G"]}
        return at, base

    def system(q: np.ndarray, theta: float) -> tuple[np.ndarray, np.ndarray]:
        at, base = pins(q, theta)
        res, jac = np.zeros(3), np.zeros((3, 3))
        for i, k in enumerate(("C", "D", "E")):
            g = at[k] - base[k]
            dist = float(np.hypot(*g))
            res[i] = dist - lengths[k]
            u = g / dist
            arm = at[k] - q[:2]
            jac[i] = [u[0], u[1], (u[1] * arm[0] - u[0] * arm[1]) / size]
        return res, jac

    def follow(direction: float) -> float:
        q = np.array([plate_ref[0], plate_ref[1], 0.0])
        done = 0.0
        while done < 360.0:
            theta = theta0 + math.radians(direction * (done + step))
            for _ in range(20):
                res, jac = system(q, theta)
                dq = np.linalg.solve(jac, -res)
                dq[2] /= size
                q = q + dq
                if np.max(np.abs(res)) < 1e-13:
                    break
            res, jac = system(q, theta)
            if np.max(np.abs(res)) > 1e-10 or 1.0 / np.linalg.cond(jac) < limit:
                return done
            done += step
        return 360.0

    up = follow(1.0)
    if up >= 360.0:
        return 0.0, 360.0
    return -follow(-1.0) + step, up - step


# ------------------------------------------------------------------------------------
# Hypothesis strategies


def _float(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.floats(lo, hi, allow_nan=False, allow_infinity=False)


def _vec(lo: float, hi: float) -> st.SearchStrategy[tuple[float, float]]:
    return st.tuples(_float(lo, hi), _float(lo, hi))


def _angle() -> st.SearchStrategy[float]:
    return _float(-math.pi, math.pi)


def _omega() -> st.SearchStrategy[float]:
    return st.tuples(_float(0.5, 30.0), st.sampled_from([1.0, -1.0])).map(
        lambda x: x[0] * x[1]
    )


def _offset(lo: float, hi: float) -> st.SearchStrategy[tuple[float, float]]:
    """A vector of length lo..hi in any direction."""
    return st.tuples(_float(lo, hi), _angle()).map(
        lambda x: (x[0] * math.cos(x[1]), x[0] * math.sin(x[1]))
    )


@st.composite
def link_decor(draw: st.DrawFn) -> LinkDecor:
    return LinkDecor(
        draw(_offset(0.01, 0.06)),
        draw(_offset(0.01, 0.06)),
        draw(_vec(-0.05, 0.05)),
        draw(st.one_of(_float(0.05, 3.0), _float(0.05, 3.0), st.none())),
        draw(_float(1e-5, 1e-2)),
        draw(st.sampled_from([0, 1, 2])),
    )


@st.composite
def load_decor(draw: st.DrawFn, table: bool = True) -> LoadDecor | None:
    if not draw(st.booleans()):
        return None
    gravity = draw(st.sampled_from([None, (0.0, -9.81), (3.0, -7.0)]))
    values = None
    if table and draw(st.booleans()):
        values = tuple(draw(st.lists(_float(-200.0, 200.0), min_size=3, max_size=6)))
    return LoadDecor(
        gravity,
        draw(_vec(-300.0, 300.0)),
        draw(st.integers(0, 4)),
        draw(_vec(-0.05, 0.05)),
        draw(_float(-20.0, 20.0)),
        draw(st.integers(0, 4)),
        values,
    )


def decors(count: int) -> st.SearchStrategy[list[LinkDecor]]:
    return st.lists(link_decor(), min_size=count, max_size=count)


def _common(draw: st.DrawFn, links: int = 3, table: bool = True) -> dict:
    return {
        "decor": draw(decors(links)),
        "loads": draw(load_decor(table)),
        "reverse": draw(st.booleans()),
    }


def _mu(draw: st.DrawFn) -> tuple[float, float]:
    return draw(_float(MU_MIN + 5.0, 70.0)), draw(_float(110.0, 180.0 - MU_MIN - 5.0))


@st.composite
def rrr_cases(
    draw: st.DrawFn, flip: bool | None = None, branch: float | None = None
) -> Case:
    mu_lo, mu_hi = _mu(draw)
    return rrr(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_omega()),
        draw(_float(0.05, 0.2)),
        draw(_float(0.05, 0.2)),
        mu_lo,
        mu_hi,
        draw(_angle()),
        draw(st.sampled_from([1.0, -1.0])) if branch is None else branch,
        draw(st.booleans()) if flip is None else flip,
        **_common(draw),
    )


@st.composite
def rrp_cases(
    draw: st.DrawFn, attach: str | None = None, flip: bool | None = None
) -> Case:
    return rrp(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_omega()),
        draw(_float(0.06, 0.25)),
        draw(_float(0.1, 0.9)),
        draw(_float(-0.9, 0.9)),
        draw(_float(-0.03, 0.03)),
        draw(_angle()),
        draw(_angle()),
        draw(_float(-0.05, 0.05)),
        draw(st.sampled_from([1.0, -1.0])),
        draw(st.sampled_from(["crank", "frame"])) if attach is None else attach,
        draw(st.booleans()) if flip is None else flip,
        **_common(draw),
    )


@st.composite
def rpr_cases(
    draw: st.DrawFn,
    guide: str | None = None,
    flip: bool | None = None,
    slot: bool = False,
) -> Case:
    if slot:
        guide = "link3"
    return rpr(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_omega()),
        draw(_float(0.02, 0.1)),
        draw(_float(0.03, 0.1)),
        draw(_angle()),
        draw(_float(-0.8, 0.8)),
        draw(_float(-0.03, 0.03)),
        draw(_float(-0.05, 0.05)),
        draw(st.sampled_from([1.0, -1.0])),
        draw(st.sampled_from([1.0, -1.0])),
        draw(st.sampled_from(["link2", "link3"])) if guide is None else guide,
        draw(st.booleans()) if flip is None else flip,
        **_common(draw),
        slot=slot,
    )


@st.composite
def prp_cases(draw: st.DrawFn, flips: tuple[bool, bool, bool] | None = None) -> Case:
    return prp(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_omega()),
        draw(_angle()),
        draw(_float(40.0, 140.0)),
        draw(_vec(-0.1, 0.1)),
        draw(_float(-0.02, 0.02)),
        draw(_float(-0.02, 0.02)),
        draw(_vec(-0.05, 0.05)),
        draw(st.tuples(st.booleans(), st.booleans(), st.booleans()))
        if flips is None
        else flips,
        **_common(draw, table=False),
    )


@st.composite
def rpp_cases(
    draw: st.DrawFn,
    attach: str | None = None,
    flips: tuple[bool, bool, bool] | None = None,
    slot: bool = False,
) -> Case:
    between = draw(_float(math.radians(30.0), math.radians(150.0)))
    return rpp(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_omega()),
        draw(_float(0.02, 0.1)),
        draw(_vec(-0.1, 0.1)),
        (draw(_angle()), between),
        (draw(_vec(-0.1, 0.1)), draw(_vec(-0.1, 0.1))),
        draw(st.sampled_from(["crank", "frame"])) if attach is None else attach,
        draw(st.tuples(st.booleans(), st.booleans(), st.booleans()))
        if flips is None
        else flips,
        **_common(draw),
        slot=slot,
    )


@st.composite
def five_bar_cases(draw: st.DrawFn) -> Case:
    mu_lo, mu_hi = _mu(draw)
    return five_bar(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_angle()),
        draw(_omega()),
        draw(_omega()),
        draw(_float(0.05, 0.2)),
        draw(_float(0.05, 0.2)),
        mu_lo,
        mu_hi,
        draw(_float(0.3, 0.7)),
        draw(_angle()),
        draw(st.sampled_from([1.0, -1.0])),
        draw(st.booleans()),
        **_common(draw, links=4),
    )


@st.composite
def slider_cases(draw: st.DrawFn) -> Case:
    mu_lo, mu_hi = _mu(draw)
    return slider_driven(
        draw(_vec(-0.1, 0.1)),
        draw(_angle()),
        draw(_float(0.1, 3.0)) * draw(st.sampled_from([1.0, -1.0])),
        draw(_float(0.05, 0.2)),
        draw(_float(0.05, 0.2)),
        mu_lo,
        mu_hi,
        draw(_float(0.0, 0.8)),
        draw(st.sampled_from([1.0, -1.0])),
        draw(_float(-0.03, 0.03)),
        draw(st.sampled_from([1.0, -1.0])),
        draw(st.booleans()),
        **_common(draw, table=False),
    )


@st.composite
def triad_cases(draw: st.DrawFn, min_span: float = 60.0) -> Case:
    moves = {k: draw(_vec(-0.012, 0.012)) for k in ("C", "D", "E", "F", "G")}
    case = triad(
        draw(_float(0.03, 0.05)),
        draw(_float(0.0, 2 * math.pi)),
        draw(_omega()),
        moves,
        **_common(draw, links=5),
    )
    assume(float(case.span[1, 0] - case.span[0, 0]) >= min_span)
    return case


DYAD_STRATEGIES = {
    "RRR": rrr_cases,
    "RRP": rrp_cases,
    "RPR": rpr_cases,
    "PRP": prp_cases,
    "RPP": rpp_cases,
}
"""Strategy of random cases per dyad kind."""


def slot_cases() -> st.SearchStrategy[Case]:
    """RPR and RPP dyads whose block is a slot joint (a pin sliding in a slot)."""
    return st.one_of(rpr_cases(slot=True), rpp_cases(slot=True))


def any_case() -> st.SearchStrategy[Case]:
    """Any of the builders' cases (triads limited to those that turn far enough)."""
    return st.one_of(
        *(s() for s in DYAD_STRATEGIES.values()),
        slot_cases(),
        five_bar_cases(),
        slider_cases(),
        triad_cases(),
    )


# ------------------------------------------------------------------------------------
# Rigid motions and similarity of a whole mechanism


def moved(
    mech: assur.Mechanism, angle: float = 0.0, shift=(0.0, 0.0), scale: float = 1.0
) -> assur.Mechanism:
    """``mech`` turned by ``angle`` (rad) about the origin, scaled by ``scale`` and then
    shifted by ``shift`` (m): every point, axis, force and gravity turned with it.

    Similarity: lengths times ``scale`` with the same masses and speeds, so moments of
    inertia go with ``scale**2``, gravity and forces with ``scale`` (accelerations do)
    and torques with ``scale**2``; every force in the result is then ``scale`` times
    the original's and every torque ``scale**2`` times. Load tables over a crank's
    position follow its angle.
    """
    c, s = math.cos(angle), math.sin(angle)
    off = np.asarray(shift, dtype=float)

    def vec(v, k: float = 1.0) -> tuple[float, float]:
        return (k * (c * v[0] - s * v[1]), k * (s * v[0] + c * v[1]))

    def at(spec):
        if spec is None or isinstance(spec, str):
            return spec
        if isinstance(spec, assur.Toward):
            return assur.Toward(spec.start, spec.toward, spec.distance * scale)
        return xy(np.array(vec(spec, scale)) + off)

    def force(value):
        if isinstance(value, assur.LoadTable):
            x, y = value.values
            turned = [vec(p, scale) for p in zip(x, y, strict=True)]
            values = (tuple(p[0] for p in turned), tuple(p[1] for p in turned))
            return assur.LoadTable(value.over, _over(value), values)
        return vec(value, scale)

    def torque(value):
        if isinstance(value, assur.LoadTable):
            return assur.LoadTable(
                value.over,
                _over(value),
                (tuple(v * scale**2 for v in value.values[0]),),
            )
        return value * scale**2

    def _over(value: assur.LoadTable) -> tuple[float, ...]:
        if value.over == "driver" and _crank_driven(mech):
            # the driver's position is its link's absolute angle when it has an axis
            joint = mech.joint(mech.drivers[0].joint)
            link = joint.links[1] if joint.links[0] == GROUND else joint.links[0]
            turn = math.degrees(angle) if mech.link(link).axis is not None else 0.0
            return tuple(x + turn for x in value.table)
        return tuple(x * scale for x in value.table)

    links = tuple(
        dataclasses.replace(
            link,
            center=at(link.center),
            inertia=None if link.inertia is None else link.inertia * scale**2,
        )
        for link in mech.links
    )
    joints = tuple(
        dataclasses.replace(
            j, at=at(j.at), axis=None if j.axis is None else vec(j.axis)
        )
        for j in mech.joints
    )
    drivers = tuple(
        d
        if _crank_driven(mech, d)
        else dataclasses.replace(d, omega=d.omega * scale, epsilon=d.epsilon * scale)
        for d in mech.drivers
    )
    loads = tuple(
        dataclasses.replace(
            load,
            at=at(load.at),
            force=None if load.force is None else force(load.force),
            torque=None if load.torque is None else torque(load.torque),
        )
        for load in mech.loads
    )
    points = tuple(dataclasses.replace(p, at=at(p.at)) for p in mech.points)
    gravity = None if mech.gravity is None else vec(mech.gravity, scale)
    return dataclasses.replace(
        mech,
        links=links,
        joints=joints,
        drivers=drivers,
        loads=loads,
        points=points,
        gravity=gravity,
    )


def _crank_driven(mech: assur.Mechanism, driver: assur.Driver | None = None) -> bool:
    driver = driver or mech.drivers[0]
    return mech.joint(driver.joint).kind == "revolute"


def bounded(max_examples: int) -> Any:
    """Hypothesis settings of these tests: few examples, deterministic, no deadline."""
    from hypothesis import HealthCheck, settings

    return settings(
        max_examples=max_examples,
        deadline=None,
        derandomize=True,
        suppress_health_check=[
            HealthCheck.too_slow,
            HealthCheck.filter_too_much,
            HealthCheck.data_too_large,
        ],
    )
