"""The library as a Python user meets it: arguments out of place, arrays shared.

Each case was found by trying the API as a user would (a review): a clear
UsageError for what is misplaced, and results that no later change of the caller's
arrays, or of another table's, can alter.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import assur

from .conftest import EXAMPLES


def test_a_table_keeps_its_own_copy_of_the_positions():
    # the caller's array was the table's: changing it relabelled every row
    mech = assur.catalog.slider_crank()
    angles = np.arange(0.0, 360.0, 30.0)
    table = assur.forces(mech, angles)
    angles += 90.0
    assert table["angle"][1] == table["crank.angle"][1] == 30.0
    assert (
        table.summary()["A.F.at"]
        == assur.forces(mech, angles - 90.0).summary()["A.F.at"]
    )
    with pytest.raises(ValueError, match="read-only"):
        table.given[0, 0] = 999.0


def test_no_column_can_be_made_writeable_again():
    # a constant column was a view of a cache shared by every table: one table's
    # write reached the next
    mech = assur.catalog.slider_crank()
    table = assur.forces(mech, np.arange(0.0, 360.0, 30.0))
    for name in ("crank.omega", "rod.omega", "B.Fx"):
        with pytest.raises(ValueError, match="WRITEABLE"):
            table[name].flags.writeable = True
    with pytest.raises(ValueError, match="read-only"):
        table.state.motion[2][1][...] = 5.0
    fresh = assur.forces(mech, np.arange(0.0, 360.0, 30.0))
    assert np.all(fresh["crank.omega"] == 200.0)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (
            lambda m: assur.forces(m, [0.0], True),
            "omega: expected real numbers, got True; expected skip_unassembled=",
        ),
        (
            lambda m: assur.forces(m, [0.0], None, False),
            "epsilon: expected real numbers, got False",
        ),
        (lambda m: assur.kinematics(m, True), "angles: expected real numbers .* True"),
        (lambda m: assur.kinematics(m, [0.0], omega=True), "omega: expected real"),
        (
            lambda m: assur.kinematics(m, np.ma.array([0.0, 45.0], mask=[0, 1])),
            "angles: .* a masked array",
        ),
        (
            lambda m: assur.forces("examples/four_bar.toml", [0.0]),
            r"mechanism: expected an assur.Mechanism, got str \(read the file with",
        ),
        (lambda m: assur.structure(None), "mechanism: expected an assur.Mechanism"),
    ],
)
def test_misplaced_arguments_are_one_clear_error(call, message):
    with pytest.raises(assur.UsageError, match=message):
        call(assur.catalog.slider_crank())


def test_model_classes_take_zero_dimensional_arrays():
    assert assur.Driver("A", np.array(200.0)) == assur.Driver("A", 200.0)
    assert assur.Link("crank", mass=np.array(10.0)).mass == 10.0


def test_a_table_is_equal_to_itself_only_and_not_iterable():
    # iteration would read as rows to numpy and pandas, as columns to dict()
    mech = assur.catalog.slider_crank()
    a, b = assur.forces(mech, [0.0, 30.0]), assur.forces(mech, [0.0, 30.0])
    assert a == a
    assert a != b
    assert len({a, b}) == 2
    with pytest.raises(TypeError, match=r"not iterable; expected table\.columns"):
        list(a)


@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: assur.catalog.four_bar(crank=0.5), "four_bar: the coupler .* cannot"),
        (lambda: assur.catalog.four_bar(frame=0.0), "frame: expected a length above"),
        (lambda: assur.catalog.slider_crank(rod=0.01), "the rod .* cannot reach"),
        (lambda: assur.catalog.slider_crank(rod=-0.2), "rod: expected a length"),
        (lambda: assur.catalog.four_bar(crank="0.04"), "crank: expected a finite"),
        (lambda: assur.catalog.four_bar(omega=float("nan")), "omega: expected"),
    ],
)
def test_catalog_dimensions_are_checked(build, message):
    # a rod too short gave "ValueError: math domain error"; a negative one was
    # taken for a positive one
    with pytest.raises(assur.ModelError, match=message):
        build()


def test_a_table_made_with_columns_says_what_a_picture_lacks():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    from assur import plotting

    mech = assur.catalog.slider_crank()
    table = assur.forces(mech, np.arange(0.0, 360.0, 10.0), columns=["driver.torque"])
    assert table.partial
    assert not assur.forces(mech, [0.0]).partial
    for draw in (table.plot, plotting.plot_torque):
        with pytest.raises(KeyError, match=r"was made with columns= .* or no columns="):
            draw(table)
    with pytest.raises(assur.UsageError, match="got Mechanism"):
        plotting.draw(mech)
    kinematic = assur.forces(mech, [0.0, 30.0], columns=["rod.omega"])
    with pytest.raises(assur.UsageError, match="columns= of kinematics only"):
        kinematic.summary()


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"angle": float("nan")}, "angle: expected a finite driver position"),
        ({"angle": "abc"}, "angle: expected a driver position"),
        # too large for a float: a raw OverflowError
        ({"angle": 10**400}, "angle: expected a driver position"),
        ({"angle": 30.0, "forces": True, "scale": -1.0}, "scale: -1.0; expected"),
        ({"angle": 30.0, "forces": True, "scale": 0.0}, "scale: 0.0; expected"),
    ],
)
def test_a_picture_s_options_are_checked(options, message):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    table = assur.forces(assur.catalog.slider_crank(), np.arange(0.0, 360.0, 10.0))
    with pytest.raises(assur.UsageError, match=message):
        table.plot(**options)


def test_one_rate_for_every_driver():
    five = assur.load(
        Path(__file__).parents[1] / "examples" / "five_bar_two_cranks.toml"
    )
    angles = np.array([[60.0, 60.0], [90.0, 80.0]])
    one = assur.forces(five, angles, omega=10.0, epsilon=-2.0)
    each = assur.forces(
        five, angles, omega=np.full((2, 2), 10.0), epsilon=np.full((2, 2), -2.0)
    )
    for name in one.columns:
        np.testing.assert_array_equal(one[name], each[name])


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (lambda m, t: assur.load(None), assur.UsageError, "path: expected the"),
        (lambda m, t: assur.loads(None), assur.UsageError, "text: expected a"),
        (
            lambda m, t: assur.loads(Path("x.toml")),
            assur.UsageError,
            r"got PosixPath \(read a file with assur.load\)|got WindowsPath",
        ),
        (lambda m, t: assur.save(m, None), assur.UsageError, "path: expected"),
        (lambda m, t: assur.dumps(None), assur.UsageError, "expected an assur.Mech"),
        (lambda m, t: t.to_csv(3), assur.UsageError, "expected a CSV file's path"),
        (lambda m, t: t.to_parquet(None), assur.UsageError, "a Parquet file's path"),
    ],
)
def test_files_and_outputs_say_what_they_take(call, error, message):
    mech = assur.catalog.four_bar()
    with pytest.raises(error, match=message):
        call(mech, assur.kinematics(mech, [0.0, 90.0]))


def test_a_file_s_bytes_read_as_its_text():
    mech = assur.catalog.four_bar()
    assert assur.loads(assur.dumps(mech).encode("utf-8")) == mech


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"fps": 0}, "fps: expected a number above 0, got 0"),
        ({"fps": -1.0}, "fps: expected a number above 0"),
        ({"dpi": "x"}, "dpi: expected a number above 0"),
    ],
)
def test_an_animation_s_options_are_checked(tmp_path, options, message):
    pytest.importorskip("matplotlib").use("Agg")
    from assur.plotting import animate

    table = assur.kinematics(assur.catalog.four_bar(), [0.0, 90.0])
    with pytest.raises(assur.UsageError, match=message):
        animate(table, tmp_path / "a.gif", **options)
    with pytest.raises(assur.OutputError, match="cannot write the file"):
        animate(table, tmp_path / "missing" / "a.gif")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"motor": assur.Motor(10.0, -60.0)}, "motor.no_load_speed: .* sign"),
        ({"motor": assur.Motor(10.0, float("nan"))}, "no_load_speed: expected a fin"),
        ({"omega0": None}, "omega0: expected a crank speed"),
        ({"omega0": np.array([1.0, 2.0])}, "omega0: expected a crank speed"),
        ({"turns": 0}, "turns: expected a whole number of turns from 1, got 0"),
        ({"turns": 2.5}, "turns: expected a whole number"),
        # 1e11 turns ran for decades, keeping every turn's samples
        ({"turns": 10**11}, r"turns: 100000000000; expected at most 100000 \("),
    ],
)
def test_a_start_up_s_arguments_are_checked(options, message):
    # a motor turning against its torque ran 2000 turns to "does not settle"
    mech = assur.catalog.slider_crank()
    options = {"motor": assur.Motor(10.0, 60.0), **options}
    with pytest.raises(assur.UsageError, match=message):
        assur.startup(mech, 0.01, **options)


def test_a_reaction_read_first_cannot_be_made_writeable():
    table = assur.forces(assur.catalog.slider_crank(), [0.0, 30.0])
    column = table["B.Fx"]  # the first read: no other column computed before
    with pytest.raises(ValueError, match="WRITEABLE"):
        column.flags.writeable = True


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda m, t: t.motion("3"), "level: expected 0, 1, 2 or 3"),
        (lambda m, t: t.motion(5), "level: expected 0, 1, 2 or 3"),
        (lambda m, t: assur.flywheel(m, "0.02"), "delta: expected a coefficient"),
        (lambda m, t: assur.dynamics(m, [0.0], flywheel=True), "flywheel: expected"),
        (lambda m, t: assur.dynamics(m, [0.0], flywheel="0.5"), "flywheel: expected"),
    ],
)
def test_levels_and_dynamics_arguments_are_checked(call, message):
    mech = assur.catalog.slider_crank()
    with pytest.raises(assur.UsageError, match=message):
        call(mech, assur.forces(mech, np.arange(0.0, 360.0, 30.0)))


def test_a_group_is_named_by_its_number():
    pytest.importorskip("matplotlib").use("Agg")
    from assur.plotting import draw_free_body

    table = assur.forces(assur.catalog.slider_crank(), [30.0])
    for wrong in ("1", True, 1.0):
        with pytest.raises(assur.UsageError, match="group_index: expected a group"):
            draw_free_body(table, wrong)


def test_every_column_stays_read_only():
    # a column computed in a block of others was a read-only view of a writeable
    # array: its flag could be set back
    for n in (12, 9000):  # one pass, and a long table computed slice by slice
        table = assur.forces(assur.catalog.slider_crank(), np.linspace(0, 720, n))
        for name in table.columns:
            with pytest.raises(ValueError, match="WRITEABLE"):
                table[name].flags.writeable = True


def test_a_study_parameter_may_be_called_angle():
    pytest.importorskip("xarray")
    study = assur.sweep(
        lambda angle: assur.catalog.slider_crank(angle=angle),
        {"angle": [40.0, 50.0]},
        [0.0, 90.0],
    )
    assert study.summary["error"].tolist() == ["", ""]
    data = study.tables([1])
    np.testing.assert_array_equal(data["angle"], [50.0])  # the parameter's
    with pytest.raises(assur.UsageError, match="'driver' names a column"):
        assur.sweep(assur.catalog.slider_crank, {"driver": [1.0]}, [0.0])


def test_a_picture_takes_one_row_of_positions():
    pytest.importorskip("matplotlib").use("Agg")
    from assur import plotting

    five = assur.load(
        Path(__file__).parents[1] / "examples" / "five_bar_two_cranks.toml"
    )
    table = assur.kinematics(five, [[60.0, 60.0], [90.0, 80.0]])
    assert plotting._row(table, table.given[1:2]) == 1


@pytest.mark.parametrize(
    ("value", "number"),
    [(0.5, 0.5), (2, 2.0), (np.float32(0.25), 0.25), (np.array(3.0), 3.0)],
)
def test_an_argument_given_as_a_number_is_read_as_one(value, number):
    from assur._vec import real

    assert real(value) == number


@pytest.mark.parametrize("value", [True, "0.5", None, [1.0], 10**400, object()])
def test_anything_else_is_no_number(value):
    from assur._vec import real

    assert real(value) is None


def _with_table(table):  # type: ignore[no-untyped-def]
    mech = assur.catalog.four_bar()
    return dataclasses.replace(mech, loads=(assur.Load("coupler", "B", table),))


@pytest.mark.parametrize(
    ("call", "kind", "message"),
    [
        # the squares of the catalog's geometry overflowed: a raw OverflowError
        (
            lambda: assur.catalog.slider_crank(rod=1e155),
            assur.ModelError,
            "rod: expected a number of magnitude at most 1e+15, got 1e+155",
        ),
        # given answers were not checked: ValueError, TypeError, AttributeError
        (
            lambda: assur.explain(assur.catalog.four_bar(), 45.0, {"C.v": math.nan}),
            assur.UsageError,
            "answers.C.v: expected a finite number, got nan",
        ),
        (
            lambda: assur.explain(assur.catalog.four_bar(), 45.0, [1.0]),
            assur.UsageError,
            "answers: expected a mapping of quantity names to numbers, got list",
        ),
        (
            lambda: assur.explain(assur.catalog.four_bar(), 45.0, {3: 1.0}),
            assur.UsageError,
            "answers: expected quantity names as keys, got 3",
        ),
        # a table's value too large was said to be of the wrong count
        (
            lambda: _with_table(
                assur.LoadTable("driver", (0.0, 360.0), ((1e16, 0.0), (0.0, 0.0)))
            ),
            assur.ModelError,
            "loads[0].force: expected a number of magnitude at most 1e+15, got "
            "1e+16 in [1e+16, 0.0]",
        ),
        (
            lambda: _with_table(
                assur.LoadTable("driver", (0.0, 1e16), ((1.0, 0.0), (0.0, 0.0)))
            ),
            assur.ModelError,
            "loads[0].force.table: expected a number of magnitude at most 1e+15, "
            "got 1e+16 in [0.0, 1e+16]",
        ),
        # AttributeError of a file's name where the mechanism goes
        (
            lambda: assur.mobility("x.toml"),
            assur.UsageError,
            "mechanism: expected an assur.Mechanism, got str (read the file with "
            "assur.load)",
        ),
        (
            lambda: assur.graph(None),
            assur.UsageError,
            "mechanism: expected an assur.Mechanism, got NoneType",
        ),
        # the library's argument was named as the command line's option
        (
            lambda: assur.structure(assur.catalog.four_bar(), driver="Z"),
            assur.DecompositionError,
            "driver: unknown joint 'Z' (joints with the frame: A, D)",
        ),
        # paths a caller reaches that no test had taken (a coverage audit)
        (
            lambda: assur.load("a\0b.toml"),
            assur.ModelError,
            "a\\x00b.toml: cannot read the file (embedded null byte)",
        ),
        (
            lambda: assur.forces(
                assur.catalog.slider_crank(), [45.0], skip_unassembled="yes"
            ),
            assur.UsageError,
            "skip_unassembled: expected True or False, got 'yes'",
        ),
        (
            lambda: dataclasses.replace(assur.catalog.slider_crank(), links="crank"),
            assur.ModelError,
            "links: expected a sequence of Link, got 'crank'",
        ),
        (
            lambda: dataclasses.replace(
                assur.catalog.slider_crank(),
                links=(assur.catalog.slider_crank().links[0], "x"),
            ),
            assur.ModelError,
            "links[1]: expected a Link, got 'x'",
        ),
        (
            lambda: assur.forces(assur.catalog.slider_crank(), [[1, 2], [3]]),
            assur.UsageError,
            "angles: expected real numbers (driver positions), got list",
        ),
        (
            lambda: assur.forces(assur.catalog.slider_crank(), object()),
            assur.UsageError,
            "angles: expected real numbers (driver positions), got object values",
        ),
    ],
)
def test_the_library_says_what_is_wrong_in_one_line(call, kind, message):
    with pytest.raises(kind) as caught:
        call()
    assert str(caught.value) == message


def test_a_table_s_repr_is_a_line() -> None:
    # a two-row table's repr spelt out every state array: 19 583 characters
    table = assur.forces(assur.catalog.slider_crank(), [0.0, 90.0])
    assert repr(table) == (
        "<assur.Table: forces of 'Slider-crank exercise', 2 rows x 109 columns>"
    )
    kinematics = assur.kinematics(assur.catalog.four_bar(), np.arange(72.0))
    assert repr(kinematics).startswith("<assur.Table: kinematics of ")
    assert repr(kinematics).endswith(", 72 rows x 83 columns>")
    one = assur.kinematics(assur.catalog.four_bar(), [0.0])
    assert repr(one).endswith(", 1 row x 83 columns>")
    # a table of the driver's position alone: one column, as its caption says
    alone = assur.kinematics(assur.catalog.four_bar(), [0.0, 5.0], columns=[])
    assert alone.columns == ("angle",)
    assert repr(alone).endswith(", 2 rows x 1 column>")
    # the dynamics table: its figures, not its mechanism and columns
    whitworth = assur.load(EXAMPLES / "whitworth.toml")
    dynamics = assur.dynamics(whitworth, [0.0], flywheel=20.0)
    assert repr(dynamics).startswith("Dynamics(omega=5.0, delta=")
    assert len(repr(dynamics)) < 400


def test_a_file_s_name_given_as_its_text_is_told() -> None:
    # "not valid TOML: Expected '=' after a key" for loads("examples/x.toml")
    with pytest.raises(assur.UsageError, match=r"is a file's name; .*assur\.load"):
        assur.loads("examples/slider_crank_exercise.toml")
    with pytest.raises(assur.UsageError, match=r"is a file's name"):
        assur.loads("m.JSON\n")
    # the text of a file is read, whatever it ends with
    text = (EXAMPLES / "four_bar.toml").read_text(
        encoding="utf-8"
    ) + "\n# see four_bar.toml"
    assert assur.loads(text).name == "Crank-rocker four-bar"


def test_a_start_up_s_and_a_study_s_repr_are_their_figures() -> None:
    # the start-up's repr spelt out its mechanism (1200 characters), the study's
    # every parameter value and angle
    mech = assur.catalog.slider_crank()
    run = assur.startup(mech, 0.05, motor=assur.Motor(20.0, no_load_speed=250.0))
    assert repr(run).startswith("Startup(motor=Motor(torque=20.0, no_load_speed=250.0)")
    assert "Mechanism" not in repr(run)
    assert len(repr(run)) < 300
    study = assur.sweep(
        assur.catalog.slider_crank, {"rod": [0.2, 0.25, 0.01]}, range(0, 360, 10)
    )
    assert repr(study) == (
        "<assur.Study: 3 variants of rod, 36 positions each, 1 failed>"
    )


@pytest.mark.parametrize(
    ("name", "given", "expected"),
    [
        ("plot_motion", "dynamics", "a table of assur.kinematics or assur.forces"),
        ("plot_paths", "dynamics", "a table of assur.kinematics or assur.forces"),
        ("plot_speed", "forces", "the result of assur.dynamics, got Table"),
        ("plot_reduced_inertia", "forces", "the result of assur.dynamics"),
        ("plot_reduced_torque", "forces", "the result of assur.dynamics"),
        ("plot_energy_mass", "mechanism", "the result of assur.dynamics"),
        ("plot_dynamics", "forces", "the result of assur.dynamics"),
        ("plot_startup", "dynamics", "the result of assur.startup, got Dynamics"),
    ],
)
def test_a_picture_of_the_wrong_result_is_one_usage_error(name, given, expected):
    # an AttributeError, a KeyError or a TypeError from deep inside, before
    import assur.plotting

    mech = assur.catalog.slider_crank()
    results = {
        "mechanism": lambda: mech,
        "forces": lambda: assur.forces(mech, [0.0, 90.0]),
        "dynamics": lambda: assur.dynamics(mech, [0.0, 90.0]),
    }
    with pytest.raises(assur.UsageError, match=f"expected {expected}"):
        getattr(assur.plotting, name)(results[given]())


def test_a_picture_of_a_table_with_no_rows_is_one_usage_error() -> None:
    # numpy's "zero-size array to reduction operation fmin" came out of the drawing
    import assur.plotting

    mech = assur.load(
        Path(__file__).parent / "data" / "edge" / "shaper_two_groups_fail.toml"
    )
    empty = assur.kinematics(mech, [250.0, 260.0], skip_unassembled=True)
    assert len(empty) == 0
    for draw in (
        assur.plotting.draw,
        assur.plotting.plot_motion,
        assur.plotting.plot_paths,
    ):
        with pytest.raises(
            assur.UsageError,
            match=r"the table has no rows \(every position was left out\); expected "
            "at least one to draw",
        ):
            draw(empty)


@pytest.mark.parametrize("copy_of", ["pickle", "deepcopy"])
def test_a_copied_table_keeps_its_arrays_read_only(copy_of):
    # numpy unpickles an array writeable: a column read before pickling, once
    # written to in the copy, changed its summary (84.6 N m read 0)
    import copy
    import pickle

    def copied(x):
        if copy_of == "pickle":
            return pickle.loads(pickle.dumps(x))
        return copy.deepcopy(x)

    mech = assur.catalog.slider_crank()
    table = assur.forces(mech, [45.0, 90.0])
    torque, _ = table["driver.torque"], table.state
    again = copied(table)
    for values in (
        again["driver.torque"],
        again["B.Fx"],
        again.given,
        again.skipped,
        again.state.drive,
    ):
        with pytest.raises(ValueError, match="read-only"):
            values[...] = 0.0
    np.testing.assert_array_equal(again["driver.torque"], torque)
    dynamics = copied(assur.dynamics(mech, [0.0, 90.0]))
    with pytest.raises(ValueError, match="read-only"):
        dynamics["driver.omega"][0] = 0.0


@pytest.mark.parametrize(
    ("call", "message"),
    [
        # the plan's cache hashed it first: "unhashable type: 'dict'"
        (lambda m: assur.forces({}, [0.0]), "mechanism: expected an assur.Mechanism"),
        (lambda m: assur.kinematics([], [0.0]), "got list"),
        # TypeError: 'int' object is not iterable
        (lambda m: assur.forces(m, [0.0], columns=5), "expected a list of column"),
        (lambda m: assur.forces(m, [0.0], columns=[None]), r"\(str\), got NoneType"),
        (lambda m: assur.forces(m, [0.0], columns=[b"B.Fx"]), "got bytes b'B.Fx'"),
        # the name but for its case, not the nearer 'B.x'
        (lambda m: assur.forces(m, [0.0], columns=["B.fx"]), "did you mean 'B.Fx'"),
        # AttributeError: 'str' object has no attribute 'plot'
        (lambda m: _drawn(m, "x"), "ax: expected matplotlib axes.*got str"),
        # "toml" is true: the text was read as JSON
        (lambda m: assur.loads(assur.dumps(m), "toml"), "json_format: expected True"),
        (lambda m: assur.dumps(m, "json"), "json_format: expected True or False"),
        # nothing shown, and no word: skip_unassembled="no" is refused
        (lambda m: assur.forces(m, [0.0], progress="yes"), "progress: expected True"),
        (
            lambda m: assur.startup(m, motor=assur.Motor(50.0), progress=None),
            "progress: expected True",
        ),
        # the callback's own TypeError came from the first report, inside the sweep
        (
            lambda m: assur.forces(m, [0.0], progress=lambda: None),
            r"progress: expected a callable of two arguments \(done, total\), got "
            r"<lambda>\(\) \(too many positional arguments\)",
        ),
        (
            lambda m: assur.forces(m, [0.0], progress=lambda done: None),
            r"got <lambda>\(done\)",
        ),
    ],
)
def test_arguments_out_of_place_are_usage_errors(call, message):
    with pytest.raises(assur.UsageError, match=message):
        call(assur.catalog.slider_crank())


def _drawn(mech: assur.Mechanism, ax: object) -> None:
    import assur.plotting

    assur.plotting.draw(assur.forces(mech, [0.0]), ax=ax)


def test_a_note_s_repr_is_short():
    # it printed every block of the note: some 21 000 characters
    note = assur.explain(assur.catalog.slider_crank(), 45.0)
    shown = repr(note)
    assert shown.startswith("Note('Slider-crank exercise at crank angle 45 deg")
    assert shown.endswith(f"{len(note.blocks)} blocks, {len(note.values)} values)")
    assert len(shown) < 200


def test_messages_of_python_built_entries_and_notes_read_plainly():
    import assur.plotting

    mech = assur.catalog.slider_crank()
    joint = dataclasses.replace(mech.joints[0], name=None)
    # it read "joints.a value of type NoneType: ..."
    with pytest.raises(
        assur.ModelError,
        match=r"^joints\.\(a value of type NoneType\): expected a non-empty name",
    ):
        dataclasses.replace(mech, joints=(joint, *mech.joints[1:]))
    note = assur.explain(mech, 45.0)
    # "unknown type of note '(none)'"
    with pytest.raises(assur.UsageError, match=r"^docx: no suffix; expected a name"):
        note.render("docx")
    # the point's 'x' was listed twice, as a column and as a quantity
    table = assur.forces(mech, [0.0, 45.0])
    with pytest.raises(assur.UnknownNameError) as caught:
        assur.plotting.plot_motion(table, ["B"], "speed")
    said = str(caught.value).split("; expected ")[1].strip("'\"")
    listed = said.replace(" or ", ", ").split(", ")
    assert sorted(listed) == sorted(set(listed))
    assert {"x", "v", "vx"} <= set(listed)
