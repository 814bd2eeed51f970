"""Exact periodic travelling waves of any lattice and their stability (docs/waves.md):
u_n(t) = U(theta n - omega t) for every field, solved as a 2 pi-periodic function of the phase by
collocation (harmonic balance) and Newton with the phase fixed, the number of harmonics chosen by a
tolerance on the tail; continued in the amplitude A (the first field's cos xi harmonic) from the linear
wave; and the Floquet-Bloch growth rates max Re lambda of perturbations e^{lambda t + i K n} W(theta n -
omega t) over K in (0, pi], each beside the NLS prediction (frequency shift h A^2/4, modulational
instability with the largest rate |h_tilde| A^2/4 where focusing). The functions are ``lrchain wave
solve|continue|stability|fate|standing``: the same job (lrchain/jobs/wave_job.hpp), its defaults from the job's one
schema.

``model`` is an :class:`lrchain.Model` (``lrchain.load_model("fput")`` or your own model file), default
the paper's resonant chain. No wave at an amplitude (Newton fails, near a harmonic resonance; the
harmonics do not decay; a one-sided contact opens) raises :class:`lrchain.NumericalFailure` with the reason.
"""

import json
from dataclasses import dataclass

import numpy as np

from . import _lrchain
from ._keywords import checked_model, documented, python_names, real_numbers, schema_options

# The job's defaults, from its one schema (jobs/src/wave/wave_schema.cpp): keyword -> default.
_D = {name: o["default"] for name, o in schema_options("wave").items()}
_SECTION = ("wave", "Options (the job's schema, as ``lrchain wave ... --help``):")


@dataclass(frozen=True, repr=False)
class TravellingWave:
    """One exact wave: ``amplitude`` A, ``omega`` (and ``omega_linear``, the branch at theta), ``harmonics``
    H used, ``tail`` and ``residual``, the ``profile`` U_f at the phases ``xi`` (fields x (2H+1)), the
    ``nls_omega_shift`` h A^2/4 and the job's whole JSON ``summary``; ``stability`` (a dict with numpy
    ``k``, ``growth_rate``, ``nls_growth_rate``, the ``bands``, ``largest_rate``, ``at_k``,
    ``nls_largest_rate``, ``nls_k``) after :func:`stability`, else None."""

    theta: float
    amplitude: float
    omega: float
    omega_linear: float
    harmonics: int
    tail: float
    residual: float
    xi: np.ndarray
    profile: np.ndarray
    nls_omega_shift: float
    stability: dict
    summary: dict
    fate: dict = None

    def to_hdf5(self, path):
        """Writes the wave with the C++ job layer's writer: the file ``lrchain wave solve|stability --format
        hdf5`` writes (layout: lrchain/jobs/wave_hdf5.hpp); :func:`lrchain.load` reads it back."""
        _write(path, self.summary)

    def __repr__(self):
        return (f"TravellingWave(theta={self.theta}, A={self.amplitude}, omega={self.omega:.12g}, "
                f"{self.harmonics} harmonics, residual {self.residual:.3g})")


@dataclass(frozen=True, repr=False)
class WaveBranch:
    """The branch omega(A) of :func:`continue_branch`: numpy arrays ``amplitude``, ``omega``, ``omega_shift``
    (omega - omega_linear), ``nls_omega_shift`` (h A^2/4) and ``harmonics``, one entry per wave; ``stopped``
    (the reason there is no wave at the next amplitude, None when every amplitude has one) and the job's JSON
    ``summary``. ``branch["omega"]`` reads a field as a dict would."""

    theta: float
    amplitude: np.ndarray
    omega: np.ndarray
    omega_shift: np.ndarray
    nls_omega_shift: np.ndarray
    harmonics: np.ndarray
    stopped: str
    summary: dict

    def __getitem__(self, key):
        return getattr(self, key)

    def to_hdf5(self, path):
        """Writes the branch with the C++ job layer's writer: the file ``lrchain wave continue --format hdf5``
        writes; :func:`lrchain.load` reads it back."""
        _write(path, self.summary)

    def __repr__(self):
        end = "" if self.stopped is None else f", stopped: {self.stopped}"
        return f"WaveBranch(theta={self.theta}, {len(self.amplitude)} waves{end})"


