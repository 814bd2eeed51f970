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
