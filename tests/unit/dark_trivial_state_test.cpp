// Newton on the dark-breather shooting residual (Sec. 5.3) must not report the trivial zero state,
// which solves F = 0 at any omega_b, as a converged breather. (The non-trivial side: the Fig. 17
// solve of dark_breather_test.cpp converges with an empty failure.)
#include <doctest/doctest.h>

#include <string>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/shooting.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

TEST_CASE("dark Newton: a solve that collapses to the zero state is not a breather") {
  // omega_b = 1.6 is far below the optical edge sqrt(6) = 2.4495 (Sec. 5.3): on 21 sites Newton from
  // the eq:xy_app seed goes to Z(0) = 0 (measured: max strain 5e-17), a zero of F but no breather.
  const DarkShooting shooting(Params{}, 21, DarkCenter::bond, ShootingMode::reversible);
  const Eigen::VectorXd seed =
      dark_seed(make_dark_breather_ansatz(Params{}, Branch::optical, 1.6), DarkCenter::bond, shooting.sites());
  const NewtonResult res = newton_solve(shooting, shooting.unknowns_from_z(seed), 1.6, {});
  REQUIRE_FALSE(res.history.empty());
  CHECK(res.history.back().residual <= 1e-11);  // F itself vanishes: Newton did reach a root ...
  CHECK(shooting.z_from_unknowns(res.q).lpNorm<Eigen::Infinity>() < 1e-12);  // ... the zero state
  CHECK_FALSE(res.converged);
  CHECK(res.failure.find("converged to the trivial state") != std::string::npos);
}

TEST_CASE("dark Newton: the failure message names omega_b, the reason and the residual history") {
  NewtonResult res;
  res.failure = "no convergence in 20 iterations";
  res.history = {{0, 3.188, 1.0}, {1, 1.208e-3, 0.0}};
  CHECK(newton_failure_message(res, 2.42) ==
        "Newton found no breather at omega_b = 2.42: no convergence in 20 iterations; residual history: 3.188e+00 "
        "1.208e-03");
}
