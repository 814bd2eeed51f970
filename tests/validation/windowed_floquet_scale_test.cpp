// Windowed, certified Floquet multipliers (sim/bright/windowed_floquet.hpp) of the matrix-free bright
// job against the dense job on 401 sites, where the default window (143 sites for klein_gordon) is a
// third of the ring: every certified localized multiplier is one of the dense monodromy's to 1e-8.
#include <doctest/doctest.h>

#include <algorithm>
#include <complex>
#include <limits>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;

TEST_CASE("windowed floquet: 401-site klein_gordon and fput breathers as the dense monodromy's") {
  struct Case {
    const char* model;
    std::vector<std::pair<std::string, double>> values;
    double omega_b;
    const char* kind;
  };
  // docs/bright-breathers.md: the Klein-Gordon breather at 1.19 is stable; the FPU Sievers-Takeno mode at
  // 2.2 has the real multiplier 1.02824 (Sandusky, Page & Schmidt, PRB 46, 6161 (1992)).
  for (const Case& k : {Case{"klein_gordon", {}, 1.19, "stable"}, Case{"fput", {{"a", 0.0}}, 2.2, "real"}}) {
    CAPTURE(k.model);
    const Model model = shipped_model(k.model, k.values);
    jobs::bright_breather::BrightBreatherConfig c;
    c.step = jobs::bright_breather::BrightStep::floquet;
    c.model = &model;
    c.kernels = sim::shipped_lattice_kernels(k.model);
    c.omega_b = k.omega_b;
    c.sites = 401;
    c.center = "site";
    c.krylov.solver = "dense";
    const auto dense = jobs::bright_breather::run(c);
    c.krylov.solver = "krylov";
    const auto krylov = jobs::bright_breather::run(c);
    REQUIRE(!jobs::bright_breather::failure(dense));
    REQUIRE(!jobs::bright_breather::failure(krylov));
    REQUIRE(dense.floquet);
    REQUIRE(krylov.krylov);
    REQUIRE(krylov.krylov->windowed);
    const auto& w = *krylov.krylov->windowed;
    CHECK(w.check_sites < 401);
    REQUIRE(!w.localized.empty());
    for (const auto& m : w.localized) {
      CHECK(m.certified);
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& d : dense.floquet->multipliers.multipliers) nearest = std::min(nearest, std::abs(m.lambda - d));
      CHECK(nearest <= 1e-8);
    }
    REQUIRE(w.verdict);
    CHECK(w.verdict->kind() == k.kind);
    CHECK(dense.floquet->multipliers.kind() == k.kind);
  }
}
