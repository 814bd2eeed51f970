// Newton on the dark-breather shooting residual (Sec. 5.3) must not report the trivial zero state,
// which solves F = 0 at any omega_b, as a converged breather.
#include <doctest/doctest.h>

#include <string>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/shooting.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

TEST_CASE("dark Newton: a solve that collapses to the zero state is not a breather") {
  // omega_b = 1.6 is far below the optical edge 2.4495 (Sec. 5.3): on 21 sites Newton from the
  // eq:xy_app seed goes to Z(0) = 0 (measured: max strain 5e-17), a zero of F that is no breather.
  const Params p;
  const int N = 21;
  const double wb = 1.6;
  const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
  DarkShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(dark_seed(a, DarkCenter::bond, N)), wb, {});
  REQUIRE(!res.history.empty());
  CHECK(res.history.back().residual <= 1e-11);  // F itself is zero: Newton did reach a root
  CHECK(sh.z_from_unknowns(res.q).lpNorm<Eigen::Infinity>() < 1e-12);  // ... the zero state
  CHECK_FALSE(res.converged);
  CHECK(res.failure.find("converged to the trivial state") != std::string::npos);
}

TEST_CASE("dark Newton: the documented optical breather (41 sites, omega_b 2.42) is not trivial") {
  const Params p;
  const int N = 41;
  const double wb = 2.42;
  const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
  DarkShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(dark_seed(a, DarkCenter::bond, N)), wb, {});
  CHECK(res.converged);
  CHECK(res.failure.empty());
  // Far-site amplitude K_x ~ 0.473 (the same solution as dark_breather_test's Fig. 17 case).
  const auto m = measure_dark_breather(p, sh.z_from_unknowns(res.q), wb);
  CHECK(m.K_x == doctest::Approx(0.4734).epsilon(1e-3));
}
