#!/usr/bin/python3
"""Whole-process comparison of experiment 1 (examples/exp1_optical_pi2.toml: optical bright
breather, theta = pi/2, N = 500, 200 T_b) between lrchain and SciPy, start to finish, each process
timed from spawn to exit (median of REPEATS runs, interleaved):
  * lrchain simulate --config examples/exp1_optical_pi2.toml --no-figures
  * lrchain simulate --no-figures --out DIR bright --branch optical --theta pi/2 (default options: automatic srkn11b step)
  * /usr/bin/python3 bench/scipy_exp1.py: solve_ivp DOP853 at rtol 1e-10, E_x/E_y at every T_b/4
The ansatz constants of the SciPy run come from lrchain's summary JSON (not timed). Prints a JSON
report with the load average before and after each run. Run from the source directory:
  bench/scipy_compare.py path/to/lrchain [REPEATS=3]
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

lrchain = os.path.abspath(sys.argv[1])
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 3
here = os.path.dirname(os.path.abspath(__file__))
out = tempfile.mkdtemp(prefix="lrchain-scipy-compare-")
default_args = ["bright", "--branch", "optical", "--theta", "pi/2"]  # rho 1/3, N 500, 200 T_b: the defaults


def timed(argv):
    """Runs argv (no shell); returns (seconds from spawn to exit, stdout, load before, load after)."""
    load = os.getloadavg()[0]
    start = time.perf_counter()
    r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
    seconds = time.perf_counter() - start
    if r.returncode != 0:
        sys.exit(f"{argv[0]} failed ({r.returncode}): {r.stderr.strip()}")
    return seconds, r.stdout, load, os.getloadavg()[0]


def summary_of(stdout):
    return json.loads(stdout)


runs = {
    "lrchain_exp1_config": [lrchain, "simulate", "--config", "examples/exp1_optical_pi2.toml", "--no-figures",
                            "--out", os.path.join(out, "config")],
    "lrchain_default_options": [lrchain, "simulate", "--no-figures", "--out", os.path.join(out, "default")] + default_args,
}
ansatz = summary_of(timed(runs["lrchain_exp1_config"])[1])["ansatz"]
constants = [ansatz[k] for k in ("M1", "M2", "inverse_width", "group_velocity", "omega", "omega_b")]
runs["scipy_dop853_rtol_1e-10"] = ["/usr/bin/python3", os.path.join(here, "scipy_exp1.py")] + [repr(float(c)) for c in constants]

times = {k: [] for k in runs}
loads = {k: [] for k in runs}
outputs = {}
for _ in range(repeats):
    for name, argv in runs.items():
        seconds, stdout, before, after = timed(argv)
        times[name].append(seconds)
        loads[name].append([before, after])
        outputs[name] = stdout
report = {"repeats": repeats, "cores": os.cpu_count(), "median_seconds": {k: statistics.median(v) for k, v in times.items()},
          "seconds": times, "load_average_before_after": loads}
scipy = json.loads(outputs["scipy_dop853_rtol_1e-10"])
report["scipy"] = scipy
for name in ("lrchain_exp1_config", "lrchain_default_options"):
    j = summary_of(outputs[name])
    report[name] = {k: j.get(k) for k in ("max_E_x", "max_E_y", "final_E_x", "max_relative_energy_drift", "rhs_evaluations",
                                          "solve_seconds", "wall_seconds")}
    report["scipy_over_" + name] = report["median_seconds"]["scipy_dop853_rtol_1e-10"] / report["median_seconds"][name]
print(json.dumps(report, indent=2))
