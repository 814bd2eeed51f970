#pragma once
// How a long run saves and resumes its progress, without knowing where it goes: the run describes
// its trajectory (TrajectoryIdentity) and, at step boundaries, hands its progress (time, next step,
// work, accumulators, state, record) to a CheckpointStore that a caller passes in RunControl. sim
// writes no checkpoint file; the file format (SHA-256, temporary name + rename) and the restart
// checks are the job layer's (lrchain/jobs/checkpoint/checkpoint_file.hpp, checkpoint_files.hpp).
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/index.hpp"
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

// A run's progress at a step boundary, apart from its state and record.
struct RunProgress {
  double t = 0;          // a step boundary of the run's step sequence
  double next_step = 0;  // step size the stepper tries next (adaptive steppers)
  std::uint64_t steps = 0, rhs_evaluations = 0;               // work done up to t
  std::vector<std::pair<std::string, double>> accumulators;  // the run's running maxima etc.
};

// What a restart continues: the progress, the state at its time and the record observed up to it.
struct SavedRun {
  RunProgress progress;
  State state;
  RunRecord record;
};

// What a run that restarts asks of the store: its identity, the sizes its state and record must
// have, its end and the accumulators it reads back.
struct RestartRequest {
  const TrajectoryIdentity& identity;
  const char* kind = "";                         // "bright", "drive", "modulated"
  std::size_t state_size = 0;
  Index sites = 0;                               // of the record's one space-time field
  const std::vector<std::string>& series_names;  // of the record's series
  double t_end = 0;                              // the saved time must lie before it
  std::vector<const char*> accumulators;         // each must be saved
};

// Where checkpoints go and come from. `save` keeps the progress of the run `identity` (periodic, at
// the end when asked, and on an interrupt); `load` returns the saved run that matches the request
// or throws (InputError / InvalidParameter naming what does not match). An empty `save`: the run
// writes no checkpoints; an empty `load`: it starts at t = 0.
struct CheckpointStore {
  std::function<void(const TrajectoryIdentity& identity, const RunProgress& progress, const State& state,
                     const RunRecord& record)>
      save;
  std::function<SavedRun(const RestartRequest& request)> load;
};

}  // namespace lrchain::sim
