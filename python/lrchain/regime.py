"""Focusing and defocusing regimes (Sec. 3.3 of the paper): the focusing theta-intervals of a branch,
the pixel maps of Fig. 2 (theta-rho plane) and Figs. 4-5 (delta0-omega plane), and the boundary
curves between the regions (omega'' = 0, h_tilde = 0 and the two non-resonance conditions).

The maps are ready for matplotlib::

    m = lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.01, 30, 600))
    plt.pcolormesh(m.rho, m.theta, m.values, shading="nearest")

Model files work the same way: pass an :class:`lrchain.Model` instead of the Params, e.g.
``lrchain.regime.theta_parameter_map(lrchain.load_model("fput"), "optical", axis="b", x=(0.1, 2))``.
The defaults and ranges are those of ``lrchain regime ...`` (one job behind both).
"""

import json
from dataclasses import dataclass

import numpy as np

from . import _lrchain
from ._keywords import documented, real_numbers, schema_options
from .errors import InvalidParameterError

#: Pixel values of the maps.
OUTSIDE, DEFOCUSING, FOCUSING, SINGULAR = -1, 0, 1, 2


@dataclass(frozen=True)
class Intervals:
    """Focusing intervals [lo[k], hi[k]] in (0, pi] and what ends each (``lo_cause``, ``hi_cause``:
    "curvature_zero", "h_tilde_zero", "nonresonance1", "nonresonance2" or "band_edge"), with every
    zero of the four smooth functions along (0, pi] (``roots``, ``root_cause``), the ``branch`` and the
    ``model`` (name, file_hash, parameters). ``to_hdf5(path)`` writes the file ``lrchain regime intervals
    --out DIR`` writes; :func:`lrchain.load` reads it back."""

    lo: np.ndarray
    hi: np.ndarray
    lo_cause: list
    hi_cause: list
    roots: np.ndarray
    root_cause: list
    branch: str = None
    model: dict = None

    def to_hdf5(self, path):
        """Writes the intervals with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5
        from .hdf5 import checked_destination

        _hdf5.write_intervals(checked_destination(path), json.dumps(self.model), self.branch or "",
                              np.asarray(self.lo, float), np.asarray(self.hi, float), list(self.lo_cause),
                              list(self.hi_cause), np.asarray(self.roots, float), list(self.root_cause))

    def __len__(self):
        return len(self.lo)

    def __iter__(self):
        return iter(zip(self.lo, self.hi))

    def __repr__(self):
        parts = ", ".join(f"[{a:.6f}, {b:.6f}]" for a, b in self)
        return f"Intervals({parts or 'none'})"


# The regime jobs' defaults, from their schemas (lrchain/jobs/regime_schema.hpp): keyword -> default.
_INTERVALS = {name: o["default"] for name, o in schema_options("regime intervals").items()}
_MAP = {name: o["default"] for name, o in schema_options("regime map").items()}
_CURVES = {name: o["default"] for name, o in schema_options("regime curves").items()}


def _job_defaults():
    return _lrchain.regime_job_defaults()


@documented(("regime intervals", "Options (the job's schema, as ``lrchain regime intervals --help``):"))
@real_numbers
def intervals(params, branch=None, samples=_INTERVALS["samples"], tolerance=_INTERVALS["tolerance"]):
    """Focusing theta-intervals of ``branch`` (omega'' h_tilde < 0), found by root finding on the
    smooth functions whose signs decide the regime; each end accurate to ``tolerance``.

    ``params`` is an :class:`lrchain.Params` (the paper's resonant chain) or an :class:`lrchain.Model`
    (any model file, e.g. ``lrchain.load_model("fput")``); ``branch`` defaults to "optical" (or a
    model's only branch). The same job as ``lrchain regime intervals [--model FILE]``.

    Example::

        >>> import lrchain
        >>> lrchain.regime.intervals(lrchain.Params(), "optical")
        Intervals([0.000000, 1.891589])
    """
    d = _lrchain.regime_structure(params, branch or "", int(samples), tolerance)
    d["model"] = json.loads(d["model"])
    return Intervals(**d)


@dataclass(frozen=True)
class RegimeMap:
    """sign(omega'' h_tilde) on a grid: ``values[j, i]`` at (``x[i]``, ``y[j]``), int8 with
    OUTSIDE (-1, out of the band), DEFOCUSING (0), FOCUSING (1), SINGULAR (2). ``pcolormesh(x, y,
    values)`` draws it; ``rho``/``theta`` (or ``delta0``/``omega``) name the axes. ``branch``, ``plane``
    and ``model`` (name, file_hash, parameters) say what it maps; ``curves`` are the traced boundary curves
    (:class:`BoundaryCurve`; a map read from the file of ``lrchain regime map --format hdf5``, empty for the
    maps of this module, which trace none: :func:`boundary_curves`). ``to_hdf5(path)`` writes the file
    ``lrchain regime map --format hdf5`` writes; :func:`lrchain.load` reads it back."""

    x: np.ndarray
    y: np.ndarray
    values: np.ndarray
    x_name: str
    y_name: str
    branch: str = None
    plane: str = None
    model: dict = None
    curves: tuple = ()

    def to_hdf5(self, path):
        """Writes the map with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5
        from .hdf5 import checked_destination

        _hdf5.write_regime_map(checked_destination(path), json.dumps(self.model), self.branch or "", self.plane or "",
                               self.x_name, self.y_name, np.asarray(self.x, float), np.asarray(self.y, float),
                               np.asarray(self.values, np.int8),
                               [(c.cause, np.asarray(c.points, float).reshape(-1, 2)) for c in self.curves])

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


def _axis(spec, n_default):
    """(lo, hi) and n of an axis given as None (the job's default range), (lo, hi) or (lo, hi, n)."""
    if spec is None:
        return None, n_default
    if len(spec) == 2:
        return (spec[0], spec[1]), n_default
    return (spec[0], spec[1]), int(spec[2])


def _keywords_named(call, keywords):
    """``call()``, with an InvalidParameterError naming a job's Config key (e.g. "nx", "rho_range")
    renamed to the keyword of this function that carries it (``keywords``: key -> keyword)."""
    try:
        return call()
    except InvalidParameterError as e:
        new = keywords.get(e.parameter)
        if new is None:
            raise
        message = str(e)
        if message.startswith(f"invalid {e.parameter}:"):
            message = f"invalid {new}:" + message[len(f"invalid {e.parameter}:"):]
        raise InvalidParameterError(message, new) from None


def _map(lattice, plane, branch, axis, x, y, x_log, x_keyword, y_keyword, x_name, y_name):
    d = _job_defaults()
    x_range, nx = _axis(x, d["nx"])
    y_range, ny = _axis(y, d["ny"])
    keywords = {"nx": x_keyword, "ny": y_keyword, "rho_range": x_keyword, "delta0_range": x_keyword,
                "axis_range": x_keyword, "theta_range": y_keyword, "omega_range": y_keyword}
    m = _keywords_named(lambda: _lrchain.regime_map(lattice, plane, branch or "", axis, x_range, nx, y_range, ny, x_log),
                        keywords)
    return RegimeMap(m["x"], m["y"], m["values"], x_name or m["axis"], y_name, branch=m["branch"], plane=m["plane"],
                     model=json.loads(m["model"]))


@documented(("regime map", "Options (the job's schema, as ``lrchain regime map --help``):"))
@real_numbers
def theta_rho_map(params, branch, rho=None, theta=None, rho_log=_MAP["rho_log"]):
    """Fig. 2: the regime at (rho_i, theta_j); the other parameters from ``params``.

    ``rho`` = (lo, hi) or (lo, hi, n) with 0 < lo, by default (0.01, 30) on the optical branch and
    (0.01, 2.5) on the acoustic one (as ``lrchain regime map``), 600 points; ``theta`` = (lo, hi, n)
    inside (0, pi] (default (pi/600, pi, 600)); ``rho_log`` spaces rho geometrically. ``params`` may be
    an :class:`lrchain.Model` with a parameter rho (see :func:`theta_parameter_map`).

    Example::

        >>> import lrchain, math
        >>> m = lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.1, 10, 20), theta=(0.1, math.pi, 20))
        >>> m.values.shape, float(m.rho[0]), bool(m.theta[-1] == math.pi)
        ((20, 20), 0.1, True)
    """
    return _map(params, "theta-rho", branch, "rho", rho, theta, rho_log, "rho", "theta", "rho", "theta")


@documented(("regime map", "Options (the job's schema, as ``lrchain regime map --help``):"))
@real_numbers
def theta_parameter_map(model, branch, axis=None, x=None, theta=None):
    """The regime at (x_i, theta_j) of a model (an :class:`lrchain.Model`, e.g. a model file), over
    its parameter ``axis`` (default rho for the resonant chain, else the model's first parameter);
    the other parameters as the model has them. The same job as ``lrchain regime map --model FILE``.

    ``x`` = (lo, hi) or (lo, hi, n) inside the parameter's range (default: its declared range when
    bounded, open ends moved in by 1e-3 of its width; rho of the resonant chain as Fig. 2), 600
    points; ``theta`` as in :func:`theta_rho_map`. The map's ``x_name`` is the parameter's name.

    Example::

        >>> import lrchain, math
        >>> m = lrchain.regime.theta_parameter_map(lrchain.load_model("fput"), "acoustic", axis="b", x=(0.1, 2, 20),
        ...                                        theta=(0.1, math.pi, 20))
        >>> m.x_name, m.values.shape
        ('b', (20, 20))
    """
    return _map(model, "theta-parameter", branch, axis or "", x, theta, False, "x", "theta", None, "theta")


@documented(("regime map", "Options (the job's schema, as ``lrchain regime map --help``):"))
@real_numbers
def delta0_omega_map(params, branch, delta0=None, omega=None, delta0_log=_MAP["delta0_log"]):
    """Figs. 4-5: the regime at (delta0_i, omega_j), theta from omega on the branch; pixels outside the
    band at delta0_i are OUTSIDE. ``delta0`` = (lo, hi) or (lo, hi, n), default (0.001, 1, 600);
    ``omega`` = (lo, hi) or (lo, hi, n), by default the branch's band over the delta0 range (optical
    [0.98 omega_lo, 1.02 omega_hi], acoustic [0, 1.02 omega_hi], as ``lrchain regime map --plane
    delta0-omega``), 600 points; each end within [0, twice the top of the optical band].

    Example::

        >>> import lrchain
        >>> m = lrchain.regime.delta0_omega_map(lrchain.Params(), "optical", delta0=(0.1, 1, 20), omega=(2.0, 3.0, 20))
        >>> m.values.shape, int((m.values == lrchain.regime.OUTSIDE).sum()) > 0
        ((20, 20), True)
    """
    return _map(params, "delta0-omega", branch, "", delta0, omega, delta0_log, "delta0", "omega", "delta0", "omega")


def map_defaults(params, branch):
    """The default ranges of the maps at ``params`` on ``branch``: {"rho": (lo, hi), "delta0": ...,
    "omega": ...} (those of ``lrchain regime map``).

    Example::

        >>> import lrchain
        >>> lrchain.regime.map_defaults(lrchain.Params(), "optical")["rho"]
        (0.01, 30.0)
    """
    return {k: tuple(v) for k, v in _lrchain.regime_map_defaults(params, branch).items()}


@dataclass(frozen=True)
class BoundaryCurve:
    """One traced zero curve: ``cause`` ("curvature_zero", "h_tilde_zero", "nonresonance1" or
    "nonresonance2") and ``points`` (k, 2): parameter value, theta (or omega: ``y_name``); the ``branch``,
    the parameter ``axis`` and the ``model`` (name, file_hash, parameters). ``to_hdf5(path)`` writes it
    (layout: :mod:`lrchain.hdf5`); :func:`lrchain.load` reads it back."""

    cause: str
    points: np.ndarray
    branch: str = None
    axis: str = None
    y_name: str = "theta"
    model: dict = None

    def to_hdf5(self, path):
        """Writes the curve with the C++ job layer's writer (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5
        from .hdf5 import checked_destination

        _hdf5.write_boundary_curve(checked_destination(path), json.dumps(self.model), self.branch or "",
                                   self.axis or "", self.y_name, self.cause,
                                   np.asarray(self.points, float).reshape(-1, 2))

    def __repr__(self):
        return f"BoundaryCurve({self.cause}, {len(self.points)} points)"


@documented(("regime curves", "Options (the job's schema):"))
@real_numbers
def boundary_curves(params, branch, axis=None, lo=None, hi=None, omega_plane=_CURVES["omega_plane"]):
    """Boundary curves between focusing and defocusing regions in the (axis, theta) plane for the
    parameter ``axis`` in [lo, hi], traced by pseudo-arclength continuation; with ``omega_plane``
    (axis "delta0") mapped to (delta0, omega) as in Figs. 4-5.

    ``params`` is an :class:`lrchain.Params` (``axis`` "rho", the default, or "delta0") or an
    :class:`lrchain.Model` (any of its parameters; default as :func:`theta_parameter_map`). Without
    ``lo``/``hi`` the range is the map's: rho (0.01, 30) optical, (0.01, 2.5) acoustic; delta0
    (0.001, 1); a model's parameter its declared range.

    Example::

        >>> import lrchain
        >>> curves = lrchain.regime.boundary_curves(lrchain.Params(), "optical", lo=0.1, hi=2)
        >>> [c.cause for c in curves], curves[0].points.shape[1]
        (['curvature_zero'], 2)
    """
    if (lo is None) != (hi is None):
        raise TypeError("boundary_curves() takes both lo and hi, or neither (the map's default range)")
    span = None if lo is None else (lo, hi)
    traced = _lrchain.boundary_curves(params, branch, axis or "", span, omega_plane)
    model = json.loads(_lrchain.lattice_model_json(params))
    axis = axis or _lrchain.lattice_default_axis(params)
    return [BoundaryCurve(cause, points, branch=branch, axis=axis, y_name="omega" if omega_plane else "theta",
                          model=model) for cause, points in traced]


@documented(("regime thresholds", "Options (the job's schema, as ``lrchain regime thresholds --help``):"))
def thresholds(model=None, scan=None, branch=None, axis=None, axis_range=None):
    """Every change of the boundary structure along a parameter (Sec. 3.3), located by root finding:
    without ``model`` the paper's scenarios (special mass ratios and precompressions, matched to the
    printed values), else the events along ``axis`` of ``model`` (an :class:`lrchain.Model`) in
    ``axis_range`` (lo, hi) on ``branch`` (default: every branch). ``scan`` points per scan (default:
    built-in 300-400; a model 300). The same job and JSON as ``lrchain regime thresholds``: a dict
    with "scenarios" (paper) or "model" and "scans", each scan with its "events".

    Example::

        >>> import lrchain
        >>> t = lrchain.regime.thresholds(lrchain.load_model("fput"), scan=50, axis="b", axis_range=(0.1, 2))
        >>> [(s["axis"], s["branch"], len(s["events"])) for s in t["scans"]]
        [('b', 'acoustic', 0)]
    """
    text = _lrchain.regime_thresholds(model, int(scan or 0), branch or "", axis or "",
                                      None if axis_range is None else (axis_range[0], axis_range[1]))
    return json.loads(text)


@real_numbers
def frequency_band(params, branch):
    """(lo, hi) of the linear band: optical [omega_+(0), omega_+(pi)], acoustic [0, omega_-(pi)].

    Example::

        >>> import lrchain
        >>> lo, hi = lrchain.regime.frequency_band(lrchain.Params(), "optical")
        >>> round(lo, 6), round(hi, 6)
        (2.0, 2.44949)
    """
    return _lrchain.frequency_band(params, branch)
