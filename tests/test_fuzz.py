"""Seeded mutation fuzzing of the whole pipeline, from a mechanism file to a table.

Every case ends in a table, an AssurError or a documented NaN: never a raw exception,
a hang or an unexplained inf (issue "Reliability", section 6). Mutants of the bundled
examples (tests/fuzzing.py) are read, decomposed and analysed at a few driver
positions (tests/fuzz_run.py); a table has every column finite except the documented
NaN and its balancing load agrees with the virtual-power check, an error has a short
one-line message.

Failures still open are listed in :data:`KNOWN`, each with a reproducer in
tests/data/fuzz/: the fuzzing tests tolerate them while they stay rare and report
them as expected failures, and a reproducer that stops failing that way fails its
test, so that the list only shrinks. The default run takes fifteen hundred cases of
one fixed seed (about 13 s); ``-m slow`` runs three more seeds of three thousand
cases each.
``benchmarks/fuzz_campaign.py`` runs longer campaigns.
"""

from __future__ import annotations

import collections
import math
import random
import time
import tomllib
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

import assur

from .fuzz_run import Outcome, run_case
from .fuzzing import bases, cases, make_case, mutate_data, toml_text

FUZZ_DATA = Path(__file__).parent / "data" / "fuzz"
SEED = 2024
COUNT = 1500


@dataclass(frozen=True)
class Known:
    """A failure still open: what it is, and a file that reproduces it."""

    description: str
    reproducer: str


KNOWN: dict[str, Known] = {}
"""Failure signatures the fuzzing tolerates for now; meant to shrink to empty."""


def run(count: int, seed: int) -> tuple[collections.Counter[str], dict[str, list]]:
    """Run ``count`` cases; return the outcomes and the failures by signature."""
    labels: collections.Counter[str] = collections.Counter()
    failures: dict[str, list[Any]] = collections.defaultdict(list)
    for case in cases(count, seed):
        outcome = run_case(case.text)
        labels[outcome.label] += 1
        if outcome.failed:
            failures[outcome.signature].append((case, outcome))
    return labels, failures


