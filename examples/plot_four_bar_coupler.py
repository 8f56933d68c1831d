"""
Four-bar: coupler curve and transmission angle
==============================================

A Grashof crank-rocker: crank O2A = 40 mm, coupler AB = 120 mm, rocker O4B = 80 mm,
frame O2O4 = 120 mm. The shortest link is the crank, and the sum of the shortest and
longest links (160 mm) is less than that of the other two (200 mm), so the crank
turns fully while the rocker swings. P is a point of the coupler off the line AB; its
path is the coupler curve.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "four_bar.toml")
angles = np.arange(60.0, 420.0, 1.0)
table = assur.kinematics(mech, angles)

# %%
# The coupler curve
# -----------------
# The paths of the coupler point P and of the pins A and B over one turn of the
# crank, over the mechanism in its reference pose.

plotting.plot_paths(table, ["P", "A", "B"])

# %%
# Speed along the curve
# ---------------------
# The crank turns at 20 rad/s and speeds up at 10 rad/s^2 (its state at every
# position). The point P moves fastest where the curve is flattest; colouring the
# curve by speed shows it.

speed = np.hypot(table["P.vx"], table["P.vy"])
fig, ax = plt.subplots(figsize=(6.5, 5))
points = ax.scatter(table["P.x"], table["P.y"], c=speed, s=8, cmap="viridis")
fig.colorbar(points, ax=ax, label="speed of P [m/s]")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_title("Coupler curve coloured by speed")
print(f"speed of P: {speed.min():.3f} to {speed.max():.3f} m/s")

# %%
# Transmission angle
# ------------------
# The angle between the coupler and the rocker at B. Far from 90 degrees the
# coupler pushes the rocker mostly along its length, and little of its force turns
# it; designers keep it within about 40 to 140 degrees.

mu = (table["rocker.angle"] - table["coupler.angle"]) % 360.0
mu = np.where(mu > 180.0, 360.0 - mu, mu)
fig, ax = plt.subplots(figsize=(8, 4))
ax.plot(table["angle"], mu)
ax.axhspan(40.0, 140.0, color="C2", alpha=0.1, label="40 to 140 degrees")
ax.set_xlabel("crank angle [deg]")
ax.set_ylabel("transmission angle [deg]")
ax.legend()
print(f"transmission angle: {mu.min():.1f} to {mu.max():.1f} degrees")

plt.show()
