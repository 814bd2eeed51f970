"""Lattice models from model files (the format of docs/models.md): the shipped ones and your own."""

import os

from . import _lrchain
from ._keywords import real_numbers
from ._lrchain import Model

SHIPPED_MODELS = _lrchain.shipped_models


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
    and RuntimeError when the C++ compiler cannot be run.
    """
    return _lrchain.load_model(os.fspath(source), **parameters)


__all__ = ["Model", "load_model", "SHIPPED_MODELS"]
