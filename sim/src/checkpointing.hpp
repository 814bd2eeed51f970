#pragma once
// Pieces the long runs (bright, drive, modulated) share for checkpoint/restart through a
// CheckpointStore (lrchain/sim/checkpoint_store.hpp): the identity items every run has, resuming
// from a saved run, the observation times left after it, and the rhythm of periodic checkpoints.
// No file is read or written here. Private to sim/src.
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/params.hpp"
#include "lrchain/sim/checkpoint_store.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/run_control.hpp"

namespace lrchain::sim {

// Run kind, model, its parameters (alpha, delta0, kappa, rho), stepper and its settings.
TrajectoryIdentity base_identity(const std::string& run, const Params& p, const IntegratorOptions& o);

// Throws InvalidParameter("checkpoint" / "restart") when the run names a checkpoint or restart file
// and `control` has no store to write or read it (sim writes no files: a job supplies the store).
void require_checkpoint_store(const RunControl& control, const std::string& checkpoint_file,
                              const std::string& restart_file);

struct CheckpointSink;

// Where a restarted run resumes: the saved time and the step its stepper tries next.
struct Resumption {
  double t = 0;
  double next_step = 0;
};

// Continues a `kind` run ("bright", "drive", "modulated") from the store's saved run (its load
// checks identity, state size, the record's series names and its one field of `sites` sites, the
// time before t_end and the named accumulators), moves its state and record into `state` and
// `record`, reads each named accumulator into its slot, carries the work done into `sink` and keeps
// the observation times from its time on.
Resumption resume_from_checkpoint(const CheckpointStore& store, const TrajectoryIdentity& identity, const char* kind,
                                  Index sites, double t_end, State& state, RunRecord& record,
                                  std::initializer_list<std::pair<const char*, double*>> accumulators,
                                  CheckpointSink& sink, std::vector<double>& times);

// The observation times of a run continued from a checkpoint at t0: t0, then those after it.
std::vector<double> times_after(const std::vector<double>& times, double t0);

// When periodic checkpoints are due: at the first step boundary at or after each multiple of
// `every` (0: never), so they add no observation time and leave the step sequence unchanged.
struct CheckpointRhythm {
  double every = 0;
  double next = 0;
  CheckpointRhythm() = default;
  CheckpointRhythm(double every_, double t0);
  bool due(double t);  // true (and advances) when t has reached the next multiple
};

// When a run saves its checkpoints: periodically (CheckpointRhythm), at its end when asked, and
// when stopped by an interrupt; into `store` (none: an empty store's save).
struct CheckpointSink {
  const CheckpointStore* store = nullptr;
  const TrajectoryIdentity* identity = nullptr;  // of the run
  CheckpointRhythm rhythm;
  double t_end = 0;
  bool at_end = false;     // also save one at t_end (so that the run can be extended)
  std::uint64_t base_steps = 0, base_rhs_evaluations = 0;  // work before a restart
  long written = 0;
  double last_time = -1;   // time of the last checkpoint saved (< 0: none)

  bool saves() const { return store && store->save; }
  // True when a checkpoint is due at the step boundary t (advances the rhythm).
  bool due(double t);
  // Saves one, recording the work so far.
  void write(const State& s, double t, double next_step, const IntegrationStats& stats,
             const RunRecord& record, std::vector<std::pair<std::string, double>> accumulators);
};

}  // namespace lrchain::sim
