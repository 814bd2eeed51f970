"""Results as labelled arrays: ``result.to_xarray()`` and :func:`open_sweep`.

Every result object has ``to_xarray()``, which returns an :class:`xarray.Dataset` with named
dimensions and coordinates (``theta``, ``site``, ``time``, ``field``, ``omega_b``, ``point``, a
sweep's axes), a ``long_name`` and ``units`` on every variable, and the model and lrchain's
provenance as attributes, so that ``ds.E_x.plot()`` and ``ds.to_netcdf(path)`` just work. The
numpy attributes of the result stay as they are; this module only relabels them (no copy where
xarray can avoid one). Units are the lattice's own (nondimensional) units: time in the units of the
model's equations of motion, theta in radians, frequencies in radians per unit time.

xarray (Debian ``python3-xarray``) is imported on the first call, not with ``import lrchain``.
Complex Floquet multipliers are stored as two real variables (``..._real``, ``..._imag``) so that
the Dataset can be written to netCDF.
"""

import json

import numpy as np

from .errors import InputError

TIME = ("time", "lattice units")  # the nondimensional time of the model's equations of motion
SITE = ("site n", "1")


def _xarray():
    try:
        import xarray
    except ImportError as e:  # pragma: no cover - depends on the machine
        raise ImportError("to_xarray needs xarray (Debian: python3-xarray)") from e
    return xarray


def _var(dims, values, long_name, units="1"):
    """(dims, values, attrs) for xarray.Dataset: one labelled variable."""
    return (dims, np.asarray(values), {"long_name": long_name, "units": units})


def _provenance(summary=None):
    """Root attributes: lrchain's build, the model (JSON text) and the job's summary (JSON text)."""
    from . import provenance

    build = provenance()
    attrs = {"lrchain_version": build["version"], "lrchain_commit": build["commit"] or "",
             "lrchain_version_line": build["version_line"]}
    if summary:
        if "model" in summary:
            attrs["model"] = json.dumps(summary["model"], sort_keys=True)
        attrs["summary"] = json.dumps(summary, sort_keys=True)
    return attrs


def _dataset(data_vars, coords, attrs):
    return _xarray().Dataset(data_vars=data_vars, coords=coords, attrs=attrs)


def _shared_dim(coords, base, name, values, label, units):
    """A dimension for ``values``: an existing coordinate ``base`` or ``base_<field>`` with the same
    values, or a new one (the strains x_n, y_n are sampled more often and on other sites than e_n)."""
    for dim in [base] + [k for k in coords if k.startswith(base + "_")]:
        if dim in coords and np.array_equal(coords[dim][1], values):
            return dim
    dim = base if base not in coords else f"{base}_{name}"
    coords[dim] = _var((dim,), values, label, units)
    return dim


def _spacetime_vars(result, names, data_vars, coords):
    """SpaceTime fields f(n, t) as variables on (time_field, site); a field sampled at other times or
    on other sites gets dimensions of its own (time_field_x, site_x)."""
    for name in names:
        st = getattr(result, name, None)
        if st is None:
            continue
        t = _shared_dim(coords, "time_field", name, np.asarray(st.t), "time", TIME[1])
        n = _shared_dim(coords, "site", name, np.asarray(st.n), *SITE)
        data_vars[name] = _var((t, n), st.values, st.quantity)


def _floquet_vars(floquet, prefix, dims, data_vars):
    """Floquet multipliers as real and imaginary parts, and the classification's scalars."""
    if floquet is None:
        return
    m = np.asarray(floquet.multipliers)
    data_vars[prefix + "multiplier_real"] = _var(dims, m.real, "Floquet multiplier, real part")
    data_vars[prefix + "multiplier_imag"] = _var(dims, m.imag, "Floquet multiplier, imaginary part")


def _series_dataset(result, series, spacetime, kind):
    """Lattice runs: the per-sample series on ``time``, the space-time fields on (time_field, site)."""
    data_vars = {name: _var(("time",), getattr(result, name), label) for name, label in series}
    coords = {"time": _var(("time",), result.t, "time", TIME[1])}
    _spacetime_vars(result, spacetime, data_vars, coords)
    attrs = _provenance(result.summary)
    attrs["lrchain_result"] = kind
    return _dataset(data_vars, coords, attrs)


