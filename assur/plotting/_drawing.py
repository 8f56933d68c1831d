"""What every plan is drawn with: its axes in mm, arrows, images, legend.

The images of the points are drawn from the pole and named, those at one place in one
label; the legend lists the coloured parts and states the scale. matplotlib is
imported inside the functions only.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from assur.plotting._apart import moved
from assur.plotting._axes import _new_axes
from assur.plotting._heads import fitted_arrow
from assur.plotting._style import literal

SAME_PLACE = 0.5
"""Images closer than this (mm of the drawing) are named in one label."""
ALONG = 0.2
"""Arrows on one line within this (mm of the drawing) would be drawn over each
other where their spans overlap by more."""
BESIDE = 1.2
"""How far sideways (mm of the drawing) an arrow along one drawn is moved."""


def _beside(
    drawn: list[tuple[np.ndarray, np.ndarray]], start: np.ndarray, end: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Return an arrow's ends (mm), moved by steps of :data:`BESIDE` off those drawn.

    ``drawn`` holds the ends of the arrows drawn before. In an RPR group whose
    slot passes through the pivot, the tangential and Coriolis terms are both
    perpendicular to the slot, on one line: the second hid the first.
    """
    return moved(drawn, start, end, BESIDE, ALONG)


def _joined(
    ax: Any, start: np.ndarray, end: np.ndarray, ends: tuple[np.ndarray, np.ndarray]
) -> None:
    """Join an arrow moved aside (``ends``) to where it belongs (``start``, ``end``).

    Two short dotted lines: the chain of arrows still reads tip to tail across the
    step (:data:`BESIDE`) the move made. Nothing when it was not moved.
    """
    for at, there in zip((start, end), ends, strict=True):
        if float(np.hypot(*(there - at))) > 0.0:
            ax.plot(*np.transpose([at, there]), ":", color="#555555", lw=0.8)


def _arrow_apart(
    ax: Any,
    drawn: list[tuple[np.ndarray, np.ndarray]],
    start: np.ndarray,
    end: np.ndarray,
    color: str,
    **kw: Any,
) -> tuple[np.ndarray, np.ndarray] | None:
    """Draw an arrow off those ``drawn`` (:func:`_beside`), joined to its place.

    Returns its ends as drawn (added to ``drawn``), or None when it is nothing
    (:func:`_arrow`).
    """
    ends = _beside(drawn, start, end)
    if not _arrow(ax, *ends, color, **kw):
        return None
    _joined(ax, start, end, ends)
    drawn.append(ends)
    return ends


def _arrow(ax: Any, start: np.ndarray, end: np.ndarray, color: str, **kw: Any) -> bool:
    """Draw an arrow from ``start`` to ``end`` (mm); return whether it was drawn.

    One shorter than 1e-9 mm (a term that is nothing) is not; a short one gets a
    head shorter than itself (:mod:`assur.plotting._heads`).
    """
    if float(np.hypot(*(end - start))) < 1e-9:
        return False
    lw = kw.pop("lw", 1.4)
    ax.add_patch(fitted_arrow([start, end], 11.0, color=color, lw=lw, **kw))
    return True


def _label(name: str) -> str:
    """Return a point's image label: lower case, as the plans name them."""
    if name.endswith(".G"):
        return f"g({name[:-2]})"
    return name.lower() if len(name) <= 3 else name


def _axes(ax: Any, title: str, size: tuple[float, float] = (7.5, 6.5)) -> Any:
    """Return axes to draw on, titled, equal aspect, in mm of the drawing.

    ``size`` is a new figure's, inches.
    """
    ax = _new_axes(ax, size)
    ax.set_title(title, fontsize=10)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("mm of the plan")
    ax.grid(True, lw=0.4, alpha=0.4)
    return ax


def _images_plot(
    ax: Any, found: dict[str, np.ndarray], mu: float, color: str
) -> list[Any]:
    """Draw every image from the pole; name them, those at one place in one label.

    Return the names' texts.
    """
    places: list[tuple[np.ndarray, list[str]]] = []
    texts = []
    for name, v in found.items():
        tip = v / mu
        _arrow(ax, np.zeros(2), tip, color, lw=0.9, alpha=0.55)
        ax.plot(*tip, "o", ms=3.5, color=color, gid=f"image-{name}")
        _place(places, tip, _label(name), SAME_PLACE)
    for tip, names in places:
        texts.append(
            ax.annotate(
                literal(" = ".join(names)),
                tip,
                xytext=(4, 4),
                textcoords="offset points",
                fontsize=8,
            )
        )
    ax.plot([0], [0], "ko", ms=5)
    ax.annotate(
        "pole", (0, 0), xytext=(-14, -12), textcoords="offset points", fontsize=8
    )
    return texts


def _place(
    places: list[tuple[np.ndarray, list[str]]], at: np.ndarray, name: str, near: float
) -> None:
    """Add ``name`` at ``at`` to ``places``: to the names within ``near`` of it."""
    for where, names in places:
        if float(np.hypot(*(where - at))) <= near:
            names.append(name)
            return
    places.append((at, [name]))


def _legend(
    ax: Any, entries: list[tuple[str, str]], note: str, beside: bool = False
) -> None:
    """Put a legend of coloured entries and a note (the scale).

    ``beside``: at the foot of the space right of the axes, not on the drawing.
    """
    from matplotlib.lines import Line2D

    handles = [Line2D([], [], color=c, lw=3, label=literal(t)) for t, c in entries]
    handles.append(Line2D([], [], color="none", label=note))
    where = {"loc": "lower left", "bbox_to_anchor": (1.02, 0.0)} if beside else {}
    ax.legend(handles=handles, fontsize=8, **({"loc": "best"} | where))
