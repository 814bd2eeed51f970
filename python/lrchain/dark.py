"""Exact stationary dark breathers (Sec. 5.3-5.4 of the paper): time-periodic solutions of the strain
lattice with periodic ends, found by shooting Newton from the NLS approximation (eq. xy_app),
continued in the frequency omega_b, with their Floquet multipliers and direct evolution.

Every function starts from ``solve``'s arguments: ``params``, ``omega_b`` (on the gap side of the
theta = pi band edge ``edge``, "optical" or "acoustic"), ``center`` ("bond" or "site"), ``sites``
(odd, >= 9), ``mode`` ("reversible" or "full" shooting), Newton's ``tolerance`` (max |F|) and
``max_iterations``. Newton failing raises :class:`lrchain.NumericalFailure`; Ctrl-C during any of
these computations (Newton, the Floquet multipliers' monodromy matrix, continuation, evolution)
stops it within one integration step and raises ``KeyboardInterrupt``.
"""

from dataclasses import asdict, dataclass, fields
import os

import numpy as np

from . import _lrchain
from ._lrchain import Params
from .hdf5 import HDF5Mixin


@dataclass(frozen=True)
class Floquet:
    """Floquet multipliers (complex array) of the monodromy matrix over one period and their
    classification: ``kind`` ("stable" or e.g. "real+oscillatory"), ``max_modulus``, ``max_real``,
    ``max_period_doubling``, ``max_oscillatory``, ``near_one`` (multipliers near +1: symmetry modes),
    ``pairing_defect`` (max distance of lambda's partner 1/conj(lambda) from the spectrum: 0 for a
    symplectic monodromy), ``conjugation_defect``, ``log_det``."""

    multipliers: np.ndarray
    kind: str
    max_modulus: float
    max_real: float
    max_period_doubling: float
    max_oscillatory: float
    near_one: int
    pairing_defect: float
    conjugation_defect: float
    log_det: float

    def __repr__(self):
        return f"Floquet({self.kind}, {len(self.multipliers)} multipliers, max |lambda| = {self.max_modulus:.6g})"


def _params_tuple(params):
    p = Params() if params is None else params
    return (p.alpha, p.delta0, p.kappa, p.rho)


def _plain(result):
    """The result's fields as a dict, Floquet results as dicts (the C++ writer's input)."""
    d = {f.name: getattr(result, f.name) for f in fields(result)}
    floquet = d.get("floquet")
    if isinstance(floquet, Floquet):
        d["floquet"] = asdict(floquet)
    elif isinstance(floquet, list):
        d["floquet"] = [asdict(f) for f in floquet] if floquet and all(f is not None for f in floquet) else None
    return d


