#pragma once
// GiNaC and CLN are not thread-safe (shared reference counts, global caches): every use of the
// symbolic engine that can run beside another thread (the run-time model compiler, the GiNaC
// fallback evaluators, the Python module's threads) holds this one process-wide lock.
#include <mutex>

namespace lrchain::derivation {

// The process-wide lock around the symbolic engine (recursive: a derivation may compile a model).
std::recursive_mutex& symbolic_engine_mutex();

}  // namespace lrchain::derivation
