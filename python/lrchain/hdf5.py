"""Results to HDF5 files (read them with h5py): ``result.to_hdf5(path)`` on every result object.

Simulation results (bright, drive, modulated) are written by the C++ library's writer, the same file
``lrchain simulate ... --format hdf5`` writes: root attributes ``lrchain_result``, ``lrchain_version``,
``git_commit``, ``model`` (the summary's model object as JSON text: name, file_hash, parameters); the
series as datasets (``t``, ``E_x``, ..., ``centre``), the ``energy_density`` group (``n``, ``t``, float32 ``values``), ``snapshots/<k>`` (attributes
``t``, ``tag``; group ``columns``), the ``summary`` tree and the optional per-sample fields (``x``, ``y``
or ``u``, ``v``).

The model-file results are written by the C++ job layer's writers, the same files as the commands'
``--format hdf5``: :class:`lrchain.simulate.ModelBrightResult` (``lrchain simulate bright --model``:
datasets ``t``, ``E_0``, ``E_1``, ..., ``energy``, ``centre``, ``snapshots``, ``summary``),
:class:`lrchain.simulate.RingResult` (``lrchain simulate ring``: ``packet_t``, ``packet_centre``, one
dataset per amplitude column, ``summary``), :class:`lrchain.dark.ModelDarkSolution` and
:class:`lrchain.dark.ModelBranch` (``lrchain dark solve|floquet|continue --model``: the resonant
chain's dark layout with the profiles ``z`` in the lattice's variables and the band edge as root
attributes); docs/simulate-models.md and docs/dark-models.md give the layouts.

For the other results (:class:`lrchain.dark.Evolution`, :class:`lrchain.dark.ModelEvolution`) the
layout follows the result's fields: a numpy array is a dataset, a nested result (e.g. a
:class:`lrchain.simulate.SpaceTime`, :class:`lrchain.dark.Floquet`) or a dict is a group, and numbers
and strings are attributes of the enclosing group. Lists of results become groups "0", "1", ...;
lists of numbers become datasets, lists of strings a JSON attribute. Complex arrays (Floquet
multipliers) are stored as h5py's complex compound. The root's attributes ``lrchain_result`` (the
result's class) and ``lrchain_version`` say what wrote the file. The file is written under a
temporary name and renamed into place; ``path`` must be a new name or an existing regular file (an
existing directory, FIFO, device or socket raises :class:`lrchain.InputError` and is left as it is).
"""

import dataclasses
import json
import numbers
import os

import numpy as np

from .errors import InputError


def checked_destination(path):
    """``path`` (a str) if ``to_hdf5`` may write it: a new name or an existing regular file, which the
    writer replaces by renaming its temporary file over it. InputError for anything else that exists
    (directory, FIFO, device, socket: renaming over it would replace it), decided by the C++ writers'
    own check (lrchain::check_output_target); every ``to_hdf5`` calls this before writing."""
    from . import _hdf5

    path = os.fspath(path)
    problem = _hdf5.output_target_problem(path)
    if problem:
        raise InputError(f"to_hdf5: {problem} (nothing was written)")
    return path


def _array(values):
    a = np.ascontiguousarray(values)
    return a.astype(np.int8) if a.dtype == np.bool_ else a


def tree_of(value):
    """The dict/array/scalar tree of a result value (see the module's docstring)."""
    if hasattr(value, "_hdf5_tree"):
        return value._hdf5_tree()
    if dataclasses.is_dataclass(value):
        return {f.name: tree_of(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, dict):
        return {str(k): tree_of(v) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        return _array(value)
    if isinstance(value, (list, tuple)):
        if all(isinstance(v, numbers.Number) and not isinstance(v, bool) for v in value) and value:
            return _array(value)
        if all(isinstance(v, str) for v in value):
            return json.dumps(list(value))
        return {str(i): tree_of(v) for i, v in enumerate(value)}
    if isinstance(value, (np.generic,)):
        return value.item()
    return value


def write(path, result):
    """Writes ``result`` (a result object of lrchain) to the HDF5 file ``path``."""
    from . import _hdf5  # links libhdf5: loaded on first use only

    tree = tree_of(result)
    tree["lrchain_result"] = type(result).__name__
    tree["lrchain_version"] = _hdf5.version
    _hdf5.write_hdf5(checked_destination(path), tree)


def write_simulation(path, kind, series, energy_density, snapshots, summary, fields):
    """Writes a simulation run through the sim library's writer (``lrchain simulate --format hdf5``
    writes the same file): ``series`` {record column: array}, the energy density and snapshots of
    :mod:`lrchain.simulate`, the summary dict and [(name, SpaceTime)] fields recorded at every sample."""
    from . import _hdf5

    e = energy_density
    _hdf5.write_simulation(checked_destination(path), kind, series, (e.quantity, e.n, e.t, e.values),
                           [(s.t, s.tag, s.columns) for s in snapshots], json.dumps(summary),
                           [(name, f.quantity, f.n, f.t, f.values) for name, f in fields])


class HDF5Mixin:
    """Adds ``to_hdf5(path)`` to a result class."""

    def to_hdf5(self, path):
        """Writes this result to the HDF5 file ``path`` (layout: :mod:`lrchain.hdf5`)."""
        write(path, self)
