"""Hand-written closed-form numpy batches of the slider-crank and the four-bar.

The yardstick for ``bench_sweep.py``: the same outputs as ``assur.kinematics`` and
``assur.forces`` (same column names, same sign conventions), written the way an
engineer would write them for one known mechanism in plain numpy: closed-form
positions, the derivatives of the loop-closure equations solved by Cramer's rule,
rigid-body formulas for every point and every link's instant centre, and the classic
dyad-by-dyad reactions. Each
function takes driver angles in degrees and returns ``{column: array}``; long sweeps
run in slices of ``CHUNK`` positions written into one preallocated array.

Also here: the per-position scipy ``fsolve`` versions (positions from the
loop-closure equations, velocities from a 2x2 solve), the way users write it by hand.

The dimensions mirror ``assur.catalog.slider_crank()`` and ``assur.catalog.four_bar()``
with their default arguments; ``bench_sweep.py`` checks the outputs against assur.
"""

from __future__ import annotations

import math

import numpy as np

CHUNK = 4096

# assur.catalog.slider_crank(): crank 0.074, rod 0.2, offset 0, reference pose at
# 45 deg, 200 rad/s; masses 10, 0.5, 0.4 kg; centres 0.020 from A on the crank and
# 0.060 from B on the rod.
SC = {
    "crank": 0.074,
    "rod": 0.200,
    "offset": 0.0,
    "angle0": 45.0,
    "omega": 200.0,
    "epsilon": 0.0,
    "m": (10.0, 0.5, 0.4),
    "J": (0.0, 0.0018, 0.0),
    "g_crank": 0.020,
    "g_rod": 0.060,
}
# assur.catalog.four_bar(): A = (0, 0), D = (0.1, 0); crank 0.04, coupler 0.12, rocker
# 0.08; reference pose at 60 deg, 10 rad/s; bars of 2 kg/m with slender-bar inertia,
# centres at mid-length; coupler point P at mid-coupler.
FB = {
    "crank": 0.04,
    "coupler": 0.12,
    "rocker": 0.08,
    "frame": 0.10,
    "angle0": 60.0,
    "omega": 10.0,
    "epsilon": 0.0,
}
TRANSLATION = 1e-12
"""A link translates (its instant centre is at infinity: NaN) where its angular speed
times the mechanism's size is at most this fraction of its origin's speed: assur's
test, so that both give NaN at the same positions."""


def _rigid(p, u_x, u_y, w, al, je):
    """Position, velocity, acceleration and jerk (x, y each) of ``p + u``.

    ``p`` is the 8-tuple of a point of the body, ``u`` the vector from it to the new
    point, ``w, al, je`` the body's angular velocity, acceleration and jerk.
    """
    px, py, vx, vy, ax, ay, jx, jy = p
    w2 = w * w
    k = je - w2 * w
    q = 3.0 * w * al
    return (
        px + u_x,
        py + u_y,
        vx - w * u_y,
        vy + w * u_x,
        ax - al * u_y - w2 * u_x,
        ay + al * u_x - w2 * u_y,
        jx - k * u_y - q * u_x,
        jy + k * u_x - q * u_y,
    )


def _ic(o, w, size):
    """Instant centre ``o + (-v_oy, v_ox) / w`` of a link with origin ``o`` (8-tuple).

    NaN where the link translates: ``|w| size <= TRANSLATION |v_o|``.
    """
    ox, oy, vx, vy = o[:4]
    moving = np.abs(w) * size > TRANSLATION * np.hypot(vx, vy)
    with np.errstate(divide="ignore", invalid="ignore"):
        return (
            np.where(moving, ox - vy / w, np.nan),
            np.where(moving, oy + vx / w, np.nan),
        )


def _size(*points):
    """Largest distance between two of ``points`` (x, y): the mechanism's size."""
    return max(math.dist(p, q) for p in points for q in points)


def _maxabs(*values):
    """Largest magnitude, position by position, of the arrays or scalars given."""
    out = np.abs(values[0])
    for v in values[1:]:
        out = np.maximum(out, np.abs(v))
    return out


