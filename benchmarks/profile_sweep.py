"""Where the time of a slider-crank sweep goes: cProfile of assur.kinematics and forces.

Run from the repository root::

    python benchmarks/profile_sweep.py [--top 25] [--output benchmarks/profile.txt]

A table's columns are computed when first read, so every figure here is for a sweep
with every column read (the call alone is timed too in the phases).

First the time of each phase of a sweep (solving the groups, the links' states, the
reverse pass, freezing the states, computing the columns when read) at 10^5, 360 and
1 positions, timed by wrapping the package's internal functions (no profiler
overhead; a phase renamed in the package is left out). Then cProfile of one sweep of
10^5 positions and of 300 sweeps of 360 positions (the per-call overhead) for each of
``assur.kinematics`` and ``assur.forces``, every column read, after a warm-up call:
the functions with the largest cumulative and the largest own time.
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
    ("assur.analysis", "to_si"),
    ("assur._kinematics", "solve"),
    ("assur._kinematics", "state_of"),
    ("assur.kinetostatics", "solve"),
    ("assur.analysis", "freeze"),
    ("assur.analysis", "_report"),
    ("assur.table", "evaluate"),
)
"""Module and name of each phase, wrapped where it is looked up when called (so
``evaluate`` in ``assur.table``, which imports it). None runs inside another."""


def read_all(table):
    """Read every column of ``table``; return it."""
    for name in table.columns:
        table[name]
    return table


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
    out.write(
        "=== phases of a slider-crank sweep, ms per call "
        "(call: the call alone; read: every column read) ===\n"
    )
    try:
        for n, calls in ((100_000, 10), (360, 300), (1, 300)):
            deg = np.arange(n) * (360.0 / n)
            for fn in (assur.kinematics, assur.forces):
                for form, run in (
                    ("call", lambda fn=fn, d=deg: fn(mech, d)),
                    ("read", lambda fn=fn, d=deg: read_all(fn(mech, d))),
                ):
                    run()
                    spent.clear()
                    t0 = time.perf_counter()
                    for _ in range(calls):
                        run()
                    total = (time.perf_counter() - t0) / calls
                    parts = ", ".join(
                        f"{k} {v / calls * 1e3:.3f}" for k, v in spent.items()
                    )
                    rest = total - sum(spent.values()) / calls
                    out.write(
                        f"{fn.__name__:10s} {form} n={n:<6d} total "
                        f"{total * 1e3:8.3f}: {parts}, other {rest * 1e3:.3f}\n"
                    )
    finally:
        for module, name, fn in saved:
            setattr(module, name, fn)
    return out.getvalue()


def profile(fn, mech, n: int, calls: int, top: int) -> str:
    deg = np.arange(n) * (360.0 / n)
    read_all(fn(mech, deg))  # warm-up: compile the plan
    prof = cProfile.Profile()
    t0 = time.perf_counter()
    prof.enable()
    for _ in range(calls):
        read_all(fn(mech, deg))
    prof.disable()
    wall = (time.perf_counter() - t0) / calls
    out = io.StringIO()
    out.write(
        f"=== assur.{fn.__name__}(slider_crank, {n} positions), every column read, "
        f"x {calls}: {wall * 1e3:.3f} ms per call under the profiler ===\n"
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
        args.output.write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
