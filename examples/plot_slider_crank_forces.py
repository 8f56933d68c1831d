"""
Slider-crank: balancing torque and joint reactions
==================================================

The slider-crank of the kinetostatics lesson: crank AB = 0.074 m turning
counter-clockwise at a constant 200 rad/s, connecting rod BC = 0.200 m, masses 10,
0.5 and 0.4 kg. The lesson works out its inertia loads at 45 degrees; here the force
analysis runs over a whole turn, with and without gravity.
"""

import dataclasses
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "slider_crank_exercise.toml")
angles = np.arange(45.0, 405.0, 1.0)  # one turn from the reference pose
table = assur.forces(mech, angles)

# %%
# The mechanism at 45 degrees
# ---------------------------
# The inertia loads, the reactions (each drawn as the force of the joint's first
# link on its second) and the balancing torque on the crank, to one force scale.

plotting.draw(table, angle=45.0, forces=True)

row = 0  # the first row is 45 degrees
print(f"balancing torque at 45 deg: {table['driver.torque'][row]:.3f} N m")
print(f"  by virtual power:          {table['driver.torque_check'][row]:.3f} N m")
for joint in ("A", "B", "C", "guide"):
    # + 0.0: a component of -0.0 N is printed 0.00, not -0.00
    fx, fy = table[f"{joint}.Fx"][row] + 0.0, table[f"{joint}.Fy"][row] + 0.0
    print(f"reaction {joint:>5}: ({fx:9.2f}, {fy:9.2f}) N")

# %%
# Balancing torque over a turn
# ----------------------------
# The torque the motor must apply to keep the crank at exactly 200 rad/s. The dots
# are the same torque found independently by the principle of virtual power. With
# the crank's speed held constant and only inertia and weight acting, the work of
# the motor over a turn is zero: the mean torque vanishes.

heavy = assur.forces(dataclasses.replace(mech, gravity=(0.0, -9.81)), angles)

fig, ax = plt.subplots(figsize=(8, 4.5))
ax.plot(table["angle"], table["driver.torque"], label="no gravity")
ax.plot(heavy["angle"], heavy["driver.torque"], "--", label="gravity 9.81 m/s$^2$")
ax.plot(
    table["angle"][::20],
    table["driver.torque_check"][::20],
    "o",
    ms=4,
    color="C0",
    label="virtual power check",
)
ax.axhline(0.0, color="0.6", lw=0.8)
ax.set_xlabel("crank angle [deg]")
ax.set_ylabel("balancing torque [N m]")
ax.set_title("Balancing torque on the crank")
ax.legend()

print(f"mean balancing torque: {table['driver.torque'].mean():.2e} N m")
print(f"with gravity at 45 deg: {heavy['driver.torque'][0]:.3f} N m")

# %%
# Reactions in the joints
# -----------------------
# The magnitude of every joint reaction over the turn. The crank's own inertia
# force (10 kg whose centre turns on a 20 mm radius: 8000 N) dominates the main
# bearing A. The guide's reaction vanishes at the dead centres (180 and 360 degrees),
# where the rod lies along the guide.

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
for ax, joints in ((top, ("A",)), (bottom, ("B", "C", "guide"))):
    for joint in joints:
        magnitude = np.hypot(table[f"{joint}.Fx"], table[f"{joint}.Fy"])
        ax.plot(table["angle"], magnitude, label=joint)
    ax.set_ylabel("reaction [N]")
    ax.legend(loc="upper right")
bottom.set_xlabel("crank angle [deg]")
top.set_title("Joint reactions (magnitude)")

plt.show()
