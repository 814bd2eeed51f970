// Windowed, certified Floquet multipliers of bright breathers (sim/bright/windowed_floquet.hpp) against
// the dense monodromy of the whole ring: a window narrower than the ring reproduces the localized
// multipliers to 1e-8, certified by full-lattice residuals; an extended eigenvector is not certified.
#include <doctest/doctest.h>

#include <algorithm>
#include <complex>
#include <limits>

#include "../support/nearest_multiplier.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/windowed_floquet.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using lrchain::test::nearest;

namespace {

// The dense bright job's breather and multipliers at omega_b on `sites` sites of the shipped model `name`.
jobs::bright_breather::BrightBreatherResult dense_breather(const Model& model, const char* name, double omega_b,
                                                           Index sites) {
  jobs::bright_breather::BrightBreatherConfig c;
  c.step = jobs::bright_breather::BrightStep::floquet;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels(name);
  c.omega_b = omega_b;
  c.sites = sites;
  c.center = "site";
  c.krylov.solver = "dense";
  jobs::bright_breather::validate(c);
  jobs::bright_breather::BrightBreatherResult r = jobs::bright_breather::run(c);
  REQUIRE(!jobs::bright_breather::failure(r));
  REQUIRE(r.floquet);
  return r;
}

}  // namespace

TEST_CASE("windowed floquet: a klein_gordon breather's internal mode from a window narrower than the ring" *
          doctest::test_suite("fast")) {
  // docs/bright-breathers.md's stable Klein-Gordon breather (omega_b = 1.19), 101 sites, dense.
  const Model model = shipped_model("klein_gordon", {});
  const auto dense = dense_breather(model, "klein_gordon", 1.19, 101);
  const lrchain_lattice_kernels* kernels = sim::shipped_lattice_kernels("klein_gordon");
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const sim::dark::DarkShooting shooting(*kernels, parameters, 101, false, sim::dark::ShootingMode::reversible);
  sim::bright::WindowedFloquetOptions o;
  o.fraction = 1e-8;  // a core narrower than the default 1e-10 one, so that the first window fits in 101 sites
  o.margin = 2;
  o.count = 4;
  const sim::bright::WindowedFloquet w =
      sim::bright::windowed_floquet(shooting, {kernels, parameters, false, {}}, dense.z0, 1.19, o);
  CHECK(w.sites < 101);  // the second window is the whole ring
  CHECK(w.trivial.size() == 2);
  // One localized pair exp(+-i theta), theta ~ 5.6e-4 (the dense monodromy has it; measured on 401 and
  // 10 001 sites alike), the rest of the window's modes extended (phonons).
  REQUIRE(w.localized.size() == 2);
  for (const auto& m : w.localized) {
    CHECK(m.certified);
    CHECK(*m.residual <= 1e-8);
    CHECK(std::abs(m.lambda.imag()) > 1e-4);
    // the same multiplier as the whole ring's dense monodromy
    CHECK(nearest(m.lambda, dense.floquet->multipliers.multipliers) <= 1e-8);
  }
  REQUIRE(w.verdict);
  CHECK(w.verdict->kind() == "stable");
  CHECK(w.max_extended_modulus <= 1 + 1e-6);
}

TEST_CASE("windowed floquet: a window too narrow for the breather's modes is not certified" *
          doctest::test_suite("fast")) {
  // The same breather with the window capped at 15 sites: its eigenvectors do not fit, the full-lattice
  // residuals are large (an independent check of the window) and no stability verdict is given.
  const Model model = shipped_model("klein_gordon", {});
  const auto dense = dense_breather(model, "klein_gordon", 1.19, 61);
  const lrchain_lattice_kernels* kernels = sim::shipped_lattice_kernels("klein_gordon");
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const sim::dark::DarkShooting shooting(*kernels, parameters, 61, false, sim::dark::ShootingMode::reversible);
  sim::bright::WindowedFloquetOptions o;
  o.cap = 15;
  o.margin = 2;
  o.edge_weight = 1.0;  // every window mode taken as localized: all must then fail the residual
  const sim::bright::WindowedFloquet w =
      sim::bright::windowed_floquet(shooting, {kernels, parameters, false, {}}, dense.z0, 1.19, o);
  CHECK(w.sites == 15);
  REQUIRE(!w.localized.empty());
  Index uncertified = 0;
  for (const auto& m : w.localized) uncertified += m.certified ? 0 : 1;
  CHECK(uncertified >= 1);
  CHECK(!w.verdict);
  CHECK(!w.verdict_reason.empty());
}
