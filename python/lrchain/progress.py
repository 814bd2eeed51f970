"""Progress of long calls: a bar with rate and ETA when a person is watching, silence otherwise.

Lattice runs (``lrchain.simulate.bright``, ``drive``, ``modulated``, ``ring``; ``bright`` of a model
file too), dark-breather continuation (``lrchain.dark.continue_branch``), sweeps (``lrchain.sweep``),
the paper's report (``lrchain.reproduce``: a bar of its steps) and model compilation (``lrchain.load_model`` of a new file) take ``progress=``: True shows
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


class _Shown:
    """What :class:`Bar` and :class:`Counter` share: tqdm's class when progress is shown and tqdm is
    installed; without tqdm a line on standard error says what runs and, at the end, how long it took.
    A context manager that closes the bar."""

    def __init__(self, what, progress):
        self.what = what
        self.on = enabled(progress)
        self._tqdm = None
        self._bar = None
        self._start = time.monotonic()
        if self.on:
            try:
                from tqdm.auto import tqdm
            except ImportError:
                print(f"lrchain: {what} ...", file=sys.stderr, flush=True)
            else:
                self._tqdm = tqdm

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        if not self.on:
            return False
        if self._bar is not None:
            self._bar.close()
        elif kind is None and self._tqdm is None:
            print(f"lrchain: {self.what}: done in {time.monotonic() - self._start:.1f} s", file=sys.stderr, flush=True)
        return False


class Bar(_Shown):
    """A progress bar from 0 to 1 for a call described by ``what``; ``update(fraction)`` is the callback
    the C++ jobs call (at most every 0.2 s). Use as a context manager; ``callback`` is None when
    progress is off, so that the job runs without any call into Python."""

    def __init__(self, what, progress=None, unit="%"):
        super().__init__(what, progress)
        if self._tqdm is not None:
            self._bar = self._tqdm(total=100, desc=what, unit=unit, leave=True,
                                   bar_format="{desc}: {percentage:3.0f}%|{bar}| [{elapsed}<{remaining}, {rate_fmt}]")

    @property
    def callback(self):
        return self.update if self.on else None

    def update(self, fraction):
        if self._bar is not None:
            target = round(100 * min(max(fraction, 0.0), 1.0))
            if target > self._bar.n:
                self._bar.update(target - self._bar.n)


class Counter(_Shown):
    """A bar that counts ``unit``s (e.g. the steps of ``lrchain.reproduce``) up to a total known once
    the work has started: ``start(total)``, then ``advance(text)`` per unit done (``text``: what was
    done, shown after the bar). tqdm shows the count, the rate and the ETA. Use as a context manager."""

    def __init__(self, what, progress=None, unit="step"):
        super().__init__(what, progress)
        self.unit = unit

    def start(self, total):
        if self._tqdm is not None and self._bar is None:
            self._bar = self._tqdm(total=total, desc=self.what, unit=self.unit, leave=True)

    def advance(self, text=None):
        if self._bar is not None:
            if text:
                self._bar.set_postfix_str(text, refresh=False)
            self._bar.update(1)


def note(text, progress=None):
    """One line on standard error when progress is shown (e.g. what a model compilation did)."""
    if enabled(progress):
        print(f"lrchain: {text}", file=sys.stderr, flush=True)
