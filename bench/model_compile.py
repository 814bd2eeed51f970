#!/usr/bin/python3
"""Cold compile of model files (issue 27): for each file, `lrchain coeffs --model FILE` with an empty
model cache (a fresh XDG_CACHE_HOME), timed as wall seconds and CPU seconds of lrchain and everything
it ran (the derivation, the emission and the C++ compiler), then a second, warm call from the cache.
Not a test: prints a table.
  bench/model_compile.py [--lrchain build/cli/lrchain] FILE[@BRANCH] ...
  e.g. bench/model_compile.py tests/derivation/mim3.toml@optical1 models/klein_gordon.toml
"""
import argparse
import os
import resource
import subprocess
import tempfile
import time


def timed(argv, env):
    """(wall seconds, CPU seconds of the children, exit status) of one run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    p = subprocess.run(argv, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(argv)}: exit {p.returncode}: {p.stderr.strip()}")
    return wall, cpu


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--lrchain", default="build/cli/lrchain")
    a.add_argument("files", nargs="+")
    args = a.parse_args()
    print("| model file | cold: wall | cold: CPU | warm: wall |")
    print("|---|---|---|---|")
    for path in args.files:
        file, _, branch = path.partition("@")
        argv = [args.lrchain, "coeffs", "--model", file, "--theta", "1"] + (["--branch", branch] if branch else [])
        with tempfile.TemporaryDirectory() as fresh:
            env = dict(os.environ, XDG_CACHE_HOME=fresh)
            cold_wall, cold_cpu = timed(argv, env)
            warm_wall, _ = timed(argv, env)
        print(f"| {os.path.basename(file)} | {cold_wall:.1f} s | {cold_cpu:.1f} s | {warm_wall:.2f} s |", flush=True)


if __name__ == "__main__":
    main()
