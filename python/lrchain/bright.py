"""Exact bright breathers of any lattice (docs/bright-breathers.md): time-periodic, localized solutions
of a model's lattice above its top band or in a gap, found by shooting Newton from the NLS bright
breather at the focusing band edge omega_b leaves, checked to be localized, with their Floquet
multipliers (the trivial +1 ones identified and removed). The functions are ``lrchain bright
solve|floquet``: the same job (lrchain/jobs/bright_breather_job.hpp), its defaults from the job's one
schema.

``model`` is an :class:`lrchain.Model` (``lrchain.load_model("klein_gordon")`` or your own model file),
default the paper's resonant chain, whose band edges are all defocusing (so it is refused: it has dark
breathers there, :mod:`lrchain.dark`). A frequency inside a band, a harmonic k omega_b inside one, or no
focusing edge raises :class:`lrchain.InvalidParameterError` naming ``omega_b``; a Newton that does not
converge, or converges to something that is no localized bright breather, raises
:class:`lrchain.NumericalFailure`. Ctrl-C raises ``KeyboardInterrupt`` after the current Newton step.
"""

import json
from dataclasses import dataclass

import numpy as np

from . import _lrchain
from ._keywords import checked_model, documented, python_names, real_numbers, schema_options

# The job's defaults, from its one schema (lrchain/jobs/bright_breather_schema.hpp): keyword -> default.
_D = {name: o["default"] for name, o in schema_options("bright breather").items()}
_SECTION = ("bright breather", "Options (the job's schema, as ``lrchain bright ... --help``):")


def _complex(pairs):
    return np.array([complex(re, im) for re, im in pairs], dtype=complex)


@dataclass(frozen=True, repr=False)
class BrightFloquet:
    """Floquet multipliers of a bright breather: ``multipliers`` (complex, |lambda| descending),
    ``trivial`` (the ones identified as the trivial +1 pair(s): ``trivial_expected`` = 2, 4 with a mean
    flow; ``trivial_found`` when they lie within 1e-3 of +1, ``trivial_distance`` their largest
    |lambda - 1|), ``stable`` (every other |lambda| <= 1 + unit_tolerance), ``kind``,
    ``max_nontrivial_modulus``, ``unit_circle_defect`` (max ||lambda| - 1| of the others),
    ``pairing_defect`` and ``det_defect`` = |det M - 1| (accuracy of the symplectic structure); from
    :func:`floquet`, ``krein``: per multiplier on the upper unit circle a dict angle, modulus and signature
    (+1, -1, None when undetermined), so that an oscillatory instability's colliding pair is labelled."""

    multipliers: np.ndarray
    trivial: np.ndarray
    trivial_expected: int
    trivial_found: bool
    trivial_distance: float
    stable: bool
    kind: str
    max_nontrivial_modulus: float
    unit_circle_defect: float
    pairing_defect: float
    det_defect: float
    krein: list = None

    def __repr__(self):
        return (f"BrightFloquet({'stable' if self.stable else self.kind}, {len(self.multipliers)} multipliers, "
                f"max non-trivial |lambda| = {self.max_nontrivial_modulus:.6g})")


