// Windowed Floquet multipliers of a dark breather (sim/dark/windowed_dark_floquet.hpp) from the
// matrix-free dark job against the dense job on 401 sites, where the window (95 sites) is a quarter
// of the ring: every certified localized multiplier is one of the dense monodromy's to 1e-8.
#include <doctest/doctest.h>

#include <algorithm>
#include <complex>
#include <limits>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;

TEST_CASE("windowed dark floquet: a 401-site klein_gordon dark breather as the dense monodromy's") {
  // klein_gordon at b = -1/2 (defocusing at theta = pi), bond-centred at omega_b = 1.0: a localized real
  // instability 2.0324 (docs/dark-breathers.md; the dense monodromy of 201 sites has it too).
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::floquet;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.center = "bond";
  c.omega_b = 1.0;
  c.sites = 401;
  c.krylov.solver = "dense";
  jobs::dark::validate(c);
  const auto dense = jobs::dark::run(c);
  c.krylov.solver = "krylov";  // auto: the window above krylov_sites = 400
  jobs::dark::validate(c);
  const auto krylov = jobs::dark::run(c);
  REQUIRE(!jobs::dark::failure(dense));
  REQUIRE(!jobs::dark::failure(krylov));
  REQUIRE(dense.floquet);
  REQUIRE(krylov.krylov);
  REQUIRE(krylov.krylov->dark_windowed);
  const auto& r = *krylov.krylov->dark_windowed;
  CHECK(r.window.check_sites < 401);
  CHECK(!r.background.unstable);
  REQUIRE(r.window.localized.size() >= 2);
  for (const auto& m : r.window.localized) {
    CHECK(m.certified);
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& d : dense.floquet->multipliers) nearest = std::min(nearest, std::abs(m.lambda - d));
    CHECK(nearest <= 1e-8);
  }
  REQUIRE(r.verdict);
  CHECK(r.verdict->kind() == "real");
  CHECK(std::abs(dense.floquet->max_real - 2.0324) <= 1e-4);
}
