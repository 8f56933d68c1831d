"""A watch-sized and a kilometre-sized mechanism are told as the metre-sized one is.

The slider-crank exercise with every length times ``s``, every mass times ``s**3``
and every moment of inertia times ``s**5`` (one material, one crank speed) is a
similarity: positions go with ``s``, angles stay, forces go with ``s**4`` and
moments with ``s**5``. What the note says, which loads a picture draws and which
shares of Zhukovsky's lever are nonzero must then not change with ``s``; a
threshold in newtons or newton-metres rather than relative to the loads at play
broke that at one end.
"""

from __future__ import annotations

import dataclasses
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur.explain import explain

from .mechanisms import moved

EXAMPLES = Path(__file__).parent.parent / "examples"
ANGLE = 30.0


def _sized(
    scale: float, stem: str = "slider_crank_exercise", angle: float = ANGLE
) -> assur.Table:
    """Return the forces at ``angle`` (deg) of example ``stem`` at ``scale`` (see
    above), without its loads and gravity (inertia loads alone)."""
    mech = moved(assur.load(EXAMPLES / f"{stem}.toml"), scale=scale)
    mech = dataclasses.replace(mech, loads=(), gravity=None)
    # moved() keeps the masses and scales inertias by scale**2: one material
    heavy = tuple(
        dataclasses.replace(
            link,
            mass=None if link.mass is None else link.mass * scale**3,
            inertia=None if link.inertia is None else link.inertia * scale**3,
        )
        for link in mech.links
    )
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "joints: the mechanism", assur.AssurWarning)
        return assur.forces(dataclasses.replace(mech, links=heavy), [angle])


def test_the_similarity_holds() -> None:
    # the premise of the tests below: forces by s**4, the balancing torque by s**5
    full, small = _sized(1.0), _sized(1e-3)
    np.testing.assert_allclose(small["guide.Fy"], 1e-12 * full["guide.Fy"], rtol=1e-9)
    np.testing.assert_allclose(
        small["driver.torque"], 1e-15 * full["driver.torque"], rtol=1e-9
    )


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_the_note_says_the_guide_is_pressed_at_any_size(scale: float) -> None:
    # a watch's guide, pressed by 4e-10 N, was said to carry no load: round-off
    # was told from 1e-9 N, not from the loads at play
    table = _sized(scale)
    assert abs(float(table["guide.Fy"][0])) > 0.0
    note = str(explain(table.mechanism, ANGLE))
    full = str(explain(_sized(1.0).mechanism, ANGLE))
    acts = "the normal force $N_{\\mathrm{guide}}$ then acts"
    assert acts in full
    assert acts in note
    assert "the guide carries no load" not in note
    assert "x_{\\mathrm{guide}} = \\frac" in note


def _lever_lines(scale: float) -> list[str]:
    """Return the lines of Zhukovsky's lever's list of shares at ``scale``."""
    import matplotlib.pyplot as plt

    from assur.plotting import lever

    ax = lever.zhukovsky_lever(_sized(scale))
    try:
        (text,) = [t.get_text() for t in ax.texts if "/ ω" in t.get_text()]
    finally:
        plt.close(ax.figure)
    return text.splitlines()


@pytest.mark.parametrize(("scale", "power"), [(1e-3, -15), (1e3, 15)])
def test_the_lever_s_shares_keep_their_digits_at_any_size(
    scale: float, power: int
) -> None:
    # a watch's shares (1e-13 N m) were all written 0 and their sum "0 N m"; a
    # kilometre crank's were written with seventeen digits, "+32400393553600000.0"
    full, sized = _lever_lines(1.0), _lever_lines(scale)
    unit = f"$10^{{{power}}}$ N·m"
    assert full[1].endswith("), N·m:")
    assert sized[1].endswith(f"), {unit}:")
    # the shares and their sum read alike, in that power of ten
    assert [line.rsplit(":  ", 1)[-1] for line in sized[2:-1]] == [
        line.rsplit(":  ", 1)[-1] for line in full[2:-1]
    ]
    (total,) = re.findall(r"load: (\S+) N·m$", full[-1])
    assert float(total) != 0.0
    assert sized[-1] == f"sum = balancing load: {total} × {unit}"


@pytest.mark.parametrize("scale", [1e-3, 1e3])
@pytest.mark.parametrize(
    ("stem", "angle"), [("slider_crank_exercise", ANGLE), ("whitworth", 100.0)]
)
def test_the_picture_draws_the_couples_at_any_size(
    scale: float, stem: str, angle: float
) -> None:
    import matplotlib.pyplot as plt

    from assur.plotting import mechanism

    # a watch's balancing torque (9e-14 N m) and the rod's inertia torque were
    # not drawn: a couple below 1e-9 N m was taken for round-off; and the
    # Whitworth lever's slot, pressed by 1e-10 N, was drawn as a couple beside
    # its force, as if that force were round-off
    def names(table: assur.Table) -> list[str]:
        ax = mechanism.draw(table, forces=True)
        try:
            return sorted(t.get_text().split(" = ")[0] for t in ax.texts)
        finally:
            plt.close(ax.figure)

    full = names(_sized(1.0, stem, angle))
    assert any(name.startswith("$M_") for name in full)
    assert names(_sized(scale, stem, angle)) == full
