"""A branch of bond-centred dark breathers below the optical edge (Sec. 5.3-5.4): the norm along the
branch and the Floquet moduli |lambda| > 1 at every point (alpha = 3/2, delta0 = 4/9, kappa = 1,
rho = 1/3), continued from omega_b = 2.42.

    python3 dark_branch_floquet.py [--out DIR] [--points K] [--sites N]
"""

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import lrchain

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", type=Path, default=Path("."), help="directory for dark_branch_floquet.png")
parser.add_argument("--points", type=int, default=40, help="branch points (default 40)")
parser.add_argument("--sites", type=int, default=101, help="odd number of sites (default 101)")
args = parser.parse_args()

branch = lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=args.sites, points=args.points, ds=0.1)

fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True, constrained_layout=True)
top.plot(branch.omega_b, branch.norm_squared, "o-", ms=3)
top.set(ylabel="||Z(0)||^2 (eq. l2norm)", title=f"dark breathers, {len(branch.omega_b)} points: {branch.stop_reason}")
for omega_b, f in zip(branch.omega_b, branch.floquet):
    moduli = np.abs(f.multipliers)
    unstable = moduli[moduli > 1 + 1e-6]
    bottom.plot(np.full(unstable.shape, omega_b), unstable, "r.", ms=4)
bottom.axhline(1, color="grey", ls="--", lw=0.8)
bottom.set(xlabel="omega_b", ylabel="|lambda| > 1", title="Floquet moduli off the unit circle")

args.out.mkdir(parents=True, exist_ok=True)
fig.savefig(args.out / "dark_branch_floquet.png", dpi=120)
print(args.out / "dark_branch_floquet.png")
