"""
Lever mechanism: a crank, an RRP dyad and a PRP dyad
====================================================

The lever mechanism of a structural and kinematic analysis sheet (variant 9): crank
AB = 0.1 m turning at 15 rad/s and accelerating at 10 rad/s^2, rod BC = 0.3 m whose
end C slides on the line y = 0, and a block sliding along the rod, pinned at D to a
slider on the vertical line x = -0.5 m. The groups are RRP (rod, slider 3) and PRP
(block 4, slider 5).
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "lever_var9.toml")
print(assur.structure(mech).formula)

angles = np.arange(45.0, 405.0, 1.0)
table = assur.kinematics(mech, angles)

# %%
# The mechanism at 45 degrees
# ---------------------------

plotting.draw(table, angle=45.0)

# %%
# Exact geometry and the sheet's shortcut
# ---------------------------------------
# The sheet takes the rod's angle as pi + yB / lBC instead of pi + asin(yB / lBC).
# At 45 degrees yB / lBC = 0.236 and the shortcut shows: the sheet prints 193.505
# degrees, 3.536 rad/s and 0.819 m/s.

row = 0
print(f"rod angle  {table['2.angle'][row] % 360:8.3f} deg   (sheet 193.505)")
print(f"rod speed  {abs(table['2.omega'][row]):8.3f} rad/s (sheet 3.536)")
print(f"|vDy|      {abs(table['D.vy'][row]):8.3f} m/s   (sheet 0.819)")

y_b = table["B.y"]
shortcut = 180.0 + np.degrees(y_b / 0.3)
exact = 180.0 + np.degrees(np.arcsin(y_b / 0.3))

fig, ax = plt.subplots(figsize=(8, 4))
ax.plot(angles, table["2.angle"] % 360.0, label="assur (exact)")
ax.plot(angles, exact, ":", color="k", label=r"$\pi + \arcsin(y_B/l_{BC})$")
ax.plot(angles, shortcut, "--", label=r"$\pi + y_B/l_{BC}$ (sheet)")
ax.set_xlabel("crank angle [deg]")
ax.set_ylabel("rod angle [deg]")
ax.legend()

# %%
# The output slider
# -----------------
# Slider 5 at D moves up and down the line x = -0.5 m; the block slides along the rod
# (``block.s``). Velocities and accelerations include the crank's angular
# acceleration, since the crank speeds up at every position.

fig, axes = plt.subplots(3, 1, sharex=True, figsize=(8, 7))
axes[0].plot(angles, table["D.y"], color="C2")
axes[0].set_ylabel("y of D [m]")
axes[1].plot(angles, table["D.vy"], color="C2")
axes[1].set_ylabel("vy of D [m/s]")
axes[2].plot(angles, table["block.s"], color="C4")
axes[2].set_ylabel("block slide [m]")
axes[2].set_xlabel("crank angle [deg]")
fig.suptitle("Lever mechanism: the output slider and the block")

plt.show()
