"""``lrchain.load(path)``: any file lrchain writes, read back into the object it came from.

- an HDF5 result (``result.to_hdf5(path)``, or the HDF5 files of ``lrchain simulate|dark|bright|wave ...
  --format hdf5``, ``lrchain regime map --format hdf5``, ``lrchain coeffs|regime intervals --out DIR``:
  the file's root attribute ``lrchain_result`` names the class) -> that result class
  (:class:`lrchain.simulate.BrightResult`, ..., :class:`lrchain.dark.ModelEvolution`,
  :class:`lrchain.Coefficients`, :class:`lrchain.regime.Intervals`, :class:`~lrchain.regime.RegimeMap`,
  :class:`~lrchain.regime.BoundaryCurve`, :class:`lrchain.bright.BrightBreather`,
  :class:`~lrchain.bright.BrightBranch`, :class:`~lrchain.bright.BrightEvolution`, :class:`lrchain.wave.TravellingWave`,
  :class:`~lrchain.wave.WaveBranch`, :class:`~lrchain.wave.StandingWave`), with the same arrays, bit for bit, and the summary read from its
  tree (a bright breather's and a wave's from its exact JSON text; layout: :mod:`lrchain.hdf5`);
- a sweep's results file (``lrchain sweep``) -> an :class:`xarray.Dataset` (:func:`lrchain.open_sweep`);
- a folder a command wrote (``--out DIR``) -> its ``result.h5`` or, failing that, its one sweep file;
- a JSON file (the command's summary, ``summary.json``) -> a dict.

A summary read from HDF5 lost what the tree cannot hold: null values are left out of the file, and
true/false are read as 1/0. Snapshot columns come back with ``n`` first, the others in alphabetical
order (HDF5 lists a group's members so). Needs h5py (Debian ``python3-h5py``) for HDF5 files.
"""

import json
import os

import numpy as np

from .errors import InputError

# The measures of a dark breather, in the order the jobs report them (sim/dark/dark_hdf5.cpp).
_MEASURES = ("norm_squared", "K_x", "K_y", "C_x", "C_y", "E_b", "max_strain")
_FLOQUET = ("kind", "max_modulus", "max_real", "max_period_doubling", "max_oscillatory", "near_one",
            "pairing_defect", "conjugation_defect", "log_det")


def _text(value):
    return value.decode() if isinstance(value, bytes) else value


def _scalar(value):
    """An HDF5 attribute as a Python value: str, int or float."""
    value = _text(value)
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    return value


def _string_list(value):
    """A list of strings the writers store as JSON text (``'["a", "b"]'``)."""
    return json.loads(_text(value))


def _tree(group):
    """The summary tree back as JSON-like data (sim/result_hdf5.cpp's write_json_tree reversed):
    groups are dicts (lists when their members are 0, 1, ...), attributes numbers and strings (JSON
    text of a list of strings becomes the list), datasets lists of numbers."""
    import h5py

    d = {}
    for name, value in group.attrs.items():
        value = _scalar(value)
        if isinstance(value, str) and value.startswith("[") and value.endswith("]"):
            try:
                parsed = json.loads(value)
            except ValueError:
                parsed = None
            if isinstance(parsed, list) and all(isinstance(s, str) for s in parsed):
                value = parsed
        d[name] = value
    for name, item in group.items():
        d[name] = item[()].tolist() if isinstance(item, h5py.Dataset) else _tree(item)
    for name, value in d.items():
        if isinstance(value, dict) and value and all(k.isdigit() for k in value):
            d[name] = [value[str(i)] for i in range(len(value))]
    return d


def _summary(f):
    """The summary tree, with its ``model`` from the root attribute (exact JSON text: nulls and
    booleans kept)."""
    summary = _tree(f["summary"])
    if "model" in f.attrs:
        summary["model"] = json.loads(_text(f.attrs["model"]))
    return summary


def _snapshots(f):
    from .simulate import Snapshot

    out = []
    group = f.get("snapshots", {})
    for k in sorted(group, key=int):
        s = group[k]
        names = sorted(s["columns"], key=lambda c: (c != "n", c))
        out.append(Snapshot(float(s.attrs["t"]), _text(s.attrs["tag"]), {c: s["columns"][c][()] for c in names}))
    return out


def _spacetime(f, name):
    from .simulate import SpaceTime

    if name not in f:
        return None
    g = f[name]
    return SpaceTime(_text(g.attrs["quantity"]), g["n"][()], g["t"][()], g["values"][()])


