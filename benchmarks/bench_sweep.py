"""Speed of assur's sweeps against hand-written numpy, per-position loops and fsolve.

Run from the repository root::

    python benchmarks/bench_sweep.py           # full: up to 10^6 positions (minutes)
    python benchmarks/bench_sweep.py --quick   # smoke test: up to 10^4, few repeats

The full run prints a table and writes ``benchmarks/results.json``; ``--quick`` writes
``benchmarks/results-quick.json`` instead (``--output PATH`` overrides either). Every
figure is the median of several runs timed with ``time.perf_counter`` in this one
process, after a warm-up call. The targets are printed as PASS/FAIL; the exit status
is 0 whatever they say. ``benchmarks/README.md`` explains every column.
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
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
sys.path.insert(0, str(HERE))
import reference as ref  # noqa: E402

FULL_SIZES = (360, 10**3, 10**4, 10**5, 10**6)
QUICK_SIZES = (360, 10**3, 10**4)
FULL_REPEATS = {360: 50, 10**3: 30, 10**4: 15, 10**5: 15, 10**6: 3}
QUICK_REPEATS = {360: 10, 10**3: 5, 10**4: 3}
LOOP_SIZES = (360, 10**3)
RATIO_SIZE = 10**5
VERIFY_N = 1009
TOLERANCE = 1e-9
"""Largest difference allowed between the hand-written results and assur's, relative
to each column's largest magnitude (at least 1)."""

MECHANISMS = {
    "slider-crank": lambda: assur.catalog.slider_crank(),
    "four-bar": lambda: assur.catalog.four_bar(),
    "ten-bar": lambda: assur.load(ROOT / "examples" / "tenbar.toml"),
}
HAND_KIN = {
    "slider-crank": ref.slider_crank_kinematics,
    "four-bar": ref.four_bar_kinematics,
}
HAND_FORCES = {"slider-crank": ref.slider_crank_forces, "four-bar": ref.four_bar_forces}
FSOLVE = {"slider-crank": ref.slider_crank_fsolve, "four-bar": ref.four_bar_fsolve}


def angles(n: int) -> np.ndarray:
    """``n`` crank angles evenly over a full turn, deg."""
    return np.arange(n) * (360.0 / n)


def run_times(
    fns: dict, repeats: int, warmup: bool = True, interleave: bool = True
) -> dict:
    """Wall times (s) of every ``fns[key]()`` over ``repeats`` runs.

    With ``interleave`` the functions take turns within each round, so a change in the
    machine's load during a long measurement falls on all of them alike; without it
    each function runs ``repeats`` times in a row (short runs: warm caches, as for a
    user calling the same function again). The garbage collector is emptied once
    before, not between runs: a collection evicts the caches (about 0.2 ms more on
    a 360-position sweep).
    """
    gc.collect()
    times: dict = {key: [] for key in fns}
    if not interleave:
        for key, fn in fns.items():
            times[key] = run_times({key: fn}, repeats, warmup)[key]
        return times
    if warmup:
        for fn in fns.values():
            fn()
    for _ in range(repeats):
        for key, fn in fns.items():
            t0 = time.perf_counter()
            result = fn()
            times[key].append(time.perf_counter() - t0)
            del result
    return times


def entry(n: int, times: list) -> dict:
    med = statistics.median(times)
    return {
        "n": n,
        "median_s": med,
        "min_s": min(times),
        "rate": n / med,
        "repeats": len(times),
        "times_s": list(times),
    }


def paired_ratio(a: dict, b: dict) -> float:
    """Median over rounds of the time ratio a/b of runs made in the same round.

    Interleaved runs share the machine's state of their round (its load, the memory
    the system hands back), so the ratio of a pair is steadier than the ratio of two
    medians taken over different rounds.
    """
    pairs = zip(a.get("times_s", []), b.get("times_s", []), strict=False)
    ratios = [x / y for x, y in pairs]
    return statistics.median(ratios) if ratios else a["median_s"] / b["median_s"]


def rate_text(rate: float) -> str:
    for unit, div in (("M", 1e6), ("k", 1e3)):
        if rate >= div:
            return f"{rate / div:.3g} {unit}/s"
    return f"{rate:.3g} /s"


