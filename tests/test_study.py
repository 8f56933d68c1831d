"""Studies: ``assur.sweep`` against separate ``assur.forces(...).summary()`` calls.

A study solves the variants of one topology in one batch; each variant's summary
must be the one a separate call gives (to 1e-12, relative to the size of the
quantity), and a variant that cannot be built or analysed must be marked with the
error a separate call raises. The same through a dask LocalCluster of two processes.
"""

from __future__ import annotations

import dataclasses
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import assur
from assur import catalog

from .conftest import EXAMPLES, local_client

pytest.importorskip("pandas")

ANGLES = np.arange(0.0, 360.0, 3.0) + 45.0

# rods: assembles; assembles at 45 deg but not at 90 (shorter than the crank);
# cannot be built (shorter than the crank pin's height at 45 deg); near a dead
# centre (a warning); and long ones
CRANKS = [0.074, 0.074, 0.074, 0.074, 0.050, 0.090, 0.060]
RODS = [0.200, 0.060, 0.040, 0.07402, 0.150, 0.300, 0.190]


def mixed(kind: float, crank: float, rod: float) -> assur.Mechanism:
    """A slider-crank (kind 0) or a four-bar (kind 1): two topologies in one study."""
    if kind:
        return catalog.four_bar(crank=crank / 2, coupler=rod / 2 + 0.05)
    return catalog.slider_crank(crank=crank, rod=rod)


def separate(factory, parameters, angles):
    """Each variant's summary from a call of its own, or its error as one line."""
    out = []
    names = list(parameters)
    for values in zip(*parameters.values(), strict=True):
        p = dict(zip(names, map(float, values), strict=True))
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", assur.AssurWarning)
                out.append(assur.forces(factory(**p), angles).summary())
        except (assur.AssurError, ValueError) as err:
            out.append(f"{type(err).__name__}: {' '.join(str(err).split())}")
    return out


def scale(summary: dict[str, float], name: str) -> float:
    """The size of a summary value: a mean that cancels over a cycle is measured
    against the RMS of the same quantity (the driver's power against its torque's
    RMS times the speed)."""
    if name == "driver.power.mean":
        return summary["driver.torque.rms"] * 200.0
    if name.endswith(".mean"):
        return summary[name[: -len("mean")] + "rms"]
    return abs(summary[name])


def assert_agrees(frame, expected):
    assert len(frame) == len(expected)
    for i, want in enumerate(expected):
        row = frame.iloc[i]
        if isinstance(want, str):
            assert row["error"] == want
            continue
        assert row["error"] == ""
        for name, value in want.items():
            got = row[name]
            assert abs(got - value) <= 1e-12 * scale(want, name), (i, name, got, value)


@pytest.fixture(scope="module")
def slider_study():
    parameters = {"crank": CRANKS, "rod": RODS}
    return parameters, assur.sweep(catalog.slider_crank, parameters, ANGLES)


def test_sweep_equals_separate_calls(slider_study):
    parameters, study = slider_study
    assert_agrees(study.summary, separate(catalog.slider_crank, parameters, ANGLES))


def test_unassemblable_variants_are_marked(slider_study):
    _, study = slider_study
    errors = study.summary["error"].tolist()
    assert errors[1].startswith("AssemblyError: group RRP (rod, slider): cannot be")
    assert errors[2] == (
        "ModelError: slider_crank: the rod (0.04 m) cannot reach the slide line "
        "0.0523259 m from the crank's pin at 45 deg; expected a longer rod"
    )
    assert [i for i, e in enumerate(errors) if e] == [1, 2]
    assert np.isnan(study.summary["A.F.max"].iloc[1])


def test_a_warning_is_kept_with_the_variant(slider_study):
    _, study = slider_study
    warned = study.summary["warning"].tolist()
    assert "near a dead centre" in warned[3]
    assert not warned[0]


def test_summary_has_the_parameters_and_the_summary_names(slider_study):
    _, study = slider_study
    frame = study.summary
    one = assur.forces(catalog.slider_crank(), ANGLES).summary()
    assert list(frame.columns) == ["crank", "rod", *one, "error", "warning"]
    np.testing.assert_array_equal(frame["rod"], RODS)
    assert frame.index.name == "variant"


def test_variants_of_two_topologies_are_grouped():
    parameters = {
        "kind": [0, 1, 0, 1, 1, 0],
        "crank": [0.074, 0.08, 0.06, 0.07, 0.09, 0.074],
        "rod": [0.2, 0.14, 0.16, 0.15, 0.16, 0.06],
    }
    study = assur.sweep(mixed, parameters, ANGLES)
    assert_agrees(study.summary, separate(mixed, parameters, ANGLES))
    # a four-bar has joint D, a slider-crank has none: NaN there
    assert np.isnan(study.summary["D.F.max"].iloc[0])
    assert np.isfinite(study.summary["D.F.max"].iloc[1])


def test_many_variants_run_in_several_batches():
    rng = np.random.default_rng(7)
    count = 130  # more than one batch of 8192 positions at 120 positions each
    parameters = {
        "crank": rng.uniform(0.05, 0.09, count),
        "rod": rng.uniform(0.05, 0.3, count),
    }
    study = assur.sweep(catalog.slider_crank, parameters, ANGLES)
    expected = separate(catalog.slider_crank, parameters, ANGLES)
    assert_agrees(study.summary, expected)
    assert any(isinstance(e, str) for e in expected)


def test_tables_give_every_column_of_chosen_variants(slider_study):
    pytest.importorskip("xarray")
    _, study = slider_study
    data = study.tables(variants=[0, 1, 6])
    values = data["values"]
    assert values.dims == ("variant", "position", "column")
    table = assur.forces(catalog.slider_crank(crank=0.06, rod=0.19), ANGLES)
    column = list(data["column"].values).index("B.F")
    np.testing.assert_array_equal(values[2, :, column], table["B.F"])
    assert np.isnan(values[1]).all()  # the variant that does not assemble
    np.testing.assert_array_equal(data["rod"], [0.2, 0.06, 0.19])


