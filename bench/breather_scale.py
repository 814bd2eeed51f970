#!/usr/bin/python3
"""Exact breathers at scale (issue 29): solve and Floquet times and peak memory of `lrchain bright`
and `lrchain dark --model` on N = 101, 1001, 10001 sites, matrix-free (--solver krylov: Newton-Krylov,
then for a bright breather the localized multipliers of its core window certified by full-lattice
residuals, krylov.windowed_floquet; for a dark one the same from the dip's window with the
background's Floquet-Bloch multipliers, --dark-floquet window, or with --dark-arnoldi the 20
largest-modulus multipliers by Arnoldi, krylov.leading_floquet) beside the dense path where it fits
(--max-dense sites). Each run is one
`lrchain ... floquet` process under /usr/bin/time (peak resident memory); the solve and Floquet seconds
come from its JSON (krylov.solve_seconds, krylov.*_floquet.seconds; dense: the whole run for
solve+Floquet). Not a test: prints a table.
  bench/breather_scale.py [--lrchain build/cli/lrchain] [--sites 101,1001,10001] [--max-dense 1001]
                          [--cases bright]   (only the cases whose name contains this) [--dark-arnoldi]
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
    # docs/bright-breathers.md's unstable FPU Sievers-Takeno mode (strain form; multiplier 1.02824)
    "bright fput a=0 2.2": ["bright", "floquet", "--model", "fput", "--set", "a=0", "--center", "site",
                            "--omega-b", "2.2"],
    # docs/dark-models.md's resonant chain dark breather below the optical band (strain form, two fields)
    "dark resonant_chain 2.42": ["dark", "floquet", "--model", "resonant_chain", "--branch", "optical",
                                 "--center", "site", "--omega-b", "2.42"],
    # docs/dark-models.md's klein_gordon (b = -1/2, defocusing at theta = pi): a site-centred dark breather
    # near the edge (stable) and a bond-centred one far from it (a localized real instability)
    "dark klein_gordon b=-1/2 1.15 site": ["dark", "floquet", "--model", "klein_gordon", "--set", "b=-1/2",
                                           "--center", "site", "--omega-b", "1.15"],
    "dark klein_gordon b=-1/2 1.0 bond": ["dark", "floquet", "--model", "klein_gordon", "--set", "b=-1/2",
                                          "--center", "bond", "--omega-b", "1.0"],
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


def floquet_seconds(k):
    """Seconds of the matrix-free Floquet step (windowed for bright, Arnoldi for dark)."""
    return k.get("windowed_floquet", k.get("leading_floquet", {})).get("seconds", 0)


def background_summary(w):
    """A dark window's background: the largest Floquet-Bloch modulus and its kind."""
    b = w.get("background")
    if b is None:
        return ""
    if b["reason"]:
        return f"; background: {b['reason']}"
    return f"; background max|l|={b['max_modulus']:.6f} ({b['kind']}, ring residual {b['ring_residual']:.1e})"


def floquet_summary(k):
    """The multipliers column: windowed (certified of listed, largest |lambda|, max residual, verdict) or Arnoldi."""
    if "windowed_floquet" in k:
        w = k["windowed_floquet"]
        ms = w["multipliers"]
        certified = [m for m in ms if m["certified"]]
        top = max((m["modulus"] for m in certified), default=float("nan"))
        worst = max((m["residual"] for m in ms if m["residual"] is not None), default=float("nan"))
        return (f"window {w['window_sites']}/{w['check_window_sites']}: {len(certified)}/{len(ms)} certified, "
                f"max|l|={top:.6f}, residual<={worst:.1e}, {w['kind'] or w['reason']}" + background_summary(w))
    f = k.get("leading_floquet", {})
    ms = f.get("multipliers", [])
    top = ms[0]["modulus"] if ms else float("nan")
    return f"Arnoldi {len(ms)}/{f.get('requested')} converged, max|l|={top:.6f}"


def main():
    a = argparse.ArgumentParser()
    a.add_argument("--lrchain", default="build/cli/lrchain")
    a.add_argument("--sites", default="101,1001,10001")
    a.add_argument("--max-dense", type=int, default=1001)
    a.add_argument("--cases", default="")
    a.add_argument("--dark-arnoldi", action="store_true", help="dark rows by Arnoldi (--dark-floquet arnoldi)")
    args = a.parse_args()
    print(f"# {os.uname().nodename}, load: {os.getloadavg()}")
    print("| case | N | path | solve s | Floquet s | total s | peak MiB | Newton | GMRES its | Floquet |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, base in CASES.items():
        if args.cases not in name:
            continue
        for n in (int(s) for s in args.sites.split(",")):
            paths = ["krylov"] + (["dense"] if n <= args.max_dense else [])
            for path in paths:
                extra = []
                if base[0] == "dark" and path == "krylov":
                    extra = ["--dark-floquet", "arnoldi" if args.dark_arnoldi else "window"]
                wall, peak, j = run(args.lrchain, [*base, "--sites", str(n), "--solver", path, *extra])
                if "error" in j:
                    print(f"| {name} | {n} | {path} | - | - | {wall:.1f} | {peak:.0f} | {j['error']} | | |")
                    continue
                newton = len(j.get("newton_residuals", [])) - 1
                if path == "krylov":
                    k = j["krylov"]
                    print(f"| {name} | {n} | krylov | {k['solve_seconds']:.2f} | {floquet_seconds(k):.2f} | {wall:.1f} | "
                          f"{peak:.0f} | {newton} | {k['gmres_iterations']} | {floquet_summary(k)} |")
                else:
                    print(f"| {name} | {n} | dense | (in total) | (in total) | {wall:.1f} | {peak:.0f} | {newton} | - | all |")


if __name__ == "__main__":
    main()
