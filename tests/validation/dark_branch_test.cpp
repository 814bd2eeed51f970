// Validation of exact dark breathers against Sec. 5.3-5.4 (Figs. 17-22), lattice N = 101.
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/continuation.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

namespace {
Eigen::VectorXd solve_z(const Params& p, int N, DarkCenter c, double wb, DarkShooting** keep = nullptr) {
  const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
  DarkShooting sh(p, N, c, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(dark_seed(a, c, N)), wb, {});
  REQUIRE(res.converged);
  (void)keep;
  return sh.z_from_unknowns(res.q);
}
}  // namespace

TEST_CASE("dark: lattice size N = 101 vs 201 at omega_b = 2.42 (rho = 1/3)") {
  const Params p;
  for (DarkCenter c : {DarkCenter::bond, DarkCenter::site}) {
    const auto m1 = measure_dark_breather(p, solve_z(p, 101, c, 2.42), 2.42);
    const auto m2 = measure_dark_breather(p, solve_z(p, 201, c, 2.42), 2.42);
    CHECK(m1.E_b <= 1e-10);
    CHECK(m2.E_b <= 1e-10);
    CHECK(m2.norm_squared == doctest::Approx(m1.norm_squared).epsilon(1e-8));
    CHECK(m2.K_x == doctest::Approx(m1.K_x).epsilon(1e-10));
  }
}

TEST_CASE("dark: optical bond-centred branch rho = 1/3 turns near omega_b = 2.37 (Fig. 18)") {
  const Params p;
  const int N = 101;
  const double w0 = 2.445;
  const auto a = make_dark_breather_ansatz(p, Branch::optical, w0);
  DarkShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(dark_seed(a, DarkCenter::bond, N)), w0, {});
  REQUIRE(res.converged);
  ContinuationOptions o;
  o.max_points = 70;  // the turning point is passed near point 55 (CLI run of 100 points)
  o.ds = 0.1;
  o.omega_max = a.omega;
  const auto br = continue_branch(sh, res.q, w0, o);
  REQUIRE(br.turning_points.size() == 1);
  CHECK(br.turning_points[0] == doctest::Approx(2.37).epsilon(0.005));  // paper: ~2.37
  for (const auto& pt : br.points) CHECK(pt.measures.E_b < 3e-9);        // paper: < 3e-9
}

TEST_CASE("dark: long-time E_b(1200) < 2e-4 at omega_b = 2.4255 (Sec. 5.4)") {
  const Params p;
  const double wb = 2.4255;
  const auto z = solve_z(p, 101, DarkCenter::bond, wb);
  const auto h = relative_error_history(p, z, wb, 1200.0);
  REQUIRE(!h.empty());
  CHECK(h.back().E_b < 2e-4);
}
