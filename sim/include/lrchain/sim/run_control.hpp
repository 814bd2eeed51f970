#pragma once
// Interrupt and progress hooks a caller (the CLI) passes into a long run. No global state.
#include <atomic>
#include <functional>

namespace lrchain::sim {

struct RunControl {
  const std::atomic<bool>* stop = nullptr;        // set (e.g. by SIGINT) to end at the next sample
  std::function<void(double fraction)> progress;  // called at samples with t / t_end in [0, 1]
  bool stop_requested() const { return stop && stop->load(std::memory_order_relaxed); }
};

}  // namespace lrchain::sim
