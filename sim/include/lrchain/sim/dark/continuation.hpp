#pragma once
// Pseudo-arclength continuation of a dark-breather family in omega_b (Sec. 5.3, Figs. 18, 21, 23),
// through turning points, with Floquet multipliers at every point (Sec. 5.4).
#include <Eigen/Dense>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

namespace lrchain::sim::dark {

struct ContinuationOptions {
  double ds = 0.02;          // initial arclength step in (q, omega_b)
  double ds_min = 1e-5;      // stop when the step falls below this
  double ds_max = 1.0;
  Index max_points = 100;
  double omega_min = 0;      // stop when omega_b leaves [omega_min, omega_max]
  double omega_max = 1e300;
  double direction = -1;     // initial sign of d omega_b (into the gap: -1)
  bool floquet = true;
  Index max_corrector = 12;
  double tolerance = 1e-11;  // max|F| at convergence
  const std::atomic<bool>* stop = nullptr;  // set (SIGINT/SIGTERM): end after the current point
};

struct BranchPoint {
  double omega_b = 0;
  Eigen::VectorXd z0;      // (x(0), y(0))
  DarkMeasures measures;
  FloquetResult floquet;   // empty multipliers if not requested
  Index iterations = 0;      // corrector iterations
  double residual = 0;     // max|F|
  double tangent_omega = 0;  // d omega_b / ds at this point
  std::optional<Index> contact_changes_per_period;  // over one period of this point (nullopt: not located)
};

struct BranchResult {
  std::vector<BranchPoint> points;
  std::vector<double> turning_points;  // omega_b where d omega_b/ds changes sign
  std::string stop_reason;
  bool interrupted = false;  // ended by ContinuationOptions::stop
};

// Continues from a converged solution q0 at omega0. on_point is called after each point. Stops (with
// stop_reason) after max_points, when omega_b leaves the window, when the step falls below ds_min,
// or when the corrector lands on the trivial state (amplitude <= trivial_state_ratio of q0's).
BranchResult continue_branch(const DarkShootingProblem& shooting, const Eigen::VectorXd& q0, double omega0,
                             const ContinuationOptions& options,
                             const std::function<void(const BranchPoint&)>& on_point = {});

// Checks the window of a continuation started at omega_b (InvalidParameter naming the option): the
// step ds in (0, 1] (it adapts within [1e-5, 1]), a finite omega_min below omega_b, and omega_max
// (none: the band edge) in (omega_b, 2 omega_top] with omega_top the top of the optical band.
void validate_continuation_window(const Params& p, double omega_b, double ds, double omega_min,
                                  std::optional<double> omega_max);

}  // namespace lrchain::sim::dark
