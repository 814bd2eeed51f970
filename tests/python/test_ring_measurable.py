"""`lrchain simulate ring` measures only what is measurable (issue 27): a plane wave that breaks up
on the ring has no frequency (exit 3, null with the reason), an amplitude outside the weakly
nonlinear range is named on stderr and in the JSON warnings, and at theta = pi (c = 0) no packet
disagreement is printed. The model file is the issue's sine_gordon_poly.toml (tests/data)."""

import json
import subprocess

from conftest import _cli_path


def _run(*args):
    done = subprocess.run([str(_cli_path()), *map(str, args)], capture_output=True, text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def test_sine_gordon_ring_at_amplitude_1_is_not_measurable(source_dir):
    # Before the fix: exit 0, measured frequency -0.084 against omega + h U^2/4 = 1.37 (the plane wave
    # of U = 1 at theta = pi/2 is modulationally unstable: it broke up and its phase meant nothing).
    code, out, err = _run("simulate", "ring", "--model", source_dir / "tests" / "data" / "sine_gordon_poly.toml",
                          "--branch", "branch0", "--theta", "pi/2", "--amplitudes", 1, "--json")
    assert code == 3, err
    summary = json.loads(out)
    row = summary["amplitudes"][0]
    assert row["measured_frequency"] is None and row["relative_disagreement"] is None
    assert row["not_measurable"].startswith("the plane wave broke up at t = ")
    assert row["least_carrier_fraction"] < 0.9
    assert "broke up" in summary["failure"]
    # |h| U^2/4 = 0.044 is 3.1 % of omega = 1.414 (h = -0.177 from the derived evaluators): outside 2 %.
    assert row["weakly_nonlinear"] is False
    assert any("weakly nonlinear" in w for w in summary["warnings"])
    assert "warning: amplitude 1: |h| U^2/4" in err and "numerical failure" in err


def test_klein_gordon_ring_at_pi_is_measured_and_standing():
    # Before the fix: shift -1.18 against h U^2/4 = 5.4e-5 (relative disagreement 2e4), and a packet
    # disagreement of 11 for c = 1e-17. Now the shift agrees to O(U^2) (< 1 % at U = 0.02) and c = 0.
    code, out, err = _run("simulate", "ring", "--model", "klein_gordon", "--branch", "branch0", "--theta", "pi",
                          "--json")
    assert code == 0, err
    summary = json.loads(out)
    for row in summary["amplitudes"]:
        assert row["relative_disagreement"] < 0.01
    assert summary["packet"]["relative_disagreement"] is None
    assert "counts as zero" in summary["packet"]["relative_disagreement_reason"]
    assert summary["warnings"] == [] and summary["failure"] is None
