"""Focusing and defocusing regimes (Sec. 3.3 of the paper): the focusing theta-intervals of a branch,
the pixel maps of Fig. 2 (theta-rho plane) and Figs. 4-5 (delta0-omega plane), and the boundary
curves between the regions (omega'' = 0, h_tilde = 0 and the two non-resonance conditions).

The maps are ready for matplotlib::

    m = lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.01, 30, 600))
    plt.pcolormesh(m.rho, m.theta, m.values, shading="nearest")
"""

from dataclasses import dataclass
from math import pi

import numpy as np

from . import _lrchain
from ._keywords import real_numbers

#: Pixel values of the maps.
OUTSIDE, DEFOCUSING, FOCUSING, SINGULAR = -1, 0, 1, 2


@dataclass(frozen=True)
class Intervals:
    """Focusing intervals [lo[k], hi[k]] in (0, pi] and what ends each (``lo_cause``, ``hi_cause``:
    "curvature_zero", "h_tilde_zero", "nonresonance1", "nonresonance2" or "band_edge"), with every
    zero of the four smooth functions along (0, pi] (``roots``, ``root_cause``)."""

    lo: np.ndarray
    hi: np.ndarray
    lo_cause: list
    hi_cause: list
    roots: np.ndarray
    root_cause: list

    def __len__(self):
        return len(self.lo)

    def __iter__(self):
        return iter(zip(self.lo, self.hi))

    def __repr__(self):
        parts = ", ".join(f"[{a:.6f}, {b:.6f}]" for a, b in self)
        return f"Intervals({parts or 'none'})"


@real_numbers
def intervals(params, branch, samples=2048, tolerance=1e-12):
    """Focusing theta-intervals of ``branch`` (omega'' h_tilde < 0), found by root finding on the
    smooth functions whose signs decide the regime; each end accurate to ``tolerance``."""
    return Intervals(**_lrchain.regime_structure(params, branch, samples, tolerance))


@dataclass(frozen=True)
class RegimeMap:
    """sign(omega'' h_tilde) on a grid: ``values[j, i]`` at (``x[i]``, ``y[j]``), int8 with
    OUTSIDE (-1, out of the band), DEFOCUSING (0), FOCUSING (1), SINGULAR (2). ``pcolormesh(x, y,
    values)`` draws it; ``rho``/``theta`` (or ``delta0``/``omega``) name the axes."""

    x: np.ndarray
    y: np.ndarray
    values: np.ndarray
    x_name: str
    y_name: str

    def __getattr__(self, name):
        if name == self.__dict__.get("x_name"):
            return self.x
        if name == self.__dict__.get("y_name"):
            return self.y
        raise AttributeError(name)

    def __repr__(self):
        focusing = np.count_nonzero(self.values == FOCUSING) / self.values.size
        return (f"RegimeMap({self.x_name} x {self.y_name}: {self.values.shape[1]} x {self.values.shape[0]}, "
                f"focusing fraction {focusing:.3f})")


@real_numbers
def theta_rho_map(params, branch, rho=(0.01, 30.0, 600), theta=None, rho_log=False):
    """Fig. 2: the regime at (rho_i, theta_j); the other parameters from ``params``.

    ``rho`` = (lo, hi, n) with 0 < lo; ``theta`` = (lo, hi, n) inside (0, pi] (default (pi/600, pi,
    600)); ``rho_log`` spaces rho geometrically."""
    if theta is None:
        theta = (pi / 600, pi, 600)
    d = _lrchain.theta_rho_map(params, branch, rho[0], rho[1], int(rho[2]), theta[0], theta[1], int(theta[2]),
                               rho_log)
    return RegimeMap(d["x"], d["y"], d["values"], "rho", "theta")


@real_numbers
def delta0_omega_map(params, branch, delta0=(0.001, 1.0, 600), omega=None, delta0_log=False):
    """Figs. 4-5: the regime at (delta0_i, omega_j), theta from omega on the branch; pixels outside the
    band at delta0_i are OUTSIDE. ``omega`` = (lo, hi, n), by default the band of ``params``."""
    if omega is None:
        lo, hi = _lrchain.frequency_band(params, branch)
        omega = (lo, hi, 600)
    d = _lrchain.delta0_omega_map(params, branch, delta0[0], delta0[1], int(delta0[2]), omega[0], omega[1],
                                  int(omega[2]), delta0_log)
    return RegimeMap(d["x"], d["y"], d["values"], "delta0", "omega")


@dataclass(frozen=True)
class BoundaryCurve:
    """One traced zero curve: ``cause`` ("curvature_zero", "h_tilde_zero", "nonresonance1" or
    "nonresonance2") and ``points`` (k, 2): parameter value, theta (or omega)."""

    cause: str
    points: np.ndarray

    def __repr__(self):
        return f"BoundaryCurve({self.cause}, {len(self.points)} points)"


@real_numbers
def boundary_curves(params, branch, axis="rho", lo=0.01, hi=30.0, omega_plane=False):
    """Boundary curves between focusing and defocusing regions in the (axis, theta) plane for the
    parameter ``axis`` ("rho" or "delta0") in [lo, hi], traced by pseudo-arclength continuation;
    with ``omega_plane`` (axis "delta0") mapped to (delta0, omega) as in Figs. 4-5."""
    return [BoundaryCurve(cause, points)
            for cause, points in _lrchain.boundary_curves(params, branch, axis, lo, hi, omega_plane)]


@real_numbers
def frequency_band(params, branch):
    """(lo, hi) of the linear band: optical [omega_+(0), omega_+(pi)], acoustic [0, omega_-(pi)]."""
    return _lrchain.frequency_band(params, branch)
