"""Private numerical helpers shared by the core: the array type and angle wrapping.

The kernels work on vectors as ``(x, y)`` pairs of arrays (see ``groups._motion``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Array = NDArray[np.float64]


def wrap(phi: Array) -> Array:
    """Wrap angles to (-pi, pi]."""
    return np.pi - np.mod(np.pi - phi, 2.0 * np.pi)
