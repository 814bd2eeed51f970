// Fast tests of the dark-breather machinery (Sec. 5.2-5.4): eq:xy_app seed, shooting Newton,
// reversible vs full shooting, Floquet reduction vs full monodromy.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

TEST_CASE("dark seed: eq:xy_app constants at the paper's parameters") {
  const Params p;  // alpha 3/2, delta0 4/9, kappa 1, rho 1/3
  const auto a = make_dark_breather_ansatz(p, Branch::optical, 2.42);
  CHECK(a.omega == doctest::Approx(2.4495).epsilon(1e-4));       // omega_opt, Sec. 5.3
  CHECK(a.mean_factor == doctest::Approx(-2.0 / std::sqrt(3.0)));  // -2/sqrt(3) printed in eq:xy_app
  const auto ac = make_dark_breather_ansatz(p, Branch::acoustic, 1.40);
  CHECK(ac.omega == doctest::Approx(1.4142).epsilon(1e-4));      // omega_acs, Sec. 5.3
  CHECK_THROWS_AS(make_dark_breather_ansatz(p, Branch::optical, 2.46), InvalidParameter);
  CHECK_THROWS_AS(ResonantChainShooting(p, 40, DarkCenter::bond, ShootingMode::reversible), InvalidParameter);
}

TEST_CASE("dark Newton: bond-centred optical breather at omega_b = 2.42 (Fig. 17)") {
  const Params p;
  const int N = 41;
  const double wb = 2.42;
  const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
  ResonantChainShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(resonant_chain_dark_seed(a, DarkCenter::bond, N)), wb, {});
  REQUIRE(res.converged);
  CHECK(res.failure.empty());      // a breather, not the trivial state (dark_trivial_state_test.cpp)
  CHECK(res.history.size() <= 7);  // quadratic convergence from the seed
  const Eigen::VectorXd z0 = sh.z_from_unknowns(res.q);
  const auto m = measure_dark_breather(p, z0, wb);
  CHECK(m.E_b <= 1e-10);                                   // paper: < 3e-9
  CHECK(m.K_x == doctest::Approx(0.4734).epsilon(1e-3));   // issue 5: K_x ~ 0.473 > delta0
  CHECK(std::abs(m.C_x) < 1e-9);                           // C_x ~ 0 (Sec. 5.3)
  CHECK(m.max_strain > p.delta0);                          // contact is lost every period
  // The bond family's symmetry Z(T/2) = R Z(0) holds for the converged orbit.
  auto evo = dark_breather_evolution(p, z0, std::numbers::pi / wb, 1);
  double sym = 0;
  for (int f = 0; f < 2; ++f)
    for (int i = 0; i < N; ++i) sym = std::max(sym, std::abs(evo[1](f * N + i) - z0(f * N + sh.reflect(i))));
  CHECK(sym < 1e-9);
  // The full-period least-squares formulation accepts the same solution.
  ResonantChainShooting full(p, N, DarkCenter::bond, ShootingMode::full);
  Eigen::VectorXd r;
  full.evaluate(full.unknowns_from_z(z0), wb, r, nullptr);
  CHECK(r.lpNorm<Eigen::Infinity>() < 1e-9);
}

TEST_CASE("dark Floquet: reversible reduction equals the full-period monodromy") {
  const Params p;
  const int N = 21;
  const double wb = 2.43;
  for (DarkCenter c : {DarkCenter::site, DarkCenter::bond}) {
    const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
    ResonantChainShooting sh(p, N, c, ShootingMode::reversible);
    const auto res = newton_solve(sh, sh.unknowns_from_z(resonant_chain_dark_seed(a, c, N)), wb, {});
    REQUIRE(res.converged);
    Eigen::VectorXd r;
    Eigen::MatrixXd J, A, M;
    sh.evaluate(res.q, wb, r, &J, &A);
    const auto fr = floquet_reversible(sh, A);
    ResonantChainShooting full(p, N, c, ShootingMode::full);
    full.evaluate(full.unknowns_from_z(sh.z_from_unknowns(res.q)), wb, r, &J, &M);
    const auto ff = floquet_from_monodromy(M);
    CHECK(ff.pairing_defect < 1e-5);          // (lambda, 1/conj lambda) sets: accuracy of M
    CHECK(std::abs(ff.log_det) < 1e-8);       // volume-preserving flow: det M = 1
    CHECK(ff.near_one >= 2);                  // symmetry multipliers at +1
    CHECK(fr.max_modulus == doctest::Approx(ff.max_modulus).epsilon(1e-6));
    double d = 0;
    for (auto l : fr.multipliers) {
      double best = 1e9;
      for (auto k : ff.multipliers) best = std::min(best, std::abs(l - k));
      d = std::max(d, best);
    }
    CHECK(d < 1e-3);  // the Jordan blocks at +1 split ~ sqrt(eps); elsewhere ~1e-8
  }
}
