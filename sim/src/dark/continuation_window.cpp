// The window of a dark-breather continuation (continuation.hpp), checked the same way for the CLI
// and the Python module.
#include <cmath>
#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/sim/dark/continuation.hpp"

namespace lrchain::sim::dark {

void validate_continuation_window(const Params& p, double omega_b, double ds, double omega_min,
                                  std::optional<double> omega_max) {
  if (!(ds > 0 && ds <= 1)) throw InvalidParameter("ds", "must be in (0, 1] (the step adapts within [1e-5, 1])");
  if (!(std::isfinite(omega_min) && omega_min < omega_b))
    throw InvalidParameter("omega_min", fmt::format("must be a finite number below omega-b = {:g}", omega_b));
  if (!omega_max) return;
  const double top = regime::frequency_band(p, Branch::optical).hi;  // of the linear spectrum
  const double highest = regime::max_frequency_over_spectrum_top * top;
  if (!(*omega_max > omega_b && *omega_max <= highest))
    throw InvalidParameter("omega_max", fmt::format("must be in (omega-b, {:g} omega_top] = ({:g}, {:.6g}] (omega_top = "
                                                    "{:.6g}, the top of the optical band; default: the band edge)",
                                                    regime::max_frequency_over_spectrum_top, omega_b, highest, top));
}

}  // namespace lrchain::sim::dark