@pytest.mark.parametrize(
    ("parameters", "message"),
    [
        ({}, "parameters: expected a mapping of names to 1-D arrays"),
        ([0.2], "parameters: expected a mapping of names to 1-D arrays"),
        ({"rod": [[0.2]]}, r"parameters.rod: expected a 1-D array .* shape \(1, 1\)"),
        ({"rod": ["a"]}, "parameters.rod: expected a 1-D array of real numbers, got"),
        # an empty array is 1-D: what it lacks is a variant
        ({"rod": []}, r"^parameters.rod: no values; expected one value per variant$"),
        # empty, but not 1-D: the shape is what is wrong
        (
            {"rod": np.zeros((0, 2))},
            r"parameters.rod: expected a 1-D array .* shape \(0, 2\)",
        ),
        (
            {"rod": [0.2, 0.3], "crank": [0.07]},
            "parameters: expected arrays of one length .* got rod 2, crank 1",
        ),
        ({"not a name": [0.2]}, "parameters: expected names that are identifiers"),
        ({"error": [0.2]}, "parameters: 'error' names a column of the study's results"),
        # the other names as a sentence lists a choice
        ({"error": [0.2]}, r"\(not error, warning, .*, driver or efficiency\)$"),
        ({"length": [0.2]}, r"its parameters \(crank, rod, offset, angle and omega\)$"),
        ({"variant": [0.2]}, "parameters: 'variant' names a column"),
        ({"position": [0.2]}, "parameters: 'position' names a column"),
        # a summary value's own name: its column held the efficiency, not the
        # parameter
        ({"efficiency": [0.2]}, "parameters: 'efficiency' names a column"),
    ],
)
def test_parameters_are_checked(parameters, message):
    with pytest.raises(assur.UsageError, match=message):
        assur.sweep(catalog.slider_crank, parameters, ANGLES)


def test_pandas_samples_are_paired_by_position_or_refused():
    pd = pytest.importorskip("pandas")
    samples = pd.DataFrame({"crank": [0.07, 0.075], "rod": [0.2, 0.21]}, index=[10, 11])
    angles = np.arange(0.0, 360.0, 30.0)
    # a DataFrame of samples: its columns, one row a variant
    found = assur.sweep(catalog.slider_crank, samples, angles).summary
    assert found[["crank", "rod"]].to_numpy().tolist() == [[0.07, 0.2], [0.075, 0.21]]
    alike = assur.sweep(catalog.slider_crank, dict(samples.items()), angles).summary
    assert alike.equals(found)
    # one Series reordered: crank 0.075 went with rod 0.2, without a word
    reordered = {"crank": samples["crank"].iloc[::-1], "rod": samples["rod"]}
    with pytest.raises(assur.UsageError, match=r"^parameters: pandas Series 'crank' "):
        assur.sweep(catalog.slider_crank, reordered, angles)
    # shuffled alike neither way: compared label by label, not by their order
    shuffled = {
        "crank": pd.Series([0.07, 0.075, 0.08], index=[0, 2, 1]),
        "rod": pd.Series([0.2, 0.21, 0.22], index=[1, 2, 0]),
    }
    with pytest.raises(assur.UsageError, match="have different indexes"):
        assur.sweep(catalog.slider_crank, shuffled, angles)
    # a DataFrame without rows, or with a column twice, is said to be one
    with pytest.raises(assur.UsageError, match=r"^parameters: an empty DataFrame"):
        assur.sweep(catalog.slider_crank, samples.iloc[:0], angles)
    twice = pd.concat([samples, samples[["rod"]]], axis=1)
    with pytest.raises(assur.UsageError, match=r"^parameters: column 'rod' twice"):
        assur.sweep(catalog.slider_crank, twice, angles)


def test_the_refused_names_are_documented():
    # the docstring and the study page list every name a parameter may not take
    # (the docstring had left out efficiency)
    from assur.study import RESERVED

    page = (Path(__file__).parent.parent / "docs" / "study.rst").read_text("utf-8")
    for name in RESERVED:
        assert f"``{name}``" in assur.sweep.__doc__, name
        assert f"``{name}``" in page, name


def test_angles_are_checked():
    # the value at fault is named: the shape shown was a valid one
    with pytest.raises(assur.UsageError) as caught:
        assur.sweep(catalog.slider_crank, {"rod": [0.2]}, [0.0, np.nan, 5.0])
    assert str(caught.value) == (
        "angles: expected finite driver positions, got nan among them"
    )
    with pytest.raises(assur.UsageError, match=r"of shape \(n,\) .* got shape \(0,\)"):
        assur.sweep(catalog.slider_crank, {"rod": [0.2]}, [])


def test_a_sweep_longer_than_a_batch_is_summarised_slice_by_slice(monkeypatch):
    # each variant's sweep was solved whole, every variant of a batch at once:
    # memory grew with the positions (530 MB per million per variant)
    from assur import _sliced, _study_stacks, analysis, study

    monkeypatch.setattr(study, "CHUNK", 500)
    monkeypatch.setattr(_sliced, "CHUNK", 400)
    solved = []
    forces = analysis.forces

    def counted(mech, angles, *args, **kwargs):  # type: ignore[no-untyped-def]
        solved.append(len(angles))
        return forces(mech, angles, *args, **kwargs)

    monkeypatch.setattr(analysis, "forces", counted)
    monkeypatch.setattr(_study_stacks, "forces", counted)
    angles = np.linspace(0.0, 360.0, 1000, endpoint=False)
    parameters = {"crank": CRANKS, "rod": RODS}
    found = assur.sweep(catalog.slider_crank, parameters, angles).summary
    assert solved
    assert max(solved) <= 400
    monkeypatch.undo()
    assert_agrees(found, separate(catalog.slider_crank, parameters, angles))
    # a variant near a dead centre warns once, as its separate call does
    assert found["warning"].iloc[3].count("dead centre") == 1


def test_a_long_sweep_s_warnings_come_in_a_separate_call_s_order(monkeypatch):
    # a rod as long as the crank: two change points, then near a dead centre; the
    # slices gave the dead centre first
    from assur import _sliced, study

    monkeypatch.setattr(study, "CHUNK", 500)
    monkeypatch.setattr(_sliced, "CHUNK", 400)
    angles = np.linspace(0.0, 360.0, 1000, endpoint=False) + 0.1
    found = assur.sweep(catalog.slider_crank, {"rod": [0.074]}, angles).summary
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assur.forces(catalog.slider_crank(rod=0.074), angles)
    said = [" ".join(str(w.message).split()) for w in caught]
    assert len(said) == 3
    assert found["warning"].iloc[0] == " | ".join(said)