def _write(path, summary):
    from . import _hdf5
    from .hdf5 import checked_destination

    _hdf5.write_wave(checked_destination(path), json.dumps(summary))


@dataclass(frozen=True, repr=False)
class StandingWave:
    """One exact standing wave u_f[n](t) = sum_k c_{f,n,k} cos(k omega t) on one spatial period of the ring
    (``lrchain wave standing``): ``amplitude`` A (the first field's cos(theta n) cos(omega t) part),
    ``omega`` (and ``omega_linear``), ``harmonics`` H, ``coefficients`` (numpy, fields x sites x (H+1)), the
    ``branch`` of the ramp (a list of dicts: amplitude, omega, omega_shift, ...), the Floquet multipliers
    on the ring of ``ring_sites`` sites (``multipliers``, complex numpy, by decreasing modulus; ``stable``)
    and the job's whole JSON ``summary``."""

    theta: float
    amplitude: float
    omega: float
    omega_linear: float
    harmonics: int
    coefficients: np.ndarray
    branch: list
    multipliers: np.ndarray
    stable: bool
    summary: dict

    def to_hdf5(self, path):
        """Writes the standing wave with the C++ job layer's writer: the file ``lrchain wave standing --format
        hdf5`` writes (layout: lrchain/jobs/wave_hdf5.hpp); :func:`lrchain.load` reads it back."""
        _write(path, self.summary)

    def __repr__(self):
        return (f"StandingWave(theta={self.theta}, A={self.amplitude}, omega={self.omega:.12g}, "
                f"{self.harmonics} harmonics, {'stable' if self.stable else 'unstable'})")


def _model(model):
    if model is None:
        from .model import load_model

        return load_model("resonant_chain")
    return checked_model(model)


def _run(model, step, branch, theta, amplitude=_D["amplitude"], ramp=_D["ramp"], amplitudes=(),
         harmonics=_D["harmonics"], max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"],
         tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], k_points=_D["k_points"],
         unstable_tolerance=_D["unstable_tolerance"], ring_sites=_D["ring_sites"], noise=_D["noise"], seed=_D["seed"],
         periods=_D["periods"], steps_per_period=_D["steps_per_period"], modulation=_D["modulation"]):
    from .errors import InvalidParameterError

    model = _model(model)
    if theta is None:
        raise InvalidParameterError("invalid theta: required", "theta")
    if step != "continue" and amplitude is None:
        raise InvalidParameterError("invalid amplitude: required (> 0)", "amplitude")
    return python_names(lambda: _lrchain.wave_job(
        model, step, "" if branch is None else branch, theta, 0.0 if amplitude is None else amplitude, ramp, list(np.atleast_1d(amplitudes)),
        harmonics, max_harmonics, tail_tolerance, tolerance, max_iterations, k_points, unstable_tolerance, ring_sites,
        noise, seed, periods, steps_per_period, modulation))


def _wave(d):
    w = d["waves"][-1]
    s = d.get("stability")
    if s is not None:
        s = dict(s)
        for key in ("k", "growth_rate", "nls_growth_rate"):
            s[key] = np.array(s[key])
    f = d.get("fate")
    if f is not None:
        f = dict(f)
        for key in ("t", "deviation", "participation", "entropy", "dark", "bright", "energy_density"):
            f[key] = np.array(f[key])
    return TravellingWave(theta=d["theta"], amplitude=w["amplitude"], omega=w["omega"], omega_linear=d["linear"]["omega"],
                          harmonics=w["harmonics"], tail=w["tail"], residual=w["residual"],
                          xi=np.array(d["profile"]["xi"]), profile=d.pop("profile_array"),
                          nls_omega_shift=w["nls_omega_shift"], stability=s, summary=d, fate=f)


