#pragma once
// Checkpoint files of long lattice runs (the job layer's side of sim::CheckpointStore). A checkpoint knows what it continues: it records the
// lrchain version and, as readable `key = value` lines, everything that defines the trajectory
// (run kind, model, every physical parameter, lattice size, stepper and its settings, a hash of the
// initial state), plus a hash of those lines; then the time, the step size the stepper tries next,
// the state, the run's accumulated outputs, and a CRC-32 of the file's own bytes. Written under a
// unique temporary name and renamed, so a crash or a signal never leaves a torn file.
//
// Layout (little-endian, as written by this machine):
//   "LRCKPT\r\n"                      8-byte magic
//   uint32 format version (3; version 2 of lrchain 0.1 hashed with FNV-1a and is refused)
//   uint64 length, text               identity: "key = value\n" lines (lrchain_version first)
//   32 bytes                          SHA-256 of the identity text
//   uint64 length, text               progress: "key = value\n" lines (t, next_step, steps,
//                                     rhs_evaluations, the run's accumulators), doubles in C99
//                                     hexadecimal (%a), so they round-trip to the last bit
//   uint64 n, n doubles               the state
//   record                            series, fields and snapshots observed up to t (doubles and
//                                     floats bit for bit; strings length-prefixed)
//   uint32 CRC-32 of every byte before it
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/sim/checkpoint_store.hpp"
#include "lrchain/sim/run_record.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::jobs {

using sim::RunRecord;
using sim::State;
using sim::TrajectoryIdentity;

struct Checkpoint {
  std::string identity;   // TrajectoryIdentity::text() of the run that wrote it
  double t = 0;           // time of `state`: a step boundary of the run's step sequence
  double next_step = 0;   // step size the stepper tries next (adaptive steppers)
  std::uint64_t steps = 0, rhs_evaluations = 0;  // work done up to t
  std::vector<std::pair<std::string, double>> accumulators;  // the run's running maxima etc.
  State state;
  RunRecord record;       // what was observed up to t (filled by read_checkpoint)

  // The accumulator `name`; throws InputError naming `file` if the checkpoint lacks it.
  double accumulator(const std::filesystem::path& file, const std::string& name) const;
};

// Writes `c` with `record` (in place of c.record, which a run need not copy) to `file` (its
// directory must exist; a `file` that is a directory, device, FIFO or socket is refused,
// check_output_target) via a temporary name + rename.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c, const RunRecord& record);
// The same file from a run's progress (sim::CheckpointStore::save): identity text, progress, state, record.
void write_checkpoint(const std::filesystem::path& file, const std::string& identity, const sim::RunProgress& progress,
                      const State& state, const RunRecord& record);

// Reads and verifies a checkpoint (magic, version, sizes against the file's size, CRC-32, identity
// hash, finite state, time >= 0). Throws InputError naming the file and what is wrong.
Checkpoint read_checkpoint(const std::filesystem::path& file);

// Throws InvalidParameter("restart", ...) naming the first item that differs as the run shows it
// (TrajectoryIdentity::shown), e.g. "checkpoint 'c.bin' was written with rho = 0.3333333333333333,
// this run has rho = 0.5", or "... with sites = 1001, this run has sites = 801".
void check_same_trajectory(const std::filesystem::path& file, const Checkpoint& c,
                           const TrajectoryIdentity& run);

}  // namespace lrchain::jobs
