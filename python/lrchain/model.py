"""Lattice models from model files (the format of docs/models.md): the shipped ones and your own."""

import os
import sys
import threading
import time

from . import _lrchain
from ._keywords import real_numbers
from ._lrchain import Model
from .progress import enabled

SHIPPED_MODELS = _lrchain.shipped_models


class _CompileNotice:
    """Says on standard error, when progress is shown, that a model file is being derived and
    compiled (once the load takes over half a second: a cached or shipped model says nothing) and
    how long it took."""

    def __init__(self, source, progress):
        self.source, self.on, self.said = source, enabled(progress), False
        self.start = time.monotonic()
        self.timer = threading.Timer(0.5, self._say) if self.on else None

    def _say(self):
        self.said = True
        print(f"lrchain: deriving and compiling the model file {self.source} (once; later loads use the cache) ...",
              file=sys.stderr, flush=True)

    def __enter__(self):
        if self.timer:
            self.timer.start()
        return self

    def __exit__(self, kind, value, traceback):
        if self.timer:
            self.timer.cancel()
        if self.said:
            how = "done" if kind is None else "stopped"
            print(f"lrchain: model file {self.source}: {how} in {time.monotonic() - self.start:.1f} s",
                  file=sys.stderr, flush=True)
        return False


@real_numbers
def load_model(source, **parameters):
    """The model of a model file, with ``parameters`` overriding the file's defaults.

    ``source`` is a shipped model's name (one of ``lrchain.SHIPPED_MODELS``, e.g. "klein_gordon"),
    or the path of a model file: a shipped model's file is recognised by its bytes; any other file
    is derived and its evaluators compiled with the C++ compiler lrchain was built with, once, into
    the per-user cache ($XDG_CACHE_HOME/lrchain, default ~/.cache/lrchain), which takes seconds the
    first time. Returns a :class:`lrchain.Model` for :func:`lrchain.coefficients`.

    Raises :class:`lrchain.InvalidParameterError` (a ValueError) naming a parameter the model does
    not have or a value outside its range, :class:`lrchain.InputError` for a missing or bad file,
    and RuntimeError when the C++ compiler cannot be run. A compilation that takes over half a second
    says so on standard error, and how long it took, when progress is shown (interactive use, or
    ``lrchain.set_progress(True)``; ``set_progress(False)`` silences it; :mod:`lrchain.progress`).

    Example::

        >>> import lrchain
        >>> kg = lrchain.load_model("klein_gordon", w0=1.2)
        >>> kg
        Model('klein_gordon', C=0.1, w0=1.2, a=0.25, b=0.5)
        >>> import math  # omega(pi) = sqrt(w0^2 + 4 C), the chain's linear dispersion at the band edge
        >>> round(lrchain.coefficients(kg, kg.branches[0], math.pi).omega, 6), round(math.sqrt(1.2**2 + 4 * 0.1), 6)
        (1.356466, 1.356466)
    """
    with _CompileNotice(os.fspath(source), None):
        return _lrchain.load_model(os.fspath(source), **parameters)


__all__ = ["Model", "load_model", "SHIPPED_MODELS"]
