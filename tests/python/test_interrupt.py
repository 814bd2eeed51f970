"""Ctrl-C (SIGINT) interrupts a long computation with KeyboardInterrupt and leaves lrchain usable."""

import math
import os
import signal
import threading
import time

import pytest

import lrchain


def interrupt_after(seconds):
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_bright_run_interrupted():
    handler = signal.getsignal(signal.SIGINT)
    start = time.monotonic()
    timer = interrupt_after(1.0)
    # About 1e5 breather periods on 4001 sites: hours of work without the interrupt.
    with pytest.raises(KeyboardInterrupt):
        lrchain.simulate.bright(lrchain.Params(), sites=4001, periods=1e5, sample_every=10, spacetime_every=1000,
                                snapshot_periods=[0])
    timer.join()
    assert time.monotonic() - start < 60
    assert signal.getsignal(signal.SIGINT) is handler  # Python's handler is back
    # The library still works: a short run completes and starts on the ansatz.
    r = lrchain.simulate.bright(lrchain.Params(), sites=81, periods=2)
    assert r.E_x[0] == 0 and len(r.t) == 9


def test_dark_continuation_interrupted():
    start = time.monotonic()
    timer = interrupt_after(1.0)
    with pytest.raises(KeyboardInterrupt):
        lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, points=100000, ds=1e-4, floquet=True)
    timer.join()
    assert time.monotonic() - start < 120
    assert lrchain.coefficients(lrchain.Params(), "optical", 1.0).regime == "focusing"


def test_custom_python_handler_is_called():
    # A user's SIGINT handler runs (chained), and what it raises is what the run raises.
    class Stop(Exception):
        pass

    def handler(signum, frame):
        raise Stop()

    previous = signal.signal(signal.SIGINT, handler)
    try:
        timer = interrupt_after(0.5)
        with pytest.raises(Stop):
            lrchain.simulate.bright(lrchain.Params(), sites=4001, periods=1e5, sample_every=10, spacetime_every=1000,
                                    snapshot_periods=[0])
        timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)


def test_floquet_interrupted():
    # The Floquet multipliers of an 801-site dark breather from the monodromy matrix over a full
    # period (3204 tangent columns): minutes of work. The loose Newton tolerance accepts the seed, so
    # the SIGINT at 1 s lands in the monodromy integration, which checks the stop flag every step.
    start = time.monotonic()
    timer = interrupt_after(1.0)
    with pytest.raises(KeyboardInterrupt):
        lrchain.dark.floquet(lrchain.Params(), omega_b=2.42, sites=801, tolerance=0.5, full_monodromy=True)
    timer.join()
    assert time.monotonic() - start < 60
    assert lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=41).newton_residuals[-1] <= 1e-11


def test_model_file_runs_interrupted():
    # Runs on a model file's generated lattice code poll the stop flag at every sample: fput's bright
    # breather on 20001 sites over 1e5 periods and plane waves on a 4000-site ring over 1e5 carrier
    # periods are hours of work without the interrupt.
    fput = lrchain.load_model("fput")
    runs = (lambda: lrchain.simulate.bright(model=fput, branch="acoustic", theta=math.pi / 2, sites=20001,
                                            periods=1e5, sample_every=1),
            lambda: lrchain.simulate.ring(fput, "acoustic", math.pi / 2, sites=4000, periods=1e5))
    for run in runs:
        start = time.monotonic()
        timer = interrupt_after(1.0)
        with pytest.raises(KeyboardInterrupt):
            run()
        timer.join()
        assert time.monotonic() - start < 60
    # The library still works: a short ring run completes (fput's only branch, branch left out).
    r = lrchain.simulate.ring(fput, theta=math.pi / 2, periods=10)
    assert len(r.amplitude) == 2
    assert r.summary["branch"] == "acoustic"


def test_sweep_interrupted_keeps_its_results_file(tmp_path):
    # Two bright points of 1e5 breather periods on 4001 sites each: hours of work without the interrupt.
    (tmp_path / "base.toml").write_text('experiment = "bright"\n[bright]\nbranch = "optical"\ntheta = "pi/2"\n'
                                        'sites = 4001\nperiods = 1e5\nsample_every = 10\nspacetime_every = 1000\n'
                                        'snapshot_periods = [0.0]\n')
    (tmp_path / "s.toml").write_text(f'job = "bright"\nbase = "base.toml"\noutput = "{tmp_path}/s.h5"\n'
                                     '[[axis]]\nparameter = "bright.detuning"\nvalues = [-1e-4, -2e-4]\n')
    start = time.monotonic()
    timer = interrupt_after(1.0)
    with pytest.raises(KeyboardInterrupt):
        lrchain.sweep(tmp_path / "s.toml", threads=1, progress=False)
    timer.join()
    assert time.monotonic() - start < 60
    ds = lrchain.open_sweep(tmp_path / "s.h5")  # written before the KeyboardInterrupt: both points missing
    assert ds.status.values.tolist() == [0, 0]