def test_a_wrong_parameter_name_is_not_a_variant_failure():
    # a name the factory does not take is a mistake in the study, not a variant that
    # fails: said before any variant is built
    with pytest.raises(assur.UsageError, match=r"unexpected keyword .*'length'.*rod"):
        assur.sweep(catalog.slider_crank, {"length": [0.2]}, ANGLES)


def test_sweep_on_a_local_cluster(slider_study):
    parameters, study = slider_study
    with local_client(workers=2, processes=True) as client:
        remote = assur.sweep(catalog.slider_crank, parameters, ANGLES, client=client)
    assert_agrees(remote.summary, separate(catalog.slider_crank, parameters, ANGLES))
    assert list(remote.summary.index) == list(range(len(RODS)))
    assert remote.summary.equals(study.summary)


def test_a_variant_passing_a_change_point_is_solved_as_a_separate_call_does():
    # a parallelogram four-bar changes branch at 0 and 180 degrees (with a
    # warning); its neighbours in the batch do not
    parameters = {
        "crank": [0.04, 0.04, 0.04],
        "coupler": [0.12, 0.10, 0.121],
        "rocker": [0.08, 0.04, 0.08],
        "frame": [0.10, 0.10, 0.10],
    }
    angles = np.arange(0.0, 360.0, 3.0) + 46.0
    study = assur.sweep(catalog.four_bar, parameters, angles)
    assert_agrees(study.summary, separate(catalog.four_bar, parameters, angles))
    warned = study.summary["warning"].tolist()
    assert "(a change point)" in warned[1]
    assert not warned[0]
    assert not warned[2]


