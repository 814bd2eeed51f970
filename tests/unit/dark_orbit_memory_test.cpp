// Memory of a model file's orbit integration stays bounded (issue 27, continuation): DarkOrbit
// records the accepted steps of a smooth orbit for the tangent replay at most chunk_steps at a time,
// and abandons an orbit that oscillates ever faster (a corrector's guess far outside the force's
// range) after 1000 + max_steps_per_time (t1 - t0) steps. Before, every accepted step was kept, and
// `dark continue --model sine_gordon_poly.toml --omega-b 1.725 --sites 61` grew by ~350 kB/s
// (past 2.4 GB in the issue, 11.6 GB measured) on a guess with amplitudes of order 100.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../support/run_lrchain.hpp"
#include "lrchain/process.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

namespace {

// The shipped klein_gordon chain (defaults C = 1/10, w0 = 1, a = 1/4, b = 1/2: a hard on-site force)
// on 9 sites, displacement form; parameters in the file's order C, w0, a, b.
const lrchain_lattice_kernels& klein_gordon() {
  const lrchain_lattice_kernels* k = lrchain::sim::shipped_lattice_kernels("klein_gordon");
  REQUIRE(k != nullptr);
  return *k;
}

// [u, udot] with u_n = amplitude (-1)^n at rest.
std::vector<double> staggered(Index sites, double amplitude) {
  std::vector<double> s(2 * std::size_t(sites), 0.0);
  for (Index n = 0; n < sites; ++n) s[std::size_t(n)] = n % 2 == 0 ? amplitude : -amplitude;
  return s;
}

}  // namespace

TEST_CASE("dark orbit: a long integration keeps at most chunk_steps step times, and its tangent is the flow's derivative" *
          doctest::test_suite("fast")) {
  const Index sites = 9;
  DarkOrbit orbit(klein_gordon(), {0.1, 1.0, 0.25, 0.5}, sites, false);
  const double t_end = 2000;  // max_step 0.25: at least 8000 accepted steps, about two chunks
  const std::vector<double> start = staggered(sites, 0.05);
  std::vector<double> state = start;
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(2 * sites, 1);
  phi(0, 0) = 1.0;  // d/du_0(0)
  orbit.integrate(state, phi, 0.0, t_end);
  CHECK(orbit.recorded_step_capacity() <= DarkOrbit::chunk_steps);
  // The orbit integrated with tangents ends where the orbit alone ends: the same steps, chunked
  // (the stepper without error estimate rounds differently: 1e-10 is ~10 times that roundoff here).
  std::vector<double> alone = start;
  orbit.integrate(alone, 0.0, t_end);
  for (std::size_t i = 0; i < state.size(); ++i) CHECK(std::abs(state[i] - alone[i]) < 1e-10);
  // Central difference in u_0(0), h = 1e-5: the tangent replayed across chunk boundaries agrees with
  // it to the difference's own error (integration error ~1e-11 over 2000 time units, / h).
  const double h = 1e-5;
  std::vector<double> plus = start, minus = start;
  plus[0] += h;
  minus[0] -= h;
  orbit.integrate(plus, 0.0, t_end);
  orbit.integrate(minus, 0.0, t_end);
  double scale = 0, error = 0;
  for (std::size_t i = 0; i < state.size(); ++i) {
    scale = std::max(scale, std::abs(phi(Eigen::Index(i), 0)));
    error = std::max(error, std::abs((plus[i] - minus[i]) / (2 * h) - phi(Eigen::Index(i), 0)));
  }
  CHECK(scale > 0.1);
  CHECK(error < 1e-4 * scale);
}

TEST_CASE("dark orbit: an orbit oscillating ever faster is abandoned as NaN after a bounded number of steps" *
          doctest::test_suite("fast")) {
  // u = 1e5: on-site frequency ~ sqrt(3 b) 1e5 ~ 1.2e5, steps of ~1e-7 at the 1e-13 tolerance, far
  // more than max_steps_per_time = 1e4 per time unit: abandoned after 1000 + 1e4 steps, none kept.
  // (A first step of 1e-8 keeps the first trial finite; from initial_step = 0.02 it overflows at once.)
  const Index sites = 9;
  ContactIntegrationOptions capped;
  capped.initial_step = 1e-8;
  capped.max_steps_per_time = 1e4;
  DarkOrbit orbit(klein_gordon(), {0.1, 1.0, 0.25, 0.5}, sites, false, capped);
  std::vector<double> state = staggered(sites, 1e5);
  orbit.integrate(state, 0.0, 1.0);
  for (double x : state) CHECK(std::isnan(x));
  std::vector<double> with_tangents = staggered(sites, 1e5);
  Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(2 * sites, 2 * sites);
  orbit.integrate(with_tangents, phi, 0.0, 1.0);
  CHECK(std::isnan(with_tangents[0]));
  CHECK(std::isnan(phi(0, 0)));
  CHECK(orbit.recorded_step_capacity() <= DarkOrbit::chunk_steps);
  // The step count abandons it, not min_step: without the cap the same orbit is integrated (finite)
  // over 1e-2 time units (~1e5 steps), more steps than the cap allows there (1000 + 1e4 * 1e-2).
  ContactIntegrationOptions uncapped = capped;
  uncapped.max_steps_per_time = 1e12;
  DarkOrbit fast(klein_gordon(), {0.1, 1.0, 0.25, 0.5}, sites, false, uncapped);
  std::vector<double> short_run = staggered(sites, 1e5);
  fast.integrate(short_run, 0.0, 1e-2);
  for (double x : short_run) CHECK(std::isfinite(x));
  std::vector<double> capped_run = staggered(sites, 1e5);
  orbit.integrate(capped_run, 0.0, 1e-2);
  CHECK(std::isnan(capped_run[0]));
}

TEST_CASE("dark continue --model: the issue's sine-Gordon polynomial chain under a 1.5 GB RLIMIT_AS ends in time" *
          doctest::test_suite("fast")) {
  using namespace lrchain::test;
  if (!lrchain::program_in_path("prlimit") || !lrchain::program_in_path("timeout")) return;
#ifdef LRCHAIN_SANITIZE_BUILD
  return;  // AddressSanitizer's shadow memory cannot be mapped under an RLIMIT_AS
#endif
  // Before: point 0 and 1, then a corrector guess that took ever more steps, all recorded (the
  // process grew without bound and never finished). After: 4 points in ~15 s (model compile included).
  const auto r = run_command({"timeout", "-s", "KILL", "300", "prlimit", "--as=1500000000", "--", LRCHAIN_CLI, "dark",
                              "continue", "--model", "tests/data/models/sine_gordon_poly.toml", "--omega-b", "1.725",
                              "--sites", "61", "--points", "4", "--quiet", "--json"},
                             LRCHAIN_SOURCE_DIR);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["points"] == 4);
  CHECK(j["stop_reason"] == "reached 4 points");
}
