#!/usr/bin/env python3
"""Rate of lrchain.coefficients(params, branch, theta_array): coefficient sets per second on one core.

Usage: PYTHONPATH=<build>/python python3 bench/python_coefficients_rate.py [--size N] [--repeats R]

Prints, per branch, the best of R calls on N random wavenumbers in (-pi, pi], as wall-clock and
as this thread's CPU time (the CPU-time rate is the per-core rate when the machine is loaded), with
new output arrays (their page faults included) and with out= reusing an earlier result's arrays,
and the rate of numpy's sin+cos of theta/2 on the same array for scale.
"""

import argparse
import time

import numpy as np

import lrchain


def best_rate(function, size, repeats):
    wall, cpu = float("inf"), float("inf")
    for _ in range(repeats):
        w0, c0 = time.perf_counter(), time.thread_time()
        function()
        wall = min(wall, time.perf_counter() - w0)
        cpu = min(cpu, time.thread_time() - c0)
    return size / wall, size / cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1_000_000, help="wavenumbers per call (default 1e6)")
    parser.add_argument("--repeats", type=int, default=10, help="calls per measurement (best is kept)")
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    theta = rng.uniform(-np.pi, np.pi, args.size)
    theta[theta == 0] = 0.5
    params = lrchain.Params()
    for branch in ("optical", "acoustic"):
        lrchain.coefficients(params, branch, theta)  # warm-up: the output arrays' memory
        wall, cpu = best_rate(lambda: lrchain.coefficients(params, branch, theta), args.size, args.repeats)
        print(f"lrchain.coefficients {branch:8s}: {wall / 1e6:6.1f} M sets/s wall, {cpu / 1e6:6.1f} M sets/s CPU "
              f"({args.size} wavenumbers, best of {args.repeats}, new arrays)")
        out = lrchain.coefficients(params, branch, theta)
        wall, cpu = best_rate(lambda: lrchain.coefficients(params, branch, theta, out=out), args.size, args.repeats)
        print(f"lrchain.coefficients {branch:8s}: {wall / 1e6:6.1f} M sets/s wall, {cpu / 1e6:6.1f} M sets/s CPU "
              f"({args.size} wavenumbers, best of {args.repeats}, out= reused)")
    half = 0.5 * theta
    wall, cpu = best_rate(lambda: (np.sin(half), np.cos(half)), args.size, args.repeats)
    print(f"numpy sin + cos of theta/2 : {wall / 1e6:6.1f} M/s wall, {cpu / 1e6:6.1f} M/s CPU (for scale)")


if __name__ == "__main__":
    main()