@dataclass(frozen=True, repr=False)
class BrightBreather:
    """A converged, localized bright breather: Z(0) as ``z`` (fields x sites, the lattice's ``variables``:
    strains r, w1, ... of a translation-invariant model or displacements u0, u1, ...) on sites ``n``
    (centred), the NLS ``seed`` in the same variables, ``newton_residuals``, the ``edge`` it leaves
    (branch, theta, omega, curvature, h_tilde, lambda, seed_amplitude, seed_inverse_width), the linear
    ``bands`` and ``harmonics_checked``, the ``profile`` and ``seed_profile`` (peak, peak_site, tail,
    width, norm_squared, localized), ``seed_difference`` (max |Z(0) - seed| / max |Z(0)|), ``floquet`` (a
    :class:`BrightFloquet`, or None) and the job's whole JSON ``summary`` (as ``lrchain bright`` prints).
    ``to_hdf5(path)`` writes the file ``lrchain bright solve|floquet --format hdf5`` writes
    (:mod:`lrchain.hdf5`); :func:`lrchain.load` reads it back; ``to_xarray()`` gives a Dataset."""

    omega_b: float
    center: str
    n: np.ndarray
    z: np.ndarray
    seed: np.ndarray
    variables: tuple
    newton_residuals: np.ndarray
    edge: dict
    bands: list
    harmonics_checked: int
    profile: dict
    seed_profile: dict
    seed_difference: float
    floquet: BrightFloquet
    summary: dict

    def to_hdf5(self, path):
        """Writes the breather with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        _write(path, self, None)

    def __repr__(self):
        f = f", {self.floquet!r}" if self.floquet else ""
        return (f"BrightBreather(omega_b={self.omega_b}, {self.center}-centred, {len(self.n)} sites, peak "
                f"{self.profile['peak']:.6g}, Newton residual {self.newton_residuals[-1]:.3g} after "
                f"{len(self.newton_residuals) - 1} steps{f})")


def _write(path, breather, branch_z, evolution=None):
    """A bright breather (branch_z None), a branch (its start and every point's Z(0)) or an evolution (its
    breather and the series per period) to ``path``."""
    from . import _hdf5
    from .hdf5 import checked_destination

    series = {}
    if evolution is not None:
        has_energy = breather.summary["evolution"]["energy"] is not None
        series = dict(evolution_t=np.asarray(evolution.t, float),
                      evolution_deviation=np.asarray(evolution.deviation, float),
                      evolution_energy=np.asarray(evolution.energy, float) if has_energy else None)
    _hdf5.write_bright_breather(checked_destination(path), json.dumps(breather.summary), list(breather.variables),
                                np.asarray(breather.z, float), np.asarray(breather.seed, float),
                                None if branch_z is None else np.asarray(branch_z, float), **series)


def _breather(d):
    z, seed, variables = d.pop("z"), d.pop("seed"), d.pop("variables")
    sites = d["sites"]
    floquet = d.get("floquet")
    if floquet is not None:
        floquet = BrightFloquet(
            multipliers=_complex(floquet["multipliers"]), trivial=_complex(floquet["trivial"]),
            **{k: floquet[k] for k in ("trivial_expected", "trivial_found", "trivial_distance", "stable", "kind",
                                       "max_nontrivial_modulus", "unit_circle_defect", "pairing_defect",
                                       "det_defect")}, krein=floquet.get("krein"))
    return BrightBreather(omega_b=d["omega_b"], center=d["center"], n=np.arange(sites) - (sites - 1) // 2, z=z,
                          seed=seed, variables=variables, newton_residuals=np.array(d["newton_residuals"]),
                          edge=d["edge"], bands=d["bands"], harmonics_checked=d["harmonics_checked"],
                          profile=d["profile"], seed_profile=d["seed_profile"], seed_difference=d["seed_difference"],
                          floquet=floquet, summary=d)


def _model(model):
    if model is None:
        from .model import load_model

        return load_model("resonant_chain")
    return checked_model(model)


# The job's result as a dict (its JSON summary, Z(0) and the seed as arrays; branch_z for a branch).
def _run(model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance, unit_tolerance, step,
         points=_D["points"], ds=_D["ds"], branch_floquet=_D["floquet"], periods=_D["periods"],
         perturb=_D["perturb"], perturb_size=_D["perturb_size"], seed=_D["seed"], parameter=_D["parameter"], to=None,
         locate_tolerance=_D["locate_tolerance"], start=_D["start"], coupling=_D["coupling"]):
    model = _model(model)
    if omega_b is None:
        from .errors import InvalidParameterError

        raise InvalidParameterError("invalid omega_b: required (the breather frequency, beyond a focusing band "
                                    "edge of the model)", "omega_b")
    return python_names(lambda: _lrchain.bright_breather_solve(
        model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance, unit_tolerance, step, points,
        ds, branch_floquet, periods, perturb, perturb_size, seed, parameter, to, locate_tolerance, start, coupling))


@documented(_SECTION)
@real_numbers
def solve(model=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], tolerance=_D["tolerance"],
          max_iterations=_D["max_iterations"], tail_tolerance=_D["tail_tolerance"], start=_D["start"],
          coupling=_D["coupling"]):
    """Newton from the NLS bright-breather seed, checked to be a localized breather; returns
    :class:`BrightBreather`. ``omega_b`` is required.

    Example::

        >>> import lrchain
        >>> b = lrchain.bright.solve(lrchain.load_model("klein_gordon"), omega_b=1.19, sites=81)
        >>> b.center, bool(b.newton_residuals[-1] < 1e-10), bool(b.profile["localized"])
        ('site', True, True)
    """
    return _breather(_run(model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance,
                          _D["unit_tolerance"], "solve", start=start, coupling=coupling))


@documented(_SECTION)
@real_numbers
def floquet(model=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], tolerance=_D["tolerance"],
            max_iterations=_D["max_iterations"], tail_tolerance=_D["tail_tolerance"],
            unit_tolerance=_D["unit_tolerance"], start=_D["start"], coupling=_D["coupling"]):
    """Solve, then the Floquet multipliers of the full-period monodromy matrix, the trivial +1 ones
    removed; returns :class:`BrightBreather` with ``floquet`` set.

    The FPU chain's Page mode is stable.

    Example::

        >>> import lrchain
        >>> b = lrchain.bright.floquet(lrchain.load_model("fput", a=0), omega_b=2.2, center="bond", sites=41)
        >>> b.floquet.stable, bool(b.floquet.unit_circle_defect < 1e-8)
        (True, True)
    """
    return _breather(_run(model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance,
                          unit_tolerance, "floquet", start=start, coupling=coupling))


@dataclass(frozen=True, repr=False)
class BrightBranch:
    """A bright-breather family continued in omega_b away from its band edge: the first point ``start`` (a
    :class:`BrightBreather`), per point ``omega_b``, ``peak``, ``norm_squared``, ``width``, ``stable`` and
    ``max_nontrivial_modulus`` (None without Floquet), ``z`` (points x fields x sites), the
    ``turning_points``, the non-resonant ``window`` (low, high; high None when unbounded), ``stop_reason``,
    ``bifurcations`` (dicts: kind fold | branch_point | period_doubling | period_tripling | krein_collision,
    index, omega_b, norm_squared, omega_low, omega_high, located, location_error, multiplier [re, im] and
    multiplier_modulus, None when not located) and ``krein`` (per point a list of dicts angle, modulus,
    signature for the multipliers on the upper unit circle, in strain form of the eigenvectors lifted to
    displacements; None without Floquet), the
    continued ``parameter`` (omega_b or a model parameter at fixed omega_b) and its ``values`` per point.
    ``to_hdf5(path)`` writes the file ``lrchain bright continue --format hdf5`` writes (:mod:`lrchain.hdf5`);
    :func:`lrchain.load` reads it back; ``to_xarray()`` gives a Dataset on ``point``."""

    start: BrightBreather
    omega_b: np.ndarray
    peak: np.ndarray
    norm_squared: np.ndarray
    width: np.ndarray
    stable: list
    max_nontrivial_modulus: list
    z: np.ndarray
    turning_points: list
    window: tuple
    stop_reason: str
    bifurcations: list
    krein: list
    parameter: str = "omega_b"
    values: np.ndarray = None

    def to_hdf5(self, path):
        """Writes the branch with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        _write(path, self.start, self.z)

    def __repr__(self):
        return (f"BrightBranch({len(self.omega_b)} points, omega_b {self.omega_b[0]:.6g} .. {self.omega_b[-1]:.6g}, "
                f"{self.stop_reason})")


