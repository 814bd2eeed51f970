"""lrchain.regime: intervals equal to the CLI's, maps consistent with the coefficients, curves."""

import numpy as np
import pytest

import lrchain


@pytest.mark.parametrize("branch, rho", [("optical", 1 / 3), ("acoustic", 0.5), ("optical", 10.0)])
def test_intervals_equal_cli(cli, branch, rho):
    # Expected: `lrchain regime intervals --json` (the same C++ root finder).
    expected = cli("regime", "intervals", "--branch", branch, "--rho", repr(rho), "--json")
    got = lrchain.regime.intervals(lrchain.Params(rho=rho), branch)
    assert len(got) == len(expected["intervals"])
    for k, e in enumerate(expected["intervals"]):
        assert (got.lo[k], got.hi[k]) == (e["lo"], e["hi"])
        assert (got.lo_cause[k], got.hi_cause[k]) == (e["lo_cause"], e["hi_cause"])
    assert list(got.roots) == [b["theta"] for b in expected["boundaries"]]


def test_exp1_carrier_is_focusing():
    # Sec. 3.3 / Fig. 2: at rho = 1/3 the optical branch focuses for theta below omega'' = 0 (about 1.89).
    iv = lrchain.regime.intervals(lrchain.Params(), "optical")
    assert any(lo <= np.pi / 2 <= hi for lo, hi in iv)
    assert iv.hi_cause[0] == "curvature_zero" and iv.hi[0] == pytest.approx(1.8916, abs=1e-4)


def test_theta_rho_map_matches_coefficients():
    # Every pixel is sign(omega'' h_tilde) of lrchain.coefficients at that (rho, theta).
    m = lrchain.regime.theta_rho_map(lrchain.Params(), "acoustic", rho=(0.05, 2.5, 23), theta=(0.1, np.pi, 17))
    assert m.values.shape == (17, 23) and m.rho.shape == (23,) and m.theta.shape == (17,)
    for i, rho in enumerate(m.rho):
        c = lrchain.coefficients(lrchain.Params(rho=rho), "acoustic", m.theta)
        expected = np.where(c.regime == "focusing", lrchain.regime.FOCUSING,
                            np.where(c.regime == "singular", lrchain.regime.SINGULAR, lrchain.regime.DEFOCUSING))
        assert np.array_equal(m.values[:, i], expected)


def test_delta0_omega_map_outside_the_band():
    m = lrchain.regime.delta0_omega_map(lrchain.Params(rho=3.0), "optical", delta0=(0.01, 1.0, 20), omega=(1.0, 4.0, 30))
    assert m.values.shape == (30, 20)
    lo, hi = lrchain.regime.frequency_band(lrchain.Params(rho=3.0, delta0=m.delta0[-1]), "optical")
    inside = (m.omega > lo + 1e-9) & (m.omega < hi - 1e-9)
    assert np.all(m.values[~inside & ((m.omega < lo - 1e-9) | (m.omega > hi + 1e-9)), -1] == lrchain.regime.OUTSIDE)
    assert np.all(m.values[inside, -1] != lrchain.regime.OUTSIDE)


def test_boundary_curves_are_zero_sets():
    # Points of an omega'' = 0 curve have curvature ~ 0 there (tracing tolerance 1e-12, normalised).
    curves = lrchain.regime.boundary_curves(lrchain.Params(), "optical", axis="rho", lo=0.01, hi=30.0)
    causes = {c.cause for c in curves}
    assert "curvature_zero" in causes
    for curve in curves:
        assert curve.points.ndim == 2 and curve.points.shape[1] == 2
        if curve.cause != "curvature_zero":
            continue
        for rho, theta in curve.points[:: max(1, len(curve.points) // 20)]:
            c = lrchain.coefficients(lrchain.Params(rho=rho), "optical", theta)
            scale = abs(c.group_velocity) + abs(c.omega)
            assert abs(c.curvature) < 1e-6 * scale
