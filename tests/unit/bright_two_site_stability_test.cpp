// A second published result on bright-breather stability, reproduced near the anti-continuum limit of
// klein_gordon: Koukouloyannis & Kevrekidis, "On the stability of multibreathers in Klein-Gordon chains"
// (arXiv:0902.3990; abstract): with positive coupling, for hard on-site nonlinearities only in-phase
// adjacent excitations may be stable and for soft ones only out-of-phase ones, and the characteristic
// exponents are O(sqrt(epsilon)) in the coupling epsilon. The bond-centred breather at small C is such a
// two-site breather: staggered (out of phase) above the band of the hard chain (b = 1/2), unstaggered
// (in phase) below the band of the soft one (b = -1/2); both must be unstable, with one real pair.
// The coefficient of sqrt(C) is not printed in that abstract; it follows from the averaged coupling
// energy of the two oscillators (MacKay's effective Hamiltonian, which arXiv:1006.0346 shows equivalent
// to Aubry's band method): with x(theta) = sum_k a_k cos(k theta) the coupling -C x1 x2 averages to
// -C sum_k a_k^2 cos(k phi) / 2 in the phase difference phi; phi'' = -2 C (d omega/dJ) V''(phi0) delta phi
// gives sigma^2 = 2 C |d omega/dJ| J / omega at phi0 = pi (hard) and 0 (soft) for an odd oscillation,
// since sum_k k^2 a_k^2 = 2 J / omega. J(omega) and d omega/dJ of the single Duffing oscillator
// x'' + x + b x^3 = 0 come from its period and action integrals (tests/support/oscillator_amplitude.hpp),
// independent of the lattice code: sigma / sqrt(C) = 0.584218 (hard, omega_b = 1.3) and 0.511665 (soft,
// omega_b = 0.9). Measured ln|lambda| / T_b / sqrt(C): hard 0.578798 (C = 0.004), 0.582874 (0.001);
// soft 0.510579, 0.511417: the relative gap falls like C (2.3 C hard, 0.5 C soft); allowed 3 C.
#include <cmath>
#include <numbers>
#include <doctest/doctest.h>

#include "../support/oscillator_amplitude.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/branch_bifurcations.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

// sigma / sqrt(C) = sqrt(2 J |d omega/dJ| / omega) of the two-site breather at omega_b (header comment).
double predicted_exponent_coefficient(double b, double omega_b) {
  const double A = test::oscillator_amplitude(1.0, b, omega_b), h = 1e-4 * A;
  const double dw = test::oscillator_frequency(1.0, b, A + h) - test::oscillator_frequency(1.0, b, A - h);
  const double dJ = test::oscillator_action(1.0, b, A + h) - test::oscillator_action(1.0, b, A - h);
  return std::sqrt(2 * test::oscillator_action(1.0, b, A) * std::abs(dw / dJ) / omega_b);
}

// The bond-centred breather at omega_b continued in C from 0.1 down to `to` (21 sites), its last point.
BrightBreatherResult bond_breather_at(const Model& model, double omega_b, double to) {
  BrightBreatherConfig c;
  c.step = BrightStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = omega_b;
  c.sites = 21;
  c.center = "bond";
  c.parameter = "C";
  c.to = to;
  c.points = 40;
  c.ds = 0.02;
  c.locate_tolerance = 0;
  validate(c);
  BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""), " ", r.branch.stop_reason);
  REQUIRE(!failure(r));
  REQUIRE(r.branch.points.back().parameter == doctest::Approx(to).epsilon(1e-12));
  return r;
}

}  // namespace

TEST_CASE("bright two-site breathers near C = 0: the in/out-of-phase rule and exponents sqrt(C) x the effective Hamiltonian's" * doctest::test_suite("fast")) {
  struct Case {
    double b, omega_b, sign;  // sign of u0 u1 at the two centre sites: -1 out of phase, +1 in phase
  };
  for (const Case k : {Case{0.5, 1.3, -1.0}, Case{-0.5, 0.9, +1.0}}) {
    CAPTURE(k.b);
    const Model model = shipped_model("klein_gordon", {{"a", 0.0}, {"b", k.b}});
    const double predicted = predicted_exponent_coefficient(k.b, k.omega_b);
    for (const double C : {0.004, 0.001}) {
      CAPTURE(C);
      const BrightBreatherResult r = bond_breather_at(model, k.omega_b, C);
      const Eigen::VectorXd& z = r.branch.points.back().z0;
      CHECK(z(10) * z(11) * k.sign > 0);  // the two excited sites (the bond between sites 10 and 11)
      CHECK(std::abs(z(9)) < 0.05 * std::abs(z(10)));
      const sim::bright::BrightFloquet& f = r.branch_floquets.back();
      CHECK_FALSE(f.stable);
      CHECK(sim::bright::real_multipliers_beyond(f, +1, 1e-6) == 1);  // one real pair (lambda, 1/lambda)
      const double coefficient = std::log(f.max_nontrivial_modulus) * k.omega_b / (2 * std::numbers::pi) / std::sqrt(C);
      MESSAGE("b = ", k.b, " C = ", C, ": sigma / sqrt(C) = ", coefficient, " predicted ", predicted);
      CHECK(std::abs(coefficient - predicted) / predicted < 3 * C);
    }
  }
}
