"""Benchmark of assur.sweep: many variants of the slider-crank exercise.

10^4 variants of ``examples/slider_crank_exercise.toml`` (crank and rod lengths drawn
uniformly within a few per cent) over 360 positions each, summarised with
``assur.sweep``, against

* one mechanism swept over the same number of positions (3.6 x 10^6) and summarised
  (``assur.forces(m, a).summary()``): target, the study takes at most 1.5 times as
  long;
* a loop of separate calls, ``assur.forces(factory(**p), a).summary()`` per variant,
  timed on a subset (300 variants) and scaled: target, the study is at least 5 times
  faster.

It also checks that the study's summaries equal the separate calls' on that subset,
and measures the peak resident memory of the study in a fresh interpreter. Prints a
table and stores the figures under the key ``study`` of ``benchmarks/results.json``
(``--quick``: 10^3 variants, 100 in the loop, into ``results-quick.json``).

    python benchmarks/bench_study.py [--quick]
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import subprocess
import sys
import time
from functools import cache
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

import assur  # noqa: E402

FILE = ROOT / "examples" / "slider_crank_exercise.toml"
ANGLE = 45.0
"""Crank angle of the file's reference pose, deg."""


@cache
def _exercise() -> assur.Mechanism:
    return assur.load(FILE)


def exercise(crank: float, rod: float) -> assur.Mechanism:
    """The exercise's slider-crank with other crank and rod lengths (m)."""
    mech = _exercise()
    a = math.radians(ANGLE)
    b = (crank * math.cos(a), crank * math.sin(a))
    c = (b[0] + math.sqrt(rod * rod - b[1] * b[1]), 0.0)
    at = {"B": b, "C": c, "guide": c}
    joints = tuple(
        dataclasses.replace(j, at=at[j.name]) if j.name in at else j
        for j in mech.joints
    )
    return dataclasses.replace(mech, joints=joints)


def parameters(count: int, seed: int = 1) -> dict[str, np.ndarray]:
    rng = np.random.default_rng(seed)
    return {
        "crank": rng.uniform(0.070, 0.078, count),
        "rod": rng.uniform(0.190, 0.210, count),
    }


ANGLES = ANGLE + np.arange(360.0)


CPU: dict[str, list[float]] = {}
"""CPU time of every timed run (``time.process_time``), by what ran: the machine is
shared, and its other work lengthens wall times more than CPU times."""


def time_study(count: int, first: int | None = None) -> tuple[float, object]:
    """Time a study of ``count`` variants (or the first ``first`` of them)."""
    p = {name: v[:first] for name, v in parameters(count).items()}
    start, cpu = time.perf_counter(), time.process_time()
    study = assur.sweep(exercise, p, ANGLES)
    CPU.setdefault("study", []).append(time.process_time() - cpu)
    return time.perf_counter() - start, study


def time_long(count: int) -> float:
    mech = _exercise()
    angles = np.tile(ANGLES, count)
    start, cpu = time.perf_counter(), time.process_time()
    assur.forces(mech, angles).summary()
    CPU.setdefault("long", []).append(time.process_time() - cpu)
    return time.perf_counter() - start


def time_loop(count: int, subset: int) -> tuple[float, list[dict[str, float]]]:
    p = parameters(count)
    out = []
    start, cpu = time.perf_counter(), time.process_time()
    for i in range(subset):
        mech = exercise(float(p["crank"][i]), float(p["rod"][i]))
        out.append(assur.forces(mech, ANGLES).summary())
    CPU["loop"] = [(time.process_time() - cpu) * count / subset]
    return (time.perf_counter() - start) * count / subset, out


def agreement(study: object, separate: list[dict[str, float]]) -> float:
    """Largest difference relative to the quantity's size (a mean against its RMS).

    Values that are both NaN (an efficiency undefined in both) agree; one NaN
    against a number, or a difference where the size is 0, is infinitely far.
    """
    frame = study.summary  # type: ignore[attr-defined]
    worst = 0.0
    for i, want in enumerate(separate):
        for name, value in want.items():
            got = float(frame[name].iloc[i])
            if (math.isnan(got) and math.isnan(value)) or got == value:
                continue
            size = abs(value)
            if name.endswith(".mean"):
                rms = want.get(name[: -len("mean")] + "rms")
                size = rms if rms is not None else want["driver.torque.rms"] * 200.0
            gap = abs(got - value)
            # NaN and a number, or any gap on a size of 0: no agreement at all
            worst = max(worst, gap / size if size > 0 and gap == gap else math.inf)
    return worst