def _simulation(f, cls):
    """BrightResult, DriveResult, ModulatedResult: the series under their attribute names."""
    values = {name: f[name][()] for _, name in cls._series}
    values.update({name: _spacetime(f, name) for name in cls._fields})
    return cls(energy_density=_spacetime(f, "energy_density"), snapshots=_snapshots(f), summary=_summary(f),
               **values)


def _model_bright(f, cls):
    fields = sorted((k for k in f if k.startswith("E_") and k[2:].isdigit()), key=lambda k: int(k[2:]))
    return cls(t=f["t"][()], E=tuple(f[k][()] for k in fields), energy=f["energy"][()], centre=f["centre"][()],
               snapshots=_snapshots(f), summary=_summary(f))


def _ring(f, cls):
    return cls(packet_t=f["packet_t"][()], packet_centre=f["packet_centre"][()], summary=_summary(f),
               **{name: f[name][()] for name in cls._amplitude_columns})


def _params(f):
    """The resonant chain's Params from the root attribute ``model``."""
    from ._lrchain import Params

    return Params(**json.loads(_text(f.attrs["model"]))["parameters"])


def _measures(values):
    """A measures dict in the jobs' order, None for a measure the file leaves out (K_y, C_y of a
    model with one strain-form variable)."""
    return {k: (None if values.get(k) is None else float(values[k])) for k in _MEASURES}


def _floquet(g):
    """One Floquet result from the group ``floquet`` of a dark solution (None without one)."""
    from .dark import Floquet

    if g is None:
        return None
    values = {k: _scalar(g.attrs[k]) for k in _FLOQUET}
    return Floquet(multipliers=g["multipliers"][()], **values)


def _floquet_points(f, points):
    """Per point of a branch: a Floquet result, or None where the multipliers were not computed."""
    from .dark import Floquet

    g = f.get("floquet")
    if g is None:
        return [None] * points
    kinds = _string_list(g.attrs["kind"])
    columns = {k: g[k][()] for k in _FLOQUET if k != "kind"}
    return [Floquet(multipliers=g["multipliers"][i], kind=kinds[i],
                    **{k: _scalar(v[i]) for k, v in columns.items()}) for i in range(points)]


def _branch_points(f):
    """The per-point series every branch file has."""
    points = len(f["omega_b"])
    measures = [_measures({k: f["measures"][k][i] for k in f["measures"]}) for i in range(points)]
    turning = f["turning_points"][()].tolist() if "turning_points" in f else _string_list(f.attrs["turning_points"])
    return dict(omega_b=f["omega_b"][()], tangent_omega=f["tangent_omega"][()], residual=f["residual"][()],
                iterations=f["iterations"][()], measures=measures, floquet=_floquet_points(f, points),
                turning_points=turning, stop_reason=_text(f.attrs["stop_reason"]))


def _edge(f):
    """The band edge and model of a model-file dark result (dark._ModelEdge's fields)."""
    a = f.attrs
    return dict(branch=_text(a["branch"]), theta=float(a["theta"]), omega_edge=float(a["omega_edge"]),
                curvature=float(a["curvature"]), h_tilde=float(a["h_tilde"]),
                lambda_=float(a["lambda"]) if "lambda" in a else None, lattice_form=_text(a["lattice_form"]),
                model=json.loads(_text(a["model"])), one_sided_contacts=tuple(_string_list(a["one_sided_contacts"])))


def _dark_solution(f, cls):
    return cls(omega_b=float(f.attrs["omega_b"]), n=f["n"][()], x=f["x"][()], y=f["y"][()], x_seed=f["x_seed"][()],
               y_seed=f["y_seed"][()], newton_residuals=f["newton_residuals"][()],
               omega_edge=float(f.attrs["omega_edge"]), measures=_measures(dict(f["measures"].attrs)),
               floquet=_floquet(f.get("floquet")), params=_params(f))


def _model_dark_solution(f, cls):
    changes = f.attrs.get("contact_changes_per_period")
    return cls(omega_b=float(f.attrs["omega_b"]), n=f["n"][()], z=f["z"][()], seed=f["seed"][()],
               variables=tuple(_string_list(f.attrs["variables"])), newton_residuals=f["newton_residuals"][()],
               measures=_measures(dict(f["measures"].attrs)), floquet=_floquet(f.get("floquet")),
               contact_changes_per_period=None if changes is None else int(changes), **_edge(f))


def _branch(f, cls):
    return cls(x=f["x"][()], y=f["y"][()], params=_params(f), **_branch_points(f))


def _model_branch(f, cls):
    points = _branch_points(f)
    changes = f["contact_changes_per_period"][()].tolist() if "contact_changes_per_period" in f else \
        [None] * len(points["omega_b"])
    extra = {}
    if "parameter_values" in f:  # the continued parameter (files of earlier versions: omega_b, not stored)
        extra = dict(parameter=_text(f.attrs["parameter"]), parameter_values=f["parameter_values"][()].tolist())
    return cls(z=f["z"][()], n=f["n"][()], variables=tuple(_string_list(f.attrs["variables"])),
               contact_changes_per_period=changes, **points, **_edge(f), **extra)