@documented(_SECTION)
@real_numbers
def solve(model=None, branch=None, theta=None, amplitude=None, ramp=_D["ramp"], harmonics=_D["harmonics"],
          max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"], tolerance=_D["tolerance"],
          max_iterations=_D["max_iterations"]):
    """The exact travelling wave of first-field amplitude ``amplitude`` on ``branch`` at wavenumber ``theta``;
    returns :class:`TravellingWave`.

    Example::

        >>> import lrchain
        >>> w = lrchain.wave.solve(lrchain.load_model("klein_gordon"), branch="branch0", theta=2.356, amplitude=0.01)
        >>> bool(abs((w.omega - w.omega_linear) / w.nls_omega_shift - 1) < 1e-3), w.profile.shape
        (True, (1, 17))
    """
    return _wave(_run(model, "solve", branch, theta, amplitude, ramp, (), harmonics, max_harmonics, tail_tolerance,
                      tolerance, max_iterations))


@documented(_SECTION)
@real_numbers
def continue_branch(model=None, branch=None, theta=None, amplitudes=None, harmonics=_D["harmonics"],
                    max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"], tolerance=_D["tolerance"],
                    max_iterations=_D["max_iterations"]):
    """The branch omega(A) through increasing ``amplitudes``, each wave seeded by the previous one; returns
    :class:`WaveBranch`: numpy arrays ``amplitude``, ``omega``, ``omega_shift``, ``nls_omega_shift``,
    ``harmonics`` and the ``stopped`` reason (None when every amplitude has a wave), with the JSON ``summary``.

    Example::

        >>> import lrchain
        >>> b = lrchain.wave.continue_branch(lrchain.load_model("fput"), branch="acoustic", theta=2.5,
        ...                                  amplitudes=[0.05, 0.1, 0.2])
        >>> b["omega"].shape, b["stopped"] is None
        ((3,), True)
    """
    if amplitudes is None:
        from .errors import InvalidParameterError

        raise InvalidParameterError("invalid amplitudes: required (increasing, > 0)", "amplitudes")
    d = _run(model, "continue", branch, theta, None, _D["ramp"], amplitudes, harmonics, max_harmonics,
             tail_tolerance, tolerance, max_iterations)
    d.pop("profile_array", None)
    return _branch(d)


def _branch(d):
    """The WaveBranch of the job's summary ``d`` (continue)."""
    waves = d["waves"]

    def column(key, dtype=float):
        return np.array([np.nan if w[key] is None else w[key] for w in waves], dtype=dtype)

    return WaveBranch(theta=d["theta"], amplitude=column("amplitude"), omega=column("omega"),
                      omega_shift=column("omega_shift"), nls_omega_shift=column("nls_omega_shift"),
                      harmonics=column("harmonics", int), stopped=d["failure"], summary=d)


@documented(_SECTION)
@real_numbers
def stability(model=None, branch=None, theta=None, amplitude=None, ramp=_D["ramp"], harmonics=_D["harmonics"],
              max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"], tolerance=_D["tolerance"],
              max_iterations=_D["max_iterations"], k_points=_D["k_points"],
              unstable_tolerance=_D["unstable_tolerance"]):
    """Solve, then the Floquet-Bloch growth rate max Re lambda over K in (0, pi] with the NLS curve beside it;
    returns :class:`TravellingWave` with ``stability`` set.

    Example::

        >>> import lrchain
        >>> w = lrchain.wave.stability(lrchain.load_model("fput"), branch="acoustic", theta=2.5, amplitude=0.02)
        >>> s = w.stability
        >>> bool(abs(s["largest_rate"] / s["nls_largest_rate"] - 1) < 1e-2), s["k"].shape
        (True, (200,))
    """
    return _wave(_run(model, "stability", branch, theta, amplitude, ramp, (), harmonics, max_harmonics,
                      tail_tolerance, tolerance, max_iterations, k_points, unstable_tolerance))


