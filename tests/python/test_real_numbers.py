"""Complex numbers where a real number is expected are refused with InvalidParameterError naming the
argument, never truncated to their real part. Before, numpy's complex scalars and arrays went through
float() (a ComplexWarning and the imaginary part dropped): coefficients(p, "optical", 1.2 + 0.5j as a
numpy scalar) returned the coefficients at theta = 1.2."""

import math

import numpy as np
import pytest

import lrchain

COMPLEX_THETA = [np.complex128(1.2 + 0.5j), np.complex64(1.2 + 0.5j), np.array([0.5, 1.2 + 0.5j]),
                 np.array(1.2 + 0j), [0.5, np.complex128(1.2 + 0.5j)], 1.2 + 0.5j]


@pytest.mark.parametrize("theta", COMPLEX_THETA, ids=repr)
def test_coefficients_refuse_complex_theta(theta):
    with pytest.raises(lrchain.InvalidParameterError, match="theta.*complex") as refused:
        lrchain.coefficients(lrchain.Params(), "optical", theta)
    assert refused.value.parameter == "theta"


def test_model_coefficients_refuse_complex_theta():
    with pytest.raises(lrchain.InvalidParameterError, match="theta") as refused:
        lrchain.coefficients(lrchain.load_model("klein_gordon"), "branch0", np.complex128(1.0 + 1e-3j))
    assert refused.value.parameter == "theta"


@pytest.mark.parametrize("name, call", [
    ("theta", lambda: lrchain.simulate.bright(lrchain.Params(), theta=np.complex128(1.5 + 0.1j), sites=81, periods=1)),
    ("detuning", lambda: lrchain.simulate.bright(lrchain.Params(), detuning=np.complex128(1e-4j), sites=81, periods=1)),
    ("t_end", lambda: lrchain.simulate.drive(t_end=np.complex128(10 + 1j))),
    ("theta", lambda: lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", np.complex128(math.pi / 2 + 0.1j))),
    ("amplitudes", lambda: lrchain.simulate.ring(lrchain.load_model("fput"), "acoustic", math.pi / 2,
                                                 amplitudes=[0.02, np.complex128(0.01 + 0.01j)])),
    ("omega_b", lambda: lrchain.dark.solve(lrchain.Params(), omega_b=np.complex128(2.42 + 0.01j), sites=21)),
    ("t_end", lambda: lrchain.dark.evolve(lrchain.Params(), omega_b=2.42, sites=21, t_end=np.complex128(30 + 1j))),
    ("tolerance", lambda: lrchain.regime.intervals(lrchain.Params(), "optical", tolerance=np.complex128(1e-12 + 1e-13j))),
    ("rho", lambda: lrchain.regime.theta_rho_map(lrchain.Params(), "optical", rho=(0.01, np.complex128(30 + 1j), 10))),
    ("rho", lambda: lrchain.Params(rho=np.complex128(1 / 3 + 0.1j))),
    ("kappa", lambda: lrchain.Params().replace(kappa=np.complex128(1 + 1j))),
    ("w0", lambda: lrchain.load_model("klein_gordon", w0=np.complex128(1.2 + 0.3j))),
    # Model.replace converts in C++ (model_binding.cpp): before, it took the real part.
    ("w0", lambda: lrchain.load_model("klein_gordon").replace(w0=np.complex128(1.2 + 0.3j))),
])
def test_complex_arguments_are_refused(name, call):
    with pytest.raises(lrchain.InvalidParameterError, match="complex") as refused:
        call()
    assert refused.value.parameter == name


def test_real_numpy_values_are_accepted():
    # numpy real scalars and a complex number's .real pass: only complex values are refused.
    c = lrchain.coefficients(lrchain.Params(rho=np.float64(1 / 3)), "optical", np.complex128(1.2 + 0.5j).real)
    assert c.theta == 1.2