def _same(a, b, path="", skipped=frozenset()):
    """Assert two stacked plans hold the same numbers, leaf by leaf, bit for bit."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        np.testing.assert_array_equal(a, b, err_msg=path)
    elif isinstance(a, tuple | list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _same(x, y, f"{path}[{i}]", skipped)
    elif isinstance(a, dict):
        assert list(a) == list(b), path
        for key in a:
            _same(a[key], b[key], f"{path}.{key}", skipped)
    elif dataclasses.is_dataclass(a):
        assert type(a) is type(b), path
        kept = {"mechanism", "topology", "origins", "angle0", "memo", "group"}
        for f in dataclasses.fields(a):
            if f.name not in kept | skipped:
                field = f"{path}.{f.name}"
                _same(getattr(a, f.name), getattr(b, f.name), field, skipped)
    else:
        assert a == b or (a != a and b != b), (path, a, b)


def _scaled(mech, factor):
    """The mechanism with its coordinates and masses scaled by ``factor``."""

    def at(spec):
        return (spec[0] * factor, spec[1] * factor) if isinstance(spec, tuple) else spec

    return dataclasses.replace(
        mech,
        joints=tuple(dataclasses.replace(j, at=at(j.at)) for j in mech.joints),
        links=tuple(
            dataclasses.replace(
                link,
                center=None if link.center is None else at(link.center),
                mass=link.mass * factor if link.mass else link.mass,
            )
            for link in mech.links
        ),
        points=tuple(dataclasses.replace(p, at=at(p.at)) for p in mech.points),
        loads=tuple(
            dataclasses.replace(ld, at=None if ld.at is None else at(ld.at))
            for ld in mech.loads
        ),
    )


@pytest.mark.parametrize(
    "name", ["slider_crank_exercise", "six_bar_lecture", "tenbar", "slot_mechanism"]
)
def test_variants_compiled_at_once_hold_their_own_plans_numbers(name):
    from assur._batch import stacked
    from assur._stack import restack
    from assur._variants import compile_many, form, numbers, template
    from assur.plan import compile_plan

    mech = assur.load(Path(__file__).parent.parent / "examples" / f"{name}.toml")
    variants = [mech, _scaled(mech, 1.01), _scaled(mech, 0.98)]
    assert len({form(m) for m in variants}) == 1
    model = template(variants[0])
    rows = np.array([numbers(m) for m in variants])
    compiled, doubtful = compile_many(model, rows)
    assert not doubtful.any()
    many = compiled.batch(np.arange(3), 5)
    each = stacked([compile_plan(m) for m in variants], 5)
    _same(many.plan, each.plan)
    _same(many.loads, each.loads)
    # the plan over another number of rows, for the change-point screen's grid
    # (which reads no reported point)
    _same(many.again(7), restack(each.plan, 5, 7), skipped={"point_offset"})
    np.testing.assert_array_equal(many.references, each.references)


def test_a_variant_at_a_dead_centre_is_compiled_on_its_own():
    from assur._variants import compile_many, numbers, template

    # a rod as long as the crank pin is high: the rod stands square to the guide
    # in the reference pose, a dead centre (refused), or next to one (accepted)
    height = catalog.slider_crank().joint("B").at[1]
    rods = [0.2, height * (1 + 1e-13), height * (1 + 1e-11), 0.3]
    variants = [catalog.slider_crank(rod=rod) for rod in rods]
    rows = np.array([numbers(m) for m in variants])
    _, doubtful = compile_many(template(variants[0]), rows)
    assert doubtful.tolist() == [False, True, True, False]


# ------------------------------------------------------------------------------------
# Loads, factories and arguments that a study must take as separate calls do


def braked(torque: float, force: float) -> assur.Mechanism:
    """The slider-crank with a torque on its crank and a force on its slider."""
    mech = catalog.slider_crank()
    loads = (
        assur.Load("crank", torque=torque),
        assur.Load("slider", at="B", force=(force, 0.0)),
    )
    return dataclasses.replace(mech, loads=mech.loads + loads)


def test_variants_differing_in_a_torque_load_are_solved_together():
    # a torque that differs between variants is a value per row of the batch, not a
    # table of the crank's angle
    parameters = {"torque": [1.0, 2.0, -3.0, 2.0], "force": [0.0, 10.0, 10.0, -5.0]}
    study = assur.sweep(braked, parameters, ANGLES)
    assert_agrees(study.summary, separate(braked, parameters, ANGLES))
    torques = study.summary["driver.torque.max"].to_numpy()
    assert torques[0] != torques[1]  # the loads count


def bare(rod: float) -> assur.Mechanism:
    """The slider-crank without masses or loads: nothing for a force analysis."""
    mech = catalog.slider_crank(rod=rod)
    links = tuple(
        dataclasses.replace(link, mass=None, center=None, inertia=None)
        for link in mech.links
    )
    return dataclasses.replace(mech, links=links, loads=())


def test_variants_without_masses_or_loads_fail_as_a_separate_call_does():
    # solved together they gave rows of zeros and no error
    parameters = {"rod": [0.2, 0.25, 0.3]}
    study = assur.sweep(bare, parameters, ANGLES)
    expected = separate(bare, parameters, ANGLES)
    assert all(e.startswith("ModelError: forces: no link has a mass") for e in expected)
    assert_agrees(study.summary, expected)
    # the parameters, error and warning alone: no variant has summary values
    assert list(study.summary.columns) == ["rod", "error", "warning"]


def test_a_shipped_example_without_masses_fails_in_a_study():
    lever = assur.load(Path(__file__).parents[1] / "examples" / "lever_var9.toml")
    study = assur.sweep(lambda k: lever, {"k": [0, 1]}, ANGLES)
    assert study.summary["error"].str.startswith("ModelError: forces: no link").all()


def picky(rod: float) -> assur.Mechanism:
    """A factory that fails in its own ways for some variants."""
    if rod > 0.35:
        msg = "no such rod in the catalogue"
        raise KeyError(msg)
    if rod > 0.25:
        return None  # type: ignore[return-value]
    return catalog.slider_crank(rod=rod)


def test_a_factory_error_of_any_kind_is_the_variants_alone():
    study = assur.sweep(picky, {"rod": [0.2, 0.3, 0.4, 0.22]}, ANGLES)
    errors = study.summary["error"].tolist()
    assert errors[0] == errors[3] == ""
    assert errors[1] == (
        "UsageError: the factory returned NoneType for rod=0.3; expected an "
        "assur.Mechanism"
    )
    assert errors[2] == "KeyError: 'no such rod in the catalogue'"
    assert np.isnan(study.summary["B.F.max"].iloc[1])
    expected = separate(catalog.slider_crank, {"rod": [0.22]}, ANGLES)[0]
    assert study.summary["B.F.max"].iloc[3] == pytest.approx(expected["B.F.max"])


def empty(rod: float) -> assur.Mechanism:
    """A factory that fails with an error of no message."""
    raise ZeroDivisionError


def test_an_error_without_a_message_is_its_class_alone():
    # "ZeroDivisionError: ", with a colon before nothing
    study = assur.sweep(empty, {"rod": [0.2]}, ANGLES)
    assert study.summary["error"].tolist() == ["ZeroDivisionError"]


def test_a_factory_that_takes_any_names_is_called_with_them():
    # no signature to check against: each variant's call says what is wrong
    def anything(**p):
        return catalog.slider_crank(**p)

    study = assur.sweep(anything, {"rod": [0.2], "length": [0.3]}, ANGLES)
    assert "unexpected keyword argument 'length'" in study.summary["error"].iloc[0]


def test_integer_and_boolean_parameters_reach_the_factory_as_they_are():
    rods = [0.2, 0.25]
    seen = []

    def choose(i: int, long: bool) -> assur.Mechanism:
        seen.append((type(i), type(long)))
        return catalog.slider_crank(rod=rods[i] + (0.01 if long else 0.0))

    study = assur.sweep(choose, {"i": [0, 1, 1], "long": [False, False, True]}, ANGLES)
    assert set(seen) == {(int, bool)}
    assert study.summary["error"].tolist() == ["", "", ""]
    assert study.summary["i"].dtype.kind == "i"
    assert study.summary["long"].dtype.kind == "b"
    expected = separate(catalog.slider_crank, {"rod": [0.26]}, ANGLES)[0]
    assert study.summary["B.F.max"].iloc[2] == pytest.approx(expected["B.F.max"])


def test_a_study_over_crank_speeds_equals_separate_calls():
    # every speed is a form of its own: each variant is analysed as a separate call
    parameters = {"omega": [100.0, 150.0, 200.0, 150.0]}
    study = assur.sweep(catalog.slider_crank, parameters, ANGLES)
    assert_agrees(study.summary, separate(catalog.slider_crank, parameters, ANGLES))


def test_angles_of_the_wrong_shape_fail_each_variant_alone():
    # a one-driver variant given two drivers' positions fails as a separate call
    # does; the two-driver variants are analysed
    five = assur.load(
        Path(__file__).parents[1] / "examples" / "five_bar_two_cranks.toml"
    )
    four = assur.load(Path(__file__).parents[1] / "examples" / "four_bar.toml")
    grid = np.column_stack([ANGLES, ANGLES / 2.0])
    study = assur.sweep(lambda k: five if k else four, {"k": [1, 0, 0, 1]}, grid)
    errors = study.summary["error"].tolist()
    assert errors[0] == errors[3] == ""
    assert errors[1] == errors[2] != ""
    with pytest.raises(assur.UsageError) as raised:
        assur.forces(four, grid)
    assert errors[1] == f"UsageError: {' '.join(str(raised.value).split())}"


class Synchronous:
    """A stand-in for a dask.distributed client that runs each task at once."""

    def submit(self, fn, *args, pure=True):
        return fn(*args)

    def gather(self, futures):
        return futures

    def nthreads(self):
        return {"here": 1}


def test_partitions_of_two_topologies_give_one_runs_columns():
    pytest.importorskip("distributed")
    parameters = {
        "kind": [0, 0, 0, 1, 1, 1],
        "crank": [0.074, 0.06, 0.07, 0.08, 0.07, 0.09],
        "rod": [0.2, 0.16, 0.18, 0.14, 0.15, 0.16],
    }
    local = assur.sweep(mixed, parameters, ANGLES)
    parted = assur.sweep(mixed, parameters, ANGLES, Synchronous(), partitions=2)
    assert list(parted.summary.columns)[-2:] == ["error", "warning"]
    assert parted.summary.equals(local.summary)


COUNT = r"partitions: expected a positive whole number \(a count\)"


@pytest.mark.parametrize(
    ("client", "partitions", "message"),
    [
        (3, None, "client: expected a dask.distributed Client, got 3"),
        (Synchronous(), 0, rf"{COUNT}, got 0"),
        (Synchronous(), -3, rf"{COUNT}, got -3"),
        (Synchronous(), 1.5, rf"{COUNT}, got 1.5"),
    ],
)
def test_the_cluster_arguments_are_checked(client, partitions, message):
    pytest.importorskip("distributed")
    with pytest.raises(assur.UsageError, match=message):
        assur.sweep(
            catalog.slider_crank, {"rod": [0.2]}, ANGLES, client, partitions=partitions
        )


class Closed(Synchronous):
    """A stand-in for a client that was closed."""

    status = "closed"


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"progress": "yes"}, "progress: expected True, False or a callable"),
        ({"client": 3}, "client: expected a dask.distributed Client, got 3"),
        ({"client": Closed()}, "client: .* is closed; expected a running client"),
    ],
)
def test_a_wrong_option_is_refused_before_any_variant_is_built(options, message):
    # the first variants were built (to check the driver positions) before a
    # wrong progress or client was refused: minutes with a slow factory
    if "client" in options:
        pytest.importorskip("distributed")
    built = []

    def counted(rod):
        built.append(rod)
        return catalog.slider_crank(rod=rod)

    with pytest.raises(assur.UsageError, match=message):
        assur.sweep(counted, {"rod": [0.2, 0.25]}, ANGLES, **options)
    assert built == []


@pytest.mark.parametrize("partitions", [0, -3, "x", 2.0])
def test_partitions_are_checked_without_a_client_too(partitions):
    # accepted without a word on one machine, refused on a cluster; 2.0 was told
    # it is not "a positive number"
    with pytest.raises(assur.UsageError, match="partitions: expected a positive whole"):
        assur.sweep(catalog.slider_crank, {"rod": [0.2]}, ANGLES, partitions=partitions)


def test_a_factory_may_run_a_study_of_its_own():
    # the best rod for each crank, by an inner study: the outer one waited for
    # ever on a lock its own thread held
    import threading

    def best(crank):
        rods = [0.18, 0.2, 0.22]
        inner = assur.sweep(
            catalog.slider_crank, {"crank": [crank] * 3, "rod": rods}, ANGLES
        )
        rod = rods[int(np.argmin(inner.summary["B.F.max"]))]
        return catalog.slider_crank(crank=crank, rod=rod)

    found = []
    cranks = {"crank": [0.07, 0.074]}
    run = threading.Thread(
        target=lambda: found.append(assur.sweep(best, cranks, ANGLES)), daemon=True
    )
    run.start()
    run.join(120.0)
    assert not run.is_alive(), "the study waits on itself"
    (study,) = found
    assert (study.summary["error"] == "").all()
    alone = assur.forces(best(0.074), ANGLES).summary()
    assert study.summary.loc[1, "B.F.max"] == pytest.approx(alone["B.F.max"], rel=1e-12)


def test_tables_say_which_variants_and_columns_there_are(slider_study):
    pytest.importorskip("xarray")
    _, study = slider_study
    data = study.tables(variants=[0], columns=["B.F"])
    np.testing.assert_array_equal(data["angle"], ANGLES)
    assert data["angle"].dims == ("position",)
    for wrong in ([7], [-1], [0.5], [True], 3, "nope", np.array(1)):
        with pytest.raises(assur.UsageError, match="variants: "):
            study.tables(variants=wrong)
    with pytest.raises(assur.UsageError, match=r"no column 'driver\.torq'.*torque'"):
        study.tables(variants=[0], columns=["driver.torq"])
    # variants that all failed gave a Dataset without a column, and no word why
    with pytest.raises(
        assur.UsageError,
        match=r"variants: none of the 2 asked for was analysed \(variant 2: "
        r"ModelError: slider_crank: the rod",
    ):
        study.tables(variants=[2, 2])
    nan = study.tables(variants=[2], columns=["B.Fx"])
    assert np.isnan(nan["values"]).all()
    # one name as a string was walked letter by letter: "no column 'B'"
    with pytest.raises(
        assur.UsageError,
        match=r"columns: expected a sequence of column names, got 'B\.Fx'; write "
        r"columns=\['B\.Fx'\]",
    ):
        study.tables(variants=[0], columns="B.Fx")


def test_studies_compare_and_hash_as_objects(slider_study):
    # the generated == compared arrays and DataFrames: numpy's "truth value of an
    # array ... is ambiguous" for two studies of the same variants
    parameters, study = slider_study
    again = assur.sweep(catalog.slider_crank, parameters, ANGLES)
    assert study == study
    assert study != again
    assert len({study, again, study}) == 2


def test_an_undefined_efficiency_says_why_from_the_row():
    # a torque on the crank that drives it: the driver does no net work, and the
    # row's NaN efficiency had no reason beside it
    from assur.summary import undefined

    base = assur.load(
        Path(__file__).parent.parent / "examples" / "four_bar_bearings.toml"
    )

    def driven(torque: float) -> assur.Mechanism:
        (load,) = [x for x in base.loads if x.torque is not None]
        rest = tuple(x for x in base.loads if x is not load)
        return dataclasses.replace(
            base, loads=(*rest, dataclasses.replace(load, link="crank", torque=torque))
        )

    row = assur.sweep(driven, {"torque": [4.0]}, ANGLES).summary.iloc[0]
    assert row["error"] == ""
    assert np.isnan(row["efficiency"])
    assert undefined(row) == {
        "efficiency": "the driver does no net work (mean power <= 0): the loads drive"
    }


@pytest.mark.parametrize("sliced", [400, 65536])
def test_a_long_sweep_that_fails_keeps_a_separate_call_s_warnings(monkeypatch, sliced):
    # a slide line offset by more than the crank: a change point at 270 deg, then a
    # dead centre there. The change point's warning was dropped with the error
    from assur import _sliced, study

    monkeypatch.setattr(study, "CHUNK", 500)
    monkeypatch.setattr(_sliced, "CHUNK", sliced)
    angles = np.linspace(0.0, 360.0, 1000, endpoint=False)
    p = {"offset": [0.126], "angle": [90.0]}
    found = assur.sweep(catalog.slider_crank, p, angles).summary
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with pytest.raises(assur.SingularConfigurationError) as raised:
            assur.forces(catalog.slider_crank(offset=0.126, angle=90.0), angles)
    said = [" ".join(str(w.message).split()) for w in caught]
    assert said
    assert "change point" in said[0]
    assert found["warning"].iloc[0] == " | ".join(said)
    assert found["error"].iloc[0] == (
        f"SingularConfigurationError: {' '.join(str(raised.value).split())}"
    )


def test_a_variant_without_friction_says_so_beside_one_with_it():
    # a study over the friction coefficient: the frictionless variant has no losses
    # and no efficiency (NaN, as any value a variant lacks), and undefined() said
    # the loads drive it
    from assur.summary import undefined

    def rubbing(f: float) -> assur.Mechanism:
        m = catalog.slider_crank()
        joints = tuple(
            dataclasses.replace(j, friction=f, radius=0.01)
            if j.kind == "revolute"
            else dataclasses.replace(j, friction=f)
            for j in m.joints
        )
        load = assur.model.Load("slider", at="C", force=(-1000.0, 0.0))
        return dataclasses.replace(m, joints=joints, loads=(load,))

    summary = assur.sweep(rubbing, {"f": [0.0, 0.05]}, ANGLES).summary
    assert (summary["error"] == "").all()
    none = "no friction in this variant: no losses, no efficiency"
    lacking = [
        "A.friction.loss",
        "B.friction.loss",
        "C.friction.loss",
        "guide.friction.loss",
        "friction.loss",
        "driver.power_ideal.mean",
        "efficiency",
    ]
    assert undefined(summary.loc[0]) == dict.fromkeys(lacking, none)
    assert undefined(summary.loc[1]) == {}


def test_a_value_a_variant_does_not_have_or_was_not_analysed_for_says_so():
    from assur.summary import undefined

    # a slider-crank, a four-bar (its joint D the slider-crank lacks, and no guide),
    # and a slider-crank that cannot be built
    parameters = {"kind": [0, 1, 0], "crank": [0.074, 0.08, 0.074]}
    parameters["rod"] = [0.2, 0.14, 0.04]
    summary = assur.sweep(mixed, parameters, ANGLES).summary
    assert summary["error"].tolist()[:2] == ["", ""]
    lacks = "not a value of this variant (its mechanism has no such part)"
    assert undefined(summary.loc[0]) == dict.fromkeys(
        ["D.F.max", "D.F.at", "D.F.rms"], lacks
    )
    assert undefined(summary.loc[1]) == dict.fromkeys(
        ["guide.F.max", "guide.F.at", "guide.F.rms", "guide.M.max", "guide.M.at"],
        lacks,
    )
    assert set(undefined(summary.loc[2]).values()) == {
        "the variant was not analysed (see its error)"
    }
    # a parameter given as NaN is the user's, not a value the summary left out
    rods = {"rod": [0.2, np.nan]}
    failed = assur.sweep(catalog.slider_crank, rods, ANGLES).summary
    assert failed.loc[1, "error"]
    said = undefined(failed.loc[1])
    assert "rod" not in said
    assert "B.F.max" in said


def test_progress_counts_the_variants_done():
    told = []
    parameters = {"rod": np.linspace(0.2, 0.3, 300)}
    study = assur.sweep(
        catalog.slider_crank,
        parameters,
        np.arange(0.0, 360.0, 30.0),
        progress=lambda done, total: told.append((done, total)),
    )
    assert len(study.summary) == 300
    done = [d for d, _ in told]
    assert done, "the callback was never called"
    assert done == sorted(done)
    assert done[-1] == 300
    assert {t for _, t in told} == {300}
    # no bar, no call: the library is quiet unless asked
    quiet = assur.sweep(catalog.slider_crank, parameters, np.arange(0.0, 360.0, 30.0))
    assert quiet.summary.equals(study.summary)


def test_progress_is_told_batch_by_batch_when_the_variants_are_slow(monkeypatch):
    # told once a block of up to 4096 variants: a factory of 2 ms a variant left a
    # bar still for 8 s over a short sweep, and the first report came at the end
    from assur import _study_stacks
    from assur._batch import CHUNK

    parameters = {"rod": np.linspace(0.2, 0.3, 100)}
    angles = np.arange(0.0, 360.0, 1.0)
    per = CHUNK // len(angles)  # variants in a batch
    fast = assur.sweep(catalog.slider_crank, parameters, angles)
    monkeypatch.setattr(_study_stacks, "PACE", 1e-9)  # every block took too long
    told = []
    study = assur.sweep(
        catalog.slider_crank,
        parameters,
        angles,
        progress=lambda done, total: told.append(done),
    )
    assert told == [*range(per, 100, per), 100]
    # the blocks change when the rows are told, not what they hold
    assert study.summary.equals(fast.summary)


def _prp(ram: float) -> assur.Mechanism:
    """The PRP dyad of tests/data/edge: its crank cannot pass 0 and 180 deg."""
    mech = assur.load(Path(__file__).parent / "data" / "edge" / "prp_dead_centre.toml")
    links = tuple(
        dataclasses.replace(link, mass=ram) if link.name == "ram" else link
        for link in mech.links
    )
    return dataclasses.replace(mech, links=links)


def test_a_variant_beyond_a_dead_centre_between_its_positions_fails_as_alone():
    """Positions 100 and 200 deg of a PRP dyad whose reference pose is 60 deg: a
    dead centre at 180 lies between, with no discriminant to show it, and no
    position near it. The batch summed the far side's numbers without a word."""
    angles = [60.0, 100.0, 200.0]
    study = assur.sweep(_prp, {"ram": [1.0, 2.0]}, angles)
    with pytest.raises(assur.AssemblyError) as caught:
        assur.forces(_prp(2.0), angles)
    for error in study.summary["error"].tolist():
        assert error == f"AssemblyError: {caught.value}"


