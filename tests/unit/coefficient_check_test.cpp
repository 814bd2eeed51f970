// The checked evaluation of a loaded model's coefficients (lrchain/coefficient_check.hpp): regular
// points of the shipped models keep their bits, the check never refuses them, and omega's
// derivatives from det M alone agree with the resonant chain's own closed-form c and omega''.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/coefficient_check.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/model.hpp"

using namespace lrchain;

TEST_CASE("a regular point of a shipped model gives the same bits as before the check") {
  // Expected: `lrchain coeffs --json` of main's build at 4f35e58 (/work/baseline-bin), shortest
  // round-trip decimal of each double.
  const Model diatomic = shipped_model("diatomic_chain");
  const NlsCoefficients d = coefficients(diatomic, diatomic.branch("optical"), 1.0471975511965976);
  CHECK(d.evaluation == CoefficientEvaluation::direct);
  CHECK(d.omega == 1.680141558182612);
  CHECK(d.group_velocity == -0.09741049310989422);
  CHECK(d.curvature == -0.08599044244414768);
  CHECK(d.gamma == 0.41007392094382633);
  CHECK(d.beta == 0.47253981323885963);
  CHECK(d.h == -1.0231109444450879);
  CHECK(d.lambda == 4.887577052329263);
  CHECK(d.h_tilde == -3.332685691943294);
  const Model kg = shipped_model("klein_gordon");
  const NlsCoefficients k = coefficients_from_evaluators(kg, kg.branch("branch0"), 0.7);
  CHECK(k.evaluation == CoefficientEvaluation::direct);
  CHECK(k.omega == 1.0232456022593512);
  CHECK(k.group_velocity == 0.06295826591536213);
  CHECK(k.curvature == 0.07087299014161647);
  CHECK(k.gamma == 0.9772824801709147);
  CHECK(k.h == 0.6310125812715095);
  CHECK(k.h_tilde == 0.6310125812715095);
}

namespace {

// The shipped model at its defaults and with each parameter scaled by 0.7 and by 1.5 (where the
// range allows).
std::vector<Model> parameter_sets(const ModelDefinition& definition) {
  const std::shared_ptr<const ModelDefinition> shared(std::shared_ptr<const ModelDefinition>(), &definition);
  std::vector<Model> models{Model(shared)};
  for (const ModelParameter& p : definition.parameters)
    for (const double factor : {0.7, 1.5})
      if (p.contains(factor * p.default_value)) models.emplace_back(shared, std::vector<std::pair<std::string, double>>{{p.name, factor * p.default_value}});
  return models;
}

// Where h has a pole although c and omega'' are regular: the diatomic chain's acoustic branch at
// theta = pi, where only the second bead moves (Bloch vector (0, 1): omega^2 = 2 K2 / m, the
// textbook dispersion omega^2 = K2 (1 + 1/m) - K2 sqrt((1 + 1/m)^2 - 4 sin^2(theta/2) / m)), so
// the first field, whose amplitude A the NLS uses, has none: h ~ (pi - theta)^-2 (main printed
// h = -3.0e28 there).
bool first_field_at_rest(const ModelDefinition& definition, Index branch, double theta) {
  return definition.name == "diatomic_chain" && definition.branch_names[std::size_t(branch)] == "acoustic" &&
         theta == std::numbers::pi;
}

}  // namespace

TEST_CASE("the check refuses no regular point of the shipped models, theta = 0 and pi included") {
  // 200 wavenumbers per branch in (-pi, pi] (0 and pi among them) plus 1e-3 and pi - 1e-3, every
  // shipped model at its defaults and with each parameter scaled by 0.7 and 1.5: never refused, in
  // the full check (coefficients_from_evaluators) and in the hot path's derivative check (coefficients_at),
  // and c, omega'' equal to the finite differences of omega from det M (branch_derivatives).
  std::vector<double> thetas{1e-3, std::numbers::pi - 1e-3};
  for (int k = -99; k <= 100; ++k) thetas.push_back(std::numbers::pi * k / 100.0);
  int limits = 0;
  for (const ModelDefinition& definition : shipped_models())
    for (const Model& model : parameter_sets(definition))
      for (Index branch = 0; branch < static_cast<Index>(definition.branch_names.size()); ++branch)
        for (const double theta : thetas) {
          NlsCoefficients hot;
          if (!coefficients_at(definition, model.inputs().data(), branch, theta, hot)) continue;  // no frequency
          INFO(definition.name << " branch " << definition.branch_names[std::size_t(branch)] << " theta " << theta);
          const NlsCoefficients c = coefficients_from_evaluators(model, branch, theta);
          REQUIRE(c.evaluation != CoefficientEvaluation::refused);
          REQUIRE(hot.evaluation != CoefficientEvaluation::refused);
          BranchDerivatives d;
          REQUIRE(branch_derivatives(definition, model.inputs().data(), branch, theta, c.omega, d));
          CHECK(agrees_with_derivatives(c, d));
          CHECK(agrees_with_derivatives(hot, d));
          if (c.evaluation == CoefficientEvaluation::limit) ++limits;
          if (first_field_at_rest(definition, branch, theta)) {
            CHECK(c.regime == Regime::singular);
            CHECK(std::isnan(c.h));
            CHECK(!singular_reason(c).empty());
          } else if (c.regime != Regime::singular) {
            CHECK(std::isfinite(c.h));
            CHECK(std::isfinite(c.h_tilde));
          }
        }
  // The limit is taken only where the emitted expressions are 0/0: the diatomic chain at theta = pi
  // (both branches, 7 parameter sets each); every other point is direct.
  CHECK(limits == 14);
}

