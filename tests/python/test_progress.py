"""Progress of long calls (lrchain.progress): a bar on standard error when asked (progress=True, or
set_progress(True)), nothing when not (progress=False, or a non-interactive run by default), the
model compiler's notice after half a second, and the run's numbers unchanged by watching it."""

import re
import time

import numpy as np
import pytest

import lrchain
from lrchain import progress
from lrchain.model import _CompileNotice


@pytest.fixture(autouse=True)
def automatic_default():
    yield
    lrchain.set_progress(None)


def test_bright_run_shows_a_bar_only_when_asked(capfd):
    quiet = lrchain.simulate.bright(lrchain.Params(), sites=61, periods=4, progress=False)
    assert capfd.readouterr().err == ""
    watched = lrchain.simulate.bright(lrchain.Params(), sites=61, periods=4, progress=True)
    err = capfd.readouterr().err
    assert "bright run" in err and "100%" in err
    np.testing.assert_array_equal(quiet.E_x, watched.E_x)  # the same run, bit for bit


def test_default_is_silent_when_not_interactive(capfd):
    assert not progress.interactive()  # pytest captures standard error: not a terminal, no kernel
    lrchain.simulate.drive(sites=20, t_end=20, switch_off_time=10, sample_every=1, spacetime_every=2,
                           snapshot_times=[20], front_fit_start=1, front_fit_end=20)
    assert capfd.readouterr().err == ""
    lrchain.set_progress(True)
    lrchain.simulate.drive(sites=20, t_end=20, switch_off_time=10, sample_every=1, spacetime_every=2,
                           snapshot_times=[20], front_fit_start=1, front_fit_end=20)
    assert "drive run" in capfd.readouterr().err


def test_branch_progress_counts_points(capfd):
    b = lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, sites=21, points=4, ds=0.02, floquet=False,
                                     progress=True)
    err = capfd.readouterr().err
    assert len(b.omega_b) == 4 and "dark-breather branch" in err and "100%" in err


def test_compile_notice_after_half_a_second(capfd):
    lrchain.set_progress(True)
    with _CompileNotice("quick.toml", None):
        time.sleep(0.05)
    assert capfd.readouterr().err == ""  # a cached model says nothing
    with _CompileNotice("slow.toml", None):
        time.sleep(0.8)
    err = capfd.readouterr().err
    assert "deriving and compiling the model file slow.toml" in err
    assert re.search(r"slow.toml: done in \d+\.\d s", err)


def test_set_progress_refuses_other_values():
    with pytest.raises(ValueError, match="True, False or None"):
        lrchain.set_progress("yes")


def test_model_file_runs_show_a_bar_that_reaches_the_end(capfd):
    import math

    fput = lrchain.load_model("fput")
    quiet = lrchain.simulate.bright(fput, "acoustic", math.pi / 2, sites=41, periods=2, progress=False)
    ring_quiet = lrchain.simulate.ring(fput, "acoustic", math.pi / 2, periods=20, packet_width=8, progress=False)
    assert capfd.readouterr().err == ""
    watched = lrchain.simulate.bright(fput, "acoustic", math.pi / 2, sites=41, periods=2, progress=True)
    ring_watched = lrchain.simulate.ring(fput, "acoustic", math.pi / 2, periods=20, packet_width=8, progress=True)
    err = capfd.readouterr().err
    assert "bright run of fput" in err and "ring run of fput" in err and err.count("100%") >= 2
    np.testing.assert_array_equal(quiet.E_x, watched.E_x)  # watching does not change the run
    np.testing.assert_array_equal(ring_quiet.measured_frequency, ring_watched.measured_frequency)


def test_model_run_fractions_rise_to_one():
    """The C++ jobs' fractions as the bar receives them: in [0, 1], never falling, the last one 1."""
    import math

    from lrchain import _lrchain

    fput = lrchain.load_model("fput")
    for run in (lambda seen: _lrchain.simulate_model_bright(fput, "acoustic", {"theta": math.pi / 2, "sites": 41,
                                                                               "periods": 2.0}, seen.append),
                lambda seen: _lrchain.simulate_ring(fput, "acoustic", {"theta": math.pi / 2, "periods": 20.0,
                                                                       "packet_width": 8.0}, seen.append)):
        seen = []
        run(seen)
        assert seen and seen[-1] == 1.0 and all(0 <= f <= 1 for f in seen) and seen == sorted(seen)


def test_sweep_shows_a_bar_per_point(tmp_path, capfd):
    (tmp_path / "base.toml").write_text('experiment = "regime intervals"\n')
    (tmp_path / "s.toml").write_text(f'job = "regime intervals"\nbase = "base.toml"\noutput = "{tmp_path}/s.h5"\n'
                                     '[[axis]]\nparameter = "model.rho"\nvalues = [0.5, 2.0]\n')
    ds = lrchain.sweep(tmp_path / "s.toml", threads=1, progress=True)
    err = capfd.readouterr().err
    assert "sweep s.toml" in err and "100%" in err and (ds.status.values == 1).all()
    lrchain.sweep(tmp_path / "s.toml", output=tmp_path / "quiet.h5", threads=1, progress=False)
    assert capfd.readouterr().err == ""


def test_evolution_shows_a_bar_per_period(capfd):
    quiet = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=11, t_end=3 * 2 * np.pi / 2.42, progress=False)
    assert capfd.readouterr().err == ""
    watched = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=11, t_end=3 * 2 * np.pi / 2.42, progress=True)
    err = capfd.readouterr().err
    assert "dark-breather evolution" in err and "100%" in err
    np.testing.assert_array_equal(quiet.E_b, watched.E_b)  # the same run, bit for bit