def test_a_study_s_tables_keep_only_the_columns_asked_for():
    # every column of every variant was kept until the Dataset was built: 560 MB
    # for 1 000 variants however few columns were asked for
    from assur._study_tables import _table

    kept, names = _table(catalog.slider_crank, {"rod": 0.2}, ANGLES, ["B.F"])
    assert list(kept) == ["B.F"]
    assert len(names) > 50
    assert "B.F" in names
    every, _ = _table(catalog.slider_crank, {"rod": 0.2}, ANGLES, None)
    np.testing.assert_array_equal(kept["B.F"], every["B.F"])
    assert _table(catalog.slider_crank, {"rod": 0.01}, ANGLES, ["B.F"]) == ({}, ())


def cutting(mass: float, cut: float) -> assur.Mechanism:
    """The cutting slider-crank of the test data, its slider's mass and cut varied."""
    mech = assur.load(Path(__file__).parent / "data" / "edge" / "cutting_steps.toml")
    links = tuple(
        dataclasses.replace(link, mass=mass) if link.name == "slider" else link
        for link in mech.links
    )
    load = mech.loads[0]
    assert isinstance(load.force, assur.LoadTable)
    force = dataclasses.replace(load.force, values=((0.0, cut, cut, 0.0), (0.0,) * 4))
    loads = (dataclasses.replace(load, force=force), *mech.loads[1:])
    return dataclasses.replace(mech, links=links, loads=loads)


