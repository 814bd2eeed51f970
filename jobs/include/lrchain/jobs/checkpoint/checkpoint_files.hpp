#pragma once
// The simulate jobs' checkpoints as files: a sim::CheckpointStore whose save writes a checkpoint file
// (checkpoint_file.hpp: format 3, temporary name + rename) and whose load reads one for a restart
// and checks it against the run (identity, state size, record, end time, accumulators).
#include <string>

#include "lrchain/sim/checkpoint_store.hpp"
#include "lrchain/sim/run_control.hpp"

namespace lrchain::jobs {

// Saves to `checkpoint_file` (empty: no save) and restarts from `restart_file` (empty: no load).
// The checkpoint's directory must exist (checked by the simulate job before the run).
sim::CheckpointStore checkpoint_files(const std::string& checkpoint_file, const std::string& restart_file);

// `control` with the store of a run config's checkpoint_file and restart_file (bright, drive, modulated).
template <class RunConfig>
sim::RunControl with_checkpoint_files(sim::RunControl control, const RunConfig& c) {
  control.checkpoints = checkpoint_files(c.checkpoint_file, c.restart_file);
  return control;
}

}  // namespace lrchain::jobs