_FIXED = (0.0,) * 8
_SUFFIX = ("x", "y", "vx", "vy", "ax", "ay", "jx", "jy")


def _point_cols(name, p):
    return [(f"{name}.{s}", v) for s, v in zip(_SUFFIX, p, strict=True)]


def _link_cols(name, angle_deg, w, al, je, ic):
    return [
        (f"{name}.angle", angle_deg),
        (f"{name}.omega", w),
        (f"{name}.alpha", al),
        (f"{name}.jerk", je),
        (f"{name}.ic.x", ic[0]),
        (f"{name}.ic.y", ic[1]),
    ]


def _sweep(kernel, deg):
    """Run ``kernel`` over ``deg`` in slices and gather its columns."""
    deg = np.asarray(deg, dtype=float)
    n = deg.shape[0]
    names = None
    out = None
    for start in range(0, n, CHUNK):
        cols = kernel(deg[start : start + CHUNK])
        if out is None:
            names = [c[0] for c in cols]
            out = np.empty((len(cols), n))
        block = out[:, start : start + CHUNK]
        for i, (_, v) in enumerate(cols):
            block[i] = v
    return dict(zip(names, out, strict=True))


# ------------------------------------------------------------------------ slider-crank


def _sc_motion(deg):
    p = SC
    r, L, e = p["crank"], p["rod"], p["offset"]
    w2, al2, j2 = p["omega"], p["epsilon"], 0.0
    th = np.radians(deg)
    B = _rigid(_FIXED, r * np.cos(th), r * np.sin(th), w2, al2, j2)
    # rod: the slide line y = e fixes sin(phi); derivatives of
    # r sin(th) + L sin(phi) = e give its omega, alpha and jerk
    sphi = (e - B[1]) / L
    cphi = np.sqrt(1.0 - sphi * sphi)
    Lc = L * cphi
    Ls = L * sphi
    w3 = -B[3] / Lc
    al3 = (Ls * w3 * w3 - B[5]) / Lc
    j3 = w3 * w3 * w3 + (3.0 * Ls * w3 * al3 - B[7]) / Lc
    C = _rigid(B, Lc, Ls, w3, al3, j3)
    return th, B, sphi, cphi, (w3, al3, j3), C


def _sc_kin_cols(deg, th, B, sphi, cphi, rod, C):
    p = SC
    w3, al3, j3 = rod
    kc = p["g_crank"] / p["crank"]
    kr = p["g_rod"] / p["rod"]
    L = p["rod"]
    G2 = tuple(kc * v for v in B)
    G3 = _rigid(B, kr * L * cphi, kr * L * sphi, w3, al3, j3)
    x0 = SC_POSE["C"][0]
    size = SC_POSE["size"]
    cols = [("angle", deg)]
    ic = _ic(_FIXED, p["omega"], size)
    cols += _link_cols("crank", deg, p["omega"], p["epsilon"], 0.0, ic)
    rod_angle = np.degrees(np.arctan2(sphi, cphi))
    cols += _link_cols("rod", rod_angle, w3, al3, j3, _ic(B, w3, size))
    # the slider translates: no instant centre
    cols += _link_cols("slider", 0.0, 0.0, 0.0, 0.0, (np.nan, np.nan))
    cols += _point_cols("A", _FIXED) + _point_cols("B", B) + _point_cols("C", C)
    cols += _point_cols("guide", C)
    cols += [
        ("guide.s", C[0] - x0),
        ("guide.v", C[2]),
        ("guide.a", C[4]),
        ("guide.j", C[6]),
    ]
    cols += _point_cols("crank.G", G2) + _point_cols("rod.G", G3)
    cols += _point_cols("slider.G", C)
    return cols, G2, G3


def _sc_kin_kernel(deg):
    th, B, sphi, cphi, rod, C = _sc_motion(deg)
    return _sc_kin_cols(deg, th, B, sphi, cphi, rod, C)[0]


