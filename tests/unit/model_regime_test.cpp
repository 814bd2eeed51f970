// Regimes of a loaded model (lrchain/regime/model_regime.hpp): the resonant chain through the
// generic evaluators against its specialised Params path, and the Klein-Gordon chain against the
// sign of omega'' times the nonlinear frequency shift computed by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "lrchain/regime/regime_map.hpp"

using namespace lrchain;
using namespace lrchain::regime;

namespace {
constexpr double pi = std::numbers::pi;

Model resonant(double rho, double delta0 = 4.0 / 9.0) {
  return shipped_model("resonant_chain", {{"alpha", 1.5}, {"delta0", delta0}, {"kappa", 1.0}, {"rho", rho}});
}
}  // namespace

TEST_CASE("the resonant chain through the generic model path has the Params path's intervals") {
  // The Params path is the paper's specialised evaluator (lib/src/coefficients.cpp); both find the
  // ends by TOMS 748 to 1e-12 in theta, so the same boundaries must agree to that tolerance.
  double worst = 0;
  for (double rho : {1.0 / 3.0, 1.0, 3.0, 17.8, 25.0, 0.32, 0.1})
    for (Branch b : {Branch::optical, Branch::acoustic}) {
      INFO("rho = " << rho << ", branch " << to_string(b));
      const Model m = resonant(rho);
      const auto params = regime_structure(regime_functions(Params{1.5, 4.0 / 9.0, 1.0, rho}, b));
      const auto generic = regime_structure(regime_functions(m, m.branch(to_string(b))));
      REQUIRE(generic.roots.size() == params.roots.size());
      for (std::size_t k = 0; k < params.roots.size(); ++k) {
        CHECK(generic.roots[k].cause == params.roots[k].cause);
        worst = std::max(worst, std::abs(generic.roots[k].theta - params.roots[k].theta));
      }
      REQUIRE(generic.intervals.size() == params.intervals.size());
      for (std::size_t k = 0; k < params.intervals.size(); ++k) {
        CHECK(generic.intervals[k].lo_cause == params.intervals[k].lo_cause);
        CHECK(generic.intervals[k].hi_cause == params.intervals[k].hi_cause);
        CHECK(std::abs(generic.intervals[k].lo - params.intervals[k].lo) <= 2e-12);
        CHECK(std::abs(generic.intervals[k].hi - params.intervals[k].hi) <= 2e-12);
      }
    }
  MESSAGE("largest difference of a boundary theta, generic vs Params path: " << worst);
}

TEST_CASE("the resonant chain's (rho, theta) map through the generic path equals theta_rho_map") {
  const Params base{};  // the paper's alpha = 3/2, delta0 = 4/9, kappa = 1
  const Model m = resonant(1.0 / 3.0);
  for (Branch b : {Branch::optical, Branch::acoustic}) {
    const GridAxis rho{0.01, 30.0, 181}, theta{pi / 157, pi, 157};
    const RegimeMap params = theta_rho_map(base, b, rho, theta);
    const ModelRegimeMap generic = parameter_theta_map(m, m.branch(to_string(b)), "rho", rho, theta);
    int differ = 0;
    for (std::size_t k = 0; k < params.values.size(); ++k) differ += params.values[k] != generic.values[k];
    INFO("branch " << to_string(b));
    CHECK(differ == 0);
  }
}

