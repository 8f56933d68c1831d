"""Text outputs print no round-off: the same words on every machine.

The last bits of a result are the machine's arithmetic's (its BLAS kernels, FMA,
the order of the sums). A mechanism whose lengths are scaled by ``1 + 2e-15``, or
a driver position moved by 1e-13 deg, has results that differ in those bits alone:
whatever the text outputs print of it must read the same.
"""

from __future__ import annotations

import re
from pathlib import Path

import matplotlib
import pytest

import assur
from assur._digits import ROUND_OFF
from assur.explain import explain
from assur.plotting import polygons

matplotlib.use("Agg")

DATA = Path(__file__).parent / "data"
EXAMPLES = Path(__file__).parent.parent / "examples"


def scaled(path: Path, factor: float) -> assur.Mechanism:
    """Return the mechanism of ``path`` with its joints and centres ``factor`` apart."""

    def times(found: re.Match[str]) -> str:
        return repr(float(found.group(0)) * factor)

    number = r"-?[\d.]+(?:[eE][-+]?\d+)?"
    text = path.read_text(encoding="utf-8")
    text = re.sub(
        r"(?m)^at = \[[^\]]*\]", lambda m: re.sub(number, times, m.group(0)), text
    )
    text = re.sub(rf"distance = {number}", lambda m: re.sub(number, times, m[0]), text)
    return assur.loads(text)


def variants(path: Path, angle: float) -> list[tuple[assur.Mechanism, float]]:
    """Return the mechanism at ``angle`` and at round-off from it, three ways."""
    mech = assur.load(path)
    return [
        (mech, angle),
        (mech, angle + 1e-13),
        (scaled(path, 1.0 + 2e-15), angle),
        (scaled(path, 1.0 - 3e-15), angle),
    ]


def test_scaled_moves_every_joint() -> None:
    path = DATA / "plans" / "fourbar.toml"
    mech, bigger = assur.load(path), scaled(path, 2.0)
    for joint, twice in zip(mech.joints, bigger.joints, strict=True):
        assert tuple(2.0 * x for x in joint.at) == tuple(twice.at)


@pytest.mark.parametrize(
    ("stem", "angle"), [("fourbar", 90.0), ("inverted", 45.0), ("shaper", 180.0)]
)
def test_a_force_polygon_s_title_closes_alike(stem: str, angle: float) -> None:
    # its gap was written 8.9e-16 mm, or 0.0e+00 mm, or 7.9e-15 mm: round-off
    import matplotlib.pyplot as plt

    titles = set()
    for mech, at in variants(DATA / "plans" / f"{stem}.toml", angle):
        fig = polygons.force_polygons(assur.forces(mech, [at]))
        titles.add(tuple(ax.get_title() for ax in fig.axes))
        plt.close(fig)
    (found,) = titles
    assert all(title.endswith(": the polygon closes") for title in found)


def _newton_words(mech: assur.Mechanism, angle: float) -> list[str]:
    """Return the note's sentences on how Newton's method found the sizes."""
    note = str(explain(mech, angle)).replace("\n", " ")
    return re.findall(r"[^.]*Newton's method on them[^.]*\.", note)


@pytest.mark.parametrize("angle", [0.0, 180.0])
def test_newton_s_steps_at_a_dead_centre_are_counted_alike(angle: float) -> None:
    # the slider at rest: its frictionless normal force is round-off (1.6e-14 N
    # beside 1622 N), and on the side of its sign the analysis solved once or
    # twice: "in 4 steps", or "in 2 steps"
    path = EXAMPLES / "slider_crank_friction.toml"
    said = {tuple(_newton_words(mech, at)) for mech, at in variants(path, angle)}
    (words,) = said
    assert re.search(r"finds the same in \d+ steps?\.", words[0]), words


