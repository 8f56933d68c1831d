"""Checks shared by the tests of the users' mechanisms (tests/data/users).

Each mechanism file there was written from the file format alone, as a user writes
one; these checks hold it to tests/oracle.py's independent computations: the global
Newton-Euler solve (without and with friction), virtual power, finite differences of
positions, and the explanatory note's arithmetic and result.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np

import assur

from . import oracle
from .notearith import pieces_checked

USERS = Path(__file__).parent / "data" / "users"
RTOL = 1e-9
POSITIONS = {
    "oscillating_cylinder": np.arange(30.0, 390.0, 11.0),  # deg: a turn
    "stephenson_six_bar": np.arange(60.0, 420.0, 13.0),
    "trammel_slider_driven": np.linspace(-0.06, 0.06, 13),  # m: the slider's stroke
    "wedge_lifter": np.linspace(-0.02, 0.03, 6),
}
"""Each mechanism's driver positions the shared checks run at."""
NOTED = {
    "oscillating_cylinder": (100.0, 250.0),
    "stephenson_six_bar": (100.0, 250.0),
    "trammel_slider_driven": (-0.05, 0.04),
    "wedge_lifter": (-0.02, 0.03),
}
"""The positions each mechanism's note is checked at."""


def load(name: str) -> assur.Mechanism:
    """The mechanism ``tests/data/users/<name>.toml``."""
    return assur.load(USERS / f"{name}.toml")


def rubbing(mech: assur.Mechanism) -> assur.Mechanism:
    """``mech`` with friction in every joint: f = 0.08 on 10 mm journals, f = 0.1 on
    slides."""
    joints = tuple(
        dataclasses.replace(j, friction=0.08, radius=0.01)
        if j.kind == "revolute"
        else dataclasses.replace(j, friction=0.1)
        for j in mech.joints
    )
    return dataclasses.replace(mech, joints=joints)


def assert_global_solve(mech: assur.Mechanism, positions: np.ndarray) -> None:
    """Reactions and balancing load equal the global solve's, without and with
    friction."""
    table = assur.forces(mech, positions)
    force, size = oracle.load_scale(mech, table)
    got = oracle.table_reactions(mech, table)
    oracle.assert_same_reactions(
        mech, got, oracle.global_solve(mech, table), RTOL, force, size
    )
    rough = rubbing(mech)
    table = assur.forces(rough, positions)
    force, size = oracle.load_scale(rough, table)
    expected, _ = oracle.global_solve_friction(rough, table)
    got = oracle.table_reactions(rough, table)
    oracle.assert_same_reactions(rough, got, expected, RTOL, force, size)


def assert_virtual_power(mech: assur.Mechanism, positions: np.ndarray) -> None:
    """The driver's power is minus the power of every other load, inertia included."""
    table = assur.forces(mech, positions)
    powers = oracle.applied_loads(mech, table).power
    loads = np.sum([powers[link.name] for link in mech.links], axis=0)
    driver = oracle.balancing_column(mech, table, 0) * mech.drivers[0].omega
    scale = float(np.max(np.abs(driver)))
    np.testing.assert_allclose(driver, -loads, rtol=0, atol=RTOL * scale)


def assert_kinematics(mech: assur.Mechanism, positions: np.ndarray) -> None:
    """Rigid links, points on their slide lines, derivatives equal to differences."""
    table = assur.kinematics(mech, positions)
    oracle.assert_rigid(mech, table)
    oracle.assert_slides(mech, table)
    oracle.assert_differences(mech, oracle.si(mech, positions))


def assert_note(mech: assur.Mechanism, position: float) -> None:
    """The note's equations hold as printed and it ends on the table's balancing
    load."""
    text = str(assur.explain(mech, position))
    checked, bad = pieces_checked(text)
    assert checked > 20
    assert not bad, bad
    printed = re.findall(r"So \$[MF]_\{b\} = (-?[\d.]+(?:e[-+]?\d+)?)", text)
    table = assur.forces(mech, [position])
    expected = oracle.balancing_column(mech, table, 0)[0]
    assert len(printed) == 1
    np.testing.assert_allclose(float(printed[0]), expected, rtol=5e-4)
