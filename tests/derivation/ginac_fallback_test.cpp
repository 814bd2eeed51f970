// The GiNaC double-precision fallback of a user model (no C++ compiler): found through the real
// detection path ($LRCHAIN_MODEL_CXX naming a program that does not exist) and checked against the
// compiled evaluators of the same file (1e-12 relative): NLS coefficients and second-order terms.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/model_compiler.hpp"

namespace fs = std::filesystem;
using namespace lrchain;

namespace {

// Sets an environment variable for the scope of one test.
struct ScopedEnvironment {
  std::string name;
  ScopedEnvironment(const char* n, const std::string& value) : name(n) { ::setenv(n, value.c_str(), 1); }
  ~ScopedEnvironment() { ::unsetenv(name.c_str()); }
};

// The agreement required: 1e-12. A compiled user model computes its NLS coefficients in long
// double or __float128 from consistent inputs and the fallback at 40 digits from the same inputs;
// both are within 1e-12 of 50-digit evaluation (model_evaluators_vs_50digit_test.cpp).
double agreement_bound(const std::string&) { return 1e-12; }

double relative(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return 0;
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

}  // namespace

TEST_CASE("without a C++ compiler a model file is evaluated through GiNaC and agrees with the compiled path") {
  const fs::path cache = fs::temp_directory_path() / ("lrchain-ginac-fallback-test-" + std::to_string(::getpid()));
  fs::remove_all(cache);
  ScopedEnvironment xdg("XDG_CACHE_HOME", cache.string());
#ifdef LRCHAIN_SANITIZE_BUILD
  // Under the sanitizers (about ten times slower; two models at 6 points took 275 s) one model and
  // fewer points: the same code paths; the Release build checks all three at 40 points per branch.
  const std::vector<std::string> models = {"klein_gordon"};
  constexpr int points_per_branch = 4;
#else
  const std::vector<std::string> models = {"diatomic_chain", "klein_gordon", "resonant_chain_polynomial"};
  constexpr int points_per_branch = 40;
#endif
  for (const std::string& name : models) {
    INFO(name);
    const fs::path file = fs::path(LRCHAIN_SOURCE_DIR) / "models" / (name + ".toml");
    CompiledModelInfo compiled_info, fallback_info;
    const auto compiled = compile_model_file(file, &compiled_info);
    REQUIRE(compiled_info.fallback_reason.empty());
    std::shared_ptr<const ModelDefinition> fallback;
    {
      ScopedEnvironment cxx("LRCHAIN_MODEL_CXX", "/nonexistent/lrchain-no-such-compiler");
      CHECK_FALSE(model_compiler_available());
      fallback = compile_model_file(file, &fallback_info);
    }
    CHECK(fallback_info.fallback_reason.find("/nonexistent/lrchain-no-such-compiler") != std::string::npos);
    CHECK(!fallback->evaluators.nls);
    REQUIRE(fallback->evaluators.object != nullptr);
    CHECK(fallback->name == compiled->name);
    CHECK(fallback->branch_names == compiled->branch_names);
    const Model a(compiled), b(fallback);
    REQUIRE(a.inputs().size() == b.inputs().size());
    for (std::size_t i = 0; i < a.inputs().size(); ++i) CHECK(relative(a.inputs()[i], b.inputs()[i]) <= 1e-12);
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> theta_of(0.05, std::numbers::pi);
    double worst = 0;
    int points = 0;
    for (std::size_t branch = 0; branch < compiled->branch_names.size(); ++branch)
      for (int k = 0; k < points_per_branch; ++k) {
        const double theta = theta_of(random);
        const NlsCoefficients x = coefficients(a, branch, theta), y = coefficients(b, branch, theta);
        for (auto [u, v] : {std::pair{x.omega, y.omega}, {x.group_velocity, y.group_velocity},
                            {x.curvature, y.curvature}, {x.gamma, y.gamma}, {x.beta, y.beta}, {x.h, y.h},
                            {x.lambda, y.lambda}, {x.h_tilde, y.h_tilde}, {x.nonresonance1, y.nonresonance1},
                            {x.nonresonance2, y.nonresonance2}, {x.h_tilde_numerator, y.h_tilde_numerator}})
          worst = std::max(worst, relative(u, v));
        CHECK(x.regime == y.regime);
        // The second-order terms (harmonics evaluator), relative to each quantity's size.
        const SecondOrderTerms p = second_order_terms(a, branch, theta), r = second_order_terms(b, branch, theta);
        for (std::size_t f = 0; f < p.mean.size(); ++f) {
          worst = std::max(worst, std::abs(p.second_harmonic[f] - r.second_harmonic[f]) /
                                      std::max(std::abs(p.second_harmonic[f]), 1e-300));
          if (p.mean[f] != r.mean[f]) worst = std::max(worst, relative(p.mean[f], r.mean[f]));
          if (p.kernel_gradient[f] != r.kernel_gradient[f])
            worst = std::max(worst, std::abs(p.kernel_gradient[f] - r.kernel_gradient[f]) / std::abs(p.kernel_gradient[f]));
        }
        ++points;
      }
    MESSAGE(name << ": GiNaC double fallback vs compiled, " << points << " points, largest relative difference "
                 << worst);
    CHECK(worst <= agreement_bound(name));
  }
  fs::remove_all(cache);
}
