"""Pictures of a mechanism and of its results, drawn with matplotlib.

The mechanism at one driver position (each Assur group in its own colour, forces as
arrows to a stated scale), its decomposition step by step, the free-body diagram of a
group, diagrams over a sweep, the dynamic model and the start-up, and an animated
GIF. matplotlib is imported inside the functions only, so ``import assur`` stays free
of it.
"""

from __future__ import annotations

# Besides the public functions, a few private names (``_row``, ``_context``, ...) and
# ``ARROW_LENGTH`` are imported here: tests/test_plotting.py reaches for them.
from assur.plotting._context import _context as _context
from assur.plotting._context import _row as _row
from assur.plotting._forces import _overview_arrows as _overview_arrows
from assur.plotting._forces import _scale as _scale
from assur.plotting._geometry import _nice as _nice
from assur.plotting._style import ARROW_LENGTH as ARROW_LENGTH
from assur.plotting.animation import animate
from assur.plotting.decomposition import (
    _free_body_arrows as _free_body_arrows,
)
from assur.plotting.decomposition import draw_decomposition, draw_free_body
from assur.plotting.diagrams import plot_motion, plot_paths
from assur.plotting.dynamics import (
    plot_dynamics,
    plot_energy_mass,
    plot_reduced_inertia,
    plot_reduced_torque,
    plot_speed,
    plot_startup,
)
from assur.plotting.force_diagrams import plot_hodographs, plot_shaking, plot_torque
from assur.plotting.lever import zhukovsky_lever
from assur.plotting.mechanism import draw
from assur.plotting.plans import (
    acceleration_plan,
    instant_centres,
    velocity_plan,
)
from assur.plotting.polygons import force_polygons

__all__ = [
    "acceleration_plan",
    "animate",
    "draw",
    "draw_decomposition",
    "draw_free_body",
    "force_polygons",
    "instant_centres",
    "plot_dynamics",
    "plot_energy_mass",
    "plot_hodographs",
    "plot_motion",
    "plot_paths",
    "plot_reduced_inertia",
    "plot_reduced_torque",
    "plot_shaking",
    "plot_speed",
    "plot_startup",
    "plot_torque",
    "velocity_plan",
    "zhukovsky_lever",
]
