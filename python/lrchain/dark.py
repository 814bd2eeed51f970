"""Exact stationary dark breathers (Sec. 5.3-5.4 of the paper): time-periodic solutions of the strain
lattice with periodic ends, found by shooting Newton from the NLS approximation (eq. (48)),
continued in the frequency omega_b, with their Floquet multipliers and direct evolution.

Every function starts from ``solve``'s arguments: ``params``, ``omega_b`` (on the gap side of the
theta = pi band edge of ``branch``, "optical" or "acoustic"), ``center`` ("bond" or "site"), ``sites``
(odd, >= 9), ``mode`` ("reversible" or "full" shooting), Newton's ``tolerance`` (max |F|) and
``max_iterations``: the options of ``lrchain dark solve|floquet|continue|evolve``.

With ``model=`` (an :class:`lrchain.Model`: a shipped model or your own model file), they are
``lrchain dark ... --model FILE``: the model's generated lattice on a periodic ring, at the band edge
where its NLS is defocusing (``branch`` a name of ``model.branches``, default the first with a
defocusing edge; theta = pi first, then theta = 0), ``omega_b`` required; the results are
:class:`ModelDarkSolution`, :class:`ModelBranch` and :class:`ModelEvolution`. Newton failing raises :class:`lrchain.NumericalFailure`; Ctrl-C during any of
these computations (Newton, the Floquet multipliers' monodromy matrix, continuation, evolution)
stops it within one integration step and raises ``KeyboardInterrupt``.
"""

from dataclasses import asdict, dataclass, fields

import numpy as np

from . import _lrchain
from ._keywords import checked_model, documented, python_names, real_numbers, renamed
from ._lrchain import Model, Params
from .errors import InputError
from .hdf5 import checked_destination
from .progress import Bar

# The dark job's defaults, from its one schema (lrchain/jobs/dark_schema.hpp, the defaults of DarkConfig):
# keyword -> default. omega_b, branch and t_end have none there (None here: see _job and evolve).
_OPTIONS = {o["python"]: o for o in _lrchain.dark_options() if o["python"]}
_D = {name: o["default"] for name, o in _OPTIONS.items()}


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
class DarkSolution:
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

        _hdf5.write_dark_solution(checked_destination(path), _params_tuple(self.params), _plain(self))

    def __repr__(self):
        f = f", {self.floquet!r}" if self.floquet else ""
        return (f"DarkSolution(omega_b={self.omega_b}, {len(self.n)} sites, Newton residual "
                f"{self.newton_residuals[-1]:.3g} after {len(self.newton_residuals) - 1} steps, "
                f"E_b = {self.measures['E_b']:.3g}{f})")


def _floquet(d):
    return None if d is None else Floquet(**d)


def _solution(params, omega_b, d):
    return DarkSolution(omega_b=omega_b, floquet=_floquet(d.pop("floquet", None)), params=params, **d)


def _job(params, model, omega_b, branch, function):
    """(params, model, omega_b, branch) of a job: bright-style ``solve(model, ...)`` accepted, the
    paper chain's defaults (omega_b 2.42, branch "optical") without a model."""
    if model is None and isinstance(params, Model):
        model, params = params, None
    if model is not None:
        checked_model(model)
        if params is not None:
            raise InputError(f"{function}: give params (the resonant chain) or model, not both")
        if omega_b is None:
            raise InputError(f"{function}: omega_b is required with model= (the breather frequency, on the side of "
                             f"the defocusing band edge where (omega_b - omega) h > 0)")
        return None, model, omega_b, branch
    return (Params() if params is None else params), None, (2.42 if omega_b is None else omega_b), \
        ("optical" if branch is None else branch)


@documented(("dark", "Options (the job's schema, as ``lrchain dark ... --help``):"))
@renamed("dark")
@real_numbers
def solve(params=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], mode=_D["mode"],
          tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], *, model=None):
    """Newton (least squares) from the seed of eq. (48) (omega_b default 2.42, branch "optical");
    returns :class:`DarkSolution`. With ``model``: the model's seed at its defocusing edge; returns
    :class:`ModelDarkSolution`.

    Example::

        >>> import lrchain
        >>> s = lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=11)
        >>> len(s.x), bool(s.newton_residuals[-1] < 1e-10), bool(s.measures["E_b"] < 1e-8)
        (11, True, True)
    """
    params, model, omega_b, branch = _job(params, model, omega_b, branch, "solve")
    if model is not None:
        return _model_solution(python_names(lambda: _lrchain.dark_model_solve(
            model, omega_b, branch, center, sites, mode, tolerance, max_iterations, False)), omega_b)
    d = python_names(lambda: _lrchain.dark_solve(params, omega_b, branch, center, sites, mode, tolerance,
                                                 max_iterations, False, False))
    return _solution(params, omega_b, d)


