// The stop flag a derivation polls between its steps (derivation_stop.hpp): one per thread.
#include "lrchain/derivation/derivation_stop.hpp"

namespace lrchain::derivation {

namespace {
thread_local const std::atomic<bool>* current_flag = nullptr;
}

DerivationStopScope::DerivationStopScope(const std::atomic<bool>* flag) : previous_(current_flag) {
  if (flag) current_flag = flag;
}

DerivationStopScope::~DerivationStopScope() { current_flag = previous_; }

void poll_derivation_stop() {
  if (current_flag && current_flag->load(std::memory_order_relaxed)) throw DerivationStopped();
}

}  // namespace lrchain::derivation
