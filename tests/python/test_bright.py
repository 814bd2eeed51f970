"""lrchain.bright: the exact bright-breather job (lrchain/jobs/bright_breather_job.hpp) from Python. The
numbers are the job's own tests' (tests/unit/bright_breather_job_test.cpp); here the keywords, the
result's arrays, the errors, and that Python and `lrchain bright` give the same bits."""

import json
import subprocess

import numpy as np
import pytest

import lrchain
from lrchain import bright

from conftest import _cli_path


def test_klein_gordon_solve_matches_the_command_line():
    kg = lrchain.load_model("klein_gordon")
    b = bright.solve(kg, omega_b=1.19, sites=61)
    assert b.z.shape == (1, 61) and b.seed.shape == (1, 61) and b.variables == ("u0",)
    assert b.n[0] == -30 and b.n[-1] == 30
    assert b.edge["theta"] == pytest.approx(np.pi) and b.edge["omega"] == pytest.approx(np.sqrt(1.4), rel=1e-12)
    assert b.newton_residuals[-1] <= 1e-11
    assert b.profile["localized"] and abs(b.z[0]).max() == b.profile["peak"]
    assert b.floquet is None
    done = subprocess.run([str(_cli_path()), "bright", "solve", "--model", "klein_gordon", "--omega-b", "1.19",
                           "--sites", "61", "--quiet", "--json"], capture_output=True, text=True, check=True)
    cli = json.loads(done.stdout)
    assert cli["profile"]["peak"] == b.profile["peak"]
    assert cli["newton_residuals"] == list(b.newton_residuals)


def test_fpu_page_mode_is_stable_with_the_trivial_multipliers_found():
    # Sandusky, Page & Schmidt, Phys. Rev. B 46, 6161 (1992): the bond-centred mode is stable.
    b = bright.floquet(lrchain.load_model("fput", a=0), omega_b=2.2, center="bond", sites=41)
    f = b.floquet
    assert f.stable and f.trivial_found and f.trivial_expected == 4 and len(f.trivial) == 4
    assert f.multipliers.dtype == complex and len(f.multipliers) == 2 * 41
    assert f.unit_circle_defect <= 1e-8 and f.det_defect <= 1e-8
    # Krein signatures of the 41 - 2 non-trivial multipliers on the upper circle (strain form, lifted to
    # displacements: tests/unit/bright_strain_krein_test.cpp checks the lift against the displacement
    # form); both signs occur, each +1 or -1.
    assert len(f.krein) == 39
    assert {k["signature"] for k in f.krein} == {1, -1}
    assert all(abs(k["modulus"] - 1) <= 1e-6 and 0 < k["angle"] < 3.1416 for k in f.krein)


def test_refusals_name_omega_b_and_failures_raise_numerical_failure():
    kg = lrchain.load_model("klein_gordon")
    with pytest.raises(lrchain.InvalidParameterError, match="inside the linear band") as e:
        bright.solve(kg, omega_b=1.1)
    assert e.value.parameter == "omega_b"
    with pytest.raises(lrchain.InvalidParameterError) as e:
        bright.solve(kg)
    assert e.value.parameter == "omega_b"
    with pytest.raises(lrchain.InvalidParameterError) as e:
        bright.solve(omega_b=2.5, sites=41)  # the resonant chain: no focusing band edge
    assert e.value.parameter == "omega_b" and "no focusing band edge" in str(e.value)
    with pytest.raises(lrchain.InvalidParameterError) as e:
        bright.solve(kg, omega_b=1.19, tail_tolerance=2)
    assert e.value.parameter == "tail_tolerance"
    with pytest.raises(lrchain.NumericalFailure, match="not localized"):
        bright.solve(lrchain.load_model("fput", a=0), omega_b=2.05, sites=41)


