"""The note's words and the plans' legend where a term is nothing or a sign matters.

Checked on the bundled Whitworth mechanism (its block's pin is the slot's point), the
Scotch yoke (an RPP dyad) and the lecture's slider-crank (no Coriolis term).
"""

from __future__ import annotations

import re

import numpy as np
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
    # the slot's point is the block's pin B, summed along the lever's side from
    # the lever's point under it, B_lever
    assert (
        r"\vec v_{\mathrm{B}} = \vec v_{\mathrm{O4}} + "
        r"\vec v_{\mathrm{B}_{\mathrm{lever}}\mathrm{O4}} + "
        r"\vec v^{r}_{\mathrm{slot}} = "
    ) in note
    # the lever's arm is kept: O4 is not at the slot's point, B
    assert r"l_{\mathrm{O4}\mathrm{B}}" in note


def test_the_rpr_position_says_the_pins_stay_apart_across_the_slide() -> None:
    """c0 = n0 . (r_B - r_O4) is the pins' distance across the slide line; the note
    said it was the line's distance from the block's pin."""
    note = str(explain(assur.load(EXAMPLES / "whitworth.toml"), 100.0))
    assert "the pins O4 and B stay $c_0 = " in note
    assert "from the pin of" not in note


@pytest.mark.parametrize("swapped", [False, True], ids=["yoke-block", "block-yoke"])
def test_the_rpp_slide_is_written_with_its_sign(swapped: bool, tmp_path) -> None:
    """s = -r0 / (+-n.e) never said which sign. The sign written, times n.e of the
    vectors written, is the denominator written; s is the yoke's slide, both ways
    round of the slot's links (which turn n over)."""
    text = (EXAMPLES / "scotch_yoke.toml").read_text(encoding="utf-8")
    if swapped:
        text = text.replace('links = ["yoke", "block"]', 'links = ["block", "yoke"]')
        assert 'links = ["block", "yoke"]' in text
    path = tmp_path / "yoke.toml"
    path.write_text(text, encoding="utf-8")
    mech = assur.load(path)
    note = str(explain(mech, 100.0))
    assert r"\pm" not in note
    (words,) = [x for x in note.splitlines() if "must bring the pair slot" in x]
    e, n = (
        np.array([float(v) for v in re.search(rf"\\vec {x} = \(([^)]*)\)", words)
                  .group(1).replace("\\", "").split(",")])
        for x in ("e", "n")
    )  # fmt: skip
    (line,) = [x for x in note.splitlines() if r"s = -\frac{r_0}" in x]
    sign = -1.0 if r"{-\vec n \cdot \vec e}" in line else 1.0
    assert sign == 1.0 or r"{\vec n \cdot \vec e}" not in line
    r0, ne, slide = (float(v) for v in re.findall(r"-?\d+\.?\d*", line)[-3:])
    assert ne == pytest.approx(sign * float(np.dot(n, e)), abs=1e-4)
    assert -r0 / ne == pytest.approx(slide, rel=1e-3)
    slid = assur.kinematics(mech, [100.0])["guide.s"][0]
    assert slide == pytest.approx(slid, rel=1e-3)


def _legend(stem: str, angle: float) -> list[str]:
    import matplotlib.pyplot as plt

    from assur.explain._solve import table_at
    from assur.plotting import plans

    ax = plans.acceleration_plan(table_at(assur.load(EXAMPLES / f"{stem}.toml"), angle))
    legend = ax.get_legend()
    texts = [t.get_text() for t in legend.get_texts()] if legend else []
    plt.close(ax.figure)
    return texts


def test_the_acceleration_plan_s_legend_names_the_parts_drawn() -> None:
    """A slider on the frame has no Coriolis term, and none is drawn: the legend
    named it."""
    assert not any("Coriolis" in t for t in _legend("slider_crank_exercise", 45.0))
    # the Whitworth block slides on a turning lever: its Coriolis term is drawn
    assert any("Coriolis" in t for t in _legend("whitworth", 100.0))
