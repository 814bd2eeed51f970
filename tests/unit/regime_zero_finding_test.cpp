// Unit tests of the generic root-finding and curve-tracing machinery behind the regime maps,
// on analytic functions whose zeros are known in closed form.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/regime/zero_curve_tracing.hpp"
#include "lrchain/regime/zero_finding.hpp"

using namespace lrchain;
using namespace lrchain::regime;
constexpr double pi = std::numbers::pi;

TEST_CASE("find_zeros: zeros of sin on [0.5, 10] are pi, 2pi, 3pi to 1e-12") {
  const auto z = find_zeros([](double x) { return std::sin(x); }, 0.5, 10.0, {101, 1e-12});
  REQUIRE(z.size() == 3);
  for (int k = 0; k < 3; ++k) CHECK(std::abs(z[k] - (k + 1) * pi) < 1e-12);
}

TEST_CASE("find_zeros: a pair of zeros inside one sample cell is found by the Brent probe") {
  // (x - 1)(x - 1.0002): both zeros lie between the samples 0.8, 1.0 (sample exactly at 1.0 is
  // avoided by using 0.95 + 0.2 k), no sample sees a sign change.
  const auto f = [](double x) { return (x - 1.0) * (x - 1.0002); };
  const auto z = find_zeros(f, 0.15, 2.15, {11, 1e-13});
  REQUIRE(z.size() == 2);
  CHECK(std::abs(z[0] - 1.0) < 1e-12);
  CHECK(std::abs(z[1] - 1.0002) < 1e-12);
}

TEST_CASE("regime_structure: analytic factors give the expected intervals and causes") {
  // curvature = cos th - cos 1.5, numerator = -1, nonresonance1 = th - 2.5, nonresonance2 = 1:
  // product < 0 (focusing) exactly on (1.5, 2.5).
  const RegimeFunctions f = [](double th) {
    return RegimeSample{std::cos(th) - std::cos(1.5), -1.0, th - 2.5, 1.0};
  };
  const auto s = regime_structure(f, {256, 1e-12});
  REQUIRE(s.intervals.size() == 1);
  CHECK(std::abs(s.intervals[0].lo - 1.5) < 1e-12);
  CHECK(std::abs(s.intervals[0].hi - 2.5) < 1e-12);
  CHECK(s.intervals[0].lo_cause == BoundaryCause::curvature_zero);
  CHECK(s.intervals[0].hi_cause == BoundaryCause::nonresonance1);

  // Flip the numerator's sign: focusing on (0, 1.5) and (2.5, pi], ends labelled band_edge.
  const RegimeFunctions g = [](double th) {
    return RegimeSample{std::cos(th) - std::cos(1.5), 1.0, th - 2.5, 1.0};
  };
  const auto t = regime_structure(g, {256, 1e-12});
  REQUIRE(t.intervals.size() == 2);
  CHECK(t.intervals[0].lo == 0.0);
  CHECK(t.intervals[0].lo_cause == BoundaryCause::band_edge);
  CHECK(t.intervals[1].hi == doctest::Approx(pi));
  CHECK(t.intervals[1].hi_cause == BoundaryCause::band_edge);
  CHECK(t.intervals[1].lo_cause == BoundaryCause::nonresonance1);
}

TEST_CASE("regime_structure: a zero shared by two factors is no boundary") {
  // numerator and nonresonance2 both vanish at 2.0: the product -(th-2)^2 keeps its sign, so
  // the whole band (0, pi] is one focusing interval.
  const RegimeFunctions f = [](double th) {
    return RegimeSample{-1.0, th - 2.0, 1.0, th - 2.0};
  };
  const auto s = regime_structure(f, {256, 1e-12});
  CHECK(s.roots.size() == 2);
  REQUIRE(s.intervals.size() == 1);
  CHECK(s.intervals[0].lo == 0.0);
  CHECK(s.intervals[0].hi == doctest::Approx(pi));
}

TEST_CASE("trace_zero_set: a circle is one closed polyline on the circle") {
  const auto F = [](double x, double y) { return x * x + y * y - 0.25; };
  const auto lines = trace_zero_set(F, {-1, 1, -1, 1});
  REQUIRE(lines.size() == 1);
  const auto& c = lines[0];
  CHECK(c.size() > 100);
  double worst = 0;
  for (const auto& p : c) worst = std::max(worst, std::abs(std::hypot(p.x, p.y) - 0.5));
  CHECK(worst < 1e-10);
  CHECK(std::hypot(c.front().x - c.back().x, c.front().y - c.back().y) < 1e-12);  // closed
}

TEST_CASE("trace_zero_set: two disjoint lines crossing the box are two polylines edge to edge") {
  // (y - x/2)(y - x/2 - 0.5) on [0,1]^2 in a stretched box.
  const auto F = [](double x, double y) { return (y - x / 2) * (y - x / 2 - 0.5); };
  const auto lines = trace_zero_set(F, {0, 1, -0.2, 1});
  REQUIRE(lines.size() == 2);
  for (const auto& l : lines) {
    const double xmin = std::min(l.front().x, l.back().x), xmax = std::max(l.front().x, l.back().x);
    CHECK(xmin <= 0.0);
    CHECK(xmax >= 1.0);
  }
}

TEST_CASE("theta_of_omega inverts the dispersion relation on both branches (eq:M, eq:disp1d)") {
  for (double rho : {0.32, 1.0 / 3.0, 3.0, 17.8})
    for (double delta0 : {0.01, 4.0 / 9.0, 1.0})
      for (Branch b : {Branch::optical, Branch::acoustic}) {
        const Params p{1.5, delta0, 1.0, rho};
        const double K2 = taylor_coefficients(p).K2;
        for (double th : {0.1, 1.0, 2.0, 3.0}) {
          const double w = dispersion_omega(p, b, th);
          CHECK(theta_of_omega(K2, p.kappa, p.rho, w) == doctest::Approx(th).epsilon(1e-9));
        }
        const auto band = frequency_band(p, b);
        CHECK(band.hi == doctest::Approx(dispersion_omega(p, b, pi)));
      }
}
