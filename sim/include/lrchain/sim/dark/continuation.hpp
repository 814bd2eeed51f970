#pragma once
// Pseudo-arclength continuation of a dark-breather family in omega_b (Sec. 5.3, Figs. 18, 21, 23),
// through turning points, with Floquet multipliers at every point (Sec. 5.4).
#include <Eigen/Dense>
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
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
  double omega_min = 0;      // stop when the parameter (omega_b) leaves [omega_min, omega_max]
  double omega_max = 1e300;
  // A point beyond the window is replaced by the solution at the bound it crossed (Newton at that
  // parameter value from the interpolated state), the branch's last point: e.g. C = 0 exactly.
  bool land_on_bounds = false;
  double direction = -1;     // initial sign of d omega_b (into the gap: -1)
  // Weight w of the unknowns against omega_b in the arclength: |du|^2 = w |dq|^2 + domega_b^2.
  // 1: unweighted (the resonant chain's figures). 0: chosen at the first point so that the state's
  // part of the first step weighs as much as omega_b's (w |dq/domega_b|^2 = 1, at most 1/unknowns):
  // ds is then a step of about ds/sqrt(2) in omega_b there, and more than that where the state moves
  // more slowly, however many unknowns (model files, issue 27).
  double state_weight = 1;
  bool floquet = true;
  Index max_corrector = 12;
  // The step grows by 1.5 after a point that took at most easy_corrector chord iterations and shrinks
  // by 0.7 after one that took hard_corrector or more (the chord corrector converges linearly: a model
  // file's 1e-11 takes 5-6 at a good step).
  Index easy_corrector = 4, hard_corrector = 7;
  // The chord corrector takes a fresh Jacobian when an iteration reduced max|F| by less than this factor.
  double chord_contraction = 0.5;
  double tolerance = 1e-11;  // max|F| at convergence
  const std::atomic<bool>* stop = nullptr;  // set (SIGINT/SIGTERM): end after the current point
};

struct BranchPoint {
  double omega_b = 0;
  double parameter = 0;    // the continued parameter's value (omega_b when continuing in omega_b)
  Eigen::VectorXd z0;      // (x(0), y(0))
  DarkMeasures measures;
  FloquetResult floquet;   // empty multipliers if not requested
  Index iterations = 0;      // corrector iterations
  double residual = 0;     // max|F|
  double tangent_omega = 0;  // d omega_b / ds at this point
  std::optional<Index> contact_changes_per_period;  // over one period of this point (nullopt: not located)
};

// A fold (turning point) between two branch points: where d omega_b/ds, interpolated linearly in the
// arclength between them, vanishes; omega_b there from the cubic Hermite interpolant of omega_b(s)
// (its values and slopes at both points), norm_squared linearly.
struct FoldPoint {
  Index after = 0;         // between points after and after + 1
  double fraction = 0;     // of the arclength between them
  double omega_b = 0;      // the continued parameter's value at the fold (omega_b when continuing in omega_b)
  double norm_squared = 0;  // ||Z(0)||^2 (eq:l2norm) interpolated
};

// Why a branch ended: the points asked for, the parameter window, the trivial state, the step below
// ds_min (the corrector could not go on: a failure), or a signal.
enum class BranchStop { points, window, trivial_state, step_too_small, interrupted };
std::string_view to_string(BranchStop stop);

struct BranchResult {
  std::vector<BranchPoint> points;
  std::vector<double> turning_points;  // omega_b where d omega_b/ds changes sign (the later point's)
  std::vector<FoldPoint> folds;        // the same turning points, interpolated
  std::string stop_reason;
  BranchStop stop = BranchStop::points;
  double state_weight = 1;   // the arclength's weight w used (ContinuationOptions::state_weight)
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
