// The default integrator of `simulate bright` (srkn11b with the step chosen by an energy-error
// probe, automatic_step.hpp) on the paper's experiments 1 and 4 with no stepper settings given:
// energy drift <= 1e-9 and max E_x within 1e-4 of an independent reference, Odeint's RKF 7(8) at
// tolerance 1e-13.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>

#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/jobs/experiment_config.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using namespace lrchain::jobs;

namespace {

// The example's physics and run with the default integrator (no [integrator] table).
BrightRunConfig with_default_integrator(const char* file) {
  BrightRunConfig c = load_experiment_config(std::filesystem::path(LRCHAIN_SOURCE_DIR) / "examples" / file).bright;
  c.integrator = BrightRunConfig{}.integrator;
  return c;
}

void check_against_rkf78(BrightRunConfig c, Index expected_steps_per_sample) {
  const auto automatic = run_resonant_chain_bright(c).summary;
  REQUIRE(automatic.step_choice.has_value());
  CHECK(automatic.integrator.stepper == StepperKind::srkn11b);
  CHECK(automatic.step_choice->steps_per_sample == expected_steps_per_sample);
  CHECK(automatic.max_energy_drift <= 1e-9);
  c.integrator = IntegratorOptions{StepperKind::rkf78, 1e-13, 1e-13, 0.05};
  const auto reference = run_resonant_chain_bright(c).summary;
  CHECK(std::abs(automatic.max_Ex - reference.max_Ex) < 1e-4);
  CHECK(std::abs(automatic.final_Ex - reference.final_Ex) < 1e-4);
  CHECK(std::abs(automatic.centre_speed - reference.centre_speed) < 1e-4);
}

}  // namespace

// exp1 (examples/exp1_optical_pi2.toml) is tuned by hand to 2 srkn11b steps per sample interval
// (drift 3.0e-11, docs/simulator.md): the automatic step must find the same step count, so the
// default run costs what the tuned one does.
TEST_CASE("automatic step: exp1 with default options meets the drift and accuracy targets at the tuned cost" *
          doctest::test_suite("validation")) {
  check_against_rkf78(with_default_integrator("exp1_optical_pi2.toml"), 2);
}

// exp4 has a larger error constant: 4 steps per sample drift 2.6e-9, 5 steps 6.7e-10 (measured);
// the probe's target 2e-10 asks for 6.
TEST_CASE("automatic step: exp4 with default options meets the drift and accuracy targets" *
          doctest::test_suite("validation")) {
  check_against_rkf78(with_default_integrator("exp4_acoustic_1948.toml"), 6);
}
