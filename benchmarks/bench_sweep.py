"""Speed of assur's sweeps against hand-written numpy, per-position loops and fsolve.

Run from the repository root::

    python benchmarks/bench_sweep.py           # full: up to 10^6 positions (minutes)
    python benchmarks/bench_sweep.py --quick   # smoke test: up to 10^4, few repeats

The full run prints a table and writes ``benchmarks/results.json``; ``--quick`` writes
``benchmarks/results-quick.json`` instead (``--output PATH`` overrides either). Every
figure is the median of several runs timed with ``time.perf_counter`` in this one
process, after a warm-up call. A table's columns are computed when first read, so each
sweep is timed as the call alone and as the call plus every column read (the work the
hand-written batches do). The targets are printed as PASS/FAIL; the exit status is 0
whatever they say. ``benchmarks/README.md`` explains every row.
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

FORMAT = 2
"""Version of the layout of ``results.json`` (2: call alone and every column read)."""
FULL_SIZES = (360, 10**3, 10**4, 10**5, 10**6)
QUICK_SIZES = (360, 10**3, 10**4)
FULL_REPEATS = {360: 50, 10**3: 30, 10**4: 15, 10**5: 15, 10**6: 5}
QUICK_REPEATS = {360: 10, 10**3: 5, 10**4: 3}
LOOP_SIZES = (360, 10**3)
RATIO_SIZE = 10**5
LARGE_SIZE = 10**6
RATES_N = {False: 10**5, True: 10**4}
"""Sweep length of the per-position driver speed benchmark (full, --quick)."""
RATES_REPEATS = {False: 9, True: 3}
MEMORY_N = {False: 10**6, True: 10**5}
"""Sweep length of the peak-memory measurement (full, --quick)."""
TORQUE = ("driver.torque",)
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


def read_all(table):
    """Read every column of ``table`` (they are computed on first read); return it."""
    for name in table.columns:
        table[name]
    return table


def sizing(table):
    """Read what a motor and bearings are sized on: the driver's torque and every
    joint's reaction magnitude (``J.F``); return ``table``."""
    table[TORQUE[0]]
    for column in table.schema:
        if column.family == "magnitude":
            table[column.name]
    return table


def torque_only(mech, deg, **kwargs):
    """``assur.forces`` of the driver's torque alone, the column read."""
    table = assur.forces(mech, deg, columns=TORQUE, **kwargs)
    table[TORQUE[0]]
    return table


ROWS = {
    "kinematics_call": "assur.kinematics(m, a) alone: the sweep, no column read",
    "kinematics": "assur.kinematics(m, a) and every column read",
    "hand_kinematics": "hand-written numpy batch: every kinematics column",
    "loop_call": "assur.kinematics(m, [a]) per position, no column read",
    "loop": "assur.kinematics(m, [a]) per position, every column read",
    "fsolve": "scipy fsolve per position: positions and velocities only",
    "forces_call": "assur.forces(m, a) alone: the sweep, no column read",
    "forces": "assur.forces(m, a) and every column read",
    "forces_array": "assur.forces(m, a).to_array(): every column, one 2-D array",
    "forces_torque": "assur.forces(m, a, columns=['driver.torque']), the column read",
    "hand_forces": "hand-written numpy batch: every forces column",
}
"""What each timing row of ``results.json`` measures."""