@dataclass(frozen=True, repr=False)
class DarkSolution(HDF5Mixin):
    """A converged dark breather: profile ``x``, ``y`` = Z(0) on sites ``n`` (centred), the NLS seed
    ``x_seed``, ``y_seed``, Newton's residual history, the band-edge frequency ``omega_edge``,
    ``measures`` (norm_squared, K_x, K_y, C_x, C_y, E_b = relative error after one period,
    max_strain) and ``floquet`` (a :class:`Floquet`, or None)."""

    omega_b: float
    n: np.ndarray
    x: np.ndarray
    y: np.ndarray
    x_seed: np.ndarray
    y_seed: np.ndarray
    newton_residuals: np.ndarray
    omega_edge: float
    measures: dict
    floquet: Floquet = None
    params: Params = None

    def to_hdf5(self, path):
        """Writes this solution with the C++ library's writer, the file ``lrchain dark solve|floquet
        --format hdf5`` writes (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_dark_solution(os.fspath(path), _params_tuple(self.params), _plain(self))

    def __repr__(self):
        f = f", {self.floquet!r}" if self.floquet else ""
        return (f"DarkSolution(omega_b={self.omega_b}, {len(self.n)} sites, Newton residual "
                f"{self.newton_residuals[-1]:.3g} after {len(self.newton_residuals) - 1} steps, "
                f"E_b = {self.measures['E_b']:.3g}{f})")


def _floquet(d):
    return None if d is None else Floquet(**d)


def _solution(params, omega_b, d):
    return DarkSolution(omega_b=omega_b, floquet=_floquet(d.pop("floquet", None)), params=params, **d)


def solve(params=None, omega_b=2.42, edge="optical", center="bond", sites=101, mode="reversible",
          tolerance=1e-11, max_iterations=20):
    """Newton (least squares) from the eq. xy_app seed; returns :class:`DarkSolution`."""
    params = Params() if params is None else params
    d = _lrchain.dark_solve(params, omega_b, edge, center, sites, mode, tolerance, max_iterations, False, False)
    return _solution(params, omega_b, d)


def floquet(params=None, omega_b=2.42, edge="optical", center="bond", sites=101, mode="reversible",
            tolerance=1e-11, max_iterations=20, full_monodromy=False):
    """Solve, then the Floquet multipliers of the monodromy matrix (from the reversible reduction,
    or integrated over a full period with ``full_monodromy``); returns :class:`DarkSolution` with
    ``floquet`` set."""
    params = Params() if params is None else params
    d = _lrchain.dark_solve(params, omega_b, edge, center, sites, mode, tolerance, max_iterations, True,
                            full_monodromy)
    return _solution(params, omega_b, d)


@dataclass(frozen=True, repr=False)
class Branch(HDF5Mixin):
    """A branch of dark breathers from pseudo-arclength continuation in omega_b: per point
    ``omega_b``, profiles ``x``, ``y`` (points, sites), ``norm_squared`` and the other ``measures``
    (list of dicts), ``floquet`` (list of :class:`Floquet` or None), ``max_modulus``, ``kind``;
    ``turning_points`` (omega_b where d omega_b/ds changes sign) and ``stop_reason``. ``to_hdf5(path)``
    writes the profiles, measures and Floquet spectra (multipliers as a complex (points, 4N) array)."""

    omega_b: np.ndarray
    tangent_omega: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    x: np.ndarray
    y: np.ndarray
    measures: list
    floquet: list
    turning_points: list
    stop_reason: str
    params: Params = None

    def to_hdf5(self, path):
        """Writes the branch with the C++ library's writer, the file ``lrchain dark continue --format
        hdf5`` writes: profiles, measures and Floquet spectra (multipliers as a complex (points, 4N)
        array; layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_dark_branch(os.fspath(path), _params_tuple(self.params), _plain(self))

    @property
    def norm_squared(self):
        return np.array([m["norm_squared"] for m in self.measures])

    @property
    def max_modulus(self):
        return np.array([f.max_modulus if f else np.nan for f in self.floquet])

    @property
    def kind(self):
        return [f.kind if f else None for f in self.floquet]

    def __repr__(self):
        return (f"Branch({len(self.omega_b)} points, omega_b {self.omega_b[0]:.6g} .. {self.omega_b[-1]:.6g}, "
                f"{len(self.turning_points)} turning points; {self.stop_reason})")


def continue_branch(params=None, omega_b=2.42, edge="optical", center="bond", sites=101, mode="reversible",
                    tolerance=1e-11, max_iterations=20, points=100, ds=0.1, omega_min=0.0, omega_max=None,
                    floquet=True):
    """Solve at ``omega_b``, then continue the family (at most ``points`` points, initial arclength step
    ``ds``) while omega_b stays in [omega_min, omega_max] (default: up to the band edge), with the
    Floquet multipliers at every point if ``floquet``; returns :class:`Branch`."""
    params = Params() if params is None else params
    d = _lrchain.dark_continue(params, omega_b, edge, center, sites, mode, tolerance, max_iterations, points, ds,
                               omega_min, omega_max, floquet)
    d["floquet"] = [_floquet(f) for f in d["floquet"]]
    return Branch(params=params, **d)


@dataclass(frozen=True, repr=False)
class Evolution(HDF5Mixin):
    """Direct integration from an exact dark breather: per period m = 1..M the time ``t`` = m T_b, the
    relative error ``E_b``, vertical centre ``C_x`` and amplitude ``K_x`` at the far site, breather
    ``position`` and ``depth``; stroboscopic strains ``x``, ``y`` (M+1, sites) at t = m T_b, m = 0..M;
    ``period`` T_b and ``max_strain``."""

    period: float
    t: np.ndarray
    E_b: np.ndarray
    C_x: np.ndarray
    K_x: np.ndarray
    position: np.ndarray
    depth: np.ndarray
    x: np.ndarray
    y: np.ndarray
    max_strain: float

    def __repr__(self):
        return f"Evolution({len(self.t)} periods to t = {self.t[-1]:g}, max E_b = {self.E_b.max():.3g})"


def evolve(params=None, omega_b=2.42, edge="optical", center="bond", sites=101, mode="reversible",
           tolerance=1e-11, max_iterations=20, t_end=None, samples=24):
    """Solve, then integrate from Z(0) over floor(t_end / T_b) periods (default: 10 periods),
    sampling every site ``samples`` times per period for the position measure; returns
    :class:`Evolution`. Ctrl-C interrupts it with ``KeyboardInterrupt``."""
    params = Params() if params is None else params
    if t_end is None:
        t_end = 10 * 2 * np.pi / omega_b
    d = _lrchain.dark_evolve(params, omega_b, edge, center, sites, mode, tolerance, max_iterations, t_end, samples)
    return Evolution(**d)
