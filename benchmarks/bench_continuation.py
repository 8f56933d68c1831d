"""Cost of the continuation of class III groups: shared paths against separate walks.

Run from the repository root::

    python benchmarks/bench_continuation.py           # 360 to 10^5 positions
    python benchmarks/bench_continuation.py --quick   # 360 and 10^4, fewer runs

``assur.kinematics`` on ``examples/class3.toml`` (a crank and one class III triad,
solved by Newton's method from the reference pose), the call alone, at crank angles
evenly over one turn. "shared" is the library as it is: the positions share their
paths from the reference pose (the poses at whole continuation steps are walked to
once per mechanism and kept, every position is one step on from the last before it),
timed as a later call (the anchors kept) and as a first call (walked to anew).
"separate" walks each position to its angle on its own path, as the library did
before. Both give the same poses (``tests/test_numbers.py`` holds them to 1e-9).
Both check every step against its prediction along the branch's tangent (a step
whose correction is large, whose tangent turns sharply or whose Jacobian changes sign
is halved). Writes
``benchmarks/results-continuation.json`` (``--output`` overrides); prints a table. The
exit status is 0 whatever the figures are.

A second table times sweeps with two drivers, where each position is reached on its
own straight path from the reference pose and every path is scanned for change
points (``assur._paths``): the two-crank five-bar (none found), the same with a
parallelogram dyad (``tests/data/edge/five_bar_parallelogram.toml``), and a triad on
two cranks with a parallelogram dyad after it
(``tests/data/edge/two_cranks_class3_parallelogram.toml``: the triad is followed
along every path so that the dyad can be scanned). The positions: a grid of both
cranks every 10 degrees (1296) and one crank alone over a turn (360), off the whole
degrees. Each run
is a first call of its positions (the scans kept by the plan dropped).
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
try:
    import assur
except ImportError:  # run from a source tree without the package installed
    sys.path.insert(0, str(ROOT))
    import assur
from assur import _kinematics  # noqa: E402
from assur.plan import plan_of  # noqa: E402

SIZES = {False: (360, 10**3, 10**4, 10**5), True: (360, 10**4)}
RUNS = {360: 20, 10**3: 10, 10**4: 5, 10**5: 3}
EDGE = ROOT / "tests" / "data" / "edge"
TWO_DRIVERS = {
    "five-bar": (ROOT / "examples" / "five_bar_two_cranks.toml", 0),
    "five-bar, parallelogram": (EDGE / "five_bar_parallelogram.toml", 0),
    "triad, parallelogram after it": (EDGE / "two_cranks_class3_parallelogram.toml", 1),
}
"""Each mechanism's file and the driver turned alone by the one-crank sweep."""


def timed(mech, deg: np.ndarray, runs: int, first: bool = False) -> float:
    """Median seconds of ``assur.kinematics(mech, deg)`` after a warm-up call.

    ``first``: each run as a first call, the anchors kept by the plan dropped.
    """
    assur.kinematics(mech, deg)
    times = []
    for _ in range(runs):
        if first:
            plan_of(mech).memo.pop("anchors", None)
        start = time.perf_counter()
        assur.kinematics(mech, deg)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def two_drivers(quick: bool) -> list[dict[str, object]]:
    """Time sweeps of the two-driver mechanisms; return and print one row each."""
    # off the whole degrees, where the parallelograms lie flat (a dead centre)
    turn = np.arange(360.0) + 0.5
    runs = 2 if quick else 5
    rows: list[dict[str, object]] = []
    print(f"\n{'two drivers':<32} {'positions':<14} {'ms':>9}")
    for name, (path, swept) in TWO_DRIVERS.items():
        mech = assur.load(path)
        alone = np.degrees([[d.reference for d in plan_of(mech).drivers]] * 360)
        alone[:, swept] = turn  # the other crank at its reference angle
        grid = np.stack(np.meshgrid(turn[::10], turn[::10])).reshape(2, -1).T
        for label, at in (("grid 1296", grid), ("one crank 360", alone)):
            times = []
            for _ in range(runs):
                plan_of(mech).memo.pop("path-changes", None)
                start = time.perf_counter()
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    assur.kinematics(mech, at)
                times.append(time.perf_counter() - start)
            seconds = statistics.median(times)
            rows.append({"mechanism": name, "positions": label, "seconds": seconds})
            print(f"{name:<32} {label:<14} {seconds * 1e3:>9.1f}")
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", type=Path)
    args = parser.parse_args(argv)
    quick = args.quick
    out = args.output or HERE / (
        "results-continuation-quick.json" if quick else "results-continuation.json"
    )
    mech = assur.load(ROOT / "examples" / "class3.toml")
    shared_walk = _kinematics._walk
    rows = []
    print(
        f"{'positions':>10} {'shared ms':>10} {'first call':>11} {'separate ms':>12} "
        f"{'ratio':>6}"
    )
    for n in SIZES[quick]:
        deg = np.arange(n) * (360.0 / n)
        runs = max(1, RUNS[n] // (2 if quick else 1))
        shared = timed(mech, deg, runs)
        fresh = timed(mech, deg, runs, first=True)
        _kinematics._walk = _kinematics._separate
        try:
            alone = timed(mech, deg, runs)
        finally:
            _kinematics._walk = shared_walk
        rows.append(
            {"n": n, "shared_s": shared, "first_call_s": fresh, "separate_s": alone}
        )
        ms = [t * 1e3 for t in (shared, fresh, alone)]
        print(
            f"{n:>10} {ms[0]:>10.2f} {ms[1]:>11.2f} {ms[2]:>12.2f} "
            f"{alone / shared:>6.1f}"
        )
    paths = two_drivers(quick)
    text = json.dumps(
        {"mechanism": "examples/class3.toml", "rows": rows, "two_drivers": paths},
        indent=1,
    )
    tmp = out.with_suffix(".tmp")
    tmp.write_text(text + "\n", encoding="utf-8")
    tmp.replace(out)
    print(f"written {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
