#pragma once
// The checks of the sampling options every lattice run (bright, drive, modulated) shares: sample
// and energy-density row intervals, snapshot times and the checkpoint interval, against the run
// length. Private to sim/src.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/sim/resource_estimate.hpp"

namespace lrchain::sim {

struct SamplingOptions {
  double length = 0;                       // the run's length: periods (bright) or t_end
  std::string length_name;                 // "periods", "t_end"
  bool in_periods = false;                 // lengths in breather periods T_b (bright)
  double sample_every = 0;
  std::optional<double> spacetime_every;   // bright and drive; modulated rows come with the samples
  double checkpoint_every = 0;             // 0: none
  std::vector<double> snapshots;           // the snapshot times the run would use
  bool continued_later = false;            // a checkpoint continues it: snapshots may lie beyond
  std::string snapshot_key;                // the config key of the snapshots ("snapshot_times")
  // Further times of the run (option name, time in the run's units): a switch-off time, the ends of
  // fit windows. They may lie beyond the run's end (a fit window there gives null now, and applies
  // to a continuation with --restart), but only as far as a continuation can reach.
  std::vector<std::pair<std::string, double>> later_times;
  // The run's sizes were it `length` long, and the memory it may use (--max-memory; 0: the
  // machine's available memory): what bounds a continuation (its record holds the whole history).
  std::function<LatticeRunSizes(double length)> sizes_at;
  double max_memory = 0;
};

// Throws InvalidParameter naming the first option out of range: sample-every in (0, length],
// spacetime-every in [sample-every, length], snapshots in [0, length] (beyond when continued
// later), checkpoint-every 0 or in [sample-every, reach], the later times at most reach, where
// reach >= length is the longest run of this configuration whose samples and memory fit (the
// limits length itself has): a time beyond it no continuation can ever get to.
void validate_sampling(const SamplingOptions& o);

}  // namespace lrchain::sim