@documented(("dark", "Options (the job's schema, as ``lrchain dark ... --help``):"))
@renamed("dark")
@real_numbers
def floquet(params=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], mode=_D["mode"],
            tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], full_monodromy=_D["full_monodromy"], *,
            model=None):
    """Solve, then the Floquet multipliers of the monodromy matrix (from the reversible reduction,
    or integrated over a full period with ``full_monodromy``); returns :class:`DarkSolution` with
    ``floquet`` set. With ``model`` the multipliers always come from the full-period monodromy (the
    symplectic pairing defect is a check); returns :class:`ModelDarkSolution`.

    Example::

        >>> import lrchain
        >>> s = lrchain.dark.floquet(lrchain.Params(), omega_b=2.42, sites=11)
        >>> s.floquet.kind, len(s.floquet.multipliers), round(s.floquet.max_modulus, 3)
        ('oscillatory', 44, 1.188)
    """
    params, model, omega_b, branch = _job(params, model, omega_b, branch, "floquet")
    if model is not None:
        if full_monodromy:
            raise InputError("full_monodromy: with model= the Floquet multipliers always come from the full-period "
                             "monodromy")
        return _model_solution(python_names(lambda: _lrchain.dark_model_solve(
            model, omega_b, branch, center, sites, mode, tolerance, max_iterations, True)), omega_b)
    d = python_names(lambda: _lrchain.dark_solve(params, omega_b, branch, center, sites, mode, tolerance,
                                                 max_iterations, True, full_monodromy))
    return _solution(params, omega_b, d)


@dataclass(frozen=True, repr=False)
class _ModelEdge:
    """The band edge and the model every model-file dark result reports: ``branch``, ``theta``,
    ``omega_edge``, ``curvature``, ``h_tilde``, ``lambda_`` (None without mean flow),
    ``lattice_form``, ``model`` (name, file_hash, parameters, lattice_code) and
    ``one_sided_contacts`` (the contact bonds by name, e.g. ``("F(u[n+1] - u[n])",)``; empty for a
    smooth model), whose contact changes are located during the integration."""

    branch: str
    theta: float
    omega_edge: float
    curvature: float
    h_tilde: float
    lambda_: float
    lattice_form: str
    model: dict
    one_sided_contacts: tuple


