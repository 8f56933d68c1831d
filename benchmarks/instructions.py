"""Instructions per 360-position sweep of the slider-crank, counted by callgrind.

Run from the repository root (needs valgrind)::

    python benchmarks/instructions.py [--what call|read|hand] [--mechanism sc|fb]

On a shared machine the time of a short sweep varies by a third from run to run;
the number of instructions it executes does not. Each count runs the sweep in a
fresh interpreter under ``valgrind --tool=callgrind``, ``SHORT`` and ``LONG`` times
after one call and a garbage collection (the collector is then off), and prints the
difference divided by ``LONG - SHORT``: the instructions of one call, without the
interpreter's start, the imports or the first call's set-up. What would make the
count vary is fixed: one BLAS thread (its idle threads spin), the hash seed, no
address-space randomisation. Two commits compared so differ by their code alone
(to a few hundred instructions in two million). ``call`` is ``assur.forces`` alone
(``assur.kinematics`` with ``--kinematics``), ``read`` the call with every column
read, ``hand`` the hand-written batch of ``reference.py`` (every forces column).
"""

from __future__ import annotations

import argparse
import os
import platform
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
SHORT, LONG = 20, 80
"""The two numbers of calls counted; their difference is what is divided."""

RUN = """
import gc, sys
import numpy as np
sys.path[:0] = [{root!r}, {here!r}]
import assur, reference
what, mech, calls, kin = {what!r}, {mech!r}, {calls}, {kin}
m = assur.catalog.slider_crank() if mech == "sc" else assur.catalog.four_bar()
a = np.linspace(0.0, 360.0, 360, endpoint=False)
sweep = assur.kinematics if kin else assur.forces
hand = reference.slider_crank_forces if mech == "sc" else reference.four_bar_forces
def once():
    if what == "hand":
        return hand(a)
    table = sweep(m, a)
    if what == "read":
        for name in table.columns:
            table[name]
once()
gc.collect()
gc.disable()
for _ in range(calls):
    once()
"""


def count(calls: int, what: str, mech: str, kin: bool) -> int:
    """Return the instructions callgrind counts for ``calls`` calls after the first."""
    root, here = str(HERE.parent), str(HERE)
    code = RUN.format(root=root, here=here, what=what, mech=mech, calls=calls, kin=kin)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    env["PYTHONHASHSEED"] = "0"
    command = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"]
    command += [sys.executable, "-c", code]
    # no address-space randomisation: allocations, and so some paths, repeat
    command = ["setarch", platform.machine(), "-R", *command]
    done = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    found = re.search(r"Collected : (\d+)", done.stderr)
    if found is None:
        msg = f"callgrind printed no count:\n{done.stderr[-2000:]}"
        raise SystemExit(msg)
    return int(found.group(1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--what", choices=("call", "read", "hand"), default="call")
    parser.add_argument("--mechanism", choices=("sc", "fb"), default="sc")
    parser.add_argument("--kinematics", action="store_true")
    args = parser.parse_args()
    # the sources compiled first: a count must not include writing bytecode
    package = str(HERE.parent / "assur")
    subprocess.run([sys.executable, "-m", "compileall", "-q", package], check=True)
    short, long = (
        count(n, args.what, args.mechanism, args.kinematics) for n in (SHORT, LONG)
    )
    per_call = (long - short) / (LONG - SHORT)
    kind = "kinematics" if args.kinematics else "forces"
    said = f"{args.mechanism} {kind} {args.what}"
    print(f"{said}: {per_call / 1e3:.1f} k instructions per call")


if __name__ == "__main__":
    main()
