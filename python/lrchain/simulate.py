"""Lattice simulations (Sec. 4 and 5.1 of the paper) with their records as numpy arrays.

- :func:`bright`: the chain started from the NLS bright breather, compared with the ansatz
  (experiments 1-5: E_x(t), E_y(t), energy, energy centre, energy density e_n(t));
- :func:`drive`: a chain at rest driven at its first bead (experiment 6);
- :func:`modulated`: a periodic chain started from a modulated acoustic wave (experiment 7);
- :func:`bright` with ``model=``: the bright breather of any model file on its generated lattice;
- :func:`ring`: plane waves and a wave packet of any model file on a periodic ring (the numerical
  check of the derived h and c).

Each run integrates in C++ without holding the GIL; Ctrl-C stops it at the next step (model-file
runs with the symplectic stepper and ``ring``: at the next sample) and raises ``KeyboardInterrupt``.
Every run takes ``progress=``: a bar with rate and ETA when interactive, or True/False
(:mod:`lrchain.progress`; ``ring``'s bar moves after each plane wave and after the packet).
Keyword arguments left out (or None)
take the library's defaults, the same as the ``lrchain simulate`` command's, and the keywords are
its options' names (``sites`` for ``--sites``, ``switch_off_time`` for ``--switch-off-time``, ...).
An ``observer(t, q1, q2, e)`` is called at every sample with copies of the lattice fields (bright: strains x_n, y_n; drive, modulated: displacements u_n, v_n)
and the energy density e_n.
"""

import json
import warnings
from dataclasses import dataclass, field
import numpy as np

from . import _lrchain
from ._keywords import checked_model, documented, python_names, real_numbers, renamed, schema_options
from ._lrchain import Model, Params
from .errors import InputError
from .hdf5 import checked_destination, write_simulation
from .progress import Bar


@dataclass(frozen=True)
class SpaceTime:
    """A field f(n, t): ``values[k, i]`` at time ``t[k]`` and site ``n[i]`` (float32)."""

    quantity: str
    n: np.ndarray
    t: np.ndarray
    values: np.ndarray

    def __repr__(self):
        return f"SpaceTime({self.quantity}, {len(self.t)} times x {len(self.n)} sites)"


@dataclass(frozen=True)
class Snapshot:
    """Lattice profiles at time ``t``: ``columns`` {name: array}, the first one ``n``."""

    t: float
    tag: str
    columns: dict

    def __repr__(self):
        return f"Snapshot(t={self.t:g}, columns={list(self.columns)})"


class _SimulationHDF5:
    """``to_hdf5(path)`` of the simulation results: the sim library's writer, the same file as
    ``lrchain simulate ... --format hdf5`` (layout: :mod:`lrchain.hdf5`)."""

    _kind = None
    _series = ()  # (record column, attribute) pairs
    _fields = ()  # attributes holding the fields recorded at every sample

    def to_hdf5(self, path):
        """Writes this result to the HDF5 file ``path`` (layout: :mod:`lrchain.hdf5`)."""
        write_simulation(path, self._kind, {column: getattr(self, name) for column, name in self._series},
                         self.energy_density, self.snapshots, self.summary,
                         [(name, getattr(self, name)) for name in self._fields if getattr(self, name) is not None])


# The bright job's defaults of branch and theta, from its schema (lrchain/jobs/simulate/simulate_schema.hpp); the
# other keywords are None: the job's default, the same as the command's (listed in each docstring from the schema).
_BRIGHT = schema_options("bright")


def _options(**kwargs):
    return {k: v for k, v in kwargs.items() if v is not None}


def _fields(d, first, second):
    if d is None:
        return None
    return SpaceTime(first, d["n"], d["t"], d["primary"]), SpaceTime(second, d["n"], d["t"], d["secondary"])


def _spacetime(record):
    f = record["fields"][0]
    return SpaceTime(f["quantity"], f["n"], f["t"], f["values"])


def _snapshots(record):
    return [Snapshot(s["t"], s["tag"], s["columns"]) for s in record["snapshots"]]