TEST_CASE("the diatomic chain at theta = pi: c, omega'' by their limit equal the textbook dispersion's") {
  // omega^2 = K2 (1 + 1/m) -+ K2 sqrt((1 + 1/m)^2 - 4 sin^2(theta/2) / m) (docs/models.md), K2 =
  // alpha delta0^(alpha - 1) = 1, m = 2: at pi, omega^2 = 1 and 2, and omega'' = -+ K2 / (2 omega
  // m sqrt((1 + 1/m)^2 - 4/m)) = -0.5 and 1/(2 sqrt 2) (expanding the square root at pi). The
  // emitted expressions are 0/0 there (main printed omega'' = -0.4615 and 0.5794, h = -3e28, 7e31).
  const Model diatomic = shipped_model("diatomic_chain");
  const NlsCoefficients acoustic = coefficients(diatomic, diatomic.branch("acoustic"), std::numbers::pi);
  const NlsCoefficients optical = coefficients(diatomic, diatomic.branch("optical"), std::numbers::pi);
  CHECK(acoustic.evaluation == CoefficientEvaluation::limit);
  CHECK(optical.evaluation == CoefficientEvaluation::limit);
  CHECK(std::abs(acoustic.group_velocity) <= 1e-12);
  CHECK(std::abs(optical.group_velocity) <= 1e-12);
  CHECK(std::abs(acoustic.curvature + 0.5) <= 1e-8);
  CHECK(std::abs(optical.curvature - 1.0 / (2.0 * std::sqrt(2.0))) <= 1e-8);
  // h of the optical branch: the limit of its regular values nearby (at pi - 1e-3, error ~ h'' 1e-6 / 2).
  NlsCoefficients near;
  REQUIRE(coefficients_at(diatomic.definition(), diatomic.inputs().data(), diatomic.branch("optical"),
                          std::numbers::pi - 1e-3, near));
  CHECK(near.evaluation == CoefficientEvaluation::direct);
  CHECK(std::abs(optical.h - near.h) <= 1e-5 * std::abs(near.h));
  CHECK(optical.regime == near.regime);
  // The acoustic branch's h has a true pole there (first_field_at_rest): null with the reason.
  CHECK(acoustic.regime == Regime::singular);
  CHECK(std::isnan(acoustic.h));
  CHECK(singular_reason(acoustic).find("pole") != std::string_view::npos);
}

TEST_CASE("omega's derivatives from det M agree with the resonant chain's closed-form c and omega''") {
  // The chain's fast path (coefficients_kernel.hpp: c, omega'' from the generated closed forms) is
  // independent of branch_derivatives (differences of the roots of the model's det M evaluator).
  const Params p{};
  const Model chain = resonant_chain_model(p);
  for (const char* name : {"optical", "acoustic"}) {
    const Index branch = chain.branch(name);
    for (const double theta : {0.05, 0.4, 1.0, 2.0, 3.0, std::numbers::pi}) {
      INFO(name << " theta " << theta);
      const NlsCoefficients c = coefficients(chain, branch, theta);
      BranchDerivatives d;
      REQUIRE(branch_derivatives(chain.definition(), chain.inputs().data(), branch, theta, c.omega, d));
      CHECK(std::abs(d.group_velocity - c.group_velocity) <= 1e-9);
      CHECK(std::abs(d.curvature - c.curvature) <= 1e-7);
      // The error estimate bounds the actual error (omega'' closed form as the reference); it grows
      // as 1/omega on the acoustic branch near theta = 0 (1.3e-5 at theta = 0.05).
      CHECK(std::abs(d.curvature - c.curvature) <= d.curvature_error);
      CHECK(agrees_with_derivatives(c, d));
      // The hot path's derivatives (det M at fixed omega^2, implicit function theorem): as close.
      BranchDerivatives implicit;
      REQUIRE(implicit_derivatives(chain.definition(), chain.inputs().data(), theta, c.omega, implicit));
      // (central differences at step 1e-4: truncation ~ step^2 times c's third derivative / 6, 1.4e-9 measured)
      CHECK(std::abs(implicit.group_velocity - c.group_velocity) <= 3e-9);
      CHECK(std::abs(implicit.group_velocity - c.group_velocity) <= implicit.group_velocity_error);
      CHECK(std::abs(implicit.curvature - c.curvature) <= 1e-7);
      CHECK(std::abs(implicit.curvature - c.curvature) <= implicit.curvature_error);
      CHECK(agrees_with_derivatives(c, implicit));
    }
  }
}

