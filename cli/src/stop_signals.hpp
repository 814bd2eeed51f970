#pragma once
// SIGINT/SIGTERM for long runs (simulate, dark continue): the first signal sets a flag the run
// polls at its next step boundary (or branch point), so it can write a checkpoint and its outputs
// so far; a second signal ends the process at once.
#include <atomic>

namespace lrchain::cli {

// Installs the handlers for SIGINT and SIGTERM for its lifetime (clearing the flag first) and
// restores the default actions afterwards. Nested (a model compiled inside a run's scope): the
// inner one changes nothing, so the outer run still sees a signal the compile received.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  // The flag a run polls (lrchain::sim::RunControl::stop).
  static const std::atomic<bool>* flag();
  // The signal received (SIGINT or SIGTERM), 0 if none.
  static int received();
  // "SIGINT" or "SIGTERM".
  static const char* name(int signal_number);
};

}  // namespace lrchain::cli
