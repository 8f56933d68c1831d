"""Where the time of a slider-crank sweep goes: cProfile of assur.kinematics and forces.

Run from the repository root::

    python benchmarks/profile_sweep.py [--top 25] [--output benchmarks/profile.txt]

First the time of each phase of a sweep (solving the groups, collecting links and
points, the reverse pass, building the columns) at 10^5, 360 and 1 positions, timed
by wrapping the package's internal functions (no profiler overhead; a phase renamed
in the package is left out). Then cProfile of one sweep of 10^5 positions and of 300
sweeps of 360 positions (the per-call overhead) for each of ``assur.kinematics`` and
``assur.forces``, after a warm-up call: the functions with the largest cumulative and
the largest own time.
"""

from __future__ import annotations

import argparse
import cProfile
import io
import pstats
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
try:
    import assur
except ImportError:  # run from a source tree without the package installed
    sys.path.insert(0, str(HERE.parent))
    import assur

CASES = ((100_000, 1), (360, 300))
PHASES = (
    ("assur.analysis", "_to_si"),
    ("assur._kinematics", "allocate"),
    ("assur._kinematics", "solve"),
    ("assur._kinematics", "collect"),
    ("assur.kinetostatics", "allocate"),
    ("assur.kinetostatics", "solve"),
    ("assur.analysis", "_report"),
    ("assur.columns", "build_columns"),
)


def phases() -> str:
    """Milliseconds per call spent in each phase of the slider-crank's sweeps."""
    import importlib

    spent: dict[str, float] = {}
    saved = []
    for module_name, name in PHASES:
        module = importlib.import_module(module_name)
        fn = getattr(module, name, None)
        if fn is None:
            continue
        label = f"{module_name.split('.')[-1]}.{name}"

        def timed(*args, _fn=fn, _label=label, **kwargs):
            t0 = time.perf_counter()
            try:
                return _fn(*args, **kwargs)
            finally:
                spent[_label] = spent.get(_label, 0.0) + time.perf_counter() - t0

        saved.append((module, name, fn))
        setattr(module, name, timed)
    mech = assur.catalog.slider_crank()
    out = io.StringIO()
    out.write("=== phases of a slider-crank sweep, ms per call ===\n")
    try:
        for n, calls in ((100_000, 10), (360, 300), (1, 300)):
            deg = np.arange(n) * (360.0 / n)
            for fn in (assur.kinematics, assur.forces):
                fn(mech, deg)
                spent.clear()
                t0 = time.perf_counter()
                for _ in range(calls):
                    fn(mech, deg)
                total = (time.perf_counter() - t0) / calls
                parts = ", ".join(
                    f"{k} {v / calls * 1e3:.3f}" for k, v in spent.items()
                )
                rest = total - sum(spent.values()) / calls
                out.write(
                    f"{fn.__name__:10s} n={n:<6d} total {total * 1e3:8.3f}: "
                    f"{parts}, other {rest * 1e3:.3f}\n"
                )
    finally:
        for module, name, fn in saved:
            setattr(module, name, fn)
    return out.getvalue()


def profile(fn, mech, n: int, calls: int, top: int) -> str:
    deg = np.arange(n) * (360.0 / n)
    fn(mech, deg)  # warm-up: compile the plan
    prof = cProfile.Profile()
    t0 = time.perf_counter()
    prof.enable()
    for _ in range(calls):
        fn(mech, deg)
    prof.disable()
    wall = (time.perf_counter() - t0) / calls
    out = io.StringIO()
    out.write(
        f"=== assur.{fn.__name__}(slider_crank, {n} positions) x {calls}: "
        f"{wall * 1e3:.3f} ms per call under the profiler ===\n"
    )
    stats = pstats.Stats(prof, stream=out).strip_dirs()
    out.write("--- by cumulative time ---\n")
    stats.sort_stats("cumulative").print_stats(top)
    out.write("--- by own time ---\n")
    stats.sort_stats("tottime").print_stats(top)
    return out.getvalue()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--output", type=Path, default=None)
    args = parser.parse_args(argv)
    mech = assur.catalog.slider_crank()
    parts = [phases()]
    parts += [
        profile(fn, mech, n, calls, args.top)
        for fn in (assur.kinematics, assur.forces)
        for n, calls in CASES
    ]
    text = "\n".join(parts)
    print(text)
    if args.output:
        args.output.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
