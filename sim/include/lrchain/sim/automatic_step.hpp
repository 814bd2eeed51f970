#pragma once
// The fixed step of a symplectic stepper chosen for the user: the energy error of a symplectic
// method of order p stays bounded and scales as dt^p, and on the bright-breather runs it reaches
// its maximum within the first breather periods (exp1: 2.8e-11 after 2 T_b, 3.0e-11 over 200 T_b;
// exp4: 1.6e-9 and 2.6e-9). So a short probe run measures the error constant, and the step is the
// largest that divides each sample interval into equal steps and keeps the predicted error below a
// target, never longer than 0.9 / (largest linear frequency).
#include <cstdint>
#include <vector>

#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/state.hpp"
#include "lrchain/sim/step_choice.hpp"

namespace lrchain::sim {

// Order of accuracy of a fixed-step symplectic stepper (symplectic 4, srkn11b/srkn14a 6, ss17 8).
int symplectic_order(StepperKind k);

// Chooses the step of `stepper` (a symplectic one) for a run of `chain` from `initial` sampled every
// `sample_interval`: probes [0, probe_time], measures the energy error, predicts it for other
// steps as (dt / dt_probe)^order, and confirms the choice with a second probe when it changed.
StepChoice choose_symplectic_step(const DisplacementLattice& chain, const State& initial,
                                  double sample_interval, StepperKind stepper,
                                  const AutomaticStepOptions& options);

}  // namespace lrchain::sim
