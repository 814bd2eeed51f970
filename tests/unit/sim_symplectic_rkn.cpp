// Unit tests of the high-order symplectic RKN steppers (sim/.../symplectic_rkn.hpp) driven by
// integrate_observed: the published coefficients must give the published orders (Blanes & Moan
// 2002: SRKN_11^b, SRKN_14^a order 6; McLachlan 1995: SS17 order 8), the skipped force evaluations
// (first-same-as-last, zero kicks) must not change the result, and energy must stay bounded.
// Reference: rkf78 at tolerance 1e-14 on the same lattice (an independent Odeint stepper).
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "lrchain/params.hpp"
#include "lrchain/sim/contiguous_algebra.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/symplectic_rkn.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

// A periodic 24-bead chain with strains ~0.1 (strongly nonlinear: delta0 = 4/9).
State rough_state(std::size_t sites) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  State s(4 * sites);
  for (double& x : s) x = d(gen);
  return s;
}

double max_abs_diff(const State& a, const State& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

State integrate_to(const DisplacementLattice& chain, State s, double t_end, StepperKind k,
                   double dt, IntegrationStats* stats = nullptr) {
  IntegratorOptions opt;
  opt.stepper = k;
  opt.dt = dt;
  opt.abs_tol = opt.rel_tol = 1e-14;
  const std::vector<double> times = {0.0, t_end / 2, t_end};
  auto st = integrate_observed(chain, s, times, [](const State&, double) { return true; }, opt);
  if (stats) *stats = st;
  return s;
}

}  // namespace

