// Stepper selection and option checks for integrate_observed (Boost.Odeint).
#include "lrchain/sim/integrator.hpp"

#include <cstdint>
#include <fmt/format.h>

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

std::size_t first_non_finite(const double* x, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return i;
  return n;
}

}  // namespace detail

std::string BlowUp::message() const {
  return fmt::format("the integration blew up (non-finite state) at t = {:.6g}, first at site n = {} ({})",
                     t, site, field);
}

std::optional<BlowUp> locate_blow_up(const IntegrationStats& stats, Index sites, Index first_label) {
  if (!stats.blew_up || sites <= 0) return std::nullopt;
  static const char* const fields[] = {"u", "v", "du/dt", "dv/dt"};
  BlowUp b;
  b.t = stats.t_reached;
  b.site = first_label + stats.blow_up_index % sites;
  b.field = fields[std::min<Index>(stats.blow_up_index / sites, 3)];
  return b;
}

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
  if (!is_symplectic(o.stepper) && !(o.abs_tol + o.rel_tol >= finest_tolerance))
    throw InvalidParameter("abs_tol", fmt::format("abs-tol + rel-tol must be at least {:g} (got abs-tol {:g}, rel-tol {:g}): "
                                                  "double precision resolves no smaller local error on the lattice's "
                                                  "O(1) state, and the steps would shrink towards zero; raise "
                                                  "--abs-tol or --rel-tol", finest_tolerance, o.abs_tol, o.rel_tol));
}

void validate_step_within_run(const IntegratorOptions& o, double run_length) {
  if (!(o.dt <= run_length))
    throw InvalidParameter("dt", fmt::format("must be in (0, {:.6g}]: a step may not exceed the run's length", run_length));
}

void validate_step_count(const IntegratorOptions& o, double duration) {
  if (!is_symplectic(o.stepper)) return;  // adaptive steppers grow their first step
  checked_count(duration / o.dt, "dt", 0, detail::max_fixed_steps,
                "fixed steps over the run (duration / dt)");
}

}  // namespace lrchain::sim
