"""Defects a visual review of the pictures found: scales, means, frames, labels.

Each test names the picture as it was wrong and checks it as drawn (Agg).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import numpy as np

import assur
from assur.plotting import lever

matplotlib.use("Agg")

EXAMPLES = Path(__file__).parent.parent / "examples"


def _arrows(ax, color: str) -> list[float]:
    """Return the lengths, mm of the drawing, of the arrows of ``color`` on ``ax``."""
    from matplotlib.colors import to_hex

    return [
        float(np.hypot(*np.subtract(*p.points)))
        for p in ax.patches
        if hasattr(p, "points") and to_hex(p.get_edgecolor()) == color
    ]


def test_the_lever_draws_couples_to_the_forces_scale() -> None:
    import matplotlib.pyplot as plt

    # the slotted lever's couples (0.1 % of the torque) were its biggest arrows,
    # drawn to 1 mm = 0.001 N beside the forces' 1 mm = 10 N
    table = assur.forces(assur.load(EXAMPLES / "slot_mechanism.toml"), [30.0])
    ax = lever.zhukovsky_lever(table)
    try:
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        assert sum("1 mm =" in t for t in legend) == 1, legend
        assert any("same scale" in t and "below the scale" in t for t in legend)
        couples = _arrows(ax, lever.COUPLE)
        assert couples
        assert max(couples) <= lever.MARK * (1 + 1e-9)
        assert max(couples) < max(_arrows(ax, lever.FORCE))
    finally:
        plt.close(ax.figure)
