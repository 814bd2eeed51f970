"""lrchain: nonlinear waves in the locally resonant granular chain, from Python.

The C++ library behind the ``lrchain`` command, with numpy arrays in and out::

    import lrchain
    p = lrchain.Params(rho=1/3)                      # alpha=3/2, delta0=4/9, kappa=1 by default
    c = lrchain.coefficients(p, "optical", theta)    # theta: a number or any numpy array
    kg = lrchain.load_model("klein_gordon", w0=1.2)  # a model file (or a shipped model's name)

Submodules: :mod:`lrchain.regime` (focusing intervals, the regime maps of Figs. 2, 4, 5 and their
boundary curves), :mod:`lrchain.simulate` (bright-breather, driven-chain and modulated-wave runs;
bright-breather and ring runs of any model file), :mod:`lrchain.dark` (exact dark breathers: Newton,
continuation, Floquet multipliers, evolution; of the resonant chain or, with ``model=``, of any model
file), :mod:`lrchain.bright` (exact bright breathers of any model file: Newton, Floquet multipliers).
:func:`lrchain.load` reads back any file lrchain writes (HDF5 results, sweep results, JSON summaries);
:func:`lrchain.sweep` runs a sweep file (``lrchain sweep``) and returns its results as an xarray Dataset.
Invalid input raises :class:`lrchain.InvalidParameterError` (a ``ValueError``) naming the parameter;
Ctrl-C interrupts a long computation with ``KeyboardInterrupt``.
"""

from .errors import InputError, InvalidParameterError, NumericalFailure
from ._lrchain import Params, build_info as _build_info
from .coefficients import Coefficients, coefficients
from .model import SHIPPED_MODELS, Model, load_model
from . import bright, dark, regime, simulate
from . import labelled as _labelled
from .labelled import open_sweep
from .reading import load
from .sweeps import sweep
from .progress import set_progress

_labelled.attach()  # result.to_xarray() on every result class

__version__ = _build_info()["version"]


def provenance():
    """Which lrchain this is, as ``lrchain --version`` says: a dict with ``version``, ``commit``
    (None outside a git checkout), ``compiler``, ``build_type`` and ``version_line`` (the line
    ``lrchain --version`` prints).

    Example::

        >>> import lrchain
        >>> info = lrchain.provenance()
        >>> info["version"] == lrchain.__version__, info["version_line"].startswith("lrchain " + info["version"])
        (True, True)
    """
    return _build_info()


__all__ = [
    "__version__",
    "provenance",
    "open_sweep",
    "load",
    "sweep",
    "set_progress",
    "Params",
    "Model",
    "load_model",
    "SHIPPED_MODELS",
    "Coefficients",
    "coefficients",
    "regime",
    "simulate",
    "dark",
    "bright",
    "InputError",
    "InvalidParameterError",
    "NumericalFailure",
]
