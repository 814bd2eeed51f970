#pragma once
// How the fixed step of a symplectic run was chosen for the user (automatic_step.hpp), as reported
// with the run's results.
#include "lrchain/index.hpp"

namespace lrchain::sim {

struct AutomaticStepOptions {
  double energy_error_target = 2e-10;  // max |H(t) - H(0)| / H(0) the step aims at (5x below 1e-9)
  double probe_time = 0;               // length of the probe run (the caller: 2 breather periods)
};

struct StepChoice {
  double dt = 0;                        // the chosen step (sample interval / steps_per_sample)
  Index steps_per_sample = 0;
  double largest_linear_frequency = 0;  // max over branches and theta of omega(theta)
  double probe_energy_error = 0;        // measured with the chosen step over the probe run
  Index probe_runs = 0;
  double probe_seconds = 0;             // wall time of the probe runs
};

}  // namespace lrchain::sim
