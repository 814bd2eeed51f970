#!/usr/bin/env python3
"""Before/after speed of two builds, measured alternately so that the load of a shared machine falls on
both alike: each round runs every benchmark once on each build (the order swapped every round), then
the median per benchmark and side, and their ratio after/before, are printed as a Markdown table.

    bench/alternate.py --before ../old/build --after build --rounds 3
    bench/alternate.py --before ../old/build --after build --only coefficients_bench,regime_map_bench

Each build directory's parent is its source tree: the benchmarks run there (they read examples/).
Google Benchmark programs report real time per iteration; sweep_bench (a JSON line) its seconds for
a short sweep (SWEEP_POINTS points on all cores). A benchmark one build lacks is reported for the
other alone.
"""

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

# (program, extra arguments): what the job layer's "no speed lost" asks for (exp1 solve, coefficient
# rates scalar and batch, dark branch, regime map, sweep throughput).
GOOGLE_BENCHMARKS = [
    ("exp1_solve_bench", ["--benchmark_filter=BM_Exp1Run"]),
    ("coefficients_bench", []),
    ("dark_branch_bench", ["--benchmark_filter=BM_DarkBranch100"]),
    ("regime_map_bench", []),
]
SWEEP_POINTS = "40"


def google(build: Path, program: str, args: list) -> dict:
    """benchmark name -> real time (in the benchmark's unit, with the unit appended to the name)."""
    exe = build / "bench" / program
    if not exe.is_file():
        return {}
    # From bench/: a benchmark compiled through ccache with base_dir set names its own source file
    # relative to there (__FILE__ = ../../bench/...), and finds examples/ from it.
    done = subprocess.run([str(exe), "--benchmark_format=json", *args], cwd=exe.parent, capture_output=True,
                          text=True, check=True)
    out = {}
    for b in json.loads(done.stdout)["benchmarks"]:
        if b.get("run_type", "iteration") == "iteration":
            out[f"{program}/{b['name']} [{b.get('time_unit', 'ns')}]"] = b["real_time"]
    return out


def sweep(build: Path) -> dict:
    exe = build / "bench" / "sweep_bench"
    if not exe.is_file():
        return {}
    done = subprocess.run([str(exe), SWEEP_POINTS], cwd=build.parent, capture_output=True, text=True, check=True)
    line = [x for x in done.stdout.splitlines() if x.startswith("{")][-1]
    return {f"sweep_bench/{SWEEP_POINTS} exp1 points [s]": json.loads(line)["seconds"]}


def measure(build: Path, only: set) -> dict:
    out = {}
    for program, args in GOOGLE_BENCHMARKS:
        if not only or program in only:
            out.update(google(build, program, args))
    if not only or "sweep_bench" in only:
        out.update(sweep(build))
    return out


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--before", type=Path, required=True, help="the build directory before the change")
    p.add_argument("--after", type=Path, required=True, help="the build directory after it")
    p.add_argument("--rounds", type=int, default=3, help="alternations (default 3)")
    p.add_argument("--only", default="", help="comma-separated programs, e.g. coefficients_bench,sweep_bench")
    a = p.parse_args()
    only = {x for x in a.only.split(",") if x}
    samples = {"before": {}, "after": {}}
    for r in range(a.rounds):
        for side in (("before", "after") if r % 2 == 0 else ("after", "before")):
            build = (a.before if side == "before" else a.after).resolve()
            print(f"round {r + 1}/{a.rounds}: {side} ({build})", file=sys.stderr, flush=True)
            for name, value in measure(build, only).items():
                samples[side].setdefault(name, []).append(value)
    names = sorted(set(samples["before"]) | set(samples["after"]))
    print("| benchmark | before (median) | after (median) | after / before |")
    print("|---|---|---|---|")
    for name in names:
        b, f = samples["before"].get(name), samples["after"].get(name)
        mb = statistics.median(b) if b else None
        mf = statistics.median(f) if f else None
        ratio = f"{mf / mb:.3f}" if mb and mf else "-"
        print(f"| {name} | {'-' if mb is None else f'{mb:.4g}'} | {'-' if mf is None else f'{mf:.4g}'} | {ratio} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
