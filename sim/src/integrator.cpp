// Stepper selection and option checks for integrate_observed (Boost.Odeint).
#include "lrchain/sim/integrator.hpp"

namespace lrchain::sim {

StepperKind parse_stepper(std::string_view text) {
  if (text == "rkf78") return StepperKind::rkf78;
  if (text == "dopri5") return StepperKind::dopri5;
  if (text == "symplectic") return StepperKind::symplectic;
  throw InvalidParameter("stepper", "must be one of rkf78, dopri5, symplectic");
}

std::string_view to_string(StepperKind k) {
  switch (k) {
    case StepperKind::rkf78: return "rkf78";
    case StepperKind::dopri5: return "dopri5";
    case StepperKind::symplectic: return "symplectic";
  }
  return "?";
}

void validate(const IntegratorOptions& o) {
  if (!(o.abs_tol > 0 && o.abs_tol < 1)) throw InvalidParameter("abs_tol", "must be in (0, 1)");
  if (!(o.rel_tol >= 0 && o.rel_tol < 1)) throw InvalidParameter("rel_tol", "must be in [0, 1)");
  if (!(o.dt > 0 && std::isfinite(o.dt))) throw InvalidParameter("dt", "must be a finite number > 0");
}

}  // namespace lrchain::sim
