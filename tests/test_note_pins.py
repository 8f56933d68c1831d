"""The note's words where a pair's point is a pin, and where a slide's sign matters.

Checked on the bundled Whitworth mechanism (its block's pin is the slot's point) and
the Scotch yoke (an RPP dyad).
"""

from __future__ import annotations

import re

import pytest

import assur
from assur.explain import explain

from .conftest import EXAMPLES


def test_a_block_pinned_at_its_sliding_point_has_no_arm_to_its_pin() -> None:
    """The Whitworth block's pin B is the slot's point: the note wrote v_slotB
    perpendicular to B slot, from slot to B and l_Bslot = 0, for terms of nothing."""
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 100.0))
    block = r"\mathrm{slot}\mathrm{B}"
    assert block not in note
    assert r"l_{\mathrm{B}\mathrm{slot}}" not in note
    # the joint moves as the pin does
    assert r"$$ \vec v_{\mathrm{B}} = \vec v_{\mathrm{O4}} + " in note
    assert r"\vec v_{\mathrm{slot}} = \vec v_{\mathrm{B}} = " in note
    # the lever's arm is kept: O4 is not at the slot's point
    assert r"l_{\mathrm{O4}\mathrm{slot}}" in note


def test_the_rpr_position_says_the_pins_stay_apart_across_the_slide() -> None:
    """c0 = n0 . (r_B - r_O4) is the pins' distance across the slide line; the note
    said it was the line's distance from the block's pin."""
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 100.0))
    assert "the pins O4 and B stay $c_0 = " in note
    assert "from the pin of" not in note


def test_the_rpp_slide_is_written_with_its_sign() -> None:
    """s = -r0 / (+-n.e) never said which sign: the one of the pair at hand."""
    note = str(explain(assur.load(EXAMPLES / "scotch_yoke.toml"), 100.0))
    assert r"\pm" not in note
    (line,) = [x for x in note.splitlines() if r"s = -\frac{r_0}" in x]
    r0, ne, s = (float(v) for v in re.findall(r"-?\d+\.?\d*(?:e-?\d+)?", line)[-3:])
    assert -r0 / ne == pytest.approx(s, rel=1e-3)
