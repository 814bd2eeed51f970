"""Results to HDF5 files (read them with h5py): ``result.to_hdf5(path)`` on every result (simulate, dark,
bright, wave, coefficients, regime), written by the C++ library's writers: the same file as the command's
``--format hdf5`` (``--out DIR`` of ``lrchain coeffs`` and ``lrchain regime intervals``).

Every file has the root attributes ``lrchain_result`` (the result's class), ``lrchain_version``,
``git_commit`` (the provenance) and ``model`` (the model object as JSON text: name, file_hash, parameters; a model
file's run adds lattice_code).

- :class:`lrchain.simulate.BrightResult`, :class:`~lrchain.simulate.DriveResult`,
  :class:`~lrchain.simulate.ModulatedResult` (``lrchain simulate bright|drive|modulated``): the series
  as datasets (``t``, ``E_x``, ..., ``centre``), the ``energy_density`` group (``n``, ``t``, float32
  ``values``), ``snapshots/<k>`` (attributes ``t``, ``tag``; group ``columns``), the ``summary`` tree
  (objects are groups, numbers and strings attributes, lists of numbers datasets, null left out) and
  the optional per-sample fields (``x``, ``y`` or ``u``, ``v``).
- :class:`lrchain.simulate.ModelBrightResult` (``lrchain simulate bright --model``): ``t``, ``E_0``,
  ``E_1``, ..., ``energy``, ``centre``, ``snapshots``, ``summary``; :class:`lrchain.simulate.RingResult`
  (``lrchain simulate ring``): ``packet_t``, ``packet_centre``, one dataset per amplitude column,
  ``summary`` (docs/simulate-models.md).
- :class:`lrchain.dark.DarkSolution`, :class:`~lrchain.dark.Branch`, :class:`~lrchain.dark.Evolution`
  (``lrchain dark solve|floquet|continue|evolve --format hdf5``): profiles ``x``, ``y``, measures,
  Floquet multipliers as h5py's complex compound, the evolution's per-period series
  (docs/dark-breathers.md); :class:`~lrchain.dark.ModelDarkSolution`, :class:`~lrchain.dark.ModelBranch`,
  :class:`~lrchain.dark.ModelEvolution` (the same with ``--model``): the profiles ``z`` in the
  lattice's variables and the band edge as root attributes (docs/dark-models.md).
- :class:`lrchain.Coefficients` (``lrchain coeffs ... --out DIR``: ``result.h5``, with ``--table``
  ``result_<branch>.h5``): ``theta`` and every coefficient with theta's shape, ``regime_code`` (int8), the
  root attribute ``branch`` (lrchain/jobs/coeffs_hdf5.hpp).
- :class:`lrchain.regime.Intervals` (``lrchain regime intervals --out DIR``): ``lo``, ``hi``, ``roots``,
  their causes as JSON attributes; :class:`~lrchain.regime.RegimeMap` (``lrchain regime map --format
  hdf5``: ``result.h5`` or ``result_<branch>.h5``): ``x``, ``y``, ``values`` (int8, y x x), attributes
  ``plane``, ``x_name``, ``y_name``, the traced curves in ``curves/<k>``; :class:`~lrchain.regime.BoundaryCurve`:
  ``points`` (k x 2), attributes ``cause``, ``axis``, ``y_name`` (lrchain/jobs/regime_hdf5.hpp).
- :class:`lrchain.bright.BrightBreather`, :class:`~lrchain.bright.BrightBranch`,
  :class:`~lrchain.bright.BrightEvolution` (``lrchain bright solve|floquet|continue|evolve --format hdf5``):
  ``n``, ``z``, ``seed``, ``branch_z`` (a branch), ``floquet_multipliers`` (complex), an evolution's ``t``,
  ``deviation`` and ``energy`` per period (no ``energy`` without a potential), the summary as a tree and as exact JSON text (root attribute
  ``summary_json``), ``omega_b``, ``center``, ``variables`` (lrchain/jobs/bright_breather_hdf5.hpp).
- :class:`lrchain.wave.TravellingWave`, :class:`~lrchain.wave.WaveBranch` (``lrchain wave
  solve|stability|continue --format hdf5``): one entry per wave in ``amplitude``, ``omega``, ``omega_shift``,
  ``nls_omega_shift``, ``harmonics``; a wave's ``xi`` and ``profile`` (fields x phases); after stability
  ``K``, ``growth_rate``, ``nls_growth_rate``; the summary as a tree and as exact JSON text
  (``summary_json``), ``branch``, ``theta`` (lrchain/jobs/wave_hdf5.hpp); :class:`~lrchain.wave.StandingWave`
  (``lrchain wave standing --format hdf5``): the ramp's ``amplitude``, ``omega``, ``omega_shift``, ``harmonics``,
  ``residual``, the orbit's ``coefficients`` (fields x sites x (H+1)), its ``profile`` and
  ``profile_quarter_period`` (fields x sites, at t = 0 and a quarter period), ``floquet_multipliers`` (complex), the
  root attributes ``ring_sites``, ``period_sites`` and the summary as for a travelling wave.

:func:`lrchain.load` reads any of these files back into its result class (:mod:`lrchain.reading`).

The file is written under a temporary name and renamed into place; ``path`` must be a new name or an
existing regular file (an existing directory, FIFO, device or socket raises
:class:`lrchain.InputError` and is left as it is).
"""

import json
import os

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


def write_simulation(path, kind, series, energy_density, snapshots, summary, fields):
    """Writes a simulation run through the sim library's writer (``lrchain simulate --format hdf5``
    writes the same file): ``series`` {record column: array}, the energy density and snapshots of
    :mod:`lrchain.simulate`, the summary dict and [(name, SpaceTime)] fields recorded at every sample."""
    from . import _hdf5

    e = energy_density
    _hdf5.write_simulation(checked_destination(path), kind, series, (e.quantity, e.n, e.t, e.values),
                           [(s.t, s.tag, s.columns) for s in snapshots], json.dumps(summary),
                           [(name, f.quantity, f.n, f.t, f.values) for name, f in fields])
