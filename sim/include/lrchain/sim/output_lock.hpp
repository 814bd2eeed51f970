#pragma once
// Forwarding header: the lock on an output directory is the job layer's (lrchain/jobs/output_lock.hpp).
// Kept while cli/src/dark_command.cpp, regime_command.cpp and reproduce_command.cpp include this
// path (they link lrchain_jobs); include the jobs header there and delete this file. Not installed.
#include "lrchain/jobs/output_lock.hpp"

namespace lrchain::sim {
using jobs::OutputLock;
}  // namespace lrchain::sim
