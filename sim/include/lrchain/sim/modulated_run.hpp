#pragma once
// Experiment 7 (Sec. 5.1, Fig. 16): periodic chain of eq:Hertz (u_{n+N} = u_n) started from the
// slowly modulated acoustic wave eq:cimi; long run with checkpoint/restart. Records e_n(t)
// (eq:edensity), the contrast of e_n (instability detector), the position of the minimum of the
// smoothed e_n (dark-breather centre) and velocity snapshots.
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/integrator_options.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/sim/run_control.hpp"
#include "lrchain/sim/run_record.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

inline std::vector<double> default_modulated_snapshot_times() { return {0, 17100, 32400}; }

struct ModulatedRunConfig {
  std::string name = "modulated";
  Params params{1.5, 0.27, 1.0, 0.32};
  Index N = 401;                      // periodic chain, n = 0..N-1; the user's `sites`
  double epsilon = 0.03;              // eq:cimi amplitude
  double theta_waves = 252;           // theta0 = theta_waves * pi / N
  double b = 0.01;                    // modulation depth; the user's `modulation_depth`
  double t_end = 45000;
  double sample_every = 10;           // series rows and e_n(t) rows
  // Snapshot times, each in [0, t_end]; the default list keeps only those inside a shorter run.
  std::vector<double> snapshot_times = default_modulated_snapshot_times();
  double contrast_threshold = 0.2;    // instability time: first t with (max e - min e)/mean e above this
  Index dark_window = 9;              // running mean (sites) before locating min e_n
  double speed_fit_start = 30000, speed_fit_end = 33000;  // dark-breather speed fit window
  double checkpoint_every = 1000;     // time units between checkpoints (0: none)
  std::string checkpoint_file;        // where to write checkpoints (empty: none)
  std::string restart_file;           // continue from this checkpoint (empty: start at t = 0)
  IntegratorOptions integrator{StepperKind::symplectic, 1e-12, 1e-12, 0.05};
  double max_memory = 0;  // bytes the run may use (--max-memory); 0: the machine's available memory
};
// Checks every option, the sample and checkpoint counts and the memory estimate (InvalidParameter
// naming the option); nothing is allocated or written before this.
void validate(const ModulatedRunConfig& c);
// Memory and output size of the run from t = 0 (resource_estimate.hpp).
ResourceEstimate estimate_resources(const ModulatedRunConfig& c);
// The snapshot times of the run: the given ones, or the default ones inside the run.
std::vector<double> snapshot_times_in_run(const ModulatedRunConfig& c);

// Initial condition eq:cimi: u, v and their rates on the periodic chain (layout of State).
State modulated_initial_state(const ModulatedRunConfig& c, double& omega, double& theta0);

struct ModulatedRunSummary {
  double theta0 = 0, omega = 0;     // carrier and omega_-(theta0)
  double group_velocity = 0;        // omega_-'(theta0)
  double t_start = 0;               // 0, or the time of the checkpoint restarted from
  double initial_contrast = 0;
  std::optional<double> instability_time;  // first t with contrast > threshold, if any
  double dark_speed = 0;            // |slope| of the unwrapped min-e position over the fit window
  Index dark_samples = 0;           // samples in that window
  double energy0 = 0, max_energy_drift = 0;
  double t_end = 0;
  Index checkpoints_written = 0;
  double last_checkpoint_time = -1;  // of the last checkpoint written (< 0: none)
  bool interrupted = false, blew_up = false;
  std::optional<BlowUp> blow_up;  // when and where, if blew_up
  IntegrationStats stats;
  double solve_seconds = 0;
};

struct ModulatedRunResult {
  ModulatedRunSummary summary;
  RunRecord record;
};

ModulatedRunResult run_modulated(const ModulatedRunConfig& c, const RunControl& control = {});

}  // namespace lrchain::sim
