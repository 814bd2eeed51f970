// The emitted harmonics evaluators of every shipped model (second harmonic W2_f = A_{2,2,f} /
// A_{1,1}^2, mean W0_f = A_{2,0,f} / |A_{1,1}|^2 and gradient term G_f, through
// lrchain::second_order_terms) against
// 50-digit CLN evaluation of the expressions the derivation produces from the model file.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <random>

#include "lrchain/derivation/branches.hpp"
#include "lrchain/derivation/evaluate.hpp"
#include "lrchain/derivation/model_file.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"

using namespace lrchain;
using namespace lrchain::derivation;

TEST_CASE("every shipped model's emitted second-order terms agree with 50-digit evaluation to 1e-11") {
  const Symbols s;
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const int points_per_branch = 200;
  for (const auto& definition : shipped_models()) {
    const ModelFile file = load_model_file(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "models" / (definition.name + ".toml"));
    REQUIRE(file.hash == definition.file_hash);
    const DerivedCoefficients d = derive(file.model, s);
    REQUIRE(d.second_harmonic.size() == std::size_t(definition.degree));
    for (std::size_t branch = 0; branch < definition.branch_names.size(); ++branch) {
      int compared = 0, excluded = 0;
      double worst = 0;
      for (int attempt = 0; compared < points_per_branch && attempt < 4 * points_per_branch; ++attempt) {
        // Parameters within a factor 2 of their defaults (in [-1, 1] for a zero default) inside their ranges.
        std::vector<std::pair<std::string, double>> values;
        GiNaC::exmap exact_values;
        GiNaC::Digits = 50;
        for (const auto& p : file.parameters) {
          const double d0 = p.default_value.to_double();
          double x = d0 == 0.0 ? U(rng) : d0 * std::exp(std::log(2.0) * U(rng));
          if (!p.range.contains(exact(x))) x = d0;
          values.emplace_back(p.name, x);
          exact_values[p.symbol] = GiNaC::evalf(exact(x));
        }
        for (const auto& i : file.intermediates)
          exact_values[i.symbol] = GiNaC::evalf(i.value.subs(exact_values, GiNaC::subs_options::no_pattern));
        const Model model(std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), &definition), values);
        const double theta = M_PI * (0.01 + 0.98 * (0.5 + 0.5 * U(rng)));
        SecondOrderTerms got;
        NlsCoefficients nls;
        try {
          nls = coefficients(model, branch, theta);
          got = second_order_terms(model, branch, theta);
        } catch (const InvalidParameter&) {
          ++excluded;  // no real frequency on this branch here
          continue;
        }
        if (nls.regime == Regime::singular) {  // within 1e-10 of a non-resonance violation (W2 or lambda has a pole)
          ++excluded;
          continue;
        }
        const BranchPoint ref(d, s, exact_values, theta, branch, 50);
        const auto value = [&](const GiNaC::ex& e) {
          const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(ref.substitutions(), GiNaC::subs_options::no_pattern)));
          return std::complex<double>(v.real().to_double(), v.imag().to_double());
        };
        for (std::size_t f = 0; f < got.mean.size(); ++f) {
          const std::complex<double> w2 = value(d.second_harmonic[f]), w0 = value(d.mean_offset[f]);
          if (std::abs(w2) > 0) worst = std::max(worst, std::abs(got.second_harmonic[f] - w2) / std::abs(w2));
          else CHECK(std::abs(got.second_harmonic[f]) == 0.0);
          if (w0.real() != 0) worst = std::max(worst, std::abs(got.mean[f] - w0.real()) / std::abs(w0.real()));
          else CHECK(got.mean[f] == 0.0);
          CHECK(std::abs(w0.imag()) <= 1e-40 * std::max(1.0, std::abs(w0.real())));
          const std::complex<double> g = value(d.kernel_gradient[f]);
          if (std::abs(g) > 0) worst = std::max(worst, std::abs(got.kernel_gradient[f] - g) / std::abs(g));
          else CHECK(std::abs(got.kernel_gradient[f]) == 0.0);
        }
        ++compared;
      }
      std::printf("%s %s: second-order terms at %d points (%d excluded), max rel err %.3g\n", definition.name.c_str(),
                  definition.branch_names[branch].c_str(), compared, excluded, worst);
      INFO(definition.name << " " << definition.branch_names[branch]);
      CHECK(compared == points_per_branch);
      CHECK(worst <= 1e-11);
    }
  }
}