@dataclass(frozen=True, repr=False)
class BrightResult(_SimulationHDF5):
    """A bright-breather run (Sec. 4.1-4.3).

    ``t``, ``E_x``, ``E_y`` (max-norm distance of the strains from the ansatz relative to the initial
    max-norm), ``energy`` and ``centre`` (energy centre X(t)) at every sample; ``energy_density``
    e_n(t) (a :class:`SpaceTime` on the beads); ``snapshots``; ``x``, ``y``: the strains x_n(t),
    y_n(t) at every sample when asked for (``record_strains=True``), else None; ``summary``: the
    same JSON as ``lrchain simulate`` (``model`` {name, file_hash, parameters}, ``sites``, ``ansatz``,
    ``max_E_x``, ``max_E_y``, ...).
    ``to_hdf5(path)`` writes it all to an HDF5 file (:mod:`lrchain.hdf5`).
    """

    t: np.ndarray
    E_x: np.ndarray
    E_y: np.ndarray
    energy: np.ndarray
    centre: np.ndarray
    energy_density: SpaceTime
    snapshots: list
    summary: dict
    x: SpaceTime = None
    y: SpaceTime = None

    _kind = "bright"
    _series = (("t", "t"), ("E_x", "E_x"), ("E_y", "E_y"), ("energy", "energy"), ("X", "centre"))
    _fields = ("x", "y")

    def __repr__(self):
        return (f"BrightResult({len(self.t)} samples to t = {self.t[-1]:g}, "
                f"max E_x = {self.summary['max_E_x']:.4g}, max E_y = {self.summary['max_E_y']:.4g})")


@documented(("bright", "Options (None: the default; the job's schema, as ``lrchain simulate bright --help``):"),
            ("bright --model", "With ``model``:"))