def bright_to_xarray(self):
    """Bright run: E_x, E_y, energy, centre on ``time``; energy_density (and x, y) on (time_field, site)."""
    return _series_dataset(self, (("E_x", "E_x: max-norm distance of x_n from the ansatz, relative"),
                                  ("E_y", "E_y: max-norm distance of y_n from the ansatz, relative"),
                                  ("energy", "total energy"), ("centre", "energy centre X(t)")),
                           ("energy_density", "x", "y"), "bright")


def drive_to_xarray(self):
    """Driven chain: energy, front, participation, u0 on ``time``; energy_density (and u, v)."""
    return _series_dataset(self, (("energy", "total energy"), ("front", "energy front (site)"),
                                  ("participation", "participation number"), ("u0", "driven boundary u_0")),
                           ("energy_density", "u", "v"), "drive")


def modulated_to_xarray(self):
    """Modulated wave: energy, contrast, dark_centre, dark_unwrapped on ``time``; energy_density (and u, v)."""
    return _series_dataset(self, (("energy", "total energy"), ("contrast", "contrast of e_n"),
                                  ("dark_centre", "dark centre (site)"),
                                  ("dark_unwrapped", "dark centre, unwrapped (site)")),
                           ("energy_density", "u", "v"), "modulated")


def model_bright_to_xarray(self):
    """Model-file bright run: E (field, time), energy, centre on ``time``."""
    fields = [f"E_{k}" for k in range(len(self.E))]
    data_vars = {"E": _var(("field", "time"), np.vstack(self.E),
                           "E_f: max-norm distance of field f from the ansatz, relative"),
                 "energy": _var(("time",), self.energy, "total energy"),
                 "centre": _var(("time",), self.centre, "energy centre X(t)")}
    coords = {"time": _var(("time",), self.t, "time", TIME[1]), "field": ("field", fields)}
    attrs = _provenance(self.summary)
    attrs["lrchain_result"] = "model_bright"
    return _dataset(data_vars, coords, attrs)


def ring_to_xarray(self):
    """Ring run: frequencies and shifts on ``amplitude``; the packet's centre on ``packet_time``."""
    data_vars = {
        "measured_frequency": _var(("amplitude",), self.measured_frequency, "measured frequency", "rad/time"),
        "predicted_frequency": _var(("amplitude",), self.predicted_frequency, "omega + h U^2/4", "rad/time"),
        "measured_shift": _var(("amplitude",), self.measured_shift, "measured frequency shift", "rad/time"),
        "predicted_shift": _var(("amplitude",), self.predicted_shift, "h U^2/4", "rad/time"),
        "relative_disagreement": _var(("amplitude",), self.relative_disagreement,
                                      "relative disagreement of the shifts"),
        "packet_centre": _var(("packet_time",), self.packet_centre, "wave packet centre (site)"),
    }
    coords = {"amplitude": _var(("amplitude",), self.amplitude, "plane-wave amplitude U"),
              "packet_time": _var(("packet_time",), self.packet_t, "time", TIME[1])}
    attrs = _provenance(self.summary)
    attrs["lrchain_result"] = "ring"
    return _dataset(data_vars, coords, attrs)


def _scalar_attrs(d, prefix=""):
    """Numbers and strings of a dict as attributes (None as the string "null")."""
    out = {}
    for k, v in (d or {}).items():
        if v is None:
            out[prefix + k] = "null"
        elif isinstance(v, (bool, np.bool_)):
            out[prefix + k] = int(v)
        elif isinstance(v, (int, float, str, np.integer, np.floating)):
            out[prefix + k] = v
    return out


def _model_edge_attrs(self):
    attrs = _provenance({"model": self.model})
    attrs.update(_scalar_attrs({"branch": self.branch, "theta": self.theta, "omega_edge": self.omega_edge,
                                "curvature": self.curvature, "h_tilde": self.h_tilde, "lambda": self.lambda_,
                                "lattice_form": self.lattice_form}))
    return attrs


