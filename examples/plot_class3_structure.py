"""
A class III mechanism: structure and a Newton-solved triad
==========================================================

A crank drives a ternary plate C-D-E through the rod BC; two rockers hang the plate
from the frame pivots F and G. No dyad can be split off: the plate carries three
internal pairs, so the rod, the plate and the two rockers form one class III Assur
group of the third order (a triad), solved together by Newton's method.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "class3.toml")

# %%
# The structural analysis
# -----------------------
# Four links and six pairs (B, C, D, E, F, G): 3k = 12 = 2p, and no smaller part of
# the chain has zero mobility on the crank and the frame.

print(assur.structure(mech))

# %%
# The decomposition, step by step: the class I mechanism (frame and crank), then the
# triad hung on the crank at B and on the frame at F and G.

table = assur.forces(mech, np.arange(30.0, 390.0, 1.0))
plotting.draw_decomposition(table, angle=30.0)

# %%
# The class depends on the input link
# -----------------------------------
# Driven by one of its rockers instead of the crank, the same chain splits into two
# dyads: a class II mechanism.

for joint in ("O2", "F", "G"):
    s = assur.structure(mech, driver=joint)
    print(f"driven at {joint}: class {s.mechanism_class}, {s.formula}")

# %%
# Motion of the triad
# -------------------
# The triad has no closed-form solution; its positions come from Newton's method,
# followed along the crank's turn from the reference pose so that it keeps the
# assembly drawn in the file. Velocities and accelerations then solve linear
# systems with the group's Jacobian.

fig, axes = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
for link in ("rod", "plate", "left_rocker", "right_rocker"):
    axes[0].plot(table["angle"], table[f"{link}.omega"], label=link)
    axes[1].plot(table["angle"], table[f"{link}.alpha"])
axes[0].set_ylabel(r"$\omega$ [rad/s]")
axes[1].set_ylabel(r"$\alpha$ [rad/s$^2$]")
axes[1].set_xlabel("crank angle [deg]")
axes[0].legend(ncol=2, fontsize="small")
fig.suptitle("Angular velocities and accelerations of the triad's links")

# %%
# Forces
# ------
# The triad's reactions come from the twelve equilibrium equations of its four
# links, all at once. The balancing torque agrees with the virtual-power check.

plotting.plot_torque(table)
gap = np.max(np.abs(table["driver.torque"] - table["driver.torque_check"]))
print(f"largest difference between the two torques: {gap:.1e} N m")

plt.show()