def _sc_forces_kernel(deg):
    p = SC
    th, B, sphi, cphi, rod, C = _sc_motion(deg)
    cols, G2, G3 = _sc_kin_cols(deg, th, B, sphi, cphi, rod, C)
    w3, al3, _ = rod
    m2, m3, m4 = p["m"]
    J2, J3, J4 = p["J"]
    w2, al2 = p["omega"], p["epsilon"]
    # d'Alembert loads (no gravity in the catalog mechanism)
    F2x, F2y, M2 = -m2 * G2[4], -m2 * G2[5], -J2 * al2
    F3x, F3y, M3 = -m3 * G3[4], -m3 * G3[5], -J3 * al3
    F4x, F4y, M4 = -m4 * C[4], -m4 * C[5], -J4 * 0.0
    ux, uy = C[0] - B[0], C[1] - B[1]  # B -> C
    gx, gy = G3[0] - B[0], G3[1] - B[1]  # B -> G3
    # slider along the guide: the rod's push balances the slider's x load
    RCx = -F4x
    # rod, moments about B: (C - B) x (-R_C) + (G3 - B) x F3 + M3 = 0
    RCy = (uy * RCx + gx * F3y - gy * F3x + M3) / ux
    RBx, RBy = RCx - F3x, RCy - F3y  # crank on rod
    Rgx, Rgy = 0.0 * RCx, -RCy - F4y  # ground on slider (normal to the guide)
    Mg = -M4  # guide couple about C (G4 = C)
    RAx, RAy = RBx - F2x, RBy - F2y  # ground on crank
    T = B[0] * RBy - B[1] * RBx - (G2[0] * F2y - G2[1] * F2x) - M2
    # virtual power: T w2 + sum of the applied loads' power = 0
    check = (
        -(
            F2x * G2[2]
            + F2y * G2[3]
            + M2 * w2
            + F3x * G3[2]
            + F3y * G3[3]
            + M3 * w3
            + F4x * C[2]
            + F4y * C[3]
        )
        / w2
    )
    shx, shy = -(RAx + Rgx), -(RAy + Rgy)
    shm = -(C[0] * Rgy - C[1] * Rgx + Mg) - T
    # residuals: every link's resultant force and moment about its origin (A, B, C)
    rf = _maxabs(
        RAx - RBx + F2x,
        RAy - RBy + F2y,
        RBx - RCx + F3x,
        RBy - RCy + F3y,
        RCx + Rgx + F4x,
        RCy + Rgy + F4y,
    )
    rm = _maxabs(
        T - (B[0] * RBy - B[1] * RBx) + G2[0] * F2y - G2[1] * F2x + M2,
        -(ux * RCy - uy * RCx) + gx * F3y - gy * F3x + M3,
        Mg + M4,
    )
    with np.errstate(divide="ignore", invalid="ignore"):
        offset = np.where(np.abs(Rgy) > 1e-12, Mg / Rgy, np.nan)
    cols += [
        ("crank.Fi.x", F2x),
        ("crank.Fi.y", F2y),
        ("crank.Mi", M2),
        ("rod.Fi.x", F3x),
        ("rod.Fi.y", F3y),
        ("rod.Mi", M3),
        ("slider.Fi.x", F4x),
        ("slider.Fi.y", F4y),
        ("slider.Mi", M4),
        ("A.Fx", RAx),
        ("A.Fy", RAy),
        ("A.F", np.hypot(RAx, RAy)),
        ("B.Fx", RBx),
        ("B.Fy", RBy),
        ("B.F", np.hypot(RBx, RBy)),
        ("C.Fx", RCx),
        ("C.Fy", RCy),
        ("C.F", np.hypot(RCx, RCy)),
        ("guide.Fx", Rgx),
        ("guide.Fy", Rgy),
        ("guide.F", np.abs(Rgy)),
        ("guide.M", Mg),
        ("guide.offset", offset),
        ("driver.torque", T),
        ("driver.torque_check", check),
        ("shaking.Fx", shx),
        ("shaking.Fy", shy),
        ("shaking.M", shm),
        ("residual.force", rf),
        ("residual.moment", rm),
    ]
    return cols


