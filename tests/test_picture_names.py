"""A joint reaction has one name and one colour in every picture and the report.

The overview (``assur plot --forces``) named the reaction at B ``R_B``, the free
body ``R_{C,rod->slider}``, the force polygon ``F_{crank,rod}`` (black there, red
elsewhere, and an inertia force red): the same force read as three. All now use the
note's ``F_{i,j}``, the force of link i on link j, in the reaction colour.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pytest

import assur
from assur import plotting
from assur._style import REACTION_COLOUR
from assur.html import render_report
from assur.plotting._mathtext import reaction_symbol
from assur.plotting._style import REACTION_LEGEND

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.colors import to_hex

EXAMPLES = Path(__file__).parent.parent / "examples"


def _named(texts: list, symbol: str) -> list:
    """The texts that name ``symbol`` (alone, or followed by its value)."""
    return [t for t in texts if t.get_text().split(" = ")[0] == symbol]


def _legend(ax) -> list[str]:  # type: ignore[no-untyped-def]
    """The legend's entries of ``ax``."""
    return [t.get_text() for t in ax.get_legend().get_texts()]


@pytest.fixture(scope="module")
def table() -> assur.Table:
    return assur.forces(assur.load(EXAMPLES / "slider_crank_exercise.toml"), [45.0])


@pytest.mark.parametrize(("by", "on"), [("crank", "rod"), ("ground", "slider")])
def test_a_reaction_reads_alike_in_every_picture(table, by: str, on: str) -> None:
    # B (crank on rod) and the guide (ground on slider) act on the group's links:
    # the overview, the group's free body and its force polygon draw the same force
    symbol = reaction_symbol(by, on)
    overview = plotting.draw(table, forces=True)
    free_body = plotting.draw_free_body(table, 0)
    polygons = plotting.force_polygons(table)
    try:
        pictures = [overview.texts, free_body.texts, polygons.axes[0].texts]
        for texts in pictures:
            (text,) = _named(texts, symbol)
            assert to_hex(text.get_color()) == REACTION_COLOUR
        for ax in (overview, free_body, polygons.axes[0]):
            assert REACTION_LEGEND in _legend(ax)
        # nothing else in the polygon is drawn in the reaction colour
        others = [t for t in polygons.axes[0].texts if "_{i," in t.get_text()]
        assert others
        assert all(to_hex(t.get_color()) != REACTION_COLOUR for t in others)
    finally:
        plt.close("all")


def test_no_picture_names_a_reaction_the_old_ways(table) -> None:
    overview = plotting.draw(table, forces=True)
    free_body = plotting.draw_free_body(table, 0)
    try:
        texts = [t.get_text() for t in overview.texts + free_body.texts]
        assert not any(t.startswith("$R_") or "\\to" in t for t in texts)
        # an external load is Q, as the note writes it: F_{i,j} is a reaction
        assert not any(t.startswith("$F_{\\text") for t in texts)
    finally:
        plt.close("all")


def test_the_report_draws_reactions_in_the_pictures_colour() -> None:
    mech = assur.load(EXAMPLES / "slider_crank_exercise.toml")
    page = render_report(mech, [30.0, 60.0])
    assert "#c2185b" not in page
    assert f'fill="{REACTION_COLOUR}"' in page  # the arrowheads
    assert f'"colour":"{REACTION_COLOUR}"' in page  # the arrows, set by the script
    assert "stroke: data.forces.colour" in page
    # its free-body strip is draw_free_body's: the same names
    assert reaction_symbol("crank", "rod") in page


def test_a_rubbing_guide_side_is_its_normal_force() -> None:
    # with friction the polygon draws the guide's normal force and its friction
    # force as two sides, as the note does: F_{ground,slider} (their sum, in the
    # other pictures) named the normal part alone
    table = assur.forces(assur.load(EXAMPLES / "slider_crank_friction.toml"), [45.0])
    fig = plotting.force_polygons(table)
    try:
        texts = {t.get_text(): t for t in fig.axes[0].texts}
        assert reaction_symbol("ground", "slider") not in texts
        for name in ("$\\vec N_{\\text{guide}}$", "$\\vec F_{f,\\text{guide}}$"):
            assert to_hex(texts[name].get_color()) == REACTION_COLOUR
    finally:
        plt.close(fig)