def dark_solution_to_xarray(self):
    """Dark breather of the paper's chain: x, y, x_seed, y_seed on ``site``; Newton's residuals."""
    data_vars = {name: _var(("site",), getattr(self, name), label) for name, label in
                 (("x", "strain x_n at t = 0"), ("y", "strain y_n at t = 0"),
                  ("x_seed", "NLS seed x_n"), ("y_seed", "NLS seed y_n"))}
    data_vars["newton_residual"] = _var(("newton_iteration",), self.newton_residuals, "Newton residual")
    _floquet_vars(self.floquet, "floquet_", ("multiplier",), data_vars)
    coords = {"site": _var(("site",), self.n, *SITE)}
    attrs = _provenance()
    attrs.update(_scalar_attrs({"omega_b": self.omega_b, "omega_edge": self.omega_edge}))
    attrs.update(_scalar_attrs(self.measures, "measure_"))
    if self.floquet is not None:
        attrs.update(_scalar_attrs({"kind": self.floquet.kind, "max_modulus": self.floquet.max_modulus}, "floquet_"))
    attrs["lrchain_result"] = "dark_solution"
    return _dataset(data_vars, coords, attrs)


def model_dark_solution_to_xarray(self):
    """Dark breather of a model file: z and seed on (field, site); Newton's residuals."""
    data_vars = {"z": _var(("field", "site"), self.z, "Z(0) in the lattice's variables"),
                 "seed": _var(("field", "site"), self.seed, "NLS seed"),
                 "newton_residual": _var(("newton_iteration",), self.newton_residuals, "Newton residual")}
    _floquet_vars(self.floquet, "floquet_", ("multiplier",), data_vars)
    coords = {"site": _var(("site",), self.n, *SITE), "field": ("field", list(self.variables))}
    attrs = _model_edge_attrs(self)
    attrs.update(_scalar_attrs({"omega_b": self.omega_b}))
    attrs.update(_scalar_attrs(self.measures, "measure_"))
    if self.floquet is not None:
        attrs.update(_scalar_attrs({"kind": self.floquet.kind, "max_modulus": self.floquet.max_modulus}, "floquet_"))
    attrs["lrchain_result"] = "model_dark_solution"
    return _dataset(data_vars, coords, attrs)


def _branch_vars(self):
    """Per continuation point: omega_b (the coordinate), tangent, residual, iterations, measures,
    Floquet maximum modulus."""
    data_vars = {"tangent_omega": _var(("point",), self.tangent_omega, "d omega_b / ds"),
                 "residual": _var(("point",), self.residual, "Newton residual"),
                 "iterations": _var(("point",), self.iterations, "Newton iterations")}
    keys = [k for k, v in (self.measures[0] if self.measures else {}).items() if isinstance(v, (int, float))]
    for k in keys:
        values = [np.nan if m.get(k) is None else m[k] for m in self.measures]
        data_vars[k] = _var(("point",), values, k)
    data_vars["max_modulus"] = _var(("point",), [f.max_modulus if f else np.nan for f in self.floquet],
                                    "largest Floquet modulus")
    coords = {"point": np.arange(len(self.omega_b)),
              "omega_b": _var(("point",), self.omega_b, "breather frequency omega_b", "rad/time")}
    return data_vars, coords


