// Newton on the dark-breather shooting residual (Sec. 5.3) must not report the trivial zero state,
// which solves F = 0 at any omega_b, as a converged breather. (The non-trivial side: the Fig. 17
// solve of dark_breather_test.cpp converges with an empty failure.)
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/continuation.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

TEST_CASE("dark Newton: a solve that collapses to the zero state is not a breather") {
  // omega_b = 1.6 is far below the optical edge sqrt(6) = 2.4495 (Sec. 5.3): on 21 sites Newton from
  // the eq:xy_app seed goes to Z(0) = 0 (measured: max strain 5e-17), a zero of F but no breather.
  const ResonantChainShooting shooting(Params{}, 21, DarkCenter::bond, ShootingMode::reversible);
  const Eigen::VectorXd seed =
      resonant_chain_dark_seed(make_dark_breather_ansatz(Params{}, Branch::optical, 1.6), DarkCenter::bond, shooting.sites());
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

namespace {
// A one-unknown problem whose breather branch q = omega_b - 1 (state Z = (q, -q), amplitude |q|) ends
// on the trivial state q = 0 for omega_b <= 1: F(q, omega_b) = q - max(omega_b - 1, 0).
class BranchIntoTrivialState : public DarkShootingProblem {
 public:
  Index unknowns() const override { return 1; }
  Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const override {
    return Eigen::Vector2d(q(0), -q(0));
  }
  void evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual, Eigen::MatrixXd* jacobian,
                Eigen::MatrixXd*) const override {
    residual = Eigen::VectorXd::Constant(1, q(0) - std::max(omega_b - 1, 0.0));
    if (jacobian) *jacobian = Eigen::RowVector2d(1.0, omega_b > 1 ? -1.0 : 0.0);
  }
  void jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                            Eigen::MatrixXd& jacobian, FloquetResult*) const override {
    evaluate(q, omega_b, residual, &jacobian, nullptr);
  }
  void measure(const Eigen::VectorXd&, double, DarkMeasures&) const override {}
};
}  // namespace

TEST_CASE("dark continuation: a branch that lands on the trivial state stops there") {
  // From q = 0.5 at omega_b = 1.5 toward smaller omega_b the breather branch reaches q = 0 at
  // omega_b = 1; past it every zero of F is the uniform state. Without the check the branch would run
  // on to omega_min = 0 with zero-amplitude "breathers".
  const BranchIntoTrivialState problem;
  ContinuationOptions o;
  o.ds = 0.1;
  o.ds_max = 0.1;
  o.max_points = 100;
  o.omega_min = 0;
  const BranchResult branch = continue_branch(problem, Eigen::VectorXd::Constant(1, 0.5), 1.5, o);
  INFO("stop reason: ", branch.stop_reason);
  CHECK(branch.stop_reason.find("trivial (uniform) state") != std::string::npos);
  REQUIRE_FALSE(branch.points.empty());
  for (const BranchPoint& point : branch.points) {
    CHECK(point.omega_b > 1 - 1e-9);                                             // all on the breather side
    CHECK(std::abs(point.z0(0) - (point.omega_b - 1)) < 1e-9);                   // q = omega_b - 1
  }
  CHECK(branch.points.back().omega_b < 1.1 + 1e-9);  // it followed the branch down to the last step before 1
}
