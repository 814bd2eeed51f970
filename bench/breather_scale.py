#!/usr/bin/python3
"""Exact breathers at scale (issue 29): solve and Floquet times and peak memory of `lrchain bright`
and `lrchain dark --model` on N = 101, 1001, 10001 sites, matrix-free (--solver krylov: Newton-Krylov,
then the 20 largest-modulus multipliers by Arnoldi) beside the dense path where it fits
(--max-dense sites). Each run is one `lrchain ... floquet` process under /usr/bin/time (peak resident
memory); the solve and Floquet seconds come from its JSON (krylov.solve_seconds,
krylov.leading_floquet.seconds; dense: the whole run for solve+Floquet). Not a test: prints a table.
  bench/breather_scale.py [--lrchain build/cli/lrchain] [--sites 101,1001,10001] [--max-dense 1001]
"""
import argparse
import json
import os
import subprocess
import tempfile
import time

CASES = {
    # docs/bright-breathers.md's Klein-Gordon breather above the band (on-site, one field)
    "bright klein_gordon 1.19": ["bright", "floquet", "--model", "klein_gordon", "--omega-b", "1.19"],
    # docs/dark-models.md's resonant chain dark breather below the optical band (strain form, two fields)
    "dark resonant_chain 2.42": ["dark", "floquet", "--model", "resonant_chain", "--branch", "optical",
                                 "--center", "site", "--omega-b", "2.42"],
}


def run(lrchain, argv):
    """(wall seconds, peak MiB, JSON) of one lrchain run."""
    with tempfile.NamedTemporaryFile("r", suffix=".time") as t:
        start = time.perf_counter()
        p = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", t.name, lrchain, *argv, "--quiet", "--json"],
                           capture_output=True, text=True)
        wall = time.perf_counter() - start
        peak = int(t.read().strip().splitlines()[-1]) / 1024
    if p.returncode != 0:
        return wall, peak, {"error": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"}
    return wall, peak, json.loads(p.stdout)


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--lrchain", default="build/cli/lrchain")
    a.add_argument("--sites", default="101,1001,10001")
    a.add_argument("--max-dense", type=int, default=1001)
    args = a.parse_args()
    print(f"# {os.uname().nodename}, load: {os.getloadavg()}")
    print("| case | N | path | solve s | Floquet s | total s | peak MiB | Newton | GMRES its | multipliers |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, base in CASES.items():
        for n in (int(s) for s in args.sites.split(",")):
            paths = ["krylov"] + (["dense"] if n <= args.max_dense else [])
            for path in paths:
                wall, peak, j = run(args.lrchain, [*base, "--sites", str(n), "--solver", path])
                if "error" in j:
                    print(f"| {name} | {n} | {path} | - | - | {wall:.1f} | {peak:.0f} | {j['error']} | | |")
                    continue
                newton = len(j.get("newton_residuals", [])) - 1
                if path == "krylov":
                    k = j["krylov"]
                    f = k.get("leading_floquet", {})
                    top = f.get("multipliers", [{}])[0].get("modulus", float("nan")) if f.get("multipliers") else float("nan")
                    print(f"| {name} | {n} | krylov | {k['solve_seconds']:.2f} | {f.get('seconds', 0):.2f} | {wall:.1f} | "
                          f"{peak:.0f} | {newton} | {k['gmres_iterations']} | {len(f.get('multipliers', []))}/"
                          f"{f.get('requested')} max|l|={top:.6f} |")
                else:
                    print(f"| {name} | {n} | dense | (in total) | (in total) | {wall:.1f} | {peak:.0f} | {newton} | - | all |")


if __name__ == "__main__":
    main()
