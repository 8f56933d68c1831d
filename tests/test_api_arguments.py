"""Library arguments of the wrong type or shape: one assur error, never Python's.

Each case was found by calling the public functions with odd arguments (a number
where names are expected, an empty list): a raw TypeError or ZeroDivisionError
came out of the loop over them.
"""

from __future__ import annotations

import numpy as np
import pytest

import assur


@pytest.fixture(scope="module")
def table() -> assur.Table:
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    return assur.forces(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 30.0))


@pytest.mark.parametrize(
    ("draw", "message"),
    [
        (
            lambda t: assur.plotting.plot_motion(t, 5),
            "names: expected a list of link or point names, got int 5",
        ),
        (
            lambda t: assur.plotting.plot_motion(t, [b"rod"]),
            r"names: expected link or point names \(str\), got bytes b'rod'",
        ),
        (
            lambda t: assur.plotting.plot_paths(t, 5),
            "points: expected a list of point names, got int 5",
        ),
        (
            lambda t: assur.plotting.plot_hodographs(t, 5),
            "joints: expected a list of joint names, got int 5",
        ),
        (
            lambda t: assur.plotting.plot_hodographs(t, []),
            "joints: no names; expected at least one joint",
        ),
    ],
)
def test_names_a_picture_cannot_use_are_one_usage_error(table, draw, message):
    import matplotlib.pyplot as plt

    try:
        with pytest.raises(assur.UsageError, match=message):
            draw(table)
    finally:
        plt.close("all")


def test_one_joint_name_is_one_joint_not_its_letters(table):
    import matplotlib.pyplot as plt

    fig = assur.plotting.plot_hodographs(table, "guide")
    try:
        drawn = [ax.get_title().split(":")[0] for ax in fig.axes if ax.axison]
        assert drawn == ["guide"]
    finally:
        plt.close(fig)


@pytest.mark.parametrize(
    ("driver", "message"),
    [
        # the loop over it raised a TypeError
        (5, "driver: expected a list of joint names, got int 5"),
        # bytes were read as numbers: "unknown joint 65"
        (b"A", "driver: expected a list of joint names, got bytes b'A'"),
        ([b"A"], "driver: expected joint names \\(str\\), got bytes b'A'"),
    ],
)
def test_a_driver_that_names_no_joint_is_a_usage_error(driver, message):
    with pytest.raises(assur.UsageError, match=message):
        assur.structure(assur.catalog.four_bar(), driver)


def test_a_zero_dimensional_array_is_no_sequence_of_parts():
    # an array is Iterable, but iterating a 0-d one raised TypeError
    mech = assur.catalog.four_bar()
    with pytest.raises(assur.ModelError, match="links: expected a sequence of Link"):
        assur.Mechanism(np.array(1.0), mech.joints, mech.drivers)


def test_a_four_bar_in_one_line_by_round_off_is_a_model_error():
    # coupler - rocker = crank: the pivot D at 1e-20 m passed the strict test by
    # round-off, and the square root of a negative h^2 raised math's ValueError
    with pytest.raises(assur.ModelError, match="expected the two to reach it"):
        assur.catalog.four_bar(frame=1e-20)


@pytest.mark.parametrize(
    ("angles", "message"),
    [
        # numpy's OverflowError escaped
        ([10**400], "angles: expected real numbers \\(driver positions\\), got object"),
        # taken as numbers by a float conversion, where assur.forces refuses them
        (["30"], "angles: expected real numbers \\(driver positions\\), got text"),
        ([True, False], "angles: expected real numbers .* got True or False"),
    ],
)
def test_a_study_checks_its_angles_as_an_analysis_does(angles, message):
    def factory(crank: float) -> assur.Mechanism:
        return assur.catalog.slider_crank(crank=crank)

    with pytest.raises(assur.UsageError, match=message):
        assur.sweep(factory, {"crank": [0.05]}, angles)


@pytest.fixture(scope="module")
def tables() -> dict[str, object]:
    mech = assur.catalog.slider_crank()
    return {
        "forces": assur.forces(mech, [0.0, 30.0]),
        "dynamics": assur.dynamics(mech, np.arange(0.0, 360.0, 10.0)),
    }


@pytest.mark.parametrize("kind", ["forces", "dynamics"])
@pytest.mark.parametrize(
    ("key", "shown"),
    [
        # the dynamics' table raised TypeError (unhashable) for these
        (["angle"], r"\['angle'\]"),
        (slice(0, 2), "slice"),
        # bytes were told as the list of their numbers, [97, 110, ...]
        (b"angle", "bytes b'angle'"),
    ],
)
def test_a_key_that_is_no_name_is_an_unknown_name(tables, kind, key, shown):
    table = tables[kind]
    message = f"no column .*{shown}.*; expected"
    with pytest.raises(assur.UnknownNameError, match=message):
        table[key]
    assert key not in table


def test_a_study_s_columns_that_are_no_sequence_are_a_usage_error():
    def factory(crank: float) -> assur.Mechanism:
        return assur.catalog.slider_crank(crank=crank)

    study = assur.sweep(factory, {"crank": [0.05]}, [0.0, 90.0])
    # list() of the number raised TypeError; the names checked as assur.forces does
    message = "columns: expected a list of column names, got int 5"
    with pytest.raises(assur.UsageError, match=message):
        study.tables(None, 5)
    with pytest.raises(assur.UsageError, match=r"column names \(str\), got int 5"):
        study.tables(None, [5])