def _evolution_series(f):
    return dict(period=float(f.attrs["period"]), max_strain=float(f.attrs["max_strain"]),
                **{k: f[k][()] for k in ("t", "E_b", "C_x", "K_x", "position", "depth")})


def _evolution(f, cls):
    return cls(x=f["x"][()], y=f["y"][()], params=_params(f), **_evolution_series(f))


def _model_evolution(f, cls):
    return cls(z=f["z"][()], n=f["n"][()], variables=tuple(_string_list(f.attrs["variables"])),
               **_evolution_series(f), **_edge(f))


def _model(f):
    """The root attribute ``model`` as a dict."""
    return json.loads(_text(f.attrs["model"]))


def _coefficients(f, cls):
    """Coefficients: a scalar theta comes back as floats (and an int regime_code), an array as arrays."""
    from .coefficients import _COLUMNS

    theta = f["theta"][()]
    scalar = np.ndim(theta) == 0
    value = float if scalar else np.asarray
    values = {("lambda_" if name == "lambda" else name): value(f[name][()]) for name in _COLUMNS}
    code = f["regime_code"][()]
    return cls(theta=value(theta), regime_code=int(code) if scalar else code, branch=_text(f.attrs["branch"]),
               source=_model(f), **values)


def _intervals(f, cls):
    a = f.attrs
    return cls(lo=f["lo"][()], hi=f["hi"][()], lo_cause=_string_list(a["lo_cause"]), hi_cause=_string_list(a["hi_cause"]),
               roots=f["roots"][()], root_cause=_string_list(a["root_cause"]), branch=_text(a["branch"]), model=_model(f))


def _boundary_curve(f, cls):
    a = f.attrs
    return cls(cause=_text(a["cause"]), points=f["points"][()], branch=_text(a["branch"]), axis=_text(a["axis"]),
               y_name=_text(a["y_name"]), model=_model(f))


def _regime_map(f, cls):
    from .regime import BoundaryCurve

    a = f.attrs
    x_name, y_name, branch, model = _text(a["x_name"]), _text(a["y_name"]), _text(a["branch"]), _model(f)
    group = f["curves"]
    curves = tuple(BoundaryCurve(cause=_text(group[k].attrs["cause"]), points=group[k]["points"][()], branch=branch,
                                 axis=x_name, y_name=y_name, model=model) for k in sorted(group, key=int))
    return cls(x=f["x"][()], y=f["y"][()], values=f["values"][()], x_name=x_name, y_name=y_name, branch=branch,
               plane=_text(a["plane"]), model=model, curves=curves)


def _bright_job(f):
    """The bright-breather job's dict (bright._run's): the summary from its exact JSON text, Z(0), seed, variables."""
    d = json.loads(_text(f.attrs["summary_json"]))
    d.update(z=f["z"][()], seed=f["seed"][()], variables=tuple(_string_list(f.attrs["variables"])))
    return d


def _bright_breather(f, cls):
    from .bright import _breather

    return _breather(_bright_job(f))


def _bright_branch(f, cls):
    from .bright import _branch

    d = _bright_job(f)
    d["branch_z"] = f["branch_z"][()]
    return _branch(d)


def _bright_evolution(f, cls):
    from .bright import _evolution

    d = _bright_job(f)
    t = f["t"][()]
    # a model without a potential has no energy dataset: zeros, as lrchain.bright.evolve gives them
    energy = f["energy"][()] if "energy" in f else np.zeros_like(t)
    return _evolution(d, t, f["deviation"][()], energy)


def _travelling_wave(f, cls):
    from .wave import _wave

    d = json.loads(_text(f.attrs["summary_json"]))
    d["profile_array"] = f["profile"][()]
    return _wave(d)


def _wave_branch(f, cls):
    from .wave import _branch

    return _branch(json.loads(_text(f.attrs["summary_json"])))


def _standing_wave(f, cls):
    from .errors import NumericalFailure
    from .wave import _standing

    d = json.loads(_text(f.attrs["summary_json"]))
    if d["failure"] is not None:  # the command's exit 3: the file holds the ramp up to the failure, no wave
        raise NumericalFailure(f"load: {f.filename} holds no standing wave at A = {d['options']['amplitude']} "
                               f"({d['failure']}); its ramp is in the file's amplitude and omega")
    d["coefficients_array"] = f["coefficients"][()]
    return _standing(d)


