"""
Counterweight on the crank: less shaking force
==============================================

The inertia loads of the slider-crank of the kinetostatics lesson (crank 0.074 m at
200 rad/s, 10 kg crank, 0.5 kg rod, 0.4 kg slider) shake its frame: the resultant of
the loads on the frame turns round once per revolution. A counterweight on the crank,
opposite the crank pin, cancels part of it. Its mass is chosen here by
``scipy.optimize.minimize_scalar`` to make the RMS shaking force over a turn as small
as it can be, for a counterweight 50 mm from the crank's pivot.
"""

import math

import matplotlib.pyplot as plt
import numpy as np
from scipy.optimize import minimize_scalar

import assur
from assur import catalog

RADIUS = 0.050  # m, from the pivot A, opposite the crank pin B
ANGLE = 45.0  # deg, the crank angle of the reference pose
angles = np.arange(45.0, 405.0, 2.0)


def balanced(counterweight: float) -> assur.Mechanism:
    """The slider-crank with a point mass (kg) on the crank, opposite B."""
    mech = catalog.slider_crank()
    crank = mech.link("crank")
    u = np.array([math.cos(math.radians(ANGLE)), math.sin(math.radians(ANGLE))])
    # the crank's own mass, 10 kg, has its centre 0.020 m from A toward B
    masses = np.array([crank.mass, counterweight])
    along = np.array([0.020, -RADIUS])
    mass = float(masses.sum())
    centre = float(masses @ along) / mass
    inertia = float(masses @ (along - centre) ** 2)
    link = assur.Link(
        "crank", crank.axis, mass, tuple(float(c) for c in centre * u), inertia
    )
    links = tuple(link if x.name == "crank" else x for x in mech.links)
    return assur.Mechanism(
        links=links, joints=mech.joints, drivers=mech.drivers, name=mech.name
    )


def shaking(counterweight: float) -> np.ndarray:
    """The shaking force over a turn, (positions, 2), N."""
    table = assur.forces(balanced(counterweight), angles)
    return np.column_stack((table["shaking.Fx"], table["shaking.Fy"]))


def rms(counterweight: float) -> float:
    force = shaking(counterweight)
    return float(np.sqrt(np.mean(np.sum(force**2, axis=1))))


best = minimize_scalar(rms, bounds=(0.0, 20.0), method="bounded")
print(f"counterweight {best.x:.3f} kg at {1e3 * RADIUS:.0f} mm")
print(f"RMS shaking force: {rms(0.0):.0f} N without, {best.fun:.0f} N with it")

# %%
# Before and after
# ----------------
# Left, the tip of the shaking-force vector over a turn: without a counterweight a
# large circle (the crank's unbalance) stretched along the slide line (the slider's
# reciprocating mass); with it, what a counterweight on the crank cannot cancel, the
# reciprocating part, shared between the two axes. Right, the magnitude over the
# turn, and, as a check, the crank bearing's peak load from a study of counterweights.

before, after = shaking(0.0), shaking(best.x)
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.5))
left.plot(before[:, 0], before[:, 1], label="no counterweight")
left.plot(after[:, 0], after[:, 1], label=f"{best.x:.2f} kg at 50 mm")
left.set_aspect("equal")
left.set_xlabel("shaking force x, N")
left.set_ylabel("shaking force y, N")
left.legend(loc="upper right", fontsize="small")
right.plot(angles, np.hypot(*before.T), label="no counterweight")
right.plot(angles, np.hypot(*after.T), label="optimal counterweight")
right.set_xlabel("crank angle, deg")
right.set_ylabel("shaking force, N")
right.legend(fontsize="small")
fig.tight_layout()

# %%
# A study of counterweights
# -------------------------
# :func:`assur.sweep <assur.study.sweep>` analyses a range of counterweights at
# once; the summary gives each one's largest load on the crank's bearing A and the
# largest driving torque.

masses = np.linspace(0.0, 2.0 * best.x, 21)
study = assur.sweep(balanced, {"counterweight": masses}, angles)
fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(masses, study.summary["A.F.max"], "o-", label="bearing A, peak load, N")
ax.plot(masses, study.summary["driver.torque.max"], "s-", label="peak torque, N m")
ax.axvline(best.x, color="k", ls="--", lw=1)
ax.set_xlabel("counterweight, kg")
ax.legend(fontsize="small")
fig.tight_layout()
plt.show()