def _sc_pose():
    """The catalog slider-crank's reference pose: pivots and size (the largest
    distance between two joints), as the catalog builds it."""
    p = SC
    r, L, e = p["crank"], p["rod"], p["offset"]
    a = math.radians(p["angle0"])
    B = (r * math.cos(a), r * math.sin(a))
    C = (B[0] + math.sqrt(L * L - (e - B[1]) ** 2), e)
    return {"B": B, "C": C, "size": _size((0.0, 0.0), B, C)}


SC_POSE = _sc_pose()


def slider_crank_kinematics(deg):
    """Kinematics columns of the catalog slider-crank at crank angles ``deg``."""
    return _sweep(_sc_kin_kernel, deg)


def slider_crank_forces(deg):
    """Kinematics and kinetostatics columns of the catalog slider-crank."""
    return _sweep(_sc_forces_kernel, deg)


# ---------------------------------------------------------------------------- four-bar


def _fb_motion(deg):
    p = FB
    r2, r3, r4, d = p["crank"], p["coupler"], p["rocker"], p["frame"]
    w2, al2 = p["omega"], p["epsilon"]
    th = np.radians(deg)
    B = _rigid(_FIXED, r2 * np.cos(th), r2 * np.sin(th), w2, al2, 0.0)
    # C: intersection of the circles about B (r3) and D (r4), left of B -> D
    dx, dy = d - B[0], -B[1]
    L2 = dx * dx + dy * dy
    a = (r3 * r3 - r4 * r4 + L2) / (2.0 * L2)
    h = np.sqrt(r3 * r3 / L2 - a * a)
    u3x, u3y = a * dx - h * dy, a * dy + h * dx  # B -> C
    u4x, u4y = B[0] + u3x - d, B[1] + u3y  # D -> C
    # Cramer on  w3 perp(u3) - w4 perp(u4) = rhs  (the loop's k-th derivative)
    inv = 1.0 / (u3y * u4x - u3x * u4y)

    def solve(rx, ry):
        return (u4x * rx + u4y * ry) * -inv, (u3x * rx + u3y * ry) * -inv

    w3, w4 = solve(-B[2], -B[3])
    w3s, w4s = w3 * w3, w4 * w4
    al3, al4 = solve(-B[4] + w3s * u3x - w4s * u4x, -B[5] + w3s * u3y - w4s * u4y)
    c3, c4 = w3s * w3, w4s * w4
    q3, q4 = 3.0 * w3 * al3, 3.0 * w4 * al4
    j3, j4 = solve(
        -B[6] - c3 * u3y + q3 * u3x + c4 * u4y - q4 * u4x,
        -B[7] + c3 * u3x + q3 * u3y - c4 * u4x - q4 * u4y,
    )
    C = _rigid(B, u3x, u3y, w3, al3, j3)
    return th, B, (u3x, u3y, w3, al3, j3), (u4x, u4y, w4, al4, j4), C


