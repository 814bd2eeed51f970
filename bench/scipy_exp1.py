#!/usr/bin/python3
"""Experiment 1 of the paper (optical bright breather, theta = pi/2, N = 500, 200 T_b) with SciPy:
the displacement lattice eq:Hertz with free ends, started from the NLS ansatz eq:focus_app /
eq:focus_ini, integrated by solve_ivp DOP853 at rtol 1e-10, with E_x, E_y (max over the strains of
|x - x^A| / max|x(0)|) at every T_b/4, as lrchain's bright run does. The ansatz's constants (M1, M2,
a, c, omega, omega_b) are arguments: scipy_compare.py takes them from lrchain's summary JSON.
Prints one JSON line: max E_x, E_y, final E_x, relative energy drift, RHS evaluations, seconds.
  scipy_exp1.py M1 M2 a c omega omega_b [N=500] [periods=200]
"""
import json
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

start = time.perf_counter()
M1, M2, a, c, omega, omega_b = (float(v) for v in sys.argv[1:7])
N = int(sys.argv[7]) if len(sys.argv) > 7 else 500
periods = float(sys.argv[8]) if len(sys.argv) > 8 else 200.0
rho, kappa, delta0, alpha = 1.0 / 3.0, 1.0, 4.0 / 9.0, 1.5
theta = np.pi / 2
B = kappa / (kappa - rho * omega * omega)
beads = 2 * N + 2
n = np.arange(-N - 1, N + 1, dtype=float)  # bead labels -N-1 .. N
d0a = delta0 ** alpha


def displacements(t):
    """u_n^A, v_n^A of eq:focus_app (lrchain's BrightBreatherAnsatz::displacements)."""
    z = a * (n - c * t)
    osc = 2 * M2 / np.cosh(z) * np.cos(n * theta - omega_b * t)
    return M1 * np.tanh(z) + osc, M1 * np.tanh(z) + B * osc


def velocities(t):
    z = a * (n - c * t)
    sech, th, phase = 1 / np.cosh(z), np.tanh(z), n * theta - omega_b * t
    kink = -c * a * M1 * sech * sech
    osc = 2 * M2 * (c * a * th * sech * np.cos(phase) + omega_b * sech * np.sin(phase))
    return kink + osc, kink + B * osc


def rhs(t, s):
    u, v, ud, vd = s[:beads], s[beads:2 * beads], s[2 * beads:3 * beads], s[3 * beads:]
    f = np.zeros(beads + 1)  # f[i] = V'(u_i - u_{i-1}); zero beyond the free ends
    f[1:beads] = d0a - np.maximum(delta0 - np.diff(u), 0.0) ** alpha
    coupling = kappa * (u - v)
    return np.concatenate((ud, vd, f[1:] - f[:-1] - coupling, coupling / rho))


def energy(s):
    u, v, ud, vd = s[:beads], s[beads:2 * beads], s[2 * beads:3 * beads], s[3 * beads:]
    r = np.diff(u)
    V = (np.maximum(delta0 - r, 0.0) ** (alpha + 1) - delta0 ** (alpha + 1)) / (alpha + 1) + d0a * r
    return 0.5 * np.sum(ud * ud) + 0.5 * rho * np.sum(vd * vd) + np.sum(V) + 0.5 * kappa * np.sum((u - v) ** 2)


u0, v0 = displacements(0.0)
ud0, vd0 = velocities(0.0)
s0 = np.concatenate((u0, v0, ud0, vd0))
Tb = 2 * np.pi / omega_b
t_end = periods * Tb
samples = np.arange(0, int(round(periods / 0.25)) + 1) * 0.25 * Tb
sol = solve_ivp(rhs, (0.0, t_end), s0, method="DOP853", rtol=1e-10, atol=1e-12, t_eval=samples)
x = np.diff(sol.y[:beads], axis=0)
y = np.diff(sol.y[beads:2 * beads], axis=0)
x0, y0 = np.max(np.abs(x[:, 0])), np.max(np.abs(y[:, 0]))
Ex, Ey = [], []
for k, t in enumerate(sol.t):
    ua, va = displacements(t)
    Ex.append(np.max(np.abs(x[:, k] - np.diff(ua))) / x0)
    Ey.append(np.max(np.abs(y[:, k] - np.diff(va))) / y0)
e0 = energy(s0)
drift = max(abs(energy(sol.y[:, k]) - e0) for k in range(0, len(sol.t), 8)) / abs(e0)
print(json.dumps({"max_Ex": max(Ex), "max_Ey": max(Ey), "final_Ex": Ex[-1], "max_energy_drift": drift,
                  "rhs_evaluations": int(sol.nfev), "success": bool(sol.success),
                  "seconds_in_python": time.perf_counter() - start}))