@renamed("bright")
@real_numbers
def bright(params=None, branch=_BRIGHT["branch"]["default"], theta=_BRIGHT["theta"]["default"], *, model=None, detuning=None, n0=None, sites=None,
           periods=None, sample_every=None, spacetime_every=None, snapshot_periods=None, centre_window=None,
           error_window_end=None, ansatz_ends=None, stepper=None, abs_tol=None, rel_tol=None, dt=None,
           max_memory=None, record_strains=False, observer=None, progress=None):
    """Bright-breather run: the strain lattice on n = -N..N (``sites`` = 2N + 1, odd) started from the
    NLS bright breather of ``branch`` at carrier ``theta`` and integrated for ``periods`` breather
    periods T_b, as ``lrchain simulate bright``.

    Library defaults: sites=1001, periods=200, sample_every=0.25 and spacetime_every=1 (units of T_b),
    snapshot_periods=(0, 50.125, 200) (those inside the run), centre_window=100, stepper "srkn11b"
    (Blanes-Moan, order 6) with its step chosen automatically: a probe run over the first 2 T_b
    measures the energy error, and the step is the largest that keeps it below 2e-10 (and
    dt * omega_max <= 0.9); giving ``dt`` fixes the step instead. With ``ansatz_ends=True`` the
    chain is not autonomous and the default stepper is the adaptive "rkf78". Other steppers:
    rkf78, dopri5 (adaptive: abs_tol = rel_tol = 1e-12 by default, dt the first step, 0.05 by
    default), symplectic, srkn14a, ss17 (fixed step dt). ``detuning`` = omega_b - omega
    (default sign(h_tilde) 1e-4). ``record_strains`` keeps x_n(t), y_n(t) at every sample.
    Returns :class:`BrightResult`.

    With ``model`` (an :class:`lrchain.Model`, e.g. ``lrchain.load_model("models/fput.toml")`` or your
    own file), the run is ``lrchain simulate bright --model FILE``: the model's bright breather on its
    generated lattice, ``branch`` one of ``model.branches``, with ``detuning``, ``n0``, ``sites`` (odd, in
    [21, 100000001]), ``periods``, ``sample_every``, ``dt`` (the srkn11b step; default from the fastest
    linear mode) and ``ansatz_ends`` (emitting ends, integrated with rkf78); the other keywords are
    refused as the command refuses them. Ctrl-C stops the model run at its next sample (emitting
    ends: its next step) with ``KeyboardInterrupt``. Returns :class:`ModelBrightResult`.

    Example::

        >>> import lrchain, math
        >>> r = lrchain.simulate.bright(lrchain.Params(), "optical", math.pi / 2, sites=41, periods=1, progress=False)
        >>> len(r.t), r.energy_density.values.shape
        (5, (2, 42))
        >>> fput = lrchain.load_model("fput")
        >>> m = lrchain.simulate.bright(fput, "acoustic", math.pi / 2, sites=41, periods=1, progress=False)
        >>> type(m).__name__, len(m.E)
        ('ModelBrightResult', 1)
    """
    if model is None and isinstance(params, Model):  # bright(lrchain.load_model(...), ...)
        model, params = params, None
    if model is not None:
        checked_model(model)
        given = dict(params=params, spacetime_every=spacetime_every, snapshot_periods=snapshot_periods,
                     centre_window=centre_window, error_window_end=error_window_end, stepper=stepper,
                     abs_tol=abs_tol, rel_tol=rel_tol, max_memory=max_memory, observer=observer,
                     record_strains=record_strains or None)
        for name, value in given.items():
            if value is not None:
                raise InputError(f"{name} is not available with model= (model bright runs use srkn11b, or rkf78 "
                                 f"with ansatz_ends=True; see help(lrchain.simulate.bright))")
        options = _options(theta=theta, n0=n0, sites=sites, periods=periods, sample_every=sample_every, dt=dt,
                           ansatz_ends=ansatz_ends)
        if detuning is not None:
            options["detuning"] = detuning
        with Bar(f"bright run of {model.name}", progress) as bar:
            out = python_names(lambda: _lrchain.simulate_model_bright(model, branch, options, bar.callback))
        return _warned(_model_bright_result(out))
    options = _options(params=params, branch=branch, theta=theta, n0=n0, sites=sites, periods=periods,
                       sample_every=sample_every, spacetime_every=spacetime_every,
                       snapshot_periods=None if snapshot_periods is None else list(snapshot_periods),
                       centre_window=centre_window, error_window_end=error_window_end, ansatz_ends=ansatz_ends,
                       stepper=stepper, abs_tol=abs_tol, rel_tol=rel_tol, dt=dt, max_memory=max_memory)
    if detuning is not None:
        options["detuning"] = detuning
    with Bar("bright run", progress) as bar:
        out = python_names(lambda: _lrchain.simulate_bright(options, record_strains, observer, bar.callback))
    record, series = out["record"], out["record"]["series"]
    fields = _fields(out["fields"], "x_n", "y_n")
    return BrightResult(t=series["t"], E_x=series["E_x"], E_y=series["E_y"], energy=series["energy"],
                        centre=series["X"], energy_density=_spacetime(record), snapshots=_snapshots(record),
                        summary=json.loads(out["summary_json"]), x=fields[0] if fields else None,
                        y=fields[1] if fields else None)