TEST_CASE("Blanes-Moan and McLachlan coefficients are consistent (sum of drifts = sum of kicks = 1)" * doctest::test_suite("fast")) {
  blanes_moan_srkn11b<std::vector<double>> m11;
  blanes_moan_srkn14a<std::vector<double>> m14;
  mclachlan_ss17<std::vector<double>> s17;
  auto sum = [](const auto& c) { double x = 0; for (double v : c) x += v; return x; };
  CHECK(sum(m11.coef_a()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(sum(m11.coef_b()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(sum(m14.coef_a()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(sum(m14.coef_b()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(sum(s17.coef_a()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(sum(s17.coef_b()) == doctest::Approx(1.0).epsilon(1e-14));
  CHECK(m11.coef_a()[0] == 0.0);   // BAB: first stage is a pure kick (reused force)
  CHECK(m14.coef_b()[14] == 0.0);  // ABA: last stage is a pure drift
  CHECK(s17.coef_b()[17] == 0.0);
}

TEST_CASE("contiguous_algebra gives Odeint's range_algebra results bit for bit" * doctest::test_suite("fast")) {
  const DisplacementLattice chain(Params{}, 24, DisplacementBoundary{true, {}, {}});
  const State s0 = rough_state(24);
  const std::size_t half = s0.size() / 2;
  auto run = [&](auto stepper) {
    std::vector<double> q(s0.begin(), s0.begin() + half), p(s0.begin() + half, s0.end());
    auto acc = [&](const std::vector<double>& x, std::vector<double>& a) {
      chain.acceleration(x.data(), a.data(), 0.0);
    };
    for (int k = 0; k < 20; ++k) stepper.do_step(acc, std::make_pair(std::ref(q), std::ref(p)), 0.0, 0.1);
    q.insert(q.end(), p.begin(), p.end());
    return q;
  };
  const auto a = run(blanes_moan_srkn11b<std::vector<double>>{});
  const auto b = run(blanes_moan_srkn11b<std::vector<double>, contiguous_algebra>{});
  CHECK(max_abs_diff(a, b) == 0.0);
}

TEST_CASE("srkn11b, srkn14a are 6th order and ss17 8th order on a nonlinear periodic chain" * doctest::test_suite("fast")) {
  const DisplacementLattice chain(Params{}, 24, DisplacementBoundary{true, {}, {}});
  const State s0 = rough_state(24);
  const double T = 8.0;
  const State ref = integrate_to(chain, s0, T, StepperKind::rkf78, 0.01);
  struct Case { StepperKind kind; double dt; double order; };
  for (const Case c : {Case{StepperKind::srkn11b, 0.2, 6}, Case{StepperKind::srkn14a, 0.2, 6},
                       Case{StepperKind::ss17, 0.2, 8}}) {
    const double e1 = max_abs_diff(integrate_to(chain, s0, T, c.kind, c.dt), ref);
    const double e2 = max_abs_diff(integrate_to(chain, s0, T, c.kind, c.dt / 2), ref);
    const double observed = std::log2(e1 / e2);
    INFO(to_string(c.kind), ": errors ", e1, " ", e2, ", observed order ", observed);
    CHECK(e2 < 1e-8);
    CHECK(observed > c.order - 0.6);
    CHECK(observed < c.order + 1.5);
  }
}

TEST_CASE("symplectic RKN steppers: force evaluations per step and skipped stages" * doctest::test_suite("fast")) {
  const DisplacementLattice chain(Params{}, 24, DisplacementBoundary{true, {}, {}});
  const State s0 = rough_state(24);
  IntegrationStats st;
  // t in [0, 8] observed at 0, 4, 8 with dt = 0.5: 2 intervals x 8 steps = 16 steps.
  integrate_to(chain, s0, 8.0, StepperKind::srkn11b, 0.5, &st);
  CHECK(st.steps == 16);
  CHECK(st.rhs_evaluations == 16 * 11 + 1);  // first-same-as-last: one extra at the start
  integrate_to(chain, s0, 8.0, StepperKind::srkn14a, 0.5, &st);
  CHECK(st.rhs_evaluations == 16 * 14);
  integrate_to(chain, s0, 8.0, StepperKind::ss17, 0.5, &st);
  CHECK(st.rhs_evaluations == 16 * 17);
}

TEST_CASE("srkn11b keeps the energy of a rough periodic chain bounded over 2000 time units" * doctest::test_suite("fast")) {
  DisplacementBoundary b;
  b.periodic = true;
  const DisplacementLattice chain(Params{}, 24, b);
  State s = rough_state(24);
  const double E0 = chain.total_energy(s);
  std::vector<double> times;
  for (int k = 0; k <= 200; ++k) times.push_back(10.0 * k);
  IntegratorOptions opt;
  opt.stepper = StepperKind::srkn11b;
  opt.dt = 0.1;
  double worst = 0;
  integrate_observed(chain, s, times, [&](const State& x, double) {
    worst = std::max(worst, std::abs(chain.total_energy(x) - E0) / E0);
    return true;
  }, opt);
  INFO("max relative energy error ", worst);
  CHECK(worst < 1e-9);
}

TEST_CASE("symplectic steppers refuse a non-autonomous chain (prescribed end motion)" * doctest::test_suite("fast")) {
  DisplacementBoundary b;
  b.left.kind = EndKind::prescribed;
  b.left.motion = [](double t) { return 0.01 * std::sin(t); };
  const DisplacementLattice chain(Params{}, 10, b);
  State s(40, 0.0);
  for (auto k : {StepperKind::symplectic, StepperKind::srkn11b, StepperKind::ss17}) {
    IntegratorOptions opt;
    opt.stepper = k;
    CHECK_THROWS_AS(integrate_observed(chain, s, {0.0, 1.0}, [](const State&, double) { return true; }, opt),
                    InvalidParameter);
  }
}

TEST_CASE("srkn11b stops at the observation where the observer asks to (Ctrl-C path), counts kept" * doctest::test_suite("fast")) {
  DisplacementBoundary b;
  b.periodic = true;
  const DisplacementLattice chain(Params{}, 24, b);
  State s = rough_state(24);
  std::vector<double> times;
  for (int k = 0; k <= 10; ++k) times.push_back(1.0 * k);
  IntegratorOptions opt;
  opt.stepper = StepperKind::srkn11b;
  opt.dt = 0.25;
  const auto st = integrate_observed(chain, s, times, [](const State&, double t) { return t < 4.0; }, opt);
  CHECK(st.stopped);
  CHECK(st.t_reached == 4.0);
  CHECK(st.steps == 16);                    // 4 intervals x 4 steps
  CHECK(st.rhs_evaluations == 16 * 11 + 1);
}