@documented(_SECTION)
@real_numbers
def continue_branch(model=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"],
                    tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], tail_tolerance=_D["tail_tolerance"],
                    unit_tolerance=_D["unit_tolerance"], points=_D["points"], ds=_D["ds"], floquet=_D["floquet"],
                    parameter=_D["parameter"], to=None, locate_tolerance=_D["locate_tolerance"], start=_D["start"],
                    coupling=_D["coupling"]):
    """Solve, then pseudo-arclength continuation in omega_b away from the band edge within the window where
    no harmonic meets a band (or to ``to``), or with ``parameter`` a model parameter at fixed omega_b from
    its value to ``to`` (e.g. the coupling ``C`` of klein_gordon towards the anti-continuum limit), each
    point checked to be a localized breather; returns :class:`BrightBranch`. Each multiplier crossing
    is located by bisection on re-solved breathers to a bracket ``locate_tolerance`` wide in the continued
    parameter (0: the branch points' bracket only).

    Example::

        >>> import lrchain
        >>> b = lrchain.bright.continue_branch(lrchain.load_model("klein_gordon"), omega_b=1.19, sites=81, points=4)
        >>> len(b.omega_b), bool(b.omega_b[-1] > 1.19)
        (4, True)
    """
    d = _run(model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance, unit_tolerance,
             "continue", points, ds, floquet, parameter=parameter, to=to, locate_tolerance=locate_tolerance,
             start=start, coupling=coupling)
    return _branch(d)


