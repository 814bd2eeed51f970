#pragma once
// Checkpoint/restart of long lattice runs. A checkpoint knows what it continues: it records the
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

#include "lrchain/sim/run_record.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

// How a restart mismatch names an item whose recorded key is not what the user sets: the config
// key / option name, and for a long item recorded in other terms, its value in the user's terms
// (the bright run records the half-width N, the user sets sites = 2N + 1).
struct ShownAs {
  std::string name;
  std::function<long(long)> value = {};  // empty: the recorded value
};

// What defines a trajectory, as ordered key = value items; doubles print in the shortest form that
// reads back to the same bits. The keys stay as written by earlier versions, so that their
// checkpoints still restart; ShownAs gives the name a mismatch message uses.
class TrajectoryIdentity {
 public:
  void add(const std::string& key, double value);
  void add(const std::string& key, long value);
  void add(const std::string& key, double value, ShownAs shown);
  void add(const std::string& key, long value, ShownAs shown);
  void add(const std::string& key, const std::string& value);
  void add(const std::string& key, const char* value) { add(key, std::string(value)); }
  void add_state_hash(const std::string& key, const State& state);  // "sha256:<hex of its bytes>"
  const std::vector<std::pair<std::string, std::string>>& items() const { return items_; }
  std::string text() const;  // "lrchain_version = ...\nkey = value\n..."
  // The item `key` with the recorded text `value` as the user names it: "sites = 1001" for
  // N = 500 added with ShownAs{"sites", 2N + 1}; "key = value" for an item added without one.
  std::string shown(const std::string& key, const std::string& value) const;

 private:
  std::vector<std::pair<std::string, std::string>> items_;
  std::vector<std::pair<std::string, ShownAs>> shown_;
};

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

// A temporary name next to `file`, unique to this process: "<dir>/.<name>.tmp.<pid>".
std::filesystem::path temporary_name(const std::filesystem::path& file);

// Writes `c` with `record` (in place of c.record, which a run need not copy) to `file` (its
// directory must exist; a `file` that is a directory, device, FIFO or socket is refused,
// check_output_target) via a temporary name + rename.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c, const RunRecord& record);

// Reads and verifies a checkpoint (magic, version, sizes against the file's size, CRC-32, identity
// hash, finite state, time >= 0). Throws InputError naming the file and what is wrong.
Checkpoint read_checkpoint(const std::filesystem::path& file);

// Throws InvalidParameter("restart", ...) naming the first item that differs as the run shows it
// (TrajectoryIdentity::shown), e.g. "checkpoint 'c.bin' was written with rho = 0.3333333333333333,
// this run has rho = 0.5", or "... with sites = 1001, this run has sites = 801".
void check_same_trajectory(const std::filesystem::path& file, const Checkpoint& c,
                           const TrajectoryIdentity& run);

}  // namespace lrchain::sim
