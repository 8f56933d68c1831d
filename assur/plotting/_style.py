"""Colours and opacities shared by every picture of :mod:`assur.plotting`."""

from __future__ import annotations

BALANCING_COLOR = "#6a3d9a"
"""Colour of the balancing loads (the links' colours are in :mod:`assur._style`)."""
GROUND_COLOR = "#333333"
PLAIN_COLOR = "#4d4d4d"
REACTION_COLOR = "#d62728"
INERTIA_COLOR = "#111111"
LOAD_COLOR = "#00838f"
PATH_COLORS = (
    "#1f77b4",
    "#d62728",
    "#2ca02c",
    "#9467bd",
    "#ff7f0e",
    "#17becf",
    "#8c564b",
    "#e377c2",
    "#bcbd22",
    "#7f7f7f",
)
"""Colours of the paths of points (cycled)."""
FAINT = 0.22
"""Opacity of the links drawn only for orientation."""
ARROW_LENGTH = 0.28
"""Length of the largest force arrow at the default scale, relative to the mechanism."""
LINK_UNITS = {"angle": "deg", "omega": "rad/s", "alpha": "rad/s²", "jerk": "rad/s³"}
POINT_PARTS = {"x": ("x", "y"), "v": ("vx", "vy"), "a": ("ax", "ay"), "j": ("jx", "jy")}
POINT_UNITS = {
    "x": "m",
    "y": "m",
    "s": "m",
    "v": "m/s",
    "vx": "m/s",
    "vy": "m/s",
    "a": "m/s²",
    "ax": "m/s²",
    "ay": "m/s²",
    "j": "m/s³",
    "jx": "m/s³",
    "jy": "m/s³",
}