def run_times(
    fns: dict,
    repeats: int,
    warmup: bool = True,
    interleave: bool = True,
    settle: bool = False,
) -> dict:
    """Wall times (s) of every ``fns[key]()`` over ``repeats`` runs.

    With ``interleave`` the functions take turns within each round, so a change in the
    machine's load during a long measurement falls on all of them alike; without it
    each function runs ``repeats`` times in a row (short runs: warm caches, as for a
    user calling the same function again). The garbage collector is emptied once
    before, not between runs: a collection evicts the caches (about 0.2 ms more on
    a 360-position sweep).

    With ``settle`` every timed run follows an untimed run of the same function. At
    10^5 positions and more a run's time otherwise depends on which function ran
    before it: memory the allocator handed back to the system is mapped again, page
    by page, by the next one that asks for it (seen here: the hand-written batch of
    10^6 positions took 0.38 s after one function and 0.7 to 1.6 s after another).
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
            if settle:
                fn()
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


def pair_ratios(a: dict, b: dict) -> list:
    """Time ratios a/b of the runs made in the same round."""
    pairs = zip(a.get("times_s", []), b.get("times_s", []), strict=False)
    return [x / y for x, y in pairs]


def paired_ratio(a: dict, b: dict) -> float:
    """Median over rounds of the time ratio a/b of runs made in the same round.

    Interleaved runs share the machine's state of their round (its load, the memory
    the system hands back), so the ratio of a pair is steadier than the ratio of two
    medians taken over different rounds.
    """
    ratios = pair_ratios(a, b)
    return statistics.median(ratios) if ratios else a["median_s"] / b["median_s"]


def spread(values: list) -> list:
    """First and third quartiles of ``values`` (the noise of a median)."""
    if len(values) < 2:
        return [values[0], values[0]] if values else []
    q = statistics.quantiles(values, n=4, method="inclusive")
    return [q[0], q[2]]


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

    Also that of ``import assur; assur.forces`` (the package loads its names at their
    first use, the analysis with them) and of ``import numpy``.

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

        bare, full, numpy_only, analysis = (
            median("pass"),
            median("import assur"),
            median("import numpy"),
            # the package loads its names at their first use: what a script that
            # runs a sweep pays before it starts
            median("import assur; assur.forces"),
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
            "with_analysis_s": analysis - bare,
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
        read_all(assur.kinematics(m, angles(360)))
    for name in HAND_FORCES:
        read_all(assur.forces(mechs[name], angles(360)))
    res: dict = {
        "format": FORMAT,
        "quick": quick,
        "sizes": list(sizes),
        "rows": ROWS,
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
    res["load_average_during"] = {}
    progress("verifying the hand-written references against assur ...")
    res["verification"] = verify(mechs)

    for key in ROWS:
        res[key] = {}
    for n in sizes:
        deg = angles(n)
        progress(f"sweeps of {n} positions ...")
        fns = {}
        for name, m in mechs.items():
            fns["kinematics_call", name] = lambda m=m, d=deg: assur.kinematics(m, d)
            fns["kinematics", name] = lambda m=m, d=deg: read_all(
                assur.kinematics(m, d)
            )
        for name, fn in HAND_KIN.items():
            fns["hand_kinematics", name] = lambda fn=fn, d=deg: fn(d)
        for name, fn in HAND_FORCES.items():
            m = mechs[name]
            fns["forces_call", name] = lambda m=m, d=deg: assur.forces(m, d)
            fns["forces", name] = lambda m=m, d=deg: read_all(assur.forces(m, d))
            fns["forces_array", name] = lambda m=m, d=deg: assur.forces(m, d).to_array()
            fns["forces_torque", name] = lambda m=m, d=deg: torque_only(m, d)
            fns["hand_forces", name] = lambda fn=fn, d=deg: fn(d)
        timed = run_times(
            fns,
            repeats[n],
            warmup=n <= 10**4,
            interleave=n >= 10**4,
            settle=n >= 10**5,
        )
        for (where, name), times in timed.items():
            res[where].setdefault(name, {})[n] = entry(n, times)
        res["load_average_during"][str(n)] = _load()

    loop_repeats = 1 if quick else 3
    for n in LOOP_SIZES:
        deg = angles(n)
        for name in HAND_KIN:
            m = mechs[name]
            progress(f"per-position loop {name} n={n}")
            timed = run_times(
                {
                    "loop_call": lambda m=m, d=deg: [
                        assur.kinematics(m, [a]) for a in d
                    ],
                    "loop": lambda m=m, d=deg: [
                        read_all(assur.kinematics(m, [a])) for a in d
                    ],
                },
                loop_repeats,
                False,
            )
            for where, times in timed.items():
                res[where].setdefault(name, {})[n] = entry(n, times)
            progress(f"fsolve {name} n={n}")
            fn = FSOLVE[name]
            res["fsolve"].setdefault(name, {})[n] = entry(
                n, run_times({0: lambda fn=fn, d=deg: fn(d)}, loop_repeats + 2)[0]
            )

    progress("360-position sweeps ...")
    res["interactive"] = interactive(mechs["slider-crank"], 50 if quick else 300)
    progress("per-position driver speed ...")
    res["driver_rates"] = driver_rates(mechs, RATES_N[quick], RATES_REPEATS[quick])
    progress("peak memory ...")
    res["memory"] = memory(MEMORY_N[quick])
    progress("import time ...")
    res["import"] = import_time()
    res["load_average_end"] = _load()
    res["ratios"], res["targets"] = ratios(res)
    return res


def interactive(mech, runs: int) -> dict:
    """Median times (ms) of the slider-crank's 360-position sweeps, run back to back.

    Each form runs ``runs`` times in a row after a warm-up call, as a user calling the
    same function again (an interactive session, a plot updated with a slider). The
    same forms at one position give what a call costs whatever its length (keys
    ``..._1_ms``): at 360 positions most of the time is that.
    """
    out: dict = {"runs": runs}
    for n in (360, 1):
        deg = angles(n)
        times = run_times(
            {
                "kinematics_call": lambda d=deg: assur.kinematics(mech, d),
                "kinematics": lambda d=deg: read_all(assur.kinematics(mech, d)),
                "forces_call": lambda d=deg: assur.forces(mech, d),
                "forces": lambda d=deg: read_all(assur.forces(mech, d)),
                "forces_array": lambda d=deg: assur.forces(mech, d).to_array(),
                "forces_sizing": lambda d=deg: sizing(assur.forces(mech, d)),
                "forces_torque": lambda d=deg: torque_only(mech, d),
                "hand_forces": lambda d=deg: ref.slider_crank_forces(d),
            },
            runs,
            interleave=False,
        )
        for key, values in times.items():
            out[f"{key}_{n}_ms"] = 1e3 * statistics.median(values)
            out[f"{key}_{n}_min_ms"] = 1e3 * min(values)
            out[f"{key}_{n}_quartiles_ms"] = [1e3 * v for v in spread(values)]
    return out


def driver_rates(mechs: dict, n: int, repeats: int) -> dict:
    """Sweeps with the driver's speed and acceleration given per position.

    ``arrays``: ``omega`` and ``epsilon`` arrays (a speed varying by 10 % over the turn,
    and its consistent acceleration); ``constants``: the same keywords as floats (the
    mean speed, a non-zero acceleration, so that no kernel skips a zero); ``file``: no
    keyword, the file's constants (its acceleration is 0). Each as the call alone
    and with every column read; runs interleaved.
    """
    deg = angles(n)
    th = np.radians(deg)
    out: dict = {"n": n, "repeats": repeats}
    for name in HAND_FORCES:
        m = mechs[name]
        w0 = m.drivers[0].omega
        w = w0 * (1.0 + 0.1 * np.sin(th))
        e = 0.1 * w0 * np.cos(th) * w  # d(omega)/dt = d(omega)/d(angle) * omega
        keywords = {
            "file": {},
            "constants": {"omega": float(w0), "epsilon": 0.05 * w0 * w0},
            "arrays": {"omega": w, "epsilon": e},
        }
        fns = {}
        for key, kw in keywords.items():
            fns[key + "_call"] = lambda m=m, kw=kw: assur.forces(m, deg, **kw)
            fns[key] = lambda m=m, kw=kw: read_all(assur.forces(m, deg, **kw))
        timed = run_times(fns, repeats, warmup=True, interleave=True)
        out[name] = {key: entry(n, times) for key, times in timed.items()}
    return out


MEMORY_SCRIPT = """
import json, resource, sys
import numpy as np
sys.path[:0] = [{root!r}, {here!r}]
import assur
import reference as ref
n, name, mode = {n}, {name!r}, {mode!r}
make = assur.catalog.slider_crank if name == "slider-crank" else assur.catalog.four_bar
hand = ref.slider_crank_forces if name == "slider-crank" else ref.four_bar_forces
mech = make()
deg = np.arange(n) * (360.0 / n)
small = deg[:360]
t = assur.forces(mech, small)  # compile the plan, load the modules
[t[c] for c in t.columns], hand(small)
del t
unit = 1.0 if sys.platform == "darwin" else 1024.0  # ru_maxrss: bytes or KiB


