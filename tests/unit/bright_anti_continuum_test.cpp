// The anti-continuum start of the bright-breather job (sim/bright/anti_continuum.hpp, start =
// anti-continuum) and the fundamental-period check of a solved breather (sim/bright/fundamental_period.hpp),
// on klein_gordon: the uncoupled oscillator's amplitude against the Duffing period integral, the same
// breather as the NLS start where both reach it, and a two-site breather the NLS start does not reach.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "../support/oscillator_amplitude.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/fundamental_period.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

BrightBreatherResult run_bright(const Model& model, double omega_b, const char* center, const char* start,
                                BrightStep step = BrightStep::solve) {
  BrightBreatherConfig c;
  c.step = step;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = omega_b;
  c.sites = 21;
  c.center = center;
  c.start = start;
  validate(c);
  return run(c);
}

}  // namespace

TEST_CASE("bright anti-continuum: the uncoupled oscillator's amplitude is the Duffing oscillator's at omega_b" *
          doctest::test_suite("fast")) {
  // a = 0: at C = 0 the centre site is x'' + x + b x^3 = 0, whose amplitude at frequency omega_b comes
  // from its period integral (tests/support/oscillator_amplitude.hpp), not from the lattice code.
  for (const auto& [b, omega_b] : {std::pair{0.5, 1.3}, std::pair{-0.5, 0.9}}) {
    const Model model = shipped_model("klein_gordon", {{"a", 0.0}, {"b", b}, {"C", 0.05}});
    const BrightBreatherResult r = run_bright(model, omega_b, "site", "anti-continuum");
    INFO("b = " << b << ": " << failure(r).value_or(""));
    REQUIRE(!failure(r));
    CHECK(r.anti_continuum_amplitude == doctest::Approx(test::oscillator_amplitude(1.0, b, omega_b)).epsilon(1e-10));
    // continued in C from 0 to its value 0.05, the last point solved there
    REQUIRE(!r.anti_continuum_branch.points.empty());
    CHECK(r.anti_continuum_branch.points.front().parameter == 0.0);
    CHECK(r.anti_continuum_branch.points.back().parameter == 0.05);
    CHECK(r.newton.history.size() <= 2);  // the continued orbit is already the breather
    CHECK(r.anti_continuum_branch.points.size() >= 2);
  }
}

TEST_CASE("bright anti-continuum: the same breather as the NLS start where both reach it" * doctest::test_suite("fast")) {
  // klein_gordon's defaults (C = 0.1, a = 1/4, b = 1/2) above the band at 1.5, and its soft version below
  // the band at 0.9 (a = 0, b = -1/2), site- and bond-centred (staggered above, in phase below).
  const Model hard = shipped_model("klein_gordon", {});
  const Model soft = shipped_model("klein_gordon", {{"a", 0.0}, {"b", -0.5}});
  for (const auto& [model, omega_b, center] : {std::tuple{&hard, 1.5, "site"}, std::tuple{&hard, 1.3, "bond"},
                                               std::tuple{&soft, 0.9, "site"}, std::tuple{&soft, 0.9, "bond"}}) {
    const BrightBreatherResult nls = run_bright(*model, omega_b, center, "nls");
    const BrightBreatherResult anti = run_bright(*model, omega_b, center, "anti-continuum");
    INFO(center << " at " << omega_b << ": " << failure(nls).value_or("") << failure(anti).value_or(""));
    REQUIRE(!failure(nls));
    REQUIRE(!failure(anti));
    CHECK((nls.z0 - anti.z0).lpNorm<Eigen::Infinity>() <= 1e-9 * nls.z0.lpNorm<Eigen::Infinity>());
  }
}

TEST_CASE("bright anti-continuum: the hard chain's staggered two-site breather at 1.5, which the NLS start misses" *
          doctest::test_suite("fast")) {
  const Model hard = shipped_model("klein_gordon", {});
  // From the NLS seed Newton converges to a localized zero whose centre turns 9 times in half a period: a
  // breather of frequency 10 omega_b (peak 25.1), refused (exit 3), no longer taken for one at 1.5.
  const BrightBreatherResult nls = run_bright(hard, 1.5, "bond", "nls");
  REQUIRE(nls.newton.converged);
  REQUIRE(failure(nls));
  CHECK(failure(nls)->find("frequency 10 omega_b") != std::string::npos);
  // From C = 0 the pair x0 = 1.76915, -x1 (x1 = 1.98335, both from scipy's DOP853 on the single
  // oscillator x'' = -(x + x^2/4 + x^3/2): its a x^2 makes x1 differ from x0) continued to C = 0.1: out of phase, turning once per half period, with a real unstable pair
  // (hard on-site forces allow stable in-phase pairs only: Koukouloyannis & Kevrekidis, arXiv:0902.3990).
  const BrightBreatherResult anti = run_bright(hard, 1.5, "bond", "anti-continuum", BrightStep::floquet);
  INFO(failure(anti).value_or(""));
  REQUIRE(!failure(anti));
  CHECK(anti.anti_continuum_amplitude == doctest::Approx(1.7691514562438626).epsilon(1e-9));
  const Index centre = 10;
  CHECK(anti.z0(centre) > 0);
  CHECK(anti.z0(centre + 1) < 0);
  const sim::dark::DarkShooting shooting(*sim::shipped_lattice_kernels("klein_gordon"), sim::lattice_parameters(hard), 21,
                                         false, sim::dark::ShootingMode::reversible);
  CHECK(sim::bright::interior_turning_points(shooting.orbit(), anti.z0, 1.5) == 0);
  CHECK(sim::bright::interior_turning_points(shooting.orbit(), nls.newton.q, 1.5) == 9);
  REQUIRE(anti.floquet);
  CHECK_FALSE(anti.floquet->stable);
}

TEST_CASE("bright anti-continuum: refusals name --start and --coupling" * doctest::test_suite("fast")) {
  const Model fput = shipped_model("fput", {});
  BrightBreatherConfig c;
  c.model = &fput;
  c.kernels = sim::shipped_lattice_kernels("fput");
  c.omega_b = 2.2;
  c.start = "anti-continuum";
  try {
    validate(c);
    FAIL("accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "start");  // fput is translation-invariant: no uncoupled limit
  }
  const Model kg = shipped_model("klein_gordon", {});
  c.model = &kg;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.5;
  for (const char* coupling : {"w0", "D"}) {  // w0's range (0, inf) has no 0; D is no parameter
    c.coupling = coupling;
    try {
      validate(c);
      FAIL("accepted");
    } catch (const InvalidParameter& e) {
      CHECK(e.parameter() == "coupling");
    }
  }
  // a = 0 is in a's range but leaves the cells coupled: the single oscillator is no orbit there (its
  // neighbours feel C), refused naming coupling when the job runs.
  c.coupling = "a";
  c.sites = 21;
  validate(c);
  try {
    run(c);
    FAIL("ran");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "coupling");
    CHECK(std::string(e.what()).find("does not uncouple") != std::string::npos);
  }
}
