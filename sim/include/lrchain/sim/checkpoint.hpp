#pragma once
// Checkpoint/restart of long lattice runs: the state vector and its time in one small binary
// file, written atomically (temporary name + rename), so a crash or Ctrl-C never leaves a torn file.
#include <filesystem>
#include <string>

#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

struct Checkpoint {
  double t = 0;
  State state;
  std::string tag;  // free text identifying the run (e.g. the config name), checked on restart
};

// Writes `c` to `file` (directory must exist) via file.tmp + rename.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c);
// Reads a checkpoint; throws std::runtime_error naming the file if it is missing or malformed.
Checkpoint read_checkpoint(const std::filesystem::path& file);

}  // namespace lrchain::sim