TEST_CASE("a wrong c or omega'' fails the check") {
  // The check is not vacuous: the resonant chain's coefficients with c off by 1e-4 or omega'' off
  // by 1e-3 disagree with omega's derivatives.
  const Model chain = resonant_chain_model(Params{});
  const Index branch = chain.branch("optical");
  NlsCoefficients c = coefficients(chain, branch, 1.0);
  BranchDerivatives d;
  REQUIRE(branch_derivatives(chain.definition(), chain.inputs().data(), branch, 1.0, c.omega, d));
  BranchDerivatives implicit;
  REQUIRE(implicit_derivatives(chain.definition(), chain.inputs().data(), 1.0, c.omega, implicit));
  c.group_velocity += 1e-4;
  CHECK_FALSE(agrees_with_derivatives(c, d));
  CHECK_FALSE(agrees_with_derivatives(c, implicit));
  c.group_velocity -= 1e-4;
  c.curvature += 1e-3;
  CHECK_FALSE(agrees_with_derivatives(c, d));
  CHECK_FALSE(agrees_with_derivatives(c, implicit));
}

namespace {

// fput's emitted NLS evaluator with h spoiled by a term that oscillates on a 1e-9 scale in theta:
// rounding noise of a 0/0 made permanent, so that no limit from nearby wavenumbers converges.
void (*fput_nls)(double, double, double, const double*, double*) = nullptr;
void noisy_fput_nls(double D1, double sigma, double omega, const double* q, double* out) {
  fput_nls(D1, sigma, omega, q, out);
  out[out_h] += 1e-3 * std::sin(1e9 * D1);
  out[out_h_tilde] = out[out_h] - out[out_lambda] * out[out_beta];
}
// The same with c spoiled too (as a 0/0 of c's expression does).
void noisy_c_fput_nls(double D1, double sigma, double omega, const double* q, double* out) {
  noisy_fput_nls(D1, sigma, omega, q, out);
  out[out_group_velocity] += 1e-3 * std::sin(1e9 * D1);
}

}  // namespace

TEST_CASE("coefficients whose expressions are noise at and around a wavenumber are refused, with the reason") {
  ModelDefinition noisy = *find_shipped_model("fput");
  fput_nls = noisy.evaluators.nls;
  REQUIRE(bool(fput_nls));
  noisy.evaluators.nls = noisy_fput_nls;
  const Model model(std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), &noisy));
  const NlsCoefficients c = coefficients_from_evaluators(model, 0, 1.0);
  CHECK(c.evaluation == CoefficientEvaluation::refused);
  CHECK(c.regime == Regime::singular);
  CHECK(std::isnan(c.h));
  CHECK(std::isnan(c.group_velocity));
  CHECK(singular_reason(c).find("removable singularity") != std::string_view::npos);
  // The hot path sees noise in h (h_tilde two ways disagree) and in c (c against det M's derivatives).
  NlsCoefficients hot;
  REQUIRE(coefficients_at(noisy, model.inputs().data(), 0, 1.0, hot));
  CHECK(hot.evaluation == CoefficientEvaluation::refused);
  noisy.evaluators.nls = noisy_c_fput_nls;
  REQUIRE(coefficients_at(noisy, model.inputs().data(), 0, 1.0, hot));
  CHECK(hot.evaluation == CoefficientEvaluation::refused);
  CHECK(std::isnan(hot.h));
  // The same point of the unspoiled fput is direct.
  const Model fput = shipped_model("fput");
  CHECK(coefficients_from_evaluators(fput, 0, 1.0).evaluation == CoefficientEvaluation::direct);
}
