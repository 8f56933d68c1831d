"""Cost of joint friction: the friction sweep against the same sweep without friction.

Run from the repository root::

    python benchmarks/bench_friction.py            # 10^5 positions, 9 rounds
    python benchmarks/bench_friction.py --quick    # 10^4 positions, 3 rounds

Mechanisms: ``examples/slider_crank_friction.toml`` (friction in every joint) and
``examples/four_bar_bearings.toml`` (journal bearings). Each round times
``assur.forces`` on the mechanism with friction and on the same mechanism with every
friction coefficient set to zero, back to back (the call alone, and the call plus every
column read), so a change in the machine's load falls on both alike; the ratio is the
median over rounds of the two runs' ratio, in wall-clock time and in the process's
CPU time (the fairer figure on a machine shared with other work). The Newton steps
each group took are counted by wrapping the group solve of ``assur._friction``. The
figures go to ``benchmarks/results-friction.json`` (``--output PATH`` overrides).
The target (a friction sweep within 3 times the frictionless one) is printed as PASS
or FAIL; the exit status is 0 whatever it says.
"""

from __future__ import annotations

import argparse
import dataclasses
import gc
import json
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
try:
    import assur
except ImportError:  # run from a source tree without the package installed
    sys.path.insert(0, str(ROOT))
    import assur
import assur._friction as friction_module  # noqa: E402
import assur.kinetostatics as kinetostatics  # noqa: E402

MECHANISMS = ("slider_crank_friction", "four_bar_bearings")
TARGET = 3.0
"""Largest cost of a friction sweep, in frictionless sweeps (columns read)."""


def frictionless(mech: assur.Mechanism) -> assur.Mechanism:
    """``mech`` with every joint's friction coefficient set to zero."""
    joints = tuple(dataclasses.replace(j, friction=0.0) for j in mech.joints)
    return dataclasses.replace(mech, joints=joints)


def read_all(table: assur.Table) -> None:
    """Read every column once (columns are computed when first read)."""
    for name in table.columns:
        table[name]


def timed(mech: assur.Mechanism, deg: np.ndarray, columns: bool) -> tuple[float, float]:
    """Wall-clock and CPU seconds of one ``assur.forces`` call (and columns read)."""
    t0, c0 = time.perf_counter(), time.process_time()
    table = assur.forces(mech, deg)
    if columns:
        read_all(table)
    return time.perf_counter() - t0, time.process_time() - c0


def count_steps(mech: assur.Mechanism, deg: np.ndarray) -> dict[str, list[int]]:
    """Newton steps each group with friction took, per slice of the sweep, by label.

    A sweep is solved in slices of a few thousand positions; each slice iterates
    until its slowest position has settled.
    """
    steps: dict[str, list[int]] = {}
    solve = friction_module.solve_group

    def counting(solver, *args, **kwargs):  # type: ignore[no-untyped-def]
        found = solve(solver, *args, **kwargs)
        if found is not None:
            steps.setdefault(solver.label, []).append(found.iterations)
        return found

    kinetostatics.solve_group = counting  # type: ignore[assignment]
    try:
        assur.forces(mech, deg)
    finally:
        kinetostatics.solve_group = solve  # type: ignore[assignment]
    return steps


def measure(name: str, n: int, rounds: int) -> dict:
    """Time the friction sweep and the frictionless one of an example (n positions)."""
    mech = assur.load(ROOT / "examples" / f"{name}.toml")
    plain = frictionless(mech)
    deg = np.arange(n) * (360.0 / n)
    out: dict = {"positions": n, "steps": count_steps(mech, deg)}
    for columns, key in ((False, "call"), (True, "columns")):
        timed(mech, deg, columns), timed(plain, deg, columns)  # warm-up
        rub, ideal = [], []
        gc.collect()
        for _ in range(rounds):
            rub.append(timed(mech, deg, columns))
            ideal.append(timed(plain, deg, columns))
        out[key] = {}
        for k, clock in enumerate(("", "cpu_")):
            a, b = [t[k] for t in rub], [t[k] for t in ideal]
            ratios = [x / y for x, y in zip(a, b, strict=True)]
            out[key] |= {
                f"{clock}friction_s": statistics.median(a),
                f"{clock}frictionless_s": statistics.median(b),
                f"{clock}ratio": statistics.median(ratios),
                f"{clock}ratio_quartiles": list(np.quantile(ratios, [0.25, 0.75])),
            }
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="10^4 positions")
    parser.add_argument("--output", type=Path, default=None, help="results file")
    args = parser.parse_args()
    n, rounds = (10**4, 3) if args.quick else (10**5, 9)
    results = {
        "machine": f"{platform.machine()} {platform.python_version()}",
        "numpy": np.__version__,
        "target_ratio": TARGET,
        "mechanisms": {},
    }
    print(f"friction sweep against the frictionless one, {n} positions")
    for name in MECHANISMS:
        found = measure(name, n, rounds)
        results["mechanisms"][name] = found
        c = found["columns"]
        verdict = "PASS" if c["ratio"] <= TARGET else "FAIL"
        print(
            f"{name:24s} call {found['call']['friction_s'] * 1e3:8.1f} ms "
            f"(x{found['call']['ratio']:.2f}), columns read "
            f"{c['friction_s'] * 1e3:8.1f} ms vs {c['frictionless_s'] * 1e3:8.1f} ms "
            f"(x{c['ratio']:.2f}; CPU time x{c['cpu_ratio']:.2f}; target {TARGET:g}: "
            f"{verdict}); Newton steps "
            + ", ".join(
                f"{g}: {min(s)} to {max(s)} per slice of the sweep"
                for g, s in found["steps"].items()
            )
        )
    output = args.output or HERE / (
        "results-friction-quick.json" if args.quick else "results-friction.json"
    )
    output.write_text(json.dumps(results, indent=2) + "\n", encoding="utf-8")
    print(f"wrote {output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
