"""Scaling of the Assur-group decomposition with the length of a chain of groups.

Run from the repository root::

    python benchmarks/bench_structure.py            # 50, 100, 200, 500 groups
    python benchmarks/bench_structure.py --quick    # fewer repeats

Times ``decompose`` (the search for the groups, without building the mechanism) on a
crank followed by n RRR dyads, each hanging on the previous dyad's rocker and the
frame, with the links listed in attachment order and backwards, and on a crank
followed by n/4 class III triads. Prints the median time per size and the ratio of
the largest to the smallest size: a decomposition linear in the number of groups
gives a ratio near 500/50 = 10; the target is a ratio within 25. No file is written;
the exit status is 0 whatever the figures.
"""

from __future__ import annotations

import argparse
import dataclasses
import gc
import statistics
import sys
import time
import warnings
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
try:
    import assur
except ImportError:  # run from a source tree without the package installed
    sys.path.insert(0, str(ROOT))
    import assur

Driver, Joint, Link, Mechanism = assur.Driver, assur.Joint, assur.Link, assur.Mechanism
decompose = assur._structure.decompose

SIZES = (50, 100, 200, 500)
TARGET = 25.0
"""Largest acceptable time ratio between 500 and 50 groups (linear: about 10)."""


def mechanism(joints: list[Joint]) -> Mechanism:
    """A mechanism of ``joints`` driven at joint O, links in order of appearance."""
    links: list[str] = []
    for joint in joints:
        links += [x for x in joint.links if x != "ground" and x not in links]
    return Mechanism(tuple(Link(x) for x in links), tuple(joints), (Driver("O", 1.0),))


def dyads(count: int) -> Mechanism:
    """A crank, then ``count`` RRR dyads, each on the previous rocker and the frame."""
    joints = [Joint("O", "revolute", ("ground", "crank"), (0.0, 0.0))]
    previous = "crank"
    for i in range(1, count + 1):
        joints += [
            Joint(f"A{i}", "revolute", (previous, f"c{i}"), (i - 0.9, 0.3)),
            Joint(f"B{i}", "revolute", (f"c{i}", f"r{i}"), (float(i), 0.8)),
            Joint(f"O{i}", "revolute", (f"r{i}", "ground"), (i + 0.1, 0.0)),
        ]
        previous = f"r{i}"
    return mechanism(joints)


def triads(count: int) -> Mechanism:
    """A crank, then ``count`` triads, each on the previous triad and the frame."""
    joints = [Joint("O", "revolute", ("ground", "crank"), (0.0, 0.0))]
    previous = "crank"
    for i in range(1, count + 1):
        x = 2.0 * i
        joints += [
            Joint(f"U{i}", "revolute", (previous, f"u{i}"), (x - 1.0, 0.5)),
            Joint(f"TU{i}", "revolute", (f"u{i}", f"t{i}"), (x - 0.5, 1.0)),
            Joint(f"TV{i}", "revolute", (f"t{i}", f"v{i}"), (x, 1.2)),
            Joint(f"TW{i}", "revolute", (f"t{i}", f"w{i}"), (x + 0.5, 1.0)),
            Joint(f"V{i}", "revolute", (f"v{i}", "ground"), (x, 0.0)),
            Joint(f"W{i}", "revolute", (f"w{i}", "ground"), (x + 0.6, 0.0)),
        ]
        previous = f"w{i}"
    return mechanism(joints)


def backwards(mech: Mechanism) -> Mechanism:
    """The same mechanism with its links listed backwards."""
    return dataclasses.replace(mech, links=mech.links[::-1])


def median_time(
    mech: Mechanism, repeats: int, work: Callable[[Mechanism], object] | None = None
) -> float:
    """Median wall time of ``work(mech)`` (``decompose``) in seconds, after a warm-up
    call."""
    work = work or decompose
    work(mech)
    gc.collect()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        work(mech)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def first_sweep(mech: Mechanism) -> object:
    """Compile the plan afresh and sweep 30 positions: the first call's whole cost."""
    assur.plan.cached_plan.cache_clear()
    return assur.kinematics(mech, [float(a) for a in range(30)])


def row(
    label: str,
    build: Callable[[int], Mechanism],
    repeats: int,
    work: Callable[[Mechanism], object] | None = None,
) -> float:
    """Print one line of timings over SIZES and return the ratio last/first."""
    times = [median_time(build(n), repeats, work) for n in SIZES]
    ratio = times[-1] / times[0]
    cells = "  ".join(f"{1e3 * t:9.2f}" for t in times)
    verdict = "PASS" if ratio <= TARGET else "FAIL"
    print(f"{label:<28}{cells}  {ratio:7.1f}  {verdict}")
    return ratio


def main() -> int:
    """Print the table of timings."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    args = parser.parse_args()
    # chains of 500 dyads are hundreds of metres across: the size's warning (lengths
    # in millimetres?) would break the table's rows, and says nothing of speed
    warnings.simplefilter("ignore", assur.AssurWarning)
    repeats = 3 if args.quick else 9
    print(f"assur {assur.__version__}, Python {sys.version.split()[0]}")
    print(
        f"median of {repeats} runs of decompose(), ms; ratio = time at "
        f"{SIZES[-1]} / time at {SIZES[0]} (target <= {TARGET:g})"
    )
    head = "  ".join(f"{n:>9}" for n in SIZES)
    print(f"{'groups':<28}{head}  {'ratio':>7}")
    row("RRR dyads", dyads, repeats)
    row("RRR dyads, links backwards", lambda n: backwards(dyads(n)), repeats)
    row("triads (n/4 groups)", lambda n: triads(n // 4), repeats)
    print("first kinematics call (plan compiled afresh, 30 positions), ms")
    row("RRR dyads: compile + sweep", dyads, max(3, repeats // 3), first_sweep)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
