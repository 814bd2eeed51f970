#include "lrchain/derivation/symbolic_lock.hpp"

namespace lrchain::derivation {

std::recursive_mutex& symbolic_engine_mutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

}  // namespace lrchain::derivation
