"""The diagrams' figures of many panels over a sweep: the links' motion, the slides.

Each quantity gets a panel; the panels share the driver's axis and one legend beside
them (each panel's own legend covered the ten-bar's curves).
"""

from __future__ import annotations

from typing import Any

__all__ = ["motion_figure", "slides_figure"]


def _panels(
    plotting: Any, plt: Any, table: Any, names: Any, quantities: tuple[str, ...]
) -> Any:
    """Return a figure of ``quantities`` of ``names``, a panel each, over the sweep.

    ``names`` None: every moving link. The panels share the driver's axis.
    """
    fig, axes = plt.subplots(
        len(quantities), 1, figsize=(8.0, 9.0), sharex=True, layout="constrained"
    )
    for ax, quantity in zip(axes, quantities, strict=True):
        plotting.plot_motion(table, names, quantity=quantity, ax=ax)
        ax.set_title("")
    for ax in axes[:-1]:
        ax.set_xlabel("")
    # the panels draw the same lines: one legend beside them, where it covers none
    handles, labels = axes[0].get_legend_handles_labels()
    for ax in axes:
        if ax.get_legend() is not None:
            ax.get_legend().remove()
    if handles:
        fig.legend(handles, labels, loc="outside right upper", fontsize=8)
    return fig


def motion_figure(plotting: Any, plt: Any, table: Any) -> Any:
    """Return the figure of the links' angles, angular speeds and accelerations."""
    # imported here: assur.plotting is loaded with the picture commands, not with
    # every command line (kinematics's start was 50 ms the slower)
    from assur.plotting._style import titled

    fig = _panels(plotting, plt, table, None, ("angle", "omega", "alpha"))
    title = f"{titled(table.mechanism)}: motion of the links"
    fig.axes[0].set_title(title, fontsize=10)
    return fig


def slides_figure(plotting: Any, plt: Any, table: Any, joints: list[str]) -> Any:
    """Return the figure of the prismatic pairs' slides, speeds and accelerations.

    For a slider-crank the slider's stroke is the motion that matters, and the
    links' angles leave it out.
    """
    from assur.plotting._style import titled

    fig = _panels(plotting, plt, table, joints, ("s", "v", "a"))
    title = f"{titled(table.mechanism)}: slides of the prismatic pairs"
    fig.axes[0].set_title(title, fontsize=10)
    return fig
