"""
Whitworth quick-return mechanism: ram velocity
==============================================

A shaper's Whitworth mechanism: the crank O2B = 60 mm carries a block that slides in
the slot of a lever pivoted at O4, 30 mm above O2. Because O2O4 is shorter than the
crank, the lever turns fully too, but unevenly. The lever's arm O4E drives the rod EF
and the ram F. The structure is a crank, an RPR dyad (block, lever) and an RRP dyad
(rod, ram). The crank turns at a constant 5 rad/s, so the ram's slow and fast strokes
take different times: the quick return.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur
from assur import plotting

# The mechanism files sit next to this script (sphinx-gallery runs it from
# this folder, without __file__).
HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "whitworth.toml")
print(assur.structure(mech).formula)

angles = np.arange(0.0, 360.0, 0.25)
table = assur.forces(mech, angles)

# %%
# The mechanism
# -------------

plotting.draw(table, angle=45.0)

# %%
# The two strokes
# ---------------
# The ram's extreme positions give the strokes. The cutting stroke (the ram moving
# to the left, against the cutting resistance) takes the longer part of the turn.

x = table["F.x"]
left, right = angles[np.argmin(x)], angles[np.argmax(x)]
cutting = (left - right) % 360.0  # from the right end to the left end
ratio = cutting / (360.0 - cutting)
print(f"ram stroke: {x.max() - x.min():.4f} m")
print(f"ends of stroke at crank angles {right:.1f} and {left:.1f} deg")
print(
    f"cutting stroke {cutting:.1f} deg, return {360 - cutting:.1f} deg, "
    f"time ratio {ratio:.2f}"
)

# %%
# Ram velocity
# ------------
# Negative while cutting, positive on the return. The return is more than twice as
# fast at its peak.

vx = table["F.vx"]
fig, ax = plt.subplots(figsize=(8, 4.5))
ax.plot(angles, vx, color="C3")
ax.fill_between(
    angles, vx, 0.0, where=vx < 0, color="C0", alpha=0.2, label="cutting stroke"
)
ax.fill_between(
    angles, vx, 0.0, where=vx > 0, color="C1", alpha=0.2, label="return stroke"
)
ax.axhline(0.0, color="0.5", lw=0.8)
ax.set_xlabel("crank angle [deg]")
ax.set_ylabel("ram velocity [m/s]")
ax.set_title("Whitworth mechanism: velocity of the ram")
ax.legend()
print(f"cutting speed up to {-vx.min():.3f} m/s, return speed up to {vx.max():.3f} m/s")

# %%
# Driving torque
# --------------
# The cutting resistance of 400 N acts on the ram from 165 to 370 degrees of crank
# angle (a load table in the file). The balancing torque on the crank, with its
# check by virtual power:

plotting.plot_torque(table)

plt.show()
