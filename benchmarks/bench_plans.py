"""Time of ``assur plans`` on the ten-bar and on chains of dyads of growing length.

Run from the repository root::

    python benchmarks/bench_plans.py                 # ten-bar, chains of 10, 20, 40
    python benchmarks/bench_plans.py --sizes 10 20   # shorter chains only

Each mechanism is written as a TOML file (a crank driving n RRR dyads in a row,
each on the one before, with masses: ``tests/test_long_chains.py``'s chain), then
``python -m assur plans FILE --angle 30 -o DIR -q`` runs once in a fresh process
on the source tree: every plan drawn and written as PNG and SVG. Prints, per
mechanism, the wall and CPU time of the command (the child's user and system
time) and the CPU time per group; a time that grows as the number of groups
gives a flat last column. No file is kept; the exit status is 0 whatever the
figures.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
try:
    import assur
except ImportError:  # run from a source tree without the package installed
    sys.path.insert(0, str(ROOT))
    import assur

sys.path.insert(0, str(ROOT))  # tests/ holds the chain the long-chain tests use
from tests.test_long_chains import chain  # noqa: E402

SIZES = (10, 20, 40)


def timed(path: Path, out: Path) -> tuple[float, float]:
    """Run ``assur plans`` on ``path`` into ``out``; return its wall and CPU time, s."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), MPLBACKEND="Agg")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    command = [sys.executable, "-m", "assur", "plans", str(path), "--angle", "30"]
    subprocess.run([*command, "-o", str(out), "-q"], check=True, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main() -> int:
    """Time the command on each mechanism and print a table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="*", default=list(SIZES))
    parser.add_argument("--no-tenbar", action="store_true")
    args = parser.parse_args()
    print(f"{'mechanism':<16}{'groups':>7}{'wall s':>9}{'CPU s':>9}{'CPU s/group':>13}")
    with tempfile.TemporaryDirectory() as folder:
        cases = [] if args.no_tenbar else [("tenbar", ROOT / "examples/tenbar.toml", 4)]
        for n in args.sizes:
            path = Path(folder) / f"chain{n}.toml"
            assur.save(chain(n), path)
            cases.append((f"chain of {n}", path, n))
        for name, path, groups in cases:
            wall, cpu = timed(path, Path(folder) / f"plans_{groups}")
            print(f"{name:<16}{groups:>7}{wall:>9.1f}{cpu:>9.1f}{cpu / groups:>13.2f}",
                  flush=True)  # fmt: skip
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