def check_failures(failures: dict[str, list], seed: int, count: int) -> None:
    """Fail on a failure not in KNOWN, or known but common; print the known ones."""
    for signature, found in sorted(failures.items()):
        if signature in KNOWN:
            print(f"known failure x{len(found)}: {signature}")
    # a known signature met in more than 1 % of the cases has found a new cause
    rare = max(3, count // 100)
    unknown = {
        s: found for s, found in failures.items() if s not in KNOWN or len(found) > rare
    }
    if unknown:
        lines = []
        for signature, found in sorted(unknown.items()):
            case, outcome = found[0]
            known = " (known, but common)" if signature in KNOWN else ""
            lines.append(
                f"{signature}{known} (x{len(found)}; first: case {case.number} of seed "
                f"{seed}, {case.base}, {'; '.join(case.mutations)}): {outcome.detail}"
            )
        pytest.fail("new fuzzing failures:\n" + "\n".join(lines))


def test_examples_end_in_tables():
    for name, text in bases():
        outcome = run_case(text)
        assert outcome == Outcome("table"), (name, outcome)


def test_mutants_end_in_a_table_or_an_assur_error():
    start = time.perf_counter()
    labels, failures = run(COUNT, SEED)
    print(f"{COUNT} cases in {time.perf_counter() - start:.1f} s: {dict(labels)}")
    check_failures(failures, SEED, COUNT)
    # the mutants reach every stage: the reader, the structure and the sweeps
    assert labels["table"] >= COUNT // 10
    assert labels["ModelError"] >= COUNT // 5
    assert labels["DecompositionError"] >= 5
    assert labels["AssemblyError"] >= 5


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_many_mutants(seed, request):
    # the project's pytest settings do not deselect slow tests: ask for -m slow here
    if "slow" not in (request.config.getoption("markexpr") or ""):
        pytest.skip("three thousand mutants: run with -m slow")
    labels, failures = run(3000, seed)
    check_failures(failures, seed, 3000)
    assert labels["table"] >= 300


@pytest.mark.parametrize("signature", sorted(KNOWN))
def test_known_failure_still_fails(signature):
    known = KNOWN[signature]
    text = (FUZZ_DATA / known.reproducer).read_text(encoding="utf-8")
    outcome = run_case(text)
    assert outcome.signature == signature, (
        f"{known.reproducer} no longer fails as {signature!r} (it now ends in "
        f"{outcome.label} {outcome.signature}): remove it from KNOWN"
    )
    pytest.xfail(known.description)


FIXED = {
    "check_far_from_origin.toml": "ModelError",
    "check_subnormal_speed.toml": "table",
    "check_subnormal_velocities.toml": "table",
    "dynamics_class3_load_table.toml": "table",
    "dynamics_speed_overflow.toml": "table",
    "doubled_pin_long_name.toml": "DecompositionError",
    # two slots in one place, and a pin entered twice with no driver: the passive
    # constraint's message ran to 500 characters
    "double_slot_passive_message.toml": "DecompositionError",
    "no_driver_passive_message.toml": "DecompositionError",
    # a loop of sliding pairs: the head of the links left over made it 417
    "sliding_loop_long_message.toml": "DecompositionError",
    # three sliding pairs on a dyad: longer words about groups made it 404
    "sliding_dyad_long_message.toml": "DecompositionError",
    "ic_overflow.toml": "table",
    "leftover_long_message.toml": "DecompositionError",
    "long_names_listed.toml": "ModelError",
    "offset_huge_friction.toml": "ModelError",  # a coefficient above 1e6
    "offset_overflow.toml": "table",
    "offset_pure_couple.toml": "table",
    "rpp_parallel_slides.toml": "ModelError",
    "rpp_parallel_slides_scaled.toml": "ModelError",
    "rrr_coincident_pins.toml": "ModelError",
    "table_key_line_break.toml": "ModelError",
    "table_jump_overflow.toml": "AssemblyError",
    "tiny_link_far_apart.toml": "ModelError",
    "tiny_link_overflow.toml": "AssemblyError",  # at 75 deg; 45 deg is NaN, told
    "triad_small_prismatic.toml": "table",
    # the class III example 1e13 m across: its reactions, solved unscaled, were 3e-4
    # out of balance at 270 deg, the balancing torque 8e-4 from its check
    "triad_huge_solve.toml": "table",
    # its rod stands square to the guide at 45 and 225 deg, a root of -1.3e-15 of
    # its size: a dead centre, where it was said not to assemble
    "unexplained_inf_sum.toml": "SingularConfigurationError",
    "vertical_slider_on_the_axis.toml": "SingularConfigurationError",
}
"""Reproducers of failures the fuzzing found and that are fixed, with how each ends
now: a table, or one line naming what is wrong."""


@pytest.mark.parametrize("name", sorted(FIXED))
def test_fixed_failures_stay_fixed(name):
    outcome = run_case((FUZZ_DATA / name).read_text(encoding="utf-8"))
    assert not outcome.failed, outcome
    assert outcome.label == FIXED[name], outcome


def test_every_reproducer_is_listed():
    listed = {k.reproducer for k in KNOWN.values()} | set(FIXED)
    assert {p.name for p in FUZZ_DATA.glob("*.toml")} == listed


# --- the fuzzer's own parts -------------------------------------------------------


def same(a: Any, b: Any) -> bool:
    """Equal data, NaN equal to NaN and a float never equal to an int or a bool.

    Keys may come in another order (the writer puts a table's values first).
    """
    if isinstance(a, dict) and isinstance(b, dict):
        return sorted(a) == sorted(b) and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(map(same, a, b))
    if type(a) is not type(b):
        return False
    if isinstance(a, float) and math.isnan(a):
        return math.isnan(b)
    return bool(a == b) and (not isinstance(a, float) or str(a) == str(b))


def test_toml_writer_round_trips_mutated_data():
    rng = random.Random(5)
    examples = bases()
    for number in range(300):
        name, text = examples[number % len(examples)]
        data = tomllib.loads(text)
        for _ in range(3):
            mutate_data(data, rng, [])
        assert same(tomllib.loads(toml_text(data)), data), (name, number)


def test_cases_are_the_same_for_a_seed():
    assert cases(50, seed=3) == cases(50, seed=3)
    assert cases(50, seed=3) != cases(50, seed=4)
    first = make_case(0, random.Random(1), bases()[0])
    assert first.mutations


def test_a_raw_exception_is_a_failure(monkeypatch):
    def broken(mech):
        return {}["missing"]

    monkeypatch.setattr(assur, "structure", broken)
    outcome = run_case(bases()[0][1])
    assert outcome.failed
    assert outcome.signature.startswith("raw KeyError at ")


def test_a_hang_is_a_failure(monkeypatch):
    def slow(mech):
        # a hang spends CPU time, which the limit counts; time.time() ends the loop
        # after 60 s should the limit ever fail to strike
        start = time.time()
        while time.time() - start < 60.0:
            pass

    monkeypatch.setattr(assur, "structure", slow)
    outcome = run_case(bases()[0][1], time_limit=0.2)
    assert outcome.failed
    assert outcome.signature.startswith("hang in structure")


def test_a_case_that_waits_is_a_hang_too(monkeypatch):
    # waiting spends no CPU time: the clock's limit, ten times longer, ends it
    def waiting(mech):
        time.sleep(30)

    monkeypatch.setattr(assur, "structure", waiting)
    started = time.monotonic()
    outcome = run_case(bases()[0][1], time_limit=0.1)
    assert outcome.signature.startswith("hang in structure")
    assert time.monotonic() - started < 20.0


def test_a_stray_warning_is_a_failure(monkeypatch):
    real = assur.structure

    def noisy(mech):
        warnings.warn("overflow", RuntimeWarning, stacklevel=1)
        return real(mech)

    monkeypatch.setattr(assur, "structure", noisy)
    outcome = run_case(bases()[0][1])
    assert outcome.signature.startswith("stray RuntimeWarning")


@pytest.mark.parametrize(
    ("message", "problem"),
    [
        ("joints.A: bad\nsecond line", "not one line"),
        ("x" * 401, "too long"),
        ("got datetime.date(2020, 1, 1)", "shows a Python repr"),
        ("got <object object at 0x7f3a2c1b9e40>", "shows a Python repr"),
        ("", "empty"),
    ],
)
def test_a_bad_message_is_a_failure(monkeypatch, message, problem):
    def failing(mech):
        raise assur.DecompositionError(message)

    monkeypatch.setattr(assur, "structure", failing)
    outcome = run_case(bases()[0][1])
    assert outcome.signature.startswith(f"message {problem}: DecompositionError")


def test_an_unexplained_nan_is_a_failure(monkeypatch):
    from assur import table as table_module

    real = table_module.Table.__getitem__

    def poisoned(self, name):
        values = real(self, name)
        return values * math.nan if name.endswith(".vx") else values

    monkeypatch.setattr(table_module.Table, "__getitem__", poisoned)
    outcome = run_case(bases()[0][1])
    assert outcome.signature == "NaN or inf in point columns"
