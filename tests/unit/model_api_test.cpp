// The loaded-model API (lrchain/model.hpp): shipped models, parameter checks, branches, and the
// generic evaluation path against the resonant chain's specialised one and textbook dispersion.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/regime/model_regime.hpp"

using namespace lrchain;

namespace {
double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }
}  // namespace

TEST_CASE("the seven shipped models are loaded with their parameters and branches") {
  for (const char* name : {"resonant_chain", "homogeneous_chain", "fput", "klein_gordon", "newtons_cradle",
                           "diatomic_chain", "resonant_chain_polynomial"}) {
    INFO(name);
    const ModelDefinition* d = find_shipped_model(name);
    REQUIRE(d != nullptr);
    CHECK(!d->branch_names.empty());
    CHECK(d->degree == int(d->branch_names.size()));
  }
  const Model rc = shipped_model("resonant_chain");
  CHECK(rc.parameter("alpha") == 1.5);
  CHECK(rc.parameter("rho") == doctest::Approx(1.0 / 3.0).epsilon(1e-16));
  CHECK(rc.definition().branch_names == std::vector<std::string>{"acoustic", "optical"});
  CHECK(!shipped_model("klein_gordon").definition().mean_flow);
}

TEST_CASE("unknown parameters, values outside the declared range and unknown branches are rejected") {
  CHECK_THROWS_AS(shipped_model("fput", {{"c", 1.0}}), InvalidParameter);
  CHECK_THROWS_AS(shipped_model("resonant_chain", {{"rho", -1.0}}), InvalidParameter);
  CHECK_THROWS_AS(shipped_model("resonant_chain", {{"alpha", 1.0}}), InvalidParameter);  // range (1, inf)
  CHECK_THROWS_AS(shipped_model("no_such_model"), InputError);
  CHECK_THROWS_AS(shipped_model("klein_gordon").branch("optical"), InvalidParameter);
  CHECK_THROWS_AS(coefficients(shipped_model("fput"), 0, 0.0), InvalidParameter);  // acoustic theta = 0
  // Branch indices are signed (lrchain::Index): the resonant chain has branches 0 and 1 only.
  const Model rc = shipped_model("resonant_chain");
  CHECK(rc.branch("optical") == 1);
  CHECK_THROWS_AS(coefficients(rc, -1, 1.0), InvalidParameter);
  CHECK_THROWS_AS(coefficients(rc, 2, 1.0), InvalidParameter);
  CHECK_THROWS_AS(second_order_terms(rc, -1, 1.0), InvalidParameter);
  CHECK_THROWS_AS(regime::regime_functions(rc, -1), InvalidParameter);
}

TEST_CASE("the generic path for the resonant chain agrees with the specialised coefficients()") {
  // Both evaluate the same derived expressions (the specialised one through mu = rho omega^2 - kappa),
  // so they agree to rounding; 1e-10 leaves room for the omega-form's cancellation.
  for (const Params p : {Params{}, Params{1.5, 0.3, 2.0, 0.1}, Params{2.5, 1.0, 0.5, 3.0}}) {
    const Model m = shipped_model("resonant_chain", {{"alpha", p.alpha}, {"delta0", p.delta0}, {"kappa", p.kappa}, {"rho", p.rho}});
    for (double theta : {0.3, std::numbers::pi / 2, 2.5, std::numbers::pi}) {
      for (const auto& [branch, b] : {std::pair{"acoustic", Branch::acoustic}, std::pair{"optical", Branch::optical}}) {
        const NlsCoefficients generic = coefficients(m, m.branch(branch), theta);
        const NlsCoefficients specialised = coefficients(p, b, theta);
        INFO(branch << " theta=" << theta << " rho=" << p.rho);
        CHECK(relative(generic.omega, specialised.omega) < 1e-13);
        CHECK(relative(generic.curvature, specialised.curvature) < 1e-10);
        CHECK(relative(generic.h_tilde, specialised.h_tilde) < 1e-10);
        CHECK(relative(generic.lambda, specialised.lambda) < 1e-10);
        CHECK(generic.regime == specialised.regime);
      }
    }
  }
}

TEST_CASE("Klein-Gordon: omega^2 = w0^2 + 4 C sin^2(theta/2) and c = omega'(theta), no lambda") {
  // The textbook linear dispersion of the discrete Klein-Gordon chain; c checked by a central difference.
  const Model m = shipped_model("klein_gordon", {{"C", 0.3}, {"w0", 1.2}});
  const double theta = 1.1, step = 1e-5;
  const auto omega = [](double t) { return std::sqrt(1.44 + 4 * 0.3 * std::pow(std::sin(t / 2), 2)); };
  const NlsCoefficients c = coefficients(m, 0, theta);
  CHECK(relative(c.omega, omega(theta)) < 1e-15);
  CHECK(relative(c.group_velocity, (omega(theta + step) - omega(theta - step)) / (2 * step)) < 1e-9);
  CHECK(std::isnan(c.lambda));
  CHECK(c.beta == 0.0);
}

TEST_CASE("omega_squared_roots: closed forms and Durand-Kerner give known roots") {
  double roots[kMaxModelDegree];
  const double quadratic[] = {2.0, -3.0, 1.0};  // (w-1)(w-2)
  REQUIRE(omega_squared_roots(quadratic, 2, roots));
  CHECK(roots[0] == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(roots[1] == doctest::Approx(2.0).epsilon(1e-15));
  const double cubic[] = {-6.0, 11.0, -6.0, 1.0};  // (w-1)(w-2)(w-3)
  REQUIRE(omega_squared_roots(cubic, 3, roots));
  CHECK(roots[0] == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(roots[1] == doctest::Approx(2.0).epsilon(1e-12));
  CHECK(roots[2] == doctest::Approx(3.0).epsilon(1e-12));
  const double complex_pair[] = {1.0, 0.0, 1.0};  // w^2 + 1
  CHECK(!omega_squared_roots(complex_pair, 2, roots));
}
