// Sampling option checks shared by the lattice runs (sampling_checks.hpp).
#include "sampling_checks.hpp"

#include <cmath>
#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

void validate_sampling(const SamplingOptions& o) {
  const std::string units = o.in_periods ? " (units of T_b)" : "", tb = o.in_periods ? " T_b" : "";
  if (!(o.sample_every > 0 && o.sample_every <= o.length))
    throw InvalidParameter("sample-every", "must be in (0, " + o.length_name + "]" + units);
  if (o.spacetime_every && !(*o.spacetime_every >= o.sample_every && *o.spacetime_every <= o.length))
    throw InvalidParameter("spacetime-every", "must be in [sample-every, " + o.length_name + "]" + units);
  // Times beyond the end belong to a longer run made of restarts (they are part of the
  // checkpoint's identity): allowed when this run continues a checkpoint or writes one at its end.
  for (double t : o.snapshots)
    if (!(t >= 0 && std::isfinite(t) && (o.continued_later || t <= o.length * (1 + 1e-12))))
      throw InvalidParameter("snapshots", fmt::format("snapshot time {}{} ({}) lies outside the run [0, {}]{}", t, tb,
                                                      o.snapshot_key, o.length, tb));
  if (!(o.checkpoint_every == 0 || (o.checkpoint_every >= o.sample_every && std::isfinite(o.checkpoint_every))))
    throw InvalidParameter("checkpoint-every", "must be 0 (none) or a finite number >= sample-every" + units);
}

}  // namespace lrchain::sim
