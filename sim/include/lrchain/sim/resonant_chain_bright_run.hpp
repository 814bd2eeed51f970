#pragma once
// Experiment of Sec. 4.1-4.3: start the lattice from the NLS bright breather (eq:focus_app,
// eq:focus_ini), integrate, and compare with the ansatz: E_x(t), E_y(t), energy density
// (eq:edensity), energy centre (eq:ectr), snapshots.
//
// The strain lattice eq:Hertzd0S on sites n = -N..N with zero-strain ends is integrated in its
// equivalent displacement form: free-end beads n = -N-1..N (x_n = u_n - u_{n-1}), which also gives
// u_n, v_n for the energy density. With `ansatz_ends` the ghost beads n = -N-2 and N+1 follow the
// ansatz u_n^A(t) instead (the "emitting" boundary conditions of Sec. 4.2).
#include <optional>
#include <string>
#include <vector>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator_options.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "lrchain/sim/run_control.hpp"
#include "lrchain/sim/run_record.hpp"
#include "lrchain/sim/step_choice.hpp"
#include "lrchain/sim/trailing_structure.hpp"

namespace lrchain::sim {

inline std::vector<double> default_bright_snapshot_periods() { return {0.0, 50.125, 200.0}; }

struct BrightRunConfig {
  Params params;
  Branch branch = Branch::optical;
  double theta = 0;
  std::optional<double> detuning;  // omega_b - omega; default sign(h_tilde) 1e-4
  double n0 = 0;                   // initial centre
  Index N = 500;                   // strain sites n = -N..N (`sites` = 2N + 1 to the user: strain_sites.hpp)
  double periods = 200;            // run length in T_b
  double sample_every = 0.25;      // E_x, E_y, energy, centre sampled every this many T_b
  double spacetime_every = 1.0;    // energy density row every this many T_b
  // Snapshot times in T_b, each in [0, periods]; the default list (the paper's run of 200 T_b)
  // keeps only those inside a shorter run.
  std::vector<double> snapshot_periods = default_bright_snapshot_periods();
  Index centre_window = 100;        // m of eq:ectr
  double error_window_end = -1;     // also report max E_x, E_y over t <= this (if > 0)
  bool ansatz_ends = false;
  TrailingStructureOptions trailing;  // secondary structure behind the breather (fit_start > 0)
  // Default: srkn11b with the step chosen by a 2 T_b probe run (automatic_step.hpp).
  IntegratorOptions integrator{.stepper = StepperKind::srkn11b, .automatic_dt = true};
  double step_energy_error_target = 2e-10;  // the automatic step's target (5x below 1e-9)
  double max_memory = 0;  // bytes the run may use (--max-memory); 0: the machine's available memory
  double checkpoint_every = 0;  // T_b between checkpoints (0: only at an interrupt)
  std::string checkpoint_file;  // where checkpoints go (empty: none)
  bool checkpoint_at_end = false;  // also write one at the end, to extend the run later
  std::string restart_file;     // continue from this checkpoint (empty: start at t = 0)
};
// Checks every option, the sample counts and the memory estimate (InvalidParameter naming the
// option); nothing is allocated before this.
void validate(const BrightRunConfig& c);
// Memory and output size of the run (resource_estimate.hpp).
ResourceEstimate estimate_resources(const BrightRunConfig& c);
// The snapshot times of the run in T_b: the given ones, or the default ones inside the run.
std::vector<double> snapshot_periods_in_run(const BrightRunConfig& c);

struct BrightRunSummary {
  double omega = 0, omega_b = 0, period = 0, group_velocity = 0, curvature = 0, h_tilde = 0;
  double M1 = 0, M2 = 0, inverse_width = 0;
  double x0_inf = 0, y0_inf = 0;          // ||x(0)||_inf, ||y(0)||_inf
  double max_Ex = 0, max_Ey = 0;          // over the whole run
  double max_Ex_window = 0, max_Ey_window = 0;  // over t <= error_window_end
  double final_Ex = 0, final_Ey = 0;
  double energy0 = 0, max_energy_drift = 0;   // max |H(t) - H(0)| / H(0) (autonomous ends)
  double centre_speed = 0;                // least-squares slope of X(t) (eq:ectr)
  double centre_start = 0, centre_end = 0;
  double t_end = 0;                       // time reached
  double t_start = 0;                     // 0, or the time of the checkpoint restarted from
  Index checkpoints_written = 0;
  double last_checkpoint_time = -1;       // of the last checkpoint written (< 0: none)
  bool interrupted = false, blew_up = false;
  std::optional<BlowUp> blow_up;  // when and where, if blew_up
  TrailingStructure trailing;             // if config.trailing.fit_start > 0
  IntegrationStats stats;
  double solve_seconds = 0;
  IntegratorOptions integrator;           // as used: with the automatic step resolved
  std::optional<StepChoice> step_choice;  // how the step was chosen, when automatic
};

struct BrightRunResult {
  BrightRunSummary summary;
  RunRecord record;  // series (t, E_x, E_y, energy, X), e_n space-time, snapshots
};

BrightRunResult run_resonant_chain_bright(const BrightRunConfig& c, const RunControl& control = {});

// What a bright run keeps from one run to the next (a sweep holds one per thread): the lattice
// (rebuilt only when the parameters, the size or the ends change), the state, the observers' arrays
// and the record. Every buffer grows to the largest run it has seen and keeps its capacity.
struct BrightWorkspace {
  std::optional<DisplacementLattice> chain;
  Params chain_params;
  Index chain_beads = 0;
  bool chain_ansatz_ends = false;
  const BrightBreatherAnsatz* ansatz = nullptr;  // of the run under way: the prescribed ends follow it
  State state;
  std::vector<double> x, y, x_ansatz, y_ansatz, energy_density, scratch, times, snapshot_times, centre_t, centre_x;
  RunRecord record;  // the last run's record
};

// The same run (bit for bit) in `workspace`, whose record holds the run's record afterwards.
BrightRunSummary run_resonant_chain_bright(const BrightRunConfig& c, BrightWorkspace& workspace, const RunControl& control = {});

}  // namespace lrchain::sim
