"""The colours of the links, shared by the pictures and the HTML report.

Every driving link is drawn in one neutral colour (a driver is the class I mechanism,
not an Assur group); the Assur groups take colour-blind-safe hues in order of
attachment, so that a link has the same colour in a picture and in the report.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from assur.plan import Plan

__all__ = [
    "DRIVER_COLOUR",
    "GROUP_COLOURS",
    "REACTION_COLOUR",
    "group_colour",
    "link_colours",
]

DRIVER_COLOUR = "#334155"
"""Colour of every driving link (and of its balancing load in the pictures)."""
REACTION_COLOUR = "#d62728"
"""Colour of every joint reaction: in each picture (overview, free body, force
polygon) and in the report's drawing, so that a reaction looks the same in all."""
GROUP_COLOURS = (
    "#0072b2",
    "#d55e00",
    "#009e73",
    "#cc79a7",
    "#e69f00",
    "#56b4e9",
    "#8c564b",
    "#b8860b",
)
"""Colours of the Assur groups in order of attachment (cycled): Okabe and Ito's six
hues for colour-blind readers (without black and yellow), then brown and dark
goldenrod."""


def group_colour(index: int) -> str:
    """Return the colour of Assur group ``index`` (0: the first group attached).

    Examples
    --------
    >>> group_colour(0), group_colour(len(GROUP_COLOURS))
    ('#0072b2', '#0072b2')
    """
    return GROUP_COLOURS[index % len(GROUP_COLOURS)]


def link_colours(plan: Plan) -> dict[str, str]:
    """Return the colour of every moving link of ``plan`` (slot blocks too), by name.

    A driving link has :data:`DRIVER_COLOUR`; the links of an Assur group their
    group's colour.
    """
    colours = {plan.bodies[d.body]: DRIVER_COLOUR for d in plan.drivers}
    for k, group in enumerate(plan.groups):
        colours.update(dict.fromkeys(group.links, group_colour(k)))
    return colours
