#pragma once
// The choices and statistics of a lattice time integration (the public part of integrator.hpp):
// which stepper, its tolerances or step, the step and right-hand-side counts, and where a run that
// blew up first became non-finite.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/index.hpp"

namespace lrchain::sim {

enum class StepperKind { rkf78, dopri5, symplectic, srkn11b, srkn14a, ss17 };
StepperKind parse_stepper(std::string_view text);  // throws InvalidParameter("stepper", ...)
std::string_view to_string(StepperKind k);
// The symplectic steppers (symplectic, srkn11b, srkn14a, ss17) integrate autonomous systems only.
bool is_symplectic(StepperKind k);

struct IntegratorOptions {
  StepperKind stepper = StepperKind::rkf78;
  double abs_tol = 1e-12;  // absolute local error tolerance (adaptive steppers)
  double rel_tol = 1e-12;  // relative local error tolerance (adaptive steppers)
  double dt = 0.05;        // initial step (adaptive) or fixed step (symplectic)
  // Fixed-step steppers: the run chooses dt itself from a probe of the energy error
  // (automatic_step.hpp) and `dt` is ignored; set where the user gave no step.
  bool automatic_dt = false;
};
// abs_tol in (0, 1), rel_tol in [0, 1), dt finite > 0; and for the adaptive steppers (rkf78,
// dopri5), which accept a step when its error estimate at each entry x is below
// abs_tol + rel_tol |x|, a tolerance double precision can meet on the lattices' O(1) states:
// abs_tol + rel_tol >= finest_tolerance (1e-15), else InvalidParameter("abs_tol") whose message
// names both options. (At an entry |x| <= 1 the tolerance is then >= 1e-15 |x|; the fixed-step
// steppers ignore the tolerances and are not checked.)
void validate(const IntegratorOptions& o);
// Refuses (InvalidParameter("dt")) a first or largest step dt longer than the whole run (t_end).
void validate_step_within_run(const IntegratorOptions& o, double run_length);
// The fixed-step steppers take about `duration / dt` steps: refuses (InvalidParameter("dt")) a dt
// that gives more than 1e12 steps (years of work) or a step count that overflows an integer.
void validate_step_count(const IntegratorOptions& o, double duration);
// The smallest local error, relative to the state's scale, that double precision can resolve:
// about 4.5 units in the last place (2^-52 = 2.2e-16). A tolerance below it only makes the
// adaptive steps shrink towards zero (rkf78 with abs_tol 1e-300 and rel_tol 0 crawls at steps of
// ~1e-37 and never reaches the next sample).
inline constexpr double finest_tolerance = 1e-15;

struct IntegrationStats {
  Index steps = 0;
  Index rhs_evaluations = 0;
  double t_reached = 0;     // time of the last observation made
  bool stopped = false;     // the observer or the step-boundary hook asked to stop (interrupt)
  bool blew_up = false;     // the state became non-finite
  Index blow_up_index = 0;  // when blew_up: first non-finite entry of the state vector
};

// Where a blown-up integration of a displacement-form state (state.hpp) first became non-finite.
struct BlowUp {
  double t = 0;       // observation time at which the state was found non-finite
  Index site = 0;     // label of the first site with a non-finite entry
  std::string field;  // "u", "v", "du/dt" or "dv/dt"
  std::string message() const;  // "the integration blew up (non-finite state) at t = ..., ..."
};
// The blow-up recorded in `stats`, if any, on `sites` sites labelled first_label, first_label + 1, ...
std::optional<BlowUp> locate_blow_up(const IntegrationStats& stats, Index sites, Index first_label);

}  // namespace lrchain::sim
