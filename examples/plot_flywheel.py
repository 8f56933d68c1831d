"""
Whitworth quick-return mechanism: flywheel and start-up
=======================================================

The shaper's crank turns at a nominal 5 rad/s against the cutting force on the ram.
The linkage is light: reduced to the crank, its inertia could not carry it through
the cutting stroke at that speed, and the crank would stop. This example finds the
flywheel that holds the coefficient of speed fluctuation to 5 %, compares it with the
classical estimates, draws the dynamic model and the energy-mass (Wittenbauer)
diagram, checks the kinetostatics at the real motion, and starts the shaper from
rest with an electric motor.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import assur

HERE = Path(__file__).parent if "__file__" in globals() else Path.cwd()
mech = assur.load(HERE / "whitworth.toml")

# %%
# The flywheel for a 5 % fluctuation
# ----------------------------------
# ``assur.flywheel`` solves the steady state for the inertia; ``flywheel_sizing``
# sets Wittenbauer's construction and the largest energy swing beside it.

sizing = assur.flywheel_sizing(mech, 0.05)
print(f"exact flywheel       {sizing.exact:.4f} kg m^2")
for name, gap in sizing.differences().items():
    print(f"{name:<20} {getattr(sizing, name):.4f} kg m^2 ({100 * gap:+.4f} %)")

steady = assur.dynamics(mech, flywheel=sizing.exact)
print(f"delta = {steady.delta:.6f}, motor torque {steady.motor:.4f} N m")

# %%
# The dynamic model
# -----------------
# The reduced inertia barely changes (the flywheel dominates it); the reduced torque
# of the cutting force is resisted over the cutting stroke only. The speed is
# lowest at the end of the cutting stroke.

steady.plot()

# %%
# Kinetostatics at the real motion
# --------------------------------
# With the crank's real speed and acceleration, the balancing torque is the motor's
# constant torque less the torque that accelerates the flywheel.

table = assur.forces(
    mech,
    steady["angle"],
    omega=steady["driver.omega"],
    epsilon=steady["driver.epsilon"],
)
want = steady["driver.motor"] - steady.flywheel * steady["driver.epsilon"]
print(f"largest difference: {np.max(np.abs(table['driver.torque'] - want)):.2e} N m")

# %%
# Start-up under an electric motor
# --------------------------------
# A motor of three times the mean load torque at standstill, whose torque falls to
# zero at 8 rad/s, brings the shaper up to its periodic motion.

run = assur.startup(mech, sizing.exact, motor=assur.Motor(3.0 * steady.motor, 8.0))
print(
    f"settled after {run.settle_time:.1f} s; periodic mean speed "
    f"{run.mean_speed:.3f} rad/s, delta {run.delta:.4f}"
)
run.plot()
plt.show()