def progress(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


# ------------------------------------------------------------------------- verification


def compare(hand: dict, table) -> dict:
    """Worst relative difference between the hand-written columns and assur's."""
    missing = sorted(set(table.columns) - set(hand))
    extra = sorted(set(hand) - set(table.columns))
    worst, where = 0.0, None
    for name in table.columns:
        if name not in hand:
            continue
        a = np.asarray(table[name], dtype=float)
        b = np.broadcast_to(np.asarray(hand[name], dtype=float), a.shape)
        nan_a, nan_b = np.isnan(a), np.isnan(b)
        if (nan_a != nan_b).any():
            worst, where = math.inf, name
            continue
        ok = ~nan_a
        if not ok.any():
            continue
        scale = max(1.0, float(np.max(np.abs(b[ok]))))
        err = float(np.max(np.abs(a[ok] - b[ok]))) / scale
        if err > worst:
            worst, where = err, name
    return {
        "n": VERIFY_N,
        "max_rel_error": worst,
        "worst_column": where,
        "missing_columns": missing,
        "extra_columns": extra,
        "ok": worst <= TOLERANCE and not missing and not extra,
    }


def verify(mechs: dict) -> dict:
    rng = np.random.default_rng(1)
    deg = np.concatenate([angles(VERIFY_N - 9), rng.uniform(-720.0, 720.0, 9)])
    out = {}
    for name in HAND_KIN:
        out[f"{name} kinematics"] = compare(
            HAND_KIN[name](deg), assur.kinematics(mechs[name], deg)
        )
        out[f"{name} forces"] = compare(
            HAND_FORCES[name](deg), assur.forces(mechs[name], deg)
        )
        # fsolve: same positions and rates as assur (a sanity check, loose tolerance)
        small = angles(360)
        fs = FSOLVE[name](small)
        t = assur.kinematics(mechs[name], small)
        if name == "slider-crank":
            want = [np.radians(t["rod.angle"]), t["C.x"], t["rod.omega"], t["C.vx"]]
        else:
            want = [
                np.radians(t["coupler.angle"]),
                np.radians(t["rocker.angle"]),
                t["coupler.omega"],
                t["rocker.omega"],
            ]
        err = max(
            float(np.max(np.abs(np.asarray(w) - fs[:, i]))) for i, w in enumerate(want)
        )
        out[f"{name} fsolve"] = {"n": 360, "max_abs_error": err, "ok": err < 1e-6}
    return out


# ------------------------------------------------------------------------------ timings


def import_time(runs: int = 5) -> dict:
    """Median wall time of ``import assur`` in a fresh interpreter, minus a bare one.

    Measured twice: with a bytecode cache (as an installed package has; the cache goes
    to a temporary ``PYTHONPYCACHEPREFIX``, not into the source tree), which the target
    applies to, and without one (``PYTHONDONTWRITEBYTECODE=1`` on a source tree: every
    assur module is compiled at each import).
    """
    base = dict(os.environ)
    paths = [str(ROOT), base.get("PYTHONPATH")]
    base["PYTHONPATH"] = os.pathsep.join(p for p in paths if p)
    for key in ("PYTHONWARNINGS", "PYTHONPYCACHEPREFIX", "PYTHONDONTWRITEBYTECODE"):
        base.pop(key, None)

    def wall(env: dict, code: str, *flags: str) -> tuple[float, str]:
        t0 = time.perf_counter()
        done = subprocess.run(
            [sys.executable, *flags, "-c", code],
            env=env,
            cwd=ROOT,
            capture_output=True,
            text=True,
            check=True,
        )
        return time.perf_counter() - t0, done.stderr

    def measure(env: dict) -> dict:
        wall(env, "import assur")  # fill the bytecode and file caches

        def median(code: str) -> float:
            return statistics.median(wall(env, code)[0] for _ in range(runs))

        bare, full, numpy_only = (
            median("pass"),
            median("import assur"),
            median("import numpy"),
        )
        cumulative, rows = [], []
        for _ in range(runs):
            _, err = wall(env, "import assur", "-X", "importtime")
            rows = []
            for line in err.splitlines():
                m = re.match(r"import time:\s+(\d+) \|\s+(\d+) \|(\s*)(\S+)", line)
                if m:
                    rows.append((int(m[1]), int(m[2]), len(m[3]), m[4]))
            cumulative += [r[1] * 1e-6 for r in rows if r[3] == "assur" and r[2] == 1]
        return {
            "python_bare_s": bare,
            "python_import_assur_s": full,
            "import_s": full - bare,
            "numpy_import_s": numpy_only - bare,
            "importtime_cumulative_s": statistics.median(cumulative)
            if cumulative
            else None,
            "largest_cumulative_us": [
                {"module": r[3], "cumulative_us": r[1], "self_us": r[0]}
                for r in sorted(rows, key=lambda r: -r[1])[:12]
            ],
        }

    with tempfile.TemporaryDirectory(prefix="assur-pycache-") as cache:
        warm = measure({**base, "PYTHONPYCACHEPREFIX": cache})
    cold = measure({**base, "PYTHONDONTWRITEBYTECODE": "1"})
    return {
        "runs": runs,
        "import_s": warm["import_s"],
        "cached_bytecode": warm,
        "no_bytecode_cache": cold,
    }


def run(quick: bool) -> dict:
    sizes = QUICK_SIZES if quick else FULL_SIZES
    repeats = QUICK_REPEATS if quick else FULL_REPEATS
    mechs = {name: make() for name, make in MECHANISMS.items()}
    for m in mechs.values():  # compile plans, warm caches
        assur.kinematics(m, angles(360))
    res: dict = {
        "quick": quick,
        "sizes": list(sizes),
        "machine": {
            "python": platform.python_version(),
            "numpy": np.__version__,
            "platform": platform.platform(),
            "processor": _cpu(),
            "cpus": os.cpu_count(),
            "assur": assur.__version__,
            **_git(),
        },
        "tolerance": TOLERANCE,
    }
    res["load_average_start"] = _load()
    progress("verifying the hand-written references against assur ...")
    res["verification"] = verify(mechs)

    for key in ("kinematics", "hand_kinematics", "forces", "hand_forces"):
        res[key] = {}
    for n in sizes:
        deg = angles(n)
        progress(f"sweeps of {n} positions ...")
        fns = {}
        for name, m in mechs.items():
            fns["kinematics", name] = lambda m=m, d=deg: assur.kinematics(m, d)
        for name, fn in HAND_KIN.items():
            fns["hand_kinematics", name] = lambda fn=fn, d=deg: fn(d)
        for name, fn in HAND_FORCES.items():
            fns["forces", name] = lambda m=mechs[name], d=deg: assur.forces(m, d)
            fns["hand_forces", name] = lambda fn=fn, d=deg: fn(d)
        timed = run_times(fns, repeats[n], warmup=n <= 10**4, interleave=n >= 10**4)
        for (where, name), times in timed.items():
            res[where].setdefault(name, {})[n] = entry(n, times)

    loop, fsolve = {}, {}
    loop_repeats = 1 if quick else 3
    for n in LOOP_SIZES:
        deg = angles(n)
        for name in HAND_KIN:
            m = mechs[name]
            progress(f"per-position loop {name} n={n}")
            loop.setdefault(name, {})[n] = entry(
                n,
                run_times(
                    {0: lambda m=m, d=deg: [assur.kinematics(m, [a]) for a in d]},
                    loop_repeats,
                    False,
                )[0],
            )
            progress(f"fsolve {name} n={n}")
            fn = FSOLVE[name]
            fsolve.setdefault(name, {})[n] = entry(
                n, run_times({0: lambda fn=fn, d=deg: fn(d)}, loop_repeats + 2)[0]
            )
    res["loop"] = loop
    res["fsolve"] = fsolve

    progress("360-position sweeps ...")
    sc = mechs["slider-crank"]
    deg = angles(360)
    many = 50 if quick else 300
    times = run_times(
        {
            "kinematics": lambda: assur.kinematics(sc, deg),
            "forces": lambda: assur.forces(sc, deg),
        },
        many,
        interleave=False,
    )
    res["interactive"] = {"runs": many}
    for key, values in times.items():
        res["interactive"][f"{key}_360_ms"] = 1e3 * statistics.median(values)
        res["interactive"][f"{key}_360_min_ms"] = 1e3 * min(values)
    progress("import time ...")
    res["import"] = import_time()
    res["load_average_end"] = _load()
    res["ratios"], res["targets"] = ratios(res)
    return res


def _load() -> list | None:
    try:
        return list(os.getloadavg())
    except OSError:
        return None


def _git() -> dict:
    """The commit benchmarked and whether the package's sources differ from it."""

    def git(*args: str) -> str:
        try:
            return subprocess.run(
                ["git", *args], cwd=ROOT, capture_output=True, text=True, check=True
            ).stdout.strip()
        except (OSError, subprocess.CalledProcessError):
            return ""

    return {
        "commit": git("rev-parse", "HEAD"),
        "assur_modified": bool(git("status", "--porcelain", "--", "assur")),
    }


def _cpu() -> str:
    try:
        text = Path("/proc/cpuinfo").read_text()
        m = re.search(r"model name\s*:\s*(.+)", text)
        if m:
            return m[1].strip()
    except OSError:
        pass
    return platform.processor()


def ratios(res: dict) -> tuple[dict, list]:
    big = RATIO_SIZE if RATIO_SIZE in res["sizes"] else max(res["sizes"])
    loop_n = max(LOOP_SIZES)
    kin, hk = res["kinematics"], res["hand_kinematics"]
    frc, hf = res["forces"], res["hand_forces"]
    out: dict = {"at_n": big}
    targets = []

    def target(label, value, limit, above):
        ok = value >= limit if above else value <= limit
        targets.append(
            {
                "target": label,
                "value": value,
                "limit": limit,
                "kind": ">=" if above else "<=",
                "pass": bool(ok),
            }
        )

    for name in HAND_KIN:
        r = paired_ratio(kin[name][big], hk[name][big])
        out[f"{name} kinematics assur/hand time"] = r
        target(f"{name} kinematics, assur/hand-written time at n={big}", r, 1.5, False)
    for name in HAND_FORCES:
        r = paired_ratio(frc[name][big], hf[name][big])
        out[f"{name} forces assur/hand time"] = r
        target(f"{name} forces, assur/hand-written time at n={big}", r, 1.5, False)
    r = kin["ten-bar"][big]["rate"] / kin["slider-crank"][big]["rate"]
    out["ten-bar rate / slider-crank rate"] = r
    target(f"ten-bar rate / slider-crank rate at n={big}", r, 0.2, True)
    for name in HAND_KIN:
        r = kin[name][big]["rate"] / res["loop"][name][loop_n]["rate"]
        out[f"{name} assur/per-position loop rate"] = r
        target(f"{name} assur at n={big} / per-position loop rate", r, 50.0, True)
        out[f"{name} assur/fsolve rate"] = (
            kin[name][big]["rate"] / res["fsolve"][name][loop_n]["rate"]
        )
    target(
        "slider-crank 360-position kinematics sweep, ms",
        res["interactive"]["kinematics_360_ms"],
        0.5,
        False,
    )
    out["slider-crank 360-position forces sweep, ms"] = res["interactive"][
        "forces_360_ms"
    ]
    target(
        "import assur (with bytecode cache), s", res["import"]["import_s"], 0.15, False
    )
    return out, targets


# ------------------------------------------------------------------------------- report


def report(res: dict) -> str:
    sizes = res["sizes"]
    lines = []
    m = res["machine"]
    commit = m["commit"][:10] or "?"
    if m["assur_modified"]:
        commit += " + local changes"
    lines.append(
        f"assur {m['assur']} ({commit}), Python {m['python']}, "
        f"numpy {m['numpy']}, {m['processor']} x{m['cpus']}"
        + (" [--quick]" if res["quick"] else "")
    )
    la, lb = res.get("load_average_start"), res.get("load_average_end")
    if la and lb:
        lines.append(
            f"load average (1 min) at start {la[0]:.2f}, at end {lb[0]:.2f}"
            + (
                "  -- the machine was busy: figures are noisy"
                if la[0] > 0.5 * (m["cpus"] or 1)
                else ""
            )
        )
    lines.append("")
    lines.append(
        "Verification of the references against assur "
        f"(max |diff| / max(1, max |column|), limit {TOLERANCE:g}):"
    )
    for key, v in res["verification"].items():
        if "max_rel_error" in v:
            note = f"{v['max_rel_error']:.2e} (worst {v['worst_column']})"
            if v["missing_columns"] or v["extra_columns"]:
                note += f" missing {v['missing_columns']} extra {v['extra_columns']}"
        else:
            note = f"max abs error {v['max_abs_error']:.2e} (positions and rates)"
        lines.append(f"  {'ok  ' if v['ok'] else 'BAD '} {key:28s} {note}")
    if not all(v["ok"] for v in res["verification"].values()):
        lines.append(
            "  WARNING: a reference disagrees with assur; the ratios below "
            "are not a fair comparison"
        )
    lines.append("")
    width = 12
    head = f"{'positions per second':46s}" + "".join(f"{n:>{width}d}" for n in sizes)
    lines.append(head)
    lines.append("-" * len(head))

    def row(label, data):
        cells = "".join(
            f"{rate_text(data[n]['rate']) if n in data else '':>{width}s}"
            for n in sizes
        )
        lines.append(f"{label:46s}{cells}")

    for name in MECHANISMS:
        row(f"assur.kinematics  {name}", res["kinematics"][name])
    for name in HAND_KIN:
        row(f"hand-written numpy kinematics {name}", res["hand_kinematics"][name])
    for name in HAND_KIN:
        row(f"per-position assur.kinematics {name}", res["loop"][name])
    for name in FSOLVE:
        row(f"per-position fsolve {name}", res["fsolve"][name])
    for name in HAND_FORCES:
        row(f"assur.forces  {name}", res["forces"][name])
    for name in HAND_FORCES:
        row(f"hand-written numpy forces {name}", res["hand_forces"][name])
    lines.append("")
    it, im = res["interactive"], res["import"]
    lines.append(
        f"slider-crank, 360 positions (median of {it['runs']}): "
        f"kinematics {it['kinematics_360_ms']:.3f} ms, "
        f"forces {it['forces_360_ms']:.3f} ms"
    )
    for key, what in (
        ("cached_bytecode", "with bytecode cache"),
        ("no_bytecode_cache", "without bytecode cache"),
    ):
        v = im[key]
        cum = v["importtime_cumulative_s"]
        lines.append(
            f"import assur, fresh interpreter {what} "
            f"(median of {im['runs']}): "
            f"{v['import_s'] * 1e3:.1f} ms over a bare interpreter"
            + (f" (-X importtime: {cum * 1e3:.1f} ms)" if cum else "")
            + f"; numpy alone {v['numpy_import_s'] * 1e3:.1f} ms, assur "
            f"beyond numpy {(v['import_s'] - v['numpy_import_s']) * 1e3:.1f}"
            " ms"
        )
    lines.append("")
    lines.append("Ratios:")
    for key, v in res["ratios"].items():
        if key != "at_n":
            lines.append(f"  {key:45s} {v:10.3g}")
    lines.append("")
    lines.append("Targets:")
    for t in res["targets"]:
        lines.append(
            f"  {'PASS' if t['pass'] else 'FAIL'}  {t['target']:58s} "
            f"{t['value']:9.3g} {t['kind']} {t['limit']:g}"
        )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--quick",
        action="store_true",
        help="only up to 10^4 positions, few repeats (a smoke test)",
    )
    parser.add_argument(
        "--output", type=Path, default=None, help="where to write the JSON results"
    )
    args = parser.parse_args(argv)
    name = "results-quick.json" if args.quick else "results.json"
    output = args.output or HERE / name
    res = run(args.quick)
    text = report(res)
    print(text)
    res["report"] = text.splitlines()
    output.write_text(json.dumps(res, indent=1, default=_json) + "\n")
    print(f"\nwrote {output}")
    return 0


def _json(x):
    if isinstance(x, np.generic):
        return x.item()
    raise TypeError(type(x))


if __name__ == "__main__":
    sys.exit(main())