@documented(_SECTION)
@real_numbers
def fate(model=None, branch=None, theta=None, amplitude=None, ramp=_D["ramp"], harmonics=_D["harmonics"],
         max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"], tolerance=_D["tolerance"],
         max_iterations=_D["max_iterations"], k_points=_D["k_points"], unstable_tolerance=_D["unstable_tolerance"],
         ring_sites=_D["ring_sites"], noise=_D["noise"], seed=_D["seed"], periods=_D["periods"],
         steps_per_period=_D["steps_per_period"], modulation=_D["modulation"]):
    """What the wave becomes (``lrchain wave fate``): :func:`stability` at the ring's nearest wavenumber
    2 pi j / ``ring_sites``, then the wave plus noise (and its ``modulation``) on that ring; returns :class:`TravellingWave` with
    ``fate`` set: the ``fate`` (stable, intact, modulated, localized or disordered), ``broke_at`` and the
    ``predicted_breakup``, numpy series ``t``, ``deviation`` (of the strains for a translation-invariant model:
    ``deviation_of``), ``participation``, ``entropy``, ``dark`` and ``bright`` (structures counted; one per carrier
    period) and the final ``energy_density``; ``localized_kind``, ``bright_structures``, ``dark_structures``,
    ``dark_end`` (centre, width, depth), the stages ``dark_from``, ``dark_until``, ``dark_stage_count``,
    ``dark_stage_width``, ``dark_stage_depth``, ``bright_from``, ``bright_until``, ``bright_stage_count`` (None
    when none), ``dark_frequency``, ``bright_frequency`` and the branch's linear ``band`` (docs/waves.md, "The fate
    of a wave"). Ctrl-C stops the ring
    run at its next period with ``KeyboardInterrupt``.

    Example::

        >>> import lrchain
        >>> w = lrchain.wave.fate(lrchain.load_model("fput"), theta=2.5, amplitude=0.3, ring_sites=64, periods=400)
        >>> w.fate["fate"] in ("modulated", "localized", "disordered"), w.fate["broke_at"] is not None
        (True, True)
    """
    return _wave(_run(model, "fate", branch, theta, amplitude, ramp, (), harmonics, max_harmonics, tail_tolerance,
                      tolerance, max_iterations, k_points, unstable_tolerance, ring_sites, noise, seed, periods,
                      steps_per_period, modulation))


@documented(_SECTION)
@real_numbers
def standing(model=None, branch=None, theta=None, amplitude=None, ramp=_D["ramp"], harmonics=_D["harmonics"],
             max_harmonics=_D["max_harmonics"], tail_tolerance=_D["tail_tolerance"], tolerance=_D["tolerance"],
             max_iterations=_D["max_iterations"], ring_sites=_D["ring_sites"]):
    """The standing wave (``lrchain wave standing``; docs/waves.md, "Standing waves"): the sum of the two
    counter-propagating waves of a reflection-symmetric model as an exact time-periodic orbit at the ring's
    wavenumber 2 pi j / ``ring_sites`` nearest theta (in (0, pi)), continued in A, with its Floquet
    multipliers on that ring; returns :class:`StandingWave`.

    Example::

        >>> import lrchain
        >>> s = lrchain.wave.standing(lrchain.load_model("fput"), theta=1.2566, amplitude=0.02, ring_sites=20)
        >>> round((s.omega - s.omega_linear) / 0.02**2, 3), s.stable, s.coefficients.shape
        (0.228, True, (1, 5, 9))
    """
    return _standing(_run(model, "standing", branch, theta, amplitude, ramp, (), harmonics, max_harmonics,
                          tail_tolerance, tolerance, max_iterations, ring_sites=ring_sites))


def _standing(d):
    """The StandingWave of the job's summary ``d`` (standing) with its ``coefficients_array``."""
    s = d["standing"]
    f = s["floquet"]
    w = s["waves"][-1]
    return StandingWave(theta=s["ring_theta"], amplitude=w["amplitude"], omega=w["omega"],
                        omega_linear=d["linear"]["omega"], harmonics=w["harmonics"],
                        coefficients=d.pop("coefficients_array"), branch=s["waves"],
                        multipliers=np.array(f["re"]) + 1j * np.array(f["im"]), stable=f["stable"], summary=d)
