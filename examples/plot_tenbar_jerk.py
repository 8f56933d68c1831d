"""
Ten-bar mechanism: angular velocities, accelerations and jerks
==============================================================

The ten-bar advance-and-grip mechanism of the kinematics notes: a crank turning at
one revolution per second drives four dyads, RRR (2, 3), RRR (4, 5), RRP (6, 7) and
RRR (8, 9). The notes solve it by vector loops up to the third derivative, the
jerk; ``assur`` solves every derivative group by group with the same linear system
(see the theory page).
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "tenbar.toml")
print(assur.structure(mech).formula)

angles = np.arange(0.0, 360.0, 0.5)
table = assur.kinematics(mech, angles)
time = table["angle"] / 360.0  # one revolution per second

# %%
# The mechanism at t = 0
# ----------------------
# Each Assur group has its own colour.

plotting.draw(table, angle=0.0)

# %%
# Jerk of the links
# -----------------
# The angular velocity, acceleration and jerk (the third derivative of the angle)
# of five links. The jerk, the rate of change of the acceleration, shows where the
# motion is least smooth: between t = 0.5 s and t = 0.8 s, when the gripping links
# swing back quickly.

fig, axes = plt.subplots(3, 1, sharex=True, figsize=(8, 8))
for link in ("2", "3", "6", "8", "9"):
    axes[0].plot(time, table[f"{link}.omega"], label=f"link {link}")
    axes[1].plot(time, table[f"{link}.alpha"])
    axes[2].plot(time, table[f"{link}.jerk"])
axes[0].set_ylabel(r"$\omega$ [rad/s]")
axes[1].set_ylabel(r"$\alpha$ [rad/s$^2$]")
axes[2].set_ylabel(r"jerk [rad/s$^3$]")
axes[2].set_xlabel("time [s]")
axes[0].legend(ncol=5, fontsize="small")
fig.suptitle("Ten-bar mechanism: derivatives of the link angles")

# %%
# The slider
# ----------
# Slider 7 runs on a guide inclined at 24 degrees; ``guide.s`` is its slide along
# the guide's axis and ``guide.v``, ``guide.a``, ``guide.j`` its derivatives.

fig, axes = plt.subplots(2, 2, sharex=True, figsize=(9, 5.5))
labels = {
    "s": "slide [m]",
    "v": "velocity [m/s]",
    "a": r"acceleration [m/s$^2$]",
    "j": r"jerk [m/s$^3$]",
}
for ax, (key, label) in zip(axes.flat, labels.items(), strict=True):
    ax.plot(time, table[f"guide.{key}"], color="C4")
    ax.set_ylabel(label)
for ax in axes[1]:
    ax.set_xlabel("time [s]")
fig.suptitle("Slider 7 on its inclined guide")

# %%
# The jerk is exact
# -----------------
# The jerk columns come from the analytic third-order equations, not from
# differencing. A central difference of the acceleration agrees with them to the
# difference's own truncation error.

step = 0.5 / 360.0  # seconds between rows (0.5 degree at one turn per second)
difference = np.gradient(table["2.alpha"], step)
inner = slice(1, -1)
error = np.max(np.abs(difference[inner] - table["2.jerk"][inner]))
print(
    f"largest difference, link 2: {error:.3g} rad/s^3 "
    f"(jerk up to {np.max(np.abs(table['2.jerk'])):.3g})"
)

plt.show()
