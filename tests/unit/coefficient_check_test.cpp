// The checked evaluation of a loaded model's coefficients (lrchain/coefficient_check.hpp): regular
// points of the shipped models keep their bits, the check never refuses them, and omega's
// derivatives from det M alone agree with the resonant chain's own closed-form c and omega''.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

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

TEST_CASE("the check refuses no regular point of the shipped models") {
  // 199 wavenumbers per branch in (-pi, pi]: every evaluation direct (no limit, no refusal) unless a
  // non-resonance condition is violated there.
  for (const ModelDefinition& definition : shipped_models()) {
    const Model model(std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), &definition));
    for (Index branch = 0; branch < static_cast<Index>(definition.branch_names.size()); ++branch)
      for (int k = -99; k <= 100; ++k) {
        const double theta = std::numbers::pi * k / 100.0;
        NlsCoefficients c;
        if (!coefficients_at(definition, model.inputs().data(), branch, theta, c)) continue;  // no frequency
        INFO(definition.name << " branch " << branch << " theta " << theta);
        CHECK(c.evaluation == CoefficientEvaluation::direct);
      }
  }
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
      CHECK(d.curvature_error <= 1e-6);
      CHECK(agrees_with_derivatives(c, d));
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
  c.group_velocity += 1e-4;
  CHECK_FALSE(agrees_with_derivatives(c, d));
  c.group_velocity -= 1e-4;
  c.curvature += 1e-3;
  CHECK_FALSE(agrees_with_derivatives(c, d));
}
