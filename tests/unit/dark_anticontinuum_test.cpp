// `dark continue --model klein_gordon --parameter C --to 0` reaches the anti-continuum limit (issue
// 27): at C = 0 every site is an independent on-site oscillator u'' = -V'(u), V(u) = w0^2 u^2/2 +
// a u^3/3 + b u^4/4, so each site of the breather at rest at t = 0 is either at rest (u = 0) or at a
// turning point x0 whose oscillation has the period T_b = 2 pi/omega_b. That x0 is computed here
// independently, by quadrature of the energy integral T(x0) = 2 int dx / sqrt(2 (V(x0) - V(x)))
// between the two turning points, and compared with the branch's last point.
#include <doctest/doctest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <iomanip>
#include <numbers>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::dark;

namespace {
// klein_gordon's defaults: w0 = 1, a = 1/4, b = 1/2.
double potential(double x) { return x * x / 2 + 0.25 * x * x * x / 3 + 0.5 * x * x * x * x / 4; }

// The other turning point: V(x1) = V(x0) on the other side of the well's bottom at 0.
double other_turning_point(double x0) {
  const double energy = potential(x0);
  auto f = [&](double x) { return potential(x) - energy; };
  boost::math::tools::eps_tolerance<double> tol(50);
  std::uintmax_t iterations = 200;
  const double far = -(10 * std::abs(x0) + 1) * (x0 > 0 ? 1 : -1), near = -1e-300 * (x0 > 0 ? 1 : -1);
  const auto [lo, hi] = boost::math::tools::toms748_solve(f, std::min(far, near), std::max(far, near), tol, iterations);
  return 0.5 * (lo + hi);
}

// T(x0) by the energy integral between the turning points xl < xu. With x = m + d sin(theta) and
// V(x) - E = b/4 (x - xl)(x - xu)(x^2 + s x + t) (polynomial division), (xu - x)(x - xl) = d^2 cos^2
// and the integrand is 1/sqrt(2 (b/4)(x^2 + s x + t)): smooth, no cancellation near the turning points.
double period(double x0) {
  const double x1 = other_turning_point(x0);
  const double xl = std::min(x0, x1), xu = std::max(x0, x1);
  const double m = 0.5 * (xl + xu), d = 0.5 * (xu - xl);
  const double c4 = 0.5 / 4, c3 = 0.25 / 3, c2 = 0.5;  // V = c2 x^2 + c3 x^3 + c4 x^4
  const double sigma = xl + xu, product = xl * xu;
  const double s = c3 / c4 + sigma, t = c2 / c4 + sigma * s - product;
  auto integrand = [&](double theta) {
    const double x = m + d * std::sin(theta);
    return 1.0 / std::sqrt(2 * c4 * (x * x + s * x + t));
  };
  return 2 * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, -std::numbers::pi / 2,
                                                                          std::numbers::pi / 2, 15, 1e-14);
}

// The turning point on the side `sign` whose period is T.
double amplitude_for_period(double T, double sign) {
  auto f = [&](double a) { return period(sign * a) - T; };
  boost::math::tools::eps_tolerance<double> tol(45);
  std::uintmax_t iterations = 200;
  const auto [lo, hi] = boost::math::tools::toms748_solve(f, 1e-3, 3.0, tol, iterations);
  return sign * 0.5 * (lo + hi);
}
}  // namespace

TEST_CASE("energy integral: the oscillator's period tends to 2 pi/w0 at small amplitude" * doctest::test_suite("fast")) {
  // Landau-Lifshitz Sec. 28: omega = w0 + (3 b/(8 w0) - 5 a^2/(12 w0^3)) A^2 (DESIGN.md's check).
  const double A = 0.01, omega = 1 + (3 * 0.5 / 8 - 5 * 0.0625 / 12) * A * A;
  CHECK(period(A) == doctest::Approx(2 * std::numbers::pi / omega).epsilon(1e-7));
}

TEST_CASE("dark continue --parameter C --to 0: klein_gordon's breather at C = 0 is the anti-continuum one" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {});
  DarkConfig c;
  c.step = DarkStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.02;  // above the theta = 0 edge omega = w0 = 1 (hard on-site force: defocusing there)
  c.sites = 20;
  c.points = 40;
  c.ds = 0.02;
  c.parameter = "C";
  c.to = 0.0;
  c.branch_floquet = false;
  validate(c);
  const DarkResult r = run(c);
  REQUIRE_FALSE(failure(r).has_value());
  CHECK(r.branch.stop == sim::dark::BranchStop::window);
  const auto& points = r.branch.points;
  REQUIRE(points.size() >= 3);
  CHECK(points.front().parameter == 0.1);
  CHECK(points.back().parameter == 0.0);
  for (const auto& p : points) CHECK(p.omega_b == 1.02);
  for (std::size_t i = 1; i < points.size(); ++i) CHECK(points[i].parameter < points[i - 1].parameter);
  const double T = 2 * std::numbers::pi / 1.02;
  const double up = amplitude_for_period(T, 1.0), down = amplitude_for_period(T, -1.0);
  INFO("anti-continuum turning points (energy integral): " << std::setprecision(17) << up << ", " << down);
  const Eigen::VectorXd& z = points.back().z0;
  int oscillating = 0;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const double distance = std::min({std::abs(z(i) - up), std::abs(z(i) - down), std::abs(z(i))});
    INFO("site " << i << ": u(0) = " << std::setprecision(17) << z(i));
    CHECK(distance < 1e-8);  // the shooting converges to max|F| <= 1e-11
    if (std::abs(z(i)) > 1e-3) ++oscillating;
  }
  CHECK(oscillating >= z.size() / 2);  // the background: every site but the dips
}
