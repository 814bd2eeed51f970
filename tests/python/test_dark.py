"""lrchain.dark: the dark breather at omega_b = 2.42 (Sec. 5.3) converges and equals the CLI's."""

import numpy as np
import pytest

import lrchain


@pytest.fixture(scope="module")
def solution():
    return lrchain.dark.floquet(lrchain.Params(), omega_b=2.42)


def test_solve_converges_and_equals_cli(cli, solution):
    # Expected: `lrchain dark solve --omega-b 2.42` (same Newton from the same seed).
    expected = cli("dark", "solve", "--omega-b", "2.42", "--quiet")
    assert expected["newton_converged"]
    assert solution.newton_residuals[-1] <= 1e-11
    assert list(solution.newton_residuals) == expected["newton_residuals"]
    for key in ("norm_squared", "K_x", "K_y", "E_b"):
        assert solution.measures[key] == pytest.approx(expected["measures"][key], rel=1e-9, abs=1e-13)
    # One period returns to the start (E_b of eq. relerr) and the bond-centred profile is a dip.
    assert solution.measures["E_b"] < 1e-9
    assert solution.omega_edge == pytest.approx(np.sqrt(6), rel=1e-15)  # omega_+(pi)^2 = 4 K2 + ... = 6 here
    assert solution.x.shape == (101,) and solution.n[0] == -50


def test_floquet_multipliers(solution):
    f = solution.floquet
    assert f.multipliers.dtype == np.complex128 and len(f.multipliers) == 4 * 101
    # Symplectic monodromy: multipliers come in (lambda, 1/conj(lambda)) pairs, det = 1.
    assert f.pairing_defect < 1e-8 and abs(f.log_det) < 1e-6
    assert f.max_modulus == pytest.approx(np.abs(f.multipliers).max())


def test_continue_branch_short():
    b = lrchain.dark.continue_branch(lrchain.Params(), omega_b=2.42, points=3, ds=0.05, floquet=False)
    assert len(b.omega_b) == 3 and b.x.shape == (3, 101)
    assert b.stop_reason == "reached 3 points"
    assert np.all(np.diff(b.norm_squared) != 0)


def test_evolve_stays_on_the_orbit():
    e = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, t_end=3 * 2 * np.pi / 2.42 + 1e-9)
    assert len(e.t) == 3 and e.x.shape == (4, 101)
    assert e.E_b.max() < 1e-8


def test_newton_failure_raises_numerical_failure():
    # From the seed Newton needs 4 steps at omega_b = 2.42 (the CLI's residual history above).
    with pytest.raises(lrchain.NumericalFailure, match="Newton found no breather at omega_b = 2.42"):
        lrchain.dark.solve(lrchain.Params(), omega_b=2.42, max_iterations=1)


def test_collapse_to_the_zero_state_raises_numerical_failure():
    # At omega_b = 1.6, far below the optical edge sqrt(6), Newton on 21 sites from the seed reaches
    # Z(0) = 0 (max strain ~5e-17): a zero of the shooting residual but no breather.
    with pytest.raises(lrchain.NumericalFailure, match="converged to the trivial state"):
        lrchain.dark.solve(lrchain.Params(), omega_b=1.6, sites=21)


def test_integer_keywords_accept_integral_floats_and_refuse_others():
    # samples, sites, points as floats: integral values are the integers (as the command's 1e3), others
    # are refused with InvalidParameterError naming the keyword (the cap of dark --samples: [4, 1000000]).
    period = 2 * np.pi / 2.42
    with pytest.raises(lrchain.InvalidParameterError, match=r"samples: must be an integer in \[4, 1000000\]") as e:
        lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=period, samples=1e7)
    assert e.value.parameter == "samples"
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=period, samples=24.5)
    assert e.value.parameter == "samples"
    with pytest.raises(lrchain.InvalidParameterError) as e:
        lrchain.dark.solve(lrchain.Params(), omega_b=2.42, sites=21.5)
    assert e.value.parameter == "sites"
    as_float = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21.0, t_end=period, samples=8.0)
    as_int = lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=period, samples=8)
    assert np.array_equal(as_float.x, as_int.x) and np.array_equal(as_float.position, as_int.position)