def _fb_kin_cols(deg, B, cpl, rck, C):
    p = FB
    u3x, u3y, w3, al3, j3 = cpl
    u4x, u4y, w4, al4, j4 = rck
    D = (p["frame"], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    G2 = tuple(0.5 * v for v in B)
    G3 = _rigid(B, 0.5 * u3x, 0.5 * u3y, w3, al3, j3)
    G4 = _rigid(D, 0.5 * u4x, 0.5 * u4y, w4, al4, j4)
    size = FB_POSE["size"]
    cols = [("angle", deg)]
    ic = _ic(_FIXED, p["omega"], size)
    cols += _link_cols("crank", deg, p["omega"], p["epsilon"], 0.0, ic)
    angle = np.degrees(np.arctan2(u3y, u3x))
    cols += _link_cols("coupler", angle, w3, al3, j3, _ic(B, w3, size))
    angle = np.degrees(np.arctan2(u4y, u4x))
    cols += _link_cols("rocker", angle, w4, al4, j4, _ic(D, w4, size))
    cols += (
        _point_cols("A", _FIXED)
        + _point_cols("B", B)
        + _point_cols("C", C)
        + _point_cols("D", D)
        + _point_cols("P", G3)
        + _point_cols("crank.G", G2)
        + _point_cols("coupler.G", G3)
        + _point_cols("rocker.G", G4)
    )
    return cols, G2, G3, G4


def _fb_kin_kernel(deg):
    _, B, cpl, rck, C = _fb_motion(deg)
    return _fb_kin_cols(deg, B, cpl, rck, C)[0]


def _fb_forces_kernel(deg):
    p = FB
    _, B, cpl, rck, C = _fb_motion(deg)
    cols, G2, G3, G4 = _fb_kin_cols(deg, B, cpl, rck, C)
    u3x, u3y, w3, al3, _ = cpl
    u4x, u4y, w4, al4, _ = rck
    d = p["frame"]
    w2, al2 = p["omega"], p["epsilon"]
    m2, m3, m4 = (2.0 * p[k] for k in ("crank", "coupler", "rocker"))
    J2, J3, J4 = (2.0 * p[k] ** 3 / 12.0 for k in ("crank", "coupler", "rocker"))
    F2x, F2y, M2 = -m2 * G2[4], -m2 * G2[5], -J2 * al2
    F3x, F3y, M3 = -m3 * G3[4], -m3 * G3[5], -J3 * al3
    F4x, F4y, M4 = -m4 * G4[4], -m4 * G4[5], -J4 * al4
    # coupler about B and rocker about D, in R_C (coupler on rocker):
    #   u3 x R_C = k3 = (G3 - B) x F3 + M3 ;  u4 x R_C = -k4 = -((G4 - D) x F4 + M4)
    k3 = 0.5 * (u3x * F3y - u3y * F3x) + M3
    k4 = 0.5 * (u4x * F4y - u4y * F4x) + M4
    inv = 1.0 / (u3x * u4y - u3y * u4x)
    RCx = (k3 * u4x + k4 * u3x) * inv
    RCy = (k3 * u4y + k4 * u3y) * inv
    RBx, RBy = RCx - F3x, RCy - F3y  # crank on coupler
    RDx, RDy = -RCx - F4x, -RCy - F4y  # ground on rocker
    RAx, RAy = RBx - F2x, RBy - F2y  # ground on crank
    T = B[0] * RBy - B[1] * RBx - (G2[0] * F2y - G2[1] * F2x) - M2
    # virtual power: T w2 + sum of the applied loads' power = 0
    check = (
        -(
            F2x * G2[2]
            + F2y * G2[3]
            + M2 * w2
            + F3x * G3[2]
            + F3y * G3[3]
            + M3 * w3
            + F4x * G4[2]
            + F4y * G4[3]
            + M4 * w4
        )
        / w2
    )
    shx, shy = -(RAx + RDx), -(RAy + RDy)
    shm = -d * RDy - T
    # residuals: every link's resultant force and moment about its pivot (A, B, D)
    rf = _maxabs(
        RAx - RBx + F2x,
        RAy - RBy + F2y,
        RBx - RCx + F3x,
        RBy - RCy + F3y,
        RCx + RDx + F4x,
        RCy + RDy + F4y,
    )
    rm = _maxabs(
        T - (B[0] * RBy - B[1] * RBx) + G2[0] * F2y - G2[1] * F2x + M2,
        k3 - (u3x * RCy - u3y * RCx),
        k4 + (u4x * RCy - u4y * RCx),
    )
    cols += [
        ("crank.Fi.x", F2x),
        ("crank.Fi.y", F2y),
        ("crank.Mi", M2),
        ("coupler.Fi.x", F3x),
        ("coupler.Fi.y", F3y),
        ("coupler.Mi", M3),
        ("rocker.Fi.x", F4x),
        ("rocker.Fi.y", F4y),
        ("rocker.Mi", M4),
        ("A.Fx", RAx),
        ("A.Fy", RAy),
        ("A.F", np.hypot(RAx, RAy)),
        ("B.Fx", RBx),
        ("B.Fy", RBy),
        ("B.F", np.hypot(RBx, RBy)),
        ("C.Fx", RCx),
        ("C.Fy", RCy),
        ("C.F", np.hypot(RCx, RCy)),
        ("D.Fx", RDx),
        ("D.Fy", RDy),
        ("D.F", np.hypot(RDx, RDy)),
        ("driver.torque", T),
        ("driver.torque_check", check),
        ("shaking.Fx", shx),
        ("shaking.Fy", shy),
        ("shaking.M", shm),
        ("residual.force", rf),
        ("residual.moment", rm),
    ]
    return cols


def _fb_pose():
    """The catalog four-bar's reference pose: pivots and size (the largest distance
    between two joints)."""
    p = FB
    _, B, _, _, C = _fb_motion(np.array([p["angle0"]]))
    B, C = (float(B[0][0]), float(B[1][0])), (float(C[0][0]), float(C[1][0]))
    size = _size((0.0, 0.0), B, C, (p["frame"], 0.0))
    return {"B": B, "C": C, "size": size}


FB_POSE = _fb_pose()


def four_bar_kinematics(deg):
    """Kinematics columns of the catalog four-bar at crank angles ``deg``."""
    return _sweep(_fb_kin_kernel, deg)


def four_bar_forces(deg):
    """Kinematics and kinetostatics columns of the catalog four-bar."""
    return _sweep(_fb_forces_kernel, deg)


# ----------------------------------------------------------------- per-position fsolve


def slider_crank_fsolve(deg):
    """Rod angle, slider x and their rates per position with ``scipy.optimize.fsolve``.

    Returns an array (n, 4): phi (rad), x (m), omega (rad/s), v (m/s).
    """
    from scipy.optimize import fsolve

    r, L, e, w = SC["crank"], SC["rod"], SC["offset"], SC["omega"]
    out = np.empty((len(deg), 4))
    guess = np.array([0.0, r + L])
    for i, a in enumerate(np.radians(deg)):
        c, s = math.cos(a), math.sin(a)

        def loop(q, c=c, s=s):
            return [r * c + L * math.cos(q[0]) - q[1], r * s + L * math.sin(q[0]) - e]

        guess = fsolve(loop, guess)
        phi = guess[0]
        jac = np.array([[-L * math.sin(phi), -1.0], [L * math.cos(phi), 0.0]])
        rates = np.linalg.solve(jac, [r * s * w, -r * c * w])
        out[i] = phi, guess[1], rates[0], rates[1]
    return out


def four_bar_fsolve(deg):
    """Coupler and rocker angles and rates per position with ``scipy.optimize.fsolve``.

    Returns an array (n, 4): theta3, theta4 (rad), omega3, omega4 (rad/s).
    """
    from scipy.optimize import fsolve

    r2, r3, r4, d, w = (FB[k] for k in ("crank", "coupler", "rocker", "frame", "omega"))
    out = np.empty((len(deg), 4))
    guess = np.array([0.5, 1.5])
    for i, a in enumerate(np.radians(deg)):
        c, s = math.cos(a), math.sin(a)

        def loop(q, c=c, s=s):
            return [
                r2 * c + r3 * math.cos(q[0]) - r4 * math.cos(q[1]) - d,
                r2 * s + r3 * math.sin(q[0]) - r4 * math.sin(q[1]),
            ]

        guess = fsolve(loop, guess)
        t3, t4 = guess
        jac = np.array(
            [
                [-r3 * math.sin(t3), r4 * math.sin(t4)],
                [r3 * math.cos(t3), -r4 * math.cos(t4)],
            ]
        )
        rates = np.linalg.solve(jac, [r2 * s * w, -r2 * c * w])
        out[i] = t3, t4, rates[0], rates[1]
    return out
