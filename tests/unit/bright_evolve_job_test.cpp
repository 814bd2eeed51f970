// `bright evolve` through the library (lrchain/jobs/bright_breather_job.hpp, sim/bright/bright_evolution.hpp):
// a stable Klein-Gordon breather keeps its profile and energy, the FPU chain's unstable Sievers-Takeno
// mode departs at the rate ln|lambda_max| / T_b its Floquet multiplier predicts, and perturb unstable
// on a stable breather is refused naming perturb.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

// An evolve config on a shipped model with its compiled-in lattice kernels.
struct EvolveLattice {
  Model model;
  const lrchain_lattice_kernels* kernels;
  EvolveLattice(const char* name, const std::vector<std::pair<std::string, double>>& values = {})
      : model(shipped_model(name, values)), kernels(sim::shipped_lattice_kernels(name)) {}
  BrightBreatherConfig config(double omega_b, Index sites, const char* center, Index periods,
                              const char* perturb = "none") const {
    BrightBreatherConfig c;
    c.step = BrightStep::evolve;
    c.model = &model;
    c.kernels = kernels;
    c.omega_b = omega_b;
    c.sites = sites;
    c.center = center;
    c.periods = periods;
    c.perturb = perturb;
    return c;
  }
};

BrightBreatherResult evolved(const BrightBreatherConfig& c) {
  validate(c);
  BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  REQUIRE(r.evolution);
  REQUIRE(r.floquet);
  return r;
}

}  // namespace

TEST_CASE("bright evolve: a stable Klein-Gordon breather keeps its profile and energy" * doctest::test_suite("fast")) {
  // klein_gordon at its defaults, omega_b = 1.19 (docs/bright-breathers.md: stable, site-centred). The
  // exact breather returns to Z(0) every period up to the Newton residual (1e-11) and the RKF78
  // integration error, both amplified at most linearly along the phase mode's Jordan block (the
  // trivial +1 pair): after 20 periods the measured drift is 1.0e-12 of the peak and the energy drift
  // 4.2e-13 (lrchain 2026-11-28); allowed 1e-10 and 1e-11, far below any growth of a 1e-11 error.
  const EvolveLattice kg("klein_gordon");
  const BrightBreatherResult r = evolved(kg.config(1.19, 61, "site", 20));
  CHECK(r.floquet->stable);
  MESSAGE("profile drift ", r.evolution->profile_drift, ", energy drift ", r.evolution->energy_drift);
  CHECK(r.evolution->samples.size() == 21);
  CHECK(r.evolution->has_energy);
  CHECK(r.evolution->profile_drift < 1e-10);
  CHECK(r.evolution->energy_drift < 1e-11);
  // A random perturbation of 1e-6 stays of its own size (no exponential growth, only the phase mode's
  // linear drift): measured max deviation 1.6e-6 over 20 periods, 1.3e-6 at the end; allowed 1e-5.
  BrightBreatherConfig random = kg.config(1.19, 61, "site", 20, "random");
  const BrightBreatherResult p = evolved(random);
  MESSAGE("random: profile drift ", p.evolution->profile_drift, ", final deviation ", p.evolution->samples.back().deviation);
  // The random perturbation is uniform in [-1e-6, 1e-6] on each of the 61 positions (perturbation.cpp):
  // its max-norm, the deviation at t = 0, is at most 1e-6 and expected 1e-6 (1 - 1/62); measured 9.98e-7.
  CHECK(p.evolution->samples.front().deviation <= 1e-6);
  CHECK(p.evolution->samples.front().deviation > 0.9e-6);
  CHECK(p.evolution->profile_drift * r.profile.peak < 1e-5);
}

TEST_CASE("bright evolve: the Sievers-Takeno mode departs at its Floquet growth rate" * doctest::test_suite("fast")) {
  // fput with a = 0, site-centred at omega_b = 2.2 on 41 sites: unstable, |lambda_max| = 1.0282
  // (bright_breather_job_test.cpp; Sandusky, Page & Schmidt 1992). Started along that multiplier's
  // eigenvector at size 1e-6, the deviation grows by |lambda_max| per period: measured rate
  // 0.00975049074 vs predicted ln|lambda_max| / T_b = 0.00975049067 (relative 7e-9), fitted over all 30
  // periods; allowed 1e-4 (the nonlinear terms enter at O(size) = 1e-6 relative).
  const EvolveLattice fpu("fput", {{"a", 0.0}});
  const BrightBreatherResult r = evolved(fpu.config(2.2, 41, "site", 30, "unstable"));
  CHECK_FALSE(r.floquet->stable);
  REQUIRE(r.evolution->growth_rate);
  MESSAGE("growth rate ", *r.evolution->growth_rate, " predicted ", r.predicted_growth_rate, " fit ", r.evolution->fit_last);
  CHECK(std::abs(r.perturbation.multiplier) == doctest::Approx(r.floquet->max_nontrivial_modulus).epsilon(1e-9));
  CHECK(r.evolution->fit_last == 30);
  CHECK(*r.evolution->growth_rate == doctest::Approx(r.predicted_growth_rate).epsilon(1e-4));
}

TEST_CASE("bright evolve: perturb unstable on a stable breather is refused naming perturb" * doctest::test_suite("fast")) {
  const EvolveLattice kg("klein_gordon");
  const BrightBreatherConfig c = kg.config(1.19, 61, "site", 2, "unstable");
  validate(c);
  std::string key;
  try {
    run(c);
  } catch (const InvalidParameter& e) {
    key = e.parameter();
  }
  CHECK(key == "perturb");
  BrightBreatherConfig bad = kg.config(1.19, 41, "site", 0);
  CHECK_THROWS_AS(validate(bad), InvalidParameter);
}
