"""lrchain.coefficients: equal to the CLI's JSON to the last bit, vectorised equal to scalar calls,
and the NaN policy (NaN only where regime == "singular")."""

import numpy as np
import pytest

import lrchain

FIELDS = ["omega", "group_velocity", "curvature", "gamma", "beta", "h", "lambda", "h_tilde", "nonresonance1",
          "nonresonance2"]


def random_points(count, seed):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        params = lrchain.Params(alpha=rng.uniform(1.1, 3.0), delta0=rng.uniform(0.05, 2.0),
                                kappa=rng.uniform(0.2, 5.0), rho=rng.uniform(0.01, 30.0))
        branch = "optical" if rng.random() < 0.5 else "acoustic"
        yield params, branch, rng.uniform(-np.pi, np.pi)


def test_equal_to_cli_json_to_the_last_bit(cli):
    # Expected values: `lrchain coeffs --json` (the C++ coefficients(), printed with round-trip
    # precision); both must agree exactly at random parameters and wavenumbers.
    for params, branch, theta in random_points(12, seed=15):
        expected = cli("coeffs", "--alpha", repr(params.alpha), "--delta0", repr(params.delta0), "--kappa",
                       repr(params.kappa), "--rho", repr(params.rho), "--branch", branch, "--theta", repr(theta),
                       "--json")
        got = lrchain.coefficients(params, branch, theta)
        assert got.theta == expected["theta"]
        for name in FIELDS:
            value = expected[name]
            if value is None:  # the CLI prints null where the coefficient is singular
                assert np.isnan(got[name]) and got.regime == "singular"
            else:
                assert got[name] == value, (name, params, branch, theta)
        assert got.regime == expected["regime"]


def test_vectorised_equals_scalar_loop():
    # The batch loop and one call per wavenumber run the same C++ evaluator: bit-identical results.
    rng = np.random.default_rng(7)
    params = lrchain.Params(rho=0.7, delta0=0.3)
    theta = rng.uniform(-np.pi, np.pi, size=(20, 25))
    for branch in ("optical", "acoustic"):
        batch = lrchain.coefficients(params, branch, theta)
        assert batch.omega.shape == theta.shape and batch.regime.shape == theta.shape
        for index in np.ndindex(theta.shape):
            one = lrchain.coefficients(params, branch, float(theta[index]))
            for name in FIELDS:
                assert np.array_equal(batch[name][index], one[name], equal_nan=True), (name, index)
            assert batch.regime[index] == one.regime


def test_vectorised_loop_equals_scalar_cpp_path_bit_for_bit():
    # The batch loop (vectorised, the CPU's AVX-512/AVX2/baseline variant) against the library's scalar
    # coefficients() called once per wavenumber: identical bits, including wavenumbers next to the
    # resonances of rho = 10 where h_tilde has poles and the singular test decides.
    rng = np.random.default_rng(11)
    for params in (lrchain.Params(), lrchain.Params(rho=10.0), lrchain.Params(alpha=2.5, delta0=1.3, kappa=3.0, rho=0.05)):
        theta = np.concatenate([rng.uniform(-np.pi, np.pi, 3000), np.linspace(1e-3, np.pi, 3001)])
        for branch in ("optical", "acoustic"):
            batch = lrchain.coefficients(params, branch, theta)
            columns = [batch[name] for name in FIELDS]
            for i, t in enumerate(theta):
                one = lrchain._lrchain.coefficients_scalar(params, branch, float(t))
                got = tuple(float(column[i]) for column in columns)
                assert np.array_equal(np.array(got).view(np.int64), np.array(one[:-1]).view(np.int64)), (params, branch, t)
                assert batch.regime_code[i] == one[-1]


def test_paper_values_at_theta_pi_over_2():
    # Sec. 4.2 (exp1): optical branch at theta = pi/2 with the paper's parameters has T_b = 2.8885,
    # i.e. omega close to 2.1752 (the breather frequency differs by the 1e-4 detuning only), and
    # is focusing.
    c = lrchain.coefficients(lrchain.Params(), "optical", np.pi / 2)
    assert c.omega == pytest.approx(2.1752, abs=2e-4)
    assert c.regime == "focusing"
    assert c.curvature * c.h_tilde < 0


def test_nan_only_where_singular():
    # A dense sweep across the resonances of rho = 10 (Fig. 2 has several poles of h_tilde there):
    # h, lambda, h_tilde are NaN exactly at the singular entries; the other fields are finite.
    theta = np.linspace(1e-3, np.pi, 200001)
    for branch in ("optical", "acoustic"):
        c = lrchain.coefficients(lrchain.Params(rho=10.0), branch, theta)
        singular = c.regime == "singular"
        for name in ("h", "lambda", "h_tilde"):
            assert np.array_equal(np.isnan(c[name]), singular)
        for name in ("omega", "group_velocity", "curvature", "gamma", "beta", "nonresonance1", "nonresonance2"):
            assert np.all(np.isfinite(c[name]))


def test_singular_at_theta_zero_optical_is_degenerate():
    # theta = 0 on the optical branch: D1 = 0, the NLS is linear (Sec. 4.2): omega'' h_tilde = 0.
    c = lrchain.coefficients(lrchain.Params(), "optical", 0.0)
    assert c.regime == "degenerate"
    assert c.omega == pytest.approx(np.sqrt(1 + 1 / (1 / 3)), rel=1e-15)  # omega_+(0)^2 = kappa (1 + 1/rho)


def test_scalar_result_types_and_repr():
    c = lrchain.coefficients(lrchain.Params(rho=1 / 3), "optical", 1.5707963267948966)
    assert isinstance(c.omega, float) and isinstance(c.regime, str)
    text = repr(c)
    assert text.startswith("Coefficients(theta=1.5707963267948966, omega=") and "regime='focusing'" in text
    arr = lrchain.coefficients(lrchain.Params(), "acoustic", np.array([0.5, 1.0]))
    assert "shape=(2,)" in repr(arr)


def test_out_reuses_the_arrays():
    # out=: the arrays of an earlier result are overwritten in place with the new values, which are
    # those of a fresh evaluation; a result of another shape is refused, naming out.
    theta = np.linspace(0.01, np.pi, 1000)
    first = lrchain.coefficients(lrchain.Params(), "optical", theta)
    expected = lrchain.coefficients(lrchain.Params(rho=3.0), "acoustic", theta)
    again = lrchain.coefficients(lrchain.Params(rho=3.0), "acoustic", theta, out=first)
    assert again.omega is first.omega and again.regime_code is first.regime_code
    for name in FIELDS:
        assert np.array_equal(again[name], expected[name], equal_nan=True)
    assert np.array_equal(again.regime, expected.regime)
    with pytest.raises(lrchain.InvalidParameterError, match="out") as err:
        lrchain.coefficients(lrchain.Params(), "optical", theta[:10], out=first)
    assert err.value.parameter == "out"
