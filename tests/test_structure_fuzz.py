"""Seeded mutation fuzzing of the structural analysis.

Every bundled example, as loaded and stripped to its links and joints, is mutated a
few times (a link of a joint swapped for another link, a joint dropped or duplicated,
a joint's kind changed between revolute and prismatic) and analysed: each case must
end in a Structure whose groups are consistent, or in an AssurError (a ModelError when
the mechanism is built, a DecompositionError from the analysis), never in another
exception. The default run takes two thousand cases; ``-m slow`` thirty thousand more.
"""

from __future__ import annotations

import collections
import dataclasses
import json
import random

import pytest

import assur
from assur import AssurError, Joint, Link, Mechanism, ModelError, _structure
from assur import _group_search as search
from assur._topology import _index
from assur.model import resolve_point

from .conftest import example_files
from .test_structure import (
    check_group,
    class_four,
    dyad_chain,
    reversed_links,
    triad_chain,
)


def stripped(mech: Mechanism) -> Mechanism:
    """``mech`` reduced to its links and joints (no masses, axes, points or loads).

    Joints are placed by their coordinates, so that dropping one leaves no dangling
    reference: more mutants reach the structural analysis.
    """
    joints = tuple(
        dataclasses.replace(j, at=tuple(float(v) for v in resolve_point(mech, j.at)))
        for j in mech.joints
    )
    links = tuple(Link(link.name) for link in mech.links)
    return Mechanism(links, joints, mech.drivers, name=mech.name)


def bases() -> list[Mechanism]:
    """Every example as loaded, and stripped."""
    loaded = [assur.load(path) for path in example_files()]
    return loaded + [stripped(m) for m in loaded]


def mutate(joints: list[Joint], links: list[str], rng: random.Random) -> None:
    """Apply one random mutation to ``joints`` in place."""
    i = rng.randrange(len(joints))
    joint = joints[i]
    what = rng.choice(("swap", "drop", "duplicate", "kind"))
    if what == "swap":
        new = list(joint.links)
        new[rng.randrange(2)] = rng.choice(links)
        joints[i] = dataclasses.replace(joint, links=tuple(new))
    elif what == "drop" and len(joints) > 1:
        del joints[i]
    elif what == "duplicate":
        joints.append(dataclasses.replace(joint, name=f"{joint.name}_{len(joints)}"))
    elif what == "kind":
        kind = rng.choice([k for k in ("revolute", "prismatic") if k != joint.kind])
        axis = (joint.axis or (1.0, 0.0)) if kind == "prismatic" else None
        joints[i] = dataclasses.replace(joint, kind=kind, axis=axis)


def mutant(base: Mechanism, rng: random.Random) -> Mechanism:
    """One to three mutations of ``base``'s joints (may raise ModelError)."""
    joints = list(base.joints)
    links = ["ground", *(link.name for link in base.links)]
    for _ in range(rng.choice((1, 1, 2, 3))):
        mutate(joints, links, rng)
    return dataclasses.replace(base, joints=tuple(joints))


def check_structure(mech: Mechanism, s: assur.Structure) -> None:
    """A successful analysis places every link once, in consistent groups."""
    placed = [g.links[1] for g in s.drivers] + [x for g in s.groups for x in g.links]
    blocks = [f"{j.name}~block" for j in mech.joints if j.kind == "slot"]
    assert sorted(placed) == sorted([link.name for link in mech.links] + blocks)
    for g in s.groups:
        check_group(g)
    assert f"Structure formula: {s.formula}" in str(s)
    json.dumps(s.to_dict())


def analyse(mech: Mechanism) -> assur.Structure | AssurError:
    """The structure of ``mech``, or the AssurError it raises."""
    try:
        return assur.structure(mech)
    except AssurError as err:
        return err


def run(count: int, seed: int) -> collections.Counter[str]:
    """Analyse ``count`` mutants; return how each ended (fails on a raw exception)."""
    rng = random.Random(seed)
    mechanisms = bases()
    outcomes: collections.Counter[str] = collections.Counter()
    for case in range(count):
        base = mechanisms[case % len(mechanisms)]
        try:
            mech = mutant(base, rng)
        except ModelError:
            outcomes["ModelError"] += 1
            continue
        try:
            result = analyse(mech)
        except Exception as err:  # what the test looks for
            joints = [(j.name, j.kind, j.links) for j in mech.joints]
            pytest.fail(f"case {case} (seed {seed}): {err!r} on {joints}")
        if isinstance(result, AssurError):
            assert "\n" not in str(result)
            outcomes[type(result).__name__] += 1
        else:
            check_structure(mech, result)
            outcomes["Structure"] += 1
    return outcomes


def reference(mech: Mechanism) -> list[tuple] | None:
    """The groups found by trying every connected set at every step, or None.

    The plain search the decomposition replaces: same rule (smallest size, then
    first links), same test of a group, no bookkeeping of what changed.
    """
    topo = _structure.topology(mech)
    index = _index(topo)
    by_name = {p.name: p for p in topo.pairs}
    known = {"ground"} | {x for d in mech.drivers for x in by_name[d.joint].links}
    unknown = [name for name in topo.links if name not in known]
    groups = []
    while unknown:
        for k in range(2, min(len(unknown), search.MAX_GROUP_LINKS) + 1, 2):
            candidates = search._connected(index, set(unknown), set(unknown), k)
            found = [s for s in candidates if search._is_group(index, s, known)[0]]
            if found:
                best = min(found, key=lambda s: sorted(index.rank[x] for x in s))
                break
        else:
            return None
        links = sorted(best, key=index.rank.__getitem__)
        counted = search._counted(index, best, known)
        groups.append(dataclasses.astuple(_structure._describe(links, counted, known)))
        known |= best
        unknown = [name for name in unknown if name not in best]
    return groups


def test_search_agrees_with_trying_every_set():
    rng = random.Random(7)
    mechanisms = bases()
    compared = 0
    for case in range(600):
        try:
            mech = mutant(mechanisms[case % len(mechanisms)], rng)
        except ModelError:
            continue
        if assur.mobility(mech) != len(mech.drivers):
            continue
        result = analyse(mech)
        expected = reference(mech)
        if isinstance(result, AssurError):
            assert expected is None, (case, str(result))
        else:
            assert [dataclasses.astuple(g) for g in result.groups] == expected, case
            compared += 1
    assert compared >= 50


def test_search_agrees_on_chains_and_examples():
    chains = [dyad_chain(12), triad_chain(6), class_four()]
    for mech in chains + bases():
        for order in (mech, reversed_links(mech)):
            groups = assur.structure(order).groups
            assert [dataclasses.astuple(g) for g in groups] == reference(order)


def test_mutants_end_in_a_structure_or_an_assur_error():
    outcomes = run(2000, seed=2024)
    # the mutants exercise the analysis, not only the model's checks
    assert outcomes["Structure"] >= 100
    assert outcomes["DecompositionError"] >= 100


@pytest.mark.slow
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_many_mutants(seed, request):
    # the project's pytest settings do not deselect slow tests: ask for -m slow here
    if "slow" not in (request.config.getoption("markexpr") or ""):
        pytest.skip("ten thousand mutants: run with -m slow")
    outcomes = run(10_000, seed=seed)
    assert outcomes["Structure"] >= 1000
