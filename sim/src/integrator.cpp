// Stepper selection and option checks for integrate_observed (Boost.Odeint).
#include "lrchain/sim/integrator.hpp"

#include <cstdint>

#include "vector_loops.hpp"

namespace lrchain::sim {

namespace detail {

// An entry is NaN or infinite iff its exponent bits are all ones; an integer OR-reduction, which
// GCC vectorises (a branch per entry cost ~1 ns per entry).
LRCHAIN_VECTOR_CLONES
bool all_finite(const double* x, std::size_t n) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000ull;
  std::uint64_t bad = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, x + i, sizeof bits);
    bad |= std::uint64_t((bits & exponent) == exponent);
  }
  return bad == 0;
}

}  // namespace detail

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
