"""Experiment 1 (Sec. 4.2, Figs. 6-7): the optical bright breather at theta = pi/2 followed for 200
breather periods; E_x(t), E_y(t) (distance from the NLS ansatz) and the energy density e_n(t).

    python3 exp1_bright_breather.py [--out DIR] [--periods P]
"""

import argparse
from math import pi
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import lrchain

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", type=Path, default=Path("."), help="directory for exp1_bright_breather.png")
parser.add_argument("--periods", type=float, default=200, help="run length in breather periods (default 200)")
args = parser.parse_args()

run = lrchain.simulate.bright(lrchain.Params(), "optical", pi / 2, sites=1001, periods=args.periods,
                              stepper="srkn11b", dt=0.37)
T_b = run.summary["ansatz"]["T_b"]
e = run.energy_density

fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
left.plot(run.t / T_b, 100 * run.E_x, label="E_x")
left.plot(run.t / T_b, 100 * run.E_y, label="E_y")
left.set(xlabel="t / T_b", ylabel="distance from the ansatz (%)", title=f"max E_x = {100 * run.E_x.max():.2f} %")
left.legend()
mesh = right.pcolormesh(e.n, e.t / T_b, e.values, shading="nearest", cmap="viridis")
right.plot(run.centre, run.t / T_b, color="white", lw=0.8, label="energy centre X(t)")
right.set(xlim=(-150, 150), xlabel="n", ylabel="t / T_b", title="energy density e_n(t)")
right.legend(loc="upper left")
fig.colorbar(mesh, ax=right)

args.out.mkdir(parents=True, exist_ok=True)
fig.savefig(args.out / "exp1_bright_breather.png", dpi=120)
print(args.out / "exp1_bright_breather.png", f"max E_x = {run.E_x.max():.5f}")
