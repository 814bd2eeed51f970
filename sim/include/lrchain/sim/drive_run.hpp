#pragma once
// Experiment 6 (Sec. 4.3, Figs. 14, 15): a chain at rest, beads n = 1..beads of eq:Hertz, clamped
// far end u_{beads+1} = 0, first bead driven by u_0(t) = A0 sin(omega0 t) chi(t) with the plateau
// chi(t) = tanh(r t) (1 - tanh(r (t - t_m))) / 2. Records e_n(t) (eq:edensity), the front of the
// wave pattern, the participation number of e_n, and velocity snapshots.
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/integrator_options.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/sim/run_control.hpp"
#include "lrchain/sim/run_record.hpp"

namespace lrchain::sim {

inline std::vector<double> default_drive_snapshot_times() { return {779.9, 2400}; }

struct DriveRunConfig {
  Params params{1.5, 4.0 / 9.0, 1.0, 10.0};
  Index beads = 2000;           // n = 1..beads, u_{beads+1} = 0 (clamped); the user's `sites`
  double amplitude = 0.06;      // A0
  double omega0 = 2.1;          // driving frequency
  double ramp_rate = 0.046;     // r of chi(t)
  double t_m = 700;             // switch-off time of chi(t); the user's `switch_off_time`
  double t_end = 2400;
  double sample_every = 1.0;    // series (energy, front, participation)
  double spacetime_every = 2.0; // rows of e_n(t)
  // Snapshot times, each in [0, t_end]; the default list keeps only those inside a shorter run.
  std::vector<double> snapshot_times = default_drive_snapshot_times();
  double front_fraction = 0.1;  // front = largest n with e_n > front_fraction * max_n e_n
  double front_fit_start = 100, front_fit_end = 700;  // window of the front-speed fit
  IntegratorOptions integrator{StepperKind::rkf78, 1e-10, 1e-10, 0.05};
  double max_memory = 0;  // bytes the run may use (--max-memory); 0: the machine's available memory
  double checkpoint_every = 0;  // time between checkpoints (0: only at an interrupt)
  std::string checkpoint_file;  // where checkpoints go (empty: none)
  bool checkpoint_at_end = false;  // also write one at the end, to extend the run later
  std::string restart_file;     // continue from this checkpoint (empty: start at t = 0)
};
// Checks every option, the sample counts and the memory estimate (InvalidParameter naming the
// option); nothing is allocated before this.
void validate(const DriveRunConfig& c);
// Memory and output size of the run (resource_estimate.hpp).
ResourceEstimate estimate_resources(const DriveRunConfig& c);
// The snapshot times of the run: the given ones, or the default ones inside the run.
std::vector<double> snapshot_times_in_run(const DriveRunConfig& c);

// chi(t) of Sec. 4.3.
double drive_envelope(double t, double r, double t_m);

struct DriveRunSummary {
  double theta = 0;            // omega_+(theta) = omega0 (optical branch)
  double group_velocity = 0;   // c_+ = omega_+'(theta)
  double front_speed = 0;      // least-squares slope of the front over the fit window
  Index front_samples = 0;     // samples in that window (the speed needs at least 2)
  double final_participation = 0;  // (sum e)^2 / sum e^2 at t_end (sites carrying energy)
  double max_participation = 0;
  Index final_peaks = 0;       // local maxima of e_n (3-site smoothed) above 10 % of the maximum
  double final_energy = 0;     // total energy at t_end
  double max_energy = 0;
  double t_end = 0;
  double t_start = 0;          // 0, or the time of the checkpoint restarted from
  Index checkpoints_written = 0;
  double last_checkpoint_time = -1;  // of the last checkpoint written (< 0: none)
  bool interrupted = false, blew_up = false;
  std::optional<BlowUp> blow_up;  // when and where, if blew_up
  IntegrationStats stats;
  double solve_seconds = 0;
};

struct DriveRunResult {
  DriveRunSummary summary;
  RunRecord record;
};

DriveRunResult run_drive(const DriveRunConfig& c, const RunControl& control = {});

}  // namespace lrchain::sim
