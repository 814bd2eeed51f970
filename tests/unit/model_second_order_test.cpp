// The second-order terms of the multiple-scale expansion (lrchain::second_order_terms: second
// harmonic W2_f per unit A^2, mean W0_f per unit |A|^2, from the emitted harmonics evaluators)
// against results the derivation did not produce, and their use in the model bright ansatz.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright_run.hpp"

using namespace lrchain;
using Complex = std::complex<double>;

TEST_CASE("klein_gordon at zero coupling: second harmonic and offset of one anharmonic oscillator (Landau-Lifshitz 28)") {
  // x'' + w0^2 x + a x^2 + b x^3 = 0 (Landau & Lifshitz, Mechanics, Sec. 28, eq. 28.10):
  //   x = X cos(w t) - a X^2 / (2 w0^2) + a X^2 / (6 w0^2) cos(2 w t).
  // Our u = A E + c.c. + A^2 W2 E^2 + c.c. + |A|^2 W0 with real A has X = 2A, so
  //   W0 = -a (2A)^2 / (2 w0^2) / A^2 = -2a / w0^2 and 2 W2 A^2 = a (2A)^2 / (6 w0^2): W2 = a / (3 w0^2).
  const double w0 = 1.3, a = 0.7;
  const Model model = shipped_model("klein_gordon", {{"C", 0.0}, {"w0", w0}, {"a", a}, {"b", -0.4}});
  for (const double theta : {0.4, 2.0, std::numbers::pi}) {
    const SecondOrderTerms t = second_order_terms(model, 0, theta);
    REQUIRE(t.second_harmonic.size() == 1);
    CHECK(t.second_harmonic[0].real() == doctest::Approx(a / (3 * w0 * w0)).epsilon(1e-13));
    CHECK(t.second_harmonic[0].imag() == 0.0);
    CHECK(t.mean[0] == doctest::Approx(-2 * a / (w0 * w0)).epsilon(1e-13));
  }
}

TEST_CASE("fput: the second harmonic is i a cot(theta/2) and there is no offset") {
  // u'' = F(u[n+1]-u[n]) - F(u[n]-u[n-1]), F(r) = r + a r^2 + b r^3, omega^2 = D1 = 4 sin^2(theta/2).
  // At E^2 (by hand): (4 sin^2 theta - 4 omega^2) W2 = a [(z-1)^2 - (1-1/z)^2] = -a (2i sin theta) D1,
  // z = e^{i theta}, and 4 sin^2 theta - 4 D1 = -D1^2: W2 = 2i a sin(theta) / D1 = i a cot(theta/2).
  // The field's mean is the mean flow (lambda), not an offset: W0 = 0.
  const double a = -0.35;
  const Model model = shipped_model("fput", {{"a", a}, {"b", 0.2}});
  for (const double theta : {0.3, 1.1, 2.5}) {
    const SecondOrderTerms t = second_order_terms(model, 0, theta);
    CHECK(std::abs(t.second_harmonic[0] - Complex(0, a / std::tan(theta / 2))) <= 1e-13 * std::abs(a / std::tan(theta / 2)));
    CHECK(t.mean[0] == 0.0);
  }
}

TEST_CASE("resonant_chain: second harmonic as eq:A22A11 with B22 = kappa / (kappa - 4 rho omega^2) A22, gradient term from eq:B21") {
  // Appendix A of the paper: A_{2,2} = K3 s D1 (kappa - 4 omega^2 rho) / ((4 omega^2 - 4 K2 sin^2 theta
  // - kappa)(kappa - 4 omega^2 rho) + kappa^2) A_{1,1}^2 with s = 2i sin theta, K2 = alpha delta0^(alpha-1),
  // K3 = -alpha (alpha-1) delta0^(alpha-2) / 2; the resonator is linear: no offset of v from u.
  const double alpha = 1.7, delta0 = 0.6, kappa = 1.4, rho = 0.45;
  const Model model = shipped_model("resonant_chain", {{"alpha", alpha}, {"delta0", delta0}, {"kappa", kappa}, {"rho", rho}});
  const double K2 = alpha * std::pow(delta0, alpha - 1), K3 = -0.5 * alpha * (alpha - 1) * std::pow(delta0, alpha - 2);
  for (const char* branch : {"acoustic", "optical"})
    for (const double theta : {0.5, 1.6, 2.9}) {
      const double omega = coefficients(model, model.branch(branch), theta).omega, w2 = omega * omega;
      const double D1 = 4 * std::pow(std::sin(theta / 2), 2), sin2 = std::pow(std::sin(theta), 2);
      const Complex s(0, 2 * std::sin(theta));
      const Complex A22 = K3 * s * D1 * (kappa - 4 * w2 * rho) /
                          ((4 * w2 - 4 * K2 * sin2 - kappa) * (kappa - 4 * w2 * rho) + kappa * kappa);
      const Complex B22 = kappa / (kappa - 4 * rho * w2) * A22;
      // eq:B21 with A_{2,1} = 0: (kappa - rho omega^2) B_{2,1} = -2i omega c rho d_xi B_{1,1}, B_{1,1} = K A_{1,1}:
      // G_1 = -2i omega c rho kappa / (kappa - rho omega^2)^2 (= -i dK/dtheta along the branch).
      const double c = coefficients(model, model.branch(branch), theta).group_velocity;
      const Complex G1(0, -2 * omega * c * rho * kappa / std::pow(kappa - rho * w2, 2));
      const SecondOrderTerms t = second_order_terms(model, model.branch(branch), theta);
      INFO(branch << " theta " << theta);
      CHECK(std::abs(t.second_harmonic[0] - A22) <= 1e-12 * std::abs(A22));
      CHECK(std::abs(t.second_harmonic[1] - B22) <= 1e-12 * std::abs(B22));
      CHECK(t.mean[0] == 0.0);
      CHECK(std::abs(t.mean[1]) <= 1e-15);
      CHECK(t.kernel_gradient[0] == 0.0);
      CHECK(std::abs(t.kernel_gradient[1] - G1) <= 1e-12 * std::abs(G1));
    }
}