def _branch(d):
    """The BrightBranch of the job's dict (its summary, Z(0), the seed, variables and branch_z)."""
    z = d.pop("branch_z")
    start = _breather(d)
    b = start.summary["branch"]
    rows = b["branch_points"]
    return BrightBranch(
        start=start, omega_b=np.array([p["omega_b"] for p in rows]), peak=np.array([p["peak"] for p in rows]),
        norm_squared=np.array([p["norm_squared"] for p in rows]), width=np.array([p["width"] for p in rows]),
        stable=[p["stable"] for p in rows], max_nontrivial_modulus=[p["max_nontrivial_modulus"] for p in rows],
        z=z, turning_points=b["turning_points"], window=tuple(b["window"]),
        stop_reason=b["stop_reason"], bifurcations=b["bifurcations"], krein=[p["krein"] for p in rows],
        parameter=b.get("parameter", "omega_b"), values=np.array([p[b.get("parameter", "omega_b")] for p in rows]))


@dataclass(frozen=True, repr=False)
class BrightEvolution:
    """An exact bright breather integrated on its lattice (``lrchain bright evolve``): the ``breather`` (a
    :class:`BrightBreather` with its ``floquet``), per period m = 0..periods the time ``t`` = m T_b, the
    ``deviation`` max|[Z, Zdot](t) - [Z(0), 0]| and the lattice ``energy``; ``profile_drift`` (max
    deviation / peak over m >= 1), ``energy_drift`` (max |E - E(0)| / |E(0)|), the measured
    ``growth_rate`` of ln(deviation) (None when it saturates within 3 periods) beside the
    ``predicted_growth_rate`` ln(max |lambda|) / T_b, and the ``perturbation`` (dict, or None).
    ``to_hdf5(path)`` writes the file ``lrchain bright evolve --format hdf5`` writes (:mod:`lrchain.hdf5`);
    :func:`lrchain.load` reads it back."""

    breather: BrightBreather
    t: np.ndarray
    deviation: np.ndarray
    energy: np.ndarray
    profile_drift: float
    energy_drift: float
    growth_rate: float
    predicted_growth_rate: float
    perturbation: dict

    def to_hdf5(self, path):
        """Writes the breather and its series with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        _write(path, self.breather, None, self)

    def __repr__(self):
        return (f"BrightEvolution({len(self.t) - 1} periods, profile drift {self.profile_drift:.3g}, growth rate "
                f"{self.growth_rate} (predicted {self.predicted_growth_rate:.6g}))")


@documented(_SECTION)
@real_numbers
def evolve(model=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], tolerance=_D["tolerance"],
           max_iterations=_D["max_iterations"], tail_tolerance=_D["tail_tolerance"],
           unit_tolerance=_D["unit_tolerance"], periods=_D["periods"], perturb=_D["perturb"],
           perturb_size=_D["perturb_size"], seed=_D["seed"], start=_D["start"], coupling=_D["coupling"]):
    """Solve, Floquet, then integrate the breather (plus a perturbation: ``perturb`` none | unstable |
    random) over ``periods`` periods; returns :class:`BrightEvolution`. ``perturb="unstable"`` on a stable
    breather raises :class:`lrchain.InvalidParameterError` naming ``perturb``.

    The FPU chain's Sievers-Takeno mode departs at the rate its unstable multiplier predicts.

    Example::

        >>> import lrchain
        >>> e = lrchain.bright.evolve(lrchain.load_model("fput", a=0), omega_b=2.2, center="site", sites=41,
        ...                           periods=30, perturb="unstable")
        >>> bool(abs(e.growth_rate / e.predicted_growth_rate - 1) < 0.05)
        True
    """
    d = _run(model, omega_b, branch, center, sites, tolerance, max_iterations, tail_tolerance, unit_tolerance,
             "evolve", periods=periods, perturb=perturb, perturb_size=perturb_size, seed=seed, start=start,
             coupling=coupling)
    return _evolution(d, d.pop("evolution_t"), d.pop("evolution_deviation"), d.pop("evolution_energy"))


def _evolution(d, t, deviation, energy):
    """The job's dict and its series per period as :class:`BrightEvolution` (``evolve`` and lrchain.load)."""
    e = d["evolution"]
    return BrightEvolution(breather=_breather(d), t=t, deviation=deviation, energy=energy,
                           profile_drift=e["profile_drift"], energy_drift=e["energy_drift"],
                           growth_rate=e["growth_rate"], predicted_growth_rate=e["predicted_growth_rate"],
                           perturbation=e["perturbation"])
