#pragma once
// The checks of the sampling options every lattice run (bright, drive, modulated) shares: sample
// and energy-density row intervals, snapshot times and the checkpoint interval, against the run
// length. Private to sim/src.
#include <optional>
#include <string>
#include <vector>

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
};

// Throws InvalidParameter naming the first option out of range: sample-every in (0, length],
// spacetime-every in [sample-every, length], snapshots in [0, length] (beyond when continued
// later), checkpoint-every 0 or >= sample-every.
void validate_sampling(const SamplingOptions& o);

}  // namespace lrchain::sim