@pytest.mark.parametrize("cuts", [[-3000.0] * 3, [-3000.0, -1000.0, -2000.0]])
def test_variants_with_a_stepped_load_table_agree_with_separate_calls(cuts):
    # a separate call's summary counts each step half on either side (a study
    # analyses variants with load tables as separate calls: this holds it so)
    parameters = {"mass": [3.0, 2.0, 4.0], "cut": cuts}
    angles = np.arange(0.0, 360.0, 1.0)
    study = assur.sweep(cutting, parameters, angles)
    assert_agrees(study.summary, separate(cutting, parameters, angles))


@pytest.mark.parametrize(
    ("reference", "angles"),
    [
        # the change point (180 deg) ahead of the reference pose only
        (60.0, np.arange(60.0, 240.0, 4.0)),
        # behind it only, the reference pose far from 0
        (300.0, np.arange(300.0, 150.0, -4.0)),
        # more than two turns back: beyond the screen's window
        (60.0, np.arange(60.0, -800.0, -10.0)),
    ],
)
def test_a_variant_with_one_change_point_a_turn_is_solved_as_alone(reference, angles):
    """crank + frame = coupler + rocker: one change point a turn, at 180 deg (a
    parallelogram has one every half turn). Ahead of the reference pose, behind it
    from far off 0, or more than two turns back, the variant's row is that of a call
    of its own, and only it is told of the change point."""
    parameters = {
        "crank": [0.04, 0.04, 0.04],
        "coupler": [0.06, 0.065, 0.06],
        "rocker": [0.06, 0.06, 0.06],
        "frame": [0.08, 0.08, 0.08],
        "angle": [reference, reference, reference + 1.0],
    }
    study = assur.sweep(catalog.four_bar, parameters, angles)
    assert_agrees(study.summary, separate(catalog.four_bar, parameters, angles))
    warned = study.summary["warning"].tolist()
    assert "(a change point)" in warned[0]
    assert not warned[1]