def _readers():
    """Result class name (the files' ``lrchain_result``) -> (class, reader)."""
    from . import bright, dark, regime, simulate, wave
    from .coefficients import Coefficients

    return {"BrightResult": (simulate.BrightResult, _simulation), "DriveResult": (simulate.DriveResult, _simulation),
            "ModulatedResult": (simulate.ModulatedResult, _simulation),
            "ModelBrightResult": (simulate.ModelBrightResult, _model_bright),
            "RingResult": (simulate.RingResult, _ring), "DarkSolution": (dark.DarkSolution, _dark_solution),
            "ModelDarkSolution": (dark.ModelDarkSolution, _model_dark_solution),
            "Branch": (dark.Branch, _branch), "ModelBranch": (dark.ModelBranch, _model_branch),
            "Evolution": (dark.Evolution, _evolution), "ModelEvolution": (dark.ModelEvolution, _model_evolution),
            "Coefficients": (Coefficients, _coefficients), "Intervals": (regime.Intervals, _intervals),
            "RegimeMap": (regime.RegimeMap, _regime_map), "BoundaryCurve": (regime.BoundaryCurve, _boundary_curve),
            "BrightBreather": (bright.BrightBreather, _bright_breather),
            "BrightBranch": (bright.BrightBranch, _bright_branch),
            "BrightEvolution": (bright.BrightEvolution, _bright_evolution),
            "TravellingWave": (wave.TravellingWave, _travelling_wave), "WaveBranch": (wave.WaveBranch, _wave_branch),
            "StandingWave": (wave.StandingWave, _standing_wave)}


def _load_hdf5(path):
    import h5py

    from .labelled import open_sweep

    with h5py.File(path, "r") as f:
        kind = _text(f.attrs.get("lrchain_result", ""))
        if not kind and "axes" in f and "scalars" in f and "status" in f:
            kind = "sweep"
        if kind != "sweep":
            readers = _readers()
            if kind not in readers:
                raise InputError(f"load: {path} is an HDF5 file but not an lrchain result (root attribute "
                                 f"lrchain_result {kind or 'missing'}; readable: {', '.join(readers)}, sweep results)")
            cls, reader = readers[kind]
            try:
                return reader(f, cls)
            except KeyError as e:
                raise InputError(f"load: {path}: a {kind} file without {e.args[0]!r} (damaged, or written by "
                                 f"another lrchain version)") from None
    return open_sweep(path)


def _is_hdf5(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89HDF\r\n\x1a\n"


def load(path):
    """The result in ``path``, a file (or folder) lrchain wrote, as the object that wrote it.

    An HDF5 result file gives back its result class (:class:`lrchain.simulate.BrightResult`,
    :class:`lrchain.dark.Branch`, ...: the root attribute ``lrchain_result`` says which) with the same
    arrays; a sweep's results file an :class:`xarray.Dataset` (as :func:`lrchain.open_sweep`); a
    folder of a command's ``--out`` its ``result.h5`` (or its one sweep file); a JSON file (a
    command's summary) a dict. Raises :class:`lrchain.InputError` naming the file for anything else.
    Layout and what a summary read from HDF5 loses: :mod:`lrchain.reading`.

    Example::

        >>> import lrchain, tempfile, os
        >>> run = lrchain.simulate.bright(sites=41, periods=1, progress=False)
        >>> path = os.path.join(tempfile.mkdtemp(), "run.h5")
        >>> run.to_hdf5(path)
        >>> again = lrchain.load(path)
        >>> type(again).__name__, bool((again.E_x == run.E_x).all())
        ('BrightResult', True)
    """
    path = os.fspath(path)
    if os.path.isdir(path):
        if os.path.isfile(os.path.join(path, "result.h5")):
            return load(os.path.join(path, "result.h5"))
        files = sorted(name for name in os.listdir(path) if name.endswith(".h5"))
        if len(files) == 1:
            return load(os.path.join(path, files[0]))
        raise InputError(f"load: the folder {path} has no result.h5 and {len(files)} .h5 files "
                         f"({', '.join(files) or 'none'}); name the file")
    if not os.path.isfile(path):
        raise InputError(f"load: {path} does not exist or is not a regular file")
    if _is_hdf5(path):
        return _load_hdf5(path)
    if path.endswith(".json"):
        with open(path, encoding="utf-8") as f:
            try:
                return json.load(f)
            except ValueError as e:
                raise InputError(f"load: {path} is not valid JSON ({e})") from None
    raise InputError(f"load: {path} is neither an HDF5 file nor a .json file (lrchain.load reads results in "
                     f"HDF5, sweep results and JSON summaries; read a CSV with numpy.loadtxt)")
