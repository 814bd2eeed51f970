// Paper numbers for the coefficient library (issue 2, section 3). Parameters alpha=3/2,
// delta0=4/9, kappa=1, rho=1/3 unless stated; tolerances from the paper's rounding.
#include <doctest/doctest.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"

using namespace lrchain;
constexpr double pi = std::numbers::pi;

TEST_CASE("dispersion values quoted in the paper") {
  const Params p = paper_params();
  CHECK(dispersion_omega(p, Branch::optical, pi) == doctest::Approx(2.4495).epsilon(5e-5 / 2.4495));   // Sec. 5.3 omega_opt
  CHECK(dispersion_omega(p, Branch::acoustic, pi) == doctest::Approx(1.4142).epsilon(5e-5 / 1.4142));  // Sec. 5.3 omega_acs
  CHECK(dispersion_omega(p, Branch::optical, pi / 8) == doctest::Approx(2.0098).epsilon(5e-5 / 2.0098));  // Sec. 4.2
  CHECK(dispersion_omega(p, Branch::optical, pi / 2) - 1e-4 == doctest::Approx(2.1752).epsilon(5e-5 / 2.1752));  // Fig. 6
  // rho = 1: omega_opt = 2.2882 (Sec. 5.3 text; Fig. 19's caption (fig:r1_norm) prints 2.2282, see docs/paper-errata.md).
  Params p1 = p;
  p1.rho = 1.0;
  CHECK(dispersion_omega(p1, Branch::optical, pi) == doctest::Approx(2.2882).epsilon(5e-5 / 2.2882));
}

TEST_CASE("group velocity and the inflection point theta_c of the optical branch (Sec. 3.3, 4.2)") {
  const Params p = paper_params();
  CHECK(coefficients(p, Branch::optical, pi / 2).group_velocity == doctest::Approx(0.23).epsilon(0.005 / 0.23));
  // omega_+''(theta_c) = 0 at theta_c ~ 1.892: bracketing root of the curvature (TOMS 748).
  auto curvature = [&](double th) { return coefficients(p, Branch::optical, th).curvature; };
  boost::uintmax_t iters = 100;
  auto [a, b] = boost::math::tools::toms748_solve(curvature, 1.5, 2.5, boost::math::tools::eps_tolerance<double>(50), iters);
  CHECK(0.5 * (a + b) == doctest::Approx(1.892).epsilon(5e-4 / 1.892));
  // c = d omega / d theta: compare with a central difference of the dispersion relation.
  const double h = 1e-5, th = 1.1;
  const double fd = (dispersion_omega(p, Branch::acoustic, th + h) - dispersion_omega(p, Branch::acoustic, th - h)) / (2 * h);
  CHECK(coefficients(p, Branch::acoustic, th).group_velocity == doctest::Approx(fd).epsilon(1e-8));
}

TEST_CASE("theta = pi edge values (Sec. 5.2) in double precision") {
  for (double rho : {0.1, 1.0 / 3.0, 3.0, 10.0})
    for (Branch b : {Branch::optical, Branch::acoustic}) {
      Params p = paper_params();
      p.rho = rho;
      const auto K = taylor_coefficients(p);
      const NlsCoefficients c = coefficients(p, b, pi);
      CHECK(std::abs(c.group_velocity) < 1e-14);
      CHECK(c.beta == doctest::Approx(-4 * K.K3 * c.gamma).epsilon(1e-13));
      CHECK(c.h_tilde == doctest::Approx((24 * K.K4 - 32 * K.K3 * K.K3 / K.K2) * c.gamma).epsilon(1e-12));
      CHECK(c.curvature == doctest::Approx(-K.K2 * c.gamma).epsilon(1e-12));
      CHECK(c.lambda == doctest::Approx(-8 * K.K3 / K.K2).epsilon(1e-12));
      CHECK(c.regime == Regime::defocusing);  // omega'' h_tilde = -(24 K2 K4 - 32 K3^2) gamma^2 > 0
    }
}

TEST_CASE("theta = 0 optical values (Sec. 4.2): beta = h = c = 0, omega'' = kappa K2 / omega^3") {
  for (double rho : {0.1, 1.0 / 3.0, 10.0}) {
    Params p = paper_params();
    p.rho = rho;
    const auto K = taylor_coefficients(p);
    const NlsCoefficients c = coefficients(p, Branch::optical, 0.0);
    CHECK(c.group_velocity == 0.0);
    CHECK(c.beta == 0.0);
    CHECK(c.h == 0.0);
    CHECK(c.omega == doctest::Approx(std::sqrt(p.kappa * (1 + 1 / rho))).epsilon(1e-15));
    CHECK(c.curvature == doctest::Approx(p.kappa * K.K2 / std::pow(c.omega, 3)).epsilon(1e-13));
    CHECK(c.regime == Regime::degenerate);
  }
}

TEST_CASE("regime and singular points") {
  const Params p = paper_params();
  CHECK(coefficients(p, Branch::optical, pi / 2).regime == Regime::focusing);   // Sec. 4.2
  CHECK(coefficients(p, Branch::optical, 2.5).regime == Regime::defocusing);    // theta > theta_c
  CHECK(coefficients(p, Branch::acoustic, 1.87).regime == Regime::focusing);    // (1.7841, 1.949), Sec. 3.3
  CHECK(coefficients(p, Branch::acoustic, 1.0).regime == Regime::defocusing);
  // The focusing acoustic interval starts at a pole of h_tilde (eq:nonresonance1 violated near 1.7841):
  auto n1 = [&](double th) { return coefficients(p, Branch::acoustic, th).nonresonance1; };
  boost::uintmax_t iters = 100;
  auto [a, b] = boost::math::tools::toms748_solve(n1, 1.7, 1.85, boost::math::tools::eps_tolerance<double>(52), iters);
  const double root = 0.5 * (a + b);
  CHECK(root == doctest::Approx(1.7841).epsilon(5e-5 / 1.7841));
  const NlsCoefficients at_pole = coefficients_unchecked(p, taylor_coefficients(p), Branch::acoustic, root);
  CHECK(at_pole.regime == Regime::singular);
  CHECK(std::isnan(at_pole.h_tilde));
  CHECK(std::isfinite(at_pole.h_tilde_numerator));
}

TEST_CASE("invalid input names the parameter") {
  Params p = paper_params();
  p.rho = -1;
  CHECK_THROWS_AS(coefficients(p, Branch::optical, 1.0), InvalidParameter);
  CHECK_THROWS_WITH_AS(coefficients(paper_params(), Branch::optical, 4.0), doctest::Contains("theta"), InvalidParameter);
  CHECK_THROWS_WITH_AS(coefficients(paper_params(), Branch::acoustic, 0.0), doctest::Contains("theta"), InvalidParameter);
  CHECK_THROWS_AS(coefficients(paper_params(), Branch::optical, -pi), InvalidParameter);  // (-pi, pi]
  CHECK_NOTHROW(coefficients(paper_params(), Branch::optical, pi));
}