def said_alone(mech: assur.Mechanism, angles) -> str:
    """The warnings a separate call gives in a fresh process (no plan cached)."""
    from assur.plan import cached_plan

    cached_plan.cache_clear()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assur.forces(mech, angles)
    return " | ".join(" ".join(str(w.message).split()) for w in caught)


def massless_rod(crank: float, rod: float = 0.2) -> assur.Mechanism:
    """A slider-crank whose rod keeps its inertia but has a mass of 0 (a warning)."""
    mech = catalog.slider_crank(crank=crank, rod=rod)
    links = tuple(
        dataclasses.replace(x, mass=0.0) if x.name == "rod" else x for x in mech.links
    )
    return dataclasses.replace(mech, links=links)


@pytest.mark.parametrize(
    ("factory", "parameters"),
    [
        # in millimetres: 245 m across, then 0.25 m, then 259 m
        (
            lambda crank, rod: catalog.slider_crank(crank=crank, rod=rod, omega=2.0),
            {"crank": [74.0, 0.05, 80.0], "rod": [200.0, 0.2, 210.0]},
        ),
        # a batch of one form against its template, every row warned
        (massless_rod, {"crank": [0.05, 0.06, 0.07, 0.065]}),
        # 93 m across, among variants of metres: batched alone, so it is told
        (
            lambda crank, rod: catalog.slider_crank(crank=crank, rod=rod, omega=2.0),
            {"crank": [0.05, 30.0, 0.06, 0.07], "rod": [0.2, 75.0, 0.21, 0.22]},
        ),
        # both warnings, in the order of a separate call: the size first
        (massless_rod, {"crank": [74.0, 80.0], "rod": [200.0, 210.0]}),
    ],
)
def test_a_compilation_s_warnings_are_in_every_row_they_concern(factory, parameters):
    # they reached the first variant's call alone (the plan and the template are
    # compiled once): run twice, the second run's rows were empty, and a batch's
    # template printed its warning to the console, in no row
    angles = np.arange(0.0, 360.0, 10.0)
    names = list(parameters)
    expected = [
        said_alone(factory(**dict(zip(names, values, strict=True))), angles)
        for values in zip(*parameters.values(), strict=True)
    ]
    assert any(expected)
    for _ in range(2):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            found = assur.sweep(factory, parameters, angles).summary
        assert found["warning"].tolist() == expected
        assert not caught  # said in the rows, not on the console


@pytest.mark.parametrize(
    ("factory", "angles", "expected"),
    [
        (catalog.slider_crank, np.zeros((36, 2)), "(36, 2) for variants of 1 driver"),
        (
            lambda crank: assur.load(EXAMPLES / "five_bar_two_cranks.toml"),
            np.arange(36.0),
            "(36,) for variants of 2 drivers",
        ),
    ],
)
def test_positions_that_fit_no_variant_are_refused_before_the_run(
    factory, angles, expected
):
    # each of the 2000 variants failed alone with one error, after the whole run
    built = []

    def counting(crank: float) -> assur.Mechanism:
        built.append(crank)
        return factory(crank=crank)

    with pytest.raises(assur.UsageError, match=re.escape(expected)):
        assur.sweep(counting, {"crank": np.full(2000, 0.074)}, angles)
    assert len(built) == 1


