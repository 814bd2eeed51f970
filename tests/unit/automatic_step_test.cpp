// The automatic step of the symplectic steppers (automatic_step.hpp) on a short exp1-like run.
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/sim/automatic_step.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

// The paper's chain, optical branch, theta = pi/2 (exp1's breather) on a short lattice and run.
BrightRunConfig short_exp1() {
  BrightRunConfig c;
  c.params = Params{1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0};
  c.branch = Branch::optical;
  c.theta = M_PI / 2;
  c.N = 200;
  c.periods = 4;
  c.snapshot_periods = {};
  return c;
}

}  // namespace

TEST_CASE("automatic step: the default bright run picks srkn11b with a step that meets its energy target") {
  const auto s = run_resonant_chain_bright(short_exp1()).summary;
  REQUIRE(s.step_choice.has_value());
  CHECK(s.integrator.stepper == StepperKind::srkn11b);
  CHECK_FALSE(s.integrator.automatic_dt);
  // Largest linear frequency of the chain (K2 = 1, kappa = 1, rho = 1/3): the optical branch at
  // theta = pi, omega^2 = 6 (root of (5 - w^2)(1 - w^2/3) = 1, by hand).
  CHECK(s.step_choice->largest_linear_frequency == doctest::Approx(std::sqrt(6.0)).epsilon(1e-12));
  CHECK(s.step_choice->probe_energy_error <= 2e-10);
  CHECK(s.integrator.dt == doctest::Approx(s.period * 0.25 / double(s.step_choice->steps_per_sample)));
  CHECK(s.max_energy_drift <= 1e-9);
}

TEST_CASE("automatic step: a target 2^6 times tighter doubles the srkn11b step count (order 6)") {
  BrightRunConfig c = short_exp1();
  const auto loose = run_resonant_chain_bright(c).summary;
  c.step_energy_error_target /= 64;
  const auto tight = run_resonant_chain_bright(c).summary;
  REQUIRE(loose.step_choice.has_value());
  REQUIRE(tight.step_choice.has_value());
  // The energy error of an order-6 method falls by 2^6 when the step halves: the tight target
  // needs about twice the steps (one more or less from rounding to whole steps per sample).
  CHECK(tight.step_choice->steps_per_sample >= 2 * loose.step_choice->steps_per_sample - 1);
  CHECK(tight.step_choice->steps_per_sample <= 2 * loose.step_choice->steps_per_sample + 1);
  CHECK(tight.step_choice->probe_energy_error <= 2e-10 / 64);
  CHECK(symplectic_order(StepperKind::symplectic) == 4);
  CHECK(symplectic_order(StepperKind::ss17) == 8);
}