def branch_to_xarray(self):
    """Dark-breather branch of the paper's chain: per ``point`` (omega_b its coordinate) x, y on site."""
    data_vars, coords = _branch_vars(self)
    data_vars["x"] = _var(("point", "site"), self.x, "strain x_n at t = 0")
    data_vars["y"] = _var(("point", "site"), self.y, "strain y_n at t = 0")
    sites = np.asarray(self.x).shape[1]
    coords["site"] = _var(("site",), np.arange(sites) - (sites - 1) // 2, *SITE)
    attrs = _provenance()
    attrs.update({"stop_reason": self.stop_reason, "turning_points": np.asarray(self.turning_points, float),
                  "lrchain_result": "dark_branch"})
    return _dataset(data_vars, coords, attrs)


def model_branch_to_xarray(self):
    """Dark-breather branch of a model file: per ``point`` z on (field, site)."""
    data_vars, coords = _branch_vars(self)
    data_vars["z"] = _var(("point", "field", "site"), self.z, "Z(0) in the lattice's variables")
    coords["site"] = _var(("site",), self.n, *SITE)
    coords["field"] = ("field", list(self.variables))
    attrs = _model_edge_attrs(self)
    attrs.update({"stop_reason": self.stop_reason, "turning_points": np.asarray(self.turning_points, float),
                  "lrchain_result": "model_dark_branch"})
    return _dataset(data_vars, coords, attrs)


def _evolution_vars(self):
    data_vars = {name: _var(("time",), getattr(self, name), label) for name, label in
                 (("E_b", "relative error after each period"), ("C_x", "vertical centre at the far site"),
                  ("K_x", "amplitude at the far site"), ("position", "breather position (site)"),
                  ("depth", "breather depth"))}
    strobe = np.arange(len(self.t) + 1) * self.period
    coords = {"time": _var(("time",), self.t, "time m T_b", TIME[1]),
              "strobe_time": _var(("strobe_time",), strobe, "stroboscopic time m T_b, m = 0..M", TIME[1])}
    return data_vars, coords


def evolution_to_xarray(self):
    """Dark-breather evolution of the paper's chain: per period on ``time``; x, y on (strobe_time, site)."""
    data_vars, coords = _evolution_vars(self)
    data_vars["x"] = _var(("strobe_time", "site"), self.x, "strain x_n at t = m T_b")
    data_vars["y"] = _var(("strobe_time", "site"), self.y, "strain y_n at t = m T_b")
    sites = np.asarray(self.x).shape[1]
    coords["site"] = _var(("site",), np.arange(sites) - (sites - 1) // 2, *SITE)
    attrs = _provenance()
    attrs.update(_scalar_attrs({"period": self.period, "max_strain": self.max_strain}))
    attrs["lrchain_result"] = "dark_evolution"
    return _dataset(data_vars, coords, attrs)


def model_evolution_to_xarray(self):
    """Dark-breather evolution of a model file: per period on ``time``; z on (strobe_time, field, site)."""
    data_vars, coords = _evolution_vars(self)
    data_vars["z"] = _var(("strobe_time", "field", "site"), self.z, "Z(m T_b) in the lattice's variables")
    coords["site"] = _var(("site",), self.n, *SITE)
    coords["field"] = ("field", list(self.variables))
    attrs = _model_edge_attrs(self)
    attrs.update(_scalar_attrs({"period": self.period, "max_strain": self.max_strain}))
    attrs["lrchain_result"] = "model_dark_evolution"
    return _dataset(data_vars, coords, attrs)


def coefficients_to_xarray(self):
    """NLS coefficients on ``theta`` (a 1-D theta; a scalar theta gives 0-d variables)."""
    theta = np.asarray(self.theta, dtype=float)
    if theta.ndim > 1:
        raise InputError("to_xarray: theta has %d dimensions; call it with a 1-D array of theta" % theta.ndim)
    dims = ("theta",) if theta.ndim == 1 else ()
    labels = (("omega", "carrier frequency omega(theta)", "rad/time"), ("group_velocity", "c = omega'", "sites/time"),
              ("curvature", "omega''", "1"), ("gamma", "gamma", "1"), ("beta", "beta", "1"), ("h", "h", "1"),
              ("lambda_", "lambda (mean flow)", "1"), ("h_tilde", "h_tilde = h - lambda beta", "1"),
              ("nonresonance1", "non-resonance value 1", "1"), ("nonresonance2", "non-resonance value 2", "1"))
    data_vars = {("lambda" if name == "lambda_" else name): _var(dims, getattr(self, name), label, units)
                 for name, label, units in labels}
    data_vars["regime"] = (dims, np.asarray(self.regime, dtype=str), {"long_name": "regime"})
    coords = {"theta": _var(dims, theta, "wavenumber theta", "rad")}
    attrs = _provenance({"model": self.model} if self.model is not None else None)
    attrs.update(_scalar_attrs({"branch": self.branch}) if self.branch is not None else {})
    attrs["lrchain_result"] = "coefficients"
    return _dataset(data_vars, coords, attrs)


def _regime_attrs(result):
    """Provenance with the model and branch of a regime result (when it carries them)."""
    attrs = _provenance({"model": result.model} if result.model is not None else None)
    if result.branch is not None:
        attrs["branch"] = result.branch
    return attrs


def intervals_to_xarray(self):
    """Focusing intervals on ``interval`` (lo, hi and their causes); the zeros on ``root``."""
    data_vars = {"lo": _var(("interval",), self.lo, "interval start theta", "rad"),
                 "hi": _var(("interval",), self.hi, "interval end theta", "rad"),
                 "lo_cause": _var(("interval",), np.asarray(self.lo_cause, dtype=str), "what ends it below"),
                 "hi_cause": _var(("interval",), np.asarray(self.hi_cause, dtype=str), "what ends it above"),
                 "root": _var(("root",), self.roots, "zero of a regime function", "rad"),
                 "root_cause": _var(("root",), np.asarray(self.root_cause, dtype=str), "which function vanishes")}
    attrs = _regime_attrs(self)
    attrs["lrchain_result"] = "regime_intervals"
    return _dataset(data_vars, {}, attrs)


def regime_map_to_xarray(self):
    """Regime map: ``regime`` (int8: -1 outside the band, 0 defocusing, 1 focusing, 2 singular) on (y, x)."""
    data_vars = {"regime": (( self.y_name, self.x_name), np.asarray(self.values),
                            {"long_name": "sign of omega'' h_tilde",
                             "flag_values": np.array([-1, 0, 1, 2], dtype=np.int8),
                             "flag_meanings": "outside_band defocusing focusing singular"})}
    coords = {self.x_name: ((self.x_name,), np.asarray(self.x), {"long_name": self.x_name}),
              self.y_name: ((self.y_name,), np.asarray(self.y), {"long_name": self.y_name})}
    attrs = _regime_attrs(self)
    if self.plane is not None:
        attrs["plane"] = self.plane
    attrs["lrchain_result"] = "regime_map"
    return _dataset(data_vars, coords, attrs)


def boundary_curve_to_xarray(self):
    """One boundary curve: parameter and theta (or omega) on ``point``."""
    p = np.asarray(self.points, dtype=float).reshape(-1, 2)
    data_vars = {"parameter": _var(("point",), p[:, 0], "parameter value"),
                 "theta": _var(("point",), p[:, 1], "theta (or omega) on the curve")}
    attrs = _regime_attrs(self)
    attrs.update({"cause": self.cause, "axis": self.axis or "", "y_name": self.y_name,
                  "lrchain_result": "boundary_curve"})
    return _dataset(data_vars, {"point": np.arange(len(p))}, attrs)


def floquet_to_xarray(self):
    """Floquet multipliers (real and imaginary parts) on ``multiplier``, the classification as attributes."""
    data_vars = {}
    _floquet_vars(self, "", ("multiplier",), data_vars)
    attrs = _provenance()
    attrs.update(_scalar_attrs({k: v for k, v in vars(self).items() if k not in ("multipliers", "trivial")}))
    attrs["lrchain_result"] = "floquet"
    return _dataset(data_vars, {}, attrs)


def _bright_vars(floquet, data_vars, attrs):
    """A bright breather's Floquet multipliers and their classification."""
    if floquet is None:
        return
    _floquet_vars(floquet, "floquet_", ("multiplier",), data_vars)
    attrs.update(_scalar_attrs({k: v for k, v in vars(floquet).items() if k not in ("multipliers", "trivial")},
                               "floquet_"))


def bright_breather_to_xarray(self):
    """Bright breather: z and seed on (field, site); Newton's residuals; Floquet multipliers; the edge,
    profile and summary as attributes."""
    data_vars = {"z": _var(("field", "site"), self.z, "Z(0) in the lattice's variables"),
                 "seed": _var(("field", "site"), self.seed, "NLS bright-breather seed"),
                 "newton_residual": _var(("newton_iteration",), self.newton_residuals, "Newton residual")}
    coords = {"site": _var(("site",), self.n, *SITE), "field": ("field", list(self.variables))}
    attrs = _provenance(self.summary)
    attrs.update(_scalar_attrs({"omega_b": self.omega_b, "center": self.center,
                                "seed_difference": self.seed_difference}))
    attrs.update(_scalar_attrs(self.edge, "edge_"))
    attrs.update(_scalar_attrs(self.profile, "profile_"))
    _bright_vars(self.floquet, data_vars, attrs)
    attrs["lrchain_result"] = "bright_breather"
    return _dataset(data_vars, coords, attrs)


def bright_branch_to_xarray(self):
    """Bright-breather branch: per ``point`` (omega_b its coordinate) peak, norm_squared, width, stability,
    largest non-trivial Floquet modulus and z on (field, site)."""
    start = self.start
    data_vars = {"peak": _var(("point",), self.peak, "peak of Z(0)"),
                 "norm_squared": _var(("point",), self.norm_squared, "sum of Z(0)^2"),
                 "width": _var(("point",), self.width, "width (sites)", "1"),
                 "stable": _var(("point",), [-1 if v is None else int(v) for v in self.stable],
                                "stable (1), unstable (0), not computed (-1)"),
                 "max_nontrivial_modulus": _var(("point",), [np.nan if v is None else v
                                                             for v in self.max_nontrivial_modulus],
                                                "largest non-trivial Floquet modulus"),
                 "z": _var(("point", "field", "site"), self.z, "Z(0) in the lattice's variables")}
    coords = {"point": np.arange(len(self.omega_b)),
              "omega_b": _var(("point",), self.omega_b, "breather frequency omega_b", "rad/time"),
              "site": _var(("site",), start.n, *SITE), "field": ("field", list(start.variables))}
    attrs = _provenance(start.summary)
    attrs.update({"stop_reason": self.stop_reason, "turning_points": np.asarray(self.turning_points, float),
                  "window_low": self.window[0], "window_high": "null" if self.window[1] is None else self.window[1],
                  "center": start.center, "lrchain_result": "bright_branch"})
    return _dataset(data_vars, coords, attrs)


def travelling_wave_to_xarray(self):
    """The wave's profile U_f(xi) on (field, xi); after lrchain.wave.stability also the growth rate and
    the NLS growth rate on the perturbation wavenumber K; the scalars (theta, A, omega, ...) as attributes."""
    fields = list(self.summary["profile"]["fields"])
    data_vars = {"profile": _var(("field", "xi"), self.profile, "U_f(xi), the wave's profile in the phase")}
    coords = {"field": ("field", fields), "xi": _var(("xi",), self.xi, "phase xi = theta n - omega t", "rad")}
    if self.stability is not None:
        coords["K"] = _var(("K",), self.stability["k"], "perturbation wavenumber K", "rad")
        data_vars["growth_rate"] = _var(("K",), self.stability["growth_rate"], "largest Re lambda at K", "1/time")
        data_vars["nls_growth_rate"] = _var(("K",), self.stability["nls_growth_rate"],
                                            "the NLS's modulational growth rate at K", "1/time")
    attrs = _provenance(self.summary)
    attrs.update({"theta": self.theta, "amplitude": self.amplitude, "omega": self.omega,
                  "omega_linear": self.omega_linear, "harmonics": self.harmonics, "tail": self.tail,
                  "residual": self.residual, "nls_omega_shift": self.nls_omega_shift,
                  "lrchain_result": "travelling_wave"})
    return _dataset(data_vars, coords, attrs)


def wave_branch_to_xarray(self):
    """The branch omega(A): omega, its shift and the NLS shift, the harmonics used, on ``amplitude``."""
    data_vars = {
        "omega": _var(("amplitude",), self.omega, "wave frequency omega", "rad/time"),
        "omega_shift": _var(("amplitude",), self.omega_shift, "omega - omega_linear", "rad/time"),
        "nls_omega_shift": _var(("amplitude",), self.nls_omega_shift, "h A^2/4, the NLS shift", "rad/time"),
        "harmonics": _var(("amplitude",), self.harmonics, "harmonics H of the collocation"),
    }
    coords = {"amplitude": _var(("amplitude",), self.amplitude, "amplitude A (the first field's cos xi harmonic)")}
    attrs = _provenance(self.summary)
    attrs.update({"theta": self.theta, "stopped": "null" if self.stopped is None else self.stopped,
                  "lrchain_result": "wave_branch"})
    return _dataset(data_vars, coords, attrs)


STATUS_MEANINGS = "missing ok blew_up numerical_failure invalid"


def open_sweep(path):
    """The results file of ``lrchain sweep`` as an :class:`xarray.Dataset`.

    A grid sweep gives every summary scalar on the sweep's axes (one dimension per axis, named as
    the axis, e.g. ``bright.theta``); a list sweep gives them on ``point`` with the axes' values as
    coordinates along it. ``status`` (0 missing, 1 ok, 2 blew_up, 3 numerical_failure, 4 invalid),
    ``reason`` and ``wall_seconds`` come along; the file's attributes (lrchain version, commit,
    date, the sweep and base configs' text, the job) become the Dataset's. Needs h5py (Debian
    ``python3-h5py``).

    Example::

        >>> import lrchain, pathlib, tempfile
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> _ = (folder / "base.toml").write_text('experiment = "regime intervals"\\n')
        >>> _ = (folder / "rho.toml").write_text(f'job = "regime intervals"\\nbase = "base.toml"\\noutput = "{folder}/rho.h5"\\n'
        ...                                      '[[axis]]\\nparameter = "model.rho"\\nvalues = [0.2, 5.0]\\n')
        >>> _ = lrchain.sweep(folder / "rho.toml", threads=1, progress=False)  # or: lrchain sweep --config rho.toml
        >>> ds = lrchain.open_sweep(folder / "rho.h5")
        >>> ds.optical_intervals.dims, ds["model.rho"].values.tolist(), ds.status.values.tolist()
        (('model.rho',), [0.2, 5.0], [1, 1])
    """
    import h5py

    with h5py.File(path, "r") as f:
        if "axes" not in f or "scalars" not in f or "status" not in f:
            raise InputError(f"open_sweep: {path} is not an lrchain sweep results file (no /axes, /scalars, /status)")
        axes_attr = f.attrs.get("axes", "")
        axes_attr = axes_attr.decode() if isinstance(axes_attr, bytes) else str(axes_attr)
        names = axes_attr.split(",") if axes_attr else sorted(f["axes"])  # the axes in the sweep file's order
        axes = {name: f["axes"][name][:] for name in names}
        status = f["status"][:]
        grid = status.shape == tuple(len(v) for v in axes.values())
        dims = tuple(names) if grid else ("point",)
        coords = {name: ((name,), values) for name, values in axes.items()} if grid else \
            {name: (("point",), values) for name, values in axes.items()}
        if not grid:
            coords["point"] = np.arange(status.size)
        data_vars = {name: (dims, f["scalars"][name][:], {"long_name": name}) for name in f["scalars"]}
        data_vars["status"] = (dims, status, {"long_name": "point status", "flag_values": np.arange(5),
                                              "flag_meanings": STATUS_MEANINGS})
        if "reason" in f:
            reason = f["reason"][:]
            data_vars["reason"] = (dims, np.vectorize(lambda r: r.decode() if isinstance(r, bytes) else r)(reason)
                                   .astype(str).reshape(status.shape), {"long_name": "why the point failed"})
        if "wall_seconds" in f:
            data_vars["wall_seconds"] = (dims, f["wall_seconds"][:].reshape(status.shape),
                                         {"long_name": "run time of the point", "units": "s"})
        attrs = {}
        for k, v in f.attrs.items():
            attrs[k] = v.decode() if isinstance(v, bytes) else v
    attrs["lrchain_result"] = "sweep"
    return _dataset(data_vars, coords, attrs)


def attach():
    """Gives each result class its ``to_xarray`` method (called once by ``import lrchain``)."""
    from . import bright, dark, regime, simulate, wave
    from .coefficients import Coefficients

    methods = {
        simulate.BrightResult: bright_to_xarray, simulate.DriveResult: drive_to_xarray,
        simulate.ModulatedResult: modulated_to_xarray, simulate.ModelBrightResult: model_bright_to_xarray,
        simulate.RingResult: ring_to_xarray, dark.DarkSolution: dark_solution_to_xarray,
        dark.ModelDarkSolution: model_dark_solution_to_xarray, dark.Branch: branch_to_xarray,
        dark.ModelBranch: model_branch_to_xarray, dark.Evolution: evolution_to_xarray,
        dark.ModelEvolution: model_evolution_to_xarray, Coefficients: coefficients_to_xarray,
        regime.Intervals: intervals_to_xarray, regime.RegimeMap: regime_map_to_xarray,
        regime.BoundaryCurve: boundary_curve_to_xarray, bright.BrightBreather: bright_breather_to_xarray,
        bright.BrightBranch: bright_branch_to_xarray, dark.Floquet: floquet_to_xarray,
        bright.BrightFloquet: floquet_to_xarray, wave.TravellingWave: travelling_wave_to_xarray,
        wave.WaveBranch: wave_branch_to_xarray,
    }
    for cls, method in methods.items():
        method.__name__ = method.__qualname__ = "to_xarray"
        cls.to_xarray = method
