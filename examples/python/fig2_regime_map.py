"""Fig. 2 of the paper: focusing (omega'' h_tilde < 0) and defocusing regions of the theta-rho plane
for both branches (alpha = 3/2, delta0 = 4/9, kappa = 1), with the boundary curves by cause.

    python3 fig2_regime_map.py [--out DIR] [--pixels N]
"""

import argparse
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.colors import ListedColormap

import lrchain

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", type=Path, default=Path("."), help="directory for fig2_regime_map.png")
parser.add_argument("--pixels", type=int, default=400, help="pixels per axis (default 400)")
args = parser.parse_args()

params = lrchain.Params()
colours = ListedColormap(["#d9d9d9", "#4a90d9", "black"])  # defocusing, focusing, singular
styles = {"curvature_zero": ("red", "omega'' = 0"), "h_tilde_zero": ("green", "h_tilde = 0"),
          "nonresonance1": ("orange", "eq. (nonresonance1)"), "nonresonance2": ("purple", "eq. (nonresonance2)")}

fig, axes = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
for ax, branch, rho_hi in zip(axes, ("optical", "acoustic"), (30.0, 2.5)):
    m = lrchain.regime.theta_rho_map(params, branch, rho=(0.01, rho_hi, args.pixels),
                                     theta=(3.141592653589793 / args.pixels, 3.141592653589793, args.pixels))
    ax.pcolormesh(m.rho, m.theta, m.values, shading="nearest", cmap=colours, vmin=0, vmax=2)
    labelled = set()
    for curve in lrchain.regime.boundary_curves(params, branch, axis="rho", lo=0.01, hi=rho_hi):
        colour, label = styles[curve.cause]
        ax.plot(curve.points[:, 0], curve.points[:, 1], color=colour, lw=1,
                label=None if curve.cause in labelled else label)
        labelled.add(curve.cause)
    ax.set(xlabel="rho", ylabel="theta", title=f"{branch} branch (blue: focusing)")
    ax.legend(loc="upper right", fontsize=8)

args.out.mkdir(parents=True, exist_ok=True)
fig.savefig(args.out / "fig2_regime_map.png", dpi=120)
print(args.out / "fig2_regime_map.png")