def test_continue_branch_rises_from_the_edge():
    b = bright.continue_branch(lrchain.load_model("klein_gordon"), omega_b=1.19, sites=61, points=4)
    assert len(b.omega_b) == 4 and b.z.shape == (4, 1, 61)
    assert np.all(np.diff(b.omega_b) > 0) and np.all(np.diff(b.peak) > 0)
    assert all(b.stable) and b.window[0] == pytest.approx(np.sqrt(1.4), rel=1e-12) and b.window[1] is None
    assert b.stop_reason == "reached 4 points"
    assert np.array_equal(b.z[0], b.start.z)
    # stable and monotone: no bifurcation; the phonons' multipliers (upper circle) carry Krein signature -1
    # (tests/unit/bright_breather_job_test.cpp explains the arc)
    assert b.bifurcations == [] and len(b.krein) == 4
    assert len(b.krein[0]) >= 55 and all(m["signature"] == -1 for m in b.krein[0])


def test_continue_branch_gives_krein_signatures_in_strain_form():
    # fput at its defaults has a mean flow (strain form); its bond-centred breather on 31 sites is stable at
    # 2.2 (the 58 non-trivial multipliers on the circle, 29 in the upper half, of both signatures) and
    # loses stability at a Krein collision located at 2.2010332 (tests/unit/bright_strain_krein_test.cpp)
    b = bright.continue_branch(lrchain.load_model("fput"), omega_b=2.2, center="bond", sites=31, points=2, ds=0.2)
    assert b.start.summary["lattice_form"] == "strain"
    assert len(b.krein[0]) == 29 and {m["signature"] for m in b.krein[0]} == {-1, 1}
    collisions = [x for x in b.bifurcations if x["kind"] == "krein_collision"]
    assert len(collisions) == 1 and collisions[0]["omega_b"] == pytest.approx(2.2010332, rel=1e-6)


def test_continue_branch_locates_a_period_tripling():
    # The job's numbers (tests/unit/bright_crossing_location_test.cpp): klein_gordon at C = 0.3 from omega_b
    # 2.05, a multiplier through exp(2 pi i/3) located at 2.0510924 to 1e-6; here the keyword and the dicts.
    kg = lrchain.load_model("klein_gordon", C=0.3)
    b = bright.continue_branch(kg, omega_b=2.05, sites=31, points=2, ds=0.2)
    (x,) = b.bifurcations
    assert x["kind"] == "period_tripling" and x["located"] and x["location_error"] <= 5e-7
    assert x["omega_b"] == pytest.approx(2.0510924, rel=1e-6)
    assert abs(complex(*x["multiplier"]) - np.exp(2j * np.pi / 3)) < 2e-6
    (y,) = bright.continue_branch(kg, omega_b=2.05, sites=31, points=2, ds=0.2, locate_tolerance=0).bifurcations
    assert not y["located"] and y["multiplier"] is None and y["location_error"] is None
    assert y["omega_b"] == pytest.approx((x["omega_low"] + x["omega_high"]) / 2, rel=1e-14)


def test_evolve_keywords_arrays_and_the_perturb_refusal():
    # The numbers are the job's (tests/unit/bright_evolve_job_test.cpp); here the keywords and arrays.
    fpu = lrchain.load_model("fput", a=0)
    e = bright.evolve(fpu, omega_b=2.2, center="site", sites=41, periods=10, perturb="unstable", perturb_size=1e-7)
    assert e.t.shape == (11,) and e.deviation.shape == (11,) and e.energy.shape == (11,)
    assert e.deviation[0] == pytest.approx(1e-7, rel=1e-9)
    assert e.perturbation["kind"] == "unstable" and e.perturbation["size"] == 1e-7
    assert e.growth_rate == pytest.approx(e.predicted_growth_rate, rel=1e-4)
    assert not e.breather.floquet.stable
    with pytest.raises(lrchain.InvalidParameterError) as refused:
        bright.evolve(lrchain.load_model("klein_gordon"), omega_b=1.19, sites=61, periods=2, perturb="unstable")
    assert "perturb" in str(refused.value)


def test_continue_branch_in_a_model_parameter():
    kg = lrchain.load_model("klein_gordon", C=0.01, a=0)
    b = bright.continue_branch(kg, omega_b=1.1, sites=21, parameter="C", to=0.005, points=10, floquet=False)
    assert b.parameter == "C" and b.values[0] == pytest.approx(0.01) and b.values[-1] == pytest.approx(0.005)
    assert np.all(b.omega_b == 1.1)
    with pytest.raises(lrchain.InvalidParameterError) as refused:
        bright.continue_branch(kg, omega_b=1.1, sites=21, parameter="C")
    assert "to" in str(refused.value)
