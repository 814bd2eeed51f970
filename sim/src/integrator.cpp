// Stepper selection and option checks for integrate_observed (Boost.Odeint).
#include "lrchain/sim/integrator.hpp"

namespace lrchain::sim {

StepperKind parse_stepper(std::string_view text) {
  if (text == "rkf78") return StepperKind::rkf78;
  if (text == "dopri5") return StepperKind::dopri5;
  if (text == "symplectic") return StepperKind::symplectic;
  if (text == "srkn11b") return StepperKind::srkn11b;
  if (text == "srkn14a") return StepperKind::srkn14a;
  if (text == "ss17") return StepperKind::ss17;
  throw InvalidParameter("stepper",
                         "must be one of rkf78, dopri5, symplectic, srkn11b, srkn14a, ss17");
}

std::string_view to_string(StepperKind k) {
  switch (k) {
    case StepperKind::rkf78: return "rkf78";
    case StepperKind::dopri5: return "dopri5";
    case StepperKind::symplectic: return "symplectic";
    case StepperKind::srkn11b: return "srkn11b";
    case StepperKind::srkn14a: return "srkn14a";
    case StepperKind::ss17: return "ss17";
  }
  return "?";
}

bool is_symplectic(StepperKind k) {
  return k == StepperKind::symplectic || k == StepperKind::srkn11b || k == StepperKind::srkn14a ||
         k == StepperKind::ss17;
}

void validate(const IntegratorOptions& o) {
  if (!(o.abs_tol > 0 && o.abs_tol < 1)) throw InvalidParameter("abs_tol", "must be in (0, 1)");
  if (!(o.rel_tol >= 0 && o.rel_tol < 1)) throw InvalidParameter("rel_tol", "must be in [0, 1)");
  if (!(o.dt > 0 && std::isfinite(o.dt))) throw InvalidParameter("dt", "must be a finite number > 0");
}

}  // namespace lrchain::sim