def status(field):  # a memory figure of this process from /proc (Linux), bytes
    try:
        with open("/proc/self/status", encoding="utf-8") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1]) * 1024
    except OSError:
        pass
    return None


before = status("VmRSS")
rusage_before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * unit
if mode == "hand":
    out = hand(deg)
    width = len(out)
elif mode == "torque":
    t = assur.forces(mech, deg, columns=["driver.torque"])
    t["driver.torque"]
    width = 1
else:
    t = assur.forces(mech, deg)
    width = len(t.columns)
    if mode == "columns":
        [t[c] for c in t.columns]
    elif mode == "array":
        a = t.to_array()
rusage = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * unit
peak = status("VmHWM")
print(json.dumps({{
    "before_bytes": rusage_before if before is None else before,
    "peak_bytes": rusage if peak is None else peak,
    "rusage_before_bytes": rusage_before,
    "rusage_peak_bytes": rusage,
    "columns": width,
}}))
"""
MEMORY_MODES = {
    "call": "assur.forces(m, a) alone",
    "columns": "assur.forces(m, a), every column read",
    "array": "assur.forces(m, a).to_array()",
    "torque": "assur.forces(m, a, columns=['driver.torque']), the column read",
    "hand": "hand-written numpy batch, every column",
}


def memory(n: int) -> dict:
    """Peak resident memory of one force sweep of ``n`` positions, each in a fresh
    interpreter: the resident size before the sweep (interpreter, numpy, assur and a
    360-position warm-up) and the peak.

    On Linux the peak is ``VmHWM`` of ``/proc/self/status``: ``ru_maxrss`` of
    ``resource.getrusage`` survives ``exec``, so in a child it starts at least at the
    benchmark process's own resident size at the fork (about 100 MB here) and hides
    smaller sweeps. ``ru_maxrss`` is recorded too (``rusage_*``) and used where
    ``/proc`` is missing.
    """
    out: dict = {"n": n, "modes": MEMORY_MODES}
    for name in HAND_FORCES:
        out[name] = {}
        for mode in MEMORY_MODES:
            progress(f"peak memory {name} {mode} n={n}")
            code = MEMORY_SCRIPT.format(
                root=str(ROOT), here=str(HERE), n=n, name=name, mode=mode
            )
            try:
                done = subprocess.run(
                    [sys.executable, "-c", code],
                    capture_output=True,
                    text=True,
                    check=True,
                    cwd=ROOT,
                )
                v = json.loads(done.stdout.strip().splitlines()[-1])
            except (OSError, subprocess.CalledProcessError, ValueError) as err:
                out[name][mode] = {"error": str(err)}
                continue
            v["peak_mb"] = v["peak_bytes"] / 2**20
            v["sweep_mb"] = (v["peak_bytes"] - v["before_bytes"]) / 2**20
            v["columns_mb"] = v["columns"] * n * 8 / 2**20
            out[name][mode] = v
    return out


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
        text = Path("/proc/cpuinfo").read_text(encoding="utf-8")
        m = re.search(r"model name\s*:\s*(.+)", text)
        if m:
            return m[1].strip()
    except OSError:
        pass
    return platform.processor()


def ratios(res: dict) -> tuple[dict, list]:
    sizes = res["sizes"]
    big = RATIO_SIZE if RATIO_SIZE in sizes else max(sizes)
    large = LARGE_SIZE if LARGE_SIZE in sizes else max(sizes)
    loop_n = max(LOOP_SIZES)
    kin, hk = res["kinematics"], res["hand_kinematics"]
    out: dict = {"at_n": big, "large_n": large}
    quartiles: dict = {}
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

    def paired(label, a, b):
        """The paired ratio a/b, kept with its quartiles."""
        out[label] = paired_ratio(a, b)
        quartiles[label] = spread(pair_ratios(a, b))
        return out[label]

    for name in HAND_KIN:
        r = paired(
            f"{name} kinematics, columns read / hand, n={big}",
            kin[name][big],
            hk[name][big],
        )
        target(
            f"{name} kinematics, columns read / hand-written at n={big}",
            r,
            1.5,
            False,
        )
        paired(
            f"{name} kinematics, call alone / hand, n={big}",
            res["kinematics_call"][name][big],
            hk[name][big],
        )
    for name in HAND_FORCES:
        for n in sorted({big, large}):
            rows = {key: res[key][name][n] for key in ROWS if key.startswith("forces")}
            hand = res["hand_forces"][name][n]
            r = paired(
                f"{name} forces, columns read / hand, n={n}", rows["forces"], hand
            )
            target(
                f"{name} forces, columns read / hand-written at n={n}", r, 1.5, False
            )
            paired(
                f"{name} forces, call alone / hand, n={n}", rows["forces_call"], hand
            )
            paired(f"{name} forces, to_array / hand, n={n}", rows["forces_array"], hand)
            paired(
                f"{name} forces, columns read / torque only, n={n}",
                rows["forces"],
                rows["forces_torque"],
            )
            # above 1 only by the torque's read, unless columns= spares the sweep work
            paired(
                f"{name} forces, torque only / call alone, n={n}",
                rows["forces_torque"],
                rows["forces_call"],
            )
        r = out[f"{name} forces, columns read / torque only, n={large}"]
        target(f"{name} forces, columns read / torque only at n={large}", r, 2.0, True)
    for key in ("kinematics", "kinematics_call"):
        what = "columns read" if key == "kinematics" else "call alone"
        r = res[key]["ten-bar"][big]["rate"] / res[key]["slider-crank"][big]["rate"]
        out[f"ten-bar rate / slider-crank rate, {what}, n={big}"] = r
        if key == "kinematics":
            target(f"ten-bar rate / slider-crank rate at n={big}", r, 0.2, True)
    for name in HAND_KIN:
        for key, what in (("kinematics", "columns read"), ("kinematics_call", "call")):
            loop = "loop" if key == "kinematics" else "loop_call"
            r = res[key][name][big]["rate"] / res[loop][name][loop_n]["rate"]
            out[f"{name} assur/per-position loop rate, {what}"] = r
            if key == "kinematics":
                target(
                    f"{name} assur at n={big} / per-position loop rate, columns read",
                    r,
                    50.0,
                    True,
                )
        out[f"{name} assur (columns read)/fsolve rate"] = (
            kin[name][big]["rate"] / res["fsolve"][name][loop_n]["rate"]
        )
    dr = res["driver_rates"]
    for name in HAND_FORCES:
        for what in ("", "_call"):
            label = "columns read" if not what else "call alone"
            paired(
                f"{name} forces, omega/epsilon arrays / constants, {label}, "
                f"n={dr['n']}",
                dr[name]["arrays" + what],
                dr[name]["constants" + what],
            )
    it = res["interactive"]
    for key, what in (("kinematics", "kinematics"), ("forces", "forces")):
        limit = 0.5 if key == "kinematics" else 0.4
        for suffix, form in (("_call", "call alone"), ("", "every column read")):
            target(
                f"slider-crank 360-position {what} sweep, {form}, ms",
                it[f"{key}{suffix}_360_ms"],
                limit,
                False,
            )
    target(
        "import assur (with bytecode cache), s", res["import"]["import_s"], 0.15, False
    )
    out["quartiles"] = quartiles
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
        during = res.get("load_average_during") or {}
        loads = [la[0], lb[0], *(v[0] for v in during.values() if v)]
        lines.append(
            f"load average (1 min) at start {la[0]:.2f}, at end {lb[0]:.2f}, "
            f"highest seen {max(loads):.2f}"
            + (
                "  -- the machine was busy: figures are noisy"
                if max(loads) > 0.5 * (m["cpus"] or 1)
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
    width = 11
    label_width = 48
    head = f"{'positions per second':{label_width}s}" + "".join(
        f"{n:>{width}d}" for n in sizes
    )
    lines.append(head)
    lines.append("-" * len(head))

    def row(label, data):
        cells = "".join(
            f"{rate_text(data[n]['rate']) if n in data else '':>{width}s}"
            for n in sizes
        )
        lines.append(f"{label:{label_width}s}{cells}")

    for name in MECHANISMS:
        row(f"assur.kinematics {name}, call alone", res["kinematics_call"][name])
        row(f"assur.kinematics {name}, columns read", res["kinematics"][name])
        if name in HAND_KIN:
            row(f"hand-written numpy kinematics {name}", res["hand_kinematics"][name])
    for name in HAND_KIN:
        row(f"per-position assur {name}, call alone", res["loop_call"][name])
        row(f"per-position assur {name}, columns read", res["loop"][name])
        row(f"per-position fsolve {name}", res["fsolve"][name])
    for name in HAND_FORCES:
        row(f"assur.forces {name}, call alone", res["forces_call"][name])
        row(f"assur.forces {name}, columns read", res["forces"][name])
        row(f"assur.forces {name}, to_array()", res["forces_array"][name])
        row(f"assur.forces {name}, columns=[torque]", res["forces_torque"][name])
        row(f"hand-written numpy forces {name}", res["hand_forces"][name])
    lines.append("")
    it, im = res["interactive"], res["import"]
    lines.append(
        f"slider-crank, 360 positions, ms (median of {it['runs']}, back to back; "
        "quartiles in brackets), and at 1 position (what any call costs):"
    )
    for key, what in (
        ("kinematics_call", "kinematics, call alone"),
        ("kinematics", "kinematics, every column read"),
        ("forces_call", "forces, call alone"),
        ("forces", "forces, every column read"),
        ("forces_array", "forces, to_array()"),
        ("forces_sizing", "forces, torque and joints' |F| read"),
        ("forces_torque", "forces, columns=['driver.torque']"),
        ("hand_forces", "hand-written numpy forces"),
    ):
        q = it[f"{key}_360_quartiles_ms"]
        one = it.get(f"{key}_1_ms")
        lines.append(
            f"  {what:40s} {it[f'{key}_360_ms']:8.3f}  [{q[0]:.3f}, {q[1]:.3f}]"
            + ("" if one is None else f"   1 position {one:6.3f}")
        )
    dr = res["driver_rates"]
    lines.append(
        f"per-position driver speed, forces at n={dr['n']}, ms (median of "
        f"{dr['repeats']}, interleaved): file's constants / constants / arrays"
    )
    for name in HAND_FORCES:
        for suffix, what in (("_call", "call alone"), ("", "columns read")):
            cells = " / ".join(
                f"{dr[name][key + suffix]['median_s'] * 1e3:.1f}"
                for key in ("file", "constants", "arrays")
            )
            lines.append(f"  {name + ', ' + what:40s} {cells}")
    mem = res["memory"]
    lines.append(
        f"peak memory of one force sweep of {mem['n']} positions, MB "
        "(fresh interpreter; in brackets: growth during the sweep / the columns' "
        "size):"
    )
    for name in HAND_FORCES:
        cells = []
        for mode in MEMORY_MODES:
            v = mem[name][mode]
            if "error" in v:
                cells.append(f"{mode} error")
            else:
                cells.append(
                    f"{mode} {v['peak_mb']:.0f} ({v['sweep_mb']:.0f}/"
                    f"{v['columns_mb']:.0f})"
                )
        lines.append(f"  {name:13s} " + ", ".join(cells))
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
            + f"; with the analysis loaded (assur.forces) "
            f"{v['with_analysis_s'] * 1e3:.1f} ms; numpy alone "
            f"{v['numpy_import_s'] * 1e3:.1f} ms, the analysis beyond numpy "
            f"{(v['with_analysis_s'] - v['numpy_import_s']) * 1e3:.1f} ms"
        )
    lines.append("")
    lines.append("Ratios (time ratios: median of paired runs [quartiles]; rates):")
    quartiles = res["ratios"].get("quartiles", {})
    for key, v in res["ratios"].items():
        if key in ("at_n", "large_n", "quartiles"):
            continue
        q = quartiles.get(key)
        noise = f"  [{q[0]:.3g}, {q[1]:.3g}]" if q else ""
        lines.append(f"  {key:62s} {v:9.3g}{noise}")
    lines.append("")
    lines.append("Targets:")
    for t in res["targets"]:
        lines.append(
            f"  {'PASS' if t['pass'] else 'FAIL'}  {t['target']:66s} "
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
    if output.exists():
        # bench_study.py keeps its figures in the same file, under "study"
        kept = json.loads(output.read_text(encoding="utf-8")).get("study")
        if kept is not None:
            res["study"] = kept
    output.write_text(json.dumps(res, indent=1, default=_json) + "\n", encoding="utf-8")
    print(f"\nwrote {output}")
    return 0


def _json(x):
    if isinstance(x, np.generic):
        return x.item()
    raise TypeError(type(x))


if __name__ == "__main__":
    sys.exit(main())
