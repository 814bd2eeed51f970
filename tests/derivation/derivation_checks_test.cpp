// The derivation's own checks (issue 2, section 2): every derived coefficient equals the paper's
// closed form, c and omega'' equal implicit derivatives of det M = 0, the edge values of Secs. 4.2
// and 5.2, and the rho -> 0 limit against the homogeneous chain; plus the no-drift test.
#include <doctest/doctest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "../support/run_lrchain.hpp"
#include "lrchain/derivation/generate.hpp"

using namespace lrchain::derivation;

namespace {
std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("every derivation check against the paper passes") {
  const Derivation d = derive_all();
  const auto checks = run_paper_checks(d.resonant_coefficients, d.homogeneous_coefficients, d.symbols);
  CHECK(checks.size() >= 27);
  for (const auto& c : checks) {
    INFO(c.name << " (" << c.method << ": " << c.detail << ")");
    CHECK(c.passed);
  }
}

TEST_CASE("the identity checker rejects a wrong formula (the checks can fail)") {
  // Perturb the derived h by one quarter of its K4 part: the comparison with the true h must fail.
  const Derivation d = derive_all();
  const Symbols& s = d.symbols;
  DerivedCoefficients wrong = d.resonant_coefficients;
  wrong.h = wrong.h + s.K4 * s.D1 * s.D1 * wrong.gamma / 4;
  wrong.h_tilde = wrong.h - wrong.lambda * wrong.beta;
  const auto checks = run_paper_checks(wrong, d.homogeneous_coefficients, s);
  int failed = 0;
  for (const auto& c : checks)
    if (!c.passed) ++failed;
  CHECK(failed >= 2);  // at least h (eq:h) and h_tilde (eq:h_tilde)
}

TEST_CASE("the homogeneous chain's coefficients are the known FPU-type ones (Chong13)") {
  const Derivation d = derive_all();
  const Symbols& s = d.symbols;
  const auto& h = d.homogeneous_coefficients;
  // omega^2 = K2 D1: c = K2 sin(theta)/omega and gamma = 1/omega.
  CHECK(GiNaC::normal(h.group_velocity - s.K2 * s.sigma / s.omega).is_zero());
  CHECK(GiNaC::normal(h.gamma - 1 / s.omega).is_zero());
}

// The emitted text depends only on the derived expressions (docs/derivation.md, "Reproducible
// bytes"), so every build of lrchain-derive, instrumented or not, reproduces the committed files.
TEST_CASE("re-running lrchain-derive reproduces every committed generated header byte for byte") {
  const auto tmp = std::filesystem::temp_directory_path() / ("lrchain-derive-drift-" + std::to_string(::getpid()));
  std::filesystem::remove_all(tmp);
  const auto source = std::filesystem::path(LRCHAIN_SOURCE_DIR);
  auto models = source / "models";
#ifdef LRCHAIN_SANITIZE_BUILD
  // Under the sanitizers (about ten times slower) three models cover the emitter's cases: a mean-flow
  // chain, an on-site chain and complex two-field kernels; the Release build regenerates them all.
  const std::vector<std::string> subset = {"fput", "klein_gordon", "diatomic_chain"};
  models = tmp / "models";
  std::filesystem::create_directories(models);
  for (const auto& name : subset) std::filesystem::copy_file(source / "models" / (name + ".toml"), models / (name + ".toml"));
#endif
  REQUIRE(lrchain::test::run_command({LRCHAIN_DERIVE, "--quiet", "--out", (tmp / "out").string(), "--models",
                                      models.string(), "--double-evaluators", LRCHAIN_DOUBLE_EVALUATOR_MODELS})
              .exit_code == 0);
  const auto committed = source / "lib/include/lrchain/generated";
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(tmp / "out")) {
    const std::string name = entry.path().filename().string();
    if (models != source / "models" && name == "shipped_models.hpp") continue;  // lists the subset only
    INFO(name);
    const std::string fresh = slurp(entry.path());
    REQUIRE(!fresh.empty());
    CHECK(fresh == slurp(committed / name));
    ++compared;
  }
  // nls_coefficients.hpp, shipped_models.hpp (all models only) and one header per model file.
  int model_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(models)) model_files += entry.path().extension() == ".toml";
  CHECK(compared == model_files + (models == source / "models" ? 2 : 1));
  std::filesystem::remove_all(tmp);
}