@pytest.mark.parametrize(
    ("stem", "angle"),
    [("prp_tangent", 0.0), ("prp_tangent", 30.0), ("slot_in_crank", 330.0)],
)
def test_a_slot_s_note_reads_alike(stem: str, angle: float) -> None:
    # a slot's pin carries no couple, "-M_slot = -8.882e-16 N m" or none by
    # machine; the sum of moments about the pin, [0 . 18.78 - 0 . 0] =
    # 5.214e-16 or 0; two slide lines' offset w = (9.714e-17, -1.804e-16) m or
    # (0, 0): round-off, told as round-off
    notes = {
        str(explain(m, at)).split("\n", 1)[1]
        for m, at in variants(DATA / "explain" / f"{stem}.toml", angle)
    }
    (note,) = notes
    assert r"-M_{\mathrm{slot}} = " not in note  # the pin's couple, 0, not written
    assert r"M_{\mathrm{slot}} = -\sum M_{\mathrm{slot}} = 0\ " in note


def test_a_small_couple_s_largest_is_found_alike() -> None:
    # the shaper's slot couple peaks at 240 and 300 deg alike by symmetry,
    # 5.5e-4 N m beside reactions of 2800 N: its round-off, 1e-13 N m, is the
    # reactions', and "slot.M.at" read 240 or 300 by machine
    path = DATA / "plans" / "slotted_lever.toml"
    angles = [float(a) for a in range(360)]
    found = set()
    for mech, _ in variants(path, 0.0):
        summary = assur.forces(mech, angles).summary()
        found.add((summary["slot.M.at"], summary["slot.F.at"]))
    assert len(found) == 1, found


@pytest.mark.parametrize(("stem", "angle"), [("fourbar", 0.0), ("shaper", 180.0)])
def test_the_lever_s_terms_round_alike(stem: str, angle: float) -> None:
    # a share at a decimal tie, 0.009375 N m (written to five decimals), or the
    # block's weight's 0.04905: "+0.00937" or "+0.00938" by the last bit
    import matplotlib.pyplot as plt

    from assur.plotting import lever

    found = set()
    for mech, at in variants(DATA / "plans" / f"{stem}.toml", angle):
        ax = lever.zhukovsky_lever(assur.forces(mech, [at]))
        found.add(tuple(t.get_text() for t in ax.texts if "/ ω" in t.get_text()))
        plt.close(ax.figure)
    assert len(found) == 1, found
    ((terms,),) = found
    assert "sum = balancing load:" in terms


def test_the_lever_s_sum_and_speed_ratios_round_alike() -> None:
    # the sum (to four decimals here) and a couple's speed ratio (to six digits) at
    # a decimal tie were written 1.2344 or 1.2345, 1.23457 or 1.23456, by the
    # last bit, as the shares were
    from types import SimpleNamespace

    import numpy as np

    from assur.plotting.lever import _list_terms

    class Axes:
        transAxes = None  # noqa: N815 (matplotlib's name)

        def __init__(self) -> None:
            self.texts: list[str] = []

        def text(self, x: float, y: float, words: str, **kwargs: object) -> None:
            self.texts.append(words)

    found = set()
    for way in (0.0, 9.0):  # an ulp below each tie, and one above
        balancing = float(np.nextafter(1.23445, way))
        load = SimpleNamespace(couple=1.0, force=(0.0, 0.0))
        term = SimpleNamespace(
            couple=True, omega=float(np.nextafter(1.234565, way)), load=load, body=0
        )
        ax = Axes()
        _list_terms(ax, {0: None}, "R", [("M", 0.5, term)], (1.0, balancing), False)
        found.add(tuple(ax.texts))
    assert len(found) == 1, found
    ((text,),) = found
    assert "= 1.23456; listed only)" in text
    assert "sum = balancing load: 1.2345 N·m" in text


def test_a_polygon_s_gap_is_round_off_of_its_longest_side() -> None:
    # round-off is a share of the sides (3e-8 mm of 60 mm closes, where a gap
    # of one millimetre's share would be an opening); twice that share is open
    longest = 60.0
    assert polygons._closing(0.5 * ROUND_OFF * longest, longest) == "the polygon closes"
    assert polygons._closing(2.0 * ROUND_OFF * longest, longest).startswith(
        "the polygon is open by"
    )