MEMORY = """
import sys, resource
sys.path.insert(0, {here!r})
import bench_study as b
b.time_study(20)
def status(key):
    try:
        for line in open("/proc/self/status", encoding="utf-8"):
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    except OSError:
        return None
before = status("VmRSS")
b.time_study({count})
rusage = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
print(before, status("VmHWM"), rusage)
"""


def peak_memory(count: int) -> dict[str, float]:
    """Resident memory before the study and at its peak, MB (a fresh interpreter)."""
    code = MEMORY.format(here=str(HERE), count=count)
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    before, peak, rusage = (int(x) for x in out.stdout.split())
    return {"before_mb": before / 1e6, "peak_mb": peak / 1e6, "rusage_mb": rusage / 1e6}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args(argv)
    count, subset, rounds = (1000, 100, 1) if args.quick else (10_000, 300, 5)
    time_study(20)  # warm-up: imports, caches
    CPU.clear()
    studies, longs = [], []
    for _ in range(rounds):
        studies.append(time_study(count)[0])
        longs.append(time_long(count))
    loop, separate = time_loop(count, subset)
    cpu = {key: float(np.median(runs)) for key, runs in CPU.items()}
    _, small = time_study(count, subset)
    error = agreement(small, separate)
    study, long = float(np.median(studies)), float(np.median(longs))
    memory = peak_memory(count)
    res = {
        "variants": count,
        "positions": len(ANGLES),
        "rounds": rounds,
        "study_s": study,
        "study_runs_s": studies,
        "one_long_sweep_s": long,
        "one_long_sweep_runs_s": longs,
        "loop_s_scaled": loop,
        "loop_subset": subset,
        "study_over_long": study / long,
        "study_over_long_rounds": [a / b for a, b in zip(studies, longs, strict=True)],
        "study_cpu_s": cpu["study"],
        "one_long_sweep_cpu_s": cpu["long"],
        "study_over_long_cpu": cpu["study"] / cpu["long"],
        "loop_cpu_s_scaled": cpu["loop"],
        "loop_over_study_cpu": cpu["loop"] / cpu["study"],
        "loop_over_study": loop / study,
        "max_rel_difference": error,
        "memory": memory,
        "targets": {
            "study_over_long<=1.5": study / long <= 1.5,
            "loop_over_study>=5": loop / study >= 5.0,
        },
        "load_average": list(os.getloadavg()),
    }
    print(f"{count} variants x {len(ANGLES)} positions")
    print(f"  assur.sweep                       {study:8.2f} s")
    print(f"  one mechanism, {count * len(ANGLES):.2g} positions   {long:8.2f} s")
    print(f"  loop of separate calls (scaled)   {loop:8.2f} s")
    print(f"  study / one long sweep  {study / long:6.2f}  (target <= 1.5)")
    print(
        f"  CPU: study {cpu['study']:.2f} s, long sweep {cpu['long']:.2f} s, "
        f"ratio {cpu['study'] / cpu['long']:.2f}; loop {cpu['loop']:.2f} s, "
        f"loop / study {cpu['loop'] / cpu['study']:.2f}"
    )
    print(f"  loop / study            {loop / study:6.2f}  (target >= 5)")
    print(f"  largest difference from separate calls {error:.2g}")
    before, peak = memory["before_mb"], memory["peak_mb"]
    print(f"  memory: {before:.0f} MB before, {peak:.0f} MB peak")
    name = "results-quick.json" if args.quick else "results.json"
    path = HERE / name
    whole = json.loads(path.read_text(encoding="utf-8")) if path.exists() else {}
    whole["study"] = res
    path.write_text(json.dumps(whole, indent=1) + "\n", encoding="utf-8")
    print(f"wrote the key 'study' of {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