@dataclass(frozen=True, repr=False)
class ModelBrightResult:
    """A bright-breather run of a model file (``lrchain simulate bright --model``).

    ``t``, ``energy``, ``centre`` (energy centre X(t)) at every sample; ``E`` a tuple with, per field f,
    E_f(t) = max_n |x_f - x_f^A| / max_n |x_f(0)| (x_f: strains of translation-invariant models,
    displacements of on-site models); ``E_x`` = E[0], ``E_y`` = E[1] (None for a one-field model);
    ``snapshots`` (the final profiles and the ansatz); ``summary``: the same JSON as the command
    (omega_b, period, max_E, max_E_x, energy0, max_relative_energy_drift, centre_speed, ...).
    ``to_hdf5(path)`` writes the file ``lrchain simulate bright --model ... --format hdf5`` writes."""

    t: np.ndarray
    E: tuple
    energy: np.ndarray
    centre: np.ndarray
    snapshots: list
    summary: dict

    @property
    def E_x(self):
        return self.E[0]

    @property
    def E_y(self):
        return self.E[1] if len(self.E) > 1 else None

    def to_hdf5(self, path):
        """Writes this run with the C++ job layer's writer, the file ``lrchain simulate bright --model
        ... --format hdf5`` writes: datasets t, E_0, E_1, ..., energy, centre; snapshots; the summary
        tree (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        series = {"t": self.t, **{f"E_{f}": e for f, e in enumerate(self.E)}, "energy": self.energy, "X": self.centre}
        _hdf5.write_model_bright(checked_destination(path), series,
                                 [(s.t, s.tag, s.columns) for s in self.snapshots], json.dumps(self.summary))

    def __repr__(self):
        return (f"ModelBrightResult({self.summary['model']['name']}, {len(self.t)} samples to t = {self.t[-1]:g}, "
                f"max E_x = {self.summary['max_E_x']:.4g})")


def _warned(result):
    """Issues the run's own warnings (its summary's ``warnings``, the lines the command prints on
    stderr) as RuntimeWarning, and returns the result."""
    for text in result.summary.get("warnings") or []:
        warnings.warn(text, RuntimeWarning, stacklevel=3)
    return result


def _model_bright_result(out):
    record, series = out["record"], out["record"]["series"]
    return ModelBrightResult(t=series["t"], E=tuple(series[f"E_{f}"] for f in range(out["fields"])),
                             energy=series["energy"], centre=series["X"], snapshots=_snapshots(record),
                             summary=json.loads(out["summary_json"]))


@dataclass(frozen=True, repr=False)
class RingResult:
    """Plane waves of a model on a periodic ring (``lrchain simulate ring``): per amplitude U
    (``amplitude``) the ``measured_frequency`` and ``predicted_frequency`` omega + h U^2/4, their
    shifts from omega and ``relative_disagreement`` of the shifts (nan where h vanishes); the wave
    packet's centre ``packet_t``, ``packet_centre`` and ``summary`` (the command's JSON: omega, h,
    group_velocity, packet_speed, packet_relative_disagreement, ...). ``to_hdf5(path)`` writes the
    file ``lrchain simulate ring ... --format hdf5`` writes."""

    amplitude: np.ndarray
    measured_frequency: np.ndarray
    predicted_frequency: np.ndarray
    measured_shift: np.ndarray
    predicted_shift: np.ndarray
    relative_disagreement: np.ndarray
    packet_t: np.ndarray
    packet_centre: np.ndarray
    summary: dict

    _amplitude_columns = ("amplitude", "measured_frequency", "predicted_frequency", "measured_shift",
                          "predicted_shift", "relative_disagreement")

    def to_hdf5(self, path):
        """Writes this run with the C++ job layer's writer, the file ``lrchain simulate ring ...
        --format hdf5`` writes: datasets packet_t, packet_centre and one per amplitude column; the
        summary tree (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_ring(checked_destination(path), {"t": self.packet_t, "packet_centre": self.packet_centre},
                         {name: getattr(self, name) for name in self._amplitude_columns}, json.dumps(self.summary))

    def __repr__(self):
        return (f"RingResult({self.summary['model']['name']}, {len(self.amplitude)} amplitudes, relative "
                f"disagreement {', '.join(f'{d:.3g}' for d in self.relative_disagreement)})")


@documented(("ring", "Options (None: the default; the job's schema, as ``lrchain simulate ring --help``):"))
@real_numbers
def ring(model, branch=None, theta=None, *, amplitudes=None, sites=None, periods=None, steps_per_period=None,
         packet_amplitude=None, packet_width=None, progress=None):
    """``lrchain simulate ring --model FILE``: plane waves of amplitude U (``amplitudes``, default
    (0.02, 0.01)) on a periodic ring of ``sites`` (default the smallest >= 8 with theta on it),
    their frequency measured over ``periods`` carrier periods (default 400, ``steps_per_period`` 80
    srkn11b steps) against omega + h U^2/4, and a Gaussian wave packet (``packet_amplitude``, default
    a tenth of the smallest U; ``packet_width`` 24 sites) whose speed is compared with c.
    ``model`` is an :class:`lrchain.Model`; ``branch`` may be left out for a model with one branch;
    ``theta`` is required. Ctrl-C stops it at its next sample (8 per carrier period) with
    ``KeyboardInterrupt``. Returns :class:`RingResult`.

    Example::

        >>> import lrchain, math
        >>> r = lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", math.pi / 2, periods=20, packet_width=8,
        ...                           progress=False)
        >>> r.amplitude.tolist(), bool((r.relative_disagreement < 1e-3).all())
        ([0.02, 0.01], True)
    """
    checked_model(model)
    if theta is None:
        from .errors import InvalidParameterError
        raise InvalidParameterError("invalid theta: required, the carrier wavenumber in (-pi, pi]", "theta")
    options = _options(theta=theta, amplitudes=None if amplitudes is None else [float(a) for a in amplitudes],
                       sites=sites, periods=periods, steps_per_period=steps_per_period,
                       packet_amplitude=packet_amplitude, packet_width=packet_width)
    with Bar(f"ring run of {model.name}", progress) as bar:
        out = python_names(lambda: _lrchain.simulate_ring(model, "" if branch is None else branch, options, bar.callback))
    series = out["record"]["series"]
    names = list(series)
    return _warned(RingResult(amplitude=out["amplitude"], measured_frequency=out["measured_frequency"],
                              predicted_frequency=out["predicted_frequency"], measured_shift=out["measured_shift"],
                              predicted_shift=out["predicted_shift"],
                              relative_disagreement=out["relative_disagreement"],
                              packet_t=series[names[0]], packet_centre=series[names[1]],
                              summary=json.loads(out["summary_json"])))


@dataclass(frozen=True, repr=False)
class DriveResult(_SimulationHDF5):
    """A driven-chain run (Sec. 4.3, experiment 6): ``t``, ``energy``, ``front`` (largest bead with
    e_n above a fraction of the maximum), ``participation`` and ``u0`` (the driven boundary) at every
    sample; ``energy_density`` e_n(t); ``snapshots``; ``u``, ``v`` (displacements at every sample)
    when asked for; ``summary`` as in the JSON of ``lrchain simulate drive``."""

    t: np.ndarray
    energy: np.ndarray
    front: np.ndarray
    participation: np.ndarray
    u0: np.ndarray
    energy_density: SpaceTime
    snapshots: list
    summary: dict
    u: SpaceTime = None
    v: SpaceTime = None

    _kind = "drive"
    _series = (("t", "t"), ("energy", "energy"), ("front", "front"), ("participation", "participation"),
               ("u0", "u0"))
    _fields = ("u", "v")

    def __repr__(self):
        return f"DriveResult({len(self.t)} samples to t = {self.t[-1]:g}, final energy {self.energy[-1]:.6g})"


@documented(("drive", "Options (None: the default; the job's schema, as ``lrchain simulate drive --help``):"))
@renamed("drive")
@real_numbers
def drive(params=None, *, sites=None, amplitude=None, omega0=None, ramp_rate=None, switch_off_time=None, t_end=None,
          sample_every=None, spacetime_every=None, snapshot_times=None, front_fraction=None,
          front_fit_start=None, front_fit_end=None, stepper=None, abs_tol=None, rel_tol=None, dt=None,
          max_memory=None, record_displacements=False, observer=None, progress=None):
    """Driven chain (``lrchain simulate drive``): beads n = 1..sites at rest, clamped far end, first
    bead driven by A0 sin(omega0 t) chi(t). Library defaults: params rho=10 (alpha=3/2,
    delta0=4/9, kappa=1), sites=2000, amplitude=0.06, omega0=2.1, ramp_rate=0.046,
    switch_off_time=700 (t_m of chi(t)), t_end=2400, sample_every=1, spacetime_every=2, stepper
    rkf78 at 1e-10. Returns :class:`DriveResult`.

    Example::

        >>> import lrchain
        >>> r = lrchain.simulate.drive(sites=50, t_end=4, switch_off_time=2, progress=False)
        >>> r.t.tolist()
        [0.0, 1.0, 2.0, 3.0, 4.0]
    """
    options = _options(params=params, sites=sites, amplitude=amplitude, omega0=omega0, ramp_rate=ramp_rate,
                       switch_off_time=switch_off_time, t_end=t_end, sample_every=sample_every, spacetime_every=spacetime_every,
                       snapshot_times=None if snapshot_times is None else list(snapshot_times),
                       front_fraction=front_fraction, front_fit_start=front_fit_start, front_fit_end=front_fit_end,
                       stepper=stepper, abs_tol=abs_tol, rel_tol=rel_tol, dt=dt, max_memory=max_memory)
    with Bar("drive run", progress) as bar:
        out = python_names(lambda: _lrchain.simulate_drive(options, record_displacements, observer, bar.callback))
    record, series = out["record"], out["record"]["series"]
    fields = _fields(out["fields"], "u_n", "v_n")
    return DriveResult(t=series["t"], energy=series["energy"], front=series["front"],
                       participation=series["participation"], u0=series["u0"], energy_density=_spacetime(record),
                       snapshots=_snapshots(record), summary=json.loads(out["summary_json"]),
                       u=fields[0] if fields else None, v=fields[1] if fields else None)


@dataclass(frozen=True, repr=False)
class ModulatedResult(_SimulationHDF5):
    """A modulated-wave run (Sec. 5.1, experiment 7): ``t``, ``energy``, ``contrast`` of e_n,
    ``dark_centre`` and ``dark_unwrapped`` (position of the minimum of the smoothed e_n) at every
    sample; ``energy_density``; ``snapshots``; ``u``, ``v`` when asked for; ``summary``."""

    t: np.ndarray
    energy: np.ndarray
    contrast: np.ndarray
    dark_centre: np.ndarray
    dark_unwrapped: np.ndarray
    energy_density: SpaceTime
    snapshots: list
    summary: dict
    u: SpaceTime = None
    v: SpaceTime = None

    _kind = "modulated"
    _series = (("t", "t"), ("energy", "energy"), ("contrast", "contrast"), ("dark_centre", "dark_centre"),
               ("dark_unwrapped", "dark_unwrapped"))
    _fields = ("u", "v")

    def __repr__(self):
        return f"ModulatedResult({len(self.t)} samples to t = {self.t[-1]:g})"


@documented(("modulated", "Options (None: the default; the job's schema, as ``lrchain simulate modulated --help``):"))
@renamed("modulated")
@real_numbers
def modulated(params=None, *, sites=None, epsilon=None, theta_waves=None, modulation_depth=None, t_end=None,
              sample_every=None, snapshot_times=None, contrast_threshold=None, dark_window=None,
              speed_fit_start=None, speed_fit_end=None, stepper=None, abs_tol=None, rel_tol=None, dt=None,
              max_memory=None, record_displacements=False, observer=None, progress=None):
    """Periodic chain of ``sites`` sites (``lrchain simulate modulated``) started from the modulated
    acoustic wave (eq. (43)). Library defaults: params delta0=0.27, rho=0.32, sites=401,
    epsilon=0.03, theta_waves=252, modulation_depth=0.01 (b of eq. (43)), t_end=45000,
    sample_every=10, symplectic stepper with dt=0.05. Returns :class:`ModulatedResult`.

    Example::

        >>> import lrchain
        >>> r = lrchain.simulate.modulated(sites=21, theta_waves=13, t_end=4, sample_every=1, progress=False)
        >>> r.t.tolist(), r.energy_density.values.shape[1]
        ([0.0, 1.0, 2.0, 3.0, 4.0], 21)
    """
    options = _options(params=params, sites=sites, epsilon=epsilon, theta_waves=theta_waves,
                       modulation_depth=modulation_depth,
                       t_end=t_end, sample_every=sample_every,
                       snapshot_times=None if snapshot_times is None else list(snapshot_times),
                       contrast_threshold=contrast_threshold, dark_window=dark_window,
                       speed_fit_start=speed_fit_start, speed_fit_end=speed_fit_end, stepper=stepper,
                       abs_tol=abs_tol, rel_tol=rel_tol, dt=dt, max_memory=max_memory)
    with Bar("modulated run", progress) as bar:
        out = python_names(lambda: _lrchain.simulate_modulated(options, record_displacements, observer,
                                                               bar.callback))
    record, series = out["record"], out["record"]["series"]
    fields = _fields(out["fields"], "u_n", "v_n")
    return ModulatedResult(t=series["t"], energy=series["energy"], contrast=series["contrast"],
                           dark_centre=series["dark_centre"], dark_unwrapped=series["dark_unwrapped"],
                           energy_density=_spacetime(record), snapshots=_snapshots(record),
                           summary=json.loads(out["summary_json"]), u=fields[0] if fields else None,
                           v=fields[1] if fields else None)
