"""Progress of long calls: a bar with rate and ETA when a person is watching, silence otherwise.

Lattice runs (``lrchain.simulate.bright``, ``drive``, ``modulated``, ``ring``; ``bright`` of a model
file too), dark-breather continuation (``lrchain.dark.continue_branch``), sweeps (``lrchain.sweep``)
and model compilation (``lrchain.load_model`` of a new file) take ``progress=``: True shows
progress, False keeps quiet, None (the default) shows it when the call runs interactively (a Jupyter
notebook, or a terminal on standard error) and the default set by :func:`set_progress` allows it. The bar is tqdm's (Debian ``python3-tqdm``: a widget in a notebook,
a text bar in a terminal); without tqdm a line on standard error says what runs and how long it took.
"""

import sys
import time

_default = None  # None: automatic; True/False: set by set_progress


def set_progress(enabled):
    """Sets the default of every call's ``progress=``: True (always), False (never) or None (when
    interactive).

    Example::

        >>> import lrchain
        >>> lrchain.set_progress(False)  # no progress anywhere, also in a notebook
        >>> lrchain.set_progress(None)   # the default again: shown when interactive
    """
    global _default
    if enabled not in (True, False, None):
        raise ValueError("set_progress: enabled must be True, False or None")
    _default = enabled


def interactive():
    """True in a running Jupyter kernel or with standard error on a terminal."""
    ipython = sys.modules.get("IPython")
    if "ipykernel" in sys.modules and ipython is not None and ipython.get_ipython() is not None:
        return True
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


def enabled(progress):
    """Whether a call given ``progress=`` shows progress."""
    if progress is not None:
        return bool(progress)
    if _default is not None:
        return _default
    return interactive()


class Bar:
    """A progress bar from 0 to 1 for a call described by ``what``; ``update(fraction)`` is the callback
    the C++ jobs call (at most every 0.2 s). Use as a context manager; ``callback`` is None when
    progress is off, so that the job runs without any call into Python."""

    def __init__(self, what, progress=None, unit="%"):
        self.what = what
        self.on = enabled(progress)
        self._bar = None
        self._start = time.monotonic()
        if self.on:
            try:
                from tqdm.auto import tqdm
            except ImportError:
                print(f"lrchain: {what} ...", file=sys.stderr, flush=True)
            else:
                self._bar = tqdm(total=100, desc=what, unit=unit, leave=True,
                                 bar_format="{desc}: {percentage:3.0f}%|{bar}| [{elapsed}<{remaining}, {rate_fmt}]")

    @property
    def callback(self):
        return self.update if self.on else None

    def update(self, fraction):
        if self._bar is not None:
            target = round(100 * min(max(fraction, 0.0), 1.0))
            if target > self._bar.n:
                self._bar.update(target - self._bar.n)

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        if not self.on:
            return False
        seconds = time.monotonic() - self._start
        if self._bar is not None:
            self._bar.close()
        if kind is None and self._bar is None:
            print(f"lrchain: {self.what}: done in {seconds:.1f} s", file=sys.stderr, flush=True)
        return False


def note(text, progress=None):
    """One line on standard error when progress is shown (e.g. what a model compilation did)."""
    if enabled(progress):
        print(f"lrchain: {text}", file=sys.stderr, flush=True)
