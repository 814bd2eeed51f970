// The emitted double-precision evaluators (lib, via coefficients_unchecked) against 50-digit CLN
// evaluation of the same symbolic expressions produced by the derivation (issue 2, section 3).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "lrchain/coefficients.hpp"
#include "lrchain/derivation/evaluate.hpp"
#include "lrchain/derivation/generate.hpp"

using namespace lrchain;
using namespace lrchain::derivation;

TEST_CASE("generated evaluators agree with 50-digit evaluation at 5000+ random points (rel. err <= 1e-11)") {
  const Derivation d = derive_all();
  const DerivedCoefficients& dc = d.resonant_coefficients;
  const Symbols& s = d.symbols;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int compared = 0, excluded = 0;
  double worst = 0.0;
  const char* worst_name = "";
  const int points = 5200;
  for (int i = 0; i < points; ++i) {
    // Ranges of the issue: theta in (0, pi], rho in [0.01, 100], delta0 in [1e-3, 1],
    // kappa in [0.1, 10], alpha in [1.1, 3]; log-uniform for the scale parameters.
    Params p{1.1 + 1.9 * U(rng), std::pow(10.0, -3.0 + 3.0 * U(rng)), std::pow(10.0, -1.0 + 2.0 * U(rng)),
             std::pow(10.0, -2.0 + 4.0 * U(rng))};
    const double theta = M_PI * (1.0 - U(rng));  // (0, pi]
    const Branch b = (i % 2 == 0) ? Branch::optical : Branch::acoustic;
    const NlsCoefficients got = coefficients_unchecked(p, taylor_coefficients(p), b, theta);
    const PrecisePoint ref(dc, s, {p.alpha, p.delta0, p.kappa, p.rho, theta, b == Branch::optical});
    // Exclude points within 1e-6 (relative) of a non-resonance violation.
    const double n1 = ref.value(dc.nonresonance1).to_double(), n2 = ref.value(explicit_form(dc, s, dc.nonresonance2)).to_double();
    const double w2 = std::pow(ref.value(s.omega).to_double(), 2), K2 = ref.value(s.K2).to_double();
    const double sig = std::sin(theta), cc = ref.value(dc.group_velocity).to_double();
    const double scale1 = (4 * w2 + 4 * K2 * sig * sig + p.kappa) * (p.kappa + 4 * w2 * p.rho) + p.kappa * p.kappa;
    const double scale2 = cc * cc * (1 + p.rho) + K2;
    if (std::abs(n1) < 1e-6 * scale1 || std::abs(n2) < 1e-6 * scale2) {
      ++excluded;
      continue;
    }
    const std::pair<const char*, std::pair<double, GiNaC::ex>> fields[] = {
        {"omega", {got.omega, s.omega}},
        {"group_velocity", {got.group_velocity, dc.group_velocity}},
        {"gamma", {got.gamma, dc.gamma}},
        {"curvature", {got.curvature, dc.curvature}},
        {"beta", {got.beta, dc.beta}},
        {"h", {got.h, dc.h}},
        {"lambda", {got.lambda, dc.lambda}},
        {"h_tilde", {got.h_tilde, dc.h_tilde}},
        {"nonresonance1", {got.nonresonance1, dc.nonresonance1}},
        {"nonresonance2", {got.nonresonance2, explicit_form(dc, s, dc.nonresonance2)}},
        {"h_tilde_numerator", {got.h_tilde_numerator, dc.h_tilde_numerator}},
    };
    for (const auto& [name, pair] : fields) {
      const double exact = ref.value(pair.second).to_double();
      const double rel = std::abs(pair.first - exact) / std::abs(exact);
      if (exact == 0.0) continue;
      if (rel > worst) {
        worst = rel;
        worst_name = name;
      }
      if (rel > 1e-11)
        std::printf("point %d (%s, theta=%.17g, alpha=%.6g delta0=%.6g kappa=%.6g rho=%.6g): %s rel err %.3g\n", i,
                    b == Branch::optical ? "optical" : "acoustic", theta, p.alpha, p.delta0, p.kappa, p.rho, name, rel);
    }
    ++compared;
  }
  std::printf("generated vs 50 digits: %d points compared, %d excluded near non-resonance, max rel err %.3g (%s)\n",
              compared, excluded, worst, worst_name);
  CHECK(compared >= 5000);
  CHECK(worst <= 1e-11);
}
