#pragma once
// Interrupt, progress and checkpoint hooks a caller (a job) passes into a long run. No global state.
#include <atomic>
#include <functional>
#include <span>

#include "lrchain/index.hpp"
#include "lrchain/sim/checkpoint_store.hpp"

namespace lrchain::sim {

// The lattice at one sample time of a run, for a caller's own measures (RunControl::on_sample).
struct SampleView {
  double t = 0;
  Index first_label = 0;              // site label n of primary[0] and secondary[0]
  std::span<const double> primary;    // bright: strains x_n; drive, modulated: displacements u_n
  std::span<const double> secondary;  // bright: strains y_n; drive, modulated: displacements v_n
  Index energy_first_label = 0;       // bead label n of energy_density[0]
  std::span<const double> energy_density;  // e_n (eq:edensity)
};

struct RunControl {
  const std::atomic<bool>* stop = nullptr;        // set (e.g. by SIGINT) to end at the next sample
  std::function<void(double fraction)> progress;  // called at samples with t / t_end in [0, 1]
  std::function<void(const SampleView&)> on_sample;  // called at every sample (also the first)
  // Where the bright, drive and modulated runs save checkpoints and restart from (empty: none).
  // A config that names a checkpoint or restart file needs one (jobs::with_checkpoint_files).
  CheckpointStore checkpoints;
  bool stop_requested() const { return stop && stop->load(std::memory_order_relaxed); }
};

}  // namespace lrchain::sim
