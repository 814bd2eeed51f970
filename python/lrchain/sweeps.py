"""``lrchain.sweep(config)``: ``lrchain sweep --config FILE`` from Python, read back as a Dataset."""

import os

from . import _lrchain
from .labelled import open_sweep
from .progress import Bar


def sweep(config, *, output=None, threads=None, retry_failed=False, progress=None):
    """Runs the sweep file ``config`` (docs/sweeps.md: one job over a grid or list of parameter
    points) as ``lrchain sweep --config FILE`` does, on ``threads`` threads of this process (None: all
    cores), and returns its results as :func:`lrchain.open_sweep` reads them (an
    :class:`xarray.Dataset` on the sweep's axes).

    The results go to the file's ``output`` (or ``output=``, the command's ``--output``); a results file
    already there is resumed (its finished points are kept; ``retry_failed=True`` runs its failed
    points again), and the figure the file asks for is written next to it. ``progress``: a bar over the
    points (:mod:`lrchain.progress`). Ctrl-C stops the sweep after the points that are running, writes
    the results so far and raises ``KeyboardInterrupt``; calling it again continues. Raises
    :class:`lrchain.InputError` naming the key of a bad sweep file, as the command does.

    Example::

        >>> import lrchain, pathlib, tempfile
        >>> folder = pathlib.Path(tempfile.mkdtemp())
        >>> _ = (folder / "base.toml").write_text('experiment = "regime intervals"\\n')  # the job's base config
        >>> _ = (folder / "rho.toml").write_text(f'job = "regime intervals"\\nbase = "base.toml"\\n'
        ...                                      f'output = "{folder}/rho.h5"\\n'
        ...                                      '[[axis]]\\nparameter = "model.rho"\\nvalues = [0.2, 1.0, 5.0]\\n')
        >>> ds = lrchain.sweep(folder / "rho.toml", threads=1, progress=False)
        >>> ds.optical_intervals.dims, ds.status.values.tolist()
        (('model.rho',), [1, 1, 1])
    """
    with Bar(f"sweep {os.path.basename(os.fspath(config))}", progress) as bar:
        out = _lrchain.sweep(os.fspath(config), "" if output is None else os.fspath(output), int(threads or 0),
                             bool(retry_failed), bar.callback)
    return open_sweep(out["output"])


__all__ = ["sweep"]
