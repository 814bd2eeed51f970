// Sampling option checks shared by the lattice runs (sampling_checks.hpp).
#include "sampling_checks.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

namespace {

// Whether a run of this configuration `length` long passes the size checks of its own length: its
// sample counts (sizes_at throws InvalidParameter past them) and memory within `memory_limit`
// (<= 0: unknown, no limit).
bool run_fits(const SamplingOptions& o, double length, double memory_limit) {
  if (!o.sizes_at) return length <= o.length;
  try {
    const ResourceEstimate e = estimate_lattice_run(o.sizes_at(length));
    return memory_limit <= 0 || e.memory_bytes <= memory_limit;
  } catch (const InvalidParameter&) {
    return false;
  }
}

// The times a continuation of the run can reach: [0, reach], reach the longest run of this
// configuration that fits (>= length). Found when a time lies beyond: `beyond` does not fit, so
// reach lies in [length, beyond); bisection (in log scale while the bracket is wide).
struct Reach {
  const SamplingOptions& o;
  double memory_limit;
  // A run that does not fit at its own length bounds nothing here: the run's own size check names
  // what is too large (sites, or its length), not a later time or the checkpoint interval.
  bool contains(double t) const {
    return t <= o.length * (1 + 1e-12) || !run_fits(o, o.length, memory_limit) || run_fits(o, t, memory_limit);
  }
  double longest(double beyond) const {
    double lo = o.length, hi = beyond;
    if (!run_fits(o, lo, memory_limit)) return lo;
    for (int i = 0; i < 400 && hi > lo * (1 + 1e-4); ++i) {
      const double mid = hi > 4 * lo ? std::exp((std::log(lo) + std::log(hi)) / 2) : (lo + hi) / 2;
      (run_fits(o, mid, memory_limit) ? lo : hi) = mid;
    }
    // Rounded down to the 4 significant digits the messages show, so the value shown is allowed.
    const double digit = std::pow(10.0, std::floor(std::log10(lo)) - 3);
    return std::max(o.length, std::floor(lo / digit) * digit);
  }
  // Why a time beyond the run's end is bounded: "(beyond the run's end, periods = 1, only ...)".
  std::string reason() const {
    return fmt::format("(beyond the run's end, {} = {:g}, only as far as a continuation with --restart can reach: "
                       "the longest run of this configuration whose samples fit in memory)",
                       o.length_name, o.length);
  }
};

double memory_limit_of(const SamplingOptions& o) { return o.max_memory > 0 ? o.max_memory : available_memory_bytes(); }

}  // namespace

void validate_sampling(const SamplingOptions& o) {
  const std::string units = o.in_periods ? " (units of T_b)" : "", tb = o.in_periods ? " T_b" : "";
  if (!(o.sample_every > 0 && o.sample_every <= o.length))
    throw InvalidParameter("sample_every", "must be in (0, " + o.length_name + "]" + units);
  if (o.spacetime_every && !(*o.spacetime_every >= o.sample_every && *o.spacetime_every <= o.length))
    throw InvalidParameter("spacetime_every", "must be in [sample-every, " + o.length_name + "]" + units);
  const Reach reach{o, o.sizes_at ? memory_limit_of(o) : 0};
  // Times beyond the end belong to a longer run made of restarts (they are part of the
  // checkpoint's identity): allowed when this run continues a checkpoint or writes one at its end.
  for (double t : o.snapshots) {
    if (!(t >= 0 && std::isfinite(t) && (o.continued_later || t <= o.length * (1 + 1e-12))))
      throw InvalidParameter("snapshots", fmt::format("snapshot time {}{} ({}) lies outside the run [0, {}]{}", t, tb,
                                                      o.snapshot_key, o.length, tb));
    if (!reach.contains(t))
      throw InvalidParameter("snapshots", fmt::format("snapshot time {:g}{} ({}) must be in [0, {:.4g}]{} {}", t, tb,
                                                      o.snapshot_key, reach.longest(t), tb, reach.reason()));
  }
  if (!(o.checkpoint_every == 0 || (o.checkpoint_every >= o.sample_every && std::isfinite(o.checkpoint_every))))
    throw InvalidParameter("checkpoint_every", "must be 0 (none) or a finite number >= sample-every" + units);
  if (o.checkpoint_every > 0 && !reach.contains(o.checkpoint_every))
    throw InvalidParameter("checkpoint_every",
                           fmt::format("must be 0 (none) or in [sample-every, {:.4g}]{} {}; got {:g}",
                                       reach.longest(o.checkpoint_every), tb, reach.reason(), o.checkpoint_every));
  for (const auto& [name, t] : o.later_times) {
    if (!std::isfinite(t)) throw InvalidParameter(name, "must be a finite number");
    if (!reach.contains(t))
      throw InvalidParameter(name, fmt::format("must be at most {:.4g}{} {}; got {:g}", reach.longest(t), tb,
                                               reach.reason(), t));
  }
}

}  // namespace lrchain::sim
