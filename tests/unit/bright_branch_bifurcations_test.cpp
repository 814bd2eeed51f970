// Folds and multiplier crossings along a bright-breather branch (sim/bright/branch_bifurcations.hpp),
// on samples and monodromy matrices whose answer is known by construction.
#include <cmath>
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "lrchain/sim/bright/branch_bifurcations.hpp"
#include "lrchain/sim/bright/krein_signature.hpp"

using namespace lrchain;
using namespace lrchain::sim::bright;

TEST_CASE("bright branch: a fold located on the Hermite interpolant of omega_b(s)" * doctest::test_suite("fast")) {
  // omega_b(s) = 1 - (s - 0.3)^2 sampled at s = 0 and 0.5 (values 0.91, 0.96; slopes 0.6, -0.4): the
  // cubic Hermite interpolant is this parabola itself, so the fold is at s = 0.3, omega_b = 1 exactly,
  // and the norm (2 -> 3, linear in s) is 2.6 there.
  const std::vector<BranchSample> samples{{0.0, 0.91, 0.6, 2.0, std::nullopt, std::nullopt, std::nullopt, std::nullopt},
                                          {0.5, 0.96, -0.4, 3.0, std::nullopt, std::nullopt, std::nullopt, std::nullopt},
                                          {1.0, 0.51, -1.4, 4.0, std::nullopt, std::nullopt, std::nullopt, std::nullopt}};
  const std::vector<BranchBifurcation> found = branch_bifurcations(samples);
  REQUIRE(found.size() == 1);
  CHECK(found[0].kind == "fold");
  CHECK(found[0].index == 0);
  CHECK(found[0].omega_b == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(found[0].norm_squared == doctest::Approx(2.6).epsilon(1e-14));
  CHECK(found[0].omega_low == 0.91);
  CHECK(found[0].omega_high == 0.96);
}

TEST_CASE("bright branch: multipliers beyond +1 and -1 counted without the trivial pair, crossings bracketed" * doctest::test_suite("fast")) {
  // A symplectic monodromy built from blocks: the trivial Jordan block at +1 (phase mode), a hyperbolic
  // pair (2, 1/2), a period-doubling pair (-3, -1/3) and a rotation by 1 rad on the unit circle.
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(8, 8);
  m.block(0, 0, 2, 2) << 1, 1, 0, 1;
  m.block(2, 2, 2, 2) << 2, 0, 0, 0.5;
  m.block(4, 4, 2, 2) << -3, 0, 0, -1.0 / 3;
  m.block(6, 6, 2, 2) << std::cos(1.0), -std::sin(1.0), std::sin(1.0), std::cos(1.0);
  const BrightFloquet f = bright_floquet(m, false);
  REQUIRE(f.trivial_found);
  CHECK(real_multipliers_beyond(f, +1, 1e-6) == 1);
  CHECK(real_multipliers_beyond(f, -1, 1e-6) == 1);
  // Stable (0 beyond +1, 0 beyond -1) -> the pair above -> stable again: two branch points and two
  // period doublings, each between the points that bracket it, at the bracket's middle.
  // The oscillatory instability appearing between the last two points is a Krein collision; its
  // disappearance between the first two is not flagged (a quadruplet returning to the circle).
  const std::vector<BranchSample> samples{
      {0.0, 1.2, 1.0, 1.0, 0, 0, true, 0}, {0.1, 1.3, 1.0, 2.0, 1, 1, false, 0}, {0.2, 1.4, 1.0, 3.0, 0, 0, true, 0}};
  const std::vector<BranchBifurcation> found = branch_bifurcations(samples);
  REQUIRE(found.size() == 5);
  CHECK(found[4].kind == "krein_collision");
  CHECK(found[4].index == 1);
  CHECK(found[0].kind == "branch_point");
  CHECK(found[1].kind == "period_doubling");
  CHECK(found[2].kind == "branch_point");
  CHECK(found[2].index == 1);
  CHECK(found[2].omega_b == doctest::Approx(1.35).epsilon(1e-14));
  CHECK(found[2].norm_squared == doctest::Approx(2.5).epsilon(1e-14));
  CHECK(found[3].omega_low == 1.3);
  CHECK(found[3].omega_high == 1.4);
}

TEST_CASE("bright branch: Krein signatures of a positive- and a negative-energy oscillator" * doctest::test_suite("fast")) {
  // State (q1, q2, q1dot, q2dot), masses (2, 1). Oscillator 1: H = m qdot^2 / 2 + k q^2 / 2 (omega = 0.7),
  // multiplier exp(+0.7 i) with eigenvector (1, 0.7 i): v^H J v = 2 i m 0.7 > 0, signature +1.
  // Oscillator 2 runs backwards (H = -(qdot^2 + omega^2 q^2)/2, omega = 1.9): exp(+1.9 i) has
  // eigenvector (1, -1.9 i), signature -1. Period T = 1: M = exp(A) of each 2 x 2 block.
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(4, 4);
  const double w1 = 0.7, w2 = 1.9;
  m(0, 0) = std::cos(w1), m(0, 2) = std::sin(w1) / w1, m(2, 0) = -w1 * std::sin(w1), m(2, 2) = std::cos(w1);
  m(1, 1) = std::cos(w2), m(1, 3) = -std::sin(w2) / w2, m(3, 1) = w2 * std::sin(w2), m(3, 3) = std::cos(w2);
  const std::vector<KreinMultiplier> k = krein_signatures(m, Eigen::Vector2d(2.0, 1.0), 1e-9);
  REQUIRE(k.size() == 2);
  CHECK(std::arg(k[0].lambda) == doctest::Approx(w1).epsilon(1e-12));
  CHECK(k[0].signature == 1);
  CHECK(std::arg(k[1].lambda) == doctest::Approx(w2).epsilon(1e-12));
  CHECK(k[1].signature == -1);
}