def test_positions_are_checked_against_a_variant_that_builds():
    # the first variant's factory fails: the second is asked instead of none
    def factory(crank: float) -> assur.Mechanism:
        if crank < 0:
            msg = "no such crank"
            raise ValueError(msg)
        return catalog.slider_crank(crank=crank)

    with pytest.raises(assur.UsageError, match=r"1 driver \(crank=0.07\)"):
        assur.sweep(factory, {"crank": [-1.0, 0.07, 0.08]}, np.zeros((12, 2)))


def test_the_refused_positions_name_the_first_variant_and_the_shapes_expected():
    with pytest.raises(assur.UsageError) as err:
        assur.sweep(catalog.slider_crank, {"crank": [0.07, 0.08]}, np.zeros((12, 2)))
    assert str(err.value) == (
        "angles: shape (12, 2) for variants of 1 driver (crank=0.07); "
        "expected (n,) or (n, 1), the same for every variant"
    )


def test_tables_that_would_not_fit_in_memory_are_refused(monkeypatch):
    pytest.importorskip("xarray")
    from assur import _study_tables

    # a machine of 16.8 MB: the tables of 20 variants (360 positions, 109 columns,
    # twice over: 12.6 MB, more than half of it) are refused after the first
    # variant, not built
    monkeypatch.setattr(_study_tables.os, "sysconf", lambda key: 4096)
    built = []

    def counting(rod: float) -> assur.Mechanism:
        built.append(rod)
        return catalog.slider_crank(rod=rod)

    study = assur.sweep(counting, {"rod": np.full(20, 0.2)}, np.arange(360.0))
    built.clear()
    with pytest.raises(
        assur.UsageError, match=r"^variants: 20 tables of 360 positions"
    ):
        study.tables()
    assert len(built) == 1
    # two variants, two columns: they fit
    found = study.tables([0, 1], columns=["driver.torque", "B.F"])
    assert found["values"].shape == (2, 360, 2)


def test_the_memory_to_be_had_is_the_least_of_machine_container_and_ulimit(
    monkeypatch, tmp_path
):
    from assur import _study_tables

    resource = pytest.importorskip("resource")  # not on Windows
    monkeypatch.setattr(_study_tables.os, "sysconf", lambda key: 4096)
    machine = (4096.0 * 4096.0, "this machine's")
    unlimited = (resource.RLIM_INFINITY, resource.RLIM_INFINITY)
    monkeypatch.setattr(resource, "getrlimit", lambda kind: unlimited)
    # a control group tree of one's own: the process in /user.slice/job (v2),
    # and in /docker/abc of the v1 memory controller
    own = tmp_path / "cgroup"
    own.write_text("0::/user.slice/job\n", encoding="utf-8")
    monkeypatch.setattr(_study_tables, "CGROUPS", str(tmp_path))
    monkeypatch.setattr(_study_tables, "OWN_GROUPS", str(own))
    assert _study_tables._memory() == machine  # no limit file: the machine's
    job = tmp_path / "user.slice" / "job"
    job.mkdir(parents=True)
    (tmp_path / "user.slice" / "memory.max").write_text("max\n", encoding="utf-8")
    (job / "memory.max").write_text("2000000\n", encoding="utf-8")
    limited = "its control group's limit of"
    assert _study_tables._memory() == (2e6, limited)  # its own group's
    (tmp_path / "user.slice" / "memory.max").write_text("1500000\n", encoding="utf-8")
    assert _study_tables._memory() == (1.5e6, limited)  # a parent's holds too
    own.write_text("4:cpu,memory:/docker/abc\n1:name=systemd:/\n", encoding="utf-8")
    abc = tmp_path / "memory" / "docker" / "abc"
    abc.mkdir(parents=True)
    no_limit = "9223372036854771712\n"  # cgroup v1's "no limit"
    (abc.parent / "memory.limit_in_bytes").write_text(no_limit, encoding="utf-8")
    assert _study_tables._memory() == machine
    (abc / "memory.limit_in_bytes").write_text("1000000\n", encoding="utf-8")
    assert _study_tables._memory() == (1e6, limited)
    (tmp_path / "memory.max").write_text("900000\n", encoding="utf-8")
    assert _study_tables._memory() == (9e5, limited)  # the mount's root: a container
    monkeypatch.setattr(resource, "getrlimit", lambda kind: (500_000, 10**9))
    assert _study_tables._memory() == (5e5, "this process's limit of")
    # the refusal names the limit met: 2 x 10 x 360 x 10 x 8 bytes > half of 500 kB
    with pytest.raises(assur.UsageError) as err:
        _study_tables._fits(10, 360, 10)
    assert str(err.value) == (
        "variants: 10 tables of 360 positions x 10 columns would take 0.000576 "
        "GB, more than half this process's limit of 0.0005 GB; expected fewer "
        "variants (variants=[...]) or columns (columns=[...])"
    )
    _study_tables._fits(10, 360, 4)  # 230 kB fit


def test_a_study_leaves_other_threads_warnings_alone():
    # the compilations' warnings were silenced by a warnings filter, the whole
    # process's: another thread's warnings were lost while a study ran (94 of 257)
    import threading

    sent: list[int] = []
    shown: list[str] = []
    stop = threading.Event()

    def warner() -> None:
        while not stop.is_set():
            warnings.warn("from another thread", assur.AssurWarning, stacklevel=1)
            sent.append(1)
            stop.wait(0.001)

    with warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.showwarning = lambda message, *args, **kwargs: shown.append(
            str(message)
        )
        thread = threading.Thread(target=warner)
        thread.start()
        try:
            cranks = np.linspace(0.05, 0.07, 2000)
            angles = np.arange(0.0, 360.0, 10.0)
            assur.sweep(catalog.slider_crank, {"crank": cranks}, angles)
        finally:
            stop.set()
            thread.join()
    assert sent
    assert len(shown) == len(sent)


def test_a_study_s_tables_repeat_no_warning_its_summary_gave():
    # the variants' warnings are in the summary's rows: the tables, solved again,
    # hold theirs (variant 3 runs near a dead centre)
    pytest.importorskip("xarray")
    study = assur.sweep(catalog.slider_crank, {"crank": CRANKS, "rod": RODS}, ANGLES)
    assert "dead centre" in study.summary["warning"].iloc[3]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        study.tables([3], columns=["driver.torque"])
    assert not [w for w in caught if issubclass(w.category, assur.AssurWarning)]
