"""A fuzzing campaign: thousands of mutants of the examples, within a time budget.

Run from the repository root::

    python benchmarks/fuzz_campaign.py                         # 5000 mutants, 20 min
    python benchmarks/fuzz_campaign.py --count 500 --budget 60 --seed 7 --out out/f

The mutants are those of tests/test_fuzz.py (tests/fuzzing.py draws them, tests/
fuzz_run.py runs and judges them), from another seed. Each ends in a table, an
AssurError or a failure; failures are grouped by their signature (what went wrong and
the traceback's last assur frame). The output folder (default ``out/fuzz``, not
committed) receives ``summary.json`` (the counts, and for each group of failures its
count, the examples it came from, its first case's mutations and the key line) and,
per group, the first failing text (``group-NN.toml``) and a shorter text that fails
the same way (``group-NN.min.toml``, found by deleting lines). One process; the exit
status is 0 whatever the outcomes.
"""

from __future__ import annotations

import argparse
import collections
import json
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # tests/ holds the fuzzer

from tests.fuzz_run import reduce, run_case  # noqa: E402
from tests.fuzzing import stream  # noqa: E402


def campaign(count: int, budget: float, seed: int) -> dict[str, Any]:
    """Run up to ``count`` mutants within ``budget`` seconds; return the summary."""
    start = time.monotonic()
    labels: collections.Counter[str] = collections.Counter()
    groups: dict[str, dict[str, Any]] = {}
    done = 0
    for case in stream(seed):
        if done >= count or time.monotonic() - start > budget:
            break
        outcome = run_case(case.text)
        done += 1
        labels[outcome.label] += 1
        if outcome.failed:
            group = groups.setdefault(
                outcome.signature,
                {
                    "signature": outcome.signature,
                    "count": 0,
                    "bases": collections.Counter(),
                    "cases": [],
                    "mutations": list(case.mutations),
                    "detail": outcome.detail,
                    "text": case.text,
                },
            )
            group["count"] += 1
            group["bases"][case.base] += 1
            if len(group["cases"]) < 20:
                group["cases"].append(case.number)
        if done % 500 == 0:
            print(
                f"{done} mutants, {time.monotonic() - start:.0f} s: {dict(labels)}",
                flush=True,
            )
    return {
        "seed": seed,
        "mutants": done,
        "seconds": round(time.monotonic() - start, 1),
        "outcomes": dict(labels.most_common()),
        "groups": sorted(groups.values(), key=lambda g: -g["count"]),
    }


def write(summary: dict[str, Any], out: Path, reduce_budget: float) -> None:
    """Write the reproducers and ``summary.json`` into ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    for number, group in enumerate(summary["groups"], 1):
        text = group.pop("text")
        name = f"group-{number:02d}"
        (out / f"{name}.toml").write_text(text, encoding="utf-8")
        short = reduce(text, group["signature"], budget=reduce_budget)
        (out / f"{name}.min.toml").write_text(short, encoding="utf-8")
        group["reproducer"] = f"{name}.toml"
        group["minimal"] = f"{name}.min.toml"
        group["minimal_lines"] = short.count("\n")
        group["bases"] = dict(group["bases"])
    (out / "summary.json").write_text(
        json.dumps(summary, indent=2, ensure_ascii=False) + "\n", encoding="utf-8"
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=5000, help="most mutants")
    parser.add_argument("--budget", type=float, default=1200.0, help="seconds")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=Path, default=ROOT / "out" / "fuzz")
    parser.add_argument(
        "--reduce-budget", type=float, default=30.0, help="seconds per group"
    )
    args = parser.parse_args(argv)
    summary = campaign(args.count, args.budget, args.seed)
    write(summary, args.out, args.reduce_budget)
    print(
        f"{summary['mutants']} mutants in {summary['seconds']} s "
        f"(seed {summary['seed']}): {summary['outcomes']}"
    )
    for number, group in enumerate(summary["groups"], 1):
        print(
            f"  group-{number:02d} x{group['count']}: {group['signature']} "
            f"({group['minimal_lines']} lines)"
        )
    print(f"written to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
