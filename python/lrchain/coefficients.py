"""NLS coefficients of the modulation equations, vectorised over the carrier wavenumber."""

import json
from dataclasses import dataclass, field, fields

import numpy as np

from . import _lrchain
from ._keywords import documented, real_numbers
from .errors import InvalidParameterError

REGIME_NAMES = np.array(_lrchain.regime_names)

# The coefficient arrays, in the order of the HDF5 file (lrchain/jobs/coeffs_hdf5.hpp); "lambda" is lambda_.
_COLUMNS = ("omega", "group_velocity", "curvature", "gamma", "beta", "h", "lambda", "h_tilde", "nonresonance1",
            "nonresonance2")


@dataclass(frozen=True, repr=False)
class Coefficients:
    """NLS coefficients of one branch (Sec. 3 of the paper), with the shape of ``theta``.

    Every field is a float (scalar ``theta``) or a numpy array of the shape of ``theta``:

    - ``omega``: carrier frequency omega(theta) (dispersion relation);
    - ``group_velocity``: c = omega'(theta);
    - ``curvature``: omega''(theta);
    - ``gamma``, ``beta``: factors of the modulation equations;
    - ``h``: cubic coefficient before the mean flow is eliminated;
    - ``lambda_``: mean-flow factor lambda (``c["lambda"]`` also works);
    - ``h_tilde``: h - lambda * beta, the NLS nonlinearity;
    - ``nonresonance1``, ``nonresonance2``: the non-resonance values, nonzero away from resonances;
    - ``regime``: ``"focusing"`` (omega'' h_tilde < 0), ``"defocusing"`` (> 0), ``"degenerate"`` (= 0,
      e.g. theta = 0 on the optical branch) or ``"singular"``;
    - ``regime_code``: the same as int8 codes 0, 1, 2, 3 (indices into ``REGIME_NAMES``).

    NaN policy: ``h``, ``lambda_`` and ``h_tilde`` are NaN exactly where ``regime == "singular"``
    (a non-resonance value vanishes to within 1e-12 of its terms: h_tilde has a pole there). All other
    fields are finite everywhere.

    ``branch`` and ``model`` (name, file_hash, parameters) say what was evaluated; ``to_hdf5(path)``
    writes the file ``lrchain coeffs --out DIR`` writes (:mod:`lrchain.hdf5`), ``to_xarray()`` a Dataset.
    """

    theta: object
    omega: object
    group_velocity: object
    curvature: object
    gamma: object
    beta: object
    h: object
    lambda_: object
    h_tilde: object
    nonresonance1: object
    nonresonance2: object
    regime_code: object
    branch: object = None
    # The Params or Model evaluated (its model object made when asked), or the model dict read from a file.
    source: object = field(default=None, repr=False, compare=False)

    @property
    def model(self):
        """The model evaluated as a dict (name, file_hash, parameters), as every output's "model"; None
        for coefficients made by hand."""
        if self.source is None or isinstance(self.source, dict):
            return self.source
        return json.loads(_lrchain.lattice_model_json(self.source))

    def to_hdf5(self, path):
        """Writes the coefficients with the C++ job layer's writer: the file ``lrchain coeffs ... --out
        DIR`` writes (theta of any shape; layout: :mod:`lrchain.hdf5`). :func:`lrchain.load` reads it back."""
        from . import _hdf5
        from .hdf5 import checked_destination

        columns = {name: np.asarray(self[name], dtype=np.float64) for name in _COLUMNS}
        _hdf5.write_coefficients(checked_destination(path), json.dumps(self.model), self.branch or "",
                                 np.asarray(self.theta, dtype=np.float64), columns,
                                 np.asarray(self.regime_code, dtype=np.int8))

    @property
    def regime(self):
        """Regime names ("focusing", ...) from ``regime_code``: a str, or an array of str."""
        if np.ndim(self.regime_code) == 0:
            return str(REGIME_NAMES[self.regime_code])
        return REGIME_NAMES[self.regime_code]

    def __getitem__(self, name):
        """``c["lambda"]`` (the field ``lambda_``) or any other field by name."""
        return getattr(self, "lambda_" if name == "lambda" else name)

    def as_dict(self):
        """{name: value} with the key "lambda" for lambda_."""
        d = {("lambda" if f.name == "lambda_" else f.name): getattr(self, f.name) for f in fields(self)
             if f.name not in ("branch", "source")}
        d["regime"] = self.regime
        return d

    def __repr__(self):
        if np.ndim(self.theta) == 0:
            body = ", ".join(
                f"{k}={v!r}" if isinstance(v, str) else f"{k}={float(v)!r}"
                for k, v in self.as_dict().items()
                if k != "regime_code"
            )
            return f"Coefficients({body})"
        counts = {name: int(np.count_nonzero(self.regime_code == i)) for i, name in enumerate(REGIME_NAMES)}
        summary = ", ".join(f"{n} {k}" for k, n in counts.items() if n)
        return f"Coefficients(shape={np.shape(self.theta)}, {summary})"


@documented(("coeffs", "Options (the job's schema, as ``lrchain coeffs --help``):"))
@real_numbers
def coefficients(params, branch, theta, out=None):
    """NLS coefficients of ``branch`` at every wavenumber of ``theta``.

    ``params`` is a :class:`lrchain.Params` (the resonant chain; ``branch`` "optical" or
    "acoustic") or a :class:`lrchain.Model` from :func:`lrchain.load_model` (``branch`` one of
    ``model.branches``). ``theta`` is a number or an array-like of any shape with values in
    (-pi, pi] (nonzero on an acoustic branch); the evaluation is one C++ loop over the array.
    Returns :class:`Coefficients`; for a model without mean flow (``model.mean_flow`` False, e.g.
    klein_gordon) ``lambda_`` is NaN everywhere and ``h_tilde`` equals ``h``. Raises
    :class:`lrchain.InvalidParameterError` naming ``theta`` (and the first bad index) or ``branch``
    for invalid input.

    ``out``: an earlier :class:`Coefficients` of an array of the same shape, whose arrays are
    overwritten and returned in a new :class:`Coefficients` instead of allocating new ones (for
    repeated large evaluations: fresh arrays cost page faults comparable to the evaluation itself).

    Example::

        >>> import lrchain, numpy as np
        >>> c = lrchain.coefficients(lrchain.Params(), "optical", 1.0)
        >>> round(c.omega, 6), c.regime
        (2.067381, 'focusing')
        >>> lrchain.coefficients(lrchain.Params(), "optical", np.linspace(0.5, 3, 4)).regime.tolist()
        ['focusing', 'focusing', 'defocusing', 'defocusing']
    """
    scalar = np.ndim(theta) == 0
    theta_array = np.asarray(theta, dtype=np.float64)
    arrays = None
    if out is not None:
        if scalar or not isinstance(out, Coefficients) or np.ndim(out.omega) == 0:
            raise InvalidParameterError("out must be an earlier Coefficients of an array theta", "out")
        arrays = {name: out[name] for name in _COLUMNS}
        arrays["regime"] = out.regime_code
    if isinstance(params, _lrchain.Model):
        values = _lrchain.model_coefficients_array(params, branch, theta_array, arrays)
    else:
        values = _lrchain.coefficients_array(params, branch, theta_array, arrays)
    codes = values.pop("regime")
    if scalar:
        values = {k: float(v) for k, v in values.items()}
        return Coefficients(theta=float(theta_array), lambda_=values.pop("lambda"), regime_code=int(codes),
                            branch=branch, source=params, **values)
    return Coefficients(theta=theta_array, lambda_=values.pop("lambda"), regime_code=codes, branch=branch,
                        source=params, **values)
