#pragma once
// Stopping a derivation from outside (SIGINT/SIGTERM in a front end): while a DerivationStopScope
// lives on a thread, the derivation on that thread polls its flag between steps (each order of the
// multiple-scale expansion, each check, each emitted function) and throws DerivationStopped once it
// is set. GiNaC cannot be interrupted inside one operation; the expression bounds of model files
// (docs/models.md) keep each operation short.
#include <atomic>
#include <stdexcept>

namespace lrchain::derivation {

struct DerivationStopped : std::runtime_error {
  DerivationStopped() : std::runtime_error("the derivation was stopped") {}
};

class DerivationStopScope {
 public:
  explicit DerivationStopScope(const std::atomic<bool>* flag);  // nullptr: nothing to poll
  ~DerivationStopScope();
  DerivationStopScope(const DerivationStopScope&) = delete;
  DerivationStopScope& operator=(const DerivationStopScope&) = delete;

 private:
  const std::atomic<bool>* previous_;
};

// Throws DerivationStopped when the flag of this thread's innermost scope is set.
void poll_derivation_stop();

}  // namespace lrchain::derivation