@dataclass(frozen=True, repr=False)
class ModelDarkSolution(_ModelEdge):
    """A converged dark breather of a model file: ``z`` (fields, sites) = Z(0) in the lattice's
    ``variables`` (strains r, w1, ... of translation-invariant models, displacements u0, u1, ... of
    on-site models) on sites ``n`` (centred), the NLS ``seed`` (same shape), Newton's residual
    history, the edge (``branch``, ``theta``, ``omega_edge``, ``curvature``, ``h_tilde``, ``lambda_``
    (None without mean flow)), ``lattice_form``, ``measures`` (norm_squared, K_x, K_y, C_x, C_y, E_b,
    max_strain; K_y, C_y None where there is no second strain-form variable), ``floquet`` (a
    :class:`Floquet` or None), ``contact_changes_per_period`` (sign changes of the one-sided contacts'
    overlaps over one period; None for a smooth model) and ``model`` (name, file_hash, parameters,
    lattice_code)."""

    omega_b: float
    n: np.ndarray
    z: np.ndarray
    seed: np.ndarray
    variables: tuple
    newton_residuals: np.ndarray
    measures: dict
    floquet: Floquet = None
    contact_changes_per_period: int = None

    def to_hdf5(self, path):
        """Writes this solution with the C++ job layer's writer, the file ``lrchain dark solve|floquet
        --model ... --format hdf5`` writes (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_model_dark_solution(checked_destination(path), _plain(self))

    def __repr__(self):
        f = f", {self.floquet!r}" if self.floquet else ""
        return (f"ModelDarkSolution({self.model['name']}, omega_b={self.omega_b}, {len(self.n)} sites, Newton "
                f"residual {self.newton_residuals[-1]:.3g}, E_b = {self.measures['E_b']:.3g}{f})")


def _edge(d):
    """The fields every model job reports, renamed for Python (lambda -> lambda_)."""
    d["lambda_"] = d.pop("lambda")
    return d


def _model_solution(d, omega_b):
    d = _edge(d)
    return ModelDarkSolution(omega_b=omega_b, floquet=_floquet(d.pop("floquet")), **d)


@dataclass(frozen=True, repr=False)
class Branch:
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

        _hdf5.write_dark_branch(checked_destination(path), _params_tuple(self.params), _plain(self))

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


@documented(("dark", "Options (the job's schema, as ``lrchain dark ... --help``):"))
@renamed("dark")
@real_numbers
def continue_branch(params=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], mode=_D["mode"],
                    tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], points=_D["points"], ds=_D["ds"],
                    omega_min=_D["omega_min"], omega_max=_D["omega_max"],
                    floquet=_D["floquet"], parameter=_D["parameter"], to=_D["to"], *, model=None, progress=None):
    """Solve at ``omega_b``, then continue the family (at most ``points`` points, initial arclength step
    ``ds``) while omega_b stays in [omega_min, omega_max] (default: up to the band edge), with the
    Floquet multipliers at every point if ``floquet``; returns :class:`Branch`. With ``model``: away
    from the model's edge (into the gap below it, upwards from an edge the branch rises from, as
    ``lrchain dark continue --model``); returns :class:`ModelBranch`. ``parameter`` (with ``model``:
    one of its parameters, at fixed omega_b) and ``to`` (where the branch ends, its last point solved
    there, e.g. ``parameter="C", to=0``) as ``--parameter``/``--to``. ``progress``: a bar over the
    points (see :mod:`lrchain.progress`).

    Example::

        >>> import lrchain
        >>> b = lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=11, points=3, ds=0.05, progress=False)
        >>> len(b.omega_b), b.stop_reason, b.x.shape
        (3, 'reached 3 points', (3, 11))
    """
    params, model, omega_b, branch = _job(params, model, omega_b, branch, "continue_branch")
    if model is not None:
        with Bar("dark-breather branch", progress, unit="point") as bar:
            d = _edge(python_names(lambda: _lrchain.dark_model_continue(
                model, omega_b, branch, center, sites, mode, tolerance, max_iterations, points, ds, omega_min,
                omega_max, floquet, parameter, to, bar.callback)))
        d["floquet"] = [_floquet(f) for f in d["floquet"]]
        return ModelBranch(**d)
    with Bar("dark-breather branch", progress, unit="point") as bar:
        d = python_names(lambda: _lrchain.dark_continue(params, omega_b, branch, center, sites, mode, tolerance,
                                                        max_iterations, points, ds, omega_min, omega_max, floquet,
                                                        parameter, to, bar.callback))
    d["floquet"] = [_floquet(f) for f in d["floquet"]]
    return Branch(params=params, **d)


@dataclass(frozen=True, repr=False)
class ModelBranch(_ModelEdge):
    """A branch of dark breathers of a model file: per point ``omega_b``, profiles ``z`` (points,
    fields, sites) in the lattice's ``variables``, ``measures`` (list of dicts), ``floquet`` (list of
    :class:`Floquet` or None), ``tangent_omega``, ``residual``, ``iterations``,
    ``contact_changes_per_period`` (list: each point's sign changes of the one-sided contacts'
    overlaps over one period, None for a smooth model); ``turning_points``, ``stop_reason``; the edge
    and ``model`` as in :class:`ModelDarkSolution`."""

    omega_b: np.ndarray
    tangent_omega: np.ndarray
    residual: np.ndarray
    iterations: np.ndarray
    z: np.ndarray
    n: np.ndarray
    variables: tuple
    measures: list
    floquet: list
    contact_changes_per_period: list
    turning_points: list
    stop_reason: str
    parameter: str = "omega_b"  # the continued parameter
    parameter_values: list = None  # its value at each point

    def to_hdf5(self, path):
        """Writes the branch with the C++ job layer's writer, the file ``lrchain dark continue --model
        ... --format hdf5`` writes (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_model_dark_branch(checked_destination(path), _plain(self))

    @property
    def norm_squared(self):
        return np.array([m["norm_squared"] for m in self.measures])

    @property
    def max_modulus(self):
        return np.array([f.max_modulus if f else np.nan for f in self.floquet])

    def __repr__(self):
        return (f"ModelBranch({self.model['name']}, {len(self.omega_b)} points, omega_b {self.omega_b[0]:.6g} .. "
                f"{self.omega_b[-1]:.6g}; {self.stop_reason})")


@dataclass(frozen=True, repr=False)
class Evolution:
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
    params: Params = None

    def to_hdf5(self, path):
        """Writes the evolution with the C++ job layer's writer, the file ``lrchain dark evolve --format
        hdf5`` writes: the per-period series, the stroboscopic x, y (M+1, sites), period, max_strain
        (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_dark_evolution(checked_destination(path), _params_tuple(self.params), _plain(self))

    def __repr__(self):
        return f"Evolution({len(self.t)} periods to t = {self.t[-1]:g}, max E_b = {self.E_b.max():.3g})"


@documented(("dark", "Options (the job's schema, as ``lrchain dark ... --help``):"))
@renamed("dark")
@real_numbers
def evolve(params=None, omega_b=None, branch=None, center=_D["center"], sites=_D["sites"], mode=_D["mode"],
           tolerance=_D["tolerance"], max_iterations=_D["max_iterations"], t_end=None, samples=_D["samples"],
           perturb=_D["perturb"], perturb_size=_D["perturb_size"], seed=_D["seed"], *, model=None, progress=None):
    """Solve, then integrate from Z(0) over floor(t_end / T_b) periods (default: 10 periods),
    sampling every site ``samples`` times per period for the position measure; returns
    :class:`Evolution` (with ``model``: :class:`ModelEvolution`). Ctrl-C interrupts it with
    ``KeyboardInterrupt``. ``perturb``: "none", "unstable" (along the eigenvector of the largest
    Floquet multiplier) or "random" (``seed``), of max-norm ``perturb_size``, added to the start so
    that an instability can be watched. ``progress``: a bar over the periods (see :mod:`lrchain.progress`).

    Example::

        >>> import lrchain, math
        >>> e = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=11, t_end=2 * 2 * math.pi / 2.42, progress=False)
        >>> len(e.t), e.x.shape, bool(e.E_b.max() < 1e-8)
        (2, (3, 11), True)
    """
    params, model, omega_b, branch = _job(params, model, omega_b, branch, "evolve")
    if t_end is None:
        t_end = 10 * 2 * np.pi / omega_b
    if model is not None:
        with Bar("dark-breather evolution", progress) as bar:
            d = _edge(python_names(lambda: _lrchain.dark_model_evolve(
                model, omega_b, branch, center, sites, mode, tolerance, max_iterations, t_end, samples, perturb,
                perturb_size, seed, bar.callback)))
        return ModelEvolution(**d)
    with Bar("dark-breather evolution", progress) as bar:
        d = python_names(lambda: _lrchain.dark_evolve(params, omega_b, branch, center, sites, mode, tolerance,
                                                      max_iterations, t_end, samples, perturb, perturb_size, seed,
                                                      bar.callback))
    return Evolution(params=params, **d)


@dataclass(frozen=True, repr=False)
class ModelEvolution(_ModelEdge):
    """Direct integration from an exact dark breather of a model file: per period ``t``, ``E_b``,
    ``C_x``, ``K_x``, ``position``, ``depth``; stroboscopic profiles ``z`` (M+1, fields, sites) in the
    lattice's ``variables``; ``period`` T_b, ``max_strain``; the edge and ``model`` as in
    :class:`ModelDarkSolution`."""

    period: float
    t: np.ndarray
    E_b: np.ndarray
    C_x: np.ndarray
    K_x: np.ndarray
    position: np.ndarray
    depth: np.ndarray
    z: np.ndarray
    n: np.ndarray
    variables: tuple
    max_strain: float

    def to_hdf5(self, path):
        """Writes the evolution with the C++ job layer's writer, the file ``lrchain dark evolve --model
        ... --format hdf5`` writes (layout: :mod:`lrchain.hdf5`)."""
        from . import _hdf5

        _hdf5.write_model_dark_evolution(checked_destination(path), _plain(self))

    def __repr__(self):
        return f"ModelEvolution({self.model['name']}, {len(self.t)} periods to t = {self.t[-1]:g}, max E_b = {self.E_b.max():.3g})"
