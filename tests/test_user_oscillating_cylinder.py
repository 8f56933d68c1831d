"""An oscillating cylinder written from the file format: crank and RPR group.

Crank O-A turns; the rod pinned at A slides in a cylinder pivoted on the frame at C,
with a 600 N load on the rod and gravity. Held to the oracle's global solve (with and
without friction), virtual power, finite differences and the note's arithmetic; by
hand, the slide is the change of the distance AC (law of cosines) and a frictionless
slide carries no force along its line.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

import assur

from . import oracle, usercheck

MECH = usercheck.load("oscillating_cylinder")
TURN = usercheck.POSITIONS["oscillating_cylinder"]


def test_slide_is_the_change_of_the_pin_distance():
    o, a, c = (np.asarray(oracle.resolve(MECH, n)) for n in ("O", "A", "C"))
    crank, base = np.hypot(*(a - o)), np.hypot(*(c - o))
    kin = assur.kinematics(MECH, TURN)
    phi = np.radians(TURN)
    distance = np.sqrt(crank**2 + base**2 - 2.0 * crank * base * np.cos(phi))
    # the rod slides toward C (the slide axis points from A to C) as AC shortens
    reference = math.dist(a, c)
    np.testing.assert_allclose(kin["piston.s"], reference - distance, atol=1e-12)


def test_frictionless_slide_pushes_only_across_its_line():
    table = assur.forces(MECH, TURN)
    # the cylinder's axis (C to A) is the slide line
    turn = np.radians(table["cylinder.angle"])
    along = table["piston.Fx"] * np.cos(turn) + table["piston.Fy"] * np.sin(turn)
    scale = float(np.max(np.hypot(table["A.Fx"], table["A.Fy"])))
    np.testing.assert_allclose(along, 0.0, atol=1e-12 * scale)


def _load_lines(mech: assur.Mechanism, link: str) -> list[str]:
    """The note's lines (at 100 deg) that give an external force on ``link``."""
    note = str(assur.explain(mech, 100.0))
    tag = f"\\vec Q_{{\\mathrm{{{link}}},"
    return [line for line in note.splitlines() if line.startswith(f"$$ {tag}")]


def test_note_names_a_load_point_only_where_it_moves_with_the_link():
    # "piston" on the cylinder is the cylinder's point where the piston was in the
    # reference pose: it stays put on the cylinder while the piston slides away
    pushed = assur.Load(link="cylinder", at="piston", force=(300.0, 200.0))
    mech = dataclasses.replace(MECH, loads=(*MECH.loads, pushed))
    (line,) = _load_lines(mech, "cylinder")
    assert "\\mathrm{piston}" not in line
    assert "P_{" in line
    table = assur.forces(mech, [100.0])
    here = f"({table['piston.x'][0]:.4g}"
    assert here not in line
    # the rod's load at its own pin A keeps the pin's name
    (rod_line,) = _load_lines(mech, "rod")
    assert "\\text{at}\\ \\mathrm{A} =" in rod_line
