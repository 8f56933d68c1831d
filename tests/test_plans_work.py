"""The work ``assur plans`` takes grows with what it draws, not faster.

A long chain of dyads (``tests/test_long_chains.py``'s) has one force polygon per
group and many symbols: the figure of the polygons is laid out once for all of
them, not once per polygon, and each symbol is checked once. The places chosen
are those the former work chose, the axes where it put them to round-off.
"""

from __future__ import annotations

import matplotlib
import numpy as np

import assur
from assur.plotting import _bars, _mathtext, polygons

from .test_long_chains import chain

matplotlib.use("Agg")


def _name_places(fig) -> list[tuple[str, tuple[float, float]]]:
    """Return every name of ``fig``'s axes with where it is put (its offset)."""
    return [
        (t.get_text(), tuple(np.round(getattr(t, "xyann", t.get_position()), 12)))
        for ax in fig.axes
        for t in ax.texts
    ]


def test_the_force_polygons_are_laid_out_once_for_every_group(monkeypatch) -> None:
    import matplotlib.pyplot as plt

    table = assur.forces(chain(4), [30.0])
    settled = _bars.settled_renderer
    calls = []

    def counted(ax):
        calls.append(ax)
        return settled(ax)

    monkeypatch.setattr(_bars, "settled_renderer", counted)
    fig = polygons.force_polygons(table)
    try:
        assert len(fig.axes) == 4
        assert len(calls) == 1
        once = _name_places(fig)
        laid = [ax.get_position().bounds for ax in fig.axes]
    finally:
        plt.close(fig)
    # as the figure laid out again before each polygon's names put them
    monkeypatch.setattr(polygons, "keys_clear", lambda axes, texts, widen: None)
    fig = polygons.force_polygons(table)
    try:
        assert len(calls) == 5
        assert _name_places(fig) == once
        # each layout run moves the axes by round-off only (1e-16 of the figure)
        again = [ax.get_position().bounds for ax in fig.axes]
        np.testing.assert_allclose(again, laid, rtol=0.0, atol=1e-12)
    finally:
        plt.close(fig)


def test_a_symbol_is_checked_once_however_often_it_is_asked_for(monkeypatch) -> None:
    parser = _mathtext._parser()
    parses = []

    class Counted:
        def parse(self, text, dpi):
            parses.append(text)
            return parser.parse(text, dpi)

    _mathtext._symbol.cache_clear()
    monkeypatch.setattr(_mathtext, "_parser", Counted)
    first = _mathtext.reaction_symbol("u7", "v7")
    assert _mathtext.reaction_symbol("u7", "v7") == first
    assert _mathtext.centre_symbol("v7", "u7") != first
    assert _mathtext.centre_symbol("v7", "u7") == _mathtext.centre_symbol("v7", "u7")
    assert len(parses) == 2
    # a symbol mathtext cannot set is written plain, the second time too
    plain = _mathtext._symbol("\\frac{")
    assert _mathtext._symbol("\\frac{") == plain
    assert "$" not in plain
    assert len(parses) == 3