TEST_CASE("Klein-Gordon: focusing where omega'' and the Landau-Lifshitz frequency shift have opposite signs") {
  // u'' = C (u[n+1] - 2u[n] + u[n-1]) - (w0^2 u + a u^2 + b u^3), u = A e^{i(theta n - omega t)} + c.c.
  // with R = |A|. By hand (harmonic balance, as Landau & Lifshitz, Mechanics, Sec. 28): a u^2 drives
  // a mean u0 = -2 a R^2 / w0^2 and a second harmonic u2 = -2 a R^2 / D2 with
  // D2 = w0^2 + 4 C sin^2(theta) - 4 omega^2 = -3 w0^2 - 16 C sin^4(theta/2) (never 0: no resonance);
  // feeding them back gives omega^2 = omega_L^2 + N R^2 with N = 3b - 4a^2/w0^2 - 2a^2/D2 (at C = 0
  // and X = 2R this is L&L's shift (3b/(8 w0) - 5a^2/(12 w0^3)) X^2). Lighthill's criterion
  // (Whitham, Linear and Nonlinear Waves, Sec. 15.4): modulational instability iff omega'' N < 0,
  // and omega'' has the sign of w0^2 cos(theta) - C (1 - cos(theta))^2.
  // With C = 1/2, w0 = 1, a = 1, b = 6/5: omega'' = 0 at cos(theta) = 2 - sqrt(3) and N = 0 where
  // 3 + 8 sin^4(theta/2) = 5, i.e. theta = pi/2, so the only focusing interval is
  // (arccos(2 - sqrt 3), pi/2).
  const double C = 0.5, w0 = 1.0, a = 1.0, b = 1.2;
  const Model m = shipped_model("klein_gordon", {{"C", C}, {"w0", w0}, {"a", a}, {"b", b}});
  const auto s = regime_structure(regime_functions(m, 0));
  REQUIRE(s.intervals.size() == 1);
  CHECK(std::abs(s.intervals[0].lo - std::acos(2.0 - std::sqrt(3.0))) < 1e-11);
  CHECK(std::abs(s.intervals[0].hi - pi / 2) < 1e-11);
  CHECK(s.intervals[0].lo_cause == BoundaryCause::curvature_zero);
  CHECK(s.intervals[0].hi_cause == BoundaryCause::h_tilde_zero);
  // The coefficient itself: h = N / (2 omega) (gamma = 1/omega; the scratch-model test in
  // cli_user_model_test.cpp checks the a = 0 case, h = 3b/(2 omega)).
  for (double theta : {0.3, 1.0, 1.4, 2.0, 2.9}) {
    const NlsCoefficients c = coefficients(m, 0, theta);
    const double s2 = std::pow(std::sin(theta / 2), 2);
    const double D2 = -3 * w0 * w0 - 16 * C * s2 * s2;
    const double N = 3 * b - 4 * a * a / (w0 * w0) - 2 * a * a / D2;
    INFO("theta = " << theta);
    CHECK(std::abs(c.omega - std::sqrt(w0 * w0 + 4 * C * s2)) < 1e-15);
    CHECK(std::abs(c.h_tilde - N / (2 * c.omega)) < 1e-13 * std::abs(N / c.omega) + 1e-15);
    const double curvature_sign = w0 * w0 * std::cos(theta) - C * std::pow(1 - std::cos(theta), 2);
    CHECK((c.regime == Regime::focusing) == (curvature_sign * N < 0));
  }
}

TEST_CASE("maps and scans over a model parameter check the axis name and range") {
  const Model kg = shipped_model("klein_gordon");
  const GridAxis theta{0.01, pi, 20};
  CHECK_THROWS_AS(parameter_theta_map(kg, 0, "rho", {0.1, 1.0, 10}, theta), InvalidParameter);
  CHECK_THROWS_AS(parameter_theta_map(kg, 0, "w0", {-1.0, 1.0, 10}, theta), InvalidParameter);  // w0 in (0, inf)
  CHECK_THROWS_AS(parameter_theta_map(kg, 1, "w0", {0.5, 1.0, 10}, theta), InvalidParameter);  // one branch
  const ModelRegimeMap map = parameter_theta_map(kg, 0, "C", {0.0, 1.0, 11}, theta);
  CHECK(map.values.size() == 220u);
  // FPU acoustic branch at theta = 0 has no positive frequency: outside the band.
  const Model fput = shipped_model("fput");
  const ModelRegimeMap f = parameter_theta_map(fput, 0, "b", {0.0, 1.0, 3}, {0.0, pi, 5});
  CHECK(f.at(0, 0) == PixelRegime::outside);
  CHECK(f.at(0, 2) != PixelRegime::outside);
}

TEST_CASE("regime events along a Klein-Gordon parameter: N = 0 enters through theta = pi") {
  // From the test above: at theta = pi, N = 3b - 4a^2 + 2a^2/(3 + 16 C) (w0 = 1), so with C = 1/2,
  // a = 1 the zero of N enters through theta = pi at b = (4 - 2/11)/3 = 14/11.
  const Model m = shipped_model("klein_gordon", {{"C", 0.5}, {"w0", 1.0}, {"a", 1.0}, {"b", 1.2}});
  const auto events = regime_events(m, 0, "b", {1.15, 1.5, 40});
  bool found = false;
  for (const auto& e : events)
    if (e.kind == EventKind::band_edge_entry && std::abs(e.value - 14.0 / 11.0) < 1e-9) found = true;
  CHECK(found);
}