TEST_CASE("resonant_chain_polynomial: the nonlinear resonator's mean offset 2 b2 |1 - K_1|^2 / k2") {
  // rho v'' = G(u - v), G(s) = k2 s + b2 s^2 + g2 s^3: the mean of G vanishes at O(eps^2), with
  // u - v = (1 - K_1) A E + c.c. + (mean of u - v): k2 (mean of u - v) + 2 b2 |1 - K_1|^2 |A|^2 = 0, and
  // u's mean is the mean flow, so v's offset is W0_1 = 2 b2 |1 - K_1|^2 / k2, K_1 = k2 / (k2 - rho omega^2).
  const double k2 = 1.3, b2 = 0.3, rho = 0.4;
  const Model model = shipped_model("resonant_chain_polynomial", {{"k2", k2}, {"b2", b2}, {"rho", rho}});
  for (const char* branch : {"acoustic", "optical"})
    for (const double theta : {0.7, 2.2}) {
      const double omega = coefficients(model, model.branch(branch), theta).omega;
      const double K1 = k2 / (k2 - rho * omega * omega);
      const SecondOrderTerms t = second_order_terms(model, model.branch(branch), theta);
      INFO(branch << " theta " << theta);
      CHECK(t.mean[0] == 0.0);
      CHECK(t.mean[1] == doctest::Approx(2 * b2 * (1 - K1) * (1 - K1) / k2).epsilon(1e-12));
    }
}

TEST_CASE("model bright ansatz of the resonant chain: first order equals BrightBreatherAnsatz, second order adds eq:A22A11") {
  // The generic ansatz (ModelBrightAnsatz on the generated lattice's Bloch vector) without its
  // second-order terms is eq:focus_app, as the specialised BrightBreatherAnsatz: equal to round-off.
  // With them, the difference is 2 |A|^2 Re(W2_f e^{2 i phi}) + 2 Re(G_f dA/dn e^{i phi}) with W2, G
  // from the paper (test above), |A| = M2 sech(a (n - n0 - c t)), phi = n theta - omega_b t (no offset:
  // the resonator is linear).
  const Params p{1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0};
  const Model model = shipped_model("resonant_chain");
  const auto& kernels = sim::lattice_kernels_of(model);
  const double theta = std::numbers::pi / 2, detuning = -1e-3, n0 = 3;
  const BrightBreatherAnsatz paper(p, Branch::optical, theta, detuning, n0);
  const sim::ModelBrightAnsatz first(model, kernels, model.branch("optical"), theta, detuning, n0, false);
  const sim::ModelBrightAnsatz second(model, kernels, model.branch("optical"), theta, detuning, n0, true);
  const SecondOrderTerms t = second_order_terms(model, model.branch("optical"), theta);
  double worst_first = 0, worst_second = 0, scale = 0;
  for (const double time : {0.0, 7.3})
    for (int n = -60; n <= 60; ++n) {
      double u, v, u_dot, v_dot;
      paper.displacements(n, time, u, v);
      paper.velocities(n, time, u_dot, v_dot);
      const double expected[2][2] = {{u, u_dot}, {v, v_dot}};
      const double z = paper.inverse_width() * (n - n0 - paper.group_velocity() * time);
      const double A = paper.M2() / std::cosh(z);
      const Complex phase = std::polar(1.0, n * theta - paper.omega_b() * time);
      for (std::size_t f = 0; f < 2; ++f) {
        double x, x_dot;
        first.field(f, n, time, x, x_dot);
        worst_first = std::max({worst_first, std::abs(x - expected[f][0]), std::abs(x_dot - expected[f][1])});
        second.field(f, n, time, x, x_dot);
        const double harmonic = 2 * A * A * (t.second_harmonic[f] * phase * phase).real() -
                                2 * paper.inverse_width() * std::tanh(z) * A * (t.kernel_gradient[f] * phase).real();
        worst_second = std::max(worst_second, std::abs(x - expected[f][0] - harmonic));
        scale = std::max(scale, std::abs(expected[f][0]));
      }
    }
  CHECK(scale > 0.01);
  CHECK(worst_first <= 1e-13 * scale);
  CHECK(worst_second <= 1e-13 * scale);
  CHECK(second.uses_second_order());
  CHECK_FALSE(first.uses_second_order());
}
